"""Points and thin curves as VPython draws them: lit meshes sized by the canvas's range.

GlowScript 3.2 (bundled with vpython 7.6.5) draws neither as GL points or lines:

- ``points``: each point is a ``simple_sphere`` (primitives.js ``__push_and_append``),
  drawn with the renderer's ``simple_sphere`` model, ``Mesh.makeSphere(0.5, 8)``: an
  8 x 8 UV sphere (8 bands of latitude, 8 sectors of longitude), lit like any sphere
  (ray-cast as that polyhedron where the GL allows, :class:`..draw.impostors.PointImpostors`). For ``size_units="pixels"`` (the default)
  WebGLRenderer.js ``render`` resizes them at every render to a diameter of
  ``20 s`` (radius 0, the default) or ``2 s radius``, with ``s = 2 range / width``:
  about 12.5 px (radius 0) or 1.25 radius px across on a 640 x 400 canvas, in the
  plane of ``center``. With ``size_units="world"`` a point is a sphere of its radius.
- a ``curve`` of radius 0: WebGLRenderer.js ``render`` gives it, for drawing, the
  radius ``4 range / width`` (``obj.__data[15]``): a lit 16-sided tube with round
  joints (mesh.js ``makeCurveSegment``) about 2.5 px wide on a 640 px canvas.

Both depend on the range, so the renderer draws them again when the view changes
(after :func:`.thinning.thin_line` merged points under a pixel apart on screen).
"""

from __future__ import annotations

import functools

import numpy as np

from . import placement, meshes
from .thinning import thin_line

POINT_SLICES = 8          # simple_sphere: Mesh.makeSphere(0.5, 8)
POINT_DIAMETER = 20.0     # in units of s = 2 range / width, for radius 0


@functools.cache
def point_sphere() -> placement.Mesh:
    """The ``simple_sphere`` model as mesh.js ``makeSphere(0.5, 8)`` builds it: diameter
    1, its poles on y, 8 bands of latitude (rings every 22.5 degrees) and 8 sectors of
    longitude (every 45 degrees from the x axis), its vertices on the sphere and their
    normals their directions; triangles wound outwards."""
    n = POINT_SLICES
    theta = np.arange(1, n) * np.pi / n                 # the rings between the poles
    phi = np.arange(n) * 2 * np.pi / n
    rings = np.stack([np.outer(np.sin(theta), np.cos(phi)),
                      np.repeat(np.cos(theta)[:, None], n, axis=1),
                      np.outer(np.sin(theta), np.sin(phi))], axis=2).reshape(-1, 3)
    directions = np.vstack([[0.0, 1.0, 0.0], rings, [0.0, -1.0, 0.0]])
    ring = (np.arange(n - 1)[:, None] * n + 1)          # each ring's first vertex
    j, k = np.arange(n), (np.arange(n) + 1) % n
    bottom = len(directions) - 1
    tris = [np.column_stack([np.zeros(n, dtype=int), ring[0] + k, ring[0] + j])]
    for a, b in zip(ring[:-1], ring[1:]):
        tris += [np.column_stack([a + j, a + k, b + j]), np.column_stack([a + k, b + k, b + j])]
    tris.append(np.column_stack([np.full(n, bottom), ring[-1] + j, ring[-1] + k]))
    triangles = np.vstack(tris)
    corners = directions[triangles]
    outward = np.einsum("ij,ij->i", np.cross(corners[:, 1] - corners[:, 0],
                                              corners[:, 2] - corners[:, 0]), corners.sum(axis=1))
    triangles = np.where((outward < 0)[:, None], triangles[:, ::-1], triangles)
    return placement.Mesh(directions / 2, directions, triangles)


def pixel_scale(range_: float, width: int) -> float:
    """GlowScript's ``scale = 2 range / width``: world units per "pixel" of a size."""
    return 2.0 * range_ / width


def point_diameters(radii: np.ndarray, range_: float, width: int) -> np.ndarray:
    """World diameters of pixel-sized points of these radii (0: the default size)."""
    s = pixel_scale(range_, width)
    radii = np.asarray(radii, dtype=float)
    return np.where(radii > 0, 2.0 * s * radii, POINT_DIAMETER * s)


def thin_radius(range_: float, width: int) -> float:
    """The world radius a curve of radius 0 is drawn with: ``4 range / width``."""
    return 4.0 * range_ / width


def spheres(pos: np.ndarray, rgb: np.ndarray, diameters: np.ndarray, template):
    """Points, normals, triangles and colours of one sphere per point (``template``, a unit
    sphere mesh), ``diameters`` across."""
    n = len(template.points)
    eye = np.broadcast_to(np.eye(3), (len(pos), 3, 3))
    size = np.repeat(np.asarray(diameters, dtype=float)[:, None], 3, axis=1)
    points, normals = placement.place(template, pos, eye, size)
    return points, normals, placement.tile(template.triangles, n, len(pos)), \
        np.repeat(rgb, n, axis=0)


def tube(pos: np.ndarray, rgb: np.ndarray, radii: np.ndarray):
    """Points, normals, triangles and colours of a curve drawn as a tube of these radii."""
    mesh = meshes.tube(pos, radii)
    return mesh.points, mesh.normals, mesh.triangles, rgb[meshes.tube_vertex_points(len(pos))]


def thin_radii(radii: np.ndarray, range_: float, width: int) -> np.ndarray:
    """Each point's drawing radius on a curve of radius 0: its own if it has one, else
    the range's (GlowScript: a point's radius -1 means the curve's)."""
    radii = np.asarray(radii, dtype=float)
    return np.where(radii > 0, radii, thin_radius(range_, width))


def _rgb(colors: np.ndarray) -> np.ndarray:
    return np.clip(np.rint(np.asarray(colors) * 255), 0, 255).astype(np.uint8)


def balls(kind: str, obj, range_: float, width: int):
    """Centres (n, 3), world diameters (n,) and RGB (n, 3) uint8 of a points object's
    balls (``kind`` "points", pixel-sized, or "sphere-points", world-sized); None when
    it has none."""
    p, col, rad = obj._arrays()
    if not len(p):
        return None
    diam = point_diameters(rad, range_, width) if kind == "points" else 2.0 * rad
    return p, diam, _rgb(col)


def polyline(kind: str, obj, view, range_: float, width: int):
    """Points (n, 3), RGB (n, 3) uint8 and radii (n,) of a curve drawn for ``view``
    (``kind`` "lines", radius 0, or "tube"): its points under a pixel apart on screen
    merged, a thin curve's radii the range's; None with fewer than two points."""
    p, col, rad = obj._arrays()
    if len(p) < 2:
        return None
    if view is not None:
        p, col, rad = thin_line((p, col, rad), view)
    if kind == "lines":
        rad = thin_radii(rad, range_, width)
    return p, _rgb(col), rad


def mesh(kind: str, obj, view, range_: float, width: int):
    """Points, normals, triangles and RGB (uint8) of one curve or points object drawn for
    ``view`` with the canvas's ``range_``; None when it has nothing to draw.

    ``kind`` is its batch's: "points" (pixel-sized), "sphere-points" (world-sized),
    "lines" (a curve of radius 0) or "tube" (radius > 0). Curves have their points
    under a pixel apart on screen merged first (a trail is thousands of them).
    """
    if kind in ("points", "sphere-points"):
        got = balls(kind, obj, range_, width)
        return None if got is None else spheres(got[0], got[2], got[1], point_sphere())
    got = polyline(kind, obj, view, range_, width)
    return None if got is None else tube(*got)
