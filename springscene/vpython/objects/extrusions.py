"""VPython's ``extrusion``: a 2D shape (with holes) swept along a 3D path, made once as a compound.

The geometry is that of GlowScript's ``lib/glow/extrude.js``:

- The shape's plane rides along the path. At the start its x axis is
  ``norm(z x up)`` and its y axis ``norm(x x z)``, z being the first segment
  (``up`` defaults to (0, 1, 0)); at each joint the frame turns by the smallest
  rotation taking one segment's direction to the next, and ``twist`` turns it
  about the path. A shape point ``[sx, sy]`` at a joint is ``pos + sx*xscale*x +
  sy*yscale*y``, slid along the path onto the joint's mitre plane (the plane
  bisecting the two segments; at the ends, the plane square to ``start_normal``
  or ``end_normal``).
- A joint turning by less than ``acos(smooth)`` (``smooth`` = 0.95, 18 degrees)
  is smooth: the two segments share its vertices and their normals are averaged;
  otherwise it is sharp (``smooth_joints``/``sharp_joints`` override). Shape
  corners follow the same rule with the same ``smooth``.
- ``color`` is one colour or one per path point: a segment shades from its start
  colour to its end colour across a smooth joint and is flat up to a sharp one.
- An open path gets flat end faces (``show_start_face``/``show_end_face``,
  ``start_face_color``/``end_face_color``), triangulated with their holes by
  earcut (mapbox-earcut); a closed path (last point equal to the first) has none,
  and, as in GlowScript, its holes' walls are not drawn (they are inside).

The result is a :class:`.compounds.fused` surface: ``pos`` is the centre of its
bounding box (``pos=`` moves it there), ``size`` the box, ``axis`` only turns it,
and setting ``color`` later multiplies the colours made, as for a compound.
:func:`sweep` is shared with 3D text (:mod:`.text3d`).
"""

from __future__ import annotations

import math
from numbers import Real
from typing import NamedTuple

import mapbox_earcut
import numpy as np

from ..core.checks import _vec
from .compounds import Surface, bounding_size, fused
from ..core.vectors import vector

SMOOTH = 0.95            # cosine of the largest turn still drawn smooth (18 degrees)
_TINY = 1e-12


class Sweep(NamedTuple):
    """Where a shape goes: J joints, S segments (S = J - 1, or J for a closed path)."""

    pos: np.ndarray        # (J, 3) joint positions
    x: np.ndarray          # (S, 3) each segment's shape x axis (unit)
    y: np.ndarray          # (S, 3) shape y axis (unit)
    d: np.ndarray          # (S, 3) direction along the path (unit)
    plane: np.ndarray      # (J, 3) normal of each joint's mitre plane
    xscale: np.ndarray     # (J,)
    yscale: np.ndarray     # (J,)
    twist: np.ndarray      # (J,) radians, accumulated
    color: np.ndarray      # (J, 3)
    sharp: np.ndarray      # (J,) bool
    closed: bool


class Caps(NamedTuple):
    """The end faces of an open sweep: shown, colours, outward normals."""

    show_start: bool
    show_end: bool
    start_color: np.ndarray
    end_color: np.ndarray
    start_normal: np.ndarray
    end_normal: np.ndarray


def _unit(v: np.ndarray) -> np.ndarray:
    n = np.linalg.norm(v, axis=-1, keepdims=True)
    return v / np.where(n < _TINY, 1.0, n)


# -- the shape: contours, their order and their columns --------------------------------------

def clean_contour(points) -> np.ndarray:
    """A contour as distinct points: the closing point and repeated points dropped."""
    p = np.array([[float(q[0]), float(q[1])] for q in points])
    if len(p) > 1 and np.allclose(p[0], p[-1], rtol=0, atol=_TINY):
        p = p[:-1]
    scale = max(float(np.abs(p).max()), 1.0) if len(p) else 1.0
    keep = np.linalg.norm(p - np.roll(p, 1, axis=0), axis=1) > _TINY * scale
    return p[keep] if keep.any() else p[:1]


def signed_area(p: np.ndarray) -> float:
    """Shoelace area: positive for a counter-clockwise contour."""
    q = np.roll(p, -1, axis=0)
    return 0.5 * float(np.sum(p[:, 0] * q[:, 1] - q[:, 0] * p[:, 1]))


def _oriented(group: list, outer_ccw: bool) -> list:
    """The outline turning one way (``outer_ccw``), its holes the other."""
    out = []
    for i, c in enumerate(group):
        want_ccw = outer_ccw if i == 0 else not outer_ccw
        out.append(c if (signed_area(c) > 0) == want_ccw else c[::-1].copy())
    return out


def _columns(r: np.ndarray, smooth: float) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Columns of vertices round a contour: a sharp corner has two (one per side)."""
    e_in = _unit(r - np.roll(r, 1, axis=0))
    e_out = _unit(np.roll(r, -1, axis=0) - r)
    sharp = np.einsum("ij,ij->i", e_in, e_out) <= smooth
    width = 1 + sharp.astype(np.int64)
    col_in = np.concatenate([[0], np.cumsum(width)[:-1]])
    col_out = col_in + sharp
    return np.repeat(np.arange(len(r)), width), col_in, col_out


# -- the path: rows of vertices -------------------------------------------------------------

def _rows(p: Sweep) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Rows of vertices along the path: a sharp joint has two (one per segment).

    Returns each row's joint, segment (whose frame places it) and colour joint,
    and each segment's start and end row.
    """
    J = len(p.pos)
    S = J if p.closed else J - 1
    joint, seg, colour = [], [], []

    def new(j: int, s: int, c: int) -> int:
        joint.append(j)
        seg.append(s)
        colour.append(c)
        return len(joint) - 1

    start, end = np.empty(S, np.int64), np.empty(S, np.int64)
    for s in range(S):
        j0, j1 = s, (s + 1) % J
        start[s] = end[s - 1] if s > 0 and not p.sharp[j0] else new(j0, s, j0)
        if p.closed and s == S - 1 and not p.sharp[0]:
            end[s] = start[0]
        else:
            smooth_next = (not p.closed and s == S - 1) or not p.sharp[j1]
            end[s] = new(j1, s, j1 if smooth_next else j0)
    return np.array(joint), np.array(seg), np.array(colour), start, end


def _bases(p: Sweep, joint: np.ndarray, seg: np.ndarray) -> np.ndarray:
    """(R, 3, 2): a row's shape point [sx, sy] is ``pos + M @ [sx, sy]``.

    The segment's axes, twisted about the path and scaled, then slid along the
    path onto the joint's mitre plane.
    """
    d, x, y = p.d[seg], p.x[seg], p.y[seg]
    a = -p.twist[joint][:, None]

    def twisted(v: np.ndarray) -> np.ndarray:    # v turned by a about d (v need not be square to d)
        along = d * np.einsum("ij,ij->i", d, v)[:, None]
        return along + (v - along) * np.cos(a) + np.cross(d, v) * np.sin(a)

    tx, ty = twisted(x), twisted(y)
    B = np.stack([tx * p.xscale[joint][:, None], ty * p.yscale[joint][:, None]], axis=2)
    n = p.plane[joint]
    nd = np.einsum("ij,ij->i", n, d)
    nd = np.where(np.abs(nd) < _TINY, 1.0, nd)
    P = np.eye(3)[None] - d[:, :, None] * n[:, None, :] / nd[:, None, None]
    return P @ B


def _walls(r: np.ndarray, pos: np.ndarray, M: np.ndarray, colour: np.ndarray,
           start: np.ndarray, end: np.ndarray, smooth: float) -> Surface:
    """The walls swept by one contour: quads between rows, normals shared where smooth."""
    col_point, col_in, col_out = _columns(r, smooth)
    C = len(col_point)
    ring = pos[:, None, :] + np.einsum("rij,mj->rmi", M, r)
    points = ring[:, col_point].reshape(-1, 3)
    nxt = col_in[np.roll(np.arange(len(r)), -1)]
    v0 = start[:, None] * C + col_out[None, :]
    v1 = end[:, None] * C + col_out[None, :]
    v2 = end[:, None] * C + nxt[None, :]
    v3 = start[:, None] * C + nxt[None, :]
    # each corner its own normal, from its two edges (extrude.js generate_vertices: N0..N3,
    # the same for a flat quad, not for a twisted one), summed where columns are shared
    normals = np.zeros_like(points)
    corners = (v0, v1, v2, v3)
    for i, v in enumerate(corners):
        after, before = points[corners[(i + 1) % 4]], points[corners[(i + 3) % 4]]
        p = points[v]          # (the next corner - p) x (the one before - p)
        np.add.at(normals, v.ravel(), _unit(np.cross(after - p, before - p).reshape(-1, 3)))
    tris = np.concatenate([np.stack([v0, v1, v2], -1).reshape(-1, 3),
                           np.stack([v0, v2, v3], -1).reshape(-1, 3)])
    rgb = np.repeat(colour, C, axis=0)
    return Surface(points, _unit(normals), tris, rgb)


def _cap(group: list, origin: np.ndarray, M: np.ndarray, normal: np.ndarray,
         colour: np.ndarray) -> Surface:
    """A flat end face: the group (outline and holes) triangulated, facing ``normal``."""
    flat = np.concatenate(group)
    rings = np.cumsum([len(c) for c in group]).astype(np.uint32)
    tris = np.asarray(mapbox_earcut.triangulate_float64(flat, rings), np.int64).reshape(-1, 3)
    points = origin + flat @ M.T
    facing = np.cross(points[tris[:, 1]] - points[tris[:, 0]],
                      points[tris[:, 2]] - points[tris[:, 0]]) @ normal
    tris[facing < 0] = tris[facing < 0][:, ::-1]
    n = len(points)
    return Surface(points, np.tile(_unit(normal), (n, 1)), tris, np.tile(colour, (n, 1)))


def sweep(groups: list, p: Sweep, smooth: float, caps: Caps | None,
          holes_inward: bool = False) -> Surface:
    """The surface of shape ``groups`` (each ``[outline, hole, ...]``, 2D) swept along ``p``.

    ``holes_inward``: every contour counter-clockwise, as extrude.js ``find_shape_info``
    turns each one (holes too), so a hole's walls face into the solid and are lit from
    behind (dark), as VPython draws an extrusion's holes.
    """
    joint, seg, colour_joint, start, end = _rows(p)
    M = _bases(p, joint, seg)
    pos = p.pos[joint]
    colour = p.color[colour_joint]
    hand = float(np.cross(p.x[0], p.y[0]) @ p.d[0]) * p.xscale[0] * p.yscale[0]
    parts = []
    for group in groups:
        group = _oriented(group, outer_ccw=hand < 0)
        for i, r in enumerate(group):
            if i > 0 and holes_inward:
                r = r[::-1].copy()
            if i == 0 or not p.closed:
                parts.append(_walls(r, pos, M, colour, start, end, smooth))
        if p.closed or caps is None:
            continue
        if caps.show_start:
            r0 = start[0]
            parts.append(_cap(group, pos[r0], M[r0], caps.start_normal, caps.start_color))
        if caps.show_end:
            r1 = end[-1]
            parts.append(_cap(group, pos[r1], M[r1], caps.end_normal, caps.end_color))
    return Surface.join(parts)


# -- the path's frames ------------------------------------------------------------------------

def _first_frame(z: np.ndarray, up: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """y = norm(up), x = norm(z x y), as the GlowScript bundled with VPython 7.6.5 does.

    (``vpython_libraries/glow.min.js``, ``extrusion``: ``y=norm(args.up); x=norm(z.cross(y))``;
    later GlowScript sources make y square to z, 7.6.5 does not.) y is not made square to
    the path: a path slanted to ``up`` gets its cross-section squeezed by the cosine of the
    slant once the points are slid onto the square end plane. :func:`first_up` keeps
    ``up`` off the first segment.
    """
    y = _unit(up)
    return _unit(np.cross(z, y)), y


def first_up(first: np.ndarray, up: np.ndarray) -> np.ndarray:
    """``up`` (unit), or a world axis when the first segment is within ~6 degrees of it.

    glow.min.js ``extrusion``: if ``|norm(path[1]-path[0]) x up| < 0.1``, up becomes
    (0, 1, 0) unless up is near that (cross > 0.2 decides), else (1, 0, 0), else (0, 0, 1).
    """
    up = _unit(up)
    if np.linalg.norm(np.cross(_unit(first), up)) >= 0.1:
        return up
    for axis in np.eye(3)[[1, 0, 2]]:
        if np.linalg.norm(np.cross(up, axis)) > 0.2:
            return axis
    return up


def _turn(vs: tuple, a: np.ndarray, b: np.ndarray) -> tuple:
    """``vs`` turned by the smallest rotation taking direction a to direction b."""
    k = np.cross(a, b)
    s = np.linalg.norm(k)
    if s < 1e-12:
        return vs
    k = k / s
    c = float(np.clip(a @ b, -1.0, 1.0))
    s = math.sqrt(max(0.0, 1 - c * c))
    return tuple(v * c + np.cross(k, v) * s + k * (k @ v) * (1 - c) for v in vs)


def path_frames(pts: np.ndarray, up: np.ndarray, closed: bool) -> tuple:
    """Segment directions and shape axes carried along the path (GlowScript's joint loop)."""
    seg = np.diff(pts, axis=0)
    if closed:
        seg = np.vstack([seg, pts[0] - pts[-1]])
    d = _unit(seg)
    x, y = _first_frame(d[-1] if closed else d[0], up)
    if closed:
        x, y = _turn((x, y), d[-1], d[0])
    xs, ys = [x], [y]
    for s in range(1, len(d)):
        x, y = _turn((x, y), d[s - 1], d[s])
        xs.append(x)
        ys.append(y)
    return d, np.array(xs), np.array(ys)


def joints(d: np.ndarray, closed: bool, smooth: float, smooth_joints,
           sharp_joints) -> tuple[np.ndarray, np.ndarray]:
    """Each joint's mitre-plane normal and whether it is sharp."""
    before = np.roll(d, 1, axis=0) if closed else np.vstack([d[:1], d])
    after = d if closed else np.vstack([d, d[-1:]])
    cos = np.clip(np.einsum("ij,ij->i", before, after), -1.0, 1.0)
    sharp = np.arccos(cos) >= math.acos(smooth)
    if not closed:
        sharp[[0, -1]] = False
    smooth_set, sharp_set = set(smooth_joints), set(sharp_joints)
    for j in range(len(sharp)):
        if j in smooth_set and j not in sharp_set:
            sharp[j] = False
        elif j in sharp_set and j not in smooth_set:
            sharp[j] = True
    plane = before + after
    flat = np.linalg.norm(plane, axis=1) < 1e-9          # the path doubles back
    plane[flat] = after[flat]
    return _unit(plane), sharp


# -- the extrusion object ----------------------------------------------------------------------

def _is_number(v) -> bool:
    return isinstance(v, Real)


def shape_groups(shape) -> list:
    """VPython's three ways to give a shape, as groups ``[outline, hole, ...]`` of arrays.

    ``[[x, y], ...]`` (one outline), ``[outline, hole, ...]``, or
    ``[[outline, hole, ...], [outline, ...], ...]``; a list holding one of these is
    taken as it (GlowScript). Every contour must be closed.
    """
    try:
        if len(shape) == 1 and not _is_number(shape[0][0]):
            shape = shape[0]
        if _is_number(shape[0][0]):
            level = 1
        elif _is_number(shape[0][0][0]):
            level = 2
        elif _is_number(shape[0][0][0][0]):
            level = 3
        else:
            raise TypeError
    except (TypeError, IndexError, KeyError):
        raise AttributeError("A shape must be a list of [x,y] elements.") from None
    groups = [[shape]] if level == 1 else [shape] if level == 2 else shape
    for group in groups:
        for c in group:
            if not (c[0][0] == c[-1][0] and c[0][1] == c[-1][1]):
                raise AttributeError("An extrusion shape must be closed.")
    return [[clean_contour(c) for c in group] for group in groups]


def _per_point(value, n: int, name: str, default: float) -> np.ndarray:
    """A scalar for every path point, or VPython's error for a list of the wrong length."""
    if value is None:
        return np.full(n, float(default))
    if _is_number(value):
        return np.full(n, float(value))
    value = [float(v) for v in value]
    if len(value) != n:
        raise AttributeError(f"The {name} list must be the same length as the list of points "
                             f"on the path ({n}).")
    return np.array(value)


def _colours(value, n: int) -> np.ndarray:
    if value is None:
        return np.ones((n, 3))
    if isinstance(value, vector):
        return np.tile(value._xyz(), (n, 1))
    if len(value) != n:
        raise AttributeError("The color list must be the same length as the list of points "
                             f"on the path ({n}).")
    return np.array([_vec(c, "color")._xyz() for c in value])


def _scales(args: dict, n: int) -> tuple[np.ndarray, np.ndarray]:
    scale = args.pop("scale", None)
    xscale, yscale = args.pop("xscale", None), args.pop("yscale", None)
    if scale is not None:
        if xscale is not None or yscale is not None:
            raise AttributeError('One cannot specify both "scale" and "xscale" or "yscale".')
        s = _per_point(scale, n, "scale", 1.0)
        s = np.where(s == 0, 1e-7, s)                   # GlowScript: no zero scale
        return s, s.copy()
    return _per_point(xscale, n, "xscale", 1.0), _per_point(yscale, n, "yscale", 1.0)


def _twists(value, n: int) -> np.ndarray:
    """Accumulated twist at each point: a number is added at every point after the first."""
    if value is None or _is_number(value):
        return float(value or 0.0) * np.arange(n)
    return np.cumsum(_per_point(value, n, "twist", 0.0))


_CLOSED_ONLY = ("show_start_face", "show_end_face", "start_face_color", "end_face_color",
                "start_normal", "end_normal")


def _drop_repeats(path: list) -> np.ndarray:
    """Indices of path points not equal to the point before (a zero-length segment has no frame)."""
    keep = [0]
    for i in range(1, len(path)):
        if not path[i].equals(path[keep[-1]]):
            keep.append(i)
    return np.array(keep)


def _sweep_spec(args: dict, path: list) -> tuple[Sweep, Caps | None, float]:
    """The path, colours, scales, twists, joints and end faces from a program's arguments."""
    n = len(path)
    colour = _colours(args.pop("color", None), n)
    xs, ys = _scales(args, n)
    twist = _twists(args.pop("twist", None), n)
    smooth = float(args.pop("smooth", SMOOTH))
    up = _vec(args.pop("up", vector(0, 1, 0)), "up").norm()
    smooth_joints = list(args.pop("smooth_joints", []))
    sharp_joints = list(args.pop("sharp_joints", []))
    closed = path[-1].equals(path[0])
    if closed:
        bad = [k for k in _CLOSED_ONLY if k in args]
        if bad:
            raise AttributeError(f"Cannot specify {bad[0]} for a closed-path extrusion.")
    keep = _drop_repeats(path[:-1] if closed else path)
    if len(keep) < 2:
        raise AttributeError("An extrusion path must contain more than one distinct point.")
    pts = np.array([path[i]._xyz() for i in keep])
    up = first_up(pts[1] - pts[0], np.array(up._xyz()))      # the first distinct step
    d, x, y = path_frames(pts, up, closed)
    plane, sharp = joints(d, closed, smooth, smooth_joints, sharp_joints)
    caps = None if closed else _caps(args, d, plane, colour[keep])
    if caps is not None:
        plane[0], plane[-1] = -caps.start_normal, caps.end_normal
    return (Sweep(pts, x, y, d, plane, xs[keep], ys[keep], twist[keep], colour[keep], sharp,
                  closed), caps, smooth)


def _caps(args: dict, d: np.ndarray, plane: np.ndarray, colour: np.ndarray) -> Caps:
    start_n = args.pop("start_normal", None)
    end_n = args.pop("end_normal", None)
    sfc = args.pop("start_face_color", None)
    efc = args.pop("end_face_color", None)
    return Caps(bool(args.pop("show_start_face", True)), bool(args.pop("show_end_face", True)),
                colour[0] if sfc is None else np.array(_vec(sfc, "start_face_color")._xyz()),
                colour[-1] if efc is None else np.array(_vec(efc, "end_face_color")._xyz()),
                -d[0] if start_n is None else _unit(np.array(_vec(start_n, "n")._xyz())),
                d[-1] if end_n is None else _unit(np.array(_vec(end_n, "n")._xyz())))


# what an extrusion's surface is made from (the rest of its arguments are its placement and look)
SWEEP_OPTIONS = ("path", "shape", "color", "scale", "xscale", "yscale", "twist", "smooth", "up",
                 "smooth_joints", "sharp_joints") + _CLOSED_ONLY


def extruded(args: dict) -> Surface:
    """The surface of an extrusion made with ``args`` (the :data:`SWEEP_OPTIONS` are popped)."""
    if "path" not in args:
        raise AttributeError("An extrusion must have a path.")
    if "shape" not in args:
        raise AttributeError("An extrusion must have a shape.")
    path = [_vec(v, "path") for v in args.pop("path")]
    if len(path) < 2:
        raise AttributeError("The path must have more than one point.")
    groups = shape_groups(args.pop("shape"))
    spec, caps, smooth = _sweep_spec(args, path)
    return sweep(groups, spec, smooth, caps, holes_inward=True)


class extrusion(fused):
    """A shape swept along a path, drawn once (VPython's ``extrusion``); see the module."""

    def __init__(self, **args) -> None:
        first = args.get("color", vector(1, 1, 1))
        first = first if isinstance(first, vector) else first[0]
        surface = extruded(args)
        centre, size0 = bounding_size(surface.points)
        self._take(surface, centre, size0)
        self._start(args, size0)
        self._color = _vec(first, "color")
        self._color._on_change = self._retint
        self._tinted = False           # VPython keeps the first colour; the surface is as made

    _FIXED = ("path", "shape", "smooth", "smooth_joints", "sharp_joints", "show_start_face",
              "show_end_face", "start_face_color", "end_face_color", "start_normal",
              "end_normal", "twist", "scale", "xscale", "yscale")

    def __setattr__(self, name: str, value) -> None:
        if name in self._FIXED:
            raise AttributeError(f"{name} cannot be changed after extrusion is created")
        super().__setattr__(name, value)

    def __getattr__(self, name: str):
        if name in self._FIXED:          # VPython keeps none of them once it is made
            return None
        raise AttributeError(name)
