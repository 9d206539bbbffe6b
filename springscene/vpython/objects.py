"""VPython's 3D objects as plain Python data: what a program builds and moves.

Each object keeps VPython 7's attributes and their links (``vpython/vpython.py``,
``standardAttributes``): ``axis`` and ``size.x`` are one length, ``up`` turns with
``axis``, ``radius``/``length``/``height``/``width`` are views of ``size``. Any
other keyword or attribute is the program's own (``ball.p = ...``).

Nothing here draws. An object only marks itself changed (``_dirty``); the renderer
(:mod:`springscene.vpython.draw`) reads all objects of a kind once per frame.
"""

from __future__ import annotations

import math

from .vector import as_vector, vector

# VPython attributes springscene does not draw: refused with a message naming them
UNSUPPORTED = {"texture": "textures", "bumpmap": "bump maps", "frame": "frames",
               "material": "materials"}


class UnsupportedError(AttributeError):
    """A real VPython feature springscene does not reproduce."""


def unsupported(what: str) -> UnsupportedError:
    return UnsupportedError(f"{what} is not supported by springscene's vpython "
                            f"(it runs without a browser)")


def _vec(value, name: str) -> vector:
    """A fresh copy of ``value`` as a vector; VPython's error if it is not one."""
    if isinstance(value, vector):
        return vector(value)
    try:
        return as_vector(value, name)
    except TypeError:
        raise TypeError(f"{name} must be a vector") from None


def _current_canvas():
    from .canvas import canvas
    return canvas.get_selected()


class _Base:
    """What every drawable object shares: its canvas, visibility and change flag."""

    _kind = "object"

    def _register(self, args: dict) -> None:
        cv = args.pop("canvas", None)
        self._canvas = cv if cv is not None else _current_canvas()
        self._dirty = True
        self._canvas._add(self)

    def _touch(self) -> None:
        self._dirty = True

    @property
    def canvas(self):
        return self._canvas

    @canvas.setter
    def canvas(self, value) -> None:
        raise AttributeError("canvas cannot be modified")

    @property
    def visible(self) -> bool:
        return self._visible

    @visible.setter
    def visible(self, value) -> None:
        self._visible = bool(value)
        self._dirty = True

    def delete(self) -> None:
        """Remove the object from its canvas, as VPython's ``obj.delete()`` does."""
        self._visible = False
        self._canvas._remove(self)

    def _ipython_display_(self) -> None:   # VPython prints nothing for an object
        pass


class standard(_Base):
    """VPython's ``standardAttributes``: pos, axis, up, size, color, opacity, trails."""

    _default_size = (1.0, 1.0, 1.0)
    _axis_sets_size = True          # sphere and ring keep their size when axis changes

    def __init__(self, **args) -> None:
        object.__setattr__(self, "_constructing", True)
        self._pos = vector(0, 0, 0)
        self._axis = vector(1, 0, 0)
        self._up = vector(0, 1, 0)
        self._size = vector(*self._default_size)
        self._color = vector(1, 1, 1)
        self._trail_color = None
        self._opacity = 1.0
        self._shininess = 0.6
        self._emissive = False
        self._visible = True
        self._make_trail = False
        self._trail_type = "curve"
        self._trail_radius = None
        self._interval = 0
        self._retain = -1
        self._pps = 0
        self._trail = None
        self._pos_sets = 0
        self._oldaxis = None
        self._adjustupaxis = True
        self._pickable = True
        for name in UNSUPPORTED:
            if name in args:
                raise unsupported(f"{self._kind}.{name} ({UNSUPPORTED[name]})")
        # VPython's order: plain vectors, then axis/size, then scalars, then linked scalars
        for name in ("pos", "up", "color"):
            if name in args:
                setattr(self, "_" + name, _vec(args.pop(name), name))
        if "trail_color" in args:
            self._trail_color = _vec(args.pop("trail_color"), "trail_color")
        for name in ("axis", "size"):
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
        self._hook()
        self._register(args)
        for name, value in args.items():        # the program's own attributes
            setattr(self, name, value)
        self._constructing = False
        if self._make_trail:
            self._add_trail_point()

    def _hook(self) -> None:
        """Let in-place changes (``ball.pos.x = 1``) reach the object."""
        self._pos._on_change = self._on_pos_change
        self._axis._on_change = self._on_axis_change
        self._size._on_change = self._on_size_change
        self._up._on_change = self._touch
        self._color._on_change = self._touch

    # -- position, trail ------------------------------------------------------------------

    @property
    def pos(self) -> vector:
        return self._pos

    @pos.setter
    def pos(self, value) -> None:
        self._pos = _vec(value, "pos")
        self._pos._on_change = self._on_pos_change
        self._on_pos_change()

    def _on_pos_change(self) -> None:
        self._dirty = True
        if self._make_trail and not self._constructing:
            self._pos_sets += 1
            if self._interval <= 0 or self._pos_sets % self._interval == 0:
                self._add_trail_point()

    def _add_trail_point(self) -> None:
        from .curves import curve, points

        if self._trail is None:
            colour = self._trail_color if self._trail_color is not None else self._color
            if self._trail_type == "points":
                radius = self._trail_radius if self._trail_radius is not None \
                    else 0.1 * self._size.y
                self._trail = points(canvas=self._canvas, color=vector(colour), radius=radius,
                                     size_units="world", retain=self._retain)
            else:
                self._trail = curve(canvas=self._canvas, color=vector(colour),
                                    radius=self._trail_radius or 0, retain=self._retain)
        self._trail.append(vector(self._pos))

    def clear_trail(self) -> None:
        if self._trail is not None:
            self._trail.clear()

    @property
    def make_trail(self) -> bool:
        return self._make_trail

    @make_trail.setter
    def make_trail(self, value) -> None:
        value = bool(value)
        if not value:
            self._trail = None            # the drawn trail stays; a new one starts next time
        elif not self._make_trail and not self._constructing:
            self._make_trail = True
            self._add_trail_point()
        self._make_trail = value

    @property
    def trail_type(self) -> str:
        return self._trail_type

    @trail_type.setter
    def trail_type(self, value) -> None:
        if value not in ("curve", "points"):
            raise ValueError("trail_type must be 'curve' or 'points'")
        self._trail_type = value

    @property
    def trail_color(self) -> vector:
        return self._trail_color if self._trail_color is not None else self._color

    @trail_color.setter
    def trail_color(self, value) -> None:
        self._trail_color = _vec(value, "trail_color")
        if self._trail is not None:
            self._trail.color = self._trail_color

    @property
    def trail_radius(self) -> float:
        return self._trail_radius if self._trail_radius is not None else 0.1 * self._size.y

    @trail_radius.setter
    def trail_radius(self, value) -> None:
        self._trail_radius = float(value)

    interval = property(lambda self: self._interval,
                        lambda self, v: setattr(self, "_interval", int(v)))
    retain = property(lambda self: self._retain,
                      lambda self, v: setattr(self, "_retain", int(v)))
    pps = property(lambda self: self._pps, lambda self, v: setattr(self, "_pps", v))
    pickable = property(lambda self: self._pickable,
                        lambda self, v: setattr(self, "_pickable", bool(v)))

    # -- axis, up, size -------------------------------------------------------------------

    @property
    def axis(self) -> vector:
        return self._axis

    @axis.setter
    def axis(self, value) -> None:
        value = _vec(value, "axis")
        old = self._axis
        self._axis = value
        value._on_change = self._on_axis_change
        if self._axis_sets_size:
            m = value.mag
            if abs(self._size.x - m) > 0.0001 * self._size.x:
                self._size._x_set(m)
        if self._adjustupaxis:
            self._adjust_up(old, value)
        self._dirty = True

    def _on_axis_change(self) -> None:
        if self._axis_sets_size:
            self._size._x_set(self._axis.mag)
        self._dirty = True

    def _adjust_up(self, old: vector, new: vector) -> None:
        """VPython's ``adjust_up``: turn ``up`` with the axis unless they are already square."""
        if abs(new.x) + abs(new.y) + abs(new.z) == 0:
            if self._oldaxis is None:
                self._oldaxis = old
            return
        if self._oldaxis is not None:
            old, self._oldaxis = self._oldaxis, None
        if new.dot(self._up) == 0:
            return
        angle = old.diff_angle(new)
        if angle > 1e-6:
            if abs(angle - math.pi) < 1e-6:
                up = -self._up
            else:
                up = self._up.rotate(angle=angle, axis=old.cross(new))
            up._on_change = self._touch
            self._up = up

    @property
    def up(self) -> vector:
        return self._up

    @up.setter
    def up(self, value) -> None:
        value = _vec(value, "up")
        old = self._up
        value._on_change = self._touch
        self._up = value
        if self._adjustupaxis:
            self._adjust_axis(old, value)
        self._dirty = True

    def _adjust_axis(self, old: vector, new: vector) -> None:
        """VPython's ``adjust_axis``: turn ``axis`` with ``up`` unless they are already square."""
        if new.mag2 == 0 or old.mag2 == 0 or new.dot(self._axis) == 0:
            return
        angle = old.diff_angle(new)
        if angle > 1e-6:
            if abs(angle - math.pi) < 1e-6:
                axis = -self._axis
            else:
                axis = self._axis.rotate(angle=angle, axis=old.cross(new))
            axis._on_change = self._on_axis_change
            self._axis = axis

    @property
    def size(self) -> vector:
        return self._size

    @size.setter
    def size(self, value) -> None:
        value = _vec(value, "size")
        self._size = value
        value._on_change = self._on_size_change
        if self._axis_sets_size:
            self._fit_axis()
        self._dirty = True

    def _on_size_change(self) -> None:
        if self._axis_sets_size:
            self._fit_axis()
        self._dirty = True

    def _fit_axis(self) -> None:
        """``mag(axis) = size.x`` keeping the axis's direction (VPython's size setter)."""
        m = self._axis.mag
        a = self._axis.norm() * self._size.x if m else vector(self._size.x, 0, 0)
        if not a.equals(self._axis):
            a._on_change = self._on_axis_change
            self._axis = a

    @property
    def length(self) -> float:
        return self._size.x

    @length.setter
    def length(self, value) -> None:
        self._size._x_set(float(value))
        self._fit_axis()
        self._dirty = True

    @property
    def height(self) -> float:
        return self._size.y

    @height.setter
    def height(self, value) -> None:
        self._size._y_set(float(value))
        self._dirty = True

    @property
    def width(self) -> float:
        return self._size.z

    @width.setter
    def width(self, value) -> None:
        self._size._z_set(float(value))
        self._dirty = True

    # -- appearance ----------------------------------------------------------------------

    @property
    def color(self) -> vector:
        return self._color

    @color.setter
    def color(self, value) -> None:
        self._color = _vec(value, "color")
        self._color._on_change = self._touch
        self._dirty = True

    red = property(lambda self: self._color.x,
                   lambda self, v: setattr(self, "color", vector(v, self._color.y, self._color.z)))
    green = property(lambda self: self._color.y,
                     lambda self, v: setattr(self, "color", vector(self._color.x, v, self._color.z)))
    blue = property(lambda self: self._color.z,
                    lambda self, v: setattr(self, "color", vector(self._color.x, self._color.y, v)))

    def _scalar(name: str, kind=float):   # noqa: N805 -- a property factory used in the class body
        attr = "_" + name

        def get(self):
            return getattr(self, attr)

        def set_(self, value):
            object.__setattr__(self, attr, kind(value))
            self._dirty = True
        return property(get, set_)

    opacity = _scalar("opacity")
    shininess = _scalar("shininess")
    emissive = _scalar("emissive", bool)

    def __setattr__(self, name: str, value) -> None:
        if name in UNSUPPORTED:
            raise unsupported(f"{self._kind}.{name} ({UNSUPPORTED[name]})")
        object.__setattr__(self, name, value)

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
                "canvas": self._canvas}

    def clone(self, **args):
        """A copy of the object (VPython copies the drawn attributes, not the program's own)."""
        new = self._clone_args()
        new.update(args)
        return type(self)(**new)


class box(standard):
    _kind = "box"


class pyramid(standard):
    _kind = "pyramid"


class _Round(standard):
    """Objects whose ``radius`` is half of size.y (and size.z)."""

    @property
    def radius(self) -> float:
        return self._size.y / 2

    @radius.setter
    def radius(self, value) -> None:
        d = 2 * float(value)
        self.size = vector(self._size.x, d, d)


class sphere(_Round):
    _kind = "sphere"
    _default_size = (2.0, 2.0, 2.0)
    _axis_sets_size = False

    @_Round.radius.setter
    def radius(self, value) -> None:
        d = 2 * float(value)
        self.size = vector(d, d, d)


class simple_sphere(sphere):
    _kind = "sphere"


class ellipsoid(sphere):
    _kind = "sphere"     # drawn as a scaled sphere
    _default_size = (1.0, 1.0, 1.0)
    _axis_sets_size = True


class cylinder(_Round):
    _kind = "cylinder"
    _default_size = (1.0, 2.0, 2.0)


class cone(_Round):
    _kind = "cone"
    _default_size = (1.0, 2.0, 2.0)


class arrow(standard):
    """``shaftwidth``, ``headwidth``, ``headlength``: 0 means VPython's automatic value."""

    _kind = "arrow"
    _default_size = (1.0, 0.2, 0.2)

    def __init__(self, **args) -> None:
        self._shaftwidth = self._headwidth = self._headlength = 0.0
        self._round = False
        super().__init__(**args)

    shaftwidth = standard._scalar("shaftwidth")
    headwidth = standard._scalar("headwidth")
    headlength = standard._scalar("headlength")
    round = standard._scalar("round", bool)

    def _clone_args(self) -> dict:
        return {**super()._clone_args(), "shaftwidth": self._shaftwidth,
                "headwidth": self._headwidth, "headlength": self._headlength}


class helix(_Round):
    """A coil from ``pos`` along ``axis``: ``radius`` to the wire's centre line,
    ``thickness`` the wire's diameter (unset: radius/10), ``coils`` turns."""

    _kind = "helix"
    _default_size = (1.0, 2.0, 2.0)

    def __init__(self, **args) -> None:
        self._coils = 5.0
        self._thickness = None
        self._ccw = True
        super().__init__(**args)

    coils = standard._scalar("coils")
    ccw = standard._scalar("ccw", bool)

    @property
    def thickness(self) -> float:
        return self._thickness if self._thickness is not None else self.radius / 10

    @thickness.setter
    def thickness(self, value) -> None:
        self._thickness = float(value)
        self._dirty = True

    def _clone_args(self) -> dict:
        return {**super()._clone_args(), "coils": self._coils, "thickness": self.thickness,
                "ccw": self._ccw}


class ring(standard):
    """A torus centred on ``pos`` whose plane is square to ``axis``: ``radius`` to the
    tube's centre, ``thickness`` the tube's radius (VPython's size = (2t, 2(R+t), 2(R+t)))."""

    _kind = "ring"
    _default_size = (0.2, 2.2, 2.2)
    _axis_sets_size = False

    @property
    def thickness(self) -> float:
        return self._size.x / 2

    @thickness.setter
    def thickness(self, value) -> None:
        r = self.radius
        t = float(value)
        self._size = vector(2 * t, 2 * (r + t), 2 * (r + t))
        self._size._on_change = self._touch
        self._dirty = True

    @property
    def radius(self) -> float:
        return (self._size.y - self._size.x) / 2

    @radius.setter
    def radius(self, value) -> None:
        t = self.thickness
        r = float(value)
        self._size = vector(2 * t, 2 * (r + t), 2 * (r + t))
        self._size._on_change = self._touch
        self._dirty = True


class label(_Base):
    """Text at a 3D point, drawn flat on the screen: VPython's ``label``."""

    _kind = "label"

    def __init__(self, **args) -> None:
        object.__setattr__(self, "_constructing", True)
        for name in ("font",):
            pass
        self._pos = vector(0, 0, 0)
        self._text = ""
        self._xoffset = self._yoffset = 0.0
        self._height = 15.0
        self._color = None            # the canvas's foreground
        self._background = None       # the canvas's background
        self._opacity = 0.66
        self._box = True
        self._border = 5.0
        self._line = True
        self._linecolor = None
        self._align = "center"
        self._pixel_pos = False
        self._visible = True
        self._font = "sans"
        for name in ("pos", "color", "background", "linecolor"):
            if name in args:
                setattr(self, "_" + name, _vec(args.pop(name), name))
        for name in ("text", "xoffset", "yoffset", "height", "opacity", "box", "border", "line",
                     "align", "pixel_pos", "visible", "font", "space", "linewidth"):
            if name in args:
                setattr(self, name, args.pop(name))
        self._register(args)
        for name, value in args.items():
            setattr(self, name, value)
        self._constructing = False

    pos = property(lambda self: self._pos, lambda self, v: self._set("_pos", _vec(v, "pos")))
    color = property(lambda self: self._color if self._color is not None
                     else self._canvas.foreground,
                     lambda self, v: self._set("_color", _vec(v, "color")))
    background = property(lambda self: self._background if self._background is not None
                          else self._canvas.background,
                          lambda self, v: self._set("_background", _vec(v, "background")))
    linecolor = property(lambda self: self._linecolor if self._linecolor is not None
                         else self.color,
                         lambda self, v: self._set("_linecolor", _vec(v, "linecolor")))
    text = property(lambda self: self._text, lambda self, v: self._set("_text", str(v)))
    xoffset = property(lambda self: self._xoffset,
                       lambda self, v: self._set("_xoffset", float(v)))
    yoffset = property(lambda self: self._yoffset,
                       lambda self, v: self._set("_yoffset", float(v)))
    height = property(lambda self: self._height, lambda self, v: self._set("_height", float(v)))
    opacity = property(lambda self: self._opacity,
                       lambda self, v: self._set("_opacity", float(v)))
    box = property(lambda self: self._box, lambda self, v: self._set("_box", bool(v)))
    border = property(lambda self: self._border, lambda self, v: self._set("_border", float(v)))
    line = property(lambda self: self._line, lambda self, v: self._set("_line", bool(v)))
    align = property(lambda self: self._align, lambda self, v: self._set("_align", str(v)))
    pixel_pos = property(lambda self: self._pixel_pos,
                         lambda self, v: self._set("_pixel_pos", bool(v)))
    font = property(lambda self: self._font, lambda self, v: self._set("_font", str(v)))
    space = property(lambda self: 0.0, lambda self, v: None)
    linewidth = property(lambda self: 1.0, lambda self, v: None)

    def _set(self, attr: str, value) -> None:
        object.__setattr__(self, attr, value)
        self._dirty = True


class _Light(_Base):
    _kind = "light"

    def __init__(self, **args) -> None:
        self._color = _vec(args.pop("color", vector(1, 1, 1)), "color")
        self._visible = bool(args.pop("visible", True))
        self._read(args)
        cv = args.pop("canvas", None)
        self._canvas = cv if cv is not None else _current_canvas()
        self._dirty = True
        self._canvas.lights.append(self)
        for name, value in args.items():
            setattr(self, name, value)

    def _read(self, args: dict) -> None:
        raise NotImplementedError

    color = property(lambda self: self._color,
                     lambda self, v: setattr(self, "_color", _vec(v, "color")))

    def delete(self) -> None:
        if self in self._canvas.lights:
            self._canvas.lights.remove(self)


class distant_light(_Light):
    """Light from a direction, fixed in the world (no fall-off)."""

    def _read(self, args: dict) -> None:
        self._direction = _vec(args.pop("direction", vector(0, 0, 1)), "direction")

    direction = property(lambda self: self._direction,
                         lambda self, v: setattr(self, "_direction", _vec(v, "direction")))


class local_light(_Light):
    """Light from a point in the scene."""

    def _read(self, args: dict) -> None:
        self._pos = _vec(args.pop("pos", vector(0, 0, 0)), "pos")

    pos = property(lambda self: self._pos,
                   lambda self, v: setattr(self, "_pos", _vec(v, "pos")))


class compound(standard):
    """Objects fused into one, moved and turned as one (VPython's ``compound``).

    The parts' surfaces are taken once, in the world as they stand; the parts
    disappear. ``pos`` is the centre of their bounding box (or ``origin``), and
    ``size`` scales the whole from the size the parts had.
    """

    _kind = "compound"
    _axis_sets_size = False          # turning a compound does not resize it
    _INELIGIBLE = ("label", "curve", "points", "helix", "light")

    def __init__(self, objList, **args) -> None:
        import numpy as np

        from .draw import object_mesh

        objs = list(objList)
        if not objs:
            raise ValueError("compound needs a list of objects")
        for obj in objs:
            if getattr(obj, "_kind", None) in self._INELIGIBLE or obj.__class__.__name__ \
                    in self._INELIGIBLE:
                raise TypeError(f"A {type(obj).__name__} object cannot be used in a compound")
        parts = [object_mesh(o) for o in objs]
        points = np.concatenate([p[0] for p in parts])
        normals = np.concatenate([p[1] for p in parts])
        offsets = np.cumsum([0] + [len(p[0]) for p in parts])
        triangles = np.concatenate([p[2] + off for p, off in zip(parts, offsets)])
        rgb = np.concatenate([p[3] for p in parts])
        lo, hi = points.min(axis=0), points.max(axis=0)
        origin = args.pop("origin", None)
        centre = (lo + hi) / 2 if origin is None else np.array(_vec(origin, "origin")._xyz())
        size0 = np.maximum(hi - lo, 1e-12)
        from .shapes import Mesh

        unit_normals = normals * size0
        unit_normals /= np.linalg.norm(unit_normals, axis=1)[:, None]
        self._mesh = Mesh((points - centre) / size0, unit_normals, triangles)
        self._size0 = size0
        self._rgb0 = rgb.astype(float) / 255
        for obj in objs:
            obj.visible = False
        args.setdefault("pos", vector(*centre))
        size = args.pop("size", None)
        super().__init__(**args)
        self._size = vector(*(hi - lo))
        self._size._on_change = self._on_size_change
        self._fit_axis()
        if size is not None:
            self.size = size

    def _vertex_rgb(self):
        import numpy as np

        tint = np.array(self._color._xyz())
        return np.clip(np.rint(self._rgb0 * tint * 255), 0, 255).astype(np.uint8)

    def _clone_args(self) -> dict:
        raise NotImplementedError

    def clone(self, **args):
        """A copy of the compound, sharing its surface."""
        new = object.__new__(compound)
        new.__dict__.update({k: v for k, v in self.__dict__.items() if k.startswith("_")})
        for name in ("_pos", "_axis", "_up", "_size", "_color"):
            new.__dict__[name] = vector(self.__dict__[name])
        new._trail = None
        new._hook()
        new._register({"canvas": self._canvas})
        for name, value in args.items():
            setattr(new, name, value)
        return new

    def world_to_compound(self, v) -> vector:
        X, Y, Z = self._local_axes()
        d = _vec(v, "v") - self._pos
        return vector(d.dot(X), d.dot(Y), d.dot(Z))

    def compound_to_world(self, v) -> vector:
        X, Y, Z = self._local_axes()
        v = _vec(v, "v")
        return self._pos + X * v.x + Y * v.y + Z * v.z

    def _local_axes(self):
        X = self._axis.norm()
        Z = X.cross(self._up).norm()
        return X, Z.cross(X).norm(), Z
