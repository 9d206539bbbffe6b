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
