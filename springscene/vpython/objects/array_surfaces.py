"""VPython 6's ``faces`` and ``convex``: surfaces whose points a program keeps as numpy arrays.

As VPython 6 (``src/python/faces.cpp``, ``convex.cpp``, ``arrayprim.cpp``; the
``faces`` and ``convex`` pages of its documentation):

- ``faces(pos=, normal=, color=, frame=)``: one-sided triangles, vertices 0-2 the
  first, 3-5 the second, ... (a last incomplete triangle is not drawn). ``pos``,
  ``normal`` and ``color`` are N x 3 float arrays, read as live views (``f.pos[0::3, 0]
  = ...`` changes the next frame) and copied when set; ``x``/``y``/``z`` and
  ``red``/``green``/``blue`` are their columns. A single vector or colour set
  (``color=color.cyan``) is given to every vertex; an N x 3 array sets the number of
  vertices for all three arrays, new vertices taking the last one's values (the first
  vertex's before there is any: how an empty ``faces`` keeps its colour).
  ``append(pos=, normal=, color=)`` (or ``red=, green=, blue=``) adds a vertex (normal
  <0, 0, 0> when none is given). ``make_normals()`` gives each triangle's vertices its
  unit normal (counter-clockwise winding), ``make_twosided()`` adds every triangle again
  wound the other way with its normals turned round, ``smooth(cosangle=0.95)`` averages
  the normals at a shared vertex that differ by less than ``acos(cosangle)``.
  A triangle is seen from the side it is counter-clockwise from, lit by its vertices'
  normals, colours blended across it.
- ``convex(pos=, color=, frame=)``: the convex hull of its points, in one colour;
  ``pos`` is an N x 3 array as above, ``append(pos=)`` adds a point. Points all in a
  plane make a flat polygon seen from both sides.

Both go in VPython 6 frames (their points in the frame's coordinates) and take
``opacity``, which VPython 6 refused. Nothing here draws: the renderer makes their
meshes (:mod:`..draw.surface_meshes`) when :attr:`_dirty`, which also notices a
program's in-place changes to the arrays.
"""

from __future__ import annotations

import zlib

import numpy as np

from ..core.attributes import Linked
from ..core.vectors import vector
from .base import _Base


def _rows(value, name: str) -> np.ndarray:
    """``value`` as a float array: one row (3,) for a single vector, else (N, 2 or 3)."""
    if isinstance(value, vector):
        return np.array(value._xyz(), dtype=float)
    try:
        if not isinstance(value, np.ndarray):
            value = [v._xyz() if isinstance(v, vector) else v for v in value]
        a = np.array(value, dtype=float)
    except (TypeError, ValueError):
        raise ValueError(f"{name} must be an Nx3 array") from None
    if a.ndim == 1 and len(a) == 0:
        return a.reshape(0, 3)
    if a.ndim == 2 and a.shape[1] == 2 and name == "pos":
        a = np.column_stack([a, np.zeros(len(a))])
    if not (a.shape == (3,) or (a.ndim == 2 and a.shape[1] == 3)):
        raise ValueError(f"{name} must be an Nx3 array")
    return a


class PointArrays:
    """Parallel N x 3 arrays with one length, grown as VPython 6's array objects grow:
    new rows copy the last row (the first row counts even at length 0)."""

    def __init__(self, names: tuple[str, ...], first: dict[str, tuple]) -> None:
        self.count = 0
        self.buffers = {n: np.zeros((16, 3)) for n in names}
        for n, row in first.items():
            self.buffers[n][0] = row

    def view(self, name: str) -> np.ndarray:
        """The live rows of ``name`` (a view: writes to it are the object's)."""
        return self.buffers[name][:self.count]

    def resize(self, n: int) -> None:
        old = self.count
        for name, buf in self.buffers.items():
            if n > len(buf):
                bigger = np.zeros((max(2 * len(buf), n), 3))
                bigger[:max(old, 1)] = buf[:max(old, 1)]
                buf = self.buffers[name] = bigger
            if n > old:
                buf[old:n] = buf[max(old, 1) - 1]
        self.count = n

    def assign(self, name: str, value, sizes: bool = True) -> None:
        """Set ``name`` from a single row (given to every row) or N rows (which set the
        length of all the arrays, when ``sizes``)."""
        a = _rows(value, name)
        if a.ndim == 1:
            if name == "pos":
                self.resize(1)
            self.buffers[name][:max(self.count, 1)] = a
            return
        if sizes or self.count == 0:
            self.resize(len(a))
        elif len(a) != self.count:
            raise ValueError(f"{name} has {len(a)} rows, the object {self.count} points")
        self.buffers[name][:self.count] = a

    def column(self, name: str, index: int, value) -> None:
        """One column (``x``, ``red``): an array sets the length, a number every row
        (a first point for ``x``, ``y``, ``z`` when there is none)."""
        a = np.asarray(value, dtype=float)
        if a.ndim == 0:
            if name == "pos":
                self.resize(max(self.count, 1))
            self.buffers[name][:max(self.count, 1), index] = a
            return
        if a.ndim != 1:
            raise ValueError(f"{name} component must be a 1D array")
        self.resize(len(a))
        self.buffers[name][:self.count, index] = a

    def append(self, values: dict) -> None:
        self.resize(self.count + 1)
        for name, row in values.items():
            self.buffers[name][self.count - 1] = row

    def checksum(self) -> int:
        total = self.count
        for buf in self.buffers.values():
            total = zlib.crc32(memoryview(buf[:self.count]), total)
        return total


def _array_property(name: str):
    sizes = name != "normal"        # N normals must match N points (unless there are none)

    def get(self):
        return self._arrays.view(name)

    def set_(self, value) -> None:
        self._arrays.assign(name, value, sizes)
        self._dirty = True
    return property(get, set_, doc=f"The N x 3 array of the vertices' {name}.")


def _column_property(name: str, index: int):
    def get(self):
        return self._arrays.view(name)[:, index]

    def set_(self, value) -> None:
        self._arrays.column(name, index, value)
        self._dirty = True
    return property(get, set_)


class _ArraySurface(_Base):
    """What faces and convex share: point arrays, a frame, opacity, change detection."""

    _names: tuple[str, ...] = ("pos",)
    texture = None           # neither takes a texture (a recording reads one)

    def __init__(self, **args) -> None:
        self._changed = True
        self._drawn_sum = None
        self._visible = bool(args.pop("visible", True))
        self._opacity = 1.0
        self._shininess = 0.6
        self._emissive = False
        self._register(args)        # canvas (display), frame
        first = self._canvas.foreground._xyz()        # VPython 6's default colour
        self._arrays = PointArrays(self._names, {"color": first} if "color" in self._names
                                   else {})
        if "color" not in self._names:
            self._color = vector(*first)
        self._setup(args)
        for name, value in args.items():        # the program's own attributes, material
            setattr(self, name, value)

    def _setup(self, args: dict) -> None:
        """The keywords VPython 6 read first: colour, then the points."""
        for name in ("color", "red", "green", "blue", *self._names):
            if name in args:
                setattr(self, name, args.pop(name))

    @property
    def _dirty(self) -> bool:
        """Changed since last drawn: set so, or its arrays changed in place."""
        return self._changed or self._arrays.checksum() != self._drawn_sum

    @_dirty.setter
    def _dirty(self, value: bool) -> None:
        self._changed = bool(value)
        if not value:
            self._drawn_sum = self._arrays.checksum()

    pos = _array_property("pos")
    x, y, z = _column_property("pos", 0), _column_property("pos", 1), _column_property("pos", 2)
    opacity = Linked(float, dirty=True)
    shininess = Linked(float, dirty=True)
    emissive = Linked(bool, dirty=True)


def _unit_rows(v: np.ndarray) -> np.ndarray:
    """Each row made unit length (zero rows stay zero)."""
    n = np.linalg.norm(v, axis=1, keepdims=True)
    return np.divide(v, n, out=np.zeros_like(v), where=n > 0)


class faces(_ArraySurface):
    """VPython 6's triangles: three vertices each, with per-vertex normal and colour."""

    _kind = "faces"
    _names = ("pos", "normal", "color")

    normal = _array_property("normal")
    color = _array_property("color")
    red, green, blue = (_column_property("color", 0), _column_property("color", 1),
                        _column_property("color", 2))

    def append(self, pos, normal=None, color=None, red=-1, green=-1, blue=-1) -> None:
        """Add one vertex (its normal <0, 0, 0> unless given; its colour the last one's
        unless given)."""
        row = {"pos": _rows(pos, "pos"), "normal": np.zeros(3)}
        if row["pos"].shape != (3,):
            raise ValueError("append takes one pos")
        if normal is not None:
            row["normal"] = _rows(normal, "normal")
        if color is not None:
            row["color"] = _rows(color, "color")
        self._arrays.append(row)
        last = self._arrays.view("color")[-1]
        for i, c in enumerate((red, green, blue)):
            if c != -1:
                last[i] = c
        self._dirty = True

    def make_normals(self) -> None:
        """Every whole triangle's vertices get its unit normal, (v1 - v0) x (v2 - v1)."""
        pos, normal = self._arrays.view("pos"), self._arrays.view("normal")
        n = len(pos) - len(pos) % 3
        normal[:] = 0
        t = pos[:n].reshape(-1, 3, 3)
        unit = _unit_rows(np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 1]))
        normal[:n] = np.repeat(unit, 3, axis=0)
        self._dirty = True

    def make_twosided(self) -> None:
        """Each triangle again, wound the other way, its normals turned round (a last
        incomplete triangle is first completed with copies of its last vertex)."""
        a = self._arrays
        if a.count < 3:
            return
        while a.count % 3:
            a.resize(a.count + 1)
        n = a.count
        a.resize(2 * n)
        for name in self._names:
            v = a.buffers[name]
            back = v[:n].reshape(-1, 3, 3)[:, (0, 2, 1)].reshape(-1, 3)
            v[n:2 * n] = -back if name == "normal" else back
        self._dirty = True

    def smooth(self, cosangle: float = 0.95) -> None:
        """Average the normals at each shared vertex position that point within
        ``acos(cosangle)`` of the first one of a group (VPython 6's rule, repeated until
        every normal there was used; zero normals are left as they are)."""
        pos, normal = self._arrays.view("pos"), self._arrays.view("normal")
        if not len(pos):
            return
        _, where = np.unique(pos, axis=0, return_inverse=True)
        order = np.argsort(where.ravel(), kind="stable")
        groups = np.split(order, np.flatnonzero(np.diff(where.ravel()[order])) + 1)
        unit = _unit_rows(normal)
        for group in groups:
            if len(group) > 1:
                _smooth_group(group, unit, normal, cosangle)
        self._dirty = True


def _smooth_group(group: np.ndarray, unit: np.ndarray, normal: np.ndarray,
                  cosangle: float) -> None:
    """One vertex position's normals averaged by likeness (:meth:`faces.smooth`)."""
    left = [int(i) for i in group if unit[i].any()]
    while left:
        seed = unit[left[0]]
        similar = [i for i in left if unit[i] @ seed >= cosangle]
        mean = unit[similar].sum(axis=0)
        length = np.linalg.norm(mean)
        normal[similar] = mean / length if length > 0 else 0.0
        used = set(similar)
        left = [i for i in left if i not in used]


def _one_colour(value, name: str) -> vector:
    a = _rows(value, name)
    if a.shape != (3,):
        raise ValueError(f"{name} must be one colour (r, g, b)")
    return vector(*a)


class convex(_ArraySurface):
    """VPython 6's convex hull of a set of points, in one colour."""

    _kind = "convex"
    _names = ("pos",)

    color = Linked(_one_colour, dirty=True)
    red = property(lambda self: self._color.x, lambda self, v: self._set_part(0, v))
    green = property(lambda self: self._color.y, lambda self, v: self._set_part(1, v))
    blue = property(lambda self: self._color.z, lambda self, v: self._set_part(2, v))

    def _set_part(self, index: int, value) -> None:
        parts = list(self._color._xyz())
        parts[index] = float(value)
        self.color = vector(*parts)

    def append(self, pos) -> None:
        """Add one point to the hull."""
        row = _rows(pos, "pos")
        if row.shape != (3,):
            raise ValueError("append takes one pos")
        self._arrays.append({"pos": row})
        self._dirty = True


__all__ = ["faces", "convex", "PointArrays"]
