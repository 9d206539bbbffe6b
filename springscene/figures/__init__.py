"""The wiki page's figures: plots, stills, a film strip, a GIF and a ``<gallery>`` snippet.

:func:`make_figures` writes, into one folder, for a config (``configs/wiki.toml``
is the page's scene):

==================  ===========================================================
``scene.png``       the scene at t = 0 (VTK, off-screen)
``position.*``      y(t) simulated against the closed form, residual below
``energy.*``        K, Us, Ug and E against time (and the heat, when damped)
``phase.*``         the phase portrait: displacement against velocity
``damped.*``        the damped y(t) inside its envelope A e^(-gamma t)
``resonance.*``     measured steady-state amplitude against the analytic A(omega)
``integrators.*``   energy error of Euler, Euler-Cromer, Verlet and RK4
``hooke.*``         the limits of Hooke's law: permanent set, force against stretch
``filmstrip.png``   one period in six stills
``oscillation.gif`` the oscillation in real time, looping, under 2 MB
``figures.wiki``    a MediaWiki ``<gallery>`` with a caption per figure
==================  ===========================================================

(``*`` is PNG and SVG.) A config without damping or drive gets a demo damping
(b = 0.1 kg/s) and a demo drive for the damped and resonance figures, and the
captions say so. The matplotlib figures are drawn with a fixed style, size and
dpi, and saved without dates, so the same config gives the same bytes every
run. Each ``*_figure`` function draws one figure from data passed in and returns
a :class:`matplotlib.figure.Figure`, so each can be tested on its own.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field, replace
from fractions import Fraction
from importlib import resources
from pathlib import Path

import numpy as np

from .. import build, config
from ..errors import UserError
from .. import render
from ..model import physics, timeline
from ..model.integrators import INTEGRATORS
from ..science import analysis, sweep, theory
from ..settings import Config
from ..view import backend as backends
from ..view.plotstyle import (BLACK, BLUE, GREEN, GREY, ORANGE, PURPLE, SKY, VERMILLION,
                              new_figure, style)
from ..units import MINUS, percent
from .files import prepare_out_dir, save_figure, write_text

# the config of the Hooke's-law figure when the user's spring has no elastic limit
OVERSTRETCHED = "overstretched.toml"

DEMO_B = 0.1                   # kg/s
DEMO_DRIVE_AMPLITUDE = 0.002   # m, of the holder
DEMO_K3 = 1000.0               # N/m^3, for the stiffening curve when the spring has none
SWEEP_FREQUENCIES = 200
SWEEP_PERIODS = 100
FILMSTRIP_FRAMES = 6
GIF_MAX_BYTES = 2_000_000
# (width, height, fps, periods) tried in turn until the GIF fits GIF_MAX_BYTES
GIF_ATTEMPTS = ((450, 300, 25, 2), (450, 300, 20, 1), (360, 240, 20, 1), (300, 200, 15, 1))
INTEGRATOR_COLORS = {"euler": VERMILLION, "euler-cromer": BLUE, "verlet": GREEN, "rk4": PURPLE}



# ---- the physics behind the figures -------------------------------------------------------

def _axis(cfg: Config) -> np.ndarray:
    return np.asarray(theory.Oscillator.from_config(cfg).axis, float)


def along(cfg: Config, traj: physics.Trajectory) -> tuple[np.ndarray, np.ndarray]:
    """The ball's position (m) and velocity (m/s) along the line of motion (up, against g)."""
    axis = _axis(cfg)
    return traj.pos @ axis, traj.p @ axis / cfg.ball.m


def position_label(cfg: Config) -> str:
    axis = _axis(cfg)
    return "$y$ (m)" if np.allclose(axis, (0, 1, 0)) else "position along $-\\vec g$ (m)"


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


def _settings(cfg: Config) -> str:
    """k, m, dt, integrator, b, drive: the values behind a figure, for its caption."""
    d = cfg.drive
    drive = "no drive" if not cfg.driven else (
        f"{'support' if d.type == 'support' else 'force'} drive "
        f"A = {d.amplitude:g} {'m' if d.type == 'support' else 'N'} at ω = {d.omega:.4g} rad/s")
    return (f"k = {cfg.spring.k:g} N/m, m = {cfg.ball.m:g} kg, L0 = {cfg.spring.L0:g} m, "
            f"dt = {cfg.physics.dt:g} s, {INTEGRATORS[cfg.physics.integrator].label}, "
            f"b = {cfg.damping.b:g} kg/s, {drive}")


def _linear(cfg: Config) -> bool:
    """Whether the spring obeys Hooke's law everywhere (no stiffening, no elastic limit)."""
    return cfg.spring.k3 == 0 and not math.isfinite(cfg.spring.yield_stretch)


def _pct(measured: float | None, expected: float | None) -> str:
    if measured is None or not expected:
        return "n/a"
    return percent((measured - expected) / abs(expected), minus=MINUS)


# ---- the figures --------------------------------------------------------------------------

def position_figure(cfg: Config, traj: physics.Trajectory, *, periods: float = 3.0,
                    measured_period: float | None = None):
    """Top: y(t) simulated (dots, one per step) and closed form (line) over the first
    ``periods``; bottom: the residual (mm) over the whole run."""
    osc = theory.Oscillator.from_config(cfg)
    y, _ = along(cfg, traj)
    t = traj.t
    y_eq = float(np.dot(osc.equilibrium, osc.axis))
    T = period_of(cfg)
    t_fine = np.linspace(0, t[-1], 20 * (len(t) - 1) + 1)
    x_fine, _ = closed_form(cfg, t_fine)
    x_t, _ = closed_form(cfg, t)
    resid = (y - y_eq - x_t) * 1e3
    with style():
        fig = new_figure(560)
        top, bottom = fig.subplots(2, 1, height_ratios=[3, 2])
        span = min(t[-1], periods * T)
        near = t <= span + 1e-9
        near_fine = t_fine <= span + 1e-9
        top.plot(t_fine[near_fine], y_eq + x_fine[near_fine], color=BLACK, lw=1.3,
                 label="closed form $y_{eq} + x(t)$")
        top.plot(t[near], y[near], "o", ms=3.2, color=BLUE, mec="none",
                 label=f"simulation ({INTEGRATORS[cfg.physics.integrator].label}, "
                       f"$\\Delta t$ = {cfg.physics.dt:g} s)")
        top.axhline(y_eq, color=GREY, ls="--", lw=1,
                    label=f"equilibrium $y_{{eq}}$ = {_signed(y_eq, '.4f')} m")
        top.set_xlim(0, span)
        top.set_xlabel("time $t$ (s)")
        top.set_ylabel(position_label(cfg))
        lo, hi = min(y[near].min(), y_eq), max(y[near].max(), y_eq)
        pad = 0.12 * (hi - lo or 1e-3)
        top.set_ylim(lo - pad, hi + 4.5 * pad)
        top.legend(loc="upper right", ncol=2, fontsize=10)
        T_th = osc.period if not cfg.driven else T
        name = ("drive period" if cfg.driven else "theory $2\\pi\\sqrt{m/k}$"
                if osc.regime == "undamped" else "theory $2\\pi/\\omega_d$")
        if not math.isfinite(T_th):
            head = f"Position: simulation against the closed form ({osc.regime})"
        elif measured_period:
            head = f"Position: measured $T$ = {measured_period:.4f} s, {name} = {T_th:.4f} s"
        else:
            head = f"Position: simulation against the closed form, {name} = {T_th:.4f} s"
        top.set_title(head)
        if np.all(np.isnan(resid)):
            bottom.text(0.5, 0.5, "no closed form (undamped drive at resonance)",
                        ha="center", va="center", transform=bottom.transAxes)
        else:
            bottom.plot(t, resid, color=VERMILLION, lw=1.2)
        bottom.axhline(0, color=GREY, lw=0.8)
        bottom.set_xlim(0, t[-1])
        bottom.set_xlabel("time $t$ (s)")
        bottom.set_ylabel("residual (mm)")
        bottom.set_title(f"Residual $y_{{sim}} - y_{{closed}}$ over the whole {t[-1]:g} s run",
                         fontsize=12)
    return fig


def position_residual(cfg: Config, traj: physics.Trajectory) -> np.ndarray:
    """y simulated minus y closed form at every step (m)."""
    osc = theory.Oscillator.from_config(cfg)
    y, _ = along(cfg, traj)
    return y - float(np.dot(osc.equilibrium, osc.axis)) - closed_form(cfg, traj.t)[0]


def energy_figure(cfg: Config, traj: physics.Trajectory, *, periods: float = 3.0):
    """Top: K, Us, Ug, E (and E_thermal, total) as the engine tallies them;
    bottom: K and U = Us + Ug measured from rest at equilibrium."""
    t = traj.t
    T = period_of(cfg)
    lossy = cfg.damping.b > 0 or bool(np.any(traj.E_thermal))
    span = t[-1] if lossy else min(t[-1], periods * T)
    sel = t <= span + 1e-9
    U_rest = _rest_potential(cfg, traj)
    with style():
        fig = new_figure(600)
        top, bottom = fig.subplots(2, 1, sharex=True, height_ratios=[1, 1])
        top.plot(t[sel], traj.K[sel], color=BLUE, label="$K = p^2/2m$")
        top.plot(t[sel], traj.Us[sel], color=GREEN, label="$U_s = \\frac{1}{2}k(\\Delta L)^2$")
        top.plot(t[sel], traj.Ug[sel], color=ORANGE, label="$U_g = mgy$")
        top.plot(t[sel], traj.E[sel], color=BLACK, lw=2, label="$E = K + U_s + U_g$")
        if lossy:
            top.plot(t[sel], traj.E_thermal[sel], color=VERMILLION, label="$E_{thermal}$")
            top.plot(t[sel], traj.total[sel], color=PURPLE, ls="--", label="$E + E_{thermal}$")
        top.set_ylabel("energy (J)")
        top.set_title("Energy as the engine tallies it ($U_g$ = 0 at the holder's height)")
        top.legend(loc="center left", bbox_to_anchor=(1.0, 0.5), fontsize=10)
        mJ = 1e3
        U = (traj.Us + traj.Ug - U_rest) * mJ
        K = traj.K * mJ
        E = (traj.E - U_rest) * mJ
        shown = [K[sel], U[sel], E[sel]]
        bottom.plot(t[sel], K[sel], color=BLUE, label="$K$")
        bottom.plot(t[sel], U[sel], color=GREEN, label="$U_s + U_g - U_{eq}$")
        bottom.plot(t[sel], E[sel], color=BLACK, lw=2, label="$E - U_{eq}$")
        if lossy and not cfg.driven:        # driven, the heat grows without bound
            total = (traj.total - U_rest)[sel] * mJ
            shown.append(total)
            bottom.plot(t[sel], total, color=PURPLE, ls="--", label="$E + E_{thermal} - U_{eq}$")
        bottom.set_ylabel("energy (mJ)")
        bottom.set_xlabel("time $t$ (s)")
        bottom.set_xlim(0, span)
        bottom.set_title("About equilibrium: kinetic and potential energy trade places")
        bottom.legend(loc="center left", bbox_to_anchor=(1.0, 0.5), fontsize=10)
        lo = min(0.0, min(float(a.min()) for a in shown))
        hi = max(float(a.max()) for a in shown)
        bottom.set_ylim(lo - 0.02 * (hi - lo) * (lo < 0), hi + 0.08 * (hi - lo))
    return fig


def _rest_potential(cfg: Config, traj: physics.Trajectory) -> float:
    """Us + Ug with the ball at rest at (the final) equilibrium."""
    osc = theory.Oscillator.from_config(cfg)
    axis = np.asarray(osc.axis)
    s = build.system(cfg)
    s.L0[:] = traj.L0[-1]
    stretch = theory.stiffening_stretch(cfg.spring.k, cfg.spring.k3, cfg.ball.m * osc.g)
    s.pos[1] = np.asarray(cfg.holder.pos) - axis * (traj.L0[-1] + stretch)
    s.p[:] = 0.0
    e = physics.energies(s)
    return e.Us + e.Ug


def phase_figure(cfg: Config, traj: physics.Trajectory,
                 damped: tuple[Config, physics.Trajectory] | None = None):
    """Velocity against displacement from equilibrium: the simulated loop(s), the closed
    form, and optionally a damped run's spiral."""
    osc = theory.Oscillator.from_config(cfg)
    y, v = along(cfg, traj)
    x = y - float(np.dot(osc.equilibrium, osc.axis))
    t_fine = np.linspace(0, min(traj.t[-1], 2 * period_of(cfg)), 2001)
    xc, vc = closed_form(cfg, t_fine)
    with style():
        fig = new_figure(560)
        ax = fig.subplots()
        if damped is not None:
            dcfg, dtraj = damped
            dy, dv = along(dcfg, dtraj)
            dosc = theory.Oscillator.from_config(dcfg)
            ax.plot(dy - float(np.dot(dosc.equilibrium, dosc.axis)), dv, color=SKY, lw=1.0,
                    label=f"with drag $b$ = {dcfg.damping.b:g} kg/s: spirals in")
        ax.plot(x, v, color=BLUE, lw=2.2,
                label=f"simulation, {traj.t[-1]:g} s ({INTEGRATORS[cfg.physics.integrator].label})")
        ax.plot(xc, vc, color=BLACK, ls="--", lw=1.2, label="closed form")
        ax.plot([x[0]], [v[0]], "o", color=VERMILLION, ms=7, label="start ($t$ = 0)", zorder=5)
        ax.axhline(0, color=GREY, lw=0.8)
        ax.axvline(0, color=GREY, lw=0.8)
        ax.set_xlabel("displacement from equilibrium $x$ (m)")
        ax.set_ylabel("velocity $v$ (m/s)")
        if osc.regime == "undamped" and not cfg.driven and _linear(cfg):
            ax.set_title(f"Phase portrait: an ellipse, $v_{{max}} = \\omega_0 A$, "
                         f"$\\omega_0$ = {osc.omega0:.4g} rad/s")
        else:
            ax.set_title(f"Phase portrait ({osc.regime if not cfg.driven else 'driven'}), "
                         f"$\\omega_0$ = {osc.omega0:.4g} rad/s")
        xm = max(np.abs(x).max(), np.nanmax(np.abs(xc)))
        vm = max(np.abs(v).max(), np.nanmax(np.abs(vc)))
        ax.set_xlim(-1.25 * xm, 1.25 * xm)
        ax.set_ylim(-1.2 * vm, 1.55 * vm)
        ax.legend(loc="upper center", ncol=2, fontsize=10)
    return fig


def damped_figure(cfg: Config, traj: physics.Trajectory, *, demo: bool = False,
                  measured_rate: float | None = None):
    """The damped y(t) inside y_eq +- A e^(-gamma t)."""
    osc = theory.Oscillator.from_config(cfg)
    y, _ = along(cfg, traj)
    t = traj.t
    y_eq = float(np.dot(osc.equilibrium, osc.axis))
    with style():
        fig = new_figure(500)
        ax = fig.subplots()
        ax.plot(t, y, color=BLUE, lw=1.1, label="simulated $y(t)$")
        if osc.omega_d > 0:
            env = osc.envelope(t)
            ax.plot(t, y_eq + env, color=VERMILLION, ls="--", lw=2,
                    label="$y_{eq} \\pm A\\,e^{-\\gamma t}$")
            ax.plot(t, y_eq - env, color=VERMILLION, ls="--", lw=2)
        else:
            ax.plot(t, y_eq + closed_form(cfg, t)[0], color=VERMILLION, ls="--", lw=2,
                    label=f"closed form ({osc.regime})")
        ax.axhline(y_eq, color=GREY, lw=0.8, ls=":", label="equilibrium")
        ax.set_xlim(0, t[-1])
        span = max(np.abs(y - y_eq).max(), 1e-6)
        ax.set_ylim(y_eq - 1.15 * span, y_eq + 1.45 * span)
        ax.set_xlabel("time $t$ (s)")
        ax.set_ylabel(position_label(cfg))
        what = "demo " if demo else ""
        rate = (f", measured {measured_rate:.4f} /s" if measured_rate is not None else "")
        ax.set_title(f"Damped ({what}$b$ = {cfg.damping.b:g} kg/s): "
                     f"$\\gamma = b/2m$ = {osc.gamma:.4g} /s{rate}")
        ax.legend(loc="upper right", ncol=3, fontsize=10)
    return fig


def resonance_figure(result: sweep.SweepResult, *, demo: str = ""):
    """Measured steady-state amplitude (dots) against A(omega) (line), in mm."""
    w, A, Ath = result.omega, result.amplitude * 1e3, result.theory * 1e3
    wp, ap = result.peak
    wt, at = result.theory_peak
    Q = result.omega0 / (2 * result.gamma)
    with style():
        fig = new_figure(500)
        ax = fig.subplots()
        w_fine = np.linspace(w[0], w[-1], 2000)
        A_fine = theory.steady_amplitude(w_fine, result.omega0, result.gamma, 1.0, 1.0) \
            * result.F0_over_m * 1e3
        ax.plot(w_fine, A_fine, color=BLACK, lw=1.4,
                label="$A(\\omega) = (F_0/m)\\,/\\,\\sqrt{(\\omega_0^2-\\omega^2)^2"
                      "+(2\\gamma\\omega)^2}$")
        ax.plot(w, A, "o", ms=3.5, color=BLUE, mec="none",
                label=f"simulated steady state ({len(w)} frequencies)")
        ax.axvline(result.omega0, color=GREY, ls="--", lw=1,
                   label=f"$\\omega_0 = \\sqrt{{k/m}}$ = {result.omega0:.4g} rad/s")
        ax.plot([wp], [ap * 1e3], "v", color=VERMILLION, ms=9,
                label=f"measured peak {ap * 1e3:.3g} mm at {wp:.4g} rad/s")
        ax.set_xlim(w[0], w[-1])
        ax.set_ylim(0, 1.18 * max(A.max(), Ath.max()))
        ax.set_xlabel("drive angular frequency $\\omega$ (rad/s)")
        ax.set_ylabel("steady-state amplitude (mm)")
        ax.set_title(f"Resonance{' (' + demo + ')' if demo else ''}: "
                     f"$\\gamma$ = {result.gamma:.3g} /s, $Q = \\omega_0/2\\gamma$ = {Q:.3g}")
        ax.legend(loc="upper left", fontsize=10)
    return fig


def integrators_figure(cfg: Config, runs: dict[str, physics.Trajectory | str]):
    """Largest |E - E0| / (1/2 k A^2) in each period, log scale, one line per integrator."""
    free = free_motion(cfg)
    scale = oscillation_energy(free)
    T = period_of(free)
    with style():
        fig = new_figure(520)
        ax = fig.subplots()
        for name in INTEGRATORS:
            run = runs.get(name)
            if run is None:
                continue
            if isinstance(run, str):
                ax.plot([], [], color=INTEGRATOR_COLORS[name],
                        label=f"{INTEGRATORS[name].label}: unstable at this step")
                continue
            ends, peaks = per_period_max(run.t, energy_error(run, scale), T)
            ax.semilogy(ends, np.maximum(peaks, 1e-16), "o-", ms=3, color=INTEGRATOR_COLORS[name],
                        label=f"{INTEGRATORS[name].label} (order {INTEGRATORS[name].order}): "
                              f"{_fmt_err(peaks[-1])} after {run.t[-1]:g} s")
        ax.set_xlabel("time $t$ (s)")
        ax.set_ylabel("largest $|E - E_0|\\,/\\,\\frac{1}{2}kA^2$ in each period")
        ax.set_title(f"Energy error of four integrators, $\\Delta t$ = {cfg.physics.dt:g} s "
                     f"($\\omega_0\\Delta t$ = "
                     f"{theory.Oscillator.from_config(cfg).omega0 * cfg.physics.dt:.3g})")
        ax.set_xlim(0, None)
        lo, hi = ax.get_ylim()
        ax.set_ylim(lo, hi * 1e3)     # room for the legend above the curves
        ax.legend(loc="upper left", fontsize=10, ncol=1)
        ax.grid(True, which="major")
    return fig


_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def _fmt_err(x: float) -> str:
    """0.065, 3.7×10⁻³, 6.8×10⁵: two figures, powers of ten as superscripts."""
    if not math.isfinite(x) or x == 0 or 0.01 <= abs(x) < 100:
        return f"{x:.2g}"
    e = math.floor(math.log10(abs(x)))
    mant = x / 10 ** e
    if round(mant, 1) >= 10:
        mant, e = mant / 10, e + 1
    return f"{mant:.2g}×10{str(e).translate(_SUPERSCRIPT)}"


def _signed(x: float, fmt: str = ".3f") -> str:
    """A number with a real minus sign."""
    return format(x, fmt).replace("-", "−")


def hooke_figure(cfg: Config, traj: physics.Trajectory):
    """Top: y(t) with the equilibrium before and after the permanent set; bottom: spring
    tension against extension (Hooke's line, a stiffening spring, the elastic limit and
    the path the simulation took)."""
    osc = theory.Oscillator.from_config(cfg)
    axis = np.asarray(osc.axis)
    sp = cfg.spring
    y, _ = along(cfg, traj)
    t = traj.t
    holder = float(np.dot(cfg.holder.pos, axis))
    weight = cfg.ball.m * osc.g
    s_eq = theory.stiffening_stretch(sp.k, sp.k3, weight)
    y_before = holder - (traj.L0[0] + s_eq)
    y_after = holder - (traj.L0[-1] + s_eq)
    length = holder - y                            # |L| for a ball below its holder
    stretch = length - traj.L0
    force = sp.k * stretch + sp.k3 * stretch ** 3
    extension = length - traj.L0[0]
    yielding = np.flatnonzero(np.diff(traj.L0) != 0) + 1
    with style():
        fig = new_figure(780)
        top, bottom = fig.subplots(2, 1, height_ratios=[1, 1.15])
        if len(yielding):
            top.axvspan(t[yielding[0] - 1], t[yielding[-1]], color=ORANGE, alpha=0.3, lw=0,
                        label=f"yielding: $L_0$ {traj.L0[0]:.3f} → {traj.L0[-1]:.3f} m")
        top.plot(t, y, color=BLUE, lw=1.1, label="$y(t)$")
        top.axhline(y_before, color=GREEN, ls="--", lw=1.8,
                    label=f"equilibrium before: {_signed(y_before)} m")
        top.axhline(y_after, color=VERMILLION, ls="-.", lw=1.8,
                    label=f"after the set: {_signed(y_after)} m")
        top.set_xlim(0, t[-1])
        lo, hi = min(y.min(), y_after), max(y.max(), y_before)
        top.set_ylim(lo - 0.06 * (hi - lo), hi + 0.3 * (hi - lo))
        top.set_xlabel("time $t$ (s)")
        top.set_ylabel(position_label(cfg))
        start = (f"Kicked at {abs(osc.v0):.3g} m/s" if osc.v0 else
                 f"Released {abs(osc.x0) * 100:.3g} cm from equilibrium")
        if len(yielding):
            top.set_title(f"{start}: the spring yields, the ball settles lower")
        else:
            top.set_title(f"{start}: the spring stays within its elastic limit")
        top.legend(loc="upper right", ncol=2, fontsize=10)

        e_max = max(float(extension.max()), 1.3 * sp.yield_stretch if math.isfinite(
            sp.yield_stretch) else 0.0)
        e = np.linspace(0, 1.1 * e_max, 400)
        bottom.plot(e, sp.k * e, color=BLACK, ls="--", lw=1.2,
                    label=f"Hooke: $F = k\\,\\Delta L$, $k$ = {sp.k:g} N/m")
        k3 = sp.k3 if sp.k3 > 0 else DEMO_K3
        bottom.plot(e, sp.k * e + k3 * e ** 3, color=PURPLE, ls=":", lw=2.2,
                    label=f"stiffening: $F = k\\,\\Delta L + k_3\\Delta L^3$, $k_3$ = {k3:g} N/m³"
                          + ("" if sp.k3 > 0 else " (illustration)"))
        if math.isfinite(sp.yield_stretch):
            Fy = sp.k * sp.yield_stretch + sp.k3 * sp.yield_stretch ** 3
            bottom.axhline(Fy, color=ORANGE, lw=1.6,
                           label=f"elastic limit: $\\Delta L$ = {sp.yield_stretch:g} m, "
                                 f"$F$ = {Fy:.3g} N")
        bottom.axhline(weight, color=GREY, lw=1.2, ls="-.",
                       label=f"$mg$ = {weight:.3g} N (equilibrium)")
        bottom.plot(extension, force, color=BLUE, lw=1.3, label="simulated path")
        bottom.set_xlim(min(0.0, float(extension.min())), 1.1 * e_max)
        Fmax = max(float(force.max()), sp.k * 1.1 * e_max)
        bottom.set_ylim(min(0.0, float(force.min())) - 0.04 * Fmax, 1.25 * Fmax)
        bottom.set_xlabel(f"extension $|L| - L_0$ (m), from the original $L_0$ = {traj.L0[0]:g} m")
        bottom.set_ylabel("spring tension (N)")
        bottom.set_title("Force against extension: Hooke's line, flow at the limit, "
                         "unloading parallel to it" if len(yielding) else
                         "Force against extension", fontsize=12)
        bottom.legend(loc="upper left", fontsize=10)
    return fig


# ---- stills, film strip and GIF -----------------------------------------------------------

@dataclass
class Filmstrip:
    tiles: list[np.ndarray]       # cropped frames, all the same size
    times: list[float]            # simulated time of each (s)
    period: float                 # T (s)
    equilibrium_row: int | None   # pixel row of the ball's centre at equilibrium, in a tile
    labels: list[str] = field(default_factory=list)


def filmstrip_frames(cfg: Config, *, n: int = FILMSTRIP_FRAMES, backend: str = "auto",
                     antialias: bool = True) -> Filmstrip:
    """n stills at t = 0, T/n, ..., (n-1)T/n, cropped around spring and ball alike."""

    T = period_of(cfg)
    dt = cfg.physics.dt
    steps = [int(round(c * T / n / dt)) for c in range(n)]
    osc = theory.Oscillator.from_config(cfg)
    axis = np.asarray(osc.axis)
    r = cfg.ball.radius
    system = build.system(cfg)
    with render.make_scene(cfg, system, antialias=antialias, backend=backend) as scene:
        # a dry pass first, so that autoscale has seen every state and one view serves all
        balls = []
        for probe in timeline.play(build.system(cfg), steps):
            scene.update(probe)
            balls.append(probe.pos[1].copy())
        frames = []
        for state in timeline.play(system, steps):
            scene.update(state)
            frames.append(scene.frame())
        view = scene.view
    h, w = frames[0].shape[:2]
    cam_right = np.cross(view.focal_point - view.position, view.up)
    cam_right /= np.linalg.norm(cam_right)
    cam_up = np.asarray(view.up, float) / np.linalg.norm(view.up)
    holder = np.asarray(cfg.holder.pos, float)
    size = np.asarray(cfg.holder.size, float)
    pts = [holder - axis * size[1] / 2]               # the middle of the holder's lower face
    for b in balls:
        pts += [b + r * cam_right, b - r * cam_right, b - r * cam_up, b + r * cam_up]
    px = view.project(np.array(pts))
    pad = 14
    c0, c1 = px[:, 0].min() - pad, px[:, 0].max() + pad
    r0, r1 = px[:, 1].min() - 3 * pad, px[:, 1].max() + pad
    centre = (c0 + c1) / 2
    half = max((c1 - c0) / 2, 55)                      # room for the time label
    c0, c1 = int(max(0, round(centre - half))), int(min(w, round(centre + half)))
    r0, r1 = int(max(0, round(r0))), int(min(h, round(r1)))
    tiles = [f[r0:r1, c0:c1] for f in frames]
    eq_row = int(round(view.project(np.asarray(osc.equilibrium))[1])) - r0
    times = [s * dt for s in steps]
    labels = [_fraction_label(Fraction(c, n)) for c in range(n)]
    return Filmstrip(tiles, times, T, eq_row if 0 <= eq_row < r1 - r0 else None, labels)


def _fraction_label(f: Fraction) -> str:
    """0, T/6, T/3, T/2, 2T/3, ... for a fraction of the period."""
    if f == 0:
        return "0"
    return f"{'' if f.numerator == 1 else f.numerator}T/{f.denominator}" if f.denominator > 1 \
        else f"{f.numerator}T"


def filmstrip_figure(strip: Filmstrip, gap: int = 8):
    """The tiles side by side at their own pixels, labelled with their times; a dashed
    line (behind the objects) marks the equilibrium."""
    tiles = [t.copy() for t in strip.tiles]
    th, tw = tiles[0].shape[:2]
    if strip.equilibrium_row is not None:
        row = strip.equilibrium_row
        for tile in tiles:
            line = tile[row]
            background = np.all(line > 235, axis=-1)          # only over the white background
            dash = (np.arange(tw) // 6) % 2 == 0
            line[background & dash] = (120, 120, 120)
    header = 64
    width = len(tiles) * tw + (len(tiles) + 1) * gap
    canvas = np.full((th + gap, width, 3), 255, np.uint8)
    for c, tile in enumerate(tiles):
        x = gap + c * (tw + gap)
        canvas[0:th, x:x + tw] = tile
    with style():
        fig = new_figure(th + gap + header, width)
        fig.set_layout_engine(None)
        fig.figimage(canvas, xo=0, yo=0, origin="upper")
        H = th + gap + header
        for c, t in enumerate(strip.times):
            x = (gap + c * (tw + gap) + tw / 2) / width
            label = strip.labels[c] if strip.labels else ""
            fig.text(x, 1 - 30 / H, label, ha="center", va="center", fontsize=12,
                     fontweight="bold")
            fig.text(x, 1 - 50 / H, f"t = {t:.2f} s", ha="center", va="center", fontsize=11)
        fig.text(0.5, 1 - 10 / H, f"One period, T = {strip.period:.3f} s "
                 "(dashed: equilibrium)", ha="center", va="center", fontsize=11, color="#333333")
    return fig


def make_gif(cfg: Config, out: Path, *, backend: str = "auto", antialias: bool = True
             ) -> tuple[render.RenderStats, tuple[int, int, int, int]]:
    """The oscillation as a looping real-time GIF under :data:`GIF_MAX_BYTES`: smaller,
    slower or shorter until it fits."""
    T = period_of(cfg)
    for width, height, fps, periods in GIF_ATTEMPTS:
        # no title: VTK's title font does not shrink with the canvas
        small = config.override(cfg, "scene", width=width, height=height, title="")
        frames = max(1, int(round(periods * T * fps)))
        stats = render.render_video(small, out, duration=frames / fps, fps=fps, backend=backend,
                                    antialias=antialias)
        if out.stat().st_size < GIF_MAX_BYTES:
            break
    else:
        out.unlink(missing_ok=True)
        raise RuntimeError(f"{out}: no GIF under {GIF_MAX_BYTES:,} bytes")
    assert out.stat().st_size < GIF_MAX_BYTES
    return stats, (width, height, fps, periods)


# ---- the gallery --------------------------------------------------------------------------

def gallery(entries: list[tuple[str, str]], vector: list[str] = ()) -> str:
    """A MediaWiki ``<gallery>`` of (file name, caption) pairs, ready to paste."""
    lines = ["<!-- springscene figures: upload each file below under the name shown. -->"]
    if vector:
        lines.append("<!-- Vector (SVG) versions of the plots: " + ", ".join(vector) + " -->")
    lines.append('<gallery mode="packed" heights="260px">')
    for name, caption in entries:
        caption = " ".join(caption.replace("|", "/").split())
        lines.append(f"File:{name}|{caption}")
    lines.append("</gallery>")
    return "\n".join(lines) + "\n"



# ---- everything ---------------------------------------------------------------------------

def make_figures(cfg: Config, out_dir: str | Path, *, backend: str = "auto",
                 antialias: bool = True) -> list[Path]:
    """Write every figure, the GIF and ``figures.wiki`` into ``out_dir``; return their paths."""

    out = prepare_out_dir(out_dir)
    backends.select(backend)
    before = set(out.iterdir())
    try:
        return _make_figures(cfg, out, backend, antialias)
    except BaseException:
        for path in set(out.iterdir()) - before:     # no half set of figures left behind
            if path.is_file():
                path.unlink()
        raise


def _make_figures(cfg: Config, out: Path, backend: str, antialias: bool) -> list[Path]:
    osc = theory.Oscillator.from_config(cfg)
    settings = _settings(cfg)
    written: list[Path] = []
    captions: list[tuple[str, str]] = []

    # 1. the scene
    render.still(cfg, 0.0, out / "scene.png", backend=backend, antialias=antialias)
    written.append(out / "scene.png")
    x0 = osc.x0
    if abs(x0) < 1e-9 and osc.v0 == 0:
        where = "at rest at equilibrium"
    elif osc.v0 == 0:
        where = (f"released from rest {abs(x0) * 100:.3g} cm {'below' if x0 < 0 else 'above'} "
                 f"equilibrium")
    else:
        where = f"starting {x0 * 100:.3g} cm from equilibrium at {osc.v0:.3g} m/s"
    captions.append(("scene.png",
                     f"The scene at t = 0: holder, spring (k = {cfg.spring.k:g} N/m, "
                     f"L0 = {cfg.spring.L0:g} m) and ball (m = {cfg.ball.m:g} kg), {where}; "
                     f"the equilibrium stretch is mg/k = {osc.equilibrium_stretch:.4f} m. "
                     f"Rendered off-screen, {cfg.scene.width}×{cfg.scene.height} px."))

    # 2. position against the closed form
    duration = run_duration(cfg)
    traj = render.simulate(cfg, duration)
    result = analyze(cfg, duration)
    meas, th = result["measured"], result["theory"]
    T_meas = meas["period"]
    fig = position_figure(cfg, traj, measured_period=T_meas)
    written += save_figure(fig, out, "position")
    resid = np.abs(position_residual(cfg, traj))
    y, _ = along(cfg, traj)
    amp = osc.amplitude or float(np.abs(y - y.mean()).max()) or 1.0
    period_text = (f"Period measured {T_meas:.5f} s against theory {th['period']:.5f} s "
                   f"({_pct(T_meas, th['period'])})" if T_meas and th["period"] else
                   "No full period in the run")
    form = ("y_eq + x0 cos(ω0 t)" if osc.regime == "undamped" and not cfg.driven and osc.v0 == 0
            else "of the linear model")
    if not _linear(cfg):
        resid_text = (" The closed form is Hooke's linear model; the residual is mostly the "
                      "spring's stiffening (k3) or yield.")
    elif np.all(np.isnan(resid)):
        resid_text = ""
    else:
        resid_text = (f" The residual is {INTEGRATORS[cfg.physics.integrator].label}'s phase "
                      f"error and grows slowly: at most {np.nanmax(resid) * 1e3:.2g} mm "
                      f"({100 * np.nanmax(resid) / amp:.2g} % of the {amp * 100:.3g} cm "
                      f"amplitude) over {traj.t[-1]:g} s.")
    captions.append(("position.png",
                     f"Position y(t): the simulation ({settings}) against the closed form "
                     f"{form}, ω0 = √(k/m) = {osc.omega0:.4g} rad/s. {period_text}."
                     f"{resid_text}"))

    # 3. energy
    fig = energy_figure(cfg, traj)
    written += save_figure(fig, out, "energy")
    scale = osc.energy
    if cfg.driven:
        energy_text = "The drive does work on the ball, so E + E_thermal is not constant."
    else:
        drift = float(np.abs(energy_error(traj, scale)).max())
        energy_text = (f"The oscillation energy ½kA² is {scale * 1e3:.3g} mJ (measured "
                       f"{meas['energy'] * 1e3:.3g} mJ); E + E_thermal stays within "
                       f"{100 * drift:.2g} % of it over {traj.t[-1]:g} s.")
    captions.append(("energy.png",
                     f"Energy: K, Us = ½k(ΔL)², Ug = mgy (zero at the holder) and "
                     f"E = K + Us + Ug ({settings}); below, measured from rest at equilibrium, "
                     f"K and Us + Ug trade places. {energy_text}"))

    # 4. phase portrait (with the damped run's spiral beside an undamped ellipse)
    dcfg, demo_b = demo_damped(cfg)
    dosc = theory.Oscillator.from_config(dcfg)
    d_duration = run_duration(dcfg, 5 / dosc.decay_rate)
    dtraj = render.simulate(dcfg, d_duration)
    spiral = cfg.damping.b == 0 and not cfg.driven
    fig = phase_figure(cfg, traj, damped=(dcfg, dtraj) if spiral else None)
    written += save_figure(fig, out, "phase")
    shape = (f"the closed form is the ellipse (x/A)² + (v/ω0A)² = 1 with "
             f"A = {osc.amplitude * 100:.3g} cm, ω0A = {osc.omega0 * osc.amplitude:.3g} m/s"
             if osc.regime == "undamped" and not cfg.driven and _linear(cfg)
             else "the dashed line is the closed form of the linear model")
    captions.append(("phase.png",
                     f"Phase portrait: velocity against displacement from equilibrium over "
                     f"{traj.t[-1]:g} s ({settings}); {shape}"
                     + (f". In light blue the same ball with drag b = {dcfg.damping.b:g} kg/s"
                        + (" (demo)" if demo_b else "") + " spirals into equilibrium."
                        if spiral else ".")))

    # 5. damped envelope
    d_result = analyze(dcfg, d_duration)
    rate = d_result["measured"].get("damping_rate")
    fig = damped_figure(dcfg, dtraj, demo=demo_b, measured_rate=rate)
    written += save_figure(fig, out, "damped")
    demo_text = (f"This config has no damping, so a demo damping b = {DEMO_B:g} kg/s is "
                 f"added. " if demo_b else "")
    shape = ("inside the envelope y_eq ± A e^(−γt)" if dosc.omega_d > 0
             else "against the closed form")
    rate_text = (f" Decay rate from the successive peaks: {rate:.4f} /s (theory "
                 f"{dosc.decay_rate:.4g} /s, {_pct(rate, dosc.decay_rate)})."
                 if rate is not None else "")
    captions.append(("damped.png",
                     f"Damped oscillation. {demo_text}y(t) ({_settings(dcfg)}) {shape}, "
                     f"γ = b/2m = {dosc.gamma:.4g} /s ({dosc.regime}).{rate_text} Heat made by "
                     f"the drag: {d_result['measured']['energy_lost'] * 1e3:.3g} mJ in "
                     f"{d_result['duration']:g} s."))

    # 6. resonance
    rcfg, added = demo_driven(cfg)
    omegas = sweep_omegas(rcfg)
    res = sweep.sweep(rcfg, omegas, periods=SWEEP_PERIODS)
    demo = ("demo " + " and ".join(added)) if added else ""
    fig = resonance_figure(res, demo=demo)
    written += save_figure(fig, out, "resonance")
    wp, ap = res.peak
    wt, at = res.theory_peak
    err = np.abs(res.amplitude - res.theory) / res.theory
    demo_text = ""
    if added:
        parts = []
        if "damping" in added:
            parts.append(f"damping b = {DEMO_B:g} kg/s")
        if "drive" in added:
            parts.append(f"a driven support (amplitude {DEMO_DRIVE_AMPLITUDE:g} m)")
        demo_text = (f"This config has no {' or '.join(added)}, so a demo "
                     f"{' and '.join(parts)} {'are' if len(parts) > 1 else 'is'} used. ")
    captions.append(("resonance.png",
                     f"Resonance. {demo_text}Steady-state amplitude measured at "
                     f"{len(omegas)} drive frequencies {omegas[0]:.3g}–{omegas[-1]:.3g} rad/s "
                     f"({res.simulated:.0f} s each, all in one batch) against "
                     f"A(ω) = (F0/m)/√((ω0² − ω²)² + (2γω)²) ({_settings(rcfg)}). "
                     f"Peak measured {ap * 1e3:.3g} mm at {wp:.4g} rad/s; theory {at * 1e3:.3g} mm "
                     f"at {wt:.4g} rad/s; Q = ω0/2γ = {res.omega0 / (2 * res.gamma):.3g}; "
                     f"median difference {100 * np.median(err):.2g} %."))

    # 7. integrators
    free = free_motion(cfg)
    runs = integrator_runs(cfg, duration)
    fig = integrators_figure(cfg, runs)
    written += save_figure(fig, out, "integrators")
    parts = []
    for name in INTEGRATORS:
        run = runs[name]
        if isinstance(run, str):
            parts.append(f"{INTEGRATORS[name].label} is unstable at this step")
            continue
        _, peaks = per_period_max(run.t, energy_error(run, oscillation_energy(free)),
                                  period_of(free))
        parts.append(f"{INTEGRATORS[name].label} {_fmt_err(peaks[-1])}")
    free_text = "" if free is cfg else " (without its drive, released away from equilibrium)"
    captions.append(("integrators.png",
                     f"The integrators' energy error: the same config{free_text} "
                     f"(dt = {cfg.physics.dt:g} s, {duration:g} s) with Euler, Euler-Cromer "
                     f"(the page's), velocity Verlet and RK4; the largest absolute E − E0 in "
                     f"each period as a fraction of ½kA². Euler's grows every period; "
                     f"Euler-Cromer's and Verlet's stay bounded; RK4's is tiny and drifts "
                     f"slowly. Last period: " + ", ".join(parts) + "."))

    # 8. the limits of Hooke's law
    hcfg = hooke_config(cfg)
    htraj = render.simulate(hcfg, run_duration(hcfg))
    fig = hooke_figure(hcfg, htraj)
    written += save_figure(fig, out, "hooke")
    hosc = theory.Oscillator.from_config(hcfg)
    source = "this config" if hcfg is cfg else "configs/overstretched.toml"
    kick = (f", ball kicked at {abs(hosc.v0):.3g} m/s from equilibrium"
            if abs(hosc.x0) < 1e-9 and hosc.v0 else "")
    if htraj.L0[-1] != htraj.L0[0]:
        outcome = (f"Stretched past the limit the spring yields: L0 grows from "
                   f"{htraj.L0[0]:.3f} m to {htraj.L0[-1]:.3f} m, a permanent set of "
                   f"{100 * (htraj.L0[-1] - htraj.L0[0]):.3g} cm, and the ball settles about a "
                   f"lower equilibrium.")
        below = ("Hooke's line up to the limit, flow at the limit, unloading parallel to it; "
                 "a stiffening spring (k3) curves up.")
    else:
        outcome = "The spring never reaches its elastic limit in this run."
        below = "Hooke's line, a stiffening spring (k3) and the elastic limit."
    k3 = f", k3 = {hcfg.spring.k3:g} N/m³" if hcfg.spring.k3 else ""
    captions.append(("hooke.png",
                     f"The limits of Hooke's law ({source}: {_settings(hcfg)}{k3}, elastic "
                     f"limit {hcfg.spring.yield_stretch:g} m of stretch{kick}). {outcome} "
                     f"Below: spring tension against extension: {below}"))

    # 9. film strip
    strip = filmstrip_frames(cfg, backend=backend, antialias=antialias)
    fig = filmstrip_figure(strip)
    written += save_figure(fig, out, "filmstrip", formats=("png",))
    captions.append(("filmstrip.png",
                     f"One period (T = {strip.period:.4f} s) in {len(strip.tiles)} stills at "
                     f"t = 0, T/{len(strip.tiles)}, …; the dashed line marks the equilibrium "
                     f"{osc.equilibrium_stretch * 100:.3g} cm below the relaxed spring's end "
                     f"({settings})."))

    # 10. GIF
    gif = out / "oscillation.gif"
    stats, (gw, gh, gfps, gper) = make_gif(cfg, gif, backend=backend, antialias=antialias)
    written.append(gif)
    captions.append(("oscillation.gif",
                     f"The oscillation in real time, looping: {gper} period{'s' * (gper > 1)} "
                     f"({stats.frames} frames at {gfps} fps, {gw}×{gh} px, "
                     f"{gif.stat().st_size / 1e3:.0f} kB) ({settings})."))

    # 11. the gallery snippet
    order = ["scene.png", "filmstrip.png", "oscillation.gif", "position.png", "energy.png",
             "phase.png", "damped.png", "resonance.png", "integrators.png", "hooke.png"]
    by_name = dict(captions)
    vector = sorted(p.name for p in written if p.suffix == ".svg")
    written.append(write_text(out / "figures.wiki",
                              gallery([(n, by_name[n]) for n in order], vector)))
    return written
