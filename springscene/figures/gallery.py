"""The words of the wiki page's figure set: a caption per figure, with the values behind
it (``*_caption``), and the MediaWiki ``<gallery>`` snippet that ``figures.wiki`` holds
(:func:`gallery`).

Each caption is made from the data its figure was drawn from (runs and measurements
from :mod:`.oscillator`), so the numbers a caption states are the figure's.
"""

from __future__ import annotations

import re
from pathlib import Path

import numpy as np

from .. import render
from ..errors import UserError
from ..model import physics
from ..model.integrators import INTEGRATORS
from ..science import sweep, theory
from ..settings import Config
from ..units import MINUS, percent
from .media import Filmstrip
from .notation import _fmt_err
from .oscillator import (DEMO_B, DEMO_DRIVE_AMPLITUDE, along, energy_error, free_motion,
                         is_linear, oscillation_energy, per_period_max, period_of,
                         position_residual)

# the files in the order the gallery shows them
GALLERY_ORDER = ("scene.png", "filmstrip.png", "oscillation.gif", "position.png", "energy.png",
                 "phase.png", "damped.png", "resonance.png", "integrators.png", "hooke.png")


def _settings(cfg: Config) -> str:
    """k, m, dt, integrator, b, drive: the values behind a figure, for its caption."""
    d = cfg.drive
    drive = "no drive" if not cfg.driven else (
        f"{'support' if d.type == 'support' else 'force'} drive "
        f"A = {d.amplitude:g} {'m' if d.type == 'support' else 'N'} at ω = {d.omega:.4g} rad/s")
    return (f"k = {cfg.spring.k:g} N/m, m = {cfg.ball.m:g} kg, L0 = {cfg.spring.L0:g} m, "
            f"dt = {cfg.physics.dt:g} s, {INTEGRATORS[cfg.physics.integrator].label}, "
            f"b = {cfg.damping.b:g} kg/s, {drive}")


def _pct(measured: float | None, expected: float | None) -> str:
    if measured is None or not expected:
        return "n/a"
    return percent((measured - expected) / abs(expected), minus=MINUS)


# ---- a caption per figure -----------------------------------------------------------------

def scene_caption(cfg: Config) -> str:
    """``scene.png``: what the still at t = 0 shows and where the ball starts."""
    osc = theory.Oscillator.from_config(cfg)
    x0 = osc.x0
    if abs(x0) < 1e-9 and osc.v0 == 0:
        where = "at rest at equilibrium"
    elif osc.v0 == 0:
        where = (f"released from rest {abs(x0) * 100:.3g} cm {'below' if x0 < 0 else 'above'} "
                 f"equilibrium")
    else:
        where = f"starting {x0 * 100:.3g} cm from equilibrium at {osc.v0:.3g} m/s"
    return (f"The scene at t = 0: holder, spring (k = {cfg.spring.k:g} N/m, "
            f"L0 = {cfg.spring.L0:g} m) and ball (m = {cfg.ball.m:g} kg), {where}; "
            f"the equilibrium stretch is mg/k = {osc.equilibrium_stretch:.4f} m. "
            f"Rendered off-screen, {cfg.scene.width}×{cfg.scene.height} px.")


def position_caption(cfg: Config, traj: physics.Trajectory, result: dict) -> str:
    """``position.png``: the period measured against theory, and the residual's size.
    ``result`` is :func:`.oscillator.analyze`'s over the run ``traj``."""
    osc = theory.Oscillator.from_config(cfg)
    meas, th = result["measured"], result["theory"]
    T_meas = meas["period"]
    resid = np.abs(position_residual(cfg, traj))
    y, _ = along(cfg, traj)
    amp = osc.amplitude or float(np.abs(y - y.mean()).max()) or 1.0
    period_text = (f"Period measured {T_meas:.5f} s against theory {th['period']:.5f} s "
                   f"({_pct(T_meas, th['period'])})" if T_meas and th["period"] else
                   "No full period in the run")
    form = ("y_eq + x0 cos(ω0 t)" if osc.regime == "undamped" and not cfg.driven and osc.v0 == 0
            else "of the linear model")
    if not is_linear(cfg):
        resid_text = (" The closed form is Hooke's linear model; the residual is mostly the "
                      "spring's stiffening (k3) or yield.")
    elif np.all(np.isnan(resid)):
        resid_text = ""
    else:
        resid_text = (f" The residual is {INTEGRATORS[cfg.physics.integrator].label}'s phase "
                      f"error and grows slowly: at most {np.nanmax(resid) * 1e3:.2g} mm "
                      f"({100 * np.nanmax(resid) / amp:.2g} % of the {amp * 100:.3g} cm "
                      f"amplitude) over {traj.t[-1]:g} s.")
    return (f"Position y(t): the simulation ({_settings(cfg)}) against the closed form "
            f"{form}, ω0 = √(k/m) = {osc.omega0:.4g} rad/s. {period_text}."
            f"{resid_text}")


def energy_caption(cfg: Config, traj: physics.Trajectory, result: dict) -> str:
    """``energy.png``: the oscillation energy and how far E + E_thermal strays from it."""
    scale = theory.Oscillator.from_config(cfg).energy
    if cfg.driven:
        energy_text = "The drive does work on the ball, so E + E_thermal is not constant."
    else:
        drift = float(np.abs(energy_error(traj, scale)).max())
        energy_text = (f"The oscillation energy ½kA² is {scale * 1e3:.3g} mJ (measured "
                       f"{result['measured']['energy'] * 1e3:.3g} mJ); E + E_thermal stays "
                       f"within {100 * drift:.2g} % of it over {traj.t[-1]:g} s.")
    return (f"Energy: K, Us = ½k(ΔL)², Ug = mgy (zero at the holder) and "
            f"E = K + Us + Ug ({_settings(cfg)}); below, measured from rest at equilibrium, "
            f"K and Us + Ug trade places. {energy_text}")


def phase_caption(cfg: Config, traj: physics.Trajectory, spiral: Config | None,
                  demo: bool) -> str:
    """``phase.png``: the closed form's shape; ``spiral`` is the damped config whose run
    is drawn beside it (None when none is), ``demo`` whether its damping is the demo's."""
    osc = theory.Oscillator.from_config(cfg)
    shape = (f"the closed form is the ellipse (x/A)² + (v/ω0A)² = 1 with "
             f"A = {osc.amplitude * 100:.3g} cm, ω0A = {osc.omega0 * osc.amplitude:.3g} m/s"
             if osc.regime == "undamped" and not cfg.driven and is_linear(cfg)
             else "the dashed line is the closed form of the linear model")
    return (f"Phase portrait: velocity against displacement from equilibrium over "
            f"{traj.t[-1]:g} s ({_settings(cfg)}); {shape}"
            + (f". In light blue the same ball with drag b = {spiral.damping.b:g} kg/s"
               + (" (demo)" if demo else "") + " spirals into equilibrium."
               if spiral is not None else "."))


def damped_caption(dcfg: Config, demo: bool, result: dict) -> str:
    """``damped.png``: gamma, the decay rate measured from the peaks and the heat made.
    ``result`` is :func:`.oscillator.analyze`'s over the damped run."""
    dosc = theory.Oscillator.from_config(dcfg)
    rate = result["measured"].get("damping_rate")
    demo_text = (f"This config has no damping, so a demo damping b = {DEMO_B:g} kg/s is "
                 f"added. " if demo else "")
    shape = ("inside the envelope y_eq ± A e^(−γt)" if dosc.omega_d > 0
             else "against the closed form")
    rate_text = (f" Decay rate from the successive peaks: {rate:.4f} /s (theory "
                 f"{dosc.decay_rate:.4g} /s, {_pct(rate, dosc.decay_rate)})."
                 if rate is not None else "")
    return (f"Damped oscillation. {demo_text}y(t) ({_settings(dcfg)}) {shape}, "
            f"γ = b/2m = {dosc.gamma:.4g} /s ({dosc.regime}).{rate_text} Heat made by "
            f"the drag: {result['measured']['energy_lost'] * 1e3:.3g} mJ in "
            f"{result['duration']:g} s.")


def resonance_caption(rcfg: Config, added: list[str], omegas: np.ndarray,
                      res: sweep.SweepResult) -> str:
    """``resonance.png``: the sweep, its peak against theory, Q and the median difference;
    ``added`` is what :func:`.oscillator.demo_driven` added to the config."""
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
    return (f"Resonance. {demo_text}Steady-state amplitude measured at "
            f"{len(omegas)} drive frequencies {omegas[0]:.3g}–{omegas[-1]:.3g} rad/s "
            f"({res.simulated:.0f} s each, all in one batch) against "
            f"A(ω) = (F0/m)/√((ω0² − ω²)² + (2γω)²) ({_settings(rcfg)}). "
            f"Peak measured {ap * 1e3:.3g} mm at {wp:.4g} rad/s; theory {at * 1e3:.3g} mm "
            f"at {wt:.4g} rad/s; Q = ω0/2γ = {res.omega0 / (2 * res.gamma):.3g}; "
            f"median difference {100 * np.median(err):.2g} %.")


def integrators_caption(cfg: Config, runs: dict[str, physics.Trajectory | str],
                        duration: float) -> str:
    """``integrators.png``: each integrator's energy error in the last period of ``runs``
    (:func:`.oscillator.integrator_runs` over ``duration``)."""
    free = free_motion(cfg)
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
    return (f"The integrators' energy error: the same config{free_text} "
            f"(dt = {cfg.physics.dt:g} s, {duration:g} s) with Euler, Euler-Cromer "
            f"(the page's), velocity Verlet and RK4; the largest absolute E − E0 in "
            f"each period as a fraction of ½kA². Euler's grows every period; "
            f"Euler-Cromer's and Verlet's stay bounded; RK4's is tiny and drifts "
            f"slowly. Last period: " + ", ".join(parts) + ".")


def hooke_caption(cfg: Config, hcfg: Config, htraj: physics.Trajectory) -> str:
    """``hooke.png``: the config shown (``hcfg``, :func:`.oscillator.hooke_config` of
    ``cfg``) and whether its spring took a permanent set in the run ``htraj``."""
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
    return (f"The limits of Hooke's law ({source}: {_settings(hcfg)}{k3}, elastic "
            f"limit {hcfg.spring.yield_stretch:g} m of stretch{kick}). {outcome} "
            f"Below: spring tension against extension: {below}")


def filmstrip_caption(cfg: Config, strip: Filmstrip) -> str:
    """``filmstrip.png``: the period and where the dashed equilibrium line is."""
    osc = theory.Oscillator.from_config(cfg)
    return (f"One period (T = {strip.period:.4f} s) in {len(strip.tiles)} stills at "
            f"t = 0, T/{len(strip.tiles)}, …; the dashed line marks the equilibrium "
            f"{osc.equilibrium_stretch * 100:.3g} cm below the relaxed spring's end "
            f"({_settings(cfg)}).")


def gif_caption(cfg: Config, gif: Path, stats: render.RenderStats,
                attempt: tuple[int, int, int, int]) -> str:
    """``oscillation.gif``: how long, how many frames, how big; ``attempt`` is the
    (width, height, fps, periods) :func:`.media.make_gif` settled on."""
    gw, gh, gfps, gper = attempt
    return (f"The oscillation in real time, looping: {gper} period{'s' * (gper > 1)} "
            f"({stats.frames} frames at {gfps} fps, {gw}×{gh} px, "
            f"{gif.stat().st_size / 1e3:.0f} kB) ({_settings(cfg)}).")


# ---- the gallery --------------------------------------------------------------------------

PREFIX_CHARS = re.compile(r"[\w.()-]*")   # letters, digits, _ . ( ) -: safe on disk and wiki


def check_prefix(prefix: str) -> str:
    """A file-name prefix (``BallSpring_``): letters, digits and ``_ . ( ) -`` only, not
    starting with a dot, at most 100 characters; else bad input naming ``--prefix``."""
    prefix = str(prefix)
    if not PREFIX_CHARS.fullmatch(prefix) or prefix.startswith(".") or len(prefix) > 100:
        raise UserError(f"--prefix {prefix!r}: use letters, digits and _ . ( ) - only "
                        "(not starting with a dot, at most 100 characters)")
    return prefix


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
