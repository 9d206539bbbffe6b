"""VPython's ``label``: text at a 3D point (or a pixel position), drawn flat on the screen.

Its attributes and defaults are GlowScript's (``label`` in ``lib/glow/primitives.js``);
:mod:`..text.label_layout` places it and :mod:`..draw.label_overlay` draws it over the frame as
GlowScript's 2D overlay does (:meth:`..draw.renderer.Renderer._sync_labels`).
"""

from __future__ import annotations

from .base import _Base
from .checks import _vec
from .vectors import vector


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
    space = property(lambda self: self._space, lambda self, v: self._set("_space", float(v)))
    linewidth = property(lambda self: self._linewidth,
                         lambda self, v: self._set("_linewidth", float(v)))

    def _set(self, attr: str, value) -> None:
        object.__setattr__(self, attr, value)
        self._dirty = True
