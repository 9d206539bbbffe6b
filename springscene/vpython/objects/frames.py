"""VPython 6's ``frame``: objects that move and turn together, in the frame's own coordinates.

An object made with ``frame=f`` keeps its ``pos``, ``axis`` and ``up`` in ``f``'s
coordinates (VPython 6.11, ``frame.cpp``): the frame's basis is ``X = norm(axis)``,
``Z = norm(axis × up)``, ``Y = Z × X`` (the length of ``axis`` does not count, there is
no scale), and a point ``p`` of the frame is at ``f.pos + p.x X + p.y Y + p.z Z`` in
its parent (frames nest). ``f.visible = False`` hides everything in it;
``f.rotate(angle=, axis=, origin=)`` turns it; ``f.objects``, ``frame_to_world`` and
``world_to_frame`` are VPython 6's.

Nothing here draws. The renderer asks :func:`hidden` whether an object's frames hide
it, and draws framed objects inside :func:`in_world`, which puts each one's world
``pos``/``axis``/``up`` (a curve's ``origin``) in place for the drawing and back after.
"""

from __future__ import annotations

from contextlib import contextmanager
from typing import Any, Iterable, Iterator

import numpy as np

from ..core.attributes import Linked
from ..core.checks import _vec
from ..core.vectors import vector


def _basis(axis: vector, up: vector) -> np.ndarray:
    """Columns X, Y, Z of a frame with this ``axis`` and ``up`` (VPython 6's rule when
    they are parallel: the side is ``axis × z``, or ``axis × -x`` near ±z)."""
    X = np.array(axis._xyz(), dtype=float)
    n = np.linalg.norm(X)
    X = X / n if n > 0 else np.array([1.0, 0.0, 0.0])
    Z = np.cross(X, np.array(up._xyz(), dtype=float))
    if np.linalg.norm(Z) < 1e-12:
        side = (0.0, 0.0, 1.0) if abs(X[2]) < 0.98 else (-1.0, 0.0, 0.0)
        Z = np.cross(X, side)
    Z = Z / np.linalg.norm(Z)
    return np.column_stack([X, np.cross(Z, X), Z])


class frame:
    """A group of objects placed in the frame's own coordinates (VPython 6)."""

    made = 0          # frames made in this process: none, and no object needs looking at

    def __init__(self, pos=None, axis=None, up=None, frame=None, visible: bool = True,
                 **args: Any) -> None:
        type(self).made += 1
        self._pos = vector(0, 0, 0) if pos is None else _vec(pos, "pos")
        self._axis = vector(1, 0, 0) if axis is None else _vec(axis, "axis")
        self._up = vector(0, 1, 0) if up is None else _vec(up, "up")
        self._visible = bool(visible)
        self._children: list = []
        self._frame = None
        args.pop("display", None)
        args.pop("canvas", None)
        if frame is not None:
            self.frame = frame
        for v in (self._pos, self._axis, self._up):
            v._on_change = self._touch
        self.__dict__.update(args)                 # the program's own attributes

    # -- where it is ---------------------------------------------------------------------

    pos = Linked(_vec, then="_touch", hook=True)
    axis = Linked(_vec, then="_touch", hook=True)
    up = Linked(_vec, then="_touch", hook=True)
    x = property(lambda self: self._pos.x, lambda self, v: setattr(self._pos, "x", v))
    y = property(lambda self: self._pos.y, lambda self, v: setattr(self._pos, "y", v))
    z = property(lambda self: self._pos.z, lambda self, v: setattr(self._pos, "z", v))

    visible = Linked(bool, then="_touch")

    @property
    def frame(self):
        return self._frame

    @frame.setter
    def frame(self, parent) -> None:
        node = parent
        while node is not None:
            if node is self:
                raise ValueError("a frame cannot be inside itself")
            node = node._frame
        if self._frame is not None and self in self._frame._children:
            self._frame._children.remove(self)
        self._frame = parent
        if parent is not None:
            parent._children.append(self)
        self._touch()

    @property
    def objects(self) -> list:
        """The visible objects directly in this frame."""
        return [c for c in self._children if getattr(c, "_visible", True)]

    def _touch(self) -> None:
        """Everything inside is drawn anew."""
        for child in self._children:
            if isinstance(child, frame):
                child._touch()
            else:
                child._dirty = True

    # -- transforms ----------------------------------------------------------------------

    def _placement(self) -> tuple[np.ndarray, np.ndarray]:
        """(origin, rotation) taking this frame's coordinates to the world's."""
        R = _basis(self._axis, self._up)
        o = np.array(self._pos._xyz(), dtype=float)
        if self._frame is None:
            return o, R
        po, PR = self._frame._placement()
        return po + PR @ o, PR @ R

    def frame_to_world(self, p) -> vector:
        o, R = self._placement()
        return vector(*(o + R @ np.array(_vec(p, "pos")._xyz())))

    def world_to_frame(self, p) -> vector:
        o, R = self._placement()
        return vector(*(R.T @ (np.array(_vec(p, "pos")._xyz()) - o)))

    def rotate(self, angle=None, axis=None, origin=None) -> None:
        """Turn the frame by ``angle`` about ``axis`` (default its own) through ``origin``
        (default its ``pos``), in its parent's coordinates."""
        if angle is None:
            raise TypeError("angle of rotation must be specified")
        rotaxis = self._axis if axis is None else _vec(axis, "axis")
        if origin is not None:
            origin = _vec(origin, "origin")
            self.pos = origin + (self._pos - origin).rotate(angle, rotaxis)
        self.axis = self._axis.rotate(angle, rotaxis)
        self.up = self._up.rotate(angle, rotaxis)


def hidden(obj) -> bool:
    """True when one of the frames holding ``obj`` is invisible."""
    node = getattr(obj, "_frame", None)
    while node is not None:
        if not node._visible:
            return True
        node = node._frame
    return False


_MOVED = ("_pos", "_axis", "_up", "_origin")


def _world(obj, o: np.ndarray, R: np.ndarray) -> dict:
    """The world values of ``obj``'s placed vectors (the ones it has)."""
    moved = {}
    for name in _MOVED:
        v = obj.__dict__.get(name)
        if v is None:
            continue
        local = np.array(v._xyz(), dtype=float)
        world = R @ local + (o if name in ("_pos", "_origin") else 0)
        moved[name] = vector(*world)
    if "_axis" in obj.__dict__ and "_up" not in obj.__dict__ and hasattr(obj, "_up"):
        moved["_up"] = vector(*(R @ np.array(obj._up._xyz())))
    return moved


def _world_points(obj, o: np.ndarray, R: np.ndarray) -> dict:
    """A ``points`` object has no origin: its point positions are placed as they are read."""
    return {"_world_transform": (o, R)}


@contextmanager
def in_world(objects: Iterable) -> Iterator[None]:
    """Within the block, every framed object's ``pos``/``axis``/``up`` (a curve's
    ``origin``) are the world's; after it, the program's own again."""
    saved = []
    for obj in objects:
        f = getattr(obj, "_frame", None)
        if f is None:
            continue
        o, R = f._placement()
        moved = _world_points(obj, o, R) if obj._kind == "points" else _world(obj, o, R)
        saved.append((obj, {name: obj.__dict__.get(name) for name in moved}))
        obj.__dict__.update(moved)
    try:
        yield
    finally:
        for obj, values in saved:
            obj.__dict__.update(values)
