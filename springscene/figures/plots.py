"""The wiki page's plots, drawn with matplotlib in :mod:`springscene.view.plotstyle`'s fixed
style: position against the closed form, energy, the phase portrait, the damped envelope,
resonance, the integrators' energy error and the limits of Hooke's law.

Each ``*_figure`` function draws one figure from data passed in (runs from
:mod:`.oscillator`) and returns a :class:`matplotlib.figure.Figure`, so each can be
tested on its own.
"""

from __future__ import annotations

import math

import numpy as np

from ..model import physics
from ..model.integrators import INTEGRATORS
from ..science import sweep, theory
from ..settings import Config
from ..view.plotstyle import (BLACK, BLUE, GREEN, GREY, ORANGE, PURPLE, SKY, VERMILLION,
                              new_figure, style)
from .notation import _fmt_err, _signed
from .oscillator import (along, axis_of, closed_form, energy_error, free_motion, is_linear,
                         oscillation_energy, per_period_max, period_of, rest_potential)

DEMO_K3 = 1000.0               # N/m^3, for the stiffening curve when the spring has none
INTEGRATOR_COLORS = {"euler": VERMILLION, "euler-cromer": BLUE, "verlet": GREEN, "rk4": PURPLE}


def position_label(cfg: Config) -> str:
    """The label of a position axis: y when the motion is vertical."""
    axis = axis_of(cfg)
    return "$y$ (m)" if np.allclose(axis, (0, 1, 0)) else "position along $-\\vec g$ (m)"


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


def energy_figure(cfg: Config, traj: physics.Trajectory, *, periods: float = 3.0):
    """Top: K, Us, Ug, E (and E_thermal, total) as the engine tallies them;
    bottom: K and U = Us + Ug measured from rest at equilibrium."""
    t = traj.t
    T = period_of(cfg)
    lossy = cfg.damping.b > 0 or bool(np.any(traj.E_thermal))
    span = t[-1] if lossy else min(t[-1], periods * T)
    sel = t <= span + 1e-9
    U_rest = rest_potential(cfg, traj)
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
        if osc.regime == "undamped" and not cfg.driven and is_linear(cfg):
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


def hooke_figure(cfg: Config, traj: physics.Trajectory):
    """Top: y(t) with the equilibrium before and after the permanent set; bottom: spring
    tension against extension (Hooke's line, a stiffening spring, the elastic limit and
    the path the simulation took)."""
    osc = theory.Oscillator.from_config(cfg)
    y, _ = along(cfg, traj)
    holder = float(np.dot(cfg.holder.pos, np.asarray(osc.axis)))
    length = holder - y                            # |L| for a ball below its holder
    yielding = np.flatnonzero(np.diff(traj.L0) != 0) + 1
    with style():
        fig = new_figure(780)
        top, bottom = fig.subplots(2, 1, height_ratios=[1, 1.15])
        _hooke_motion(top, cfg, traj, y, holder, yielding)
        _hooke_force(bottom, cfg, traj, length, yielding)
    return fig


def _hooke_motion(ax, cfg: Config, traj: physics.Trajectory, y: np.ndarray, holder: float,
                  yielding: np.ndarray) -> None:
    """The top of :func:`hooke_figure`: y(t), the span where the spring yields, and the
    equilibrium before and after the permanent set."""
    osc = theory.Oscillator.from_config(cfg)
    sp = cfg.spring
    t = traj.t
    s_eq = theory.stiffening_stretch(sp.k, sp.k3, cfg.ball.m * osc.g)
    y_before = holder - (traj.L0[0] + s_eq)
    y_after = holder - (traj.L0[-1] + s_eq)
    if len(yielding):
        ax.axvspan(t[yielding[0] - 1], t[yielding[-1]], color=ORANGE, alpha=0.3, lw=0,
                   label=f"yielding: $L_0$ {traj.L0[0]:.3f} → {traj.L0[-1]:.3f} m")
    ax.plot(t, y, color=BLUE, lw=1.1, label="$y(t)$")
    ax.axhline(y_before, color=GREEN, ls="--", lw=1.8,
               label=f"equilibrium before: {_signed(y_before)} m")
    ax.axhline(y_after, color=VERMILLION, ls="-.", lw=1.8,
               label=f"after the set: {_signed(y_after)} m")
    ax.set_xlim(0, t[-1])
    lo, hi = min(y.min(), y_after), max(y.max(), y_before)
    ax.set_ylim(lo - 0.06 * (hi - lo), hi + 0.3 * (hi - lo))
    ax.set_xlabel("time $t$ (s)")
    ax.set_ylabel(position_label(cfg))
    start = (f"Kicked at {abs(osc.v0):.3g} m/s" if osc.v0 else
             f"Released {abs(osc.x0) * 100:.3g} cm from equilibrium")
    if len(yielding):
        ax.set_title(f"{start}: the spring yields, the ball settles lower")
    else:
        ax.set_title(f"{start}: the spring stays within its elastic limit")
    ax.legend(loc="upper right", ncol=2, fontsize=10)


def _hooke_force(ax, cfg: Config, traj: physics.Trajectory, length: np.ndarray,
                 yielding: np.ndarray) -> None:
    """The bottom of :func:`hooke_figure`: spring tension against extension (Hooke's line,
    a stiffening spring, the elastic limit, the weight and the simulated path)."""
    sp = cfg.spring
    weight = cfg.ball.m * theory.Oscillator.from_config(cfg).g
    stretch = length - traj.L0
    force = sp.k * stretch + sp.k3 * stretch ** 3
    extension = length - traj.L0[0]
    e_max = max(float(extension.max()), 1.3 * sp.yield_stretch if math.isfinite(
        sp.yield_stretch) else 0.0)
    e = np.linspace(0, 1.1 * e_max, 400)
    ax.plot(e, sp.k * e, color=BLACK, ls="--", lw=1.2,
            label=f"Hooke: $F = k\\,\\Delta L$, $k$ = {sp.k:g} N/m")
    k3 = sp.k3 if sp.k3 > 0 else DEMO_K3
    ax.plot(e, sp.k * e + k3 * e ** 3, color=PURPLE, ls=":", lw=2.2,
            label=f"stiffening: $F = k\\,\\Delta L + k_3\\Delta L^3$, $k_3$ = {k3:g} N/m³"
                  + ("" if sp.k3 > 0 else " (illustration)"))
    if math.isfinite(sp.yield_stretch):
        Fy = sp.k * sp.yield_stretch + sp.k3 * sp.yield_stretch ** 3
        ax.axhline(Fy, color=ORANGE, lw=1.6,
                   label=f"elastic limit: $\\Delta L$ = {sp.yield_stretch:g} m, "
                         f"$F$ = {Fy:.3g} N")
    ax.axhline(weight, color=GREY, lw=1.2, ls="-.",
               label=f"$mg$ = {weight:.3g} N (equilibrium)")
    ax.plot(extension, force, color=BLUE, lw=1.3, label="simulated path")
    ax.set_xlim(min(0.0, float(extension.min())), 1.1 * e_max)
    Fmax = max(float(force.max()), sp.k * 1.1 * e_max)
    ax.set_ylim(min(0.0, float(force.min())) - 0.04 * Fmax, 1.25 * Fmax)
    ax.set_xlabel(f"extension $|L| - L_0$ (m), from the original $L_0$ = {traj.L0[0]:g} m")
    ax.set_ylabel("spring tension (N)")
    ax.set_title("Force against extension: Hooke's line, flow at the limit, "
                 "unloading parallel to it" if len(yielding) else
                 "Force against extension", fontsize=12)
    ax.legend(loc="upper left", fontsize=10)
