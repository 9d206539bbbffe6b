"""VPython's ``canvas`` (the ``scene``), its camera, its lights, and the ``color`` names.

A canvas holds its objects, lights and view settings with VPython 7's defaults
(``shared/vpython-reference.md``): 640 x 400, black, ambient 0.2, two distant
lights (:data:`springscene.view.scene.LIGHTS`, the lights springscene's own scene
has), center (0,0,0), forward (0,0,-1), fov pi/3, autoscale on. Setting
``range``, ``camera.pos`` or ``camera.axis`` turns autoscale off, as VPython does.

The lights (``distant_light``, ``local_light``) live here with the canvas: they are
the canvas's (``scene.lights``), not objects drawn on it, and every canvas is made
with its default two. The canvas knows which one is current
(:meth:`canvas.get_selected`), where objects made without ``canvas=`` go.

Interaction needs a user, and there is none: ``bind`` records nothing to call,
``waitfor``/``pause`` return at once, and each is noted on stderr by the runner.
"""

from __future__ import annotations

import colorsys
import math
import re

from ...errors import OutputError, UserError
from ...view.scene import LIGHTS
from . import runtime, widgets
from .attributes import Linked
from .checks import _vec
from .page_order import claim_slot
from .vectors import is_lenient, vector


MAX_SIDE = 8192    # pixels a side; VPython sets no limit (GlowScript hands any value to the
                   # page's <canvas> element, and WebGL clamps its drawing buffer to the GPU's)


class CanvasSizeError(ValueError):
    """A canvas width or height no picture can have; the runner reports it on one line
    at the program's line that set it."""


class CaptureError(CanvasSizeError):
    """A ``scene.capture`` that could not be written: one line at the program's line, as
    a canvas size (the runner reports both alike)."""


CAPTURE_BYTES = 241    # a capture's longest name, .png included: its temporary file
                       # ".NAME.XXXXXXXX.png" (outputs.atomic_path) must fit in 255 bytes


def capture_name(filename) -> str:
    """The file a capture goes to, as a browser saves VPython's download: the last part of
    the name (no folders), control characters (NUL, newlines) as ``_``, ``.png`` added, cut
    to :data:`CAPTURE_BYTES`. A name left empty or hidden (``""``, ``".x"``) is named after
    the output by the runner."""
    if not isinstance(filename, str):               # VPython's own error
        raise TypeError("'filename' for Capture must be a string.")
    name = filename.replace("\\", "/").rsplit("/", 1)[-1]
    name = "".join("_" if ord(c) < 32 or ord(c) == 127 else c for c in name)
    name = name.encode("utf-8", "replace").decode("utf-8")        # (a lone surrogate: ?)
    # ".png" added unless the name ends so, exactly (GlowScript's test: "a.PNG.png")
    stem, png = (name[:-4], ".png") if name.endswith(".png") else (name, ".png")
    room = CAPTURE_BYTES - len(png)
    return stem.encode("utf-8")[:room].decode("utf-8", "ignore") + png   # (whole characters)


def _shown(value) -> str:
    """``value`` quoted for a one-line message (escaped, and cut if long)."""
    text = repr(str(value))
    return text if len(text) <= 40 else text[:37] + "..."


def _side(cv: "canvas", name: str, value):
    """``value`` if it is a canvas side springscene can draw: 1 to :data:`MAX_SIDE` px (a
    number written as text, ``height="500"``, as the browser takes it)."""
    if isinstance(value, str):
        try:
            value = float(value)
        except ValueError:
            pass
    try:
        ok = math.isfinite(value) and 1 <= value < MAX_SIDE + 1
    except TypeError:
        ok = None
    if not ok:
        who = "scene" if canvas._all and canvas._all[0] is cv else "canvas"
        shown = repr(value) if len(repr(value)) <= 40 else repr(value)[:37] + "..."
        need = "a number of pixels" if ok is None else f"1 to {MAX_SIDE} pixels"
        raise CanvasSizeError(f"{who}.{name} = {shown}: a canvas {name} must be {need}")
    return value


def _direction(value, name: str) -> vector:
    """``value`` as a vector that can be a direction: not the zero vector."""
    value = _vec(value, name)
    if value.mag2 == 0:
        raise ValueError(f"{name} cannot be the zero vector")
    return value


class _Colors:
    """``color.red`` ... and ``color.gray(g)``, VPython's values."""

    # float literals: the components are shared constants, not three new floats a call
    red = property(lambda self: vector(1.0, 0.0, 0.0))
    green = property(lambda self: vector(0.0, 1.0, 0.0))
    blue = property(lambda self: vector(0.0, 0.0, 1.0))
    yellow = property(lambda self: vector(1.0, 1.0, 0.0))
    cyan = property(lambda self: vector(0.0, 1.0, 1.0))
    magenta = property(lambda self: vector(1.0, 0.0, 1.0))
    orange = property(lambda self: vector(1.0, 0.6, 0.0))
    purple = property(lambda self: vector(0.4, 0.2, 0.6))
    white = property(lambda self: vector(1.0, 1.0, 1.0))
    black = property(lambda self: vector(0.0, 0.0, 0.0))

    @staticmethod
    def gray(g: float) -> vector:
        return vector(g, g, g)

    grey = gray

    @staticmethod
    def hsv_to_rgb(v: vector) -> vector:
        return vector(*colorsys.hsv_to_rgb(v.x, v.y, v.z))

    @staticmethod
    def rgb_to_hsv(v: vector) -> vector:
        return vector(*colorsys.rgb_to_hsv(v.x, v.y, v.z))

    @staticmethod
    def rgb_to_grayscale(v: vector) -> vector:
        lum = 0.21 * v.x + 0.71 * v.y + 0.07 * v.z
        return vector(lum, lum, lum)


color = _Colors()


class _Anchor:
    """``scene.title_anchor`` / ``scene.caption_anchor``: where widgets go on the page."""

    def __init__(self, where: str) -> None:
        self._anchor = where


class _Camera:
    """``scene.camera``: ``pos`` and ``axis`` derived from center, forward and range."""

    def __init__(self, cv: "canvas") -> None:
        self._cv = cv

    @property
    def pos(self) -> vector:
        cv = self._cv
        return cv.center - cv.forward.norm() * cv._distance()

    @pos.setter
    def pos(self, value) -> None:
        cv = self._cv
        d = cv._distance()
        cv._autoscale = False
        cv._range = cv._range_now()
        cv._center = _vec(value, "camera.pos") + cv.forward.norm() * d

    @property
    def axis(self) -> vector:
        cv = self._cv
        return cv.forward.norm() * cv._distance()

    @axis.setter
    def axis(self, value) -> None:
        cv = self._cv
        value = _vec(value, "camera.axis")
        pos = self.pos
        cv._autoscale = False
        cv._forward = value.norm()
        d = value.mag
        cv._range = d * math.tan(cv.fov / 2) * (1 if cv.width >= cv.height
                                                 else cv.width / cv.height)
        cv._center = pos + value

    @property
    def up(self) -> vector:
        return self._cv.up

    @up.setter
    def up(self, value) -> None:
        self._cv.up = value

    def follow(self, obj) -> None:
        """Keep ``obj`` at the centre of the view (read each frame by the renderer)."""
        self._cv._follow = obj

    def rotate(self, angle: float, axis=None, origin=None) -> None:
        """Turn the camera where it stands (VPython: pos fixed, axis and up turn)."""
        cv = self._cv
        axis = cv.up if axis is None else _vec(axis, "axis")
        pos, view = self.pos, self.axis
        if origin is not None:
            origin = _vec(origin, "origin")
            pos = origin + (pos - origin).rotate(angle, axis)
        view = view.rotate(angle, axis)
        cv._autoscale = False
        cv._range = cv._range_now()
        cv._forward = view.norm()
        cv._up = cv.up.rotate(angle, axis)
        cv._center = pos + view


class _Mouse:
    """``scene.mouse`` with no user: the pointer rests at the centre, no buttons down."""

    def __init__(self, cv: "canvas") -> None:
        self._cv = cv
        self.alt = self.ctrl = self.shift = False
        self.pick = None

    @property
    def pos(self) -> vector:
        return vector(self._cv.center)

    @property
    def ray(self) -> vector:
        return self._cv.forward.norm()

    def project(self, normal=None, point=None, d=None):
        return vector(self._cv.center)

    # VPython 6's polling: nobody clicks, so a wait ends one frame later, counts stay 0
    clicked = events = 0

    def getclick(self) -> "_Event":
        widgets.skipped("scene.mouse.getclick(): returned after one frame")
        runtime.wait()
        return _Event(self._cv, "click")

    getevent = getclick

    def peekevent(self) -> None:
        return None


class _Keyboard:
    """VPython 6's ``scene.kb``: no keys are ever pressed."""

    keys = 0

    def __init__(self, cv: "canvas") -> None:
        self._cv = cv

    def getkey(self) -> str:
        widgets.skipped("scene.kb.getkey(): returned '' after one frame")
        runtime.wait()
        return ""


class _Event:
    """What ``waitfor`` returns: an event that no user made."""

    def __init__(self, cv: "canvas", kind: str) -> None:
        self.event = kind
        self.type = kind
        self.pos = vector(cv.center)
        self.canvas = cv
        self.which = None
        self.key = ""


class canvas:
    """A VPython canvas: objects, lights, title and caption, and how the camera sees them."""

    _all: list["canvas"] = []
    _selected: "canvas | None" = None

    def __init__(self, **args) -> None:
        self._objects: list = []
        self._listed: list = []             # listed in ``objects`` but not drawn themselves
        self.lights: list = []
        self._title = ""
        self._caption = ""
        self.width, self.height = 640, 400
        self._background = vector(0, 0, 0)
        self._foreground = vector(1, 1, 1)
        self._ambient = vector(0.2, 0.2, 0.2)
        self._center = vector(0, 0, 0)
        self._forward = vector(0, 0, -1)
        self._up = vector(0, 1, 0)
        self.fov = math.pi / 3
        self._range = None
        self._autoscale = True
        self._follow = None
        self._visible = True
        self.userzoom = self.userspin = self.userpan = True
        self.resizable = True
        self.align = "none"
        self.camera = _Camera(self)
        self.mouse = _Mouse(self)
        self.kb = _Keyboard(self)
        self.title_anchor = _Anchor("title")
        self.caption_anchor = _Anchor("caption")
        self._autoscaled_range = None       # the renderer's last autoscale result
        canvas._all.append(self)
        canvas._selected = self
        for direction, brightness in LIGHTS:
            distant_light(direction=vector(*direction),
                          color=vector(brightness, brightness, brightness), canvas=self)
        for name, value in args.items():
            if name in ("pixel_to_world", "objects"):
                raise AttributeError(f"canvas: {name} cannot be set")
            setattr(self, name, value)

    # -- registry ------------------------------------------------------------------------

    @classmethod
    def get_selected(cls) -> "canvas":
        if cls._selected is None:
            cls()
        return cls._selected

    def select(self) -> None:
        canvas._selected = self

    @classmethod
    def _reset(cls) -> None:
        cls._all = []
        cls._selected = None

    def _add(self, obj) -> None:
        self._objects.append(obj)
        claim_slot(self)          # VPython shows a canvas on the page at its first object

    def _remove(self, obj) -> None:
        if obj in self._objects:
            self._objects.remove(obj)
        if obj in self._listed:
            self._listed.remove(obj)

    def _list_only(self, obj) -> None:
        """List ``obj`` in ``objects`` though it draws nothing itself (an ``attach_trail``)."""
        self._listed.append(obj)

    @property
    def objects(self) -> list:
        """The visible objects, as VPython 7's ``scene.objects`` (``canvas.objects`` in
        vpython.py: the visible Python objects made on this canvas). A ``make_trail``
        trail is drawn in the browser and is no Python object there, so it is not listed
        (its curve here is marked ``_unlisted``); an ``attach_trail`` is listed itself,
        not the curves it draws."""
        drawn = [o for o in self._objects if o.visible and not getattr(o, "_unlisted", False)]
        return drawn + [o for o in self._listed if o.visible]

    def delete(self) -> None:
        self._visible = False

    visible = Linked(bool)

    # width and height are checked with the canvas (the message names scene or canvas)
    width = property(lambda self: self._width,
                     lambda self, v: setattr(self, "_width", _side(self, "width", v)))
    height = property(lambda self: self._height,
                      lambda self, v: setattr(self, "_height", _side(self, "height", v)))

    # -- page text -----------------------------------------------------------------------

    title = Linked(str)
    caption = Linked(str)

    def append_to_title(self, *args) -> None:
        self._title += "".join(str(a) for a in args)

    def append_to_caption(self, *args) -> None:
        self._caption += "".join(str(a) for a in args)

    # -- colours -------------------------------------------------------------------------

    background = Linked(_vec)
    foreground = Linked(_vec)
    ambient = Linked(_vec)

    # -- view ----------------------------------------------------------------------------

    center = Linked(_vec)
    up = Linked(_vec)
    forward = Linked(_direction)

    @property
    def autoscale(self) -> bool:
        return self._autoscale

    @autoscale.setter
    def autoscale(self, value) -> None:
        value = bool(value)
        if not value and self._autoscale:
            self._measure()
            self._range = self._range_now()       # freeze the range autoscale had reached
        self._autoscale = value

    @property
    def range(self) -> float:
        if self._autoscale and self._autoscaled_range is None:
            self._measure()
        r = self._range_now()
        return vector(r, r, r) if is_lenient() else r     # VPython 6 read it as a vector

    # Set by the runner: autoscale the canvas over the objects it has now (VPython computes
    # the range when autoscale is turned off or the range is read, not only at a render)
    _measurer = None

    def _measure(self) -> None:
        if canvas._measurer is not None and self._objects:
            canvas._measurer(self)

    @range.setter
    def range(self, value) -> None:
        if isinstance(value, (vector, tuple, list)):   # VPython 6 allowed a vector or a
            value = value[0]                           # tuple; the x counts
        value = float(value)
        if not value > 0:
            raise ValueError("range must be positive")
        self._range = value
        self._autoscale = False

    def _range_now(self) -> float:
        if self._autoscale or self._range is None:
            if self._autoscaled_range is not None:
                return self._autoscaled_range
            return self._range if self._range is not None else 10.0
        return self._range

    def _distance(self) -> float:
        d = self._range_now() / math.tan(self.fov / 2)
        return d if self.width >= self.height else d * self.height / self.width

    # -- things a user would do ----------------------------------------------------------

    def bind(self, events: str, fn=None, *args) -> None:
        widgets.skipped(f"scene.bind({events!r}, {getattr(fn, '__name__', fn)}): "
                        "no user events, never called")

    def unbind(self, events: str, fn=None) -> None:
        pass

    def waitfor(self, events: str, *args) -> _Event:
        """No user: the event comes one video frame later (so a loop of waits still ends)."""
        widgets.skipped(f"scene.waitfor({events!r}): returned after one frame")
        runtime.wait()
        return _Event(self, events.split()[0] if events.split() else events)

    def pause(self, *args) -> _Event:
        widgets.skipped("scene.pause(): returned after one frame")
        runtime.wait()
        return _Event(self, "click")

    def follow(self, obj) -> None:
        """Keep ``obj`` at the centre of the view (VPython's ``scene.follow``)."""
        self._follow = obj

    def capture(self, filename: str, *args) -> None:
        """Save the canvas as ``filename`` (.png added) beside the output, at this moment
        (:func:`capture_name`; a name captured again replaces the earlier picture). A
        capture that cannot be written is one line at the program's line."""
        name = capture_name(filename)
        try:
            runtime.capture(self, name)
        except OutputError:                 # no space: one line naming the file, already
            raise
        except (UserError, OSError) as exc:
            why = getattr(exc, "strerror", None) or str(exc)
            found = re.search(r"\(([^()]*)\)$", why)
            raise CaptureError(f"scene.capture({_shown(filename)}): cannot be written beside "
                               f"the output ({found[1] if found else why})") from None

    def pixel_to_world(self, pixels: float) -> float:
        return 2 * self._range_now() * pixels / min(self.width, self.height)


# -- lights ----------------------------------------------------------------------------

class _Light:
    """A light of a canvas (in its ``lights``, not among its objects)."""

    _kind = "light"

    def __init__(self, **args) -> None:
        self._color = _vec(args.pop("color", vector(1, 1, 1)), "color")
        self._visible = bool(args.pop("visible", True))
        self._read(args)
        cv = args.pop("canvas", None)
        self._canvas = cv if cv is not None else canvas.get_selected()
        self._dirty = True
        self._canvas.lights.append(self)
        for name, value in args.items():
            setattr(self, name, value)

    def _read(self, args: dict) -> None:
        raise NotImplementedError

    color = Linked(_vec)
    canvas = Linked(readonly="canvas cannot be modified")
    visible = Linked(bool, dirty=True)

    def delete(self) -> None:
        if self in self._canvas.lights:
            self._canvas.lights.remove(self)

    def _ipython_display_(self) -> None:   # VPython prints nothing for a light
        pass


class distant_light(_Light):
    """Light from a direction, fixed in the world (no fall-off)."""

    def _read(self, args: dict) -> None:
        self._direction = _vec(args.pop("direction", vector(0, 0, 1)), "direction")

    direction = Linked(_vec)


class local_light(_Light):
    """Light from a point in the scene."""

    def _read(self, args: dict) -> None:
        self._pos = _vec(args.pop("pos", vector(0, 0, 0)), "pos")

    pos = Linked(_vec)


def canvases() -> list[canvas]:
    """Every canvas a program has made since the last reset, the default ``scene`` first."""
    return list(canvas._all)
