"""The ball-and-spring engine: plain numpy state and pure step functions.

One engine serves every scene: a set of nodes (balls and fixed anchors) joined
by Hooke's-law springs, under a uniform gravitational field. The wiki scene is
one fixed holder node, one ball node and one spring; a crystal is the same with
more rows. Nothing here imports VTK or draws anything.

The step is the page's momentum principle, stepped by Euler-Cromer, in exactly
the page's order (Model 14)::

    L    = ball.pos - holder.pos
    Fs   = -k * (mag(L) - L0) * norm(L)
    Fg   = m * g
    Fnet = Fs + Fg
    p    = p + Fnet * dt
    pos  = pos + (p / m) * dt

Every operation is the same float64 operation, in the same order, as VPython's
``vector`` arithmetic, so a single spring reproduces the wiki's loop bit for bit.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np


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
        True for anchors that never move (the holder).
    i, j : (S,) int arrays
        Each spring joins node ``i`` (its start, e.g. the holder) to node ``j``
        (its end, e.g. the ball); ``L = pos[j] - pos[i]``.
    k, L0 : (S,) float64 arrays
        Spring stiffness (N/m) and relaxed length (m).
    g : (3,) float64 array
        Gravitational field (m/s^2).
    dt : float
        Time step (s).
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
    t: float = 0.0
    steps: int = 0
    _free: np.ndarray = field(init=False, repr=False)

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
        self.p[self.fixed] = 0.0
        self._free = np.flatnonzero(~self.fixed)

    @property
    def n_nodes(self) -> int:
        return len(self.pos)

    @property
    def free(self) -> np.ndarray:
        """Indices of the nodes that move."""
        return self._free


def spring_vectors(s: System) -> tuple[np.ndarray, np.ndarray]:
    """Return ``L = pos[j] - pos[i]`` (S, 3) and ``mag(L)`` (S,), as VPython computes them."""
    L = s.pos[s.j] - s.pos[s.i]
    mag = np.sqrt(L[:, 0] ** 2 + L[:, 1] ** 2 + L[:, 2] ** 2)
    return L, mag


def net_forces(s: System) -> np.ndarray:
    """Net force on every node (N, 3): Hooke's-law springs plus gravity.

    For one spring this is ``(-k*(mag(L)-L0)) * (L/mag(L)) + m*g`` on the ball,
    the page's ``Fs + Fg`` to the last bit. Fixed nodes get zero.
    """
    L, mag = spring_vectors(s)
    coef = -s.k * (mag - s.L0)
    Fs = coef[:, None] * (L / mag[:, None])
    n = s.n_nodes
    F = np.empty((n, 3))
    for c in range(3):
        F[:, c] = (np.bincount(s.j, weights=Fs[:, c], minlength=n)
                   - np.bincount(s.i, weights=Fs[:, c], minlength=n))
    F += s.m[:, None] * s.g
    F[s.fixed] = 0.0
    return F


def step(s: System, n: int = 1) -> System:
    """Advance ``s`` in place by ``n`` Euler-Cromer steps of ``s.dt`` and return it."""
    free = s.free
    m = s.m[free, None]
    for _ in range(n):
        Fnet = net_forces(s)
        s.p[free] = s.p[free] + Fnet[free] * s.dt
        s.pos[free] = s.pos[free] + (s.p[free] / m) * s.dt
        s.steps += 1
        s.t = s.steps * s.dt
    return s


@dataclass
class Energies:
    """Kinetic, spring and gravitational energy (J) and their sum."""

    K: float
    Us: float
    Ug: float

    @property
    def E(self) -> float:
        return self.K + self.Us + self.Ug


def energies(s: System) -> Energies:
    """K = |p|^2/2m, Us = 1/2 k (|L| - L0)^2, Ug = -m g . (r - r_ref).

    ``r_ref`` is the first fixed node (the holder), so with g = <0, -9.8, 0>
    Ug = m |g| y with y measured from the holder's height.
    """
    free = s.free
    K = float(np.sum(np.einsum("ij,ij->i", s.p[free], s.p[free]) / (2.0 * s.m[free])))
    _, mag = spring_vectors(s)
    Us = float(np.sum(0.5 * s.k * (mag - s.L0) ** 2))
    anchors = np.flatnonzero(s.fixed)
    ref = s.pos[anchors[0]] if len(anchors) else np.zeros(3)
    Ug = float(np.sum(-s.m[free] * ((s.pos[free] - ref) @ s.g)))
    return Energies(K, Us, Ug)


@dataclass
class Trajectory:
    """States of one node at every step: t (n,), pos (n, 3), p (n, 3), energies (n, 3)."""

    t: np.ndarray
    pos: np.ndarray
    p: np.ndarray
    K: np.ndarray
    Us: np.ndarray
    Ug: np.ndarray

    @property
    def E(self) -> np.ndarray:
        return self.K + self.Us + self.Ug


def run(s: System, n_steps: int, node: int | None = None) -> Trajectory:
    """Record ``node`` (default: the first free node) at t = 0 and after each of ``n_steps`` steps.

    ``s`` is advanced in place.
    """
    node = int(s.free[0]) if node is None else node
    rows = n_steps + 1
    t = np.empty(rows)
    pos = np.empty((rows, 3))
    p = np.empty((rows, 3))
    en = np.empty((rows, 3))
    for r in range(rows):
        if r:
            step(s)
        t[r] = s.t
        pos[r] = s.pos[node]
        p[r] = s.p[node]
        e = energies(s)
        en[r] = (e.K, e.Us, e.Ug)
    return Trajectory(t, pos, p, en[:, 0], en[:, 1], en[:, 2])
