"""Triangle meshes and where their copies go: VPython's frame rule, many objects at a time.

:class:`Mesh` is a template's vertices, normals, triangles (and texture
coordinates, for the textured templates); :func:`frames` gives
each object's local frame from its ``axis`` and ``up``; :func:`place` puts M
copies of a template into the world with one batched matrix product; :func:`tile`
and :func:`vtk_cells` give the triangles of the copies. The templates themselves
are in :mod:`.meshes`.

The frame convention shared with the renderer
---------------------------------------------
An object has ``pos``, ``axis``, ``up`` and ``size``. Its local frame is
X = norm(axis), Y = norm(up - (up.X) X), Z = X x Y, and a template point ``p``
goes to ``pos + R @ (p * size)`` with R's columns (X, Y, Z). Centred kinds
(sphere, ellipsoid, box) span [-0.5, 0.5] on every local axis; end-anchored
kinds (cylinder, cone, pyramid) span x in [0, 1] and y, z in [-0.5, 0.5], so
``pos`` is one end and ``size = (length, diameter, diameter)``. Arrow and ring
templates are built in local *lengths* (placed with size (1, 1, 1)) because
their proportions do not scale linearly.

VPython facts used: primitives.js ``getTransformedMesh`` (the frame rule when up
is parallel to the axis, :func:`frames`); ``vpython/vpython.py`` ``adjust_up``
(:func:`adjust_up`); GlowScript's object vertex shaders transform normals as
``rot * (normal / size)``, i.e. by the inverse transpose (:func:`place`).
"""

from __future__ import annotations

import itertools
import operator
from typing import NamedTuple

import numpy as np


class Mesh(NamedTuple):
    """A triangle mesh: vertices, unit vertex normals, outward counter-clockwise triangles,
    and, for a textured template, each vertex's texture coordinates (VPython's ``texpos``:
    u to the right and v up the picture, both 0..1)."""

    points: np.ndarray     # (n, 3) float64
    normals: np.ndarray    # (n, 3) float64, unit
    triangles: np.ndarray  # (f, 3) int64
    uv: np.ndarray | None = None   # (n, 2) float64, or None: not textured


def _unit_rows(v: np.ndarray) -> np.ndarray:
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(n == 0, 1.0, n)


# -- frames -------------------------------------------------------------------------------

_X_AXIS = np.array([1.0, 0.0, 0.0])
_Y_AXIS = np.array([0.0, 1.0, 0.0])


def _robust_unit(v: np.ndarray) -> np.ndarray:
    """Unit rows, dividing by the largest component first (as GlowScript's shaders); zero stays zero."""
    vmax = np.abs(v).max(axis=-1, keepdims=True)
    w = v / np.where(vmax == 0, 1.0, vmax)
    return _unit_rows(w)


def frames(axis, up) -> np.ndarray:
    """Local frames (M, 3, 3), columns X, Y, Z, of objects with these ``axis`` and ``up``.

    X = norm(axis), Z = norm(X x norm(up)), Y = Z x X, i.e. Y = norm(up - (up.X) X).
    When up is parallel to the axis (``|X x up|^2 < 1e-10``) VPython's rule
    (primitives.js ``getTransformedMesh``, GlowScript's object shaders) takes
    up = (1, 0, 0) instead, and (0, 1, 0) if that is parallel too. A zero
    axis is taken as (1, 0, 0) (the object then has zero length anyway).
    """
    axis, up = np.broadcast_arrays(np.atleast_2d(np.asarray(axis, dtype=float)),
                                   np.asarray(up, dtype=float))
    X = _robust_unit(axis)
    X[~X.any(axis=1)] = _X_AXIS
    Z = np.cross(X, _robust_unit(up))
    bad = np.einsum("ij,ij->i", Z, Z) < 1e-10
    if bad.any():
        Z[bad] = np.cross(X[bad], _X_AXIS)
        worse = bad.copy()
        worse[bad] = np.einsum("ij,ij->i", Z[bad], Z[bad]) < 1e-10
        Z[worse] = np.cross(X[worse], _Y_AXIS)
    Z = _unit_rows(Z)
    Y = _unit_rows(np.cross(Z, X))
    return np.stack([X, Y, Z], axis=-1)


def adjust_up(old_axis, new_axis, up) -> np.ndarray:
    """VPython's ``up`` after ``axis`` changes from ``old_axis`` to ``new_axis``, vectorised (M, 3).

    vpython.py ``adjust_up``: when the new axis is not exactly perpendicular to
    up, up is rotated by the angle between the axes about ``old x new``
    (negated for a half turn; unchanged below 1e-6 rad or for a zero axis).
    The same rotation as :class:`springscene.view.geometry.HelixFrame`.
    """
    old, new, up = np.broadcast_arrays(*(np.atleast_2d(np.asarray(v, dtype=float))
                                         for v in (old_axis, new_axis, up)))
    up = up.copy()
    a, b = _unit_rows(old), _unit_rows(new)
    angle = np.arccos(np.clip(np.einsum("ij,ij->i", a, b), -1.0, 1.0))
    turn = (new.any(axis=1) & old.any(axis=1) & (np.einsum("ij,ij->i", new, up) != 0)
            & (angle > 1e-6))
    flip = turn & (np.abs(angle - np.pi) < 1e-6)
    rot = turn & ~flip
    k = _unit_rows(np.cross(a[rot], b[rot]))
    v, c, s = up[rot], np.cos(angle[rot])[:, None], np.sin(angle[rot])[:, None]
    up[rot] = v * c + np.cross(k, v) * s + k * np.einsum("ij,ij->i", k, v)[:, None] * (1 - c)
    up[flip] = -up[flip]
    return up


# -- placement ----------------------------------------------------------------------------

_TINY = 1e-30


def _nonzero(size: np.ndarray) -> np.ndarray:
    """``size`` with zero components replaced by a tiny number, for ``normal / size``."""
    return np.where(np.abs(size) < _TINY, _TINY, size)


def place(mesh: Mesh, pos, R, size) -> tuple[np.ndarray, np.ndarray]:
    """World points and unit normals, each (M * n, 3), of M copies of a template.

    ``world = pos + R @ (p * size)``; normals by the inverse transpose,
    ``R @ norm(n / size)`` (GlowScript: ``rot * (normal / size)``). Copies with
    equal size components (spheres) skip the normalisation. ``pos`` (M, 3),
    ``R`` (M, 3, 3) from :func:`frames`, ``size`` (M, 3); any of them may be a
    single row broadcast to all. Both are one batched matrix product with the
    template (points in homogeneous coordinates, so ``pos`` comes free).
    """
    R = np.asarray(R, dtype=float)
    if R.ndim == 2:
        R = R[None]
    pos = np.asarray(pos, dtype=float).reshape(-1, 3)
    size = np.asarray(size, dtype=float).reshape(-1, 3)
    M = max(len(R), len(pos), len(size))
    R, pos, size = (np.broadcast_to(x, (M,) + x.shape[1:]) for x in (R, pos, size))
    n = len(mesh.points)
    # out[m, k, i] = sum_j p_h[k, j] H[m, i, j] with H = [R diag(size) | pos]
    H = np.concatenate([R * size[:, None, :], pos[:, :, None]], axis=2)
    homogeneous = np.hstack([mesh.points, np.ones((n, 1))])
    points = np.empty((M, n, 3))
    np.matmul(homogeneous[None], H.transpose(0, 2, 1), out=points)
    normals = np.empty((M, n, 3))
    uniform = (size[:, 0] == size[:, 1]) & (size[:, 1] == size[:, 2]) & (size[:, 0] != 0)
    if uniform.all():
        np.matmul(mesh.normals[None], R.transpose(0, 2, 1), out=normals)
    else:
        scale = np.where(uniform[:, None], 1.0, 1.0 / _nonzero(size))
        np.matmul(mesh.normals[None], (R * scale[:, None, :]).transpose(0, 2, 1), out=normals)
        odd = ~uniform
        part = normals if odd.all() else normals[odd]
        length = np.sqrt(np.einsum("mki,mki->mk", part, part))
        part /= np.where(length == 0, 1.0, length)[:, :, None]
        if part is not normals:
            normals[odd] = part
    return points.reshape(-1, 3), normals.reshape(-1, 3)


def xyz_array(objs, *names: str) -> np.ndarray:
    """The vector attributes ``names`` of each object side by side, (M, 3 * len(names)):
    read straight into the array, no list of tuples held (for 100,000 spheres such a list
    is 7 MB an attribute, freed but left in the allocator's pools)."""
    getters = [operator.attrgetter(n) for n in names]
    flat = itertools.chain.from_iterable(g(o)._xyz() for o in objs for g in getters)
    return np.fromiter(flat, dtype=float, count=3 * len(names) * len(objs)).reshape(
        len(objs), 3 * len(names))


def object_frames(objs) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """pos, frame (columns X, Y, Z), size and colour arrays of VPython objects, (M, ...)."""
    pos, axis, up, size, color = np.split(
        xyz_array(objs, "_pos", "_axis", "_up", "_size", "_color"), 5, axis=1)
    return pos, frames(axis, up), size, color


def tile(triangles, n_points: int, M: int) -> np.ndarray:
    """Triangle indices (M * f, 3) of M copies of a mesh of ``n_points`` points, copy after copy."""
    triangles = np.asarray(triangles, dtype=np.int64)
    offsets = n_points * np.arange(M, dtype=np.int64)
    return (triangles[None] + offsets[:, None, None]).reshape(-1, 3)


def vtk_cells(triangles) -> np.ndarray:
    """Triangles in VTK's flat cell layout ``[3, a, b, c, 3, ...]`` for ``pyvista.PolyData``."""
    triangles = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    return np.hstack([np.full((len(triangles), 1), 3, dtype=np.int64), triangles]).ravel()




__all__ = ["Mesh", "frames", "adjust_up", "place", "object_frames", "tile", "vtk_cells"]
