"""VPython's ``attach_trail`` and ``attach_arrow``: things that follow an object at each render.

As in GlowScript (``lib/glow/WebGLRenderer.js``, the render loop; ``primitives.js``,
``attach_trail``/``attach_arrow``), they are updated when the scene is drawn, not
when the program changes the object: before each frame, :func:`update` moves every
attached arrow to its object's ``pos`` with ``axis = scale * obj.<attr>`` (hidden
while that is zero), and adds the object's position to every running trail when it
moved since the last point.

- ``attach_trail(obj or function, type='curve'|'points', radius=, color=, retain=,
  pps=)``: a thin curve (radius 0) or world-sized points (radius 0.1 × ``size.y``) in
  the object's colour; ``stop()``, ``start()`` (a new piece of trail) and ``clear()``.
- ``attach_arrow(obj, "attr", scale=1, color=obj.color, shaftwidth=0.5 × size.y,
  ...)``: an ``arrow``, with ``stop()`` and ``start()``;
- ``attach_light(obj, offset=, color=)``: a ``local_light`` kept at ``obj.pos + offset``.

As in VPython 7 (vpython.py: ``attach_trail`` is a ``standardAttributes`` object, and
``canvas.objects`` lists the visible Python objects), ``scene.objects`` lists an
``attach_trail`` itself, not the curves it draws (they are marked ``_unlisted``).
"""

from __future__ import annotations

from typing import Any

from ..core import runtime
from ..objects.base import _current_canvas
from ..objects import trails as make_trails
from ..objects.curves import curve, points
from ..objects.solids import arrow
from ..core.vectors import vector

_trails: list["attach_trail"] = []
_arrows: list[arrow] = []
_lights: list = []


class attach_trail:
    """A trail left by an object (or by the point a function returns) at each render."""

    def __init__(self, obj, type: str = "curve", radius: float | None = None,
                 color=None, retain: int = -1, pps: float = 0, canvas=None) -> None:
        if type == "spheres":
            type = "points"
        if type not in ("curve", "points"):
            raise ValueError("attach_trail type must be 'curve' or 'points' (or 'spheres')")
        self._obj = obj
        self.type = type
        is_object = not callable(obj)
        if radius is None:
            radius = 0.1 * obj.size.y if is_object and type == "points" else 0.0
        self.radius = float(radius)
        if color is None:
            color = obj.color if is_object else vector(1, 1, 1)
        self.color = vector(color)
        self.retain = retain
        self.pps = pps
        self.canvas = obj.canvas if is_object else (canvas or _current_canvas())
        self._last = None
        self._last_time = None
        self._run = True
        self._pieces: list = []
        self._new_piece()
        self.visible = True
        self.canvas._list_only(self)     # in scene.objects as itself, not its curves
        _trails.append(self)

    def _new_piece(self) -> None:
        options = {"canvas": self.canvas, "color": vector(self.color), "radius": self.radius,
                   "retain": self.retain, "pickable": False}
        if self.type == "points":
            options["size_units"] = "world"
        self._trail = (curve if self.type == "curve" else points)(**options)
        self._trail._unlisted = True
        self._pieces.append(self._trail)

    def _position(self):
        if callable(self._obj):
            return self._obj()
        obj = self._obj
        if not obj.visible or getattr(obj, "_interval", 0) > 0:
            return None
        return obj.pos

    def update(self) -> None:
        if not self._run:
            return
        pos = self._position()
        if pos is None or (self._last is not None and pos.equals(self._last)):
            return
        if self.pps and self.pps > 0 and runtime.current() is not None:   # points a second
            now = runtime.current().clock
            if self._last_time is not None and now - self._last_time < 1 / self.pps:
                return
            self._last_time = now
        self._trail.append(pos=vector(pos), color=vector(self.color), radius=self.radius)
        self._last = vector(pos)

    def stop(self) -> None:
        self._run = False

    def start(self) -> None:
        self._run = True
        self._new_piece()

    def clear(self) -> None:
        self._last = None
        for piece in self._pieces:
            piece.clear()

    def delete(self) -> None:
        """Stop, remove the trail's curves from the picture and the trail from the list."""
        self._run = False
        for piece in self._pieces:
            piece.delete()
        self.canvas._remove(self)
        if self in _trails:
            _trails.remove(self)


def attach_arrow(obj, attr: str, scale: float = 1.0, **options: Any) -> arrow:
    """An arrow from ``obj.pos`` along ``scale * obj.<attr>``, redrawn at each render."""
    value = getattr(obj, attr, None)
    if not isinstance(value, vector):
        raise AttributeError(f'The attach_arrow attribute "{attr}" must be a vector.')
    options.setdefault("color", obj.color)
    options.setdefault("shaftwidth", 0.5 * obj.size.y)
    options.setdefault("canvas", obj.canvas)
    options.setdefault("pickable", False)
    a = arrow(pos=vector(obj.pos), axis=value * scale, **options)
    a._attached = (obj, attr)
    a.scale = scale
    a._run = True
    a.stop = lambda: setattr(a, "_run", False)
    a.start = lambda: setattr(a, "_run", True)
    _arrows.append(a)
    return a


def _follow(a: arrow) -> None:
    obj, attr = a._attached
    value = getattr(obj, attr, None)
    a.pos = vector(obj.pos)
    if isinstance(value, vector) and value.mag > 0:
        if not a.visible:
            a.visible = True
        a.axis = value * a.scale
    else:
        a.visible = False


def attach_light(obj, make_light, offset=None, color=None, **options: Any):
    """A light made by ``make_light`` (a ``local_light``) kept at ``obj.pos + offset``,
    in the object's colour unless given (GlowScript's ``attach_light``)."""
    offset = vector(0, 0, 0) if offset is None else vector(offset)
    light = make_light(pos=obj.pos + offset, color=obj.color if color is None else color,
                       **options)
    light._attached = (obj, offset)
    _lights.append(light)
    return light


def update() -> None:
    """Bring every attached arrow, trail and light up to date (called at each render),
    and the trails of ``make_trail`` (:mod:`..objects.trails`)."""
    for a in _arrows:
        if a._run:
            _follow(a)
    for t in _trails:
        t.update()
    make_trails.at_render()
    for light in _lights:
        obj, offset = light._attached
        light.pos = obj.pos + offset


def reset() -> None:
    _trails.clear()
    make_trails.reset()
    _arrows.clear()
    _lights.clear()
