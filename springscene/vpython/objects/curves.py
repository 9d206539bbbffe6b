"""VPython's ``curve`` and ``points``: lists of points, each with its own colour and radius.

As in ``vpython/vpython.py`` (``curveMethods``): points come as vectors, lists of
vectors or dictionaries ``{"pos": v, "color": c, "radius": r}``; ``append``,
``modify``, ``point``, ``slice``, ``splice``, ``pop``, ``shift``, ``unshift``,
``clear`` and ``npoints`` work on the list. ``retain`` keeps only the newest points
(trails use it). A curve of radius 0 is a thin lit tube whose width follows the range;
``points`` are lit balls of ``radius`` pixels (or world units with ``size_units="world"``),
both as :mod:`..geometry.point_meshes` draws them.
"""

from __future__ import annotations

import numpy as np

from ..core.attributes import Linked
from .base import _Base
from ..core.checks import _vec, one_of
from ..core.vectors import is_lenient, vector


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
                isinstance(c, (int, float)) and not isinstance(c, bool) for c in a):
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
        pos = kwargs.pop("pos", None)
        if pos is None and is_lenient() and any(c in kwargs for c in "xyz"):
            pos = _columns(kwargs)               # VPython 6: curve(x=arange(...), y=...)
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
        self._constructing = False

    # -- attributes ----------------------------------------------------------------------

    color = Linked(_vec, then="_touch", hook=True)
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
    def pos(self):
        raise AttributeError('object does not have a "pos" attribute')

    @pos.setter
    def pos(self, value) -> None:
        raise AttributeError("use object methods to change its shape")

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

    def _trim(self) -> None:
        if self._retain > 0 and len(self._pts) > self._retain:
            k = len(self._pts) - self._retain
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
        new = self._parse(args, kwargs)
        self._pts.extend(new)
        self._appended += len(new)
        self._trim()

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
