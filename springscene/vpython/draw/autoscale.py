"""VPython's autoscale: every object bounded as GlowScript bounds it, the range grown at each render.

The rules, read in GlowScript 3.2 (the one vpython 7.6.5 bundles):

- ``lib/glow/autoscale.js`` ``find_extent``: an object is bounded by the 8 corners of
  its oriented box, from ``pos``, ``norm(axis)``, ``norm(up)`` and ``size``
  (z = norm(axis x up), y = z x axis; when axis is parallel to up, z = axis x (1,0,0),
  then axis x (0,1,0)). The box starts at ``pos`` (cylinder, cone, pyramid, helix) or
  is centred on it (``__hasPosAtCenter``: box, ellipsoid, sphere, ring, compound).
  A helix is bounded as the cylinder it is a subclass of: its wire's thickness is not.
- ``primitives.js`` ``__get_extent``: an arrow by its shaft (a box) and head (a
  pyramid) as ``arrow_update`` places them; a triangle or quad by its vertices; a
  compound by its original bounding box (``__offset0``, ``__size0``); a curve by the
  box of its points plus ``origin`` (its radius is not counted), centred and turned
  by the curve's own axis and up (``__no_autoscale`` for a helix's inner curve); a
  ``points`` object by each point (a ``simple_sphere``): a point of pixel size by its
  position only, one of world size by its sphere.
- ``compute_autoscale`` (called from the render function while ``canvas.autoscale``
  is on): an object's extent (``obj.__xmin`` ...) is only ever widened, never reset,
  so it covers every place the object was at a render. With c = cot(fov/2), each
  object gives ``zx = xx c + zz`` and ``zy = yy c + zz`` (xx, yy, zz its largest
  distance from ``center`` per axis); their maxima set the range when one of them grew
  or fell below a third of its last value: ``range = 1.1 (h/w) zx / c`` when
  ``zx h/w > zy`` on a landscape canvas, else ``1.1 zy / c`` (portrait: ``1.1 zx / c``,
  else ``1.1 (w/h) zy / c``).

:func:`at_render` runs that pass for every canvas at each of VPython's renders (the
runner calls it 60 times a program second); the renderer runs it before placing its
camera. Nothing here draws; the state is kept on the canvas (``cv._extents``).
"""

from __future__ import annotations

import math

import numpy as np

from ..objects import frames
from ..geometry import placement, meshes
from ..core.canvases import canvases
from . import surface_meshes

CENTERED = ("box", "sphere", "ring", "compound")
ANCHORED = ("cylinder", "cone", "pyramid", "helix")
_UNIT = np.array([[x, y, z] for x in (0.0, 1.0) for y in (-0.5, 0.5) for z in (-0.5, 0.5)])


def oriented_boxes(pos, axis, up, size, centered: bool) -> np.ndarray:
    """Axis-aligned bounds (M, 2, 3) of the 8 corners of M oriented boxes (find_extent)."""
    pos = np.atleast_2d(np.asarray(pos, dtype=float))
    R = placement.frames(axis, up)                       # columns: X (axis), Y, Z
    size = np.atleast_2d(np.asarray(size, dtype=float))
    unit = _UNIT - ([0.5, 0.0, 0.0] if centered else 0.0)
    corners = pos[:, None, :] + np.einsum("mij,mkj->mki", R, unit[None] * size[:, None, :])
    return np.stack([corners.min(axis=1), corners.max(axis=1)], axis=1)


def _vectors(objs, *names) -> list[np.ndarray]:
    return [np.array([getattr(o, n)._xyz() for o in objs], dtype=float) for n in names]


def _template_boxes(kind: str, objs) -> np.ndarray:
    pos, axis, up, size = _vectors(objs, "_pos", "_axis", "_up", "_size")
    if kind == "compound":            # its original box, wherever its origin is
        lo, hi = zip(*(_unit_box(o) for o in objs))
        lo, hi = np.array(lo) * size, np.array(hi) * size
        R = placement.frames(axis, up)
        pos = pos + np.einsum("mij,mj->mi", R, (lo + hi) / 2)
        size = hi - lo
    return oriented_boxes(pos, axis, up, size, kind in CENTERED)


def _unit_box(obj) -> tuple[np.ndarray, np.ndarray]:
    p = obj._mesh.points
    return p.min(axis=0), p.max(axis=0)


def _arrow_boxes(objs) -> np.ndarray:
    """Shaft and head of each arrow (primitives.js ``arrow_update``), their boxes joined."""
    out = []
    for o in objs:
        axis = np.array(o._axis._xyz())
        L = float(np.linalg.norm(axis))
        pos, up = np.array(o._pos._xyz()), np.array(o._up._xyz())
        if not L > 0:
            out.append([pos, pos])
            continue
        sw, hw, hl = meshes.arrow_dims(L, o._shaftwidth, o._headwidth, o._headlength)
        A = axis / L
        shaft = oriented_boxes(pos, axis, up, [L - hl, sw, sw], False)[0]
        head = oriented_boxes(pos + A * (L - hl), axis, up, [hl, hw, hw], False)[0]
        out.append([np.minimum(shaft[0], head[0]), np.maximum(shaft[1], head[1])])
    return np.array(out, dtype=float).reshape(-1, 2, 3)


def _polygon_boxes(objs) -> np.ndarray:
    out = []
    for o in objs:
        p = np.array([v._pos._xyz() for v in o._verts], dtype=float)
        out.append([p.min(axis=0), p.max(axis=0)])
    return np.array(out, dtype=float).reshape(-1, 2, 3)


_X, _Y = (1.0, 0.0, 0.0), (0.0, 1.0, 0.0)


def bounds(xyz: list) -> tuple[tuple, tuple]:
    """Lowest and highest corner of points given as (x, y, z) tuples."""
    if len(xyz) > 32:
        a = np.array(xyz, dtype=float)
        return tuple(a.min(axis=0).tolist()), tuple(a.max(axis=0).tolist())
    xs, ys, zs = zip(*xyz)
    return (min(xs), min(ys), min(zs)), (max(xs), max(ys), max(zs))


def curve_box(obj, xyz: list) -> tuple[tuple, tuple]:
    """A curve's box from its points (without origin): primitives.js curve
    ``__get_extent``, the points' box plus origin, turned by the curve's axis and up."""
    ox, oy, oz = obj._origin._xyz()
    (x0, y0, z0), (x1, y1, z1) = bounds(xyz)
    lo, hi = (x0 + ox, y0 + oy, z0 + oz), (x1 + ox, y1 + oy, z1 + oz)
    if obj._axis._xyz() == _X and obj._up._xyz() == _Y:
        return lo, hi
    mid = [(a + b) / 2 for a, b in zip(lo, hi)]
    return box_one(mid, obj._axis._xyz(), obj._up._xyz(), [b - a for a, b in zip(lo, hi)],
                   True)


def _unit(v) -> tuple[float, float, float] | None:
    n = math.sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2])
    return None if n == 0 else (v[0] / n, v[1] / n, v[2] / n)


def _cross(a, b) -> tuple[float, float, float]:
    return (a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0])


def box_one(pos, axis, up, size, centered: bool) -> tuple[tuple, tuple]:
    """:func:`oriented_boxes` for one object in plain floats (a few microseconds, where
    numpy's calls cost tens): the centre plus and minus the box's half-diagonal spread."""
    X = _unit(axis) or (1.0, 0.0, 0.0)
    Z = _cross(X, _unit(up) or (0.0, 1.0, 0.0))
    for other in (_X, _Y):
        if Z[0] * Z[0] + Z[1] * Z[1] + Z[2] * Z[2] >= 1e-10:
            break
        Z = _cross(X, other)
    Z = _unit(Z) or (0.0, 0.0, 1.0)
    Y = _cross(Z, X)
    sx, sy, sz = size
    shift = 0.0 if centered else sx / 2
    mid = [pos[i] + X[i] * shift for i in range(3)]
    half = [abs(X[i]) * sx / 2 + abs(Y[i]) * sy / 2 + abs(Z[i]) * sz / 2 for i in range(3)]
    return tuple(m - h for m, h in zip(mid, half)), tuple(m + h for m, h in zip(mid, half))


def _key(o):
    """What an object's box depends on: while it is the same, the box is too."""
    if o._kind == "triangle":
        return tuple(v._pos._xyz() for v in o._verts)
    key = (o._pos._xyz(), o._axis._xyz(), o._up._xyz(), o._size._xyz())
    if o._kind == "arrow":
        return key + (o._shaftwidth, o._headwidth, o._headlength)
    return key + (id(o._mesh),) if o._kind == "compound" else key


def _boxes(kind: str, objs) -> list:
    """(lo, hi) of each object of a kind, with numpy for many at once."""
    if kind == "arrow":
        return _arrow_boxes(objs).tolist()
    if kind == "triangle":
        return _polygon_boxes(objs).tolist()
    if len(objs) >= 16 or kind == "compound":
        return _template_boxes(kind, objs).tolist()
    return [box_one(o._pos._xyz(), o._axis._xyz(), o._up._xyz(), o._size._xyz(),
                    kind in CENTERED) for o in objs]


BOXED = CENTERED + ANCHORED + ("arrow", "triangle")


class Extents:
    """One canvas's autoscale (GlowScript's ``canvas.__extent`` and each object's extent).

    As GlowScript keeps each object's ``__zx_camera`` while it is unchanged, an object's
    box and zx, zy are kept with what they depend on, and measured again only when that
    changed (a curve: only its new points while it is only appended to).
    """

    def __init__(self) -> None:
        self.entries: dict[int, list] = {}   # id -> [object, key, box (2, 3), zx, zy]
        self.seen: dict[int, tuple] = {}     # curves, points: (version, appended) measured
        self.center: tuple | None = None
        self.c = 0.0
        self.last = (-1.0, -1.0)
        self.range: float | None = None
        self.blocks: dict[str, _Block] = {}  # kind -> solids measured in columns

    def update(self, cv) -> float | None:
        """The range after one render's pass over the canvas's visible objects (None
        when there is nothing to bound yet)."""
        if len(self.entries) + sum(len(b.ids) for b in self.blocks.values()) \
                > 2 * len(cv._objects) + 64:
            self._forget(cv._objects)
        center, c = cv.center._xyz(), 1.0 / math.tan(cv.fov / 2)
        if (center, c) != (self.center, self.c):
            self.center, self.c = center, c
            self._recenter()
        zs = self._measure([o for o in cv._objects if o._visible and not frames.hidden(o)])
        if not zs:
            return self.range
        zx, zy = max(z[0] for z in zs), max(z[1] for z in zs)
        lx, ly = self.last
        if zx > lx or zx < lx / 3 or zy > ly or zy < ly / 3:
            self.range = vpython_range(zx, zy, c, cv.width, cv.height)
            self.last = (zx, zy)
        return self.range

    def _measure(self, objs) -> list:
        """Each object's (zx, zy): kept ones as they are, changed ones measured anew
        (solids by kind in :class:`_Block` columns, the others one by one)."""
        zs, todo, bulk = [], {}, {}
        for o in objs:
            kind = o._kind
            if kind in BULK:
                bulk.setdefault(kind, []).append(o)
                continue
            if kind == "curve":
                z = self._curve(o)
            elif kind == "points":
                z = self._points_kept(o)
                if z is None:
                    z = self._points(o)
            elif kind in surface_meshes.KINDS:       # VPython 6's faces and convex
                box = surface_meshes.box(o)
                z = None if box is None else self._store(o, None, box)
            elif kind in BOXED:
                e, key = self.entries.get(id(o)), _key(o)
                if e is None or e[0] is not o or e[1] != key:
                    todo.setdefault(kind, []).append((o, key))
                    continue
                z = e[3:]
            else:
                continue
            if z is not None:
                zs.append(z)
        for kind, items in todo.items():
            for (o, key), box in zip(items, _boxes(kind, [o for o, _ in items])):
                zs.append(self._store(o, key, box))
        for kind in set(self.blocks) | set(bulk):
            block = self.blocks.get(kind) or _Block.empty()
            self.blocks[kind] = block = block.measured(kind, bulk.get(kind, []))
            z = block.z_shown(self.center, self.c)
            if z is not None:
                zs.append(z)
        return zs

    def _store(self, o, key, box) -> list:
        """Widen the object's box by ``box`` (GlowScript never narrows it); its zx, zy."""
        e = self.entries.get(id(o))
        if e is not None and e[0] is o and e[2] is not None:
            box = (tuple(map(min, e[2][0], box[0])), tuple(map(max, e[2][1], box[1])))
        zx, zy = self._z(box)
        self.entries[id(o)] = [o, key, box, zx, zy]
        return [zx, zy]

    def _z(self, box) -> tuple[float, float]:
        xx, yy, zz = (max(abs(a - c), abs(b - c)) for a, b, c in zip(*box, self.center))
        return xx * self.c + zz, yy * self.c + zz

    def _recenter(self) -> None:
        for e in self.entries.values():
            if e[2] is not None:
                e[3:] = self._z(e[2])
        self.entries = {k: e for k, e in self.entries.items() if e[2] is not None}
        self.seen = {k: v for k, v in self.seen.items() if k in self.entries}

    def _curve(self, o):
        if getattr(o, "_frame", None) is not None:     # VPython 6: its points in the world
            p = o._arrays()[0]
            return self._store(o, None, bounds(p.tolist())) if len(p) else None
        p = self._new_points(o)
        if p is None:
            e = self.entries.get(id(o))
            return e[3:] if e is not None and e[0] is o else None
        return self._store(o, None, curve_box(o, p))

    def _new_points(self, o):
        """The points of a curve or points object not measured yet: those appended since
        the last pass while nothing else changed, else all of them (None: no new one);
        a curve's as (x, y, z) tuples, a points object's as an (n, 4) array with radii."""
        mark = (o._version, o._appended)
        old = self.seen.get(id(o))
        self.seen[id(o)] = mark
        pts = o._pts
        if old is not None and old[0] == mark[0]:
            k = min(mark[1] - old[1], len(pts))
            if k <= 0:
                return None
            pts = pts[len(pts) - k:]
        if not pts:
            return None
        xyz = [q["pos"]._xyz() for q in pts]
        if o._kind != "points":
            return xyz
        p = np.array(xyz, dtype=float)
        placed = o.__dict__.get("_world_transform")     # points in a VPython 6 frame
        if placed is not None:
            p = p @ placed[1].T + placed[0]
        r0 = o._radius
        return np.column_stack([p, [q.get("radius", r0) for q in pts]])

    def _points_kept(self, o):
        """A points object's zx, zy as kept, when nothing was added or changed since it
        was measured (a million one-point objects are looked at every render); else None."""
        if self.seen.get(id(o)) != (o._version, o._appended):
            return None
        e = self.entries.get(id(o))
        return e[3:] if e is not None and e[0] is o else None

    def _points(self, o):
        """A points object's largest zx, zy over its points (each one a simple_sphere);
        points do not move, so the largest ever seen is kept."""
        e = self.entries.get(id(o))
        old = e[3:] if e is not None and e[0] is o else None
        p = self._new_points(o)
        if p is None:
            return old
        pad = p[:, 3] if o._size_units == "world" else 0.0
        d = np.abs(p[:, :3] - self.center)
        xx, yy, zz = (d[:, k] + pad for k in range(3))
        z = [float(np.max(xx * self.c + zz)), float(np.max(yy * self.c + zz))]
        if old is not None:
            z = [max(z[0], old[0]), max(z[1], old[1])]
        self.entries[id(o)] = [o, None, None, *z]
        return z

    def _forget(self, objects) -> None:
        alive = {id(o) for o in objects}
        self.entries = {k: e for k, e in self.entries.items() if k in alive}
        self.seen = {k: v for k, v in self.seen.items() if k in alive}
        self.blocks = {k: b.keep(alive) for k, b in self.blocks.items()}


BULK = ("box", "sphere", "ring", "cylinder", "cone", "pyramid", "helix")


def digest(values: np.ndarray) -> np.ndarray:
    """A 64-bit FNV-1a-style digest of each row of floats (M, k): two rows that differ
    in any bit differ in digest but for a chance of 2**-64 a change."""
    bits = np.ascontiguousarray(values, dtype=float).view(np.uint64)
    h = np.full(len(bits), 0xCBF29CE484222325, dtype=np.uint64)
    prime = np.uint64(0x100000001B3)
    for j in range(bits.shape[1]):
        h ^= bits[:, j]
        h *= prime
        h ^= h >> np.uint64(29)
    return h
CHUNK = 4096          # objects measured at a time (:meth:`_Block.measured`)


class _Block:
    """The boxes of every solid of one kind measured so far, in columns: per object its
    id, a digest of what its box depends on (pos, axis, up, size: :func:`digest`), its
    box (GlowScript's extent, only ever widened) and whether it was shown at the last
    pass: 73 bytes an object where a dict of tuples held about 700 (100,000 spheres:
    7 MB, not 70). An object not shown keeps its row (its extent comes back with it),
    until it leaves the canvas (:meth:`Extents._forget`)."""

    def __init__(self, objs: list, ids, keys, boxes, shown) -> None:
        self.objs, self.ids, self.keys, self.boxes, self.shown = objs, ids, keys, boxes, shown

    @classmethod
    def empty(cls) -> "_Block":
        return cls([], np.zeros(0, np.int64), np.zeros(0, np.uint64), np.zeros((0, 2, 3)),
                   np.zeros(0, bool))

    def measured(self, kind: str, objs: list) -> "_Block":
        """This block after a pass that shows ``objs``: their rows kept where nothing
        changed, widened by their new box where something did, new ones added. Worked
        through in chunks of :data:`CHUNK` objects, so the temporary arrays stay small
        (whole, 100,000 spheres left 76 MB in the allocator's pools)."""
        n = len(objs)
        ids = np.fromiter(map(id, objs), dtype=np.int64, count=n)
        if n == len(self.ids) and np.array_equal(ids, self.ids) and self.shown.all() \
                and all(a is b for a, b in zip(objs, self.objs)):
            for s in range(0, n, CHUNK):        # the same objects: updated in place
                part = slice(s, s + CHUNK)
                values = placement.xyz_array(objs[part], "_pos", "_axis", "_up", "_size")
                self.keys[part] = self._boxes(kind, values, np.arange(s, min(s + CHUNK, n)),
                                              self.boxes[part])
            return self
        row = self._rows(ids, objs)
        keys, boxes = np.empty(n, np.uint64), np.zeros((n, 2, 3))
        for s in range(0, n, CHUNK):
            part = slice(s, s + CHUNK)
            values = placement.xyz_array(objs[part], "_pos", "_axis", "_up", "_size")
            keys[part] = self._boxes(kind, values, row[part], boxes[part])
        rest = np.ones(len(self.ids), dtype=bool)
        rest[row[row >= 0]] = False               # rows of objects not shown this pass
        shown = np.ones(n, bool)
        if rest.any():
            objs = objs + [o for o, r in zip(self.objs, rest.tolist()) if r]
            ids, keys = np.concatenate([ids, self.ids[rest]]), np.concatenate([keys, self.keys[rest]])
            boxes = np.concatenate([boxes, self.boxes[rest]])
            shown = np.concatenate([shown, np.zeros(int(rest.sum()), bool)])
        return _Block(objs, ids, keys, boxes, shown)

    def _boxes(self, kind: str, values: np.ndarray, row: np.ndarray,
               out: np.ndarray) -> np.ndarray:
        """Boxes (into ``out``) of objects whose pos, axis, up and size are ``values``
        (M, 12), at ``row`` of this block (-1: new): the kept box where they are the same,
        else the new one, widened. Returns their keys."""
        keys = digest(values)
        old = row >= 0
        same = old.copy()
        if old.any():
            at = row[old]
            same[old] = keys[old] == self.keys[at]
            out[old] = self.boxes[at]
        todo = ~same
        if todo.any():
            k = values[todo]
            box = oriented_boxes(k[:, 0:3], k[:, 3:6], k[:, 6:9], k[:, 9:12], kind in CENTERED)
            grow = old[todo]
            box[grow, 0] = np.minimum(box[grow, 0], out[todo][grow, 0])
            box[grow, 1] = np.maximum(box[grow, 1], out[todo][grow, 1])
            out[todo] = box
        return keys

    def _rows(self, ids, objs) -> np.ndarray:
        """Each object's row in this block (-1: none; an id reused by a new object
        after the old one was freed is not its row)."""
        if not len(self.ids) or not len(ids):
            return np.full(len(ids), -1)
        order = np.argsort(self.ids, kind="stable")
        at = np.minimum(np.searchsorted(self.ids[order], ids), len(order) - 1)
        row = np.where(self.ids[order[at]] == ids, order[at], -1)
        mine = self.objs
        return np.array([r if r < 0 or mine[r] is o else -1 for r, o in zip(row.tolist(), objs)],
                        dtype=np.int64).reshape(-1)

    def z_shown(self, center, c: float) -> list[float] | None:
        """The largest (zx, zy) of the objects shown at the last pass (compute_autoscale),
        None when none was; worked out a chunk at a time."""
        best = None
        center = np.asarray(center, dtype=float)
        for s in range(0, len(self.ids), CHUNK):
            part = slice(s, s + CHUNK)
            b = self.boxes[part][self.shown[part]]
            if not len(b):
                continue
            d = np.maximum(np.abs(b[:, 0] - center), np.abs(b[:, 1] - center))
            z = [float(np.max(d[:, 0] * c + d[:, 2])), float(np.max(d[:, 1] * c + d[:, 2]))]
            best = z if best is None else [max(best[0], z[0]), max(best[1], z[1])]
        return best

    def keep(self, alive: set) -> "_Block":
        """Only the rows of objects still on the canvas."""
        k = np.fromiter((i in alive for i in self.ids.tolist()), dtype=bool,
                        count=len(self.ids))
        return _Block([o for o, a in zip(self.objs, k) if a], self.ids[k], self.keys[k],
                      self.boxes[k], self.shown[k])


def vpython_range(zx: float, zy: float, c: float, width: int, height: int) -> float:
    """compute_autoscale's range from the largest ``zx``, ``zy`` (c = cot(fov/2))."""
    if zx * height / width > zy:
        return 1.1 * (height / width) * zx / c if width >= height else 1.1 * zx / c
    return 1.1 * zy / c if width >= height else 1.1 * (width / height) * zy / c


def extents(cv) -> Extents:
    """The canvas's autoscale state, made at first use."""
    state = cv.__dict__.get("_extents")
    if state is None:
        state = cv.__dict__["_extents"] = Extents()
    return state


def update(cv) -> None:
    """One render's autoscale pass over ``cv`` (its objects already in the world)."""
    if cv._autoscale:
        r = extents(cv).update(cv)
        if r is not None:
            cv._autoscaled_range = r


def at_render() -> None:
    """VPython's autoscale at one render, for every canvas with autoscale on."""
    for cv in canvases():
        if cv._autoscale and cv._objects:
            with frames.in_world(cv._objects):
                update(cv)
