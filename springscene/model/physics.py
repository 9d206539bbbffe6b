"""The ball-and-spring engine: plain numpy state and pure step functions.

One engine serves every scene: a set of nodes (balls and fixed anchors) joined
by springs, under a uniform gravitational field, with optional linear drag, a
periodic drive and springs that stiffen or yield. The wiki scene is one fixed
holder node, one ball node and one spring; a resonance sweep is a thousand such
pairs side by side; a crystal is the same with more rows. Nothing here imports
VTK or draws anything.

The default step is the page's momentum principle, stepped by Euler-Cromer, in
exactly the page's order (Model 14)::

    L    = ball.pos - holder.pos
    Fs   = -k * (mag(L) - L0) * norm(L)
    Fg   = m * g
    Fnet = Fs + Fg
    p    = p + Fnet * dt
    pos  = pos + (p / m) * dt

Every operation is the same float64 operation, in the same order, as VPython's
``vector`` arithmetic, so a single spring reproduces the wiki's loop bit for bit.
Other integrators (:mod:`springscene.model.integrators`) use the same forces.

Beyond Hooke's law (all off by default):

- drag ``F = -b v`` on each node (``b`` in kg/s); the energy it takes is
  tallied in ``E_thermal``;
- a stiffening term: ``F = -(k s + k3 s^3)`` along the spring, s = |L| - L0;
- an elastic limit: stretched (or compressed) beyond ``yield_stretch`` a spring
  takes a permanent set (elastic-perfectly-plastic: its force stays at its value
  at the limit while L0 moves so that |s| = yield_stretch), and the work of that
  flow goes to ``E_thermal`` (plastic work heats the metal);
- a :class:`Drive`: driven support nodes moving as ``A sin(omega t)``, or an
  external force ``F0 cos(omega t)`` on chosen nodes;
- a steady external force per node (``F_ext``), e.g. a bar pulled at one face.

A lattice of atoms (:mod:`springscene.model.lattice`) is the same system with its
nodes on a grid: with ``grid = (nx, ny, nz)`` the nodes are the grid's points in
C order and the springs its bonds, axis by axis (:func:`grid_bonds`), and the
spring forces are computed on the grid by slicing (a stencil) instead of by
gather and scatter. The arithmetic per spring is the same; only the order in
which each node's spring forces are summed differs.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from . import integrators
from ..errors import UserError

DRIVE_KINDS = ("support", "force")


@dataclass
class Drive:
    """A periodic drive, one frequency per driven node.

    Parameters
    ----------
    kind : "support" or "force"
        ``support``: the (fixed) nodes move as ``base + A sin(omega t) direction``.
        ``force``: the (free) nodes feel ``A cos(omega t) direction`` (A in N).
    nodes : (D,) int array
    amplitude, omega : (D,) float arrays (m or N; rad/s)
    direction : (3,) unit vector
    """

    kind: str
    nodes: np.ndarray
    amplitude: np.ndarray
    omega: np.ndarray
    direction: np.ndarray
    base: np.ndarray | None = None     # support nodes' rest positions, set by System

    def __post_init__(self) -> None:
        if self.kind not in DRIVE_KINDS:
            raise ValueError(f"drive kind must be one of {DRIVE_KINDS}, got {self.kind!r}")
        self.nodes = np.asarray(self.nodes, dtype=np.intp).reshape(-1)
        d = len(self.nodes)
        self.amplitude = np.broadcast_to(np.asarray(self.amplitude, float), (d,)).copy()
        self.omega = np.broadcast_to(np.asarray(self.omega, float), (d,)).copy()
        u = np.asarray(self.direction, float).reshape(3)
        self.direction = u / np.linalg.norm(u)

    def offsets(self, t: float) -> np.ndarray:
        """Support displacement (D, 3) at time t."""
        return (self.amplitude * np.sin(self.omega * t))[:, None] * self.direction

    def force(self, t: float) -> np.ndarray:
        """External force (D, 3) at time t."""
        return (self.amplitude * np.cos(self.omega * t))[:, None] * self.direction


@dataclass
class System:
    """State of a ball-and-spring system.

    Parameters
    ----------
    pos : (N, 3) float64 array
        Node positions in metres.
    p : (N, 3) float64 array
        Node momenta in kg m/s (zero for fixed nodes).
    m : (N,) float64 array
        Node masses in kg (ignored for fixed nodes).
    fixed : (N,) bool array
        True for anchors that never move by force (the holder; it may be driven).
    i, j : (S,) int arrays
        Each spring joins node ``i`` (its start, e.g. the holder) to node ``j``
        (its end, e.g. the ball); ``L = pos[j] - pos[i]``.
    k, L0 : (S,) float64 arrays
        Spring stiffness (N/m) and relaxed length (m).
    g : (3,) float64 array
        Gravitational field (m/s^2).
    dt : float
        Time step (s).
    b : (N,) float64 array
        Linear drag coefficient per node (kg/s), ``F = -b p/m``.
    k3 : (S,) float64 array
        Cubic stiffening (N/m^3).
    yield_stretch : (S,) float64 array
        Elastic limit of |mag(L) - L0| (m); inf for none.
    drive : Drive or None
    integrator : str
        One of :data:`springscene.model.integrators.NAMES`.
    F_ext : (N, 3) float64 array or None
        A steady external force on each node (N); fixed nodes ignore it.
    grid : (nx, ny, nz) or None
        The nodes are a grid in C order and the springs :func:`grid_bonds`' bonds.
    """

    pos: np.ndarray
    p: np.ndarray
    m: np.ndarray
    fixed: np.ndarray
    i: np.ndarray
    j: np.ndarray
    k: np.ndarray
    L0: np.ndarray
    g: np.ndarray
    dt: float
    b: np.ndarray | float = 0.0
    k3: np.ndarray | float = 0.0
    yield_stretch: np.ndarray | float = np.inf
    drive: Drive | None = None
    integrator: str = integrators.DEFAULT
    F_ext: np.ndarray | None = None
    grid: tuple[int, int, int] | None = None
    t: float = 0.0
    steps: int = 0
    E_thermal: float = 0.0
    _free: np.ndarray = field(init=False, repr=False)
    _grid_work: "_GridWork | None" = field(init=False, repr=False, default=None)

    def __post_init__(self) -> None:
        self.pos = np.array(self.pos, dtype=np.float64).reshape(-1, 3)
        n = len(self.pos)
        self.p = np.array(self.p, dtype=np.float64).reshape(n, 3)
        self.m = np.broadcast_to(np.asarray(self.m, dtype=np.float64), (n,)).copy()
        self.fixed = np.broadcast_to(np.asarray(self.fixed, dtype=bool), (n,)).copy()
        self.i = np.asarray(self.i, dtype=np.intp).reshape(-1)
        self.j = np.asarray(self.j, dtype=np.intp).reshape(-1)
        s = len(self.i)
        self.k = np.broadcast_to(np.asarray(self.k, dtype=np.float64), (s,)).copy()
        self.L0 = np.broadcast_to(np.asarray(self.L0, dtype=np.float64), (s,)).copy()
        self.g = np.asarray(self.g, dtype=np.float64).reshape(3)
        self.b = np.broadcast_to(np.asarray(self.b, dtype=np.float64), (n,)).copy()
        self.k3 = np.broadcast_to(np.asarray(self.k3, dtype=np.float64), (s,)).copy()
        self.yield_stretch = np.broadcast_to(
            np.asarray(self.yield_stretch, dtype=np.float64), (s,)).copy()
        if self.integrator not in integrators.STEPPERS:
            raise ValueError(f"integrator must be one of {integrators.NAMES}, "
                             f"got {self.integrator!r}")
        self.p[self.fixed] = 0.0
        self.b[self.fixed] = 0.0
        self.m[self.fixed & ~(self.m > 0)] = 1.0     # anchors never divide by their mass
        self._free = np.flatnonzero(~self.fixed)
        self._held = np.flatnonzero(self.fixed)
        if self.F_ext is not None:
            self.F_ext = np.array(self.F_ext, dtype=np.float64).reshape(n, 3)
            self.F_ext[self.fixed] = 0.0
        if self.grid is not None:
            self.grid = tuple(int(c) for c in self.grid)
            i, j = grid_bonds(self.grid)
            if n != math.prod(self.grid) or not (np.array_equal(i, self.i)
                                                 and np.array_equal(j, self.j)):
                raise ValueError(f"the nodes and springs are not the grid {self.grid}'s")
        anchors = np.flatnonzero(self.fixed)
        self.ref = self.pos[anchors[0]].copy() if len(anchors) else np.zeros(3)
        if self.drive is not None:
            on_fixed = self.fixed[self.drive.nodes]
            if self.drive.kind == "support" and not on_fixed.all():
                raise ValueError("a driven support must be a fixed node")
            if self.drive.kind == "force" and on_fixed.any():
                raise ValueError("a driving force must act on free nodes")
            if self.drive.kind == "support":
                self.drive.base = self.pos[self.drive.nodes].copy()
                self.pos[self.drive.nodes] = self.drive.base + self.drive.offsets(self.t)

    @property
    def n_nodes(self) -> int:
        return len(self.pos)

    @property
    def free(self) -> np.ndarray:
        """Indices of the nodes that move."""
        return self._free

    @property
    def has_drag(self) -> bool:
        return bool(np.any(self.b))

    @property
    def is_plastic(self) -> bool:
        return bool(np.any(np.isfinite(self.yield_stretch)))

    @property
    def stiffens(self) -> bool:
        return bool(np.any(self.k3))


def grid_bonds(shape: tuple[int, int, int]) -> tuple[np.ndarray, np.ndarray]:
    """Nearest-neighbour bonds of a grid of nodes numbered in C order: (i, j) with j = i + 1 step.

    The x bonds come first, then y, then z; each block in C order of the bond's
    start node, so that block a reshaped to the grid less one layer along a is the
    slice ``pos[1:] - pos[:-1]`` along a.
    """
    index = np.arange(math.prod(shape)).reshape(shape)
    i, j = [], []
    for a in range(3):
        if shape[a] > 1:
            i.append(np.take(index, np.arange(shape[a] - 1), axis=a).ravel())
            j.append(np.take(index, np.arange(1, shape[a]), axis=a).ravel())
    return (np.concatenate(i) if i else np.zeros(0, np.intp),
            np.concatenate(j) if j else np.zeros(0, np.intp))


class _GridWork:
    """Buffers for the grid stencil, made once per system: the state in planes (3, nx, ny, nz)
    (structure of arrays, so every operation runs over contiguous memory), the force planes,
    and per axis the bond vectors, lengths and coefficients.

    (Splitting the bonds over two threads was measured slower on this two-core machine:
    the stencil is bound by memory traffic, not arithmetic.)
    """

    def __init__(self, s: "System") -> None:
        shape = s.grid
        self.shape = shape
        self.P = np.empty((3,) + shape)
        self.F = np.empty((3,) + shape)
        self.blocks = []
        start = 0
        for a in range(3):
            if shape[a] < 2:
                continue
            hi, lo = [slice(None)] * 4, [slice(None)] * 4
            hi[a + 1], lo[a + 1] = slice(1, None), slice(None, -1)
            block = tuple(n - (b == a) for b, n in enumerate(shape))
            stop = start + math.prod(block)
            self.blocks.append((tuple(hi), tuple(lo), block, slice(start, stop),
                                np.empty((3,) + block), np.empty(block), np.empty(block)))
            start = stop
        # one stiffness and relaxed length for every bond (the usual lattice): scalars
        self.k = float(s.k[0]) if s.k.size and np.all(s.k == s.k[0]) else None
        self.L0 = float(s.L0[0]) if s.L0.size and np.all(s.L0 == s.L0[0]) else None


def _grid_spring_forces(s: System, pos: np.ndarray, plastic: bool, stiffens: bool) -> np.ndarray:
    """The springs' net force on each node of a grid system (N, 3), by slicing the grid.

    Per bond: ``L = pos[j] - pos[i]``, ``coef = -k (mag(L) - L0)``, and
    ``(coef / mag) L`` added to j and taken from i: the generic path's force up to
    the last bit's rounding.
    """
    w = s._grid_work
    if w is None or w.shape != s.grid:
        w = s._grid_work = _GridWork(s)
    P, F = w.P, w.F
    P.reshape(3, -1)[...] = pos.T
    F[...] = 0.0
    k = w.k if w.k is not None else s.k
    L0 = w.L0 if (w.L0 is not None and not plastic) else s.L0
    for hi, lo, block, bonds, L, mag, c in w.blocks:
        np.subtract(P[hi], P[lo], out=L)
        np.multiply(L[0], L[0], out=mag)
        np.multiply(L[1], L[1], out=c)
        mag += c
        np.multiply(L[2], L[2], out=c)
        mag += c
        np.sqrt(mag, out=mag)
        np.subtract(mag, L0 if np.ndim(L0) == 0 else L0[bonds].reshape(block), out=c)  # stretch
        if plastic:
            y = s.yield_stretch[bonds].reshape(block)
            np.clip(c, -y, y, out=c)
        stretch = c.copy() if stiffens else None
        c *= -k if np.ndim(k) == 0 else -k[bonds].reshape(block)                   # coef
        if stiffens:
            c -= s.k3[bonds].reshape(block) * stretch ** 3
        c /= mag
        L *= c
        F[hi] += L
        F[lo] -= L
    return F.reshape(3, -1).T.copy()


def spring_vectors(s: System, pos: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
    """Return ``L = pos[j] - pos[i]`` (S, 3) and ``mag(L)`` (S,), as VPython computes them."""
    pos = s.pos if pos is None else pos
    L = pos[s.j] - pos[s.i]
    mag = np.sqrt(L[:, 0] ** 2 + L[:, 1] ** 2 + L[:, 2] ** 2)
    return L, mag


def forces(s: System, pos: np.ndarray, t: float,
           flags: tuple[bool, bool] | None = None) -> np.ndarray:
    """Net force without drag on every node (N, 3) at positions ``pos`` and time ``t``.

    Springs, gravity and the drive; drag ``-b p/m`` is left to the integrator
    (see :mod:`springscene.model.integrators`). For one spring this is
    ``(-k*(mag(L)-L0)) * (L/mag(L)) + m*g`` on the ball, the page's ``Fs + Fg``
    to the last bit. Fixed nodes get zero. ``flags`` = (plastic, stiffens) when the
    caller already knows them (the step loop does).
    """
    drive = s.drive
    if drive is not None and drive.kind == "support":
        pos = pos.copy()
        pos[drive.nodes] = drive.base + drive.offsets(t)
    plastic, stiffens = flags if flags is not None else (s.is_plastic, s.stiffens)
    if s.grid is not None:
        F = _grid_spring_forces(s, pos, plastic, stiffens)
    else:
        L, mag = spring_vectors(s, pos)
        stretch = mag - s.L0
        if plastic:      # elastic-perfectly-plastic: the force never exceeds its value at the limit
            stretch = np.clip(stretch, -s.yield_stretch, s.yield_stretch)
        coef = -s.k * stretch
        if stiffens:
            coef = coef - s.k3 * stretch ** 3
        Fs = coef[:, None] * (L / mag[:, None])
        n = s.n_nodes
        F = np.empty((n, 3))
        for c in range(3):
            F[:, c] = (np.bincount(s.j, weights=Fs[:, c], minlength=n)
                       - np.bincount(s.i, weights=Fs[:, c], minlength=n))
    if s.g.any():
        F += s.m[:, None] * s.g
    if s.F_ext is not None:
        F += s.F_ext
    if drive is not None and drive.kind == "force":
        F[drive.nodes] += drive.force(t)
    F[s._held] = 0.0
    return F


def mode_bounds(s: System) -> tuple[np.ndarray, np.ndarray]:
    """Per free node, an upper bound on the angular frequency of any linear mode it
    takes part in (Gershgorin's circle theorem on the mass-weighted stiffness
    matrix, linear Hooke part) and its drag rate gamma = b/2m.

    For a ball on one spring from a fixed holder this is exactly sqrt(k/m).
    """
    free = ~s.fixed
    m = s.m
    rows = np.zeros(s.n_nodes)
    for a, b in ((s.i, s.j), (s.j, s.i)):
        # diagonal term k/m_a, and off-diagonal k/sqrt(m_a m_b) when b also moves
        rows += np.bincount(a, weights=s.k / m[a], minlength=s.n_nodes)
        rows += np.bincount(a, weights=np.where(free[b], s.k / (np.sqrt(m[a]) * np.sqrt(m[b])),
                                                0.0),
                            minlength=s.n_nodes)
    return np.sqrt(rows[free]), (s.b / (2 * m))[free]


def net_forces(s: System) -> np.ndarray:
    """Net force on every node (N, 3) in the current state, drag included."""
    F = forces(s, s.pos, s.t)
    if s.has_drag:
        F -= (s.b / s.m)[:, None] * s.p
    return F


def step(s: System, n: int = 1) -> System:
    """Advance ``s`` in place by ``n`` steps of ``s.dt`` with its integrator and return it."""
    advance = integrators.STEPPERS[s.integrator]
    m = s.m[:, None]
    drive = s.drive if s.drive is not None and s.drive.kind == "support" else None
    plastic = s.is_plastic
    beta = (s.b / s.m)[:, None] if s.has_drag else None

    flags = (plastic, s.stiffens)

    def f(pos, t):
        return forces(s, pos, t, flags)

    with np.errstate(over="ignore", invalid="ignore"):   # a blow-up is reported below
        _advance(s, n, advance, m, f, beta, drive, plastic)
    if not (np.isfinite(s.pos).all() and np.isfinite(s.p).all()):
        raise UserError(
            f"the simulation blew up by t = {s.t:.4g} s (positions or momenta are no longer "
            "finite): "
            f"dt = {s.dt:g} s is too large for how stiff the springs get (a large k3?); "
            "use a smaller --dt or [physics] dt")
    return s


def _advance(s: System, n: int, advance, m, f, beta, drive, plastic) -> None:
    for _ in range(n):
        pos, p, heat = advance(s.pos, s.p, m, s.t, s.dt, f, beta)
        s.steps += 1
        s.t = s.steps * s.dt
        s.pos, s.p = pos, p
        s.E_thermal += heat
        if drive is not None:
            s.pos[drive.nodes] = drive.base + drive.offsets(s.t)
        if plastic:
            _yield(s)
        if not np.isfinite(s.pos[s.free[:1]]).all():   # stop early once it has blown up
            return


def _yield(s: System) -> None:
    """Permanent set: a spring stretched beyond its limit gets a longer (or shorter) L0.

    While it flows the spring pulls with its force at the limit, F_y = k s_y + k3 s_y^3
    (:func:`forces` caps it there), so the work the flow turns into heat is
    F_y |delta L0|; it goes to ``E_thermal``.
    """
    _, mag = spring_vectors(s)
    stretch = mag - s.L0
    over = np.abs(stretch) > s.yield_stretch
    if not over.any():
        return
    s_y = s.yield_stretch[over]
    new_L0 = mag[over] - np.sign(stretch[over]) * s_y
    F_y = s.k[over] * s_y + s.k3[over] * s_y ** 3
    s.E_thermal += float(np.sum(F_y * np.abs(new_L0 - s.L0[over])))
    s.L0[over] = new_L0


def _spring_energy(k, k3, stretch):
    return 0.5 * k * stretch ** 2 + 0.25 * k3 * stretch ** 4


@dataclass
class Energies:
    """Kinetic, spring and gravitational energy (J), and the thermal energy made so far."""

    K: float
    Us: float
    Ug: float
    E_thermal: float = 0.0

    @property
    def E(self) -> float:
        """Mechanical energy K + Us + Ug."""
        return self.K + self.Us + self.Ug

    @property
    def total(self) -> float:
        """K + Us + Ug + E_thermal: constant without a drive, up to the integrator's error."""
        return self.E + self.E_thermal


def energies(s: System) -> Energies:
    """K = |p|^2/2m, Us = 1/2 k s^2 + 1/4 k3 s^4, Ug = -m g . (r - r_ref), and E_thermal.

    ``r_ref`` is the first fixed node's starting position (the holder), so with
    g = <0, -9.8, 0> Ug = m |g| y with y measured from the holder's height. Energies that
    are no longer finite (values beyond double precision) raise :class:`UserError`.
    """
    free = s.free
    with np.errstate(over="ignore", invalid="ignore"):     # reported below, in one line
        K = float(np.sum(np.einsum("ij,ij->i", s.p[free], s.p[free]) / (2.0 * s.m[free])))
        _, mag = spring_vectors(s)
        Us = float(np.sum(_spring_energy(s.k, s.k3, mag - s.L0)))
        Ug = float(np.sum(-s.m[free] * ((s.pos[free] - s.ref) @ s.g)))
    e = Energies(K, Us, Ug, s.E_thermal)
    if not math.isfinite(e.total):
        raise UserError(f"the simulation blew up by t = {s.t:.4g} s (its energies are no "
                        f"longer finite: K = {K:.3g} J, Us = {Us:.3g} J, Ug = {Ug:.3g} J): "
                        "dt is too large for how stiff the springs get, or the config's "
                        "numbers are beyond double precision")
    return e


@dataclass
class Trajectory:
    """One node at every step: t (n,), pos, p and acceleration a (n, 3), energies (n,)."""

    t: np.ndarray
    pos: np.ndarray
    p: np.ndarray
    a: np.ndarray
    K: np.ndarray
    Us: np.ndarray
    Ug: np.ndarray
    E_thermal: np.ndarray
    L0: np.ndarray       # the node's first spring's relaxed length (changes when it yields)
    t0: float = 0.0      # time of the first row when the clock was restarted

    @property
    def E(self) -> np.ndarray:
        """Mechanical energy K + Us + Ug."""
        return self.K + self.Us + self.Ug

    @property
    def total(self) -> np.ndarray:
        return self.E + self.E_thermal


def run(s: System, n_steps: int, node: int | None = None, progress=None) -> Trajectory:
    """Record ``node`` (default: the first free node) at t = 0 and after each of ``n_steps`` steps.

    ``s`` is advanced in place. ``progress``, when given, is called with the number of
    steps done since its last call, every 10,000 steps.
    """
    node = int(s.free[0]) if node is None else node
    spring = np.flatnonzero((s.i == node) | (s.j == node))
    spring = int(spring[0]) if len(spring) else None
    rows = n_steps + 1
    t = np.empty(rows)
    pos = np.empty((rows, 3))
    p = np.empty((rows, 3))
    a = np.empty((rows, 3))
    en = np.empty((rows, 4))
    L0 = np.full(rows, np.nan)
    for r in range(rows):
        if r:
            step(s)
            if progress is not None and r % 10_000 == 0:
                progress(10_000)
        t[r] = s.t
        pos[r] = s.pos[node]
        p[r] = s.p[node]
        a[r] = net_forces(s)[node] / s.m[node]
        e = energies(s)
        en[r] = (e.K, e.Us, e.Ug, e.E_thermal)
        if spring is not None:
            L0[r] = s.L0[spring]
    return Trajectory(t, pos, p, a, en[:, 0], en[:, 1], en[:, 2], en[:, 3], L0)
