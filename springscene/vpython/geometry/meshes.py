"""The meshes of VPython's objects, one function a kind, as numpy arrays.

Each kind of object has a *template* mesh in its own local frame (the convention
is :mod:`.placement`'s, which puts copies of it into the world). Plain numpy, but
for the sphere's vertex layout, taken once from pyvista's core ``Sphere``, so a
VPython ``sphere`` renders exactly like the wiki scene's ball.

VPython facts used (VPython 7, ``vpython/vpython-jupyter``; GlowScript,
``vpython/glowscript``):

- ``lib/glow/primitives.js`` ``arrow_update``: shaft and head widths/length and
  their shrinking rules (:func:`arrow_dims`); the arrow is a box shaft plus a
  pyramid head.
- ``lib/glow/mesh.js``: ``makeCube`` (24 vertices), ``makeCylinder`` (50
  sides), ``makeCone`` (200 sides), ``makePyramid``, ``makeRing`` (60 cross
  sections of 20 sides), ``makeCurveSegment`` (16-sided open tube with a
  hemisphere on its far end); for textured objects, the same functions' vertex
  layouts and ``texpos`` (``textured_*``, :data:`TEXTURED`, ``ring(uv=True)``),
  and ``makeSphere(0.5, 30)``'s UV sphere.

VPython's size rules (default sizes, radius and size) are the objects' own
(:mod:`springscene.vpython.objects.solids`).
"""

from __future__ import annotations

import functools

import numpy as np

from ...view.geometry import TUBE_SIDES
from .placement import Mesh, _nonzero, _unit_rows, frames, tile

SPHERE_SLICES = 30      # our scene's ball (GlowScript: makeSphere(0.5, 30))
CYLINDER_SIDES = 50     # mesh.js makeCylinder: N = 50
CONE_SIDES = 200        # mesh.js makeCone: N = 200
RING_SECTIONS = 60      # mesh.js makeRing: NC = 60 cross sections around the ring
RING_SIDES = 20         # mesh.js makeRing: N = 20 sides of each cross section
CURVE_SIDES = TUBE_SIDES  # mesh.js makeCurveSegment: N = 16
CAP_RINGS = 4           # latitude rings of a curve's hemispherical joint (ours)

# -- templates ----------------------------------------------------------------------------

def _mesh(points, normals, triangles, uv=None) -> Mesh:
    return Mesh(np.ascontiguousarray(points, dtype=float),
                np.ascontiguousarray(_unit_rows(np.asarray(normals, dtype=float))),
                np.ascontiguousarray(triangles, dtype=np.int64).reshape(-1, 3),
                None if uv is None else np.ascontiguousarray(uv, dtype=float).reshape(-1, 2))


def _frozen(mesh: Mesh) -> Mesh:
    for a in mesh:
        if a is not None:
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
    from pyvista.core import Sphere  # noqa: PLC0415  heavy: pyvista, only to copy its vertex layout, once

    s = Sphere(radius=0.5, theta_resolution=slices, phi_resolution=slices)
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
    with np.errstate(invalid="ignore"):    # a size not finite (VPython 6's v / 0): not drawn
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
         sections: int = RING_SECTIONS, uv: bool = False) -> Mesh:
    """A ring in local lengths, centred on ``pos``, lying in the local YZ plane (normal = axis).

    ``radius`` is to the tube's centre line and ``thickness`` is VPython's: the
    *radius* of the cross section (``size.x / 2``; VPython docs: "half the
    diameter of the cross section"), so the ring spans ``radius +- thickness``
    from its centre. mesh.js ``makeRing``: 60 cross sections of 20 sides.
    Place with size (1, 1, 1). ``sides * sections`` points, twice as many triangles.

    With ``uv``, mesh.js's textured layout: ``(sections + 1) x (sides + 1)``
    points (the seams doubled), texture u = c / 60 around the ring from the
    back (-z), v = i / 20 around the tube from its inside (``texpos.push(c/NC, i/N)``).
    """
    n_phi, n_psi = (sections + 1, sides + 1) if uv else (sections, sides)
    phi = 2 * np.pi * np.arange(n_phi) / sections             # around the ring
    psi = np.pi + 2 * np.pi * np.arange(n_psi) / sides        # around the tube; seam inside
    # e(phi): unit vector from the centre, starting at -z as mesh.js ("seam to the back")
    e = np.stack([np.zeros(n_phi), np.sin(phi), -np.cos(phi)], axis=-1)[:, None, :]
    x = np.array([1.0, 0, 0])
    normals = np.cos(psi)[None, :, None] * e + np.sin(psi)[None, :, None] * x
    points = radius * e + thickness * normals
    if not uv:
        # d/dphi x d/dpsi is along the outward normal, so rows = phi, columns = psi
        triangles = _grid_triangles(sections, sides, wrap_rows=True)
        return _mesh(points.reshape(-1, 3), normals.reshape(-1, 3), triangles)
    c, i = np.meshgrid(np.arange(n_phi) / sections, np.arange(n_psi) / sides, indexing="ij")
    return _mesh(points.reshape(-1, 3), normals.reshape(-1, 3), _open_grid(n_phi, n_psi),
                 np.column_stack([c.ravel(), i.ravel()]))


def _open_grid(rows: int, cols: int) -> np.ndarray:
    """mesh.js's bands: (a, below a, below a + 1), (a, below a + 1, a + 1), no wrapping."""
    i = np.arange(rows - 1)[:, None]
    j = np.arange(cols - 1)[None, :]
    a = i * cols + j
    b, d, c = a + cols, a + cols + 1, a + 1
    return np.stack([np.stack([a, b, d], -1), np.stack([a, d, c], -1)], axis=2).reshape(-1, 3)


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


# -- textured templates: GlowScript's vertex layouts and texpos (lib/glow/mesh.js) ---------

TEXTURED_SPHERE_SLICES = 30   # WebGLRenderer.js: Mesh.makeSphere(0.5, 30)


@functools.cache
def textured_sphere(slices: int = TEXTURED_SPHERE_SLICES) -> Mesh:
    """mesh.js ``makeSphere``: a UV sphere of ``(N + 1) x (N + 1)`` points, seam and poles doubled.

    Latitude i (0 at the +y pole) and longitude j: ``(x, y, z) = R (-sin t sin p,
    cos t, -sin t cos p)``, t = i pi / N, p = 2 pi j / N, so the seam (u = 0 and
    1) is at -z and u = 0.25, 0.5, 0.75 face -x, +z, +x; ``texpos = (j/N, 1 - i/N)``
    puts the picture's top at the +y pole. An Earth map (longitude -180 at its
    left edge) shows longitude 0 towards +z and north at +y, east to the right.
    """
    n = slices
    t = np.pi * np.arange(n + 1) / n
    p = 2 * np.pi * np.arange(n + 1) / n
    T, P = np.meshgrid(t, p, indexing="ij")
    points = 0.5 * np.stack([-np.sin(T) * np.sin(P), np.cos(T), -np.sin(T) * np.cos(P)], -1)
    J, I = np.meshgrid(np.arange(n + 1) / n, np.arange(n + 1) / n)
    uv = np.stack([J, 1 - I], -1)                            # texpos(j/Nlong, 1 - i/Nlat)
    return _frozen(_mesh(points.reshape(-1, 3), points.reshape(-1, 3), _open_grid(n + 1, n + 1),
                         uv.reshape(-1, 2)))


@functools.cache
def textured_box() -> Mesh:
    """:func:`box` with mesh.js ``makeCube``'s texpos: (0,1), (0,0), (1,0), (1,1) on every face."""
    b = box()
    uv = np.tile([[0, 1], [0, 0], [1, 0], [1, 1]], (6, 1))
    return _frozen(_mesh(b.points, b.normals, b.triangles, uv))


@functools.cache
def textured_pyramid() -> Mesh:
    """:func:`pyramid` with mesh.js ``makePyramid``'s texpos (the four sides share one picture)."""
    p = pyramid()
    uv = [[1, 1], [0, 1], [0, 0], [1, 0],                       # base (left)
          [0, 0], [0.25, 0], [0.125, 1], [1, 0], [0.75, 0], [0.875, 1],
          [0.5, 0], [0.75, 0], [0.625, 1], [0.25, 0], [0.5, 0], [0.375, 1]]
    return _frozen(_mesh(p.points, p.normals, p.triangles, uv))


@functools.cache
def textured_cylinder(sides: int = CYLINDER_SIDES) -> Mesh:
    """mesh.js ``makeCylinder``: centres, then per side k: left-cap, side, right-cap, side points.

    texpos: the caps ``(0.5 (1 +- z/R), 0.5 + 0.5 y/R)`` (upright seen from
    outside); the side u = 0 at ``pos`` and 1 at the far end, v going 0 -> 1
    over the first half turn from -y and back 1 -> 0 over the second (no seam).
    """
    y, z = _circle(sides)
    k = np.arange(sides)
    v = np.where(k < sides / 2, k / (sides / 2), 1 - (k - sides / 2) / (sides / 2))
    zero, one = np.zeros(sides), np.ones(sides)
    quad_p = np.stack([np.column_stack([zero, y, z]), np.column_stack([zero, y, z]),
                       np.column_stack([one, y, z]), np.column_stack([one, y, z])], 1)
    radial = np.column_stack([zero, y, z])
    quad_n = np.stack([np.tile([-1.0, 0, 0], (sides, 1)), radial,
                       np.tile([1.0, 0, 0], (sides, 1)), radial], 1)
    quad_uv = np.stack([np.column_stack([0.5 * (1 + 2 * z), 0.5 + y]), np.column_stack([zero, v]),
                        np.column_stack([0.5 * (1 - 2 * z), 0.5 + y]), np.column_stack([one, v])], 1)
    left, side0, right, side1 = (2 + 4 * k + m for m in range(4))
    k1 = (k + 1) % sides
    triangles = np.vstack([_fan(0, left), np.column_stack([side0, side1, side1[k1]]),
                           np.column_stack([side0, side1[k1], side0[k1]]),
                           np.column_stack([np.ones(sides, int), right[k1], right])])
    return _frozen(_mesh(np.vstack([[[0, 0, 0], [1, 0, 0]], quad_p.reshape(-1, 3)]),
                         np.vstack([[[-1, 0, 0], [1, 0, 0]], quad_n.reshape(-1, 3)]),
                         triangles, np.vstack([[[0.5, 0.5], [0.5, 0.5]], quad_uv.reshape(-1, 2)])))


@functools.cache
def textured_cone(sides: int = CONE_SIDES) -> Mesh:
    """mesh.js ``makeCone``: base centre, then per k = 0..N a base-rim, side-rim and apex point.

    The rim starts at -z and turns towards -y; texpos: base ``(0.5 (1 + z/R),
    0.5 (1 + y/R))``, side u = 1 - k/N (v 0 at the rim, 1 at the apex).
    """
    k = np.arange(sides + 1)
    theta = 2 * np.pi * k / sides
    y, z = -0.5 * np.sin(theta), -0.5 * np.cos(theta)
    ym, zm = -0.5 * np.sin(theta + np.pi / sides), -0.5 * np.cos(theta + np.pi / sides)
    zero = np.zeros(sides + 1)
    rim = np.column_stack([zero, y, z])
    apex = np.tile([1.0, 0, 0], (sides + 1, 1))
    points = np.stack([rim, rim, apex], 1).reshape(-1, 3)
    normals = np.stack([np.tile([-1.0, 0, 0], (sides + 1, 1)),
                        np.column_stack([np.ones(sides + 1), 4 * y, 4 * z]),
                        np.column_stack([np.ones(sides + 1), 4 * ym, 4 * zm])], 1).reshape(-1, 3)
    u = 1 - k / sides
    uv = np.stack([np.column_stack([0.5 * (1 + 2 * z), 0.5 * (1 + 2 * y)]),
                   np.column_stack([u, zero]), np.column_stack([u, zero + 1])], 1).reshape(-1, 2)
    i = 1 + 3 * np.arange(sides)
    triangles = np.vstack([np.column_stack([np.zeros(sides, int), i, i + 3]),
                           np.column_stack([i + 1, i + 2, i + 4])])
    return _frozen(_mesh(np.vstack([[0, 0, 0], points]), np.vstack([[-1, 0, 0], normals]),
                         triangles, np.vstack([[0.5, 0.5], uv])))


TEXTURED = {            # textured unit templates: kind -> function making it
    "sphere": textured_sphere,
    "box": textured_box,
    "cylinder": textured_cylinder,
    "cone": textured_cone,
    "pyramid": textured_pyramid,
}

SIDES, LEFT, RIGHT = 0, 1, 2


def texture_parts(mesh: Mesh, kind: str) -> np.ndarray:
    """Each vertex's place for ``texture={'place': ...}``: SIDES, LEFT or RIGHT.

    GlowScript's object shaders (render_vertex.shader): a vertex whose template
    normal is exactly (-1, 0, 0) is *left*, (1, 0, 0) *right*, any other a *side*.
    A sphere's and a ring's are all sides (mesh.js gives none of theirs an exact
    +-x normal; the ring's normal attribute has x = 0), and so are a compound's
    (its merged normals are scaled by its size, mesh.js ``adjust``).
    """
    parts = np.full(len(mesh.points), SIDES, dtype=np.int8)
    if kind not in ("sphere", "ring", "compound"):
        nx = mesh.normals[:, 0]
        parts[nx == -1.0] = LEFT
        parts[nx == 1.0] = RIGHT
    return parts


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


__all__ = [
    "Mesh", "sphere", "box", "cylinder", "cone", "pyramid", "arrow", "arrow_dims", "ring",
    "tube", "tube_vertex_points", "template", "SPHERE_SLICES", "TEXTURED", "texture_parts",
    "textured_sphere", "textured_box", "textured_cylinder", "textured_cone", "textured_pyramid", "CYLINDER_SIDES",
    "CONE_SIDES", "RING_SECTIONS", "RING_SIDES", "CURVE_SIDES",
]
