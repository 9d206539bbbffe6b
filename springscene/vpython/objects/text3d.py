"""VPython's 3D ``text``: glyph outlines extruded by ``depth``, made once as a compound.

As GlowScript's ``text3D`` (``lib/glow/extrude.js``) and ``text`` (``primitives.js``):

- The glyphs' outlines (here DejaVu Sans or DejaVu Serif, which matplotlib ships,
  for VPython's Roboto Medium and Nimbus Roman; curves cut into 8 straight pieces
  each) are scaled so that a lowercase ``h`` is ``height`` tall, and extruded from
  z = 0 to z = ``depth`` (default 0.2 x height; a depth under 1 % of the height is
  1 % of it). Walls are smooth across bends under 18 degrees.
- ``pos`` is on the first baseline: its left end for ``align='left'``, its middle
  for ``'center'``, its right end for ``'right'``, each line aligned by its own
  length; each next line is 1.5 x height lower. ``axis`` runs along the baseline
  and ``up`` up the letters.
- ``length`` is the width of the letters' bounding box; ``descender`` is, as
  VPython computes it, (height of ``h`` - height of ``y``'s top) per unit font
  size, times ``height``. ``length``, ``height`` and ``depth`` can be changed
  afterwards (the letters are stretched); ``text``, ``font``, ``align`` and the
  face colours cannot.
- The sides are ``color``, the faces ``start_face_color`` (at z = 0) and
  ``end_face_color``; as in GlowScript the whole is then tinted by ``color`` again.
- ``billboard=True`` keeps the text facing the camera: its axis is the camera's
  right and its up the camera's up (GlowScript's ``update_billboards``), read
  whenever the picture is drawn.
"""

from __future__ import annotations

import math
from functools import lru_cache

import numpy as np

from ..core.attributes import Linked
from .compounds import Surface, fused
from .extrusions import SMOOTH, Caps, Sweep, clean_contour, sweep
from ..core.vectors import vector

FONTS = {"sans": "DejaVu Sans", "serif": "DejaVu Serif"}
BEZIER_STEPS = 8           # straight pieces per curve (GlowScript's addBezier)
LINE_SPACING = 1.5         # baselines apart, in heights
_MOVETO, _LINETO, _CURVE3, _CURVE4, _CLOSEPOLY = 1, 2, 3, 4, 79


# -- glyph outlines ---------------------------------------------------------------------------

def _bezier(points: np.ndarray) -> np.ndarray:
    """The curve through control ``points`` (3 or 4) at t = 1/8 ... 1."""
    t = np.arange(1, BEZIER_STEPS + 1)[:, None] / BEZIER_STEPS
    if len(points) == 3:
        return ((1 - t) ** 2 * points[0] + 2 * (1 - t) * t * points[1] + t ** 2 * points[2])
    return ((1 - t) ** 3 * points[0] + 3 * (1 - t) ** 2 * t * points[1]
            + 3 * (1 - t) * t ** 2 * points[2] + t ** 3 * points[3])


@lru_cache(maxsize=256)
def outlines(line: str, font: str) -> tuple[tuple, float]:
    """The contours of a line of text in font units (1 em = 100), and its largest x.

    The largest x counts control points, as GlowScript's ``processOneLine``.
    """
    from matplotlib.font_manager import FontProperties  # noqa: PLC0415  heavy: matplotlib
    from matplotlib.path import Path  # noqa: PLC0415  heavy: matplotlib
    from matplotlib.textpath import text_to_path  # noqa: PLC0415  heavy: matplotlib

    verts, codes = text_to_path.get_text_path(FontProperties(family=FONTS[font]), line)
    contours, current, xmax = [], [], 0.0
    if len(codes):
        for seg, code in Path(np.asarray(verts, float), codes).iter_segments(
                curves=True, simplify=False):
            seg = seg.reshape(-1, 2)
            if code in (_MOVETO, _CLOSEPOLY) and len(current) > 2:
                contours.append(clean_contour(current))
            if code == _CLOSEPOLY:
                current = []
                continue
            xmax = max(xmax, float(seg[:, 0].max()))
            if code == _MOVETO:
                current = [seg[0]]
            elif code == _LINETO:
                current.append(seg[0])
            else:
                current.extend(_bezier(np.vstack([current[-1], seg])))
    if len(current) > 2:
        contours.append(clean_contour(current))
    return tuple(c for c in contours if len(c) > 2), xmax


@lru_cache(maxsize=4)
def font_heights(font: str) -> tuple[float, float]:
    """Top of ``h`` and top of ``y`` in font units: GlowScript's measure of a font's height."""
    h = max(float(c[:, 1].max()) for c in outlines("h", font)[0])
    y = max(float(c[:, 1].max()) for c in outlines("y", font)[0])
    return h, y


def _inside(point: np.ndarray, poly: np.ndarray) -> bool:
    """Even-odd test: is ``point`` inside the polygon ``poly``?"""
    x, y = point
    xi, yi = poly[:, 0], poly[:, 1]
    xj, yj = np.roll(xi, 1), np.roll(yi, 1)
    spans = (yi > y) != (yj > y)
    with np.errstate(divide="ignore", invalid="ignore"):
        cross = x < (xj - xi) * (y - yi) / (yj - yi) + xi
    return bool(np.count_nonzero(spans & cross) % 2)


def nest(contours) -> list:
    """Contours as groups ``[outline, hole, ...]``: a contour inside an odd number of
    others is a hole of the smallest one holding it."""
    lo = np.array([c.min(axis=0) for c in contours]).reshape(-1, 2)
    hi = np.array([c.max(axis=0) for c in contours]).reshape(-1, 2)
    area = np.prod(hi - lo, axis=1)
    # boxed[i, j]: contour i's box lies within contour j's (a cheap first test)
    boxed = (lo[:, None] >= lo[None]).all(-1) & (hi[:, None] <= hi[None]).all(-1)
    np.fill_diagonal(boxed, False)
    holders = [[j for j in np.flatnonzero(boxed[i]) if _inside(c[0], contours[j])]
               for i, c in enumerate(contours)]
    groups: dict[int, list] = {}
    for i in range(len(contours)):
        if len(holders[i]) % 2 == 0:
            groups[i] = [contours[i]]
    for i in range(len(contours)):
        if len(holders[i]) % 2 == 1:
            outers = [j for j in holders[i] if j in groups]
            if outers:
                groups[min(outers, key=lambda j: area[j])].append(contours[i])
    return list(groups.values())


# -- the letters as a surface -----------------------------------------------------------------

def _lines(text: str, font: str, height: float, align: str) -> tuple[list, float]:
    """Each line's groups, placed: scaled, aligned on its own length, 1.5 heights apart."""
    k = height / font_heights(font)[0]
    groups, longest = [], 0.0
    for i, line in enumerate(text.split("\n")):
        contours, xmax = outlines(line, font)
        length = k * xmax
        longest = max(longest, length)
        dx = {"right": -length, "center": -length / 2}.get(align, 0.0)
        shift = np.array([dx, -LINE_SPACING * height * i])
        groups += [[k * c + shift for c in g] for g in nest(contours)]
    return groups, longest


def text_groups(text: str, height: float = 1.0, align: str = "left",
                font: str = "sans") -> list:
    """The letters of ``text`` as shape groups ``[outline, hole, ...]`` (each contour
    closed), a lowercase ``h`` ``height`` tall, the first baseline at y = 0: a string
    given as an extrusion's shape (VPython 6)."""
    groups, _ = _lines(text, font, height, align)
    return [[np.vstack([c, c[:1]]) for c in g] for g in groups]


def letters(text: str, font: str, height: float, depth: float, align: str, colours: tuple,
            faces: tuple) -> tuple[Surface, float]:
    """The extruded letters, pos at the origin; and VPython's text length (max x) before boxing."""
    groups, longest = _lines(text, font, height, align)
    if not groups:                                # only spaces: a point, nothing to see
        groups = [[np.array([[0.0, 0.0], [1e-9, 0.0], [0.0, 1e-9]])]]
    side, start_c, end_c = (np.asarray(c, float) for c in colours)
    d = np.array([0.0, 0.0, math.copysign(1.0, depth)])
    path = Sweep(pos=np.array([[0.0, 0.0, 0.0], [0.0, 0.0, depth]]), x=np.array([[1.0, 0, 0]]),
                 y=np.array([[0.0, 1, 0]]), d=d[None], plane=np.array([d, d]),
                 xscale=np.ones(2), yscale=np.ones(2), twist=np.zeros(2),
                 color=np.array([side, side]), sharp=np.zeros(2, bool), closed=False)
    caps = Caps(faces[0], faces[1], start_c, end_c, -d, d)
    return sweep(groups, path, SMOOTH, caps), longest


# -- the text object --------------------------------------------------------------------------

class text(fused):
    """VPython's 3D text; see the module."""

    _looks_counted = False     # its facing turns with the camera: a recorder reads it all

    _READ_ONLY = ("text", "font", "align", "billboard", "descender", "start_face_color",
                  "end_face_color", "show_start_face", "show_end_face", "start", "end",
                  "upper_left", "upper_right", "lower_left", "lower_right", "vertical_spacing",
                  "lines")

    def __init__(self, **args) -> None:
        if "size" in args:
            raise AttributeError("The text object has no size attribute.")
        if "length" in args:
            raise AttributeError("text length can't be set when creating a text object")
        if "text" not in args:
            raise AttributeError("A text object must have a text attribute")
        spec = self._spec(args)
        object.__setattr__(self, "_billboard", spec["billboard"])
        self._axis, self._up = vector(1, 0, 0), vector(0, 1, 0)   # stored: _axis_v, _up_v
        surface, longest = letters(spec["text"], spec["font"], spec["height"], spec["depth"],
                                   spec["align"], spec["colours"], spec["faces"])
        lo, hi = surface.points.min(axis=0), surface.points.max(axis=0)
        width = max(float(hi[0] - lo[0]), 1e-9)
        if longest > 0:       # GlowScript: the box is as wide as the letters, offset by max x
            surface = surface._replace(points=surface.points + [(lo[0] + hi[0]) / 2
                                                                * (width / longest - 1), 0, 0])
        size0 = (width, spec["height"], spec["depth"])
        self._take(surface, (0.0, 0.0, 0.0), size0)
        h_top, y_top = font_heights(spec["font"])
        self._descender0 = (h_top - y_top) / 100 * spec["height"]
        self._spec_args = spec
        self._start(args, size0)

    @staticmethod
    def _spec(args: dict) -> dict:
        """The text's own arguments, taken out of ``args`` (the rest are ``standard``'s)."""
        s = str(args.pop("text"))
        if not s:
            raise AttributeError("A text object needs non-empty text.")
        font = args.pop("font", "sans")
        if font not in FONTS:
            raise AttributeError("text font must be either 'sans' or 'serif' ")
        height = float(args.pop("height", 1.0))
        depth = float(args.pop("depth", 0.2 * height))
        if abs(depth) < 0.01 * height:
            depth = 0.01 * height
        colour = vector(args["color"]) if "color" in args else vector(1, 1, 1)
        start_c = vector(args.pop("start_face_color", colour))
        end_c = vector(args.pop("end_face_color", colour))
        return {"text": s, "font": font, "height": height, "depth": depth,
                "align": args.pop("align", "left"), "billboard": bool(args.pop("billboard", False)),
                "colours": (colour._xyz(), start_c._xyz(), end_c._xyz()),
                "faces": (bool(args.pop("show_start_face", True)),
                          bool(args.pop("show_end_face", True))),
                "face_colors": (start_c, end_c)}

    def _fit_axis(self) -> None:        # text: axis only turns it
        pass

    # -- billboarding: axis and up follow the camera -------------------------------------

    def _camera(self) -> tuple:
        cv = self.__dict__.get("_canvas")
        return (cv.forward._xyz(), cv.up._xyz()) if cv is not None else ()

    def _facing(self) -> tuple[vector, vector] | None:
        """The camera's right and up, when the text is billboarded."""
        cv = self.__dict__.get("_canvas")
        if not self.__dict__.get("_billboard") or cv is None:
            return None
        right = cv.forward.cross(cv.up)
        if right.mag2 == 0:
            return None
        return right.norm(), right.cross(cv.forward).norm()

    @property
    def _axis(self) -> vector:
        facing = self._facing()
        stored = self.__dict__["_axis_v"]
        return stored if facing is None else facing[0] * stored.mag

    @_axis.setter
    def _axis(self, value: vector) -> None:
        self.__dict__["_axis_v"] = value

    @property
    def _up(self) -> vector:
        facing = self._facing()
        return self.__dict__["_up_v"] if facing is None else facing[1]

    @_up.setter
    def _up(self, value: vector) -> None:
        self.__dict__["_up_v"] = value

    @property
    def _dirty(self) -> bool:
        return self.__dict__.get("_dirty_v", True) or (
            bool(self.__dict__.get("_billboard")) and self._camera() != self.__dict__.get("_seen"))

    @_dirty.setter
    def _dirty(self, value: bool) -> None:
        self.__dict__["_dirty_v"] = bool(value)
        if not value:
            self.__dict__["_seen"] = self._camera()

    # -- VPython's attributes ------------------------------------------------------------

    def __setattr__(self, name: str, value) -> None:
        if name in self._READ_ONLY:
            raise AttributeError(f"{name} is read-only")
        super().__setattr__(name, value)

    @property
    def size(self) -> vector:
        raise AttributeError("The text object has no size attribute.")

    @size.setter
    def size(self, value) -> None:
        raise AttributeError("The text object has no size attribute.")

    @property
    def length(self) -> float:
        return self._size.x

    @length.setter
    def length(self, value) -> None:
        self._size._x_set(float(value))
        self._dirty = True

    @property
    def height(self) -> float:
        return self._size.y

    @height.setter
    def height(self, value) -> None:
        self._size._y_set(float(value))
        self._dirty = True

    @property
    def depth(self) -> float:
        return self._size.z

    @depth.setter
    def depth(self, value) -> None:
        value = float(value)
        if abs(value) < 0.01 * self.height:
            value = math.copysign(0.01 * self.height, value)
        self._size._z_set(value)
        self._dirty = True

    text = property(lambda self: self._spec_args["text"])
    font = property(lambda self: self._spec_args["font"])
    align = property(lambda self: self._spec_args["align"])
    billboard = Linked(readonly=True)
    start_face_color = property(lambda self: vector(self._spec_args["face_colors"][0]))
    end_face_color = property(lambda self: vector(self._spec_args["face_colors"][1]))
    show_start_face = property(lambda self: self._spec_args["faces"][0])
    show_end_face = property(lambda self: self._spec_args["faces"][1])
    lines = property(lambda self: len(self._spec_args["text"].split("\n")))
    descender = property(lambda self: self._descender0 * self.height / self._size0[1])
    vertical_spacing = property(lambda self: LINE_SPACING * self.height)
    # VPython 6's names (visual_common/primitives.py): the descender, and each line's width
    descent = property(lambda self: self.descender)

    @property
    def widths(self) -> list[float]:
        """Each line's width at the text's height, its letters' box (VPython 6's
        ``widths``, shapes.py: the line's bounding box)."""
        font = self._spec_args["font"]
        k = self.height / font_heights(font)[0]
        out = []
        for line in self.text.split("\n"):
            xs = [c[:, 0] for c in outlines(line, font)[0]]
            out.append(k * float(np.ptp(np.concatenate(xs))) if xs else 0.0)
        return out

    @property
    def upper_left(self) -> vector:
        dx = {"right": -self.length, "center": -self.length / 2}.get(self.align, 0.0)
        return self.pos + self.up.norm() * self.height + self.axis.norm() * dx

    @property
    def upper_right(self) -> vector:
        return self.upper_left + self.axis.norm() * self.length

    @property
    def lower_left(self) -> vector:
        drop = -self.height - self.descender - LINE_SPACING * self.height * (self.lines - 1)
        return self.upper_left + self.up.norm() * drop

    @property
    def lower_right(self) -> vector:
        return self.lower_left + self.axis.norm() * self.length

    @property
    def start(self) -> vector:
        return self.upper_left - self.up.norm() * self.height

    @property
    def end(self) -> vector:
        return self.upper_right - self.up.norm() * self.height

    def clone(self, **args) -> text:
        """Another text like this one (VPython's clone of a text is a text)."""
        s = self._spec_args
        new = text(text=s["text"], font=s["font"], align=s["align"], height=s["height"],
                   depth=s["depth"], billboard=s["billboard"], color=vector(self._color),
                   start_face_color=s["face_colors"][0], end_face_color=s["face_colors"][1],
                   show_start_face=s["faces"][0], show_end_face=s["faces"][1],
                   pos=vector(self._pos), axis=vector(self.__dict__["_axis_v"]),
                   up=vector(self.__dict__["_up_v"]), opacity=self._opacity,
                   shininess=self._shininess, emissive=self._emissive, canvas=self._canvas)
        new._size = vector(self._size)
        new._size._on_change = new._on_size_change
        for name, value in args.items():
            setattr(new, name, value)
        return new


__all__ = ["text", "letters", "outlines", "nest", "text_groups", "font_heights"]
