"""The page's "experimental quantities", measured from a simulated trajectory, beside theory.

:func:`analyze` simulates a config and measures, along the line of motion:

- the equilibrium, where the simulated net force on the ball vanishes (a least-
  squares fit of the acceleration against displacement and velocity);
- the period, from interpolated upward crossings of equilibrium over all full
  cycles; frequency and angular frequency from it;
- the amplitude (largest displacement in the first period), the largest speed
  and acceleration, and the oscillation energy about equilibrium (K + Us + Ug
  minus their value at rest at equilibrium, averaged over the first period);
- with damping: the decay rate from the logarithm of the successive peaks, and
  the energy lost (the thermal energy tallied by the engine);
- with a drive: the same over the steady state (the last half of the run).

Theory comes from :mod:`springscene.science.theory`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

import numpy as np

from .. import build, config, progress
from ..model import physics, timeline
from . import tables, theory
from .sweep import check_sweepable
from ..settings import Config
from ..errors import UserError

MIN_STEPS_PER_PERIOD = 12
KEYS = ("period", "frequency", "angular_frequency", "equilibrium_stretch", "amplitude",
        "max_speed", "max_acceleration", "energy")
DAMPED_KEYS = ("damping_rate", "energy_lost")
UNITS = {"period": "s", "frequency": "Hz", "angular_frequency": "rad/s",
         "equilibrium_stretch": "m", "amplitude": "m", "max_speed": "m/s",
         "max_acceleration": "m/s^2", "energy": "J", "damping_rate": "1/s",
         "energy_lost": "J", "permanent_set": "m"}


def crossings(t: np.ndarray, x: np.ndarray) -> np.ndarray:
    """Interpolated times at which x crosses zero going up."""
    idx = np.flatnonzero((x[:-1] < 0) & (x[1:] >= 0))
    return t[idx] - x[idx] * (t[idx + 1] - t[idx]) / (x[idx + 1] - x[idx])


def period_from_crossings(t: np.ndarray, x: np.ndarray) -> float | None:
    """Mean period over all full cycles between the first and last upward crossing."""
    tc = crossings(t, x)
    if len(tc) < 2:
        return None
    return float((tc[-1] - tc[0]) / (len(tc) - 1))


def peak_decay_rate(t: np.ndarray, x: np.ndarray) -> float | None:
    """gamma from ln|x| at its successive extrema (both signs): ln|x_peak| = c - gamma t."""
    ax = np.abs(x)
    idx = np.flatnonzero((ax[1:-1] > ax[:-2]) & (ax[1:-1] >= ax[2:])) + 1
    idx = idx[ax[idx] > 1e-6 * ax.max()]          # above round-off
    if len(idx) < 3:      # not oscillating: fit the tail of |x| itself
        tail = np.flatnonzero(ax > 1e-6 * ax.max())
        tail = tail[len(tail) // 2:]
        if len(tail) < 3:
            return None
        idx = tail
    slope = np.polyfit(t[idx], np.log(ax[idx]), 1)[0]
    return float(-slope)


def _equilibrium(traj: physics.Trajectory, axis: np.ndarray) -> float:
    """Position along ``axis`` where the fitted net force is zero: a = c + a1 y + a2 v."""
    y = traj.pos @ axis
    v = traj.p @ axis
    a = traj.a @ axis
    coef = np.linalg.lstsq(np.column_stack([np.ones_like(y), y, v]), a, rcond=None)[0]
    return float(-coef[0] / coef[1])


def analyze(cfg: Config, duration: float | None = None) -> dict:
    """Measured and theoretical quantities of the config's oscillation (SI units)."""
    cfg = config.override(cfg, "render", duration=duration)
    osc = theory.Oscillator.from_config(cfg)
    _check_measurable(cfg, osc, duration)
    n = timeline.step_at(cfg.render.duration, cfg.physics.dt, "--duration")
    with progress.steps(n, "simulating") as advance:
        traj = physics.run(build.system(cfg), n, progress=advance)
    extra_measured, extra_theory = {}, {}
    plastic = bool(np.any(traj.L0 != traj.L0[0]))
    if plastic:
        traj, osc = _after_permanent_set(cfg, osc, traj, extra_measured, extra_theory)
    run = _Run.of(cfg, osc, traj)
    T = period_from_crossings(run.t[run.sel], run.x[run.sel])
    measured: dict[str, float | None] = {
        "period": T,
        "frequency": 1 / T if T else None,
        "angular_frequency": 2 * math.pi / T if T else None,
        "equilibrium_stretch": float(run.holder_y - run.y_eq - traj.L0[-1]),
    }
    amplitudes, th = _driven_motion(cfg, run) if cfg.driven else _free_motion(cfg, run, T)
    measured.update(amplitudes)
    theory_: dict[str, float | None] = {
        "period": th["period"] if math.isfinite(th["period"]) else None,
        "equilibrium_stretch": osc.equilibrium_stretch,
        **{k: th[k] for k in ("amplitude", "max_speed", "max_acceleration", "energy")},
    }
    P = theory_["period"]
    theory_["frequency"] = 1 / P if P else None
    theory_["angular_frequency"] = 2 * math.pi / P if P else None
    damped = cfg.damping.b > 0
    if damped:
        _measure_damping(cfg, run, th, measured, theory_)
    measured.update(extra_measured)
    theory_.update(extra_theory)
    keys = KEYS + (DAMPED_KEYS if damped else ()) + tuple(extra_measured)
    return {"config": cfg.source, "integrator": cfg.physics.integrator, "dt": cfg.physics.dt,
            "duration": float(traj.t[-1] + traj.t0), "regime": _regime(cfg, osc, traj, plastic),
            "measured": {k: measured.get(k) for k in keys},
            "theory": {k: theory_.get(k) for k in keys},
            "unit": {k: UNITS[k] for k in keys}, "dt_unit": "s", "duration_unit": "s"}


def _check_measurable(cfg: Config, osc: theory.Oscillator, duration: float | None) -> None:
    """Refuse a drive off the line of motion, too few steps a period, too short a run."""
    if cfg.driven:
        check_sweepable(cfg, "analyze")
    if osc.omega_d > 0 and osc.period / cfg.physics.dt < MIN_STEPS_PER_PERIOD:
        raise UserError(f"{cfg.source}: dt = {cfg.physics.dt:g} s (--dt or [physics] dt) gives {osc.period / cfg.physics.dt:.3g} steps "
                        f"a period: analyze needs at least {MIN_STEPS_PER_PERIOD} to measure; "
                        f"use dt <= {osc.period / MIN_STEPS_PER_PERIOD:.3g} s")
    need = needed_duration(cfg, osc)
    if cfg.render.duration < need:
        where = "--duration" if duration is not None else f"{cfg.source}: [render] duration"
        raise UserError(f"{where} {cfg.render.duration:g} s is too short to analyze: it needs "
                        f"at least {need:.3g} s ({_why_needed(cfg, osc)})")


def _after_permanent_set(cfg: Config, osc: theory.Oscillator, traj: physics.Trajectory,
                         extra_measured: dict, extra_theory: dict
                         ) -> tuple[physics.Trajectory, theory.Oscillator]:
    """The spring took a permanent set: the motion after it, about the new equilibrium;
    theory (perfect plasticity) starts it at rest at the elastic limit."""
    axis = np.asarray(osc.axis)
    s_y, s_eq = cfg.spring.yield_stretch, osc.equilibrium_stretch
    extra_measured["permanent_set"] = float(traj.L0[-1] - traj.L0[0])
    extra_theory["permanent_set"] = theory.permanent_set(osc, s_y)
    i_set = int(np.flatnonzero(np.diff(traj.L0))[-1]) + 1
    traj = _after(traj, i_set)
    shift = axis * (extra_theory["permanent_set"] or 0.0)
    osc = replace(osc, L0=float(traj.L0[-1]), x0=-(s_y - s_eq), v0=0.0,
                  equilibrium=tuple(np.asarray(osc.equilibrium) - shift))
    return traj, osc


@dataclass
class _Run:
    """The run seen along the line of motion, about its equilibrium."""

    traj: physics.Trajectory
    osc: theory.Oscillator
    sel: slice             # the steps measured: a driven run's steady state, else all
    y_eq: float            # the equilibrium along the axis
    holder_y: float
    x: np.ndarray          # displacement from equilibrium along the axis
    v: np.ndarray          # velocity along the axis
    t: np.ndarray
    E_osc: np.ndarray      # energy about equilibrium

    @classmethod
    def of(cls, cfg: Config, osc: theory.Oscillator, traj: physics.Trajectory) -> "_Run":
        axis = np.asarray(osc.axis)
        sel = slice(_steady_start(cfg, osc, traj.t), None) if cfg.driven else slice(None)
        # driven: the mean over whole drive periods of the steady state (the response is a
        # sinusoid at the drive's frequency there, so a force fit could not tell it apart)
        y_eq = (float(np.mean(traj.pos[sel][:-1] @ axis)) if cfg.driven
                else _equilibrium(traj, axis))
        holder_y = float(np.dot(cfg.holder.pos, axis))
        # energy about equilibrium: the engine's own energies, minus those at rest there
        rest = build.system(cfg)
        rest.pos[1] = np.asarray(cfg.holder.pos) + axis * (y_eq - holder_y)
        rest.p[:] = 0.0
        rest.L0[:] = traj.L0[-1]
        E_rest = physics.energies(rest).E
        return cls(traj, osc, sel, y_eq, holder_y, traj.pos @ axis - y_eq,
                   traj.p @ axis / cfg.ball.m, traj.t, traj.E - E_rest)


def _driven_motion(cfg: Config, run: _Run) -> tuple[dict, dict]:
    """Measured amplitude, speed, acceleration and energy of the steady state, and theory's."""
    osc, sel, m = run.osc, run.sel, cfg.ball.m
    axis = np.asarray(osc.axis)
    F0 = theory.drive_force_amplitude(cfg) * float(np.dot(
        np.asarray(cfg.drive.direction) / np.linalg.norm(cfg.drive.direction), axis))
    w = cfg.drive.omega
    A = float(abs(theory.steady_amplitude(w, osc.omega0, osc.gamma, F0, m)))
    xs = run.x[sel]
    measured = dict(amplitude=float((xs.max() - xs.min()) / 2),
                    max_speed=float(np.abs(run.v[sel]).max()),
                    max_acceleration=float(np.abs(run.traj.a[sel] @ axis).max()),
                    energy=float(run.E_osc[sel].mean()))
    # mean of 1/2 m v^2 + 1/2 k (x - y_holder)^2 over a cycle, x lagging the drive by delta
    delta = math.atan2(2 * osc.gamma * w, osc.omega0 ** 2 - w ** 2)
    As = cfg.drive.amplitude if cfg.drive.type == "support" else 0.0   # along the axis
    th = {"period": 2 * math.pi / w, "amplitude": A, "max_speed": A * w,
          "max_acceleration": A * w * w,
          "energy": 0.25 * m * (A * w) ** 2
          + 0.25 * cfg.spring.k * abs(A * complex(math.cos(delta), -math.sin(delta)) - As) ** 2}
    return measured, th


def _free_motion(cfg: Config, run: _Run, T: float | None) -> tuple[dict, dict]:
    """Measured amplitude, speed, acceleration and energy over the first period, and theory's."""
    osc, t, traj, m = run.osc, run.t, run.traj, cfg.ball.m
    t_th = np.linspace(0.0, t[-1], 20 * (len(t) - 1) + 1)
    first = t <= (T if T else t[-1])
    xt, vt = osc._xv(t_th)
    at = -osc.omega0 ** 2 * xt - 2 * osc.gamma * vt
    first_th = t_th <= osc.period
    measured = dict(amplitude=float(np.abs(run.x[first]).max()),
                    max_speed=float(np.linalg.norm(traj.p, axis=1).max() / m),
                    max_acceleration=float(np.linalg.norm(traj.a, axis=1).max()),
                    energy=float(run.E_osc[first].mean()))
    th = {"period": osc.period, "amplitude": float(np.abs(xt[first_th]).max()),
          "max_speed": float(np.abs(vt).max()), "max_acceleration": float(np.abs(at).max()),
          "energy": osc.energy if not cfg.damping.b > 0 else float(
              osc.mechanical_energy(t_th[first_th]).mean())}
    return measured, th


def _measure_damping(cfg: Config, run: _Run, th: dict, measured: dict, theory_: dict) -> None:
    """The damping rate and the energy the drag took, measured and in theory."""
    osc, traj, t, m = run.osc, run.traj, run.t, cfg.ball.m
    if cfg.driven:
        # over the steady state the drag dissipates 1/2 b (A w)^2 on average
        # the drag's power b <v^2> is what the engine tallied as heat: b = dE_th / int v^2 dt
        vs, ts = run.v[run.sel], t[run.sel]
        v2dt = float(np.sum((vs[1:] ** 2 + vs[:-1] ** 2) / 2 * np.diff(ts)))
        measured["damping_rate"] = float((traj.E_thermal[-1] - traj.E_thermal[run.sel][0])
                                         / v2dt / (2 * m))
        theory_["damping_rate"] = osc.gamma
        window = t[-1] - t[run.sel][0]
        measured["energy_lost"] = float(traj.E_thermal[-1] - traj.E_thermal[run.sel][0])
        theory_["energy_lost"] = 0.5 * cfg.damping.b * (th["max_speed"]) ** 2 * window
    else:
        measured["damping_rate"] = peak_decay_rate(t, run.x)
        # a motion that does not oscillate: the same fit of ln|x| on the closed form
        theory_["damping_rate"] = (osc.decay_rate if osc.omega_d > 0
                                   else peak_decay_rate(t, osc.x(t)))
        measured["energy_lost"] = float(traj.E_thermal[-1])
        theory_["energy_lost"] = float(osc.energy - osc.mechanical_energy(t[-1]))


def _regime(cfg: Config, osc: theory.Oscillator, traj: physics.Trajectory, plastic: bool) -> str:
    regime = "driven" if cfg.driven else osc.regime
    if cfg.spring.k3:
        regime += " (stiffening: theory linearised about equilibrium, k + 3 k3 s_eq^2)"
    if plastic:
        regime += f", after a permanent set at t = {traj.t0:.3g} s"
    return regime


def _after(traj: physics.Trajectory, i: int) -> physics.Trajectory:
    """The trajectory from row i on, its clock restarted at 0 (``t0`` keeps the offset)."""
    part = physics.Trajectory(traj.t[i:] - traj.t[i], traj.pos[i:], traj.p[i:], traj.a[i:],
                              traj.K[i:], traj.Us[i:], traj.Ug[i:],
                              traj.E_thermal[i:] - traj.E_thermal[i], traj.L0[i:])
    part.t0 = float(traj.t[i])
    return part


def needed_duration(cfg: Config, osc: theory.Oscillator) -> float:
    if cfg.driven:
        settle = -math.log(SETTLED) / osc.gamma if osc.gamma > 0 else 0.0
        return settle + 5 * 2 * math.pi / cfg.drive.omega
    if osc.omega_d > 0:
        return 2.5 * osc.period
    return 5 / osc.decay_rate


def _why_needed(cfg: Config, osc: theory.Oscillator) -> str:
    if cfg.driven:
        return "the transient must decay to 1e-3 and five drive periods follow"
    if osc.omega_d > 0:
        return "two full periods and a half"
    return "five decay times"


SETTLED = theory.SETTLED


def _steady_start(cfg: Config, osc: theory.Oscillator, t: np.ndarray) -> int:
    """First step of the steady state: when e^(-gamma t) < SETTLED, but at least
    five drive periods before the end and no earlier than half way."""
    end = t[-1]
    settle = -math.log(SETTLED) / osc.gamma if osc.gamma > 0 else end / 2
    T = 2 * math.pi / cfg.drive.omega
    start = max(end / 2, min(settle, end - 5 * T))
    start = end - math.floor((end - start) / T) * T      # a whole number of drive periods
    return int(np.searchsorted(t, start - 1e-9))


def table(result: dict) -> str:
    """A readable terminal table: quantity, measured, theory, difference."""
    lines = [f"{result['config']}: {result['regime']}, {result['integrator']}, "
             f"dt = {result['dt']:g} s, {result['duration']:g} s simulated",
             tables.header(22, 14)]
    for key, meas in result["measured"].items():
        lines.append(tables.row(key, meas, result["theory"][key], UNITS[key], label_width=22,
                                measured_width=14))
    return "\n".join(lines)
