"""The geometry of VPython's objects as numpy arrays, placed many at a time.

Each kind of object has a *template* mesh in its own local frame; :func:`place`
puts M copies of a template into the world with one ``einsum``. No VTK here
(the sphere's vertex layout is taken once from :func:`pyvista.Sphere`, so a
VPython ``sphere`` renders exactly like springscene's existing ball).

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

VPython facts used (VPython 7, ``vpython/vpython-jupyter``; GlowScript,
``vpython/glowscript``):

- ``vpython/vpython.py``: default sizes (box, pyramid, ellipsoid (1,1,1);
  sphere (2,2,2); cylinder, cone, helix (1,2,2); arrow (1,0.2,0.2); ring
  (0.2,2.2,2.2)); ``radius = size.y/2``; ring ``thickness = size.x/2`` and
  ``radius = (size.y - size.x)/2``; setting ``axis`` sets ``size.x = |axis|``
  except for sphere and ring; setting ``size`` rescales ``axis`` except for
  ring; ``adjust_up`` rotates ``up`` with the axis.
- ``lib/glow/primitives.js`` ``arrow_update``: shaft and head widths/length and
  their shrinking rules (:func:`arrow_dims`); the arrow is a box shaft plus a
  pyramid head. ``getTransformedMesh``: the frame rule when up is parallel to
  the axis (:func:`frames`).
- ``lib/glow/mesh.js``: ``makeCube`` (24 vertices), ``makeCylinder`` (50
  sides), ``makeCone`` (200 sides), ``makePyramid``, ``makeRing`` (60 cross
  sections of 20 sides), ``makeCurveSegment`` (16-sided open tube with a
  hemisphere on its far end).
- GlowScript's object vertex shaders transform normals as ``rot * (normal /
  size)``, i.e. by the inverse transpose (:func:`place`).
"""

from __future__ import annotations

import functools
from typing import NamedTuple

import numpy as np

from ..view.geometry import TUBE_SIDES

SPHERE_SLICES = 30      # our scene's ball (GlowScript: makeSphere(0.5, 30))
CYLINDER_SIDES = 50     # mesh.js makeCylinder: N = 50
CONE_SIDES = 200        # mesh.js makeCone: N = 200
RING_SECTIONS = 60      # mesh.js makeRing: NC = 60 cross sections around the ring
RING_SIDES = 20         # mesh.js makeRing: N = 20 sides of each cross section
CURVE_SIDES = TUBE_SIDES  # mesh.js makeCurveSegment: N = 16
CAP_RINGS = 4           # latitude rings of a curve's hemispherical joint (ours)

# -- sizes in VPython terms ---------------------------------------------------------------

DEFAULT_SIZE = {         # vpython.py: args['_default_size'] of each class
    "box": (1.0, 1.0, 1.0),
    "pyramid": (1.0, 1.0, 1.0),
    "ellipsoid": (1.0, 1.0, 1.0),
    "sphere": (2.0, 2.0, 2.0),
    "cylinder": (1.0, 2.0, 2.0),
    "cone": (1.0, 2.0, 2.0),
    "helix": (1.0, 2.0, 2.0),
    "arrow": (1.0, 0.2, 0.2),
    "ring": (0.2, 2.2, 2.2),
}
CENTRED = frozenset({"sphere", "ellipsoid", "box", "ring"})   # pos is the centre
SIZE_INDEX = {"length": 0, "height": 1, "width": 2}           # box.length = size.x, ...
_RADIUS_ALL = frozenset({"sphere", "ellipsoid"})              # radius sets (d, d, d)
_RADIUS_YZ = frozenset({"cylinder", "cone", "helix"})         # radius sets (x, d, d)


def default_size(kind: str) -> np.ndarray:
    """VPython's default ``size`` of an object of this kind (a new array)."""
    return np.array(DEFAULT_SIZE[kind], dtype=float)


def is_centred(kind: str) -> bool:
    """True when ``pos`` is the object's centre, False when it is one end."""
    return kind in CENTRED


def axis_sets_length(kind: str) -> bool:
    """Whether setting ``axis`` sets ``size.x = |axis|`` (vpython.py: not for sphere, ring)."""
    return kind not in ("sphere", "ring")


def size_sets_axis(kind: str) -> bool:
    """Whether setting ``size`` rescales ``axis`` to ``size.x`` (vpython.py: not for ring)."""
    return kind != "ring"


def radius_from_size(kind: str, size) -> float:
    """``radius`` as VPython reads it from ``size``.

    ``size.y / 2`` for sphere, ellipsoid, cylinder, cone and helix; for a ring
    the radius of the tube's centre line, ``(size.y - size.x) / 2``.
    """
    s = np.asarray(size, dtype=float)
    if kind == "ring":
        return float((s[1] - s[0]) / 2)
    if kind in _RADIUS_ALL or kind in _RADIUS_YZ:
        return float(s[1] / 2)
    raise AttributeError(f"a {kind} has no radius")


def size_for_radius(kind: str, size, radius: float) -> np.ndarray:
    """The ``size`` after setting ``radius`` (vpython.py's radius setters)."""
    s = np.array(size, dtype=float)
    d = 2.0 * radius
    if kind in _RADIUS_ALL:
        s[:] = d
    elif kind in _RADIUS_YZ:
        s[1] = s[2] = d
    elif kind == "ring":
        s[1] = s[2] = 2.0 * (radius + s[0] / 2)
    else:
        raise AttributeError(f"a {kind} has no radius")
    return s


def ring_thickness_from_size(size) -> float:
    """A ring's ``thickness``: the *radius* of its cross section, ``size.x / 2``."""
    return float(np.asarray(size, dtype=float)[0] / 2)


def size_for_ring_thickness(size, thickness: float) -> np.ndarray:
    """A ring's ``size`` after setting ``thickness``, keeping its radius (vpython.py)."""
    s = np.array(size, dtype=float)
    radius = (s[1] - s[0]) / 2
    s[0] = 2.0 * thickness
    s[1] = s[2] = 2.0 * (radius + thickness)
    return s


def ring_size(radius: float, thickness: float) -> np.ndarray:
    """``size`` of a ring of centre-line ``radius`` and cross-section radius ``thickness``."""
    return np.array([2 * thickness, 2 * (radius + thickness), 2 * (radius + thickness)])


def helix_wire_radius(size, thickness: float = 0.0) -> float:
    """Radius of a helix's wire: ``thickness / 2``, or ``size.y / 40`` when unset (primitives.js)."""
    return thickness / 2 if thickness else float(np.asarray(size, dtype=float)[1] / 40)


# -- templates ----------------------------------------------------------------------------

class Mesh(NamedTuple):
    """A triangle mesh: vertices, unit vertex normals, outward counter-clockwise triangles."""

    points: np.ndarray     # (n, 3) float64
    normals: np.ndarray    # (n, 3) float64, unit
    triangles: np.ndarray  # (f, 3) int64


def _unit_rows(v: np.ndarray) -> np.ndarray:
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(n == 0, 1.0, n)


def _mesh(points, normals, triangles) -> Mesh:
    return Mesh(np.ascontiguousarray(points, dtype=float),
                np.ascontiguousarray(_unit_rows(np.asarray(normals, dtype=float))),
                np.ascontiguousarray(triangles, dtype=np.int64).reshape(-1, 3))


def _frozen(mesh: Mesh) -> Mesh:
    for a in mesh:
        a.setflags(write=False)
    return mesh


@functools.cache
def sphere(slices: int = SPHERE_SLICES) -> Mesh:
    """Centred sphere of diameter 1 with ``pyvista.Sphere``'s vertex layout and triangles.

    Points are ``pyvista.Sphere(radius=0.5, theta_resolution=slices,
    phi_resolution=slices)``'s (made once and cached); normals are the exact
    radial directions. Also the ellipsoid's template (GlowScript draws an
    ellipsoid with the sphere model).
    """
    import pyvista as pv          # only to copy its vertex layout, once

    s = pv.Sphere(radius=0.5, theta_resolution=slices, phi_resolution=slices)
    points = np.asarray(s.points, dtype=float)
    triangles = np.asarray(s.faces).reshape(-1, 4)[:, 1:]
    return _frozen(_mesh(points, points, triangles))


@functools.cache
def box() -> Mesh:
    """Centred unit cube: 24 vertices (4 a face), flat normals, as mesh.js ``makeCube``."""
    s = 0.5
    points = np.array([
        [+s, +s, +s], [+s, -s, +s], [+s, -s, -s], [+s, +s, -s],   # right  (+x)
        [-s, +s, -s], [-s, -s, -s], [-s, -s, +s], [-s, +s, +s],   # left   (-x)
        [-s, -s, +s], [-s, -s, -s], [+s, -s, -s], [+s, -s, +s],   # bottom (-y)
        [-s, +s, -s], [-s, +s, +s], [+s, +s, +s], [+s, +s, -s],   # top    (+y)
        [-s, +s, +s], [-s, -s, +s], [+s, -s, +s], [+s, +s, +s],   # front  (+z)
        [+s, +s, -s], [+s, -s, -s], [-s, -s, -s], [-s, +s, -s],   # back   (-z)
    ])
    face_normals = np.array([[1, 0, 0], [-1, 0, 0], [0, -1, 0], [0, 1, 0], [0, 0, 1], [0, 0, -1]])
    normals = np.repeat(face_normals, 4, axis=0)
    quad = np.array([[0, 1, 2], [0, 2, 3]])
    triangles = (quad[None] + 4 * np.arange(6)[:, None, None]).reshape(-1, 3)
    return _frozen(_mesh(points, normals, triangles))


def _circle(sides: int) -> tuple[np.ndarray, np.ndarray]:
    """(y, z) of a circle of radius 0.5, starting at (-0.5, 0) as mesh.js's cylinder and cone."""
    theta = 2 * np.pi * np.arange(sides) / sides
    return -0.5 * np.cos(theta), 0.5 * np.sin(theta)


def _fan(center: int, rim: np.ndarray) -> np.ndarray:
    """Triangles (center, rim[k], rim[k+1]) around a closed rim."""
    return np.column_stack([np.full(len(rim), center), rim, np.roll(rim, -1)])


@functools.cache
def cylinder(sides: int = CYLINDER_SIDES) -> Mesh:
    """Cylinder from x = 0 to 1, diameter 1: smooth side, two flat caps (mesh.js: 50 sides).

    Points: the two cap centres, the rims of the caps (flat normals), then the
    side's two rings (radial normals): ``4 * sides + 2`` points, ``4 * sides`` triangles.
    """
    y, z = _circle(sides)
    zero, one = np.zeros(sides), np.ones(sides)
    ring0 = np.column_stack([zero, y, z])
    ring1 = np.column_stack([one, y, z])
    radial = np.column_stack([zero, y, z])
    points = np.vstack([[0, 0, 0], [1, 0, 0], ring0, ring1, ring0, ring1])
    normals = np.vstack([[-1, 0, 0], [1, 0, 0], np.tile([-1, 0, 0], (sides, 1)),
                         np.tile([1, 0, 0], (sides, 1)), radial, radial])
    k = np.arange(sides)
    k1 = np.roll(k, -1)
    cap0, cap1 = 2 + k, 2 + sides + k
    side0, side1 = 2 + 2 * sides + k, 2 + 3 * sides + k
    triangles = np.vstack([
        _fan(0, cap0),                                    # faces -x
        _fan(1, cap1)[:, [0, 2, 1]],                      # faces +x
        np.column_stack([side0, side1, side0[k1]]),
        np.column_stack([side0[k1], side1, side1[k1]]),
    ])
    return _frozen(_mesh(points, normals, triangles))


@functools.cache
def cone(sides: int = CONE_SIDES) -> Mesh:
    """Cone with base disc at x = 0 (diameter 1) and apex at x = 1 (mesh.js: 200 sides).

    Points: the base centre, the base rim (flat normals), the side's base ring
    and one apex vertex per side (smooth normals, the apex's at mid-side, as
    mesh.js): ``3 * sides + 1`` points, ``2 * sides`` triangles.
    """
    y, z = _circle(sides)
    zero = np.zeros(sides)
    rim = np.column_stack([zero, y, z])
    half = np.pi / sides                                  # the apex normal at mid-side
    theta = 2 * np.pi * np.arange(sides) / sides + half
    ym, zm = -0.5 * np.cos(theta), 0.5 * np.sin(theta)
    # the side r = (1 - x)/2 has outward normal along (1, 2 r_hat) = (1, 4 y, 4 z) on the rim r = 1/2
    side_n = np.column_stack([np.ones(sides), 4 * y, 4 * z])
    apex_n = np.column_stack([np.ones(sides), 4 * ym, 4 * zm])
    points = np.vstack([[0, 0, 0], rim, rim, np.tile([1.0, 0, 0], (sides, 1))])
    normals = np.vstack([[-1, 0, 0], np.tile([-1, 0, 0], (sides, 1)), side_n, apex_n])
    k = np.arange(sides)
    base, side, apex = 1 + k, 1 + sides + k, 1 + 2 * sides + k
    triangles = np.vstack([_fan(0, base), np.column_stack([side, apex, np.roll(side, -1)])])
    return _frozen(_mesh(points, normals, triangles))


@functools.cache
def pyramid() -> Mesh:
    """Square base 1 x 1 at x = 0 centred on the axis, apex at x = 1, flat normals (mesh.js)."""
    points = np.array([
        [0, .5, .5], [0, .5, -.5], [0, -.5, -.5], [0, -.5, .5],   # base
        [0, .5, -.5], [0, .5, .5], [1, 0, 0],                     # top    (+y)
        [0, -.5, -.5], [0, .5, -.5], [1, 0, 0],                   # back   (-z)
        [0, -.5, .5], [0, -.5, -.5], [1, 0, 0],                   # bottom (-y)
        [0, .5, .5], [0, -.5, .5], [1, 0, 0],                     # front  (+z)
    ])
    normals = np.array([[-1, 0, 0]] * 4 + [[1, 2, 0]] * 3 + [[1, 0, -2]] * 3
                       + [[1, -2, 0]] * 3 + [[1, 0, 2]] * 3)
    triangles = np.array([[0, 1, 2], [0, 2, 3], [4, 5, 6], [7, 8, 9], [10, 11, 12], [13, 14, 15]])
    return _frozen(_mesh(points, normals, triangles))


def arrow_dims(length: float, shaftwidth: float = 0, headwidth: float = 0,
               headlength: float = 0) -> tuple[float, float, float]:
    """VPython's arrow proportions: ``(shaftwidth, headwidth, headlength)`` as drawn.

    From primitives.js ``arrow_update``: an unset (0) shaftwidth is
    ``0.1 * length``, headwidth ``2 * shaftwidth``, headlength ``3 * shaftwidth``.
    If the shaft is thinner than ``0.02 * length``, the *unset* ones grow by
    ``0.02 * length / shaftwidth``; then if the head is longer than half the
    arrow, the unset ones shrink by ``0.5 * length / headlength``. Values the
    user set are never changed, so a set headlength may exceed ``length`` (the
    shaft then points backwards from ``pos``, as in VPython).
    """
    L = float(length)
    sw = shaftwidth or L * 0.1
    hw = headwidth or sw * 2
    hl = headlength or sw * 3
    if sw < L * 0.02:
        scale = L * 0.02 / sw
        sw = sw if shaftwidth else sw * scale
        hw = hw if headwidth else hw * scale
        hl = hl if headlength else hl * scale
    if hl > L * 0.5:
        scale = L * 0.5 / hl
        sw = sw if shaftwidth else sw * scale
        hw = hw if headwidth else hw * scale
        hl = hl if headlength else hl * scale
    return float(sw), float(hw), float(hl)


def _scaled(mesh: Mesh, offset, scale) -> tuple[np.ndarray, np.ndarray]:
    """A template's points and normals under ``p * scale + offset`` (inverse-transpose normals)."""
    scale = np.asarray(scale, dtype=float)
    points = mesh.points * scale + np.asarray(offset, dtype=float)
    return points, _unit_rows(mesh.normals / _nonzero(scale))


def arrow(length: float, shaftwidth: float, headwidth: float, headlength: float) -> Mesh:
    """An arrow along local x from 0 to ``length`` in local lengths (place with size (1,1,1)).

    A box shaft of square cross-section ``shaftwidth`` from 0 to ``length -
    headlength`` and a pyramid head of square base ``headwidth`` from there to
    ``length`` (primitives.js ``arrow_update``). Pass the result of
    :func:`arrow_dims`. 40 points, 18 triangles; flat normals.
    """
    shaft_len = length - headlength
    # a negative shaft (head longer than the arrow) runs backwards from pos, as VPython's
    shaft_p, shaft_n = _scaled(box(), (shaft_len / 2, 0, 0), (abs(shaft_len), shaftwidth, shaftwidth))
    head_p, head_n = _scaled(pyramid(), (shaft_len, 0, 0), (headlength, headwidth, headwidth))
    triangles = np.vstack([box().triangles, pyramid().triangles + len(shaft_p)])
    return _mesh(np.vstack([shaft_p, head_p]), np.vstack([shaft_n, head_n]), triangles)


def _grid_triangles(rows: int, cols: int, wrap_rows: bool) -> np.ndarray:
    """Triangles of a (rows x cols) grid of points, columns wrapping, rows wrapping if asked.

    With point (i, j) at ``i * cols + j``, the quad (i, j)-(i+1, j+1) becomes
    (i,j),(i+1,j),(i,j+1) and (i,j+1),(i+1,j),(i+1,j+1): outward when the
    surface's d/d(row) x d/d(col) points outward.
    """
    i = np.arange(rows if wrap_rows else rows - 1)[:, None]
    j = np.arange(cols)[None, :]
    i1, j1 = (i + 1) % rows, (j + 1) % cols
    a, b, c, d = i * cols + j, i1 * cols + j, i * cols + j1, i1 * cols + j1
    return np.stack([np.stack([a, b, c], -1), np.stack([c, b, d], -1)], axis=2).reshape(-1, 3)


def ring(radius: float, thickness: float, sides: int = RING_SIDES,
         sections: int = RING_SECTIONS) -> Mesh:
    """A ring in local lengths, centred on ``pos``, lying in the local YZ plane (normal = axis).

    ``radius`` is to the tube's centre line and ``thickness`` is VPython's: the
    *radius* of the cross section (``size.x / 2``; VPython docs: "half the
    diameter of the cross section"), so the ring spans ``radius +- thickness``
    from its centre. mesh.js ``makeRing``: 60 cross sections of 20 sides.
    Place with size (1, 1, 1). ``sides * sections`` points, twice as many triangles.
    """
    phi = 2 * np.pi * np.arange(sections) / sections          # around the ring
    psi = np.pi + 2 * np.pi * np.arange(sides) / sides        # around the tube; seam inside
    # e(phi): unit vector from the centre, starting at -z as mesh.js ("seam to the back")
    e = np.stack([np.zeros(sections), np.sin(phi), -np.cos(phi)], axis=-1)[:, None, :]
    x = np.array([1.0, 0, 0])
    normals = np.cos(psi)[None, :, None] * e + np.sin(psi)[None, :, None] * x
    points = radius * e + thickness * normals
    # d/dphi x d/dpsi is along the outward normal, so rows = phi, columns = psi
    triangles = _grid_triangles(sections, sides, wrap_rows=True)
    return _mesh(points.reshape(-1, 3), normals.reshape(-1, 3), triangles)


def tube(points, radius, sides: int = CURVE_SIDES, joints: bool = True,
         start_cap: bool = False) -> Mesh:
    """VPython's ``curve`` with ``radius > 0``: a ``sides``-gon tube along a polyline, world coordinates.

    As GlowScript's curve (mesh.js ``makeCurveSegment``): every segment is its
    own open tube, its cross-section frame built from world up (0, 1, 0) like
    the curve shader, with a hemisphere on its far end that rounds the joint
    (``joints``). GlowScript leaves the curve's first end open; ``start_cap``
    adds a hemisphere there too. ``radius`` is a scalar or one per point (a
    tube segment then tapers like a cone). The topology depends only on the
    number of points, so it can be rebuilt in place each frame.
    """
    pts = np.asarray(points, dtype=float).reshape(-1, 3)
    if len(pts) < 2:
        raise ValueError("a tube needs at least two points")
    r = np.broadcast_to(np.asarray(radius, dtype=float), (len(pts),))
    a, b = pts[:-1], pts[1:]
    ra, rb = r[:-1, None, None], r[1:, None, None]
    S = len(a)
    F = frames(b - a, np.broadcast_to([0.0, 1.0, 0.0], (S, 3)))
    X, Y, Z = F[:, None, :, 0], F[:, None, :, 1], F[:, None, :, 2]     # (S, 1, 3)
    psi = 2 * np.pi * np.arange(sides) / sides
    # mesh.js: the cross section starts at (y, z) = (0, -R) and turns towards -y
    radial = -np.sin(psi)[None, :, None] * Y - np.cos(psi)[None, :, None] * Z   # (S, sides, 3)
    length = np.linalg.norm(b - a, axis=1)[:, None, None]
    slope = (rb - ra) / np.where(length == 0, np.inf, length)
    side_n = _unit_rows(radial - slope * X)
    parts_p = [a[:, None] + ra * radial, b[:, None] + rb * radial]
    parts_n = [side_n, side_n]
    tri = [_grid_triangles(2, sides, wrap_rows=False)]       # rows: start ring, end ring
    n_per = 2 * sides
    caps = [(b, rb, X, False)] if joints else []
    if start_cap:
        caps.append((a, ra, -X, True))
    for centre, rc, direction, mirrored in caps:
        cp, cn = _hemisphere(centre, rc, radial, direction)
        t = _cap_triangles(sides) + n_per
        if mirrored:                             # bulging backwards: reverse the winding
            t = t[:, [0, 2, 1]]
        tri.append(t)
        parts_p.append(cp)
        parts_n.append(cn)
        n_per += cp.shape[1]
    seg_points = np.concatenate(parts_p, axis=1)
    seg_normals = np.concatenate(parts_n, axis=1)
    return _mesh(seg_points.reshape(-1, 3), seg_normals.reshape(-1, 3),
                 tile(np.vstack(tri), n_per, S))


def tube_vertex_points(n_points: int, sides: int = CURVE_SIDES, joints: bool = True,
                       start_cap: bool = False) -> np.ndarray:
    """For each vertex of :func:`tube`, the index of the polyline point it belongs to.

    The vertices come segment after segment; in segment s the start ring (and
    start cap) belong to point s, the end ring and the joint to point s + 1.
    Use it to give the tube per-point colours (GlowScript blends a segment's
    two colours along it).
    """
    block = [0] * sides + [1] * sides
    if joints:
        block += [1] * (CAP_RINGS * sides + 1)
    if start_cap:
        block += [0] * (CAP_RINGS * sides + 1)
    segments = np.arange(n_points - 1)[:, None]
    return (segments + np.array(block)[None, :]).ravel()


def _hemisphere(centre, rc, radial, direction) -> tuple[np.ndarray, np.ndarray]:
    """Points and normals (S, CAP_RINGS * sides + 1, 3) of hemispheres bulging along ``direction``."""
    alpha = (np.pi / 2) * np.arange(CAP_RINGS) / CAP_RINGS          # equator .. last ring
    n = (np.cos(alpha)[None, :, None, None] * radial[:, None]
         + np.sin(alpha)[None, :, None, None] * direction[:, None])   # (S, rings, sides, 3)
    n = np.concatenate([n.reshape(len(radial), -1, 3), direction], axis=1)  # + the pole
    return centre[:, None] + rc * n, n


def _cap_triangles(sides: int) -> np.ndarray:
    """Triangles of a hemisphere: latitude rings as in :func:`_grid_triangles`, then a fan to the pole."""
    bands = _grid_triangles(CAP_RINGS, sides, wrap_rows=False)
    last = (CAP_RINGS - 1) * sides + np.arange(sides)
    pole = CAP_RINGS * sides
    fan = np.column_stack([last, np.full(sides, pole), np.roll(last, -1)])
    return np.vstack([bands, fan])


TEMPLATES = {           # unit templates: kind -> function making it
    "sphere": sphere,
    "ellipsoid": sphere,
    "box": box,
    "cylinder": cylinder,
    "cone": cone,
    "pyramid": pyramid,
}


def template(kind: str) -> Mesh:
    """The unit template of ``kind`` (sphere, ellipsoid, box, cylinder, cone or pyramid)."""
    return TEMPLATES[kind]()


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
    The same rotation as :class:`springscene.geometry.HelixFrame`.
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


def tile(triangles, n_points: int, M: int) -> np.ndarray:
    """Triangle indices (M * f, 3) of M copies of a mesh of ``n_points`` points, copy after copy."""
    triangles = np.asarray(triangles, dtype=np.int64)
    offsets = n_points * np.arange(M, dtype=np.int64)
    return (triangles[None] + offsets[:, None, None]).reshape(-1, 3)


def vtk_cells(triangles) -> np.ndarray:
    """Triangles in VTK's flat cell layout ``[3, a, b, c, 3, ...]`` for ``pyvista.PolyData``."""
    triangles = np.asarray(triangles, dtype=np.int64).reshape(-1, 3)
    return np.hstack([np.full((len(triangles), 1), 3, dtype=np.int64), triangles]).ravel()


__all__ = [
    "Mesh", "sphere", "box", "cylinder", "cone", "pyramid", "arrow", "arrow_dims", "ring",
    "tube", "tube_vertex_points", "template", "frames", "adjust_up", "place", "tile", "vtk_cells",
    "default_size", "is_centred", "axis_sets_length", "size_sets_axis", "radius_from_size",
    "size_for_radius", "ring_thickness_from_size", "size_for_ring_thickness", "ring_size",
    "helix_wire_radius", "DEFAULT_SIZE", "SIZE_INDEX", "SPHERE_SLICES", "CYLINDER_SIDES",
    "CONE_SIDES", "RING_SECTIONS", "RING_SIDES", "CURVE_SIDES",
]
