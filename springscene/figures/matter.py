"""The figures of the ball-and-spring model of matter, from :func:`springscene.science.matter.measure`.

``pulse.png`` (space-time picture of the pulse, arrivals and the fitted line of slope
1/v), ``dispersion.png`` (the measured modes on omega(q) over their spectra, and each
mode's error), ``pull.png`` and ``thermal.png``: palette PNGs of a few tens of kB,
written atomically.
"""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np

from ..model.constants import BOLTZMANN
from ..science.matter import ARRIVAL_FRACTION, measure
from ..settings import Config
from ..view.plotstyle import BLACK, BLUE, GREY, VERMILLION, new_figure, style
from ..units import MINUS, percent, prefixes, si_prefix
from .files import prepare_out_dir, save_png
from .gallery import check_prefix

# ---- figures -----------------------------------------------------------------------------

SPECTRUM_DB = 60          # the dispersion figure's spectra: this many dB below each mode's peak
SHADE = "#e6e6e6"         # a shaded span (the palette PNG whitens anything above 245)


def si_scale(top: float) -> tuple[float, str]:
    """(factor, prefix) that shows values up to ``top`` as 1 to 999 of the prefixed unit."""
    return si_prefix(top, largest="", smallest="z")


def power_scale(top: float) -> tuple[float, str]:
    """(10^k, label) for an axis in units of 10^k when ``top`` is 1e4 or more, else (1, "")."""
    if abs(top) < 1e4:
        return 1.0, ""
    k = int(math.floor(math.log10(abs(top))))
    return 10.0 ** k, f"$10^{{{k}}}$ "


def _pct(x: float) -> str:
    return percent(x, minus=MINUS)


def pulse_figure(result: dict):
    """Space-time picture of the kicked pulse: displacement (or velocity) of each atom
    (layer) against time, the arrivals and the fitted line of slope 1/v."""

    geo, rec = result["_geometry"], result["_record"]
    s = result["speed_of_sound"]
    lat = geo.lat
    cfg = result["_config"]
    velocity = s["signal"] == "velocity"
    sign = 1.0 if cfg.start.kick[0] > 0 else -1.0
    data = sign * (rec.pulse_v if velocity else rec.pulse)
    t = rec.t_pulse
    nx = geo.shape[0]
    L = (nx - 1) * lat.d
    lf, lp = si_scale(L)
    tf, tp = si_scale(t[-1])
    if velocity:
        vf, vp, vunit = 1.0, "", "m/s"
    else:
        vf, vp = si_scale(np.abs(data).max())
        vunit = f"{vp}m"
    lim = float(np.percentile(np.abs(data), 99.5)) or 1.0
    n_all, t_all, ok = s["_all"]
    fit = s["fit"]
    with style():
        fig = new_figure(540)
        ax = fig.subplots()
        img = ax.imshow(data / vf, origin="lower", aspect="auto", cmap="RdBu_r",
                        vmin=-lim / vf, vmax=lim / vf, interpolation="nearest",
                        extent=(-0.5 * lat.d / lf, (nx - 0.5) * lat.d / lf, 0, t[-1] / tf))
        bar = fig.colorbar(img, ax=ax, pad=0.01, aspect=30)
        bar.set_label(f"{'velocity' if velocity else 'displacement'} along x ({vunit})")
        x_at = (n_all + geo.source) * lat.d / lf
        ax.plot(x_at[ok], t_all[ok] / tf, "o", ms=3, color=BLACK, mec="none",
                label=f"arrival: {ARRIVAL_FRACTION:.1%} of the first peak ({s['atoms']} atoms)")
        if (~ok).any():
            ax.plot(x_at[~ok], t_all[~ok] / tf, "o", ms=3, mfc="none", mec=BLACK, mew=0.7,
                    label="arrival, not fitted (near the kick or the reflection)")
        n_line = np.linspace(0, geo.wall - geo.source, 200)
        t_line = fit["t0"] + fit["tau"] * n_line
        ax.plot((n_line + geo.source) * lat.d / lf, t_line / tf, "-", color=BLACK, lw=1.2,
                label=f"fit, slope 1/v: v = {s['measured']:.5g} m/s "
                      f"(theory {s['theory']:.5g}, {_pct(s['measured'] / s['theory'] - 1)})")
        ax.set_xlim(-0.5 * lat.d / lf, (nx - 0.5) * lat.d / lf)
        ax.set_ylim(0, t[-1] / tf)
        ax.set_xlabel(f"position along the chain x ({lp}m)")
        ax.set_ylabel(f"time t ({tp}s)")
        ax.grid(False)
        ax.legend(loc="lower right", fontsize=9.5)
        what = "crystal's layers" if not lat.is_chain else "chain"
        ax.set_title(f"A kick at one end crosses the {what} at the speed of sound "
                     f"d$\\sqrt{{k/m}}$")
    return fig


def dispersion_figure(result: dict):
    """ω(q): the measured normal-mode frequencies on the theory curve, over the modes'
    spectra (faint); below, each mode's relative error."""

    geo = result["_geometry"]
    lat = geo.lat
    D = result["dispersion"]
    q = np.array(D["q"])
    meas = np.array(D["measured"])
    omega, spectra = D["_spectrum"]
    lf, lp = next(((f, p) for f, p in reversed(prefixes("", "z")) if math.pi / lat.d * f >= 1),
                  (1.0, ""))
    qf = 1 / lf
    w_top = 1.12 * 2 * lat.omega0
    wf, wl = power_scale(w_top)
    pooled = _pooled_spectra(omega, spectra, w_top)
    dq = q[1] - q[0] if len(q) > 1 else q[0]
    q_curve = np.linspace(0, math.pi / lat.d, 400)
    with style():
        fig = new_figure(620)
        top, bottom = fig.subplots(2, 1, height_ratios=[3, 1.1])
        db = 20 * np.log10(np.maximum(pooled, 1e-12))
        top.imshow(db, origin="lower", aspect="auto", cmap="Greys", vmin=-SPECTRUM_DB,
                   vmax=SPECTRUM_DB * 0.6, interpolation="nearest",
                   extent=((q[0] - dq / 2) / qf, (q[-1] + dq / 2) / qf, 0, w_top / wf))
        top.plot(q_curve / qf, lat.sound_speed * q_curve / wf, "--", color=GREY, lw=1,
                 label="sound line ω = v q, v = d$\\sqrt{k/m}$")
        top.plot(q_curve / qf, lat.dispersion(q_curve) / wf, "-", color=BLACK, lw=1.4,
                 label="theory ω = 2$\\sqrt{k/m}$ |sin(q d/2)|")
        top.plot(q / qf, meas / wf, "o", ms=3.2, color=VERMILLION, mec="none",
                 label=f"measured: FFT of each of the {len(q)} normal modes "
                       f"(grey: its spectrum, {SPECTRUM_DB:g} dB)")
        top.axvline(math.pi / lat.d / qf, color=GREY, lw=0.9, ls=":")
        top.text(math.pi / lat.d / qf, 0.985 * w_top / wf, " π/d ", ha="right", va="top",
                 color=GREY, fontsize=10)
        top.set_xlim(0, 1.04 * math.pi / lat.d / qf)
        top.set_ylim(0, w_top / wf)
        top.set_ylabel(f"angular frequency ω ({wl}rad/s)")
        top.legend(loc="lower right", fontsize=10)
        top.grid(False)
        top.set_title(f"Dispersion of a {geo.shape[0]}-atom chain: k = {lat.k:g} N/m, "
                      f"m = {lat.m:.3g} kg, d = {lat.d / lf:.3g} {lp}m")
        _dispersion_errors(bottom, D, q / qf, result["_config"].physics.integrator, lp,
                           top.get_xlim())
    return fig


def _pooled_spectra(omega: np.ndarray, spectra, w_top: float, rows: int = 360) -> np.ndarray:
    """The modes' spectra, pooled (max) onto a coarse frequency grid from 0 to ``w_top``
    for the picture: one column per mode, ``rows`` rows."""
    edges = np.searchsorted(omega, np.linspace(0, w_top, rows + 1))
    return np.array([[spec[a:max(b, a + 1)].max() for a, b in zip(edges[:-1], edges[1:])]
                     for spec in spectra]).T


def _dispersion_errors(ax, D: dict, x: np.ndarray, integrator: str, lp: str,
                       xlim: tuple[float, float]) -> None:
    """The bottom of :func:`dispersion_figure`: each mode's relative error (%) at ``x``
    (the wavenumbers as shown, in 1/``lp``m), and the integrator's own frequency shift."""
    th = np.array(D["theory"])
    rel = 100 * (np.array(D["measured"]) / th - 1)
    integ = D.get("integrator_theory")
    ax.axhline(0, color=GREY, lw=0.8)
    if integ is not None:
        ax.plot(x, 100 * (np.array(integ) / th - 1), "-", color=BLUE, lw=1.1,
                label=f"{integrator}'s own shift, (2/dt) asin(ω dt/2)")
    ax.plot(x, rel, "o", ms=3, color=VERMILLION, mec="none",
            label=f"measured (largest {100 * D['max_relative_error']:.3f} %)")
    span = max(np.abs(rel).max(), 0.01) * 1.6
    ax.set_ylim(-span, span)
    ax.set_xlim(xlim)
    ax.set_xlabel(f"wavenumber q ({lp}m$^{{-1}}$)" if lp else "wavenumber q (m$^{-1}$)")
    ax.set_ylabel("error (%)")
    ax.legend(loc="lower right", fontsize=9, ncol=2)


def thermal_figure(result: dict):
    """Kinetic and bond energy per atom against time: equipartition after the start."""

    T, e = result["temperature"], result["equipartition"]
    t, K, U, start = e["_series"]
    ef, ep = si_scale(max(K.max(), U.max()))
    tf, tp = si_scale(t[-1])
    geo = result["_geometry"]
    per_atom = 0.5 * geo.dof / geo.n_free * BOLTZMANN
    with style():
        fig = new_figure(500)
        ax = fig.subplots()
        ax.axvspan(0, t[start] / tf, color=SHADE, lw=0, label="equilibration (left out)")
        ax.plot(t / tf, K / ef, color=VERMILLION, lw=1.1, label="kinetic energy per atom")
        ax.plot(t / tf, U / ef, color=BLUE, lw=1.1, label="bond energy per atom")
        ax.axhline(per_atom * T["start"] / ef, color=GREY, lw=0.9, ls=":",
                   label=f"at the start: $\\frac{{3}}{{2}} k_B T_0$, T$_0$ = {T['start']:g} K")
        if T["theory"] is not None:
            ax.axhline(per_atom * T["theory"] / ef, color=GREY, lw=1.2, ls="--",
                       label="harmonic theory: half each")
        ax.set_xlim(0, t[-1] / tf)
        ax.set_ylim(0, 1.5 * per_atom * T["start"] / ef)
        ax.set_xlabel(f"time t ({tp}s)")
        ax.set_ylabel(f"energy per atom ({ep}J)")
        ax.legend(loc="upper right", fontsize=9.5, ncol=2)
        th = f" (theory T$_0$/2 = {T['theory']:g} K)" if T["theory"] is not None else ""
        digits = max(0, 1 - int(math.floor(math.log10(T["error"])))) if T["error"] > 0 else 2
        ax.set_title(f"Equipartition: T = {T['measured']:.{digits}f} ± {T['error']:.{digits}f} K"
                     f"{th}, "
                     f"<K>/<U$_s$> = {e['measured']:.4f}")
    return fig


def pull_figure(result: dict):
    """The pulled bar's strain against time, settling at F / (ny nz k d)."""

    geo = result["_geometry"]
    Y = result["youngs_modulus"]
    t, e = Y["_series"]
    nx = geo.shape[0]
    strain = e / ((nx - 1) * geo.lat.d)
    tf, tp = si_scale(t[-1])
    with style():
        fig = new_figure(460)
        ax = fig.subplots()
        ax.axvspan(0.8 * t[-1] / tf, t[-1] / tf, color=SHADE, lw=0,
                   label=f"last fifth: changes {Y['settled']['change_last_fifth']:.2%}")
        ax.plot(t / tf, 100 * strain, color=BLUE, lw=1.4, label="strain of the pulled bar")
        ax.axhline(100 * Y["strain"]["theory"], color=GREY, ls="--", lw=1.1,
                   label="theory F / (n$_y$ n$_z$ k d)")
        ax.set_xlim(0, t[-1] / tf)
        ax.set_xlabel(f"time t ({tp}s)")
        ax.set_ylabel("strain (%)")
        ax.legend(loc="lower right", fontsize=10)
        ax.set_title(f"Young's modulus: Y = {Y['measured'] / 1e9:.4g} GPa measured, "
                     f"k/d = {Y['theory'] / 1e9:.4g} GPa ({_pct(Y['measured'] / Y['theory'] - 1)})")
    return fig


def make_figures(cfg: Config, out_dir: str | Path, prefix: str = "") -> list[Path]:
    """Write the lattice config's figures (PNG) into ``out_dir``: ``pulse.png`` (a kick),
    ``dispersion.png`` (a chain), ``pull.png`` (a pull), ``thermal.png`` (a temperature),
    each name after ``prefix`` (:func:`.wiki.check_prefix`).

    Measured first, then written atomically; on an error no new file is left behind.
    """

    prefix = check_prefix(prefix)
    created = not Path(out_dir).exists()
    out = prepare_out_dir(out_dir)
    makers = (("speed_of_sound", "pulse", pulse_figure),
              ("dispersion", "dispersion", dispersion_figure),
              ("youngs_modulus", "pull", pull_figure),
              ("temperature", "thermal", thermal_figure))
    written: list[Path] = []
    try:
        result = measure(cfg)
        for key, stem, draw in makers:
            if key in result:
                written.append(save_png(draw(result), out / f"{prefix}{stem}.png"))
    except BaseException:
        for path in written:
            path.unlink(missing_ok=True)
        if created and not any(out.iterdir()):     # nor the folder this call made
            out.rmdir()
        raise
    return written
