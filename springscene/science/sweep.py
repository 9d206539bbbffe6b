"""Resonance: the steady-state amplitude against drive frequency, as one batch.

All N drive frequencies run as one :class:`~springscene.model.physics.System` of N
independent holder-ball pairs side by side (copy c driven at ``omega[c]``), so
the whole sweep is one numpy run through the same engine, not N Python loops.
Every copy runs until the slowest drive has made ``periods`` periods (and the
transient has decayed to 1e-3 of itself); the amplitude is half the range of
the ball's displacement over the last ``window`` periods of the slowest drive.
"""

from __future__ import annotations

import math
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .. import build, config
from ..model import physics, timeline
from . import theory
from ..settings import Config
from ..errors import UserError
from ..outputs import atomic_path, check_output

MAX_FREQUENCIES = 100_000
WINDOW_PERIODS = 10
SETTLED = theory.SETTLED


def parse_omega(text: str, flag: str = "--omega") -> np.ndarray:
    """``START:STOP:N`` (rad/s) as N evenly spaced frequencies."""
    parts = str(text).split(":")
    if len(parts) != 3:
        raise UserError(f"{flag} {text!r}: expected START:STOP:N, e.g. 6:18:200")
    try:
        start, stop = float(parts[0]), float(parts[1])
        n = int(parts[2])
    except ValueError:
        raise UserError(f"{flag} {text!r}: START and STOP must be numbers and N a whole number"
                        ) from None
    if not (math.isfinite(start) and math.isfinite(stop)):
        raise UserError(f"{flag} {text!r}: START and STOP must be finite")
    if n < 1:
        raise UserError(f"{flag} {text!r}: N = {n} gives an empty sweep (need N >= 1)")
    if n > MAX_FREQUENCIES:
        raise UserError(f"{flag} {text!r}: N = {n} is more than {MAX_FREQUENCIES:,} frequencies")
    if start <= 0 or stop <= 0:
        raise UserError(f"{flag} {text!r}: drive frequencies must be > 0 rad/s")
    if stop < start:
        raise UserError(f"{flag} {text!r}: STOP must not be below START")
    return np.linspace(start, stop, n)


@dataclass
class SweepResult:
    omega: np.ndarray        # rad/s
    amplitude: np.ndarray    # measured steady-state amplitude (m)
    theory: np.ndarray       # A(omega) (m)
    omega0: float
    gamma: float
    simulated: float         # seconds simulated by every copy
    steps: int
    seconds: float           # wall time
    F0_over_m: float = 1.0   # drive force amplitude per unit mass (m/s^2)

    @property
    def peak(self) -> tuple[float, float]:
        """(omega, amplitude) of the largest measured amplitude."""
        c = int(np.argmax(self.amplitude))
        return float(self.omega[c]), float(self.amplitude[c])

    @property
    def theory_peak(self) -> tuple[float, float]:
        """omega_r = sqrt(omega0^2 - 2 gamma^2) and A(omega_r)."""
        wr = math.sqrt(max(self.omega0 ** 2 - 2 * self.gamma ** 2, 0.0))
        return wr, float(theory.steady_amplitude(wr, self.omega0, self.gamma, 1.0, 1.0)
                         * self.F0_over_m)


def check_sweepable(cfg: Config, command: str = "sweep") -> None:
    """A steady state to measure: a drive along the line of motion, and damping."""
    if not cfg.driven:
        raise UserError(f"{cfg.source}: {command} needs a [drive] section (type = \"support\" or "
                        "\"force\", amplitude)")
    if cfg.damping.b <= 0:
        raise UserError(f"{cfg.source}: {command} needs [damping] b > 0 with a drive: without "
                        "damping the amplitude never settles to a steady state")
    theory.check_drive_along_motion(cfg, command)


def sweep(cfg: Config, omega: np.ndarray, periods: float = 200) -> SweepResult:
    """Steady-state amplitude at each drive frequency, all frequencies in one system."""
    check_sweepable(cfg)
    omega = np.asarray(omega, float)
    if periods <= 0 or not math.isfinite(periods):
        raise UserError(f"--periods must be > 0, got {periods:g}")
    osc = theory.Oscillator.from_config(cfg)
    axis = np.asarray(osc.axis)
    dt = cfg.physics.dt
    fastest = float(omega.max())
    if fastest * dt > config.MAX_DRIVE_PHASE_PER_STEP:
        raise UserError(f"--omega: a drive at {fastest:g} rad/s needs dt <= "
                        f"{config.MAX_DRIVE_PHASE_PER_STEP / fastest:.3g} s (at least "
                        f"{2 * math.pi / config.MAX_DRIVE_PHASE_PER_STEP:.0f} steps per drive "
                        f"period), dt is {dt:g} s")
    slowest = 2 * math.pi / omega.min()
    window = WINDOW_PERIODS * slowest
    total = max(periods * slowest, -math.log(SETTLED) / osc.gamma + window)
    n_total = timeline.step_at(total, dt, "--omega/--periods: the run of")
    if n_total * len(omega) > 50 * timeline.current_limit():
        raise UserError(f"--omega/--periods: {len(omega)} frequencies x {n_total:,} steps is "
                        f"more than {50 * timeline.current_limit():,} spring updates; use fewer")
    n_window = max(int(round(window / dt)), 1)

    start = time.perf_counter()
    s = build.system(cfg, omega=omega)
    balls = s.free
    physics.step(s, n_total - n_window)
    y = s.pos[balls] @ axis
    hi, lo = y.copy(), y.copy()
    for _ in range(n_window):
        physics.step(s)
        y = s.pos[balls] @ axis
        np.maximum(hi, y, out=hi)
        np.minimum(lo, y, out=lo)
    seconds = time.perf_counter() - start

    direction = np.asarray(cfg.drive.direction, float)
    F0 = theory.drive_force_amplitude(cfg) * abs(float(np.dot(direction / np.linalg.norm(direction),
                                                              axis)))
    result = SweepResult(omega, (hi - lo) / 2,
                         theory.steady_amplitude(omega, osc.omega0, osc.gamma, F0, cfg.ball.m),
                         osc.omega0, osc.gamma, s.t, s.steps, seconds, F0 / cfg.ball.m)
    return result


CSV_HEADER = ("omega [rad/s]", "frequency [Hz]", "amplitude [m]", "theory [m]")


def write_csv(result: SweepResult, out: str | Path) -> Path:
    """omega (rad/s), frequency (Hz), measured and theoretical amplitude (m), full precision."""
    out = check_output(out, (".csv",))
    table = np.column_stack([result.omega, result.omega / (2 * math.pi), result.amplitude,
                             result.theory])
    with atomic_path(out) as tmp, open(tmp, "w") as fh:
        fh.write(",".join(CSV_HEADER) + "\n")
        for row in table.tolist():
            fh.write(",".join(repr(v) for v in row) + "\n")
    return out


def summary(result: SweepResult) -> str:
    wp, ap = result.peak
    wt, at = result.theory_peak
    err = np.abs(result.amplitude - result.theory) / result.theory
    inside = ("" if result.omega[0] <= wt <= result.omega[-1]
              else " (outside the swept range: the measured peak is at its edge)")
    return (f"{len(result.omega)} drive frequencies {result.omega[0]:g}..{result.omega[-1]:g} rad/s, "
            f"{result.simulated:g} s simulated each ({result.steps:,} steps) in "
            f"{result.seconds:.2f} s\n"
            f"peak: measured {ap:.6g} m at {wp:.4g} rad/s; theory {at:.6g} m at {wt:.4g} rad/s"
            f"{inside}\n"
            f"measured vs A(omega): largest difference {100 * err.max():.2f} %, "
            f"median {100 * np.median(err):.2f} %")
