"""VPython 6's ``faces`` and ``convex`` (:mod:`..objects.array_surfaces`) as world meshes.

- A ``faces`` object is drawn as its whole triangles, each vertex with its own position,
  normal and colour (blended across a triangle, as VPython 6's smooth shading did), only
  from the side its vertices run counter-clockwise (VPython 6 culled the back,
  ``GL_CULL_FACE``). A vertex whose normal is <0, 0, 0> is lit by its triangle's normal
  (VPython 6 lit it by the ambient light alone).
- A ``convex`` object is drawn as the convex hull of its points, flat-shaded, in its one
  colour: :func:`hull` finds the hull's triangles with VTK's ``vtkDelaunay3D``, turned
  to face outward; points all in a plane (VTK has no volume there) make a flat polygon,
  found in the plane, drawn with both windings. A hull is found again only when the
  points changed.

In a VPython 6 frame their points (and normals) are the frame's, placed in the world
here. :func:`box` gives autoscale (:mod:`.autoscale`) their world bounds.
"""

from __future__ import annotations

import weakref
import zlib

import numpy as np

from ..geometry.object_meshes import rgb8

KINDS = ("faces", "convex")

_HULLS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()   # convex -> (checksum, mesh)


def _placement(obj) -> tuple[np.ndarray, np.ndarray] | None:
    """(origin, rotation) of the frame holding ``obj``, or None in the world."""
    f = getattr(obj, "_frame", None)
    return None if f is None else f._placement()


def _in_world(points: np.ndarray, placed, shift: bool = True) -> np.ndarray:
    if placed is None:
        return points
    o, R = placed
    return points @ R.T + (o if shift else 0.0)


def box(obj) -> tuple[tuple, tuple] | None:
    """The world (lo, hi) corners of the points drawn (None: nothing drawn)."""
    p = obj._arrays.view("pos")
    if obj._kind == "faces":
        p = p[:len(p) - len(p) % 3]
    if not len(p):
        return None
    p = _in_world(p, _placement(obj))
    return tuple(p.min(axis=0).tolist()), tuple(p.max(axis=0).tolist())


def meshes(objs: list) -> list:
    """(points, normals, triangles, RGB uint8) of each object that draws anything."""
    out = []
    for o in objs:
        m = faces_mesh(o) if o._kind == "faces" else convex_mesh(o)
        if m is not None:
            out.append(m)
    return out


def one_sided(batch, key: tuple) -> None:
    """Faces are seen from their front only; a convex hull (closed) skips its far side
    when opaque, as any closed surface."""
    if batch.actor is not None:
        batch.actor.GetProperty().SetBackfaceCulling(key[0] == "faces" or key[1] >= 1)


def _triangle_normals(t: np.ndarray) -> np.ndarray:
    """Unit normals of triangles (M, 3, 3), counter-clockwise (zero for degenerate ones)."""
    n = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 1])
    length = np.linalg.norm(n, axis=1, keepdims=True)
    return np.divide(n, length, out=np.zeros_like(n), where=length > 0)


def faces_mesh(obj):
    """A faces object's whole triangles in the world, or None when it has none."""
    a = obj._arrays
    n = a.count - a.count % 3
    if n == 0:
        return None
    placed = _placement(obj)
    points = _in_world(a.view("pos")[:n], placed)
    normals = _in_world(a.view("normal")[:n], placed, shift=False)
    unset = ~normals.any(axis=1)
    if unset.any():
        normals = normals.copy()
        own = np.repeat(_triangle_normals(points.reshape(-1, 3, 3)), 3, axis=0)
        normals[unset] = own[unset]
    triangles = np.arange(n, dtype=np.int64).reshape(-1, 3)
    return points, normals, triangles, rgb8(a.view("color")[:n])


def convex_mesh(obj):
    """A convex object's hull in the world, flat-shaded, or None when it has no area."""
    pos = obj._arrays.view("pos")
    mark = zlib.crc32(memoryview(np.ascontiguousarray(pos)), len(pos))
    kept = _HULLS.get(obj)
    if kept is None or kept[0] != mark:
        kept = _HULLS[obj] = (mark, hull(pos))
    corners = kept[1]
    if corners is None:
        return None
    placed = _placement(obj)
    t = _in_world(corners.reshape(-1, 3), placed).reshape(-1, 3, 3)
    points = t.reshape(-1, 3)
    normals = np.repeat(_triangle_normals(t), 3, axis=0)
    triangles = np.arange(len(points), dtype=np.int64).reshape(-1, 3)
    colors = np.repeat(rgb8([obj._color._xyz()]), len(points), axis=0)
    return points, normals, triangles, colors


def hull(points: np.ndarray) -> np.ndarray | None:
    """The convex hull of ``points`` as triangles (M, 3, 3), each counter-clockwise seen
    from outside; a flat one has each triangle twice, once each way. None when the
    points span no area (fewer than three, or all in a line)."""
    p = np.unique(np.asarray(points, dtype=float).reshape(-1, 3), axis=0)
    if len(p) < 3:
        return None
    centre = p.mean(axis=0)
    _, s, axes = np.linalg.svd(p - centre, full_matrices=False)
    if s[1] <= 1e-9 * s[0]:
        return None
    if len(p) == 3 or s[2] <= 1e-9 * s[0]:
        return _flat_hull(p, centre, axes)
    return _outward(p[_delaunay_surface(p)], centre)


def _delaunay_surface(p: np.ndarray) -> np.ndarray:
    """The outer triangles (indices into ``p``) of VTK's Delaunay tetrahedra of ``p``."""
    from vtkmodules.util.numpy_support import numpy_to_vtk, vtk_to_numpy  # noqa: PLC0415  heavy: vtk
    from vtkmodules.vtkCommonCore import vtkPoints  # noqa: PLC0415  heavy: vtk
    from vtkmodules.vtkCommonDataModel import vtkPolyData  # noqa: PLC0415  heavy: vtk
    from vtkmodules.vtkFiltersCore import vtkDelaunay3D  # noqa: PLC0415  heavy: vtk
    from vtkmodules.vtkFiltersGeometry import vtkDataSetSurfaceFilter  # noqa: PLC0415  heavy: vtk

    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(np.ascontiguousarray(p), deep=True))
    cloud = vtkPolyData()
    cloud.SetPoints(pts)
    tetra = vtkDelaunay3D()
    tetra.SetInputData(cloud)
    tetra.SetTolerance(0.0)          # every distinct point kept (its ids are the input's)
    surface = vtkDataSetSurfaceFilter()
    surface.SetInputConnection(tetra.GetOutputPort())
    surface.PassThroughPointIdsOn()
    surface.Update()
    out = surface.GetOutput()
    ids = vtk_to_numpy(out.GetPointData().GetArray(surface.GetOriginalPointIdsName()))
    cells = vtk_to_numpy(out.GetPolys().GetConnectivityArray()).reshape(-1, 3)
    return ids[cells]


def _outward(t: np.ndarray, centre: np.ndarray) -> np.ndarray:
    """Triangles (M, 3, 3) of a convex surface wound counter-clockwise from outside."""
    n = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
    inward = np.einsum("ij,ij->i", n, t.mean(axis=1) - centre) < 0
    t = t.copy()
    t[inward] = t[inward][:, (0, 2, 1)]
    return t


def _flat_hull(p: np.ndarray, centre: np.ndarray, axes: np.ndarray) -> np.ndarray:
    """A flat hull: the polygon around the points in their plane, as a fan of
    triangles, each once counter-clockwise about the plane's normal and once back."""
    uv = (p - centre) @ axes[:2].T
    ring = p[_ring_2d(uv)]
    front = np.stack([np.repeat(ring[:1], len(ring) - 2, axis=0), ring[1:-1], ring[2:]],
                     axis=1)
    return np.concatenate([front, front[:, (0, 2, 1)]])


def _ring_2d(uv: np.ndarray) -> np.ndarray:
    """Indices of the 2D convex hull's corners, counter-clockwise (Andrew's monotone
    chain: the lower and the upper chains of the points sorted by u, then v)."""
    order = np.lexsort((uv[:, 1], uv[:, 0])).tolist()

    def chain(indices: list) -> list:
        out: list = []
        for i in indices:
            while len(out) >= 2 and _turn(uv[out[-2]], uv[out[-1]], uv[i]) <= 0:
                out.pop()
            out.append(i)
        return out[:-1]
    return np.array(chain(order) + chain(order[::-1]))


def _turn(a, b, c) -> float:
    return float((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))


__all__ = ["KINDS", "box", "meshes", "one_sided", "faces_mesh", "convex_mesh", "hull"]
