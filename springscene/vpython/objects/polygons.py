"""VPython 7's ``vertex``, ``triangle`` and ``quad``: surfaces a program builds point by point.

As ``vpython/vpython.py`` (``class vertex``, ``triangle``, ``quad(triangle)``)
and GlowScript's ``lib/glow/primitives.js``:

- a ``vertex`` has ``pos``, ``normal`` (default <0, 0, 1>: VPython does not
  compute one from the triangle), ``color``, ``opacity``, ``shininess`` (0.6),
  ``emissive``, ``texpos`` (z must be 0) and ``bumpaxis``; it is not drawn
  itself, and changing it (``v.pos.z = 1`` too) changes every triangle or quad
  that uses it in the next frame. ``v.rotate(angle, axis, origin)`` turns its
  pos about ``origin`` (default <0, 0, 0>) and its normal (GlowScript's);
- a ``triangle`` is ``triangle(v0=, v1=, v2=)`` or ``triangle(vs=[a, b, c])``, a
  ``quad`` the same with four vertices, drawn as the triangles (v0, v1, v2) and
  (v0, v2, v3) (WebGLRenderer.js ``add_indices``). Their attributes are the
  vertices, ``vs``, ``texture``, ``bumpmap``, ``visible`` and ``pickable``;
  ``pos``, ``color``, ``size``, ``axis``, ``up``, ``opacity``, ``shininess`` and
  ``emissive`` are GlowScript's "A triangle has no pos attribute." errors, and
  ``rotate`` is refused ("rotate the vertices instead").

Colours are blended between vertices, a texture is multiplied by them
(tri_render_vertex.shader: ``vcolor = color``; no place, flip or turn for
triangles) and placed by each vertex's ``texpos``; their meshes are
:func:`..geometry.object_meshes.polygon_arrays`.
"""

from __future__ import annotations

import numpy as np

from ..core.attributes import Linked
from .base import _Base, _current_canvas, component
from ..core.checks import _vec
from ..core.vectors import vector


def _texpos(value, name: str) -> vector:
    v = _vec(value, name)
    if v.z != 0:
        raise AttributeError("the z component of texpos must currently be zero")
    return v


class vertex:
    """A corner of triangles and quads: position, normal, colour, opacity, texture position."""

    def __init__(self, **args) -> None:
        object.__setattr__(self, "_users", [])
        cv = args.pop("canvas", None)
        self._canvas = cv if cv is not None else _current_canvas()
        self._pos = vector(0, 0, 0)
        self._normal = vector(0, 0, 1)
        self._color = vector(1, 1, 1)
        self._texpos = vector(0, 0, 0)
        self._bumpaxis = vector(1, 0, 0)
        self._opacity = 1.0
        self._shininess = 0.6
        self._emissive = False
        self._visible = True
        self._pickable = True
        for name in ("pos", "normal", "color", "texpos", "bumpaxis", "opacity", "shininess",
                     "emissive", "visible", "pickable", "red", "green", "blue"):
            if name in args:
                setattr(self, name, args.pop(name))
        for name in ("_pos", "_normal", "_color", "_texpos", "_bumpaxis"):
            getattr(self, name)._on_change = self._changed
        for name, value in args.items():      # the program's own attributes
            setattr(self, name, value)

    def _changed(self) -> None:
        for user in self._users:
            user._dirty = True

    pos = Linked(_vec, then="_changed", hook=True)
    normal = Linked(_vec, then="_changed", hook=True)
    color = Linked(_vec, then="_changed", hook=True)
    texpos = Linked(_texpos, then="_changed", hook=True)
    bumpaxis = Linked(_vec, then="_changed", hook=True)
    opacity = Linked(float, then="_changed")
    shininess = Linked(float, then="_changed")
    emissive = Linked(bool, then="_changed")
    visible = Linked(bool, then="_changed")
    pickable = Linked(bool, then="_changed")
    red, green, blue = component("color", 0), component("color", 1), component("color", 2)

    canvas = Linked(readonly=True)

    @property
    def triangleCount(self) -> int:     # noqa: N802 -- VPython's name
        return len(self._users)

    def rotate(self, angle=None, axis=None, origin=None) -> None:
        """Turn pos about ``origin`` (default <0, 0, 0>) and the normal, by ``angle`` about ``axis``."""
        if angle is None:
            raise TypeError("vertex.rotate() requires angle:...")
        if axis is None:
            raise TypeError("vertex.rotate() requires axis:...")
        axis = _vec(axis, "axis").norm()
        origin = vector(0, 0, 0) if origin is None else _vec(origin, "origin")
        self.pos = origin + (self._pos - origin).rotate(angle=angle, axis=axis)
        self.normal = self._normal.rotate(angle=angle, axis=axis)


def _check_vertex(value, shape: str, name: str) -> "vertex":
    if not isinstance(value, vertex):
        raise AttributeError(f"In a {shape}, {name} must be a vertex object.")
    return value


class triangle(_Base):
    """Three vertices, counter-clockwise seen from where their normals point."""

    _kind = "triangle"
    _names = ("v0", "v1", "v2")

    def __init__(self, **args) -> None:
        shape = type(self).__name__
        if "vs" in args:
            vs = list(args.pop("vs"))
            if len(vs) != len(self._names):
                raise AttributeError(f"A {shape} must specify {len(self._names)} vertex objects.")
            args.update(zip(self._names, vs))
        verts = [_check_vertex(args.pop(n, None), shape, n) for n in self._names]
        object.__setattr__(self, "_verts", verts)
        self._visible = bool(args.pop("visible", True))
        self._pickable = bool(args.pop("pickable", True))
        self._texture = args.pop("texture", None)
        self._bumpmap = args.pop("bumpmap", None)
        args.pop("canvas", None)                  # a triangle's canvas is its vertices'
        for v in verts:
            v._users.append(self)
        self._register({"canvas": verts[0].canvas})
        for name, value in args.items():        # the program's own attributes
            setattr(self, name, value)

    def _vertex_property(index: int):   # noqa: N805 -- a property factory used in the class body
        def get(self):
            return self._verts[index]

        def set_(self, value):
            self._replace(index, _check_vertex(value, type(self).__name__,
                                               self._names[index]))
        return property(get, set_)

    def _replace(self, index: int, value: vertex) -> None:
        old = self._verts[index]
        if self in old._users:
            old._users.remove(self)
        self._verts[index] = value
        value._users.append(self)
        self._dirty = True

    v0, v1, v2 = _vertex_property(0), _vertex_property(1), _vertex_property(2)

    @property
    def vs(self) -> list:
        return list(self._verts)

    @vs.setter
    def vs(self, value) -> None:
        value = list(value)
        if len(value) != len(self._names):
            raise AttributeError(f"A {type(self).__name__} must be a list of "
                                 f"{len(self._names)} vertex objects.")
        for i, v in enumerate(value):
            self._replace(i, _check_vertex(v, type(self).__name__, self._names[i]))

    texture = Linked(dirty=True)
    bumpmap = Linked(dirty=True)
    pickable = Linked(dirty=True)

    def _missing(name: str):   # noqa: N805 -- a property factory used in the class body
        def fail(self, *value):
            raise AttributeError(f"A {type(self).__name__} has no {name} attribute.")
        return property(fail, fail)

    pos, color, size = _missing("pos"), _missing("color"), _missing("size")
    axis, up, opacity = _missing("axis"), _missing("up"), _missing("opacity")
    shininess, emissive = _missing("shininess"), _missing("emissive")

    def rotate(self, *args, **kwargs) -> None:
        raise AttributeError(f"A {type(self).__name__} has no rotate method; "
                             "rotate the vertices instead.")

    def clone(self, **args):
        raise TypeError(f"Cannot clone a {type(self).__name__} object.")   # vpython.py

    def delete(self) -> None:
        for v in self._verts:
            if self in v._users:
                v._users.remove(self)
        super().delete()


class quad(triangle):
    """Four vertices, drawn as the triangles (v0, v1, v2) and (v0, v2, v3)."""

    _names = ("v0", "v1", "v2", "v3")
    v3 = triangle._vertex_property(3)


def look(obj) -> tuple[float, bool]:
    """(shininess, emissive) a triangle is drawn with: its vertices' mean and any."""
    return (float(np.mean([v._shininess for v in obj._verts])),
            any(v._emissive for v in obj._verts))


__all__ = ["vertex", "triangle", "quad", "look"]
