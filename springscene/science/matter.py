"""Measurements on the ball-and-spring model of matter (lattice configs), beside theory.

:func:`analyze` simulates a lattice config's own scenario once and measures what
that scenario shows; each quantity is ``{"measured", "theory", "unit", ...}``:

``speed_of_sound`` (a [start] kick with an x component)
    The pulse's arrival at each atom (each x layer of a crystal, its free atoms'
    mean) along the chain, fitted by a line whose slope is 1/v; theory
    v = d sqrt(k/m). A velocity kick spreads dispersively: with the atom behind the
    kicked one held, atom n's displacement is (v0/omega0) J_2n(2 omega0 t), whose
    leading edge is an Airy front, J_nu(nu + z nu^(1/3)) ~ (2/nu)^(1/3) Ai(-2^(1/3) z).
    Its first peak (z = 0.81) therefore lags the line by ~ n^(1/3), a bias of
    1.4-5 % in v for these chains. The arrival is instead the moment the pulse first
    reaches :data:`ARRIVAL_FRACTION` = Ai(0) / max Ai = 0.6628 of its first peak,
    which is z = 0 exactly: the n^(1/3) term vanishes, and the next order, which
    goes as n^(-1/3), is fitted: t_n = t0 + n d / v + b n^(-1/3). Atoms whose peak
    could meet the reflection from the far end (from a first estimate of v over
    the near half of the chain) are left out. With a free kicked end the pulse is
    the atoms' velocity instead of their displacement (the chain then moves on).
    ``first_peak_linear_fit`` gives, for comparison, v from a plain line through
    the first peaks.
``dispersion`` (a chain, kicked along x or thermal)
    The displacements along x projected onto the chain's normal modes (held ends:
    sin modes, q_n = n pi / ((N_free + 1) d); free ends: cos modes, q_n = n pi / (N d);
    held at the start only: q_n = (2n - 1) pi / ((2 N_free + 1) d)); each mode's
    time series Hann-windowed, zero-padded, Fourier transformed, its peak
    interpolated (a parabola through the log magnitudes); against omega(q) =
    2 sqrt(k/m) |sin(q d / 2)|. Euler-Cromer and Verlet run a mode of frequency
    omega at (2/dt) asin(omega dt / 2): ``integrator_theory`` gives that too. Only the
    longitudinal modes are linear: sideways, a bond relaxed at the spacing has no
    tension and so no linear restoring force.
``youngs_modulus`` (a [pull] force)
    stress F / (ny nz d^2) over strain, the settled elongation (the pulled face's
    mean x minus the held face's, less (nx - 1) d) over (nx - 1) d; theory Y = k/d.
    The bar must have settled: its elongation may change by less than
    :data:`SETTLE_TOLERANCE` over the last fifth of the run, else a
    :class:`UserError` says what to change.
``temperature`` and ``equipartition`` (a [start] temperature)
    After an equilibration (one period of the slowest mode's kinetic energy),
    T = 2 <K> / (dof k_B), dof = 3 N_free (less 3 with no atom held), against half
    the start temperature: a harmonic crystal started with all its energy kinetic
    shares it equally between K and the bonds' Us. Equipartition: <K> per atom
    against <Us> per atom, and the kinetic share of x, y and z (a third each).
    Errors are standard errors of :data:`THERMAL_BLOCKS` block means. In this
    model x, y and z motions do not exchange energy at linear order, so each
    direction keeps the share the random start gave it: the share's error adds the
    start's sampling spread, sqrt(4 / (27 N_free)). Theory is given only when every
    motion has a linear restoring force (every line of atoms held somewhere, e.g.
    the outer layer held); a chain's sideways motion has none.

    The bonds' sideways stretch is of second order in the displacement, so the model
    is harmonic only for small thermal strain: for aluminium <K>/<Us> - 1 comes out
    +0.2 % at 30 K and +1.0 % at 300 K (long runs); the output notes it.

The speed of sound comes out within 0.01 % of theory for the aluminium and lead chains
(a line through the first peaks: -1.4 %) and 0.1 % for the 20-ball chain; every mode's
frequency within 0.04 % (the lowest mode's FFT over four periods) plus the integrator's
own shift (0.25 % at the 20-ball chain's zone edge).

Run length: each measurement needs a least simulated time (the dispersion four
periods of the lowest mode; the pulse to cross 90 % of the chain; the thermal
averages an equilibration and eight blocks). When the config's [render] duration
is shorter, the run is lengthened for the measurement and ``notes`` says so; an
explicit ``--duration`` that is too short is refused with the length needed. A pulse
that cannot be timed (too short a chain) is a note when something else is measured.

The figures of these measurements are :mod:`springscene.figures.matter`'s.
"""

from __future__ import annotations

import math

import numpy as np

from ..errors import UserError
from ..model.constants import BOLTZMANN
from ..model.integrators import INTEGRATORS
from ..settings import Config
from .. import config
from . import tables
from .lattice_run import THERMAL_BLOCKS, Geometry, Record, plan_run, simulate

AI_0 = 0.355028053887817239          # Ai(0)
AI_MAX = 0.535656656015700           # max Ai = Ai(-1.0187929716474710)
ARRIVAL_FRACTION = AI_0 / AI_MAX     # 0.6628: the Airy front's z = 0
PEAK_FLOOR = 0.3                     # a first peak is at least this share of the record's largest
MIN_ARRIVALS = 5                     # atoms the pulse fit needs (it has three parameters)
ZERO_PAD = 16                        # FFT length over the record's
SETTLE_TOLERANCE = 0.01              # the bar's elongation over the last fifth of the run
KEYS = ("speed_of_sound", "dispersion", "youngs_modulus", "temperature", "equipartition")


# ---- speed of sound ----------------------------------------------------------------------

def _parabola_peak(y: np.ndarray, i: int) -> tuple[float, float]:
    """Sub-sample offset and height of the peak at sample i (a parabola through 3 points)."""
    if i <= 0 or i >= len(y) - 1:
        return 0.0, float(y[i])
    a, b, c = y[i - 1], y[i], y[i + 1]
    den = a - 2 * b + c
    if den >= 0:
        return 0.0, float(b)
    off = 0.5 * (a - c) / den
    return float(off), float(b - 0.25 * (a - c) * off)


def first_peak(y: np.ndarray, floor: float = PEAK_FLOOR) -> int | None:
    """Index of the first local maximum of y at least ``floor`` times y's largest value."""
    top = y.max()
    if not top > 0:
        return None
    i = np.flatnonzero((y[1:-1] >= y[:-2]) & (y[1:-1] > y[2:]) & (y[1:-1] >= floor * top)) + 1
    return int(i[0]) if len(i) else None


def arrival(t: np.ndarray, y: np.ndarray, fraction: float = ARRIVAL_FRACTION
            ) -> tuple[float, float] | None:
    """(arrival, first peak time): when y first reaches ``fraction`` of its first peak,
    interpolated between steps, and when that peak is."""
    i = first_peak(y)
    if i is None:
        return None
    off, top = _parabola_peak(y, i)
    level = fraction * top
    below = np.flatnonzero(y[:i + 1] < level)
    if not len(below):
        return None
    j = int(below[-1])
    ta = t[j] + (level - y[j]) / (y[j + 1] - y[j]) * (t[j + 1] - t[j])
    return float(ta), float(t[i] + off * (t[1] - t[0]))


def fit_arrivals(n: np.ndarray, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Least squares t = t0 + tau n + b n^(-1/3); returns the coefficients and their errors."""
    A = np.column_stack([np.ones_like(n), n, n ** (-1.0 / 3.0)])
    coef, *_ = np.linalg.lstsq(A, t, rcond=None)
    resid = t - A @ coef
    dof = max(len(t) - 3, 1)
    cov = np.linalg.inv(A.T @ A) * float(resid @ resid) / dof
    return coef, np.sqrt(np.maximum(np.diag(cov), 0.0))


def speed_of_sound(cfg: Config, geo: Geometry, rec: Record) -> dict:
    lat = geo.lat
    sign = 1.0 if cfg.start.kick[0] > 0 else -1.0
    signal = sign * (rec.pulse if geo.held_start else rec.pulse_v)
    t = rec.t_pulse
    nx = geo.shape[0]
    layers = np.arange(geo.kicked_layer, nx)
    if geo.grid_held[-1].all():
        layers = layers[layers < nx - 1]
    rows = []
    for ix in layers:
        a = arrival(t, signal[:, ix])
        if a is not None and first_peak(signal[:, ix]) < len(t) - 2:
            rows.append((ix - geo.source, a[0], a[1]))
    rows = np.array(rows).reshape(-1, 3)
    n_all, t_all, t_peak = rows.T
    d = lat.d
    wall = geo.wall - geo.source           # in spacings from the source

    def usable(tau: float, t0: float) -> np.ndarray:
        w = lambda n: (2 * n) ** (1 / 3) * tau / 2          # the Airy front's width
        back = 2 * wall - n_all                              # the reflection's path
        return ((n_all >= 1.5) & (t_peak + 2 * w(n_all) < t0 + back * tau - 3 * w(back)))

    near = (n_all >= 1.5) & (n_all <= max(wall / 2, 2.5 + MIN_ARRIVALS))
    if near.sum() < MIN_ARRIVALS:
        raise UserError(f"{cfg.source}: the pulse could be timed at only {int(near.sum())} "
                        f"atoms along x; analyze needs {MIN_ARRIVALS} (a longer chain along x, "
                        "or a longer run)")
    coef, _ = fit_arrivals(n_all[near], t_all[near])
    ok = usable(coef[1], coef[0]) if coef[1] > 0 else near
    if ok.sum() < MIN_ARRIVALS:
        ok = near
    coef, err = fit_arrivals(n_all[ok], t_all[ok])
    t0, tau, b = coef
    v = d / tau
    v_err = v * err[1] / tau
    # the naive line through the first peaks, for comparison
    naive = d / np.polyfit(n_all[ok], t_peak[ok], 1)[0]
    resid = t_all[ok] - (t0 + tau * n_all[ok] + b * n_all[ok] ** (-1 / 3))
    return {
        "measured": float(v), "theory": lat.sound_speed, "unit": "m/s", "fit_error": float(v_err),
        "atoms": int(ok.sum()),
        "fit": {"t0": float(t0), "tau": float(tau), "airy_next_order": float(b),
                "rms_residual": float(np.sqrt(np.mean(resid ** 2))), "unit": "s"},
        "arrival_fraction": ARRIVAL_FRACTION,
        "signal": "displacement" if geo.held_start else "velocity",
        "first_peak_linear_fit": float(naive), "first_peak_linear_fit_unit": "m/s",
        "n": n_all[ok].tolist(), "arrival": t_all[ok].tolist(), "arrival_unit": "s",
        "_all": (n_all, t_all, ok),
    }


# ---- dispersion --------------------------------------------------------------------------

def mode_frequency(t: np.ndarray, a: np.ndarray, pad: int = ZERO_PAD
                   ) -> tuple[float, np.ndarray, np.ndarray]:
    """Angular frequency of the strongest line of a(t) (rad/s): Hann window, zero padding,
    a parabola through the log magnitudes at the peak. Also the spectrum (omega, |A|)."""
    n = len(a)
    h = t[1] - t[0]
    win = np.hanning(n)
    nfft = 1 << int(math.ceil(math.log2(n * pad)))
    spec = np.abs(np.fft.rfft((a - a.mean()) * win, nfft))
    omega = 2 * math.pi * np.fft.rfftfreq(nfft, h)
    k = int(np.argmax(spec[1:])) + 1
    if 0 < k < len(spec) - 1 and spec[k - 1] > 0 and spec[k + 1] > 0:
        la, lb, lc = np.log(spec[k - 1:k + 2])
        den = la - 2 * lb + lc
        off = 0.5 * (la - lc) / den if den < 0 else 0.0
    else:
        off = 0.0
    return float((k + off) * (omega[1] - omega[0])), omega, spec


def integrator_frequency(name: str, omega: np.ndarray, dt: float) -> np.ndarray | None:
    """The frequency integrator ``name`` runs a linear mode at, where known (Euler-Cromer
    and Verlet: (2/dt) asin(omega dt/2)); None otherwise."""
    shifted = INTEGRATORS[name].mode_frequency
    return None if shifted is None else shifted(omega, dt)


def dispersion(cfg: Config, geo: Geometry, rec: Record) -> dict:
    lat = geo.lat
    _, q, phi = geo.modes()
    amps = rec.x_modes @ phi                   # (S, modes)
    t = rec.t_modes
    measured, spectra = [], []
    for c in range(amps.shape[1]):
        w, omega, spec = mode_frequency(t, amps[:, c])
        measured.append(w)
        spectra.append(spec / spec.max() if spec.max() > 0 else spec)
    measured = np.array(measured)
    theory = lat.dispersion(q)
    rel = (measured - theory) / theory
    worst = int(np.argmax(np.abs(rel)))
    integ = integrator_frequency(cfg.physics.integrator, theory, cfg.physics.dt)
    out = {
        "measured": measured.tolist(), "theory": theory.tolist(), "unit": "rad/s",
        "q": q.tolist(), "q_unit": "1/m",
        "max_relative_error": float(abs(rel[worst])),
        "worst_mode": worst + 1,
        "modes": len(q),
        "zone_edge": {"measured": float(measured[-1]), "theory": float(theory[-1]),
                      "unit": "rad/s", "q": float(q[-1]), "q_unit": "1/m"},
        "lowest": {"measured": float(measured[0]), "theory": float(theory[0]),
                   "unit": "rad/s", "q": float(q[0]), "q_unit": "1/m"},
        "record": float(t[-1]), "record_unit": "s",
        "integrator_theory": integ.tolist() if integ is not None else None,
        "_spectrum": (omega, np.array(spectra)),
    }
    if integ is not None:
        out["integrator_shift"] = float(np.max(np.abs(integ / theory - 1)))
    if cfg.start.temperature > 0:
        out["note"] = ("a thermal chain's sideways motion has no linear restoring force (its "
                       "bonds have no tension) and pulls on the bonds as it swings, at any "
                       "temperature alike: the longitudinal modes are driven and shifted by it, "
                       "so a thermal chain need not follow omega(q); a kick along x gives the "
                       "harmonic dispersion")
    return out


# ---- Young's modulus ---------------------------------------------------------------------

def youngs_modulus(cfg: Config, geo: Geometry, rec: Record) -> dict:
    lat = geo.lat
    nx, ny, nz = geo.shape
    e, t = rec.elongation, rec.t_pull
    tail = e[int(0.8 * (len(e) - 1)):]
    end = float(e[-1])
    change = float((tail.max() - tail.min()) / abs(end)) if end else math.inf
    if not change < SETTLE_TOLERANCE:
        raise UserError(_unsettled(cfg, geo, float(t[-1]), change))
    F = cfg.pull.force
    stress = F / (ny * nz * lat.d ** 2)
    strain = end / ((nx - 1) * lat.d)
    stiff = lat.k * ny * nz / (nx - 1)          # the bar as springs in series and parallel
    return {
        "measured": stress / strain, "theory": lat.youngs_modulus, "unit": "Pa",
        "stress": {"measured": stress, "unit": "Pa"},
        "strain": {"measured": strain, "theory": F / stiff / ((nx - 1) * lat.d), "unit": ""},
        "elongation": {"measured": end, "theory": F / stiff, "unit": "m"},
        "settled": {"change_last_fifth": change, "tolerance": SETTLE_TOLERANCE},
        "_series": (t, e),
    }


def _unsettled(cfg: Config, geo: Geometry, t_end: float, change: float) -> str:
    lat = geo.lat
    nx = geo.shape[0]
    w1 = float(lat.dispersion(math.pi / ((2 * (nx - 1) + 1) * lat.d)))
    b_crit = 2 * lat.m * w1
    b = cfg.damping.b
    what = (f"its elongation still changes by {change:.2%} over the last fifth of the run "
            f"(analyze needs under {SETTLE_TOLERANCE:.0%})" if math.isfinite(change)
            else "it has not stretched")
    if b == 0:
        fix = (f"add [damping] b (about {b_crit:.2g} kg/s, 2 m omega_min, damps the bar's "
               "slowest mode critically) so that it settles")
    else:
        g = b / (2 * lat.m)
        rate = g if g <= w1 else g - math.sqrt(g * g - w1 * w1)
        need = t_end + math.log(max(change, 1e-300) / (SETTLE_TOLERANCE / 4)) / rate
        fix = (f"run longer (--duration or [render] duration, about {need:.2g} s)")
        if not 0.3 < b / b_crit < 3:
            fix += f", or damp it near critically ([damping] b about {b_crit:.2g} kg/s)"
    return f"{cfg.source}: the pulled bar has not settled by t = {t_end:.3g} s: {what}; {fix}"


# ---- temperature and equipartition -------------------------------------------------------

def _blocks(x: np.ndarray, n: int) -> np.ndarray:
    usable = len(x) - len(x) % n
    return x[len(x) - usable:].reshape(n, -1, *x.shape[1:]).mean(axis=1)


def _sem(blocks: np.ndarray) -> np.ndarray:
    return blocks.std(axis=0, ddof=1) / math.sqrt(len(blocks))


def thermal(cfg: Config, geo: Geometry, rec: Record) -> tuple[dict, dict]:
    lat = geo.lat
    T0 = cfg.start.temperature
    t = rec.t_energy
    t_eq = math.pi / geo.slowest_line_mode()
    start = int(np.searchsorted(t, t_eq - 1e-12 * t_eq))
    start = min(start, len(t) - THERMAL_BLOCKS)
    Kx = rec.K_xyz[start:]
    K = Kx.sum(axis=1)
    Us = rec.Us[start:]
    nf, dof = geo.n_free, geo.dof
    bK, bU, bX = _blocks(K, THERMAL_BLOCKS), _blocks(Us, THERMAL_BLOCKS), _blocks(Kx, THERMAL_BLOCKS)
    floppy = geo.floppy()
    harmonic = not floppy
    T = 2 * K.mean() / (dof * BOLTZMANN)
    T_err = 2 * float(_sem(bK)) / (dof * BOLTZMANN)
    temperature = {
        "measured": float(T), "theory": T0 / 2 if harmonic else None, "unit": "K",
        "error": T_err, "start": T0, "equilibration": float(t[start]), "dof": dof,
        "blocks": THERMAL_BLOCKS,
    }
    ratio_b = bK / bU
    share_b = bX / bX.sum(axis=1, keepdims=True)
    share = Kx.mean(axis=0) / K.mean()
    spread = math.sqrt(4 / (27 * nf))
    share_err = np.sqrt(_sem(share_b) ** 2 + spread ** 2)
    K0 = rec.K_xyz[0]
    equipartition = {
        "measured": float(K.mean() / Us.mean()), "theory": 1.0 if harmonic else None,
        "unit": "", "error": float(_sem(ratio_b)), "quantity": "<K> / <Us>",
        "kinetic_per_atom": {"measured": float(K.mean() / nf), "error": float(_sem(bK) / nf),
                             "unit": "J"},
        "potential_per_atom": {"measured": float(Us.mean() / nf),
                               "error": float(_sem(bU) / nf), "unit": "J"},
        "kinetic_share": {"measured": share.tolist(),
                          "theory": [1 / 3] * 3 if harmonic else None,
                          "error": share_err.tolist(), "start": (K0 / K0.sum()).tolist(),
                          "start_spread": spread, "unit": ""},
        "_series": (t, rec.K_xyz.sum(axis=1) / nf, rec.Us / nf, start),
    }
    strain = math.sqrt(BOLTZMANN * T / lat.k) / lat.d
    temperature["thermal_strain"] = strain
    if harmonic:
        temperature["note"] = equipartition["note"] = (
            f"the harmonic theory holds for small thermal strain; here sqrt(k_B T/k)/d = "
            f"{strain:.2%}, and a bond's sideways stretch is of second order in the "
            "displacement, so the model is slightly anharmonic: <K>/<Us> - 1 and T/(T0/2) - 1 "
            "grow with T (for aluminium, long runs: +0.2 % and +0.2 % at 30 K, +1.0 % and "
            "+0.6 % at 300 K)")
    if floppy:
        note = ("no linear restoring force for the motion along " + ", ".join(floppy)
                + ": that motion is not harmonic, so the harmonic theory (T0/2, <K> = <Us>, "
                "a third each) does not apply")
        temperature["note"] = equipartition["note"] = note
    return temperature, equipartition


# ---- everything --------------------------------------------------------------------------

def measure(cfg: Config, duration: float | None = None) -> dict:
    """:func:`analyze`'s result with the raw series the figures draw (keys starting ``_``)."""
    if not cfg.is_lattice:
        raise UserError(f"{cfg.source}: not a [lattice] config")
    cfg = config.override(cfg, "render", duration=duration)
    geo = Geometry.of(cfg)
    plan = plan_run(cfg, geo, duration)
    rec = simulate(cfg, geo, plan)
    lat = geo.lat
    result = {
        "config": cfg.source,
        "lattice": {"shape": list(lat.shape), "spacing": lat.d, "spacing_unit": "m",
                    "mass": lat.m, "mass_unit": "kg", "k": lat.k, "k_unit": "N/m",
                    "fixed": lat.fixed, "free_atoms": geo.n_free},
        "integrator": cfg.physics.integrator, "dt": cfg.physics.dt, "dt_unit": "s",
        "duration": plan.duration, "duration_unit": "s",
    }
    if "speed_of_sound" in plan.what:
        try:
            result["speed_of_sound"] = speed_of_sound(cfg, geo, rec)
        except UserError as exc:
            if len(plan.what) == 1:
                raise
            plan.notes.append("speed of sound not measured: "
                              + str(exc).removeprefix(f"{cfg.source}: "))
    if "dispersion" in plan.what:
        result["dispersion"] = dispersion(cfg, geo, rec)
    if "youngs_modulus" in plan.what:
        result["youngs_modulus"] = youngs_modulus(cfg, geo, rec)
    if "temperature" in plan.what:
        result["temperature"], result["equipartition"] = thermal(cfg, geo, rec)
    result["notes"] = plan.notes
    result["_geometry"], result["_record"], result["_config"] = geo, rec, cfg
    return result


def public(result: dict) -> dict:
    """The result without its raw series: plain JSON."""
    def clean(x):
        if isinstance(x, dict):
            return {k: clean(v) for k, v in x.items() if not k.startswith("_")}
        if isinstance(x, (list, tuple)):
            return [clean(v) for v in x]
        if isinstance(x, np.generic):
            return x.item()
        return x
    return clean(result)


def analyze(cfg: Config, duration: float | None = None) -> dict:
    """Measured and theoretical quantities of a lattice config's scenario (SI units)."""
    return public(measure(cfg, duration))


# ---- the table ---------------------------------------------------------------------------

def _row(label: str, meas, th, unit: str, err=None) -> str:
    return tables.row(label, meas, th, unit, error=err, label_width=30, measured_width=22)


def table(result: dict) -> str:
    """A readable terminal table: quantity, measured (± standard error), theory, difference."""
    lat = result["lattice"]
    shape = lat["shape"]
    what = (f"chain of {shape[0]} atoms" if shape[1] == shape[2] == 1
            else f"{shape[0]}×{shape[1]}×{shape[2]} lattice")
    lines = [f"{result['config']}: {what} ({lat['free_atoms']} free; d = {lat['spacing']:.4g} m, "
             f"m = {lat['mass']:.4g} kg, k = {lat['k']:g} N/m), {result['integrator']}, "
             f"dt = {result['dt']:g} s, {result['duration']:.4g} s simulated",
             tables.header(30, 22)]
    if "speed_of_sound" in result:
        s = result["speed_of_sound"]
        lines.append(_row(f"speed of sound ({s['atoms']} atoms)", s["measured"], s["theory"],
                          "m/s"))
        lines.append(_row("  (a line through 1st peaks)", s["first_peak_linear_fit"],
                          s["theory"], "m/s"))
    if "dispersion" in result:
        d = result["dispersion"]
        lines.append(_row("dispersion: lowest mode", d["lowest"]["measured"],
                          d["lowest"]["theory"], "rad/s"))
        lines.append(_row("dispersion: zone-edge mode", d["zone_edge"]["measured"],
                          d["zone_edge"]["theory"], "rad/s"))
        lines.append(f"{'  worst of ' + str(d['modes']) + ' modes':<30}"
                     f"{100 * d['max_relative_error']:>20.3f} %{'':>14}{'':>12}  "
                     f"(mode {d['worst_mode']})")
    if "youngs_modulus" in result:
        y = result["youngs_modulus"]
        lines.append(_row("Young's modulus", y["measured"], y["theory"], "Pa"))
        lines.append(_row("  stress F/(ny nz d^2)", y["stress"]["measured"], None, "Pa"))
        lines.append(_row("  strain", y["strain"]["measured"], y["strain"]["theory"], ""))
    if "temperature" in result:
        T = result["temperature"]
        e = result["equipartition"]
        lines.append(_row("temperature", T["measured"], T["theory"], "K", T["error"]))
        lines.append(_row("<K> / <Us>", e["measured"], e["theory"], "", e["error"]))
        lines.append(_row("  K per atom", e["kinetic_per_atom"]["measured"], None, "J",
                          e["kinetic_per_atom"]["error"]))
        lines.append(_row("  Us per atom", e["potential_per_atom"]["measured"], None, "J",
                          e["potential_per_atom"]["error"]))
        ks = e["kinetic_share"]
        for c, name in enumerate("xyz"):
            lines.append(_row(f"  kinetic share {name}", ks["measured"][c],
                              ks["theory"][c] if ks["theory"] else None, "", ks["error"][c]))
    notes = list(result.get("notes", []))
    for key in ("dispersion", "temperature"):
        if key in result and "note" in result[key]:
            notes.append(result[key]["note"])
    if "dispersion" in result and result["dispersion"].get("integrator_shift"):
        notes.append(f"{result['integrator']} runs each mode at (2/dt) asin(omega dt/2): up to "
                     f"{100 * result['dispersion']['integrator_shift']:.3g} % above omega(q) here")
    lines += [f"note: {n}" for n in notes]
    return "\n".join(lines)
