"""VPython 6's 2D shapes and its ``extrusion``, on springscene's VPython 7 extrusion.

VPython 6 (``vis/shapes.py``, ``vis/primitives.py``; docs ``extrusion.html``,
``shapes.html``) made its shapes with the Polygon package (a binding of GPC), and
``from visual import *`` gave its ``Polygon``:

- :class:`Polygon` is a set of contours, each solid or a hole. ``a + b`` (or
  ``a | b``) is the union, ``a - b`` the difference, ``a & b`` the intersection and
  ``a ^ b`` the exclusive or, computed by shapely (GEOS); ``contour(i)``, ``len``,
  ``p[i]``, ``isHole(i)``, ``addContour``, ``scale``, ``shift``, ``rotate``,
  ``center``, ``boundingBox``, ``area`` and ``nPoints`` are the package's.
- ``shapes.*`` (:class:`PolygonShapes`) are VPython 7's figures returned as
  :class:`Polygon` (a figure with ``thickness`` is an outline and its hole);
  ``paths.*`` (:class:`PathFigures`) VPython 7's lists of points that also have
  VPython 6's ``pos`` and ``up``.
- ``extrusion(pos=path, shape=..., ...)``: the path is ``pos`` (VPython 7 calls it
  ``path``), a list of points, an N x 3 array, ``x=``/``y=``/``z=`` arrays, or a
  :class:`Polygon` (its first contour, counter-clockwise in the xz plane seen from
  above: ``(x, y)`` goes to ``(x, 0, -y)``, closed). The shape is a Polygon (holes
  drawn as holes), a list of 2D points (closed if it is not), a VPython 7 shape or a
  string (its letters). ``scale`` is a number, an ``(sx, sy)`` pair, or one of either
  per point; ``xscale``, ``yscale`` and ``twist`` one number or one per point
  (``twist[0]`` is ignored, ``initial_twist`` turns the first face); ``color`` one
  colour or one per point; ``start``/``end`` show part of the path. A path of one
  point draws the shape as a flat face.

Its ``pos``, ``x``, ``y``, ``z``, ``color``, ``scale``, ``xscale``, ``yscale`` and
``twist`` read as numpy arrays, one row per path point, as VPython 6's did. Setting
one of them, ``shape``, ``initial_twist``, ``start`` or ``end`` makes the surface
again before it is next drawn, in the place and size of the first (so
``E.yscale = 1.2`` each frame animates it); a change made inside an array in place
(``E.pos[3][0] = 1``) is drawn at the next such setting. What differs: a shape's open
contour is closed (VPython 6 drew an open one as a thin wall with no end faces).
"""

from __future__ import annotations

import math
from numbers import Real
from typing import Any, Callable, Iterable

import numpy as np
import shapely

from ..core.vectors import vector
from ..objects.extrusions import SWEEP_OPTIONS, extruded, signed_area
from ..objects.extrusions import extrusion as _extrusion
from ..objects.text3d import nest, text_groups


# -- Polygon ------------------------------------------------------------------------------------

def _contour(points) -> np.ndarray:
    """A contour as an (n, 2) float array, without a closing point equal to the first."""
    if isinstance(points, Polygon):
        points = points.contour(0)
    p = np.array([[float(q[0]), float(q[1])] for q in points], dtype=float).reshape(-1, 2)
    if len(p) > 1 and np.array_equal(p[0], p[-1]):
        p = p[:-1]
    return p


class Polygon:
    """The Polygon package's ``Polygon``: contours, each solid or a hole (see the module)."""

    def __init__(self, contour=None, hole: bool = False) -> None:
        self._contours: list[np.ndarray] = []
        self._holes: list[bool] = []
        if isinstance(contour, Polygon):
            self._contours = [c.copy() for c in contour._contours]
            self._holes = list(contour._holes)
        elif contour is not None:
            self.addContour(contour, hole)

    # -- what it holds
    def addContour(self, contour, hole: bool = False) -> None:
        c = _contour(contour)
        if len(c):
            self._contours.append(c)
            self._holes.append(bool(hole))

    def contour(self, i: int) -> list[tuple[float, float]]:
        """Contour ``i`` as a list of ``(x, y)`` (a new list: changing it changes nothing)."""
        return [(float(x), float(y)) for x, y in self._contours[i]]

    def __len__(self) -> int:
        return len(self._contours)

    def __getitem__(self, i: int) -> list[tuple[float, float]]:
        return self.contour(i)

    def __iter__(self):
        return (self.contour(i) for i in range(len(self)))

    def isHole(self, i: int | None = None):
        return self._holes[i] if i is not None else list(self._holes)

    def isSolid(self, i: int | None = None):
        return (not self._holes[i]) if i is not None else [not h for h in self._holes]

    def nPoints(self, i: int | None = None) -> int:
        return len(self._contours[i]) if i is not None else sum(map(len, self._contours))

    def area(self, i: int | None = None) -> float:
        if i is not None:
            return abs(signed_area(self._contours[i]))
        return sum(-abs(signed_area(c)) if h else abs(signed_area(c))
                   for c, h in zip(self._contours, self._holes))

    def boundingBox(self, i: int | None = None) -> tuple[float, float, float, float]:
        """``(xmin, xmax, ymin, ymax)``, the Polygon package's order."""
        if not self._contours:            # (a shape taken wholly away: none)
            raise ValueError("an empty Polygon has no bounding box")
        pts = self._contours[i] if i is not None else np.concatenate(self._contours)
        lo, hi = pts.min(axis=0), pts.max(axis=0)
        return float(lo[0]), float(hi[0]), float(lo[1]), float(hi[1])

    def center(self, i: int | None = None) -> tuple[float, float]:
        """The centre of the bounding box (what ``scale`` and ``rotate`` turn about)."""
        x0, x1, y0, y1 = self.boundingBox(i)
        return (x0 + x1) / 2, (y0 + y1) / 2

    def orientation(self, i: int | None = None):
        """1 for a counter-clockwise contour, -1 clockwise."""
        signs = [1 if signed_area(c) > 0 else -1 for c in self._contours]
        return signs[i] if i is not None else signs

    # -- changed in place, as the package's
    def shift(self, dx: float, dy: float) -> None:
        self._contours = [c + (float(dx), float(dy)) for c in self._contours]

    def scale(self, xs: float, ys: float, xc: float | None = None,
              yc: float | None = None) -> None:
        """Scaled about ``(xc, yc)``, by default the centre of the bounding box."""
        if not self._contours:
            return
        c = np.array(self.center() if xc is None or yc is None else (xc, yc), dtype=float)
        self._contours = [(p - c) * (float(xs), float(ys)) + c for p in self._contours]

    def rotate(self, angle: float, xc: float | None = None, yc: float | None = None) -> None:
        """Turned counter-clockwise by ``angle`` radians about ``(xc, yc)`` (default the centre)."""
        if not self._contours:
            return
        c = np.array(self.center() if xc is None or yc is None else (xc, yc), dtype=float)
        co, si = math.cos(angle), math.sin(angle)
        turn = np.array([[co, si], [-si, co]])
        self._contours = [(p - c) @ turn + c for p in self._contours]

    # -- arithmetic, by shapely
    def _geometry(self):
        """The region: the union of the solid contours less the union of the holes."""
        def region(contours: list):
            parts = [shapely.make_valid(shapely.Polygon(c)) for c in contours if len(c) > 2]
            return shapely.union_all(parts) if parts else shapely.Polygon()
        solid = region([c for c, h in zip(self._contours, self._holes) if not h])
        holes = [c for c, h in zip(self._contours, self._holes) if h]
        return solid.difference(region(holes)) if holes else solid

    @classmethod
    def _of(cls, geometry) -> Polygon:
        """A Polygon of a shapely region: each piece's outline, then its holes."""
        out = cls()
        for piece in getattr(geometry, "geoms", [geometry]):
            if piece.geom_type == "Polygon" and not piece.is_empty:
                out.addContour(np.asarray(piece.exterior.coords), False)
                for ring in piece.interiors:
                    out.addContour(np.asarray(ring.coords), True)
            elif hasattr(piece, "geoms"):
                for contour in cls._of(piece)._pairs():
                    out.addContour(*contour)
        return out

    def _pairs(self) -> Iterable[tuple[np.ndarray, bool]]:
        return zip(self._contours, self._holes)

    def _combine(self, other, how: str) -> Polygon:
        b = other if isinstance(other, Polygon) else as_polygon(other)
        return Polygon._of(getattr(self._geometry(), how)(b._geometry()))

    def __add__(self, other) -> Polygon:
        return self._combine(other, "union")

    __or__ = __add__

    def __radd__(self, other) -> Polygon:
        return as_polygon(other)._combine(self, "union")

    def __sub__(self, other) -> Polygon:
        return self._combine(other, "difference")

    def __rsub__(self, other) -> Polygon:
        return as_polygon(other)._combine(self, "difference")

    def __and__(self, other) -> Polygon:
        return self._combine(other, "intersection")

    def __xor__(self, other) -> Polygon:
        return self._combine(other, "symmetric_difference")

    def __repr__(self) -> str:
        kinds = ", ".join(f"{'hole' if h else 'solid'} of {len(c)}" for c, h in self._pairs())
        return f"Polygon({kinds})"

    # -- as springscene's extrusion takes a shape
    def groups(self) -> list:
        """The shape as groups ``[outline, hole, ...]``, each contour closed."""
        if not self._contours:
            raise AttributeError("An extrusion shape must have a contour.")
        if len(self._contours) == 1:
            groups = [[self._contours[0]]]
        else:
            groups = nest([c for c in self._contours])
        return [[np.vstack([c, c[:1]]) for c in g] for g in groups]


def _is_number(v) -> bool:
    return isinstance(v, Real)


def as_polygon(value) -> Polygon:
    """A Polygon of a shape VPython 7 makes: ``[[x, y], ...]``, ``[outline, hole, ...]``
    or ``[[outline, hole, ...], ...]`` (a shapes figure), or of one already."""
    if isinstance(value, Polygon):
        return value
    try:
        if _is_number(value[0][0]):
            groups = [[value]]
        elif _is_number(value[0][0][0]):
            groups = [value]
        else:
            groups = value
    except (TypeError, IndexError, KeyError):
        raise TypeError(f"not a shape: {value!r}") from None
    out = Polygon()
    for group in groups:
        for i, contour in enumerate(group):
            out.addContour(contour, hole=i > 0)
    return out


class Figures:
    """A figure library as VPython 6 gave it: each figure of ``outlines`` (VPython 7's
    ``shapes`` or ``paths``) made, then given as ``wrap`` makes it (``shapes.circle(...)``
    a :class:`Polygon`, ``paths.arc(...)`` a :class:`PathPoints`)."""

    def __init__(self, outlines: Any, wrap: Callable[[Any, dict], Any]) -> None:
        self._outlines, self._wrap = outlines, wrap

    def __getattr__(self, name: str):
        if name.startswith("_"):
            raise AttributeError(name)
        made = getattr(self._outlines, name)
        if not callable(made):
            return made

        def figure(*args: Any, **kwargs: Any):
            return self._wrap(made(*args, **kwargs), kwargs)
        figure.__name__ = name
        figure.__doc__ = getattr(made, "__doc__", None)
        return figure


class PathPoints(list):
    """A ``paths`` figure as VPython 6 made it, an object whose ``pos`` is its points and
    ``up`` its plane's normal; it is also the list of points VPython 7 gives."""

    def __init__(self, points: Iterable, up=(0, 1, 0)) -> None:
        super().__init__(points)
        self.up = up

    @property
    def pos(self) -> list:
        return list(self)


def PolygonShapes(outlines: Any) -> Figures:
    """``shapes`` as VPython 6 gave it: each figure a :class:`Polygon`."""
    return Figures(outlines, lambda made, kwargs: as_polygon(made))


def PathFigures(outlines: Any) -> Figures:
    """``paths`` as VPython 6 gave it: each figure a :class:`PathPoints` in its plane."""
    return Figures(outlines, lambda made, kwargs: PathPoints(made, kwargs.get("up", (0, 1, 0))))


# -- extrusion ----------------------------------------------------------------------------------

def _triple(p) -> list[float]:
    if isinstance(p, vector):
        return [p.x, p.y, p.z]
    q = [float(c) for c in p]
    if len(q) == 2:
        return q + [0.0]
    if len(q) != 3:
        raise AttributeError(f"An extrusion's pos point must have 2 or 3 numbers, not {p!r}.")
    return q


def _path_points(pos) -> np.ndarray:
    """VPython 6's ``pos``: one point, a list or array of points, or a Polygon (a loop in
    the xz plane, counter-clockwise seen from above)."""
    if pos is None:
        return np.zeros((1, 3))
    if isinstance(pos, Polygon):
        c = pos._contours[0]
        if signed_area(c) < 0:
            c = c[::-1]
        c = np.vstack([c, c[:1]])
        return np.column_stack([c[:, 0], np.zeros(len(c)), -c[:, 1]])
    if isinstance(pos, vector) or (len(pos) in (2, 3) and all(_is_number(v) for v in pos)):
        return np.array([_triple(pos)])
    return np.array([_triple(p) for p in pos], dtype=float).reshape(-1, 3)


def _components(points: np.ndarray, args: dict) -> np.ndarray:
    """``x=``, ``y=``, ``z=`` (a number or an array each) laid over ``pos``; one point
    of ``pos`` is repeated to the arrays' length."""
    given = {i: args.pop(k) for i, k in enumerate("xyz") if k in args}
    n = max([len(points)] + [len(np.atleast_1d(v)) for v in given.values()])
    if len(points) != n:
        points = np.resize(points, (n, 3)) if len(points) > 1 else np.repeat(points, n, axis=0)
    points = points.copy()
    for i, v in given.items():
        points[:, i] = np.resize(np.asarray(v, dtype=float), n)
    return points


def _shape_groups(shape) -> list:
    """VPython 6's four ways to give a shape, as springscene's groups."""
    if isinstance(shape, str):
        return text_groups(shape, 1.0, "center")
    if isinstance(shape, Polygon):
        return shape.groups()
    if len(shape) and isinstance(shape[0], vector):          # a paths figure
        return Polygon([(p.x, -p.z) for p in shape]).groups()
    return as_polygon(shape).groups()


def _per_point(value, n: int) -> np.ndarray:
    return np.resize(np.asarray(value, dtype=float), n)


def _scales(args: dict, n: int) -> tuple[np.ndarray, np.ndarray]:
    """(xscale, yscale) per point, from ``scale`` (a number, an (sx, sy) pair or one of
    either per point), then ``xscale`` and ``yscale``."""
    xs, ys = np.ones(n), np.ones(n)
    scale = args.pop("scale", None)
    if scale is not None:
        s = np.asarray(scale, dtype=float)
        if s.ndim == 1 and len(s) == 2:                  # one (sx, sy) for every point
            xs, ys = np.full(n, s[0]), np.full(n, s[1])
        elif s.ndim == 2:                                # an (sx, sy) per point
            xs, ys = _per_point(s[:, 0], n), _per_point(s[:, 1], n)
        else:                                            # a number, or one per point
            xs = ys = _per_point(s, n)
    xscale, yscale = args.pop("xscale", None), args.pop("yscale", None)
    if xscale is not None:
        xs = _per_point(xscale, n)
    if yscale is not None:
        ys = _per_point(yscale, n)
    return xs, ys


def _twists(args: dict, n: int) -> np.ndarray:
    """Each point's twist from the one before (the first is ``initial_twist``)."""
    twist = args.pop("twist", 0.0)
    t = _per_point(twist, n).copy() if twist is not None else np.zeros(n)
    t[0] = float(args.pop("initial_twist", 0.0) or 0.0)
    return t


def _colours(value, n: int) -> np.ndarray:
    if value is None:
        return np.ones((n, 3))
    if isinstance(value, vector):
        return np.tile([value.x, value.y, value.z], (n, 1))
    c = np.asarray([_triple(v) for v in value] if not _is_number(value[0]) else value,
                   dtype=float)
    return np.tile(c, (n, 1)) if c.ndim == 1 else np.resize(c, (n, 3))


# VPython 6 names springscene's extrusion has no use for
_IGNORED = ("np", "retain", "twosided", "display", "red", "green", "blue", "material_pos")
# what a program reads (and may set) after the extrusion is made; setting one redraws it
_REDRAWN = ("pos", "x", "y", "z", "scale", "xscale", "yscale", "twist", "color", "shape",
            "initial_twist", "start", "end")


def _kept(key: str, column: int | None = None) -> property:
    """A VPython 6 extrusion's kept array ``key`` (or one ``column`` of it), read live; a
    write goes through the class's ``__setattr__``, which makes the surface again."""
    if column is None:
        return property(lambda self: self._v6[key])
    return property(lambda self: self._v6[key][:, column])


class extrusion(_extrusion):
    """VPython 6's ``extrusion(pos=path, shape=...)``: see the module."""

    # its arrays may be changed in place (``e.pos[1] = ...``): a recorder reads it in full
    _looks_counted = False

    def __init__(self, **args: Any) -> None:
        if args.get("shape") is None:
            raise AttributeError("An extrusion must have a shape.")
        if "path" in args and "pos" not in args:
            args["pos"] = args.pop("path")
        points = _components(_path_points(args.pop("pos", None)), args)
        n = len(points)
        xs, ys = _scales(args, n)
        v6 = {"pos": points, "scale": np.column_stack([xs, ys]), "twist": _twists(args, n),
              "color": _colours(args.pop("color", None), n), "shape": args.pop("shape"),
              "start": args.pop("start", 0), "end": args.pop("end", None),
              "sweep": {k: args.pop(k) for k in SWEEP_OPTIONS if k in args}}
        for name in _IGNORED:
            args.pop(name, None)
        object.__setattr__(self, "_v6", v6)
        first = self._sweep_args()
        super().__init__(**first, **args)
        self._first = (np.array(self._origin._xyz()), self._size0)

    def _sweep_args(self) -> dict:
        """springscene's extrusion arguments for the path and arrays as they are now."""
        v6 = self._v6
        end = v6["end"]
        shown = slice(v6["start"], None if end in (None, -1) else end + 1)
        path, scale, twist, colours = (v6[k][shown] for k in ("pos", "scale", "twist", "color"))
        if len(path) == 1:                      # one point: the shape as a flat face
            path = np.vstack([path, path - (0, 0, 1e-4)])
            scale, twist, colours = (np.concatenate([a, a]) for a in (scale, twist, colours))
        one = bool(np.all(colours == colours[0]))
        return {**v6["sweep"], "path": [vector(*p) for p in path],
                "shape": _shape_groups(v6["shape"]), "xscale": list(scale[:, 0]),
                "yscale": list(scale[:, 1]), "twist": list(twist),
                "color": vector(*colours[0]) if one else [vector(*c) for c in colours]}

    # changed since drawn: set so, or its arrays changed in place (then made again)
    def _arrays_sum(self) -> int | None:
        v6 = self.__dict__.get("_v6")
        if v6 is None:
            return None
        return hash(b"".join(np.ascontiguousarray(v6[k]).tobytes()
                             for k in ("pos", "scale", "twist", "color")))

    @property
    def _dirty(self) -> bool:
        if self._arrays_sum() != self.__dict__.get("_drawn_sum"):
            self.__dict__["_stale"] = True
            return True
        return self.__dict__.get("_changed", True)

    @_dirty.setter
    def _dirty(self, value: bool) -> None:
        self.__dict__["_changed"] = bool(value)
        if not value:
            self.__dict__["_drawn_sum"] = self._arrays_sum()

    # the surface, made again (in the first one's place and size) when it was changed
    @property
    def _mesh(self):
        if self.__dict__.get("_stale"):
            self.__dict__["_stale"] = False
            self._take(extruded(self._sweep_args()), *self._first)
        return self.__dict__["_made_mesh"]

    @_mesh.setter
    def _mesh(self, mesh) -> None:
        self.__dict__["_made_mesh"] = mesh

    # the per-point arrays (and the shape), as VPython 6 kept them: live, so a program may
    # change them in place (seen by :attr:`_dirty`'s checksum)
    pos, scale, twist, color, shape = (_kept(k) for k in ("pos", "scale", "twist", "color",
                                                            "shape"))
    x, y, z = _kept("pos", 0), _kept("pos", 1), _kept("pos", 2)
    xscale, yscale = _kept("scale", 0), _kept("scale", 1)

    def __setattr__(self, name: str, value) -> None:
        if "_v6" not in self.__dict__ or name.startswith("_"):
            object.__setattr__(self, name, value)
        elif name in _REDRAWN:
            self._store(name, value)
            self.__dict__["_stale"] = True
            self._touch()
        else:
            super().__setattr__(name, value)

    def _store(self, name: str, value) -> None:
        v6 = self._v6
        n = len(v6["pos"])
        if name in ("x", "y", "z"):
            v6["pos"][:, "xyz".index(name)] = np.resize(np.asarray(value, dtype=float), n)
        elif name in ("xscale", "yscale"):
            v6["scale"][:, 0 if name == "xscale" else 1] = _per_point(value, n)
        elif name == "scale":
            v6["scale"] = np.column_stack(_scales({"scale": value}, n))
        elif name == "pos":
            v6["pos"] = points = _path_points(value)
            m = len(points)
            v6["scale"], v6["color"] = np.resize(v6["scale"], (m, 2)), np.resize(v6["color"],
                                                                                 (m, 3))
            v6["twist"] = np.resize(v6["twist"], m)
        elif name == "twist":
            v6["twist"] = _twists({"twist": value, "initial_twist": v6["twist"][0]}, n)
        elif name == "initial_twist":
            v6["twist"][0] = float(value)
        elif name == "color":
            v6["color"] = _colours(value, n)
        else:                                   # shape, start, end
            v6[name] = value


__all__ = ["Polygon", "PolygonShapes", "PathPoints", "PathFigures", "as_polygon",
           "extrusion"]
