"""VPython's ``curve`` and ``points``: lists of points, each with its own colour and radius.

As in ``vpython/vpython.py`` (``curveMethods``): points come as vectors, lists of
vectors or dictionaries ``{"pos": v, "color": c, "radius": r}``; ``append``,
``modify``, ``point``, ``slice``, ``splice``, ``pop``, ``shift``, ``unshift``,
``clear`` and ``npoints`` work on the list. ``retain`` keeps only the newest points
(trails use it). A curve of radius 0 is a thin lit tube whose width follows the range;
``points`` are lit balls of ``radius`` pixels (or world units with ``size_units="world"``),
both as :mod:`..geometry.point_meshes` draws them.

In a VPython 6 program (:func:`..core.vectors.is_lenient`) the points are also numpy
arrays, as VPython 6's ``arrayprim`` (``src/python/arrayprim.cpp``) kept them: ``c.pos``
and ``c.color`` N x 3, ``c.x`` ... ``c.blue`` their columns. Reading one gives a live
view (:class:`LivePoints`): a write through it changes the points as ``modify`` does.
Setting one replaces the points, resizing the list (fewer keep the last ones, more repeat
the last point); a single colour colours every point.
"""

from __future__ import annotations

import numpy as np

from ..core.attributes import Linked
from .base import _Base
from ..core.checks import _vec, one_of
from ..core.vectors import is_lenient, vector

_COLUMNS = {"x": ("pos", 0), "y": ("pos", 1), "z": ("pos", 2),
            "red": ("color", 0), "green": ("color", 1), "blue": ("color", 2)}


def _plain(value):
    """A value numpy can take: a live array as a plain one, a vector as its 3 numbers."""
    if isinstance(value, LivePoints):
        return value.view(np.ndarray)
    return np.array(value._xyz()) if isinstance(value, vector) else value


class LivePoints(np.ndarray):
    """A VPython 6 curve's ``pos`` or ``color`` (or a slice of one), as VPython 6 handed
    them out: a view of the points, so that ``c.pos[3] = (1, 2, 3)``, ``c.pos[:, 1] += 0.1``
    and ``c.x *= 2`` move the drawn points. Anything computed from it (``c.pos * 2``, a
    copy) is a plain array."""

    _owner = None        # (the curve, "pos" or "color", the array this views)

    def __array_finalize__(self, obj) -> None:
        owner = getattr(obj, "_owner", None)
        self._owner = owner if owner is not None and np.may_share_memory(self, owner[2]) \
            else None

    def _wrote(self) -> None:
        if self._owner is not None:
            self._owner[0]._array_written(*self._owner[1:])

    def __setitem__(self, key, value) -> None:
        super().__setitem__(key, _plain(value))
        self._wrote()

    def __array_ufunc__(self, ufunc, method, *inputs, out=None, **kwargs):
        if out is not None:
            kwargs["out"] = tuple(_plain(o) for o in out)
        result = getattr(ufunc, method)(*(_plain(x) for x in inputs), **kwargs)
        if out is None:
            return result
        for o in out:
            if isinstance(o, LivePoints):
                o._wrote()
        return out[0] if len(out) == 1 else out

    def __repr__(self) -> str:
        return repr(self.view(np.ndarray))


for _op in ("__iadd__", "__isub__", "__imul__", "__itruediv__"):   # a vector: its 3 numbers
    setattr(LivePoints, _op, lambda self, v, _f=getattr(np.ndarray, _op): _f(self, _plain(v)))


def _is_table(value) -> bool:
    """An N x 3 array or a list of triples (one colour each), not one colour."""
    if isinstance(value, np.ndarray):
        return value.ndim == 2
    return isinstance(value, (list, tuple)) and bool(value) and not all(
        isinstance(c, (int, float, np.number)) for c in value)


def _rows(value, name: str) -> np.ndarray:
    """What VPython 6 took for ``pos`` or ``color``: an N x 3 (or N x 2, z = 0) array, a
    list of vectors or tuples, or one vector, as an (n, 3) array of floats."""
    if hasattr(value, "pos") and not isinstance(value, (np.ndarray, list, tuple, vector)):
        value = value.pos                      # a path (paths.circle(...)) as VPython 6 took
    if isinstance(value, vector):
        return np.array([value._xyz()])
    if _is_table(value) and not isinstance(value, np.ndarray):
        value = [_vec(v, name)._xyz() for v in value]
    a = np.array(value, dtype=float)
    if a.ndim == 1 and a.size in (0, 2, 3):            # none, or one point
        a = a.reshape(-1, a.size or 3)
    if a.ndim != 2 or a.shape[1] not in (2, 3):
        raise ValueError(f"{name} must be an Nx3 array")
    if a.shape[1] == 2:
        a = np.column_stack([a, np.zeros(len(a))])
    return a


def _v6_colour_args(args: tuple) -> bool:
    """``append(pos, color[, retain])`` as VPython 6 took it: a second argument that is a
    colour (three numbers from 0 to 1), a third a number; else VPython 7's
    ``append(v1, v2, ...)``, several points."""
    if len(args) not in (2, 3) or (len(args) == 3 and not isinstance(args[2], (int, float))):
        return False
    c = args[1]._xyz() if isinstance(args[1], vector) else args[1]
    return isinstance(c, (list, tuple, np.ndarray)) and len(c) == 3 and all(
        isinstance(v, (int, float, np.number)) and 0 <= v <= 1 for v in c)


def _point(value, constructing: bool) -> dict:
    if isinstance(value, dict):
        if "pos" not in value:
            raise AttributeError("To add a point to a curve or points object, specify pos information.")
        pt = dict(value)
        pt["pos"] = _vec(pt["pos"], "pos")
        if "color" in pt:
            pt["color"] = _vec(pt["color"], "color")
        return pt
    if isinstance(value, (vector, list, tuple, np.ndarray)):
        return {"pos": _vec(value, "pos")}
    raise AttributeError("Point pos must be a vector" if constructing
                         else "Point information must be a vector or a dictionary")


def _columns(kwargs: dict) -> np.ndarray:
    """VPython 6's ``x=``, ``y=``, ``z=`` arrays (or numbers) as N x 3 points."""
    cols = [np.atleast_1d(np.asarray(kwargs.pop(c, 0.0), dtype=float)) for c in "xyz"]
    n = max(len(c) for c in cols)
    return np.column_stack([np.broadcast_to(c, (n,)) for c in cols])


def _flatten(args: tuple) -> list:
    """``append(v)``, ``append(v1, v2)``, ``append([v1, v2])`` and ``append(pos=[...])`` alike."""
    out = []
    for a in args:
        if isinstance(a, np.ndarray) and a.ndim == 2:       # VPython 6: an N x 3 array
            out.extend(a)
        elif isinstance(a, (list, tuple)) and a and not all(
                isinstance(c, (int, float, np.number)) and not isinstance(c, bool) for c in a):
            out.extend(a)
        else:
            out.append(a)
    return out


class _PointList(_Base):
    _kind = "curve"
    _default_radius = 0.0
    # for autoscale (:mod:`..draw.autoscale`): points appended so far, and a count of the other
    # changes; while only appends happen, only the new points need measuring
    _appended = 0
    _version = 0
    _edits = 0          # changes to the point list other than appends (for a recording)

    def __init__(self, *args, **kwargs) -> None:
        object.__setattr__(self, "_constructing", True)
        self._pts: list[dict] = []
        self._color = vector(1, 1, 1)
        self._radius = self._default_radius
        self._retain = -1
        self._visible = True
        self._shininess = 0.6
        self._emissive = False
        self._origin = vector(0, 0, 0)
        self._size_units = "pixels"
        self._cache = None      # arrays of the first points, kept while only appends happen
        self._live: dict = {}   # VPython 6's arrays handed out: field -> [array, seen, stamp]
        pos = kwargs.pop("pos", None)
        later = {}                               # VPython 6: per-point colours, set once made
        if is_lenient():
            if pos is None and any(c in kwargs for c in "xyz"):
                pos = _columns(kwargs)           # curve(x=arange(...), y=...)
            if _is_table(kwargs.get("color")):
                later["color"] = kwargs.pop("color")
            later.update((c, kwargs.pop(c)) for c in ("red", "green", "blue") if c in kwargs)
        if pos is not None and args:
            raise AttributeError("Malformed constructor")
        for name in ("color", "origin"):
            if name in kwargs:
                setattr(self, "_" + name, _vec(kwargs.pop(name), name))
        for name in ("radius", "retain", "visible", "shininess", "emissive", "size_units",
                     "pickable"):
            if name in kwargs:
                setattr(self, name, kwargs.pop(name))
        self._color._on_change = self._touch
        self._origin._on_change = self._touch
        self._register(kwargs)
        for name, value in kwargs.items():
            setattr(self, name, value)
        if pos is not None:
            self.append(pos)
        if args:
            self.append(*args)
        for name, value in later.items():
            setattr(self, name, value)
        self._constructing = False

    # -- attributes ----------------------------------------------------------------------

    radius = Linked(float, then="_touch")
    retain = Linked(int, then="_touch")
    shininess = Linked(float, then="_touch")
    emissive = Linked(bool, then="_touch")
    pickable = property(lambda self: True, lambda self, v: None)
    size_units = Linked(one_of("pixels", "world"), then="_touch")

    def _touch(self) -> None:
        self._cache = None
        self._dirty = True
        self._version += 1

    @property
    def color(self):
        """The object's colour (a vector); in VPython 6, every point's, an N x 3 array."""
        if is_lenient():
            return self._array("color")
        return self._color

    @color.setter
    def color(self, value) -> None:
        if is_lenient() and _is_table(value):
            self._set_rows("color", _rows(value, "color"))
            return
        value = _vec(value, "color")
        self._color = value
        value._on_change = self._touch
        if is_lenient() and any("color" in p for p in self._pts):
            for p in self._pts:                  # VPython 6: one colour for every point
                p.pop("color", None)
            self._changed()
        else:
            self._touch()

    @property
    def pos(self):
        if is_lenient():
            return self._array("pos")
        raise AttributeError('object does not have a "pos" attribute')

    @pos.setter
    def pos(self, value) -> None:
        if not is_lenient():
            raise AttributeError("use object methods to change its shape")
        self._set_rows("pos", _rows(value, "pos"))

    @property
    def npoints(self) -> int:
        return len(self._pts)

    # -- the point list ------------------------------------------------------------------

    def _parse(self, args: tuple, kwargs: dict) -> list[dict]:
        items = _flatten(args) if args else _flatten((kwargs.pop("pos"),)) if "pos" in kwargs \
            else []
        if not items:
            raise AttributeError("To add a point to a curve or points object, specify pos information.")
        pts = [_point(v, self._constructing) for v in items]
        for pt in pts:
            for key in ("color", "radius", "visible"):
                if key in kwargs and key not in pt:
                    pt[key] = _vec(kwargs[key], key) if key == "color" else kwargs[key]
        return pts

    def _trim(self, retain: int | None = None) -> None:
        retain = self._retain if retain is None else retain
        if retain > 0 and len(self._pts) > retain:
            k = len(self._pts) - retain
            del self._pts[:k]
            if self._cache is not None:
                count, *arrays = self._cache
                self._cache = (count - k, *(a[k:] for a in arrays)) if count > k else None
        self._dirty = True

    def _changed(self) -> None:
        """A change to the points other than an append: the arrays are made anew."""
        self._edits += 1
        self._touch()

    def append(self, *args, **kwargs) -> None:
        retain = None
        if is_lenient():
            args, retain = self._v6_append_args(args, kwargs)
        new = self._parse(args, kwargs)
        if is_lenient() and self._pts and "color" in self._pts[-1]:
            for pt in new:                       # VPython 6: the last point's colour goes on
                pt.setdefault("color", self._pts[-1]["color"])
        self._pts.extend(new)
        self._appended += len(new)
        self._trim(retain)

    def _v6_append_args(self, args: tuple, kwargs: dict) -> tuple[tuple, int | None]:
        """VPython 6's ``append(pos, color, retain)`` and ``append(pos, red=, green=,
        blue=, retain=)`` (``arrayprim.cpp``): the point and how many points to keep
        (0: the new one alone; None: the curve's ``retain``)."""
        if _v6_colour_args(args):
            kwargs.update(zip(("color", "retain"), args[1:]))
            args = args[:1]
        parts = [(i, kwargs.pop(c)) for i, c in enumerate(("red", "green", "blue")) if c in kwargs]
        if parts and "color" not in kwargs:
            rgb = list((self._pts[-1].get("color", self._color) if self._pts
                        else self._color)._xyz())
            for i, value in parts:
                rgb[i] = float(value)
            kwargs["color"] = vector(*rgb)
        retain = kwargs.pop("retain", None)
        return args, None if retain is None or retain < 0 else max(int(retain), 1)

    def unshift(self, *args, **kwargs) -> None:
        self._pts[:0] = self._parse(args, kwargs)
        self._edits += 1
        self._touch()
        self._trim()

    def _check_index(self, n: int) -> None:
        if n >= len(self._pts) or (n < 0 and -n > len(self._pts)):
            raise ValueError(f"N = {n} is outside the bounds 0-{len(self._pts) - 1} "
                             "of the curve points")

    def point(self, n: int) -> dict:
        self._check_index(n)
        info = dict(self._pts[n])
        info.setdefault("color", self._color)
        info.setdefault("radius", self._radius)
        info.setdefault("visible", self._visible)
        info.setdefault("retain", self._retain)
        return info

    def modify(self, n: int, *args, **kwargs) -> None:
        self._check_index(n)
        p = self._pts[n]
        if len(args) == 1:
            p["pos"] = _vec(args[0], "pos")
        for key, value in kwargs.items():
            if key in ("x", "y", "z"):
                xyz = list(p["pos"].value)
                xyz["xyz".index(key)] = float(value)
                p["pos"] = vector(*xyz)
            elif key == "pos":
                p["pos"] = _vec(value, "pos")
            elif key == "color":
                p["color"] = _vec(value, "color")
            elif key in ("radius", "visible", "retain"):
                p[key] = value
            else:
                raise AttributeError(f"modify: unknown point attribute {key!r}")
        self._changed()

    def slice(self, start: int, end: int) -> list[dict]:
        return self._pts[start:end]

    def splice(self, start: int, howmany: int, *args) -> None:
        if howmany < 0:
            raise ValueError("You cannot delete a negative number of points")
        pts = self._parse(args, {}) if args else []
        self._pts[start:start + howmany] = pts
        self._changed()

    def pop(self, n: int = -1):
        if not self._pts:
            return None
        self._changed()
        return self._pts.pop(n)

    def shift(self):
        return self.pop(0)

    def clear(self) -> None:
        self._pts = []
        self._changed()

    # -- VPython 6's arrays ----------------------------------------------------------------

    def _stamp(self) -> tuple:
        """What changes whenever the points do (an edit, an append, a drop)."""
        return self._version, self._appended, len(self._pts)

    def _values(self, field: str) -> np.ndarray:
        """The points' positions or colours as an (n, 3) array."""
        c0 = self._color
        xyz = [p["pos"]._xyz() for p in self._pts] if field == "pos" else \
            [p.get("color", c0)._xyz() for p in self._pts]
        return np.array(xyz, dtype=float).reshape(-1, 3)

    def _array(self, field: str) -> LivePoints:
        """``pos`` or ``color`` as VPython 6 gave it: a live view of the points. The array
        is kept while the points do not change, and refilled in place while their number
        stays, so that a view a program holds stays live."""
        entry, stamp = self._live.get(field), self._stamp()
        if entry is None or entry[2] != stamp:
            values = self._values(field)
            if entry is None or entry[0].shape != values.shape:
                entry = self._live[field] = [values, values.copy(), stamp]
            else:                                  # refilled: views held stay live
                entry[0][...] = entry[1][...] = values
                entry[2] = stamp
        view = entry[0].view(LivePoints)
        view._owner = (self, field, entry[0])
        return view

    def _array_written(self, field: str, array: np.ndarray) -> None:
        """A program wrote into a live array: the rows that changed become the points'."""
        entry = self._live.get(field)
        if entry is None or entry[0] is not array:
            return                               # an array since replaced: no longer live
        changed = np.flatnonzero((array != entry[1]).any(axis=1)[:len(self._pts)])
        if not changed.size:
            return
        current = entry[2] == self._stamp()
        for k, row in zip(changed.tolist(), array[changed].tolist()):
            self._pts[k][field] = vector(*row)
        entry[1][changed] = array[changed]
        self._changed()
        if current:
            entry[2] = self._stamp()

    def _resize(self, n: int) -> None:
        """VPython 6's ``set_length``: fewer points keep the last ones; more repeat the last
        point (its colour too), or start at the origin."""
        pts = self._pts
        if n == len(pts):
            return
        del pts[:max(len(pts) - n, 0)]
        while len(pts) < n:
            last = pts[-1] if pts else {"pos": vector(0, 0, 0)}
            pts.append({k: vector(v) if isinstance(v, vector) else v for k, v in last.items()})
        self._changed()

    def _same(self, field: str, rows: np.ndarray) -> bool:
        """The rows are the points already (``c.pos += v`` writes in place, then sets;
        ``c.pos = c.ends`` each frame): no change to record."""
        entry = self._live.get(field)
        held = entry[0] if entry is not None and entry[2] == self._stamp() else None
        return len(rows) == len(self._pts) and np.array_equal(
            self._values(field) if held is None else held, rows)

    def _set_rows(self, field: str, rows: np.ndarray) -> None:
        """``c.pos = array`` or ``c.color = array``: the points, resized to the rows."""
        if self._same(field, rows):
            return
        self._resize(len(rows))
        for p, row in zip(self._pts, rows.tolist()):
            p[field] = vector(*row)
        self._changed()

    def _set_column(self, name: str, value) -> None:
        """``c.x = array`` (resizing) or ``c.x = number`` (every point's x), and so on."""
        field, i = _COLUMNS[name]
        if np.ndim(value) == 0:
            if field == "color" and not any("color" in p for p in self._pts):
                xyz = list(self._color._xyz())       # one colour: the object's
                xyz[i] = float(value)
                self.color = vector(*xyz)
                return
            if not self._pts:
                self._resize(1)
        else:
            value = np.asarray(value, dtype=float)
            if value.ndim != 1:
                raise ValueError(f"{name} must be a 1D array.")
            self._resize(len(value))
            entry = self._live.get(field)
            if entry is not None and entry[2] == self._stamp() and \
                    np.array_equal(entry[0][:, i], value):
                return                            # c.x *= 2: written in place already
        rows = self._values(field)
        rows[:, i] = value
        self._set_rows(field, rows)

    def _arrays(self):
        """Positions (n, 3), colours (n, 3) and radii (n,) of the visible points.

        The arrays of the points already seen are kept while the program only appends
        (a trail), so a frame reads only the new points, not all of them again.
        """
        start, kept = (0, None) if self._cache is None else (self._cache[0], self._cache[1:])
        new = self._pts[start:]
        n = len(new)
        pos, col = np.empty((n, 3)), np.empty((n, 3))
        rad, vis = np.empty(n), np.empty(n, dtype=bool)
        c0, r0 = self._color.value, self._radius
        for k, p in enumerate(new):
            pos[k] = p["pos"]._xyz()
            c = p.get("color")
            col[k] = c._xyz() if c is not None else c0
            rad[k] = p.get("radius", r0)
            vis[k] = p.get("visible", True)
        if kept is not None:
            pos, col, rad, vis = (np.concatenate([a, b]) for a, b in zip(kept,
                                                                         (pos, col, rad, vis)))
        self._cache = (len(self._pts), pos, col, rad, vis)
        placed = self.__dict__.get("_world_transform")     # points in a VPython 6 frame
        if placed is not None:
            pos = pos @ placed[1].T + placed[0]
        if vis.all():
            return pos, col, rad
        return pos[vis], col[vis], rad[vis]


def _column(name: str) -> property:
    """VPython 6's ``x``, ``y``, ``z`` (columns of ``pos``) and ``red``, ``green``, ``blue``
    (of ``color``), live views; in VPython 7 a program's own attribute, as before."""
    field, i = _COLUMNS[name]

    def read(self):
        if is_lenient():
            return self._array(field)[:, i]
        if name in self.__dict__:
            return self.__dict__[name]
        raise AttributeError(f"{type(self).__name__!r} object has no attribute {name!r}")

    def write(self, value) -> None:
        if is_lenient():
            self._set_column(name, value)
        else:
            self.__dict__[name] = value

    return property(read, write)


for _name in _COLUMNS:
    setattr(_PointList, _name, _column(_name))


class curve(_PointList):
    """A polyline; radius 0 draws a thin line, radius > 0 a tube.

    Its points are placed as GlowScript's curve shader places them
    (``shaders/curve_render_vertex.shader``): ``origin + R (size * p)``, where the
    columns of ``R`` are ``norm(axis)``, ``norm(up)`` and their cross product; by
    default (axis <1,0,0>, up <0,1,0>, size <1,1,1>) the points are where given.
    """

    _kind = "curve"

    def __init__(self, *args, **kwargs) -> None:
        self._axis, self._up, self._size = vector(1, 0, 0), vector(0, 1, 0), vector(1, 1, 1)
        for name in ("axis", "up", "size"):
            if name in kwargs:
                object.__setattr__(self, "_" + name, _vec(kwargs.pop(name), name))
        super().__init__(*args, **kwargs)
        for v in (self._axis, self._up, self._size):
            v._on_change = self._touch

    origin = Linked(_vec, then="_touch", hook=True)
    axis = Linked(_vec, then="_touch", hook=True)
    up = Linked(_vec, then="_touch", hook=True)
    size = Linked(_vec, then="_touch", hook=True)

    def rotate(self, angle=None, axis=None, origin=None) -> None:
        """Turn the curve by ``angle`` about ``axis`` (default its own) through ``origin``
        (default its own ``origin``), as GlowScript's ``rotate``."""
        if angle is None:
            raise TypeError("object.rotate() requires an angle.")
        if angle == 0:
            return
        rotaxis = self._axis if axis is None else _vec(axis, "axis")
        centre = self._origin if origin is None else _vec(origin, "origin")
        self.origin = centre + (self._origin - centre).rotate(angle, rotaxis)
        self.axis = self._axis.rotate(angle, rotaxis)
        self.up = self._up.rotate(angle, rotaxis)

    def _placement(self) -> tuple[np.ndarray, np.ndarray] | None:
        """The rotation (columns X, Y, Z) and scale, or None when they change nothing."""
        if self._axis.equals(vector(1, 0, 0)) and self._up.equals(vector(0, 1, 0)) and \
                self._size.equals(vector(1, 1, 1)):
            return None
        X = np.array(self._axis.hat._xyz())
        Y = np.array(self._up.hat._xyz())
        Y = Y - X * (X @ Y)
        n = np.linalg.norm(Y)
        Y = Y / n if n > 0 else np.array([0.0, 1.0, 0.0])
        return np.column_stack([X, Y, np.cross(X, Y)]), np.array(self._size._xyz())

    def _arrays(self):
        pos, col, rad = super()._arrays()
        placed = self._placement()
        if placed is not None:
            R, scale = placed
            pos = (pos * scale) @ R.T
        return pos + self._origin.value, col, rad


class points(_PointList):
    """Round dots, drawn as lit balls (:mod:`..geometry.point_meshes`): ``radius`` in VPython's
    pixels unless ``size_units="world"``; radius 0 is 20 of those pixels across."""

    _kind = "points"
    _default_radius = 0.0

    @property
    def origin(self):
        raise AttributeError("points object does not have an origin")
