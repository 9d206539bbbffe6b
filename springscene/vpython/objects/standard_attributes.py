"""VPython's ``standardAttributes``: what every solid object has, as plain Python data.

:class:`standard` keeps VPython 7's attributes and their links
(``vpython/vpython.py``, ``standardAttributes``): ``axis`` and ``size.x`` are one
length, ``up`` turns with ``axis``, ``radius``/``length``/``height``/``width`` are
views of ``size``, and ``make_trail`` leaves a :mod:`.curves` trail behind ``pos``.
Any other keyword or attribute is the program's own (``ball.p = ...``).

The solids built on it (``sphere``, ``box``, ``helix``, ...) are in :mod:`.solids`,
``compound`` in :mod:`.compounds`, ``label`` in :mod:`.labels` and the lights with
the canvas (:mod:`..core.canvases`). Nothing here draws: an object only marks itself
changed (``_dirty``); the renderer (:mod:`springscene.vpython.draw.renderer`) reads all
objects of a kind once per frame. A change to anything but ``pos`` goes through
:meth:`_touch`, which also counts it (``_looks``): a recorder reads a moving object's
position every frame and the rest only when that count moved.
"""

from __future__ import annotations

import math

from ..core import runtime
from ..core.attributes import Linked
from .base import _Base, component
from ..core.checks import _vec, one_of
from . import trails
from .curves import curve, points
from .shared_defaults import Default, compact, default, seed_keys, stored
from ..core.vectors import is_lenient, vector


def _turned(other: vector, old: vector, new: vector) -> vector | None:
    """``other`` (an object's up or axis) turned as ``old`` turned into ``new``, VPython's
    rule for both ``adjust_up`` and ``adjust_axis``: None (left as it is) when ``other``
    is square to ``new`` or the turn is negligible; reversed for a half turn."""
    if new.dot(other) == 0:
        return None
    angle = old.diff_angle(new)
    if angle <= 1e-6:
        return None
    if abs(angle - math.pi) < 1e-6:
        return -other
    return other.rotate(angle=angle, axis=old.cross(new))

class _PosShortcut:
    """VPython 6's ``obj.x``/``.y``/``.z``: ``obj.pos.x``... in a VPython 6 program; in
    any other program a plain attribute of the program's own (VPython 7 has none)."""

    def __init__(self, component: str) -> None:
        self.component = component

    def __get__(self, obj, owner=None):
        if obj is None:
            return self
        if is_lenient():
            return getattr(obj._pos, self.component)
        try:
            return obj.__dict__[self.component]
        except KeyError:
            raise AttributeError(f"'{type(obj).__name__}' object has no attribute "
                                 f"'{self.component}'") from None

    def __set__(self, obj, value) -> None:
        if is_lenient():
            pos = vector(obj._pos)
            setattr(pos, self.component, value)
            obj.pos = pos
        else:
            obj.__dict__[self.component] = value


_BUILDING: set[int] = set()     # ids of the objects whose ``__init__`` is running
_ORIGIN, _X, _Y, _WHITE = default(0, 0, 0), default(1, 0, 0), default(0, 1, 0), default(1, 1, 1)


def _class_setup(cls) -> None:
    """The default vectors ``cls``'s objects start with, and its seeded key table."""
    cls._defaults = stored(cls, {"_pos": _ORIGIN, "_axis": _X, "_up": _Y,
                                 "_size": default(*cls._default_size), "_color": _WHITE})
    seed_keys(cls, cls._KEYS)


class standard(_Base):
    """VPython's ``standardAttributes``: pos, axis, up, size, color, opacity, trails.

    Memory (:mod:`.shared_defaults`): the scalars at VPython's default are the class's;
    the vectors at their default are read-only vectors shared by the class, copied by an
    object when it changes one in place (:meth:`_own`). A program reading ``ball.axis``
    gets the object's own vector, hooked (``_on_change``) then (:meth:`_live`)."""

    _default_size = (1.0, 1.0, 1.0)
    _axis_sets_size = True          # sphere and ring keep their size when axis changes
    _compact = False                # vectors shared with equal ones once made (:func:`compact`)
    # every change but the position counted in ``_looks`` (:meth:`_touch`): a recorder may
    # read the position alone while that count stands (False where that does not hold)
    _looks_counted = True

    # the defaults (vpython.py ``standardAttributes``), stored on an object once set
    _trail_color = None
    _opacity = 1.0
    _shininess = 0.6
    _emissive = False
    _visible = True
    _make_trail = False
    _trail_type = "curve"
    _trail_radius = None
    _interval = 0
    _retain = -1
    _pps = 0
    _trail = None
    _pos_sets = 0
    _pos_set = True          # pos given or set: a render may add it to the trail
    _trail_last = None       # the last point a render added to the trail
    _ninterval = 0           # changes of pos counted towards the next interval point
    _oldaxis = None
    _adjustupaxis = True
    _pickable = True
    # what an in-place change of each vector calls (a compound's colour: ``_retint``)
    _HOOKS = {"_pos": "_on_pos_change", "_axis": "_on_axis_change",
              "_size": "_on_size_change", "_up": "_touch", "_color": "_touch"}
    # what every object stores, first in its class's key table (:func:`.shared_defaults.seed_keys`)
    _KEYS = ("_pos", "_axis", "_up", "_size", "_color", "_canvas", "_dirty", "_looks")

    def __init_subclass__(cls, **kwargs) -> None:
        super().__init_subclass__(**kwargs)
        _class_setup(cls)

    @property
    def _constructing(self) -> bool:
        """True while the object's ``__init__`` runs (kept outside the object)."""
        return id(self) in _BUILDING

    def __init__(self, **args) -> None:
        pos_given = "pos" in args
        _BUILDING.add(id(self))
        try:
            self._setup(args)
        finally:
            _BUILDING.discard(id(self))
        if self._compact:
            compact(self)
        if self._make_trail:
            if is_lenient():        # VPython 6: the trail starts at the pos given
                if pos_given:
                    self._add_trail_point()
            else:
                trails.begin(self, pos_given)

    def _setup(self, args: dict) -> None:
        for name, v in self._defaults:
            object.__setattr__(self, name, v)
        # VPython's order: plain vectors, then axis, size, up, then scalars, then linked scalars
        for name in ("pos", "color"):
            if name in args:
                setattr(self, "_" + name, _vec(args.pop(name), name))
        if "trail_color" in args:
            self._trail_color = _vec(args.pop("trail_color"), "trail_color")
        # vpython.py ``standardAttributes.setup`` (attrLists: 'axis', 'size', 'up'): axis turns
        # the default up with it, then up turns the axis (adjust_axis), so up stays as given
        for name in ("axis", "size", "up"):
            if name in args:
                setattr(self, name, _vec(args.pop(name), name))
        for name in ("visible", "opacity", "shininess", "emissive", "make_trail", "trail_type",
                     "interval", "retain", "trail_radius", "pps", "pickable", "shaftwidth",
                     "headwidth", "headlength", "coils", "thickness", "round"):
            if name in args and hasattr(type(self), name):
                setattr(self, name, args.pop(name))
        for name in ("red", "green", "blue", "radius", "length", "height", "width"):
            if name in args and hasattr(type(self), name):
                setattr(self, name, args.pop(name))
        self._register(args)
        for name, value in args.items():        # the program's own attributes
            setattr(self, name, value)

    def _own(self, name: str) -> vector:
        """The object's own vector ``name``, copied from the class's default first, to be
        changed in place."""
        v = getattr(self, name)
        if type(v) is Default:
            v = vector(v)
            setattr(self, name, v)
        return v

    def _live(self, name: str) -> vector:
        """The vector ``name`` as a program gets it: the object's own, whose in-place
        changes (``ball.pos.x = 1``) reach the object."""
        v = self._own(name)
        if v._on_change is None:
            v._on_change = getattr(self, self._HOOKS[name])
        return v

    # -- position, trail ------------------------------------------------------------------

    # hooked when set, not on the next read: a moving object's pos is read again
    pos = Linked(_vec, then="_on_pos_change", hook=True, live=True)

    def _on_pos_change(self) -> None:
        self._dirty = True
        if not self._make_trail or self._constructing:
            return
        if not is_lenient():          # Web VPython, VPython 7: :mod:`.trails`
            trails.pos_changed(self)
        else:                         # VPython 6 (trail_update): changes 1, 1 + n, 1 + 2n...
            self._pos_sets += 1
            if (self._interval <= 0 or (self._pos_sets - 1) % self._interval == 0) \
                    and self._pps_allows():
                self._add_trail_point()

    def _pps_allows(self) -> bool:
        """``pps`` > 0: at most that many trail points a program second."""
        if not self._pps or self._pps <= 0 or runtime.current() is None:
            return True
        now = runtime.current().clock
        last = self.__dict__.get("_pps_last")
        if last is not None and now - last < 1 / self._pps:
            return False
        self.__dict__["_pps_last"] = now
        return True

    trail_object = Linked(readonly=True, store="_trail",
                          doc="VPython 6's name for the object's trail (a curve, or points).")

    def _add_trail_point(self) -> None:
        if self._trail is None:
            self._new_trail_piece()
        self._trail.append(vector(self._pos))

    def _new_trail_piece(self) -> None:
        """A new, empty piece of trail in the trail's colour as it is now."""
        colour = self._trail_color if self._trail_color is not None else self._color
        if self._trail_type == "points":
            radius = self._trail_radius if self._trail_radius is not None \
                else 0.1 * self._size.y
            self._trail = points(canvas=self._canvas, color=vector(colour), radius=radius,
                                 size_units="world", retain=self._retain, frame=self._frame)
        else:
            radius = 0 if is_lenient() else self._trail_radius or 0   # VPython 6: thin
            self._trail = curve(canvas=self._canvas, color=vector(colour), radius=radius,
                                retain=self._retain, frame=self._frame)
        self._trail._unlisted = not is_lenient()   # VPython 7 lists no make_trail curve

    def clear_trail(self) -> None:
        """Clear the trail, with its pieces from before a ``make_trail = False``: GlowScript
        stops the object's one ``attach_trail`` then, and ``clear_trail`` clears it all."""
        for piece in [*self.__dict__.get("_stopped_trails", ()), self._trail]:
            if piece is not None:
                piece.clear()
        trails.restarted(self)

    @property
    def make_trail(self) -> bool:
        return self._make_trail

    @make_trail.setter
    def make_trail(self, value) -> None:
        value = bool(value)
        if not value:
            if self._trail is not None:   # the drawn trail stays; a new one starts next time
                self.__dict__.setdefault("_stopped_trails", []).append(self._trail)
            self._trail = None
        elif not self._make_trail and not self._constructing:
            self._make_trail = True
            self._add_trail_point()      # a new piece, starting at the object
            if not is_lenient():
                self._pos_set = True
                trails.follow(self)
        self._make_trail = value

    def _retain_trail(self) -> None:
        """GlowScript's ``retain`` setter: the running trail keeps that many from its next point."""
        if self._trail is not None:
            self._trail.retain = self._retain

    def _recolour_trail(self) -> None:
        if self._trail is not None:
            if not is_lenient():        # GlowScript: the points made so far keep their colour
                trails.keep_colours(self._trail)
            self._trail.color = self._trail_color

    trail_type = Linked(one_of("curve", "points"))
    trail_color = Linked(_vec, then="_recolour_trail", get=lambda self: (
        self._trail_color if self._trail_color is not None else self.color))
    trail_radius = Linked(float, get=lambda self: (
        self._trail_radius if self._trail_radius is not None else 0.1 * self._size.y))
    interval = Linked(int)
    retain = Linked(int, then="_retain_trail")
    pps = Linked()
    pickable = Linked(bool)

    # -- axis, up, size: read as every vector is, each write linked to the others --------

    def _set_axis(self, value) -> None:
        value = _vec(value, "axis")
        old = self._axis
        self._axis = value
        if self._axis_sets_size:
            m = value.mag
            if abs(self._size.x - m) > 0.0001 * self._size.x:
                self._own("_size")._x_set(m)
        if self._adjustupaxis:
            self._adjust_up(old, value)
        self._touch()

    axis = Linked(live=True, set=_set_axis)

    def _on_axis_change(self) -> None:
        if self._axis_sets_size:
            self._own("_size")._x_set(self._axis.mag)
        self._touch()

    def _adjust_up(self, old: vector, new: vector) -> None:
        """VPython's ``adjust_up``: turn ``up`` with the axis unless they are already square."""
        if abs(new.x) + abs(new.y) + abs(new.z) == 0:
            if self._oldaxis is None:
                self._oldaxis = old
            return
        if self._oldaxis is not None:
            old, self._oldaxis = self._oldaxis, None
        up = _turned(self._up, old, new)
        if up is not None:
            self._up = up

    def _set_up(self, value) -> None:
        value = _vec(value, "up")
        old = self._up
        self._up = value
        if self._adjustupaxis:
            self._adjust_axis(old, value)
        self._touch()

    up = Linked(live=True, set=_set_up)

    def _adjust_axis(self, old: vector, new: vector) -> None:
        """VPython's ``adjust_axis``: turn ``axis`` with ``up`` unless they are already square."""
        if new.mag2 == 0 or old.mag2 == 0:
            return
        axis = _turned(self._axis, old, new)
        if axis is not None:
            self._axis = axis

    def _set_size(self, value) -> None:
        self._size = _vec(value, "size")
        if self._axis_sets_size:
            self._fit_axis()
        self._touch()

    size = Linked(live=True, set=_set_size)

    def _on_size_change(self) -> None:
        if self._axis_sets_size:
            self._fit_axis()
        self._touch()

    def _fit_axis(self) -> None:
        """``mag(axis) = size.x`` keeping the axis's direction (VPython's size setter)."""
        m = self._axis.mag
        a = self._axis.norm() * self._size.x if m else vector(self._size.x, 0, 0)
        if not a.equals(self._axis):
            self._axis = a

    @property
    def length(self) -> float:
        return self._size.x

    @length.setter
    def length(self, value) -> None:
        self._own("_size")._x_set(float(value))
        self._fit_axis()
        self._touch()

    @property
    def height(self) -> float:
        return self._size.y

    @height.setter
    def height(self, value) -> None:
        self._own("_size")._y_set(float(value))
        self._touch()

    @property
    def width(self) -> float:
        return self._size.z

    @width.setter
    def width(self, value) -> None:
        self._own("_size")._z_set(float(value))
        self._touch()

    # -- appearance ----------------------------------------------------------------------

    color = Linked(_vec, then="_touch", live=True)
    visible = Linked(bool, then="_touch")

    red, green, blue = component("color", 0), component("color", 1), component("color", 2)

    x, y, z = _PosShortcut("x"), _PosShortcut("y"), _PosShortcut("z")
    texture = bumpmap = None          # none until given (:mod:`..api.texturing` reads them)

    @property
    def material(self):
        """VPython 6's look (``materials.wood``): drawn with the texture VPython 7 has for
        it, or glowing for ``emissive``/``unshaded``."""
        return self.__dict__.get("_material")

    @material.setter
    def material(self, value) -> None:
        self.__dict__["_material"] = value
        if getattr(value, "texture_value", None) is not None:
            self.texture = value.texture_value
        if getattr(value, "emissive", False):
            self._emissive = True
        self._touch()

    opacity = Linked(float, then="_touch")
    shininess = Linked(float, then="_touch")
    emissive = Linked(bool, then="_touch")

    # -- motion --------------------------------------------------------------------------

    def rotate(self, angle=None, axis=None, origin=None) -> None:
        """Turn the object by ``angle`` about ``axis`` (default its own) through ``origin``."""
        if angle is None:
            raise TypeError("You must specify an angle through which to rotate")
        rotaxis = self._axis if axis is None else _vec(axis, "axis")
        if origin is not None:
            origin = _vec(origin, "origin")
            new_pos = origin + (self._pos - origin).rotate(angle, rotaxis)
            if not new_pos.equals(self._pos):
                self.pos = new_pos
        self._adjustupaxis = False       # axis and up turn together, rigidly
        try:
            self.axis = self._axis.rotate(angle=angle, axis=rotaxis)
            self.up = self._up.rotate(angle=angle, axis=rotaxis)
        finally:
            self._adjustupaxis = True

    def _clone_args(self) -> dict:
        return {"pos": self._pos, "color": self._color, "opacity": self._opacity,
                "size": self._size, "axis": self._axis, "up": self._up,
                "shininess": self._shininess, "emissive": self._emissive,
                "canvas": self._canvas, "texture": self.texture}

    def clone(self, **args):
        """A copy of the object (VPython copies the drawn attributes, not the program's own)."""
        new = self._clone_args()
        new.update(args)
        return type(self)(**new)


_class_setup(standard)
