"""One run of a lattice config for the measurements of :mod:`springscene.science.matter`.

:class:`Geometry` is the lattice and how a chain's modes and pulse see it; :func:`plan_run`
decides what the config's scenario lets us measure and for how long; :func:`simulate` runs
it once, keeping only what the measurements read (:class:`Record`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from .. import build
from ..errors import UserError
from ..model import physics, timeline
from ..model.lattice import Lattice, first_free_layer
from ..settings import Config

SOUND_REACH = 0.9                    # the pulse must cross this share of the chain
DISPERSION_PERIODS = 4.0             # periods of the lowest mode the mode FFT needs
SAMPLES_PER_PERIOD = 10              # of the fastest mode, for the mode time series
THERMAL_BLOCKS = 8
MAX_STEPS = 2_000_000



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
        lat = build.lattice(cfg)
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


def plan_run(cfg: Config, geo: Geometry, duration: float | None) -> Plan:
    """What the config's scenario lets us measure, and the steps the run needs for it."""
    what, needs, notes = _what_to_measure(cfg, geo)
    run = _run_length(cfg, duration, needs, notes)
    dt = cfg.physics.dt
    steps = max(1, int(math.ceil(run / dt - 1e-9)))
    limit = MAX_STEPS if timeline.current_limit() == timeline.MAX_STEPS \
        else timeline.current_limit()          # --max-steps given: the user's limit
    if steps > limit:
        raise UserError(f"{cfg.source}: measuring this needs {steps:,} steps of dt = {dt:g} s "
                        f"(more than {limit:,}); use a smaller lattice or a larger dt, "
                        "or --max-steps N")
    plan = Plan(tuple(what), steps, steps * dt, notes=notes)
    if "speed_of_sound" in what:
        # enough for the pulse, its reflection coming back, and the figure
        plan.pulse_steps = min(steps, int(math.ceil(2.2 * geo.crossing / dt)))
    if "dispersion" in what:
        w_max = float(geo.lat.dispersion(geo.modes()[1]).max())
        plan.mode_stride = max(1, int(2 * math.pi / (w_max * dt * SAMPLES_PER_PERIOD)))
    return plan


def _what_to_measure(cfg: Config, geo: Geometry
                     ) -> tuple[list[str], dict[str, tuple[float, str]], list[str]]:
    """The quantities the scenario shows, the least run each needs (s, why), and notes."""
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
    return what, needs, early_notes


def _run_length(cfg: Config, duration: float | None, needs: dict[str, tuple[float, str]],
                notes: list[str]) -> float:
    """The run's length: the asked one, lengthened (with a note) to what the measurements
    need; an explicit ``--duration`` that is too short is refused."""
    asked = duration if duration is not None else cfg.render.duration
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
    return run


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


def _layer_means(geo: Geometry):
    """A function of per-atom values (N,) that gives their mean over each x layer's free
    atoms (nx,)."""
    nx = geo.shape[0]
    free_grid = ~geo.grid_held
    # layer means over free atoms: a (nx, N) averaging matrix, as a weight per atom
    layer_of = np.unravel_index(np.arange(geo.lat.n_atoms), geo.shape)[0]
    counts = np.array([free_grid[ix].sum() for ix in range(nx)], float)
    w_layer = np.where(~geo.held, 1.0, 0.0) / np.maximum(counts[layer_of], 1)

    def layers(values: np.ndarray) -> np.ndarray:
        return np.bincount(layer_of, weights=values * w_layer, minlength=nx)

    return layers


def simulate(cfg: Config, geo: Geometry, plan: Plan) -> Record:
    """Run the config's system for the plan's steps, recording what its measurements read."""
    s = build.system(cfg)
    lat = geo.lat
    x0 = lat.sites()[:, 0]
    dt = cfg.physics.dt
    rec = Record()
    grid = np.arange(lat.n_atoms).reshape(geo.shape)
    nx = geo.shape[0]
    layers = _layer_means(geo)
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
