"""Every helix of one look as one mesh, numpy-vectorised, with a level of detail.

VPython's helix (primitives.js ``helix.__update``) is a curve of ``coils * 60 + 1``
points (``NCHORDS = 60`` chords per coil) drawn as GlowScript's 16-sided tube, of
wire radius ``thickness / 2`` (``size.y / 40`` when thickness is 0). springscene
draws the same tube (the numbers of :class:`springscene.view.geometry.HelixTube`:
analytic tangent and normal of the centre line, one ring of ``sides`` vertices per
centre-line point).

Two things make a lattice of springs fast:

* all helices of a batch with the same ``coils`` and ``ccw`` (and detail) share one
  unit template (per vertex: s, sin/cos theta, sin/cos phi); each helix's length,
  radius, wire and frame are applied by one batched matrix product, and the
  triangles (fixed while only points move) are tiled once;
* level of detail: a helix a few pixels across does not need 60 chords a coil and
  16 sides. The chords and sides are the fewest (of :data:`CHORD_STEPS` and
  :data:`SIDE_STEPS`) whose polygon departs from the true circle by at most the
  renderer's :class:`.lod.LevelOfDetail` (``helix_px``; the wire's sides a share of it),
  for the centre line's radius and the wire's radius as the nearest helix of the group
  is seen. Bigger helices (the wiki's spring, about 30 px across) keep VPython's full
  60 x 16, and so do anti-aliased pictures (:func:`detail`).
"""

from __future__ import annotations

import functools
import math

import numpy as np

from ...view.geometry import CHORDS_PER_COIL, TUBE_SIDES
from . import placement
from .lod import DEFAULT, LevelOfDetail, steps_for

CHORD_STEPS = (CHORDS_PER_COIL, 48, 40, 32, 24, 20, 16, 12, 8, 6)   # chords per coil
SIDE_STEPS = (TUBE_SIDES, 14, 12, 10, 8, 6, 4)        # sides of the wire (even: _bounds)
_TEMPLATES: dict[tuple, "_Template"] = {}
MAX_TEMPLATES = 64


class _Template:
    """Per-vertex constants of a unit helix of ``coils`` turns, ``chords`` a coil and
    ``sides`` round the wire; vertex ``ring * sides + side``."""

    def __init__(self, coils: float, ccw: bool, chords: int, sides: int) -> None:
        n = int(round(coils * chords)) + 1        # VPython allows fractional coils
        self.k = (1.0 if ccw else -1.0) * 2 * math.pi * coils      # d(theta)/ds
        s = np.linspace(0.0, 1.0, n)
        theta = self.k * s
        phi = 2 * math.pi * np.arange(sides) / sides
        grid = np.ones((n, sides))
        self.s = (s[:, None] * grid).ravel()
        self.sin_t = (np.sin(theta)[:, None] * grid).ravel()
        self.cos_t = (np.cos(theta)[:, None] * grid).ravel()
        self.sin_p = (np.sin(phi)[None, :] * grid).ravel()
        self.cos_p = (np.cos(phi)[None, :] * grid).ravel()
        self.triangles = _ring_triangles(n, sides)
        st, ct, sp, cp = self.sin_t, self.cos_t, self.sin_p, self.cos_p
        # :func:`place`'s bases: a vertex's normal and point are sums of these per-vertex
        # functions with per-helix coefficients (columns in the order :func:`place` uses)
        self.normal_basis = np.column_stack([sp, st * cp, ct * sp, ct * cp, st * sp])
        self.point_basis = np.column_stack([self.normal_basis, self.s, st, ct,
                                            np.ones_like(st)])

    @property
    def size(self) -> int:
        return len(self.s)


def _ring_triangles(n_rings: int, sides: int) -> np.ndarray:
    """Two triangles (a, b, c), (a, c, d) per quad between consecutive rings."""
    ring = np.arange(n_rings - 1)[:, None] * sides
    q = np.arange(sides)[None, :]
    q1 = (q + 1) % sides
    a, b, c, d = ring + q, ring + q1, ring + sides + q1, ring + sides + q
    quads = np.stack([a, b, c, d], axis=-1).reshape(-1, 4)
    return np.stack([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]], axis=1).reshape(-1, 3)


def template(coils: float, ccw: bool, chords: int = CHORDS_PER_COIL,
             sides: int = TUBE_SIDES) -> _Template:
    key = (float(coils), bool(ccw), int(chords), int(sides))
    t = _TEMPLATES.get(key)
    if t is None:
        if len(_TEMPLATES) > MAX_TEMPLATES:        # an animated coils
            _TEMPLATES.clear()
        t = _TEMPLATES[key] = _Template(*key)
    return t


def place(t: _Template, pos, R, length, radius, wire) -> tuple[np.ndarray, np.ndarray]:
    """World points and unit normals (M * t.size, 3) of M helices of template ``t``.

    With T the centre line's unit tangent (L, R k cos, -R k sin) / |T| and N its
    inward normal (0, -sin, -cos), the ring normal is N cos(phi) + (T x N) sin(phi),
    T x N = (-R k, L cos, -L sin) / |T|; a vertex is the centre line plus
    ``wire`` times it, in the local frame ``R`` (columns X, Y, Z) from ``pos``.

    Written out, with a = L / |T| and b = R k / |T|, the local normal is
    (-b sin_p, -sin_t cos_p + a cos_t sin_p, -cos_t cos_p - a sin_t sin_p): a sum of
    five per-vertex functions (``t.normal_basis``) with per-helix coefficients along
    X, Y and Z; the point adds s L X + R sin_t Y + R cos_t Z + pos. So both are one
    batched product (vertices x functions) @ (functions x 3) per helix, the frame
    folded into the coefficients: about 3x faster than placing the local vectors and
    turning them (AtomicSolid's 144 helices).
    """
    L, rad, w = (np.asarray(x, dtype=float).reshape(-1, 1) for x in (length, radius, wire))
    Rk = rad * t.k
    norm_T = np.sqrt(L * L + Rk * Rk)
    a, b = L / norm_T, Rk / norm_T                                  # (M, 1)
    F = np.swapaxes(np.asarray(R, dtype=float), 1, 2)               # rows X, Y, Z
    X, Y, Z = F[:, 0], F[:, 1], F[:, 2]                             # (M, 3)
    cn = np.stack([-b * X, -Y, a * Y, -Z, -a * Z], axis=1)          # (M, 5, 3)
    cp = np.concatenate([cn * w[:, :, None],
                         np.stack([L * X, rad * Y, rad * Z,
                                   np.asarray(pos, dtype=float).reshape(-1, 3)], axis=1)],
                        axis=1)                                     # (M, 9, 3)
    world = np.matmul(t.point_basis, cp)
    return world.reshape(-1, 3), np.matmul(t.normal_basis, cn).reshape(-1, 3)


@functools.lru_cache(maxsize=MAX_TEMPLATES)
def _centre_basis(coils: float, ccw: bool, chords: int) -> np.ndarray:
    """(n, 4) per centre-line point of a unit helix (:class:`_Template`'s ``s``, sin and
    cos of theta, 1): a point is this times the helix's coefficients (:func:`centre_lines`)."""
    t = template(coils, ccw, chords, 1)
    basis = np.column_stack([t.s, t.sin_t, t.cos_t, np.ones_like(t.s)])
    basis.flags.writeable = False
    return basis


def centre_lines(coils: float, ccw: bool, chords: int, pos, R, length,
                 radius) -> tuple[np.ndarray, np.ndarray]:
    """The centre-line points (M, n, 3) of M helices of one shape, ``chords`` a coil:
    GlowScript's ``coils * chords + 1`` points (primitives.js ``helix``, the curve its
    chords are drawn as), and the line's tangents there (M, n, 3; d/ds, not unit), in
    one batched product for all of them (as :func:`place`)."""
    F = np.swapaxes(np.asarray(R, dtype=float), 1, 2)                # rows X, Y, Z
    L = np.asarray(length, dtype=float)[:, None]
    rad = np.asarray(radius, dtype=float)[:, None]
    coef = np.stack([L * F[:, 0], rad * F[:, 1], rad * F[:, 2],
                     np.asarray(pos, dtype=float).reshape(-1, 3)], axis=1)   # (M, 4, 3)
    basis = _centre_basis(coils, ccw, chords)
    k = template(coils, ccw, chords, 1).k
    slope = np.column_stack([np.ones(len(basis)), k * basis[:, 2], -k * basis[:, 1],
                             np.zeros(len(basis))])
    return np.matmul(basis, coef), np.matmul(slope, coef)


def _vertex_colors(colors: np.ndarray, size: int) -> np.ndarray:
    """RGB (uint8) of ``size`` vertices per helix of ``colors`` (M, 3) in 0..1."""
    return np.repeat(np.clip(np.rint(colors * 255), 0, 255).astype(np.uint8), size, axis=0)


def helix_arrays(objs) -> dict:
    """pos, frame, length, radius, wire, coils, ccw and colour of helices of nonzero length."""
    axis = np.array([o._axis._xyz() for o in objs], dtype=float).reshape(-1, 3)
    length = np.linalg.norm(axis, axis=1)
    keep = length > 0
    objs = [o for o, k in zip(objs, keep) if k]
    axis, length = axis[keep], length[keep]
    up = np.array([o._up._xyz() for o in objs], dtype=float).reshape(-1, 3)
    radius = np.array([o._size.y / 2 for o in objs], dtype=float)
    thick = np.array([o._thickness or 0.0 for o in objs], dtype=float)
    return {"pos": np.array([o._pos._xyz() for o in objs], dtype=float).reshape(-1, 3),
            "R": placement.frames(axis, up) if len(objs) else np.zeros((0, 3, 3)),
            "length": length, "radius": radius,
            "wire": np.where(thick > 0, thick / 2, radius / 20),
            "coils": [float(o._coils) for o in objs], "ccw": [bool(o._ccw) for o in objs],
            "color": np.array([o._color._xyz() for o in objs], dtype=float).reshape(-1, 3)}


def pixels_per_unit(view, points: np.ndarray, nearer: np.ndarray | float = 0.0) -> np.ndarray:
    """Pixels per world unit at each point's depth before the camera (less ``nearer``)."""
    fwd = view.focal_point - view.position
    fwd = fwd / np.linalg.norm(fwd)
    depth = np.maximum((points - view.position) @ fwd - nearer, view.near)
    return (view.height / 2) / math.tan(view.fov / 2) / depth


def detail(a: dict, idx: np.ndarray, view, full: bool = False,
           lod: LevelOfDetail = DEFAULT) -> tuple[int, int]:
    """(chords per coil, sides) for the helices ``idx``: enough for the nearest of them
    (each taken at its end nearer the camera, less its radius). ``full`` keeps VPython's
    60 x 16 (anti-aliased pictures: fewer chords or sides moved the highlights of
    AtomicSolid's springs, and of smaller ones, outside the image tolerance of full
    detail: 40 x 16 0.091 % of pixels off by more than 24/255, 60 x 10 on a wire under a
    pixel 0.085 %; the tolerance is 0.05 %)."""
    if view is None or full:
        return CHORDS_PER_COIL, TUBE_SIDES
    pos, radius, wire = a["pos"][idx], a["radius"][idx], a["wire"][idx]
    end = pos + a["R"][idx][:, :, 0] * a["length"][idx, None]
    ppu = np.maximum(pixels_per_unit(view, pos, radius + wire),
                     pixels_per_unit(view, end, radius + wire))
    return (steps_for(float(np.max(radius * ppu)), CHORD_STEPS, lod.helix_px),
            steps_for(float(np.max(wire * ppu)), SIDE_STEPS, lod.helix_px * lod.side_share))


def capsule_chords(a: dict, idx: np.ndarray, view, px: float) -> int:
    """Chords a coil for the helices ``idx`` drawn as capsules: the fewest of
    :data:`CHORD_STEPS` whose sagitta stays within ``px`` pixels on the coil of the
    nearest of them, as :func:`detail` takes it (GlowScript's 60 without a view or
    with ``px`` 0)."""
    if view is None or px <= 0:
        return CHORDS_PER_COIL
    pos, radius, wire = a["pos"][idx], a["radius"][idx], a["wire"][idx]
    end = pos + a["R"][idx][:, :, 0] * a["length"][idx, None]
    ppu = np.maximum(pixels_per_unit(view, pos, radius + wire),
                     pixels_per_unit(view, end, radius + wire))
    return steps_for(float(np.max(radius * ppu)), CHORD_STEPS, px)


def mesh(objs, view=None, triangles: bool = True, full: bool = False,
         bounds: bool = True, arrays: dict | None = None, lod: LevelOfDetail = DEFAULT):
    """World points, normals, triangles, RGB (uint8), per-helix bounds (M, 2, 3) and the
    shape signature of helices, grouped by shape (bounds zero with ``bounds=False``);
    None when none has a length. With
    ``view``, each group at its level of detail (:func:`detail`); without, VPython's full
    60 x 16. ``triangles=False`` leaves them out (None): a batch keeps its cells.
    ``arrays``: :func:`helix_arrays` of ``objs`` when the caller has them already."""
    a = helix_arrays(objs) if arrays is None else arrays
    if not len(a["length"]):
        return None
    parts, start = [], 0
    for (coils, ccw), idx in groups(a).items():
        chords, sides = detail(a, idx, view, full, lod)
        t = template(coils, ccw, chords, sides)
        points, normals = place(t, a["pos"][idx], a["R"][idx], a["length"][idx],
                                a["radius"][idx], a["wire"][idx])
        m = len(idx)
        rgb = _vertex_colors(a["color"][idx], t.size)
        tris = placement.tile(t.triangles, t.size, m) + start if triangles else None
        parts.append((points, normals, tris, rgb,
                      _bounds(points, a["wire"][idx], m, sides, view is None) if bounds
                      else np.zeros((m, 2, 3))))
        parts[-1] += ((coils, ccw, chords, sides, m),)
        start += len(points)
    out = [np.concatenate([p[i] for p in parts]) if i != 2 or triangles else None
           for i in range(5)]
    return (*out, tuple(p[5] for p in parts))


def _bounds(points, wire, m: int, sides: int, exact: bool) -> np.ndarray:
    """Per-helix bounds (m, 2, 3): of the vertices (``exact``), or, cheaper, of the ring
    centres (the midpoint of two opposite vertices; ``sides`` is even) widened by the wire."""
    if exact:
        per = points.reshape(m, -1, 3)
        return np.stack([per.min(axis=1), per.max(axis=1)], axis=1)
    per = points.reshape(m, -1, sides, 3)
    centres = (per[:, :, 0] + per[:, :, sides // 2]) / 2
    w = wire[:, None]
    return np.stack([centres.min(axis=1) - w, centres.max(axis=1) + w], axis=1)


def groups(a: dict) -> dict[tuple, np.ndarray]:
    """The helices of :func:`helix_arrays` ``a`` by shape, (coils, ccw): their indices, in
    first-seen order (a batch's groups and its signature's)."""
    groups: dict[tuple, list[int]] = {}
    for i, shape in enumerate(zip(a["coils"], a["ccw"])):
        groups.setdefault(shape, []).append(i)
    return {shape: np.array(idx) for shape, idx in groups.items()}


__all__ = ["CHORD_STEPS", "SIDE_STEPS", "template", "place", "centre_lines", "capsule_chords",
           "helix_arrays",
           "pixels_per_unit", "detail", "mesh", "groups"]
