"""Mesh geometry as numpy arrays: VPython's helix as a tube, and its frame as the axis moves.

No VTK here: the scene module wraps these arrays once in meshes and, each frame,
writes new points into them in place.
"""

from __future__ import annotations

import math

import numpy as np

CHORDS_PER_COIL = 60   # VPython: coils*60 + 1 centre-line points
TUBE_SIDES = 16        # VPython curves are 16-sided tubes


def _unit(v: np.ndarray) -> np.ndarray:
    return v / np.linalg.norm(v)


def rotation_between(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """The 3x3 rotation that takes direction ``a`` to direction ``b`` (shortest arc)."""
    a, b = _unit(np.asarray(a, float)), _unit(np.asarray(b, float))
    v = np.cross(a, b)
    c = float(np.dot(a, b))
    if c < -1 + 1e-12:   # opposite: half turn about any axis perpendicular to a
        axis = _unit(np.cross(a, [1.0, 0, 0] if abs(a[0]) < 0.9 else [0, 1.0, 0]))
        return 2 * np.outer(axis, axis) - np.eye(3)
    vx = np.array([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])
    return np.eye(3) + vx + vx @ vx / (1 + c)


class HelixFrame:
    """VPython's rule for a helix's ``up`` as its ``axis`` changes.

    ``up`` is rotated by the rotation that takes the old axis to the new one,
    unless the new axis is already perpendicular to ``up``. Starts from VPython's
    defaults, axis (1,0,0) and up (0,1,0).
    """

    def __init__(self, axis=(1.0, 0.0, 0.0), up=(0.0, 1.0, 0.0)) -> None:
        self.axis = np.asarray(axis, dtype=float)
        self.up = np.asarray(up, dtype=float)

    def set_axis(self, axis) -> np.ndarray:
        """Set the new axis and return the rotation (columns X, Y, Z) of the local frame."""
        axis = np.asarray(axis, dtype=float)
        if abs(np.dot(_unit(axis), _unit(self.up))) > 1e-12:
            self.up = rotation_between(self.axis, axis) @ self.up
        self.axis = axis
        X = _unit(axis)
        Y = _unit(self.up - np.dot(self.up, X) * X)
        Z = np.cross(X, Y)
        return np.column_stack([X, Y, Z])


class HelixTube:
    """A helix of ``coils`` turns as a tube mesh whose points are recomputed for any axis.

    ``radius`` is to the centre line of the wire, ``thickness`` the wire's diameter,
    as in VPython; a thickness of 0 means VPython's automatic radius/10. The topology (faces) is fixed; :meth:`points` gives the vertex
    positions and normals for a helix from ``pos`` along ``axis``.
    """

    def __init__(self, radius: float, thickness: float, coils: int, ccw: bool = True) -> None:
        self.radius = radius
        self.wire = thickness / 2 if thickness > 0 else radius / 20
        self.coils = coils
        n = int(round(coils * CHORDS_PER_COIL)) + 1      # VPython allows fractional coils
        s = np.linspace(0.0, 1.0, n)
        sign = 1.0 if ccw else -1.0
        self._s = s
        self._dtheta = sign * 2 * math.pi * coils           # d(theta)/ds
        theta = self._dtheta * s
        self._sin, self._cos = np.sin(theta), np.cos(theta)
        phi = 2 * math.pi * np.arange(TUBE_SIDES) / TUBE_SIDES
        self._sphi = np.sin(phi)
        # the inward normal N of the centre line does not depend on the length
        N = np.column_stack([np.zeros_like(s), -self._sin, -self._cos])
        self._N = N
        self._N_cphi = N[:, None, :] * np.cos(phi)[None, :, None]          # (n, 16, 3)
        self.n_rings = n

    def faces(self) -> np.ndarray:
        """Quads between consecutive rings, in VTK's flat ``[4, a, b, c, d, ...]`` layout."""
        ring = np.arange(self.n_rings - 1)[:, None] * TUBE_SIDES
        q = np.arange(TUBE_SIDES)[None, :]
        q1 = (q + 1) % TUBE_SIDES
        quads = np.stack([ring + q, ring + q1, ring + TUBE_SIDES + q1, ring + TUBE_SIDES + q],
                         axis=-1).reshape(-1, 4)
        return np.hstack([np.full((len(quads), 1), 4), quads]).ravel()

    def centerline(self, length: float) -> np.ndarray:
        """Centre-line points (n, 3) in the local frame: x along the axis."""
        return np.column_stack([self._s * length, self.radius * self._sin, self.radius * self._cos])

    def points(self, pos, axis, frame: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """World vertex positions and unit normals, each (n_rings * 16, 3).

        ``frame`` is the 3x3 rotation from :meth:`HelixFrame.set_axis`.
        """
        length = float(np.linalg.norm(axis))
        R, k = self.radius, self._dtheta
        c = self.centerline(length)
        # analytic tangent and inward normal of the centre line
        T = np.column_stack([np.full_like(self._s, length), R * k * self._cos, -R * k * self._sin])
        T /= np.linalg.norm(T, axis=1)[:, None]
        B = np.cross(T, self._N)
        normals = self._N_cphi + B[:, None, :] * self._sphi[None, :, None]   # (n, 16, 3)
        local = c[:, None, :] + self.wire * normals
        world = local.reshape(-1, 3) @ frame.T + np.asarray(pos, dtype=float)
        return world, normals.reshape(-1, 3) @ frame.T


def perpendicular_ups(axes) -> np.ndarray:
    """For each direction in ``axes`` (S, 3), the ``up`` VPython gives a helix first
    set to that axis (:class:`HelixFrame` from its defaults): unit, perpendicular to it."""
    axes = np.asarray(axes, dtype=float).reshape(-1, 3)
    return np.array([HelixFrame().set_axis(a)[:, 1] for a in axes]).reshape(-1, 3)


def frames_from_up(axes: np.ndarray, ups: np.ndarray) -> np.ndarray:
    """Local frames (S, 3, 3), columns X, Y, Z: X along each axis, Y its ``up`` made
    perpendicular to X (Gram-Schmidt), Z = X x Y.

    Continuous in the axis as long as it stays away from its ``up`` (a bond of a
    lattice turns a little about its rest direction, and ``up`` is perpendicular to
    that); where an axis is parallel to its ``up`` any perpendicular is taken.
    """
    axes = np.asarray(axes, dtype=float)
    X = axes / np.linalg.norm(axes, axis=1)[:, None]
    Y = ups - np.einsum("sk,sk->s", ups, X)[:, None] * X
    n = np.linalg.norm(Y, axis=1)
    bad = n < 1e-9
    if bad.any():                    # up along the axis: any perpendicular will do
        other = np.where(np.abs(X[bad, :1]) < 0.9, [[1.0, 0, 0]], [[0, 1.0, 0]])
        Y[bad] = np.cross(X[bad], other)
        n[bad] = np.linalg.norm(Y[bad], axis=1)
    Y /= n[:, None]
    return np.stack([X, Y, np.cross(X, Y)], axis=-1)


class HelixBatch:
    """``count`` helices of one shape as one tube mesh: VPython's helix
    (:class:`HelixTube`'s numbers) for many springs at once, each from its own start
    along its own axis.

    ``chords_per_coil`` and ``sides`` set the resolution (VPython's are 60 and 16; a
    lattice of hundreds of bonds draws fewer). The faces are fixed; :meth:`points`
    writes every vertex and normal for new axes, vectorised over the springs.
    """

    def __init__(self, count: int, radius: float, thickness: float, coils: float,
                 chords_per_coil: int = CHORDS_PER_COIL, sides: int = TUBE_SIDES,
                 ccw: bool = True) -> None:
        self.count = int(count)
        self.radius = radius
        self.wire = thickness / 2 if thickness > 0 else radius / 20
        self.coils = coils
        self.sides = int(sides)
        n = int(round(coils * chords_per_coil)) + 1
        self.n_rings = n
        s = np.linspace(0.0, 1.0, n)
        self._k = (1.0 if ccw else -1.0) * 2 * math.pi * coils      # d(theta)/ds
        theta = self._k * s
        sin_t, cos_t = np.sin(theta)[:, None], np.cos(theta)[:, None]
        phi = 2 * math.pi * np.arange(self.sides) / self.sides
        sin_p, cos_p = np.sin(phi)[None, :], np.cos(phi)[None, :]
        # Per vertex (ring, side), flattened. With T the unit tangent and N the inward
        # normal of the centre line, B = T x N = (-R k, L cos, -L sin) / |T|, so the
        # local normal N cos(phi) + B sin(phi) is (b sp, P + a Q, U + a V) with
        # a = L/|T|, b = -R k/|T| per spring and P, Q, U, V per vertex.
        ones = np.ones((n, self.sides))
        self._s = (s[:, None] * ones).ravel()
        self._sin_p = (sin_p * ones).ravel()
        self._P = (-sin_t * cos_p).ravel()
        self._Q = (cos_t * sin_p).ravel()
        self._U = (-cos_t * cos_p).ravel()
        self._V = (-sin_t * sin_p).ravel()
        self._Rsin = (radius * sin_t * ones).ravel()
        self._Rcos = (radius * cos_t * ones).ravel()

    @property
    def points_per_helix(self) -> int:
        return self.n_rings * self.sides

    def faces(self) -> np.ndarray:
        """Quads between consecutive rings of every helix, VTK's flat ``[4, a, b, c, d, ...]``."""
        m = self.sides
        ring = np.arange(self.n_rings - 1)[:, None] * m
        q = np.arange(m)[None, :]
        q1 = (q + 1) % m
        quads = np.stack([ring + q, ring + q1, ring + m + q1, ring + m + q],
                         axis=-1).reshape(-1, 4)
        offsets = np.arange(self.count)[:, None, None] * self.points_per_helix
        quads = (quads[None] + offsets).reshape(-1, 4)
        return np.hstack([np.full((len(quads), 1), 4), quads]).ravel()

    def points(self, pos, axis, frames: np.ndarray, out_points: np.ndarray | None = None,
               out_normals: np.ndarray | None = None) -> tuple[np.ndarray, np.ndarray]:
        """World vertex positions and unit normals, each (count * points_per_helix, 3).

        ``pos`` and ``axis`` are (count, 3); ``frames`` (count, 3, 3) the local frames
        (columns X along the axis, Y, Z), e.g. from :func:`frames_from_up`. With
        ``out_points`` / ``out_normals`` (any float dtype, that shape) the results are
        written into them.
        """
        pos = np.asarray(pos, dtype=float).reshape(-1, 3)
        L = np.linalg.norm(np.asarray(axis, dtype=float).reshape(-1, 3), axis=1)[:, None]
        Rk = self.radius * self._k
        norm_T = np.sqrt(L * L + Rk * Rk)
        a, b = L / norm_T, -Rk / norm_T                     # (S, 1)
        nx = b * self._sin_p                                # (S, M)
        ny = self._P + a * self._Q
        nz = self._U + a * self._V
        w = self.wire
        local = np.stack([self._s * L + w * nx, self._Rsin + w * ny, self._Rcos + w * nz],
                         axis=-1)                           # (S, M, 3)
        F = np.swapaxes(frames, 1, 2)                       # rows X, Y, Z
        world = np.matmul(local, F)
        world += pos[:, None, :]
        normals = np.matmul(np.stack([nx, ny, nz], axis=-1), F)
        shape = (-1, 3)
        if out_points is not None:
            out_points[...] = world.reshape(shape)
            world = out_points
        if out_normals is not None:
            out_normals[...] = normals.reshape(shape)
            normals = out_normals
        return world.reshape(shape), normals.reshape(shape)
