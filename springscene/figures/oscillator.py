"""The runs and closed forms behind the wiki figures: the ball's motion along its line, the
linear model's x(t), the demo damping and drive, the integrators' runs and their energy
errors, how long a figure's run lasts and the period of its time axis.

Nothing here draws: the plots (:mod:`.plots`), stills (:mod:`.media`) and captions
(:mod:`.gallery`) take what these functions return.
"""

from __future__ import annotations

import math
from dataclasses import replace
from importlib import resources

import numpy as np

from .. import config, render
from ..errors import UserError
from ..model import physics
from ..model.integrators import INTEGRATORS
from ..science import analysis, theory
from ..settings import Config

# the config of the Hooke's-law figure when the user's spring has no elastic limit
OVERSTRETCHED = "overstretched.toml"

DEMO_B = 0.1                   # kg/s
DEMO_DRIVE_AMPLITUDE = 0.002   # m, of the holder
SWEEP_FREQUENCIES = 200
SWEEP_PERIODS = 100


def axis_of(cfg: Config) -> np.ndarray:
    """The unit vector of the line of motion (up, against g)."""
    return np.asarray(theory.Oscillator.from_config(cfg).axis, float)


def along(cfg: Config, traj: physics.Trajectory) -> tuple[np.ndarray, np.ndarray]:
    """The ball's position (m) and velocity (m/s) along the line of motion (up, against g)."""
    axis = axis_of(cfg)
    return traj.pos @ axis, traj.p @ axis / cfg.ball.m


def closed_form(cfg: Config, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Displacement from equilibrium x(t) (m) and velocity v(t) (m/s) of the linear model.

    Free motion from :class:`theory.Oscillator`; with a drive, the steady state
    plus the free motion that matches the initial state. A driven support
    ``A sin(w t)`` pulls as a force ``k A sin(w t)``; a driving force is ``F0 cos(w t)``.
    Returns NaNs for an undamped drive exactly at resonance (no steady state).
    """
    osc = theory.Oscillator.from_config(cfg)
    t = np.asarray(t, float)
    if not cfg.driven:
        return osc.x(t), osc.v(t)
    d = cfg.drive
    u = np.asarray(d.direction, float) / np.linalg.norm(d.direction)
    F0 = theory.drive_force_amplitude(cfg) * float(np.dot(u, osc.axis))
    w, w0, g = d.omega, osc.omega0, osc.gamma
    if g == 0 and math.isclose(w, w0):
        nan = np.full_like(t, np.nan)
        return nan, nan
    A = float(theory.steady_amplitude(w, w0, g, F0, cfg.ball.m))
    delta = math.atan2(2 * g * w, w0 ** 2 - w ** 2)
    trig, dtrig = (np.sin, np.cos) if d.type == "support" else (np.cos, lambda a: -np.sin(a))
    xp, vp = A * trig(w * t - delta), A * w * dtrig(w * t - delta)
    free = replace(osc, x0=osc.x0 - float(A * trig(-delta)),
                   v0=osc.v0 - float(A * w * dtrig(-delta)))
    return free.x(t) + xp, free.v(t) + vp


def demo_damped(cfg: Config) -> tuple[Config, bool]:
    """The config with damping: its own, or the demo b = 0.1 kg/s (True when a demo).

    Its free motion (:func:`free_motion`: no drive, not at rest at equilibrium), so that
    the envelope is the free decay."""
    base = free_motion(cfg)
    if cfg.damping.b > 0:
        return base, False
    return config.override(base, "damping", b=DEMO_B), True


def demo_driven(cfg: Config) -> tuple[Config, list[str]]:
    """A config a resonance sweep can run: the config's damping and drive, or demo ones.

    Returns the config and what was added ("damping", "drive")."""
    added = []
    if cfg.damping.b <= 0:
        cfg = config.override(cfg, "damping", b=DEMO_B)
        added.append("damping")
    if not cfg.driven:
        w0 = theory.Oscillator.from_config(cfg).omega0
        axis = tuple(float(c) for c in theory.Oscillator.from_config(cfg).axis)
        cfg = config.override(cfg, "drive", type="support", amplitude=DEMO_DRIVE_AMPLITUDE,
                              omega=w0, direction=axis)
        added.append("drive")
    return cfg, added


def sweep_omegas(cfg: Config, n: int = SWEEP_FREQUENCIES) -> np.ndarray:
    """n drive frequencies from omega0/2 to 3 omega0/2."""
    w0 = theory.Oscillator.from_config(cfg).omega0
    return np.linspace(0.5 * w0, 1.5 * w0, n)


def free_motion(cfg: Config) -> Config:
    """The config without its drive, its ball displaced by L0/5 if it would rest at equilibrium."""
    base = config.override(cfg, "drive", type="none") if cfg.driven else cfg
    osc = theory.Oscillator.from_config(base)
    if osc.amplitude < 1e-9:
        pos = np.asarray(osc.equilibrium) - np.asarray(osc.axis) * 0.2 * cfg.spring.L0
        base = config.override(base, "ball", pos=tuple(float(c) for c in pos))
    return base


def integrator_runs(cfg: Config, duration: float | None = None
                    ) -> dict[str, physics.Trajectory | str]:
    """The config's free motion (:func:`free_motion`) run by each integrator; a string
    says why one cannot (unstable at this step)."""
    base = free_motion(cfg)
    runs: dict[str, physics.Trajectory | str] = {}
    for name in INTEGRATORS:
        try:
            runs[name] = render.simulate(config.override(base, "physics", integrator=name),
                                         duration)
        except UserError as exc:
            runs[name] = str(exc)
    return runs


def hooke_config(cfg: Config) -> Config:
    """The user's config when it sets an elastic limit, else configs/overstretched.toml."""
    if math.isfinite(cfg.spring.yield_stretch):
        return cfg
    with resources.as_file(resources.files("springscene") / "configs" / OVERSTRETCHED) as path:
        return config.load(path)


def oscillation_energy(cfg: Config) -> float:
    """1/2 k A^2 of the free motion about equilibrium (J), the scale of energy errors."""
    return theory.Oscillator.from_config(cfg).energy


def energy_error(traj: physics.Trajectory, scale: float) -> np.ndarray:
    """(E + E_thermal - its start) / scale at every step."""
    total = traj.total
    return (total - total[0]) / scale


def per_period_max(t: np.ndarray, err: np.ndarray, period: float) -> tuple[np.ndarray, np.ndarray]:
    """Largest |err| in each whole period: (period end times, maxima)."""
    n = int(t[-1] // period)
    if n < 1:
        return np.array([t[-1]]), np.array([np.abs(err).max()])
    idx = np.minimum((t // period).astype(int), n)
    ends, peaks = [], []
    for c in range(n):
        ends.append((c + 1) * period)
        peaks.append(np.abs(err[idx == c]).max())
    return np.array(ends), np.array(peaks)


MAX_EXTRA_STEPS = 20_000     # a figure lengthens a short run by at most this many steps


def run_duration(cfg: Config, least: float | None = None) -> float:
    """The config's duration, but at least ``least`` (default: three periods, or five
    decay times when it does not oscillate), lengthened by at most MAX_EXTRA_STEPS steps."""
    if least is None:
        osc = theory.Oscillator.from_config(cfg)
        least = 3 * period_of(cfg) if osc.omega_d > 0 or cfg.driven else 5 / osc.decay_rate
    least = min(least, MAX_EXTRA_STEPS * cfg.physics.dt)
    return max(cfg.render.duration, least)


def analyze(cfg: Config, duration: float | None = None) -> dict:
    """:func:`analysis.analyze` over ``duration``, or over a run long enough to measure."""
    need = 2 * analysis.needed_duration(cfg, theory.Oscillator.from_config(cfg))
    if (duration if duration is not None else cfg.render.duration) >= need:
        return analysis.analyze(cfg, duration)
    return analysis.analyze(cfg, max(need, duration or 0.0, cfg.render.duration))


def period_of(cfg: Config) -> float:
    """The period of the figures' time axes: the drive's when driven, else the free motion's."""
    if cfg.driven:
        return 2 * math.pi / cfg.drive.omega
    osc = theory.Oscillator.from_config(cfg)
    if math.isfinite(osc.period):
        return osc.period
    return 2 * math.pi / osc.omega0


def is_linear(cfg: Config) -> bool:
    """Whether the spring obeys Hooke's law everywhere (no stiffening, no elastic limit)."""
    return cfg.spring.k3 == 0 and not math.isfinite(cfg.spring.yield_stretch)


def position_residual(cfg: Config, traj: physics.Trajectory) -> np.ndarray:
    """y simulated minus y closed form at every step (m)."""
    osc = theory.Oscillator.from_config(cfg)
    y, _ = along(cfg, traj)
    return y - float(np.dot(osc.equilibrium, osc.axis)) - closed_form(cfg, traj.t)[0]


def rest_potential(cfg: Config, traj: physics.Trajectory) -> float:
    """Us + Ug with the ball at rest at (the final) equilibrium."""
    return theory.rest_potential(cfg, float(traj.L0[-1]))

