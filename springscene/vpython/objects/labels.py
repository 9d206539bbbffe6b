"""VPython's ``label``: text at a 3D point (or a pixel position), drawn flat on the screen.

Its attributes and defaults are GlowScript's (``label`` in ``lib/glow/primitives.js``);
:mod:`..text.label_layout` places it and :mod:`..draw.label_overlay` draws it over the frame as
GlowScript's 2D overlay does (:meth:`..draw.renderer.Renderer._sync_labels`).
"""

from __future__ import annotations

from ..core.attributes import Linked
from .base import _Base
from ..core.checks import _vec
from ..core.vectors import vector


class label(_Base):
    """Text at a 3D point, drawn flat on the screen: VPython's ``label``."""

    _kind = "label"

    def __init__(self, **args) -> None:
        object.__setattr__(self, "_constructing", True)
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
        self._linewidth = 1.0
        self._space = 0.0
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

    pos = Linked(_vec, dirty=True)
    # the colours unset (None) are the canvas's
    color = Linked(_vec, dirty=True, get=lambda self: (
        self._color if self._color is not None else self._canvas.foreground))
    background = Linked(_vec, dirty=True, get=lambda self: (
        self._background if self._background is not None else self._canvas.background))
    linecolor = Linked(_vec, dirty=True, get=lambda self: (
        self._linecolor if self._linecolor is not None else self.color))
    text = Linked(str, dirty=True)
    xoffset = Linked(float, dirty=True)
    yoffset = Linked(float, dirty=True)
    height = Linked(float, dirty=True)
    opacity = Linked(float, dirty=True)
    box = Linked(bool, dirty=True)
    border = Linked(float, dirty=True)
    line = Linked(bool, dirty=True)
    align = Linked(str, dirty=True)
    pixel_pos = Linked(bool, dirty=True)
    font = Linked(str, dirty=True)
    space = Linked(float, dirty=True)
    linewidth = Linked(float, dirty=True)
