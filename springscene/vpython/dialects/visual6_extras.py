"""VPython 6 names VPython 7 dropped: ``materials``, ``ghistogram`` and ``controls``.

- ``materials.*`` (``visual_common/materials.py``): a look for an object
  (``material=materials.wood``). Each is drawn with the texture VPython 7 gives the
  same look (``materials.earth`` → ``textures.earth``), or as plain colour where
  VPython 7 has none; ``emissive`` and ``unshaded`` glow (VPython 7's
  ``emissive=True``).
- ``ghistogram(bins=, accumulate=, average=, delta=, gdisplay=, color=)``
  (``visual_common/graph.py``): a histogram drawn as ``gvbars``; ``plot(data=...)``
  counts the data into the bins.
- ``controls(...)``: VPython 6's separate window of widgets. With no user its
  widgets never fire; it only holds them.
- positional arguments where VPython 6's constructors had them (:func:`positional`):
  3D ``text(pos, axis, up, height, color, ...)``, ``gcurve(dot, dot_color, size,
  shape)``, ``gdots(size, shape)``,
  ``gvbars(delta)``, ``ghbars(delta)``, ``controls(x, y, width, height, range, ...)``.
  ``shapes.*`` and ``paths.*`` take VPython 6's order of arguments (:class:`Outlines`).
  VPython 6's objects (``sphere``, ``curve``, ``label``, ``points`` ...) took keywords
  only (``py_renderable.__init__(self, **keywords)``), and so do these.
- ``color`` (``crayola``): VPython 6's colour functions take a tuple, a list or a
  vector and return a tuple (``visual_common/crayola.py``): ``gray(x)``,
  ``rgb_to_hsv``, ``hsv_to_rgb``, ``rgb_to_grayscale``.
"""

from __future__ import annotations

import colorsys
import inspect
from typing import Any

import numpy as np

from ..core import runtime, widgets
from ..core.canvases import color as _colors
from ..core.vectors import vector
from ..api.graphs import gvbars
from ..api.texturing import textures

# material → (texture name in VPython 7, or None; drawn emissive)
MATERIALS = {"unshaded": (None, True), "emissive": (None, True), "diffuse": (None, False),
             "plastic": (None, False), "rough": ("rough", False), "shiny": (None, False),
             "chrome": ("metal", False), "ice": (None, False), "glass": (None, False),
             "blazed": (None, False), "silver": ("metal", False), "wood": ("wood", False),
             "marble": ("stucco", False), "earth": ("earth", False),
             "BlueMarble": ("earth", False), "bricks": ("stones", False)}


class Material:
    """One of VPython 6's materials: a name, the texture that shows it, and glow."""

    def __init__(self, name: str) -> None:
        self.name = name
        self.texture, self.emissive = MATERIALS[name]
        # what ``texture=`` takes for it (VPython 7's texture of that name), or None
        self.texture_value = getattr(textures, self.texture) if self.texture else None

    def __repr__(self) -> str:
        return f"materials.{self.name}"


class _MaterialMaker(Material):
    """A name of ``materials`` springscene does not know: a plain look, and a function
    (``materials.texture(data=materials.loadTGA("wood"))``) that makes one."""

    def __call__(self, *args: Any, **kwargs: Any) -> Material:
        return Material("diffuse")


class _Materials:
    """``materials``: VPython 6's looks, by name."""

    def __init__(self) -> None:
        for name in MATERIALS:
            setattr(self, name, Material(name))

    def __getattr__(self, name: str) -> Material:     # texture(), loadTGA, show_mat_pos ...
        if name.startswith("__"):
            raise AttributeError(name)
        return _MaterialMaker("diffuse")


materials = _Materials()


class ghistogram:
    """VPython 6's histogram: counts of data in ``bins``, shown as vertical bars.

    Bin ``i`` counts data with ``bins[i] <= d < bins[i+1]``; the last bin counts
    ``d >= bins[-1]``; data below ``bins[0]`` are dropped. ``accumulate`` adds each
    plot's counts to the last ones; with ``average`` the sum is divided by the plots.
    """

    def __init__(self, bins=None, accumulate: bool = False, average: bool = False,
                 delta: float | None = None, gdisplay=None, color=None, **kwargs: Any) -> None:
        self.bins = np.asarray(bins if bins is not None else np.arange(0, 10), dtype=float)
        self.delta = float(delta if delta is not None else
                           (self.bins[1] - self.bins[0] if len(self.bins) > 1 else 1.0))
        self.accumulate, self.average = bool(accumulate), bool(average)
        self._counts = np.zeros(len(self.bins))
        self._plots = 0
        args = {"delta": 0.8 * self.delta, "graph": gdisplay or kwargs.pop("graph", None)}
        if color is not None:
            args["color"] = color
        self._bars = gvbars(**args)

    def plot(self, data=None, accumulate: bool | None = None, average: bool | None = None,
             color=None) -> None:
        acc = self.accumulate if accumulate is None else bool(accumulate)
        avg = self.average if average is None else bool(average)
        data = np.ravel(np.asarray(data if data is not None else [], dtype=float))
        index = np.searchsorted(self.bins, data, side="right") - 1
        counts = np.bincount(index[index >= 0], minlength=len(self.bins))[:len(self.bins)]
        if acc:
            self._counts = self._counts + counts
            self._plots += 1
            shown = self._counts / self._plots if avg else self._counts
        else:
            self._counts, self._plots, shown = counts.astype(float), 1, counts
        centres = self.bins + 0.5 * self.delta
        self._bars.data = [[float(x), float(y)] for x, y in zip(centres, shown)]
        if color is not None:
            self._bars.color = color


class controls:
    """VPython 6's controls window: holds its widgets, which no user ever works."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        args = _named("controls", CONTROLS_ARGS, args, kwargs)
        self.__dict__.update(args)
        self.display = None

    def select(self) -> None:
        pass

    def interact(self) -> None:
        """VPython 6 handled the mouse here; with no user, one video frame passes (so a
        ``while True: c.interact()`` loop ends with the video)."""
        widgets.skipped("controls.interact(): no user; each call lets one frame pass")
        runtime.wait()


def _v6_args(args: dict[str, Any]) -> dict[str, Any]:
    """VPython 6's control keywords as VPython 7's: ``action`` is the ``bind`` (called with
    no argument, never here); its place in the controls window (``pos``, ``axis``) is
    not kept."""
    action = args.pop("action", None)
    args["bind"] = action if action is not None else (lambda *a: None)
    for name in ("pos", "axis", "controls", "display"):
        args.pop(name, None)
    return args


def button(**args: Any) -> widgets.button:
    """VPython 6's ``button(pos=, width=, height=, text=, color=, action=)``."""
    return widgets.button(**_v6_args(args))


def slider(**args: Any) -> widgets.slider:
    """VPython 6's ``slider(pos=, axis=|length=, width=, min=, max=, value=, action=)``."""
    args = _v6_args(args)
    args.setdefault("min", 0)
    args.setdefault("max", 100)
    return widgets.slider(**args)


def toggle(**args: Any) -> widgets.checkbox:
    """VPython 6's ``toggle(text0=, text1=, value=, action=)``: ``value`` stays as made."""
    args = _v6_args(args)
    args.setdefault("value", 0)
    return widgets.checkbox(**args)


def menu(**args: Any) -> widgets.menu:
    """VPython 6's ``menu(text=)``, filled by ``m.items.append(("label", function))``."""
    args = _v6_args(args)
    args.setdefault("choices", [])
    m = widgets.menu(**args)
    m.items = []
    return m



def _rgb(T) -> tuple[float, float, float]:
    """VPython 6's colour argument: any sequence (tuple, list, vector, array), its first
    three numbers."""
    if isinstance(T, vector):
        return T.x, T.y, T.z
    r, g, b = (float(c) for c in list(T)[:3])
    return r, g, b


class Crayola(type(_colors)):
    """``color`` (``crayola``) in VPython 6: VPython 7's named colours, and functions that
    take a tuple (or a vector) and return a tuple, as ``visual_common/crayola.py``'s did."""

    @staticmethod
    def gray(luminance: float) -> tuple[float, float, float]:
        return (luminance, luminance, luminance)

    grey = gray

    @staticmethod
    def rgb_to_hsv(T) -> tuple[float, float, float]:
        return colorsys.rgb_to_hsv(*_rgb(T))

    @staticmethod
    def hsv_to_rgb(T) -> tuple[float, float, float]:
        return colorsys.hsv_to_rgb(*_rgb(T))

    @staticmethod
    def rgb_to_grayscale(T) -> tuple[float, float, float]:
        r, g, b = _rgb(T)
        luminance = 0.21 * r + 0.71 * g + 0.07 * b
        return (luminance, luminance, luminance)


crayola = Crayola()


# VPython 6's positional arguments, in order (visual_common/graph.py, controls.py,
# primitives.py; VPython 5's vis/ the same)
TEXT_ARGS = ("pos", "axis", "up", "height", "color", "x", "y", "z", "red", "green", "blue",
             "text", "font", "align", "visible", "twosided", "depth", "material", "spacing",
             "vertical_spacing")
CONTROLS_ARGS = ("x", "y", "width", "height", "range", "title", "foreground", "background")
SERIES_ARGS = {"gcurve": ("dot", "dot_color", "size", "shape"), "gdots": ("size", "shape"),
               "gvbars": ("delta",), "ghbars": ("delta",)}


def _named(what: str, names: tuple[str, ...], args: tuple, kwargs: dict) -> dict:
    """Positional arguments given their VPython 6 names, joined to the keywords."""
    if len(args) > len(names):
        raise TypeError(f"{what}() takes at most {len(names)} positional arguments "
                        f"({len(args)} given)")
    for name, value in zip(names, args):
        if name in kwargs:
            raise TypeError(f"{what}() got multiple values for argument {name!r}")
        kwargs[name] = value
    return kwargs


def positional(cls: type, names: tuple[str, ...], drop: tuple[str, ...] = ()) -> type:
    """``cls`` that also takes VPython 6's positional arguments ``names`` (in order), and
    accepts (and ignores) the keywords ``drop`` VPython 6 had and VPython 7 has not."""
    def __init__(self, *args: Any, **kwargs: Any) -> None:
        kwargs = _named(cls.__name__, names, args, kwargs)
        for name in drop:
            kwargs.pop(name, None)
        cls.__init__(self, **kwargs)
    return type(cls.__name__, (cls,), {"__init__": __init__, "__doc__": cls.__doc__,
                                       "__module__": __name__})



_SCALES = ("scale", "xscale", "yscale")
_LOOKS = ("roundness", "invert") + _SCALES
# VPython 6's order of arguments (visual_common/shapes.py), where VPython 7's differs
SHAPES_ARGS = {
    "rectangle": ("pos", "width", "height", "rotate", "thickness") + _LOOKS,
    "cross": ("pos", "width", "thickness", "rotate") + _LOOKS,
    "trapezoid": ("pos", "width", "height", "top", "rotate", "thickness") + _LOOKS,
    "circle": ("pos", "radius", "np") + _SCALES + ("thickness", "angle1", "angle2", "rotate"),
    "line": ("pos", "np", "rotate") + _SCALES + ("thickness", "start", "end", "path"),
    "arc": ("pos", "radius", "np", "rotate") + _SCALES + ("thickness", "angle1", "angle2",
                                                          "path"),
    "ellipse": ("pos", "width", "height", "np", "rotate", "thickness") + _SCALES +
               ("angle1", "angle2"),
    "ngon": ("pos", "np", "length", "radius", "rotate", "thickness") + _LOOKS,
    "triangle": ("pos", "length", "rotate", "roundness", "thickness", "invert") + _SCALES,
    "pentagon": ("pos", "length", "rotate", "roundness", "thickness", "invert") + _SCALES,
    "hexagon": ("pos", "length", "rotate", "roundness", "thickness", "invert") + _SCALES,
    "star": ("pos", "radius", "n", "iradius", "rotate", "thickness") + _LOOKS,
    "pointlist": ("pos", "rotate", "roundness", "invert") + _SCALES + ("path",),
    "gear": ("pos", "n", "radius", "phi", "addendum", "dedendum", "fradius", "rotate",
             "scale", "internal", "res", "bevel"),
    "rackGear": ("pos", "n", "radius", "phi", "addendum", "dedendum", "fradius", "rotate",
                 "scale", "length", "res", "bevel", "depth"),
}
# ... visual_common/paths.py
PATHS_ARGS = {
    "rectangle": ("pos", "width", "height", "rotate", "thickness") + _LOOKS + ("up",),
    "cross": ("pos", "width", "thickness", "rotate") + _LOOKS + ("up",),
    "trapezoid": ("pos", "width", "height", "top", "rotate", "thickness") + _LOOKS + ("up",),
    "circle": ("pos", "radius", "np", "thickness") + _SCALES + ("up",),
    "line": ("start", "end", "np"),
    "arc": ("pos", "radius", "np", "rotate", "angle1", "angle2", "thickness") + _SCALES +
           ("up",),
    "ellipse": ("pos", "width", "height", "np", "thickness") + _SCALES + ("up",),
    "ngon": ("pos", "np", "length", "radius", "rotate", "thickness") + _LOOKS + ("up",),
    "triangle": ("pos", "np", "length", "rotate", "thickness") + _LOOKS + ("up",),
    "pentagon": ("pos", "np", "length", "rotate", "thickness") + _LOOKS + ("up",),
    "hexagon": ("pos", "np", "length", "rotate", "thickness") + _LOOKS + ("up",),
    "star": ("pos", "radius", "n", "iradius", "rotate", "thickness") + _LOOKS + ("up",),
    "pointlist": ("pos", "rotate", "thickness") + _LOOKS + ("up",),
}
# VPython 6's names of VPython 7's shapes
SHAPE_NAMES = {"pointlist": "points", "rackGear": "rackgear"}


class Outlines:
    """VPython 6's ``shapes`` or ``paths``: each of VPython 7's functions, called with
    VPython 6's order of positional arguments (``shapes.ngon(pos, np, length)``,
    ``shapes.star(pos, radius, n)``), and VPython 6's names for two (``pointlist``,
    ``rackGear``). An argument given by position that VPython 7's function has no option
    for is dropped, as it made no difference VPython 7 keeps."""

    def __init__(self, outlines: Any, orders: dict[str, tuple[str, ...]],
                 names: dict[str, str] | None = None) -> None:
        names = {**{n: n for n in dir(outlines) if not n.startswith("_")}, **(names or {})}
        for name, own in names.items():
            made = getattr(outlines, own, None)
            if made is not None:
                setattr(self, name, _ordered(name, made, orders.get(name)))


def _ordered(name: str, made: Any, order: tuple[str, ...] | None) -> Any:
    """``made`` taking its positional arguments in ``order`` (VPython 6's)."""
    if order is None or not callable(made):
        return made
    taken = inspect.signature(made).parameters
    if any(p.kind is p.VAR_KEYWORD for p in taken.values()):
        taken = None

    def outline(*args: Any, **kwargs: Any):
        named = _named(name, order, args, {})
        if taken is not None:
            named = {k: v for k, v in named.items() if k in taken}
        return made(**named, **kwargs)
    outline.__name__ = name
    return outline
