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

:func:`make_figures` draws ``pulse.png`` (space-time picture of the pulse, arrivals and
the fitted line of slope 1/v), ``dispersion.png`` (the measured modes on omega(q) over
their spectra, and each mode's error), ``pull.png`` and ``thermal.png``: palette PNGs of
a few tens of kB, written atomically.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from . import config, physics
from .config import BOLTZMANN, Config
from .errors import UserError
from .lattice import Lattice, build, first_free_layer

AI_0 = 0.355028053887817239          # Ai(0)
AI_MAX = 0.535656656015700           # max Ai = Ai(-1.0187929716474710)
ARRIVAL_FRACTION = AI_0 / AI_MAX     # 0.6628: the Airy front's z = 0
PEAK_FLOOR = 0.3                     # a first peak is at least this share of the record's largest
MIN_ARRIVALS = 5                     # atoms the pulse fit needs (it has three parameters)
SOUND_REACH = 0.9                    # the pulse must cross this share of the chain
DISPERSION_PERIODS = 4.0             # periods of the lowest mode the mode FFT needs
ZERO_PAD = 16                        # FFT length over the record's
SAMPLES_PER_PERIOD = 10              # of the fastest mode, for the mode time series
THERMAL_BLOCKS = 8
SETTLE_TOLERANCE = 0.01              # the bar's elongation over the last fifth of the run
MAX_STEPS = 2_000_000
KEYS = ("speed_of_sound", "dispersion", "youngs_modulus", "temperature", "equipartition")


# ---- the lattice's geometry ---------------------------------------------------------------

@dataclass(frozen=True)
class Geometry:
    """The config's lattice, its held atoms and how a chain's modes and pulse see them."""

    cfg: Config
    lat: Lattice
    held: np.ndarray          # (N,) bool
    free: np.ndarray          # (N_free,) indices

    @classmethod
    def of(cls, cfg: Config) -> "Geometry":
        lat = Lattice.from_config(cfg)
        held = lat.held()
        return cls(cfg, lat, held, np.flatnonzero(~held))

    @property
    def shape(self) -> tuple[int, int, int]:
        return self.lat.shape

    @property
    def grid_held(self) -> np.ndarray:
        return self.held.reshape(self.shape)

    @property
    def n_free(self) -> int:
        return len(self.free)

    @property
    def dof(self) -> int:
        return 3 * self.n_free - (3 if not self.held.any() else 0)

    def floppy(self) -> list[str]:
        """Motions without a linear restoring force: along each axis, the lines of atoms
        (along that axis) that have a free atom and no held one."""
        out = []
        h = self.grid_held
        for a, name in enumerate("xyz"):
            unpinned = int(np.sum((~h).any(axis=a) & ~h.any(axis=a)))
            if unpinned:
                out.append(f"{name} ({unpinned} line{'s' * (unpinned != 1)} of atoms along "
                           f"{name} with no held atom)")
        return out

    # the pulse: along x, layer by layer; positions in units of d from the x = 0 layer
    @property
    def kicked_layer(self) -> int:
        first = first_free_layer(self.shape, self.held)
        return int(np.unravel_index(first[0], self.shape)[0])

    @property
    def source(self) -> float:
        """Where the kick's image point is: the held layer behind the kicked one, or half a
        spacing behind a free kicked end."""
        ix = self.kicked_layer
        return ix - 1.0 if ix > 0 and self.grid_held[ix - 1].any() else ix - 0.5

    @property
    def held_start(self) -> bool:
        return self.source == self.kicked_layer - 1.0

    @property
    def wall(self) -> float:
        """Where the far end reflects: its held layer, or half a spacing beyond a free end."""
        nx = self.shape[0]
        return nx - 1.0 if self.grid_held[-1].all() else nx - 0.5

    @property
    def crossing(self) -> float:
        """Theory's time for the pulse to cross from the kick to the far end (s)."""
        return (self.wall - self.source) * self.lat.d / self.lat.sound_speed

    # a chain's normal modes (along x)
    def modes(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(atoms, q, Phi): the chain's free atoms in order, the modes' wavenumbers (1/m)
        and orthonormal shapes (N_free, n_modes); the free chain's translation left out."""
        d, n = self.lat.d, self.shape[0]
        h = self.held
        atoms = self.free
        M = len(atoms)
        if h[0] and h[-1]:
            j = np.arange(1, M + 1)
            q = np.arange(1, M + 1) * math.pi / ((M + 1) * d)
            phi = np.sin(np.outer(j * d, q))
        elif h[0]:
            j = np.arange(1, M + 1)
            q = (2 * np.arange(1, M + 1) - 1) * math.pi / ((2 * M + 1) * d)
            phi = np.sin(np.outer(j * d, q))
        elif h[-1]:      # held at the far end only: the mirror image of the above
            j = np.arange(M, 0, -1)
            q = (2 * np.arange(1, M + 1) - 1) * math.pi / ((2 * M + 1) * d)
            phi = np.sin(np.outer(j * d, q))
        else:
            j = np.arange(n)
            q = np.arange(1, n) * math.pi / (n * d)
            phi = np.cos(np.outer((j + 0.5) * d, q))
        phi /= np.linalg.norm(phi, axis=0)
        return atoms, q, phi

    def lowest_mode(self) -> float:
        """The lowest nonzero mode of the chain along x (rad/s), theory."""
        return float(self.lat.dispersion(self.modes()[1][0]))

    def slowest_line_mode(self) -> float:
        """The lowest nonzero linear mode of any line of atoms along x, y or z (rad/s):
        held at both ends, one end, or neither (then its first non-translation)."""
        lat, h = self.lat, self.grid_held
        w = []
        for a, n in enumerate(self.shape):
            if n < 2:
                continue
            first = np.take(h, 0, axis=a).any()
            last = np.take(h, n - 1, axis=a).any()
            if first and last:
                M = n - 2
                q = math.pi / ((M + 1) * lat.d) if M > 0 else None
            elif first or last:
                q = math.pi / ((2 * (n - 1) + 1) * lat.d)
            else:
                q = math.pi / (n * lat.d)
            if q is not None:
                w.append(float(lat.dispersion(q)))
        return min(w) if w else lat.omega0


# ---- what to measure, and for how long ---------------------------------------------------

@dataclass
class Plan:
    what: tuple[str, ...]
    steps: int
    duration: float
    pulse_steps: int = 0
    mode_stride: int = 0
    notes: list[str] = field(default_factory=list)


def _plan(cfg: Config, geo: Geometry, duration: float | None) -> Plan:
    src, lat = cfg.source, geo.lat
    kick, T0, F = cfg.start.kick, cfg.start.temperature, cfg.pull.force
    nx = geo.shape[0]
    what = []
    early_notes = []
    needs: dict[str, tuple[float, str]] = {}
    if kick[0] != 0 and nx >= 2:
        what.append("speed_of_sound")
        needs["speed_of_sound"] = (SOUND_REACH * geo.crossing,
                                   f"the pulse must cross {SOUND_REACH:.0%} of the chain at "
                                   f"v = d sqrt(k/m)")
    if lat.is_chain and (kick[0] != 0 or T0 > 0) and geo.n_free >= 2 and cfg.damping.b > 0:
        early_notes.append("dispersion not measured: [damping] b damps the normal modes, "
                           "whose frequencies omega(q) are those of the undamped chain")
    elif lat.is_chain and (kick[0] != 0 or T0 > 0) and geo.n_free >= 2:
        what.append("dispersion")
        w1 = geo.lowest_mode()
        needs["dispersion"] = (DISPERSION_PERIODS * 2 * math.pi / w1,
                               f"{DISPERSION_PERIODS:g} periods of the lowest mode, "
                               f"{2 * math.pi / w1:.3g} s each")
    if F > 0:
        what.append("youngs_modulus")
    if T0 > 0:
        what += ["temperature", "equipartition"]
        ws = geo.slowest_line_mode()
        needs["temperature"] = ((1 + THERMAL_BLOCKS) * math.pi / ws,
                                f"an equilibration and {THERMAL_BLOCKS} blocks, each a period "
                                f"of the slowest mode's kinetic energy, {math.pi / ws:.3g} s")
    if not what:
        if any(kick):
            why = ("its [start] kick is sideways, and sideways motion does not travel in this "
                   "model (bonds relaxed at the spacing have no tension, so no linear "
                   "restoring force)")
        else:
            why = "it has no [start] kick, [start] temperature or [pull] force"
        raise UserError(f"{src}: nothing to measure: {why}; analyze measures the speed of "
                        "sound (a kick along x), the dispersion (a kicked or thermal chain), "
                        "Young's modulus (a pull) and equipartition (a temperature)")
    asked = duration if duration is not None else cfg.render.duration
    notes = early_notes
    run = asked
    if needs:
        key, (need, why) = max(needs.items(), key=lambda kv: kv[1][0])
        if asked < need * (1 - 1e-9):
            if duration is not None:
                raise UserError(f"--duration {duration:g} s is too short to measure the "
                                f"{key.replace('_', ' ')}: it needs at least {need:.3g} s "
                                f"({why})")
            run = need
            notes.append(f"the run is lengthened from the config's {asked:g} s to {need:.3g} s "
                         f"for the {key.replace('_', ' ')} ({why})")
    dt = cfg.physics.dt
    steps = max(1, int(math.ceil(run / dt - 1e-9)))
    if steps > MAX_STEPS:
        raise UserError(f"{src}: measuring this needs {steps:,} steps of dt = {dt:g} s "
                        f"(more than {MAX_STEPS:,}); use a smaller lattice or a larger dt")
    plan = Plan(tuple(what), steps, steps * dt, notes=notes)
    if "speed_of_sound" in what:
        # enough for the pulse, its reflection coming back, and the figure
        plan.pulse_steps = min(steps, int(math.ceil(2.2 * geo.crossing / dt)))
    if "dispersion" in what:
        w_max = float(lat.dispersion(geo.modes()[1]).max())
        plan.mode_stride = max(1, int(2 * math.pi / (w_max * dt * SAMPLES_PER_PERIOD)))
    return plan


# ---- the run -----------------------------------------------------------------------------

@dataclass
class Record:
    t_pulse: np.ndarray | None = None        # (P,)
    pulse: np.ndarray | None = None          # (P, nx) layer mean displacement along x (m)
    pulse_v: np.ndarray | None = None        # (P, nx) layer mean velocity along x (m/s)
    t_modes: np.ndarray | None = None        # (S,)
    x_modes: np.ndarray | None = None        # (S, N_free) displacement along x of a chain's atoms
    t_energy: np.ndarray | None = None       # (R,)
    K_xyz: np.ndarray | None = None          # (R, 3) kinetic energy per direction (J)
    Us: np.ndarray | None = None             # (R,) the bonds' energy (J)
    t_pull: np.ndarray | None = None
    elongation: np.ndarray | None = None     # (R,) pulled face minus held face, less (nx-1) d


def _simulate(cfg: Config, geo: Geometry, plan: Plan) -> Record:
    s = build(cfg)
    lat = geo.lat
    sites = lat.sites()
    x0 = sites[:, 0]
    dt = cfg.physics.dt
    rec = Record()
    grid = np.arange(lat.n_atoms).reshape(geo.shape)
    free_grid = ~geo.grid_held
    nx = geo.shape[0]
    # layer means over free atoms: a (nx, N) averaging matrix, as a weight per atom
    layer_of = np.unravel_index(np.arange(lat.n_atoms), geo.shape)[0]
    counts = np.array([free_grid[ix].sum() for ix in range(nx)], float)
    w_layer = np.where(~geo.held, 1.0, 0.0) / np.maximum(counts[layer_of], 1)
    want_pulse = "speed_of_sound" in plan.what
    want_modes = "dispersion" in plan.what
    want_energy = "temperature" in plan.what
    want_pull = "youngs_modulus" in plan.what
    P = plan.pulse_steps + 1 if want_pulse else 0
    if want_pulse:
        rec.pulse = np.zeros((P, nx))
        rec.pulse_v = np.zeros((P, nx))
    atoms = geo.modes()[0] if want_modes else None
    stride = plan.mode_stride
    if want_modes:
        S = plan.steps // stride + 1
        rec.x_modes = np.empty((S, len(atoms)))
    R = plan.steps + 1
    if want_energy:
        rec.K_xyz = np.empty((R, 3))
        rec.Us = np.empty(R)
    if want_pull:
        first, last = grid[0].ravel(), grid[-1].ravel()
        rec.elongation = np.empty(R)
    free = geo.free
    m = lat.m

    def layers(values: np.ndarray) -> np.ndarray:
        return np.bincount(layer_of, weights=values * w_layer, minlength=nx)

    for i in range(plan.steps + 1):
        if i:
            physics.step(s, 1)
        if i < P:
            rec.pulse[i] = layers(s.pos[:, 0] - x0)
            rec.pulse_v[i] = layers(s.p[:, 0] / m)
        if want_modes and i % stride == 0:
            rec.x_modes[i // stride] = s.pos[atoms, 0] - x0[atoms]
        if want_energy:
            pf = s.p[free]
            rec.K_xyz[i] = np.einsum("ij,ij->j", pf, pf) / (2 * m)
            rec.Us[i] = physics.energies(s).Us
        if want_pull:
            rec.elongation[i] = (s.pos[last, 0].mean() - s.pos[first, 0].mean()
                                 - (nx - 1) * lat.d)
    if want_pulse:
        rec.t_pulse = np.arange(P) * dt
    if want_modes:
        rec.t_modes = np.arange(len(rec.x_modes)) * stride * dt
    rec.t_energy = rec.t_pull = np.arange(R) * dt
    return rec


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
                "rms_residual": float(np.sqrt(np.mean(resid ** 2)))},
        "arrival_fraction": ARRIVAL_FRACTION,
        "signal": "displacement" if geo.held_start else "velocity",
        "first_peak_linear_fit": float(naive),
        "n": n_all[ok].tolist(), "arrival": t_all[ok].tolist(),
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
    """The frequency Euler-Cromer or Verlet runs a linear mode at: (2/dt) asin(omega dt/2)."""
    if name not in ("euler-cromer", "verlet"):
        return None
    return 2.0 / dt * np.arcsin(np.clip(omega * dt / 2, -1, 1))


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
                      "q": float(q[-1])},
        "lowest": {"measured": float(measured[0]), "theory": float(theory[0]),
                   "q": float(q[0])},
        "record": float(t[-1]),
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
    plan = _plan(cfg, geo, duration)
    rec = _simulate(cfg, geo, plan)
    lat = geo.lat
    result = {
        "config": cfg.source,
        "lattice": {"shape": list(lat.shape), "spacing": lat.d, "mass": lat.m, "k": lat.k,
                    "fixed": lat.fixed, "free_atoms": geo.n_free},
        "integrator": cfg.physics.integrator, "dt": cfg.physics.dt, "duration": plan.duration,
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

def _num(x: float | None) -> str:
    return "—" if x is None else f"{x:.6g}"


def _row(label: str, meas, th, unit: str, err=None) -> str:
    diff = ""
    if meas is not None and th:
        diff = f"{100 * (meas - th) / abs(th):+.3f} %"
    m = _num(meas) + (f" ± {err:.2g}" if err is not None else "")
    return f"{label:<30}{m:>22}{_num(th):>14}{diff:>12}  {unit}"


def table(result: dict) -> str:
    """A readable terminal table: quantity, measured (± standard error), theory, difference."""
    lat = result["lattice"]
    shape = lat["shape"]
    what = (f"chain of {shape[0]} atoms" if shape[1] == shape[2] == 1
            else f"{shape[0]}×{shape[1]}×{shape[2]} lattice")
    lines = [f"{result['config']}: {what} ({lat['free_atoms']} free; d = {lat['spacing']:.4g} m, "
             f"m = {lat['mass']:.4g} kg, k = {lat['k']:g} N/m), {result['integrator']}, "
             f"dt = {result['dt']:g} s, {result['duration']:.4g} s simulated",
             f"{'quantity':<30}{'measured':>22}{'theory':>14}{'difference':>12}  unit"]
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


# ---- figures -----------------------------------------------------------------------------

SPECTRUM_DB = 60          # the dispersion figure's spectra: this many dB below each mode's peak
PNG_COLORS = 128
SHADE = "#e6e6e6"         # a shaded span (the palette PNG whitens anything above 245)
_PREFIXES = ((1e-21, "z"), (1e-18, "a"), (1e-15, "f"), (1e-12, "p"), (1e-9, "n"),
             (1e-6, "µ"), (1e-3, "m"), (1.0, ""))


def si_scale(top: float) -> tuple[float, str]:
    """(factor, prefix) that shows values up to ``top`` as 1 to 999 of the prefixed unit."""
    top = abs(top)
    for factor, prefix in reversed(_PREFIXES):
        if top >= factor:
            return factor, prefix
    return _PREFIXES[0]


def power_scale(top: float) -> tuple[float, str]:
    """(10^k, label) for an axis in units of 10^k when ``top`` is 1e4 or more, else (1, "")."""
    if abs(top) < 1e4:
        return 1.0, ""
    k = int(math.floor(math.log10(abs(top))))
    return 10.0 ** k, f"$10^{{{k}}}$ "


def _pct(x: float) -> str:
    return f"{100 * x:+.3f} %".replace("-", "−")


def pulse_figure(result: dict):
    """Space-time picture of the kicked pulse: displacement (or velocity) of each atom
    (layer) against time, the arrivals and the fitted line of slope 1/v."""
    from .figures import BLACK, new_figure, style

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
    from .figures import BLACK, BLUE, GREY, VERMILLION, new_figure, style

    geo = result["_geometry"]
    lat = geo.lat
    D = result["dispersion"]
    cfg = result["_config"]
    q = np.array(D["q"])
    meas = np.array(D["measured"])
    th = np.array(D["theory"])
    omega, spectra = D["_spectrum"]
    lf, lp = next(((f, p) for f, p in _PREFIXES if math.pi / lat.d * f >= 1), (1.0, ""))
    qf = 1 / lf
    w_top = 1.12 * 2 * lat.omega0
    wf, wl = power_scale(w_top)
    # the spectra, pooled (max) onto a coarse frequency grid for the picture
    rows = 360
    edges = np.searchsorted(omega, np.linspace(0, w_top, rows + 1))
    pooled = np.array([[spec[a:max(b, a + 1)].max() for a, b in zip(edges[:-1], edges[1:])]
                       for spec in spectra]).T
    dq = q[1] - q[0] if len(q) > 1 else q[0]
    q_curve = np.linspace(0, math.pi / lat.d, 400)
    integ = D.get("integrator_theory")
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
        rel = 100 * (meas / th - 1)
        bottom.axhline(0, color=GREY, lw=0.8)
        if integ is not None:
            bottom.plot(q / qf, 100 * (np.array(integ) / th - 1), "-", color=BLUE, lw=1.1,
                        label=f"{cfg.physics.integrator}'s own shift, (2/dt) asin(ω dt/2)")
        bottom.plot(q / qf, rel, "o", ms=3, color=VERMILLION, mec="none",
                    label=f"measured (largest {100 * D['max_relative_error']:.3f} %)")
        span = max(np.abs(rel).max(), 0.01) * 1.6
        bottom.set_ylim(-span, span)
        bottom.set_xlim(top.get_xlim())
        bottom.set_xlabel(f"wavenumber q ({lp}m$^{{-1}}$)" if lp else "wavenumber q (m$^{-1}$)")
        bottom.set_ylabel("error (%)")
        bottom.legend(loc="lower right", fontsize=9, ncol=2)
    return fig


def thermal_figure(result: dict):
    """Kinetic and bond energy per atom against time: equipartition after the start."""
    from .figures import BLUE, GREY, VERMILLION, new_figure, style
    from .config import BOLTZMANN as KB

    T, e = result["temperature"], result["equipartition"]
    t, K, U, start = e["_series"]
    ef, ep = si_scale(max(K.max(), U.max()))
    tf, tp = si_scale(t[-1])
    geo = result["_geometry"]
    per_atom = 0.5 * geo.dof / geo.n_free * KB
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
    from .figures import BLUE, GREY, new_figure, style

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


def save_png(fig, path: Path, colors: int = PNG_COLORS) -> Path:
    """Write the figure as a palette PNG of ``colors`` colours (a few tens of kB), atomically,
    without dates: the same figure gives the same bytes."""
    from PIL import Image

    from .figures import figure_image
    from .outputs import atomic_path

    image = Image.fromarray(figure_image(fig)).quantize(colors, method=Image.Quantize.FASTOCTREE,
                                                         dither=Image.Dither.NONE)
    palette = np.array(image.getpalette()[:3 * colors], dtype=np.int16).reshape(-1, 3)
    palette[(palette >= 246).all(axis=1)] = 255       # the quantizer greys the white a little
    image.putpalette(palette.astype(np.uint8).ravel().tolist())
    with atomic_path(path) as tmp:
        image.save(tmp, format="PNG", optimize=True)
    return path


def make_figures(cfg: Config, out_dir: str | Path) -> list[Path]:
    """Write the lattice config's figures (PNG) into ``out_dir``: ``pulse.png`` (a kick),
    ``dispersion.png`` (a chain), ``pull.png`` (a pull), ``thermal.png`` (a temperature).

    Measured first, then written atomically; on an error no new file is left behind.
    """
    from .figures import prepare_out_dir

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
                written.append(save_png(draw(result), out / f"{stem}.png"))
    except BaseException:
        for path in written:
            path.unlink(missing_ok=True)
        if created and not any(out.iterdir()):     # nor the folder this call made
            out.rmdir()
        raise
    return written
