"""VPython 7's graphs (``graph``, ``gcurve``, ``gdots``, ``gvbars``, ``ghbars``), headless.

A VPython program makes graphs and plots into them; here every plotted point is
recorded, and the graphs are drawn with matplotlib (Agg) in the look of VPython's
default ("fast", Flot-based) graphs: a white plot area, light grid lines in the
foreground colour, axes that grow with the data unless ``xmin`` etc. are given,
and a legend at the upper right for the series that have a label.

Behaviour taken from VPython 7 (``vpython/vpython.py`` of vpython-jupyter, and the
GlowScript graph code it runs in the browser):

* ``graph()`` defaults: 640 x 400 px, white background, black foreground, fast,
  no scrolling. Keyword arguments VPython does not know are kept, not rejected
  (VPython stores them and never sends them to the browser).
* The most recently made graph (or the one last ``select()``-ed) is the current one;
  a plot object made without ``graph=`` goes there, and if there is none a graph is
  made for it.
* Plot objects accept GlowScript's series options only; any other keyword is an
  error naming it ("... is not an attribute of a series"), as the browser gives.
* ``plot(x, y)``, ``plot([x, y])``, ``plot([x, y], [x2, y2], ...)``,
  ``plot([[x, y], ...])``, ``plot(pos=...)`` and ``plot(data=...)`` all add points;
  ``interval=n`` keeps the first call and then every n-th, ``interval=0`` none.
* ``delete()`` clears what the graph shows (the object can be plotted into again);
  ``data`` still lists every point plotted, as VPython's Python side does.

Module state: :func:`graphs` lists the graphs made, :func:`reset` forgets them.
Drawing: :func:`draw` (one graph, optionally only its first ``upto`` points a
series, so a video can show it growing), :func:`write_images` (PNGs at each
graph's own size) and :class:`GraphStrip` (all graphs stacked under the video,
redrawn cheaply every frame by blitting).
"""

from __future__ import annotations

import colorsys
import html
import re
from pathlib import Path
from typing import Any, Iterable, Sequence

import numpy as np

__all__ = [
    "graph", "gcurve", "gdots", "gvbars", "ghbars", "gdisplay",
    "graphs", "reset", "draw", "write_images", "GraphStrip",
]

DPI = 100
TICK_FONT_PX = 12          # tick labels and legend
TITLE_FONT_PX = 14         # graph title and axis titles
PLOT_USAGE = ("Must be plot(x,y) or plot(pos=[x,y]) or plot([x,y]) or plot([x,y], ...) "
              "or plot([ [x,y], ... ])")

_made: list["graph"] = []
_selected: "graph | None" = None


# --------------------------------------------------------------------------- helpers

def _rgb(value: Any, name: str) -> tuple[float, float, float]:
    """A colour given as a VPython vector (``.x .y .z`` in 0..1) or a 3-sequence, as an RGB tuple.

    Raises
    ------
    AttributeError
        If ``value`` is neither, with VPython's message ("color must be a vector").
    """
    if all(hasattr(value, a) for a in ("x", "y", "z")):
        c = (value.x, value.y, value.z)
    elif isinstance(value, (list, tuple, np.ndarray)) and len(value) == 3:
        c = tuple(value)
    else:
        raise AttributeError(f"{name} must be a vector")
    try:
        return tuple(min(max(float(v), 0.0), 1.0) for v in c)   # type: ignore[return-value]
    except (TypeError, ValueError):
        raise AttributeError(f"{name} must be a vector") from None


def _graph_background(rgb: tuple[float, float, float]) -> tuple[float, float, float]:
    """GlowScript lightens a graph background darker than half brightness (HSV value >= 0.5)."""
    h, s, v = colorsys.rgb_to_hsv(*rgb)
    return colorsys.hsv_to_rgb(h, s, max(v, 0.5))


_BR = re.compile(r"<br\s*/?>", re.IGNORECASE)
_TAG = re.compile(r"<[^>]*>")


def plain_text(markup: Any) -> str:
    """HTML from a VPython program (a title, a label) as plain text: ``<br>`` a new line,
    other tags dropped, entities decoded."""
    return html.unescape(_TAG.sub("", _BR.sub("\n", str(markup)))).strip()


def _is_seq(v: Any) -> bool:
    return isinstance(v, (list, tuple, np.ndarray))


def _number(v: Any) -> float:
    if hasattr(v, "x") and hasattr(v, "y"):
        raise TypeError("Cannot plot a vector, only a vector component.")
    try:
        return float(v)
    except (TypeError, ValueError):
        raise TypeError("A quantity to plot must be an ordinary number.") from None


def _pair(v: Any) -> tuple[float, float]:
    if not _is_seq(v) or len(v) != 2:
        raise AttributeError("Plot data must be 2-dimensional, like [x,y].")
    return _number(v[0]), _number(v[1])


def _points(items: Any) -> list[tuple[float, float]]:
    """``[x, y]`` or ``[[x, y], ...]`` (lists, tuples or arrays) as a list of points."""
    if not _is_seq(items):
        raise AttributeError(PLOT_USAGE)
    if len(items) == 0:
        return []
    if _is_seq(items[0]):
        return [_pair(v) for v in items]
    return [_pair(items)]


def _resolve(args: tuple, kwargs: dict) -> list[tuple[float, float]]:
    """The points of a ``plot(...)`` call, in every form VPython accepts."""
    if args:
        if kwargs:
            raise AttributeError(PLOT_USAGE)
        if len(args) == 1:                       # plot([x,y]) or plot([[x,y], ...])
            return _points(args[0])
        if _is_seq(args[0]):                     # plot([x,y], [x,y], ...)
            return [_pair(a) for a in args]
        if len(args) == 2:                       # plot(x, y)
            return [(_number(args[0]), _number(args[1]))]
        raise AttributeError("Plot data must be 2-dimensional, like [x,y].")
    if "color" in kwargs:
        raise AttributeError("Cannot currently change color in a plot statement.")
    if "pos" in kwargs:
        return _points(kwargs["pos"])
    if "data" in kwargs:
        return _points(kwargs["data"])
    raise AttributeError(PLOT_USAGE)


# --------------------------------------------------------------------------- graph

class graph:
    """A 2D graph that plot objects draw into (VPython's ``graph``).

    Parameters
    ----------
    width, height : int
        Size in pixels, default 640 x 400.
    title, xtitle, ytitle : str
        HTML text above the graph and along its axes.
    xmin, xmax, ymin, ymax : float or None
        Fixed axis ends; None (default) lets the axis follow the data.
    logx, logy : bool
        Logarithmic axes.
    foreground, background : vector
        Axis/text colour (black) and plot-area colour (white).
    fast, align, scroll : bool, str, bool
        VPython's options; ``scroll=True`` needs ``xmin < xmax`` and then the x
        window follows the newest points.
    **other
        Kept (VPython accepts and ignores unknown graph attributes).
    """

    def __init__(self, **args: Any) -> None:
        global _selected
        self.width: int = int(args.pop("width", 640))
        self.height: int = int(args.pop("height", 400))
        self.title: str = str(args.pop("title", ""))
        self.xtitle: str = str(args.pop("xtitle", ""))
        self.ytitle: str = str(args.pop("ytitle", ""))
        self.xmin = args.pop("xmin", None)
        self.xmax = args.pop("xmax", None)
        self.ymin = args.pop("ymin", None)
        self.ymax = args.pop("ymax", None)
        self.logx: bool = bool(args.pop("logx", False))
        self.logy: bool = bool(args.pop("logy", False))
        self.fast: bool = bool(args.pop("fast", True))
        self.scroll: bool = bool(args.pop("scroll", False))
        self.align: str = args.pop("align", "none")
        self.foreground = args.pop("foreground", (0.0, 0.0, 0.0))
        self.background = args.pop("background", (1.0, 1.0, 1.0))
        _rgb(self.foreground, "foreground")
        _rgb(self.background, "background")
        for a in ("x", "y"):                      # GlowScript drops these silently
            args.pop(a, None)
        self.user_attributes: dict[str, Any] = dict(args)
        if self.scroll:
            if self.xmin is None or self.xmax is None:
                raise AttributeError(
                    "For a scrolling graph, both xmin and xmax must be specified.")
            if self.xmax <= self.xmin:
                raise AttributeError("For a scrolling graph, xmax must be greater than xmin.")
        self.series: list[_gobj] = []
        self.deleted = False
        _made.append(self)
        _selected = self

    def select(self) -> None:
        """Make this the current graph (where new plot objects go)."""
        global _selected
        _selected = self

    @staticmethod
    def get_selected() -> "graph | None":
        """The current graph, or None if none was made."""
        return _selected

    def delete(self) -> None:
        """Remove this graph and everything in it from the page."""
        self.deleted = True

    @property
    def has_data(self) -> bool:
        """True if some visible series shows at least one point (VPython shows a graph
        only once something is plotted into it)."""
        return any(s.visible and s.shown_count() > 0 for s in self.series)

    def __repr__(self) -> str:
        return f"<graph {self.title!r} {self.width}x{self.height}, {len(self.series)} series>"


gdisplay = graph        # the old (VPython 6) name GlowScript still accepts


# --------------------------------------------------------------------------- plot objects

_SERIES_OPTIONS = {
    "graph", "gdisplay", "fast", "type", "data", "pos", "color", "marker_color", "width",
    "markers", "radius", "size", "horizontal", "delta", "label", "legend", "dot",
    "dot_radius", "dot_color", "interval", "integrate_selected", "visible",
}


class _gobj:
    """What gcurve, gdots, gvbars and ghbars share: their data, colour, label, graph."""

    _kind = "lines"          # "lines", "points" or "bars"

    def __init__(self, **args: Any) -> None:
        unknown = [a for a in args if a not in _SERIES_OPTIONS]
        if len(unknown) == 1:
            raise AttributeError(f"{unknown[0]} is not an attribute of a series")
        if unknown:
            raise AttributeError("These are not attributes of a graph object: "
                                 + ", ".join(unknown))
        g = args.pop("graph", None) or args.pop("gdisplay", None)
        fast = args.pop("fast", True)
        if g is None:
            g = _selected if _selected is not None else graph(fast=fast)
        if not isinstance(g, graph):
            raise AttributeError("graph must be a graph")
        self._graph = g
        self._color: Any = args.pop("color", (0.0, 0.0, 0.0))
        _rgb(self._color, "color")
        self.marker_color: Any = args.pop("marker_color", self._color)
        _rgb(self.marker_color, "marker_color")
        self.width = float(args.pop("width", 2))
        markers = bool(args.pop("markers", False))
        if markers and self._kind != "lines":
            raise AttributeError("One can add markers only to graph curves.")
        self.markers = markers
        self.radius = float(args.pop("radius", self.width / 2 + 2 if markers else 3))
        self.dot_radius = float(self.width / 2 + 4)
        if "size" in args:                        # gcurve: the dot's size; others: the dots'
            size = float(args.pop("size"))
            if self._kind == "lines":
                self.dot_radius = size / 2
            else:
                self.radius = size / 2
        self.delta = float(args.pop("delta", 1))
        self.horizontal = bool(args.pop("horizontal", self.horizontal_default()))
        self.label = str(args.pop("label", ""))
        self.legend = bool(args.pop("legend", self.label != ""))
        dot = bool(args.pop("dot", False))
        if dot and self._kind != "lines":
            raise AttributeError('Can add a moving dot only to a gcurve or "lines" object')
        self.dot = dot
        self.dot_radius = float(args.pop("dot_radius", self.dot_radius))
        self.dot_color: Any = args.pop("dot_color", self._color)
        _rgb(self.dot_color, "dot_color")
        self._interval = int(args.pop("interval", -1))
        self._iterations = 0
        self._firstplot = True
        self._visible = bool(args.pop("visible", True))
        self.integrate_selected = args.pop("integrate_selected", False)
        args.pop("type", None)                   # fixed by the class, as in GlowScript
        self._buf = np.empty((64, 2))
        self._n = 0
        self._shown_from = 0                     # points before this were delete()d
        initial = args.pop("data", None)
        if initial is None:
            initial = args.pop("pos", None)
        if initial is not None:
            self._append(_points(initial))
        g.series.append(self)

    def horizontal_default(self) -> bool:
        return False

    # ---- attributes with rules
    @property
    def graph(self) -> graph:
        """The graph this object belongs to (fixed when it is made)."""
        return self._graph

    @graph.setter
    def graph(self, value: Any) -> None:
        raise AttributeError("graph cannot be modified")

    @property
    def color(self) -> Any:
        """The colour, a vector (black by default)."""
        return self._color

    @color.setter
    def color(self, value: Any) -> None:
        _rgb(value, "color")
        self._color = value

    @property
    def size(self) -> float:
        """Diameter of the dots in pixels (``2 * radius``)."""
        return 2 * self.radius

    @size.setter
    def size(self, value: float) -> None:
        self.radius = float(value) / 2

    @property
    def interval(self) -> int:
        """Keep one ``plot`` call in ``interval`` (-1: all, 0: none)."""
        return self._interval

    @interval.setter
    def interval(self, value: int) -> None:
        self._interval = int(value)
        self._iterations = 0

    @property
    def visible(self) -> bool:
        """Whether the graph shows this object."""
        return self._visible

    @visible.setter
    def visible(self, value: bool) -> None:
        self._visible = bool(value)

    @property
    def data(self) -> list[list[float]]:
        """Every point plotted, as a list of ``[x, y]``; setting it replaces them."""
        return self._buf[:self._n].tolist()

    @data.setter
    def data(self, value: Any) -> None:
        pts = _points(value)
        self._n = 0
        self._shown_from = 0
        self._append(pts)

    # ---- methods
    def plot(self, *args: Any, **kwargs: Any) -> None:
        """Add points: ``plot(x, y)``, ``plot([x, y])``, ``plot([x, y], [x2, y2])``,
        ``plot([[x, y], ...])``, ``plot(pos=...)`` or ``plot(data=...)``."""
        if self._interval == 0:
            return
        if self._interval > 0:
            self._iterations += 1
            if self._firstplot:
                self._firstplot = False
            elif self._iterations < self._interval:
                return
            self._iterations = 0
        if len(args) == 2 and not kwargs and not _is_seq(args[0]) and not _is_seq(args[1]):
            self._append([(_number(args[0]), _number(args[1]))])     # the usual call, quickly
        else:
            self._append(_resolve(args, kwargs))

    def delete(self) -> None:
        """Clear what the graph shows of this object; later plots show again."""
        self._shown_from = self._n
        self._firstplot = True
        self._iterations = 0

    # ---- for drawing
    def _append(self, pts: Sequence[tuple[float, float]]) -> None:
        k = len(pts)
        if k == 0:
            return
        need = self._n + k
        if need > len(self._buf):
            cap = len(self._buf)
            while cap < need:
                cap *= 2
            buf = np.empty((cap, 2))
            buf[:self._n] = self._buf[:self._n]
            self._buf = buf
        self._buf[self._n:need] = pts
        self._n = need

    def __len__(self) -> int:
        return self._n

    def shown_count(self, upto: int | None = None) -> int:
        """How many points the graph shows (of the first ``upto`` plotted, if given)."""
        n = self._n if upto is None else min(max(int(upto), 0), self._n)
        return max(n - self._shown_from, 0)

    def shown(self, upto: int | None = None) -> np.ndarray:
        """The (n, 2) points shown (of the first ``upto`` plotted, if given); a view."""
        n = self._n if upto is None else min(max(int(upto), 0), self._n)
        return self._buf[min(self._shown_from, n):n]

    def __repr__(self) -> str:
        return f"<{type(self).__name__} {self.label!r}, {self._n} points>"


class gcurve(_gobj):
    """Points joined by a line (VPython's ``gcurve``): ``color``, ``width`` (2 px),
    ``markers``/``marker_color``/``radius``, ``dot``/``dot_color``/``dot_radius``,
    ``label``, ``legend``, ``data``, ``interval``, ``visible``, ``graph``."""

    _kind = "lines"


class gdots(_gobj):
    """Points as dots (VPython's ``gdots``): ``radius`` (3 px) or ``size``, ``color``, ..."""

    _kind = "points"


class gvbars(_gobj):
    """Vertical bars from 0 to y centred on x (VPython's ``gvbars``), ``delta`` wide (1)."""

    _kind = "bars"


class ghbars(_gobj):
    """Horizontal bars from 0 to x centred on y (VPython's ``ghbars``), ``delta`` high (1)."""

    _kind = "bars"

    def horizontal_default(self) -> bool:
        return True


# --------------------------------------------------------------------------- module state

def graphs() -> list[graph]:
    """The graphs made since the last :func:`reset` (and not deleted), in order."""
    return [g for g in _made if not g.deleted]


def reset() -> None:
    """Forget every graph and the current one (before running another program)."""
    global _selected
    _made.clear()
    _selected = None
    _figures.clear()


# --------------------------------------------------------------------------- drawing

def _px_to_pt(px: float) -> float:
    return px * 72.0 / DPI


def _flot_step(span: float, pixels: float) -> float:
    """Flot's tick spacing for an axis ``pixels`` long showing ``span``: about
    0.3 * sqrt(pixels) ticks, at 1, 2, 2.5 or 5 times a power of ten."""
    n = max(0.3 * np.sqrt(max(pixels, 1.0)), 2.0)
    delta = span / n
    if not (np.isfinite(delta) and delta > 0):
        return 0.0
    magn = 10.0 ** np.floor(np.log10(delta))
    norm = delta / magn
    if norm < 1.5:
        size = 1.0
    elif norm < 2.25:
        size = 2.0
    elif norm < 3:
        size = 2.5
    elif norm < 7.5:
        size = 5.0
    else:
        size = 10.0
    return float(size * magn)


def _axis_limits(lo: float | None, hi: float | None, fixed_min: Any, fixed_max: Any,
                 log: bool, margin: float, pixels: float) -> tuple[float, float, float]:
    """One axis's ends and tick step, as Flot autoscales: the fixed ends, else the data's
    (``lo``..``hi``; None without data) widened by ``margin`` of the span (not across 0)
    and out to whole ticks. The step is 0 on a log axis."""
    fmin = None if fixed_min is None else float(fixed_min)
    fmax = None if fixed_max is None else float(fixed_max)
    if lo is None or hi is None:
        lo, hi = (1.0, 10.0) if log else (0.0, 1.0)
        margin = 0.0
    dlo, dhi = lo, hi
    if fmin is not None:
        lo = fmin
        hi = max(hi, fmin)
    if fmax is not None:
        hi = fmax
        lo = min(lo, fmax)
    if log:
        lo, hi = max(lo, 1e-300), max(hi, 1e-300)
        if hi <= lo:
            lo, hi = lo / 10, hi * 10
        if fmin is None:
            lo = 10.0 ** np.floor(np.log10(lo))
        if fmax is None:
            hi = 10.0 ** np.ceil(np.log10(hi))
        return lo, hi, 0.0
    degenerate = hi - lo <= 0
    if degenerate:
        widen = 1.0 if hi == 0 else 0.01 * abs(hi)
        if fmin is None:
            lo -= widen
        if fmax is None or fmin is not None:
            hi += widen
    span = hi - lo
    if margin:
        if fmin is None:
            lo -= margin * span
            if lo < 0 <= dlo and not degenerate:
                lo = 0.0
        if fmax is None:
            hi += margin * span
            if hi > 0 >= dhi and not degenerate:
                hi = 0.0
    step = _flot_step(hi - lo, pixels)
    if not (np.isfinite(step) and step > 0):
        return lo, hi, 0.0
    if fmin is None:
        lo = float(np.floor(lo / step + 1e-9) * step)
    if fmax is None:
        hi = float(np.ceil(hi / step - 1e-9) * step)
    return lo, hi, step


def _extent(g: graph, upto: int | None) -> tuple[list[float], list[float]]:
    """[xlo, xhi], [ylo, yhi] of what the graph shows (bars take in 0 and their width);
    empty lists without data. Log axes count positive values only."""
    xs: list[float] = []
    ys: list[float] = []
    for s in g.series:
        if not s.visible:
            continue
        p = s.shown(upto)
        if len(p) == 0:
            continue
        x, y = p[:, 0], p[:, 1]
        if s._kind == "bars":
            half = s.delta / 2
            if s.horizontal:
                x, y = np.append(x, 0.0), np.concatenate([y - half, y + half])
            else:
                x, y = np.concatenate([x - half, x + half]), np.append(y, 0.0)
        for vals, out, log in ((x, xs, g.logx), (y, ys, g.logy)):
            v = vals[np.isfinite(vals)]
            if log:
                v = v[v > 0]
            if len(v):
                out += [float(v.min()), float(v.max())]
    return ([min(xs), max(xs)] if xs else []), ([min(ys), max(ys)] if ys else [])


class _Panel:
    """One graph's axes in a figure, with its artists (made as series appear)."""

    def __init__(self, fig, g: graph, left: float, bottom: float, width: float,
                 height: float) -> None:
        self.g = g
        self.box = (left, bottom, width, height)          # px, from the figure's bottom-left
        self.fig = fig
        self.ax = fig.add_axes((0, 0, 1, 1))
        self.ax.set_axisbelow(True)
        self.ax.tick_params(labelsize=_px_to_pt(TICK_FONT_PX), length=3, pad=2)
        self.artists: dict[int, dict[str, Any]] = {}
        self.legend = None
        self.legend_key: tuple | None = None
        self.key: tuple | None = None

    # ---- artists of each series
    def _artists(self, s: _gobj) -> dict[str, Any]:
        from matplotlib.collections import PolyCollection
        from matplotlib.lines import Line2D

        got = self.artists.get(id(s))
        if got is not None and got["series"] is s:
            return got
        a: dict[str, Any] = {"series": s}
        if s._kind == "bars":
            a["bars"] = PolyCollection(np.zeros((0, 4, 2)), animated=True)
            self.ax.add_collection(a["bars"], autolim=False)
        elif s._kind == "points":
            (a["points"],) = self.ax.plot([], [], linestyle="none", marker="o",
                                          markeredgewidth=0, animated=True)
        else:
            (a["line"],) = self.ax.plot([], [], animated=True, solid_joinstyle="round")
            (a["markers"],) = self.ax.plot([], [], linestyle="none", marker="o",
                                           markeredgewidth=0, animated=True)
            (a["dot"],) = self.ax.plot([], [], linestyle="none", marker="o",
                                       markeredgewidth=0, animated=True, clip_on=False)
        for art in a.values():
            if isinstance(art, Line2D):
                art.set_visible(False)
        self.artists[id(s)] = a
        return a

    def update(self, upto: int | None) -> list:
        """Put each series' shown points into its artists; the artists to draw, in order."""
        out: list = []
        for s in self.g.series:
            a = self._artists(s)
            show = s.visible and not self.g.deleted
            p = s.shown(upto) if show else s.shown(0)
            if s._kind == "bars":
                bars = a["bars"]
                half = s.delta / 2
                v = np.zeros((len(p), 4, 2))
                if s.horizontal:
                    v[:, :, 0] = np.outer(p[:, 0], [0, 1, 1, 0])
                    v[:, :, 1] = p[:, 1:2] + [-half, -half, half, half]
                else:
                    v[:, :, 0] = p[:, 0:1] + [-half, half, half, -half]
                    v[:, :, 1] = np.outer(p[:, 1], [0, 0, 1, 1])
                bars.set_verts(v)
                rgb = _rgb(s.color, "color")
                bars.set_facecolor((*rgb, 0.5))
                bars.set_edgecolor(rgb)
                bars.set_linewidth(_px_to_pt(1))
                bars.set_visible(show and len(p) > 0)
                out.append(bars)
            elif s._kind == "points":
                pts = a["points"]
                pts.set_data(p[:, 0], p[:, 1])
                pts.set_color(_rgb(s.color, "color"))
                pts.set_markersize(_px_to_pt(2 * s.radius))
                pts.set_visible(show and len(p) > 0)
                out.append(pts)
            else:
                line, mk, dot = a["line"], a["markers"], a["dot"]
                line.set_data(p[:, 0], p[:, 1])
                line.set_color(_rgb(s.color, "color"))
                line.set_linewidth(_px_to_pt(s.width))
                line.set_visible(show and len(p) > 0)
                mk.set_data(p[:, 0], p[:, 1])
                mk.set_color(_rgb(s.marker_color, "marker_color"))
                mk.set_markersize(_px_to_pt(2 * s.radius))
                mk.set_visible(show and s.markers and len(p) > 0)
                dot.set_data(p[-1:, 0], p[-1:, 1])
                dot.set_color(_rgb(s.dot_color, "dot_color"))
                dot.set_markersize(_px_to_pt(2 * s.dot_radius))
                dot.set_visible(show and s.dot and len(p) > 0)
                out += [line, mk, dot]
        return out

    def _legend_entries(self) -> list[_gobj]:
        return [s for s in self.g.series
                if s.visible and s.legend and s.label and not self.g.deleted]

    def _legend_entries_key(self) -> tuple:
        return tuple((s.label, _rgb(s.color, "color"), s._kind) for s in self._legend_entries())

    def legend_artist(self):
        """The legend (made again only when what it lists changes), or None."""
        from matplotlib.lines import Line2D
        from matplotlib.patches import Patch

        entries = self._legend_entries()
        key = self._legend_entries_key()
        if key == self.legend_key:
            return self.legend
        if self.legend is not None:
            self.legend.remove()
            self.legend = None
        self.legend_key = key
        if entries:
            colors = [_rgb(s.color, "color") for s in entries]
            handles = [Patch(facecolor=(*c, 0.5), edgecolor=c) if s._kind == "bars"
                       else Line2D([], [], color=c, linewidth=2,
                                   marker="o" if s._kind == "points" else None,
                                   linestyle="none" if s._kind == "points" else "-")
                       for s, c in zip(entries, colors)]
            labels = [plain_text(s.label) for s in entries]
            leg = self.ax.legend(handles, labels, loc="upper right",
                                 fontsize=_px_to_pt(TICK_FONT_PX), framealpha=0.85,
                                 handlelength=1.2, borderpad=0.3, labelspacing=0.2)
            for text, c in zip(leg.get_texts(), colors):
                text.set_color(c)
                text.set_parse_math(False)
            leg.set_animated(True)
            self.legend = leg
        return self.legend

    def compute(self, upto: int | None) -> tuple:
        """Limits, titles, colours, series and legend entries: a key that changes when the
        static picture (everything but the data) does; :meth:`apply` sets them."""
        from matplotlib.colors import to_hex

        g = self.g
        left, bottom, width, height = self.box
        title, xtitle, ytitle = plain_text(g.title), plain_text(g.xtitle), plain_text(g.ytitle)
        fg = _rgb(g.foreground, "foreground")
        bg = _graph_background(_rgb(g.background, "background"))
        # margins (px) that fit the titles and tick labels
        top = 8 + (TITLE_FONT_PX * 1.3 * (title.count("\n") + 1) + 4 if title else 0)
        bot = 6 + TICK_FONT_PX * 1.3 + (TITLE_FONT_PX * 1.3 + 2 if xtitle else 0)
        lft = 8 + (TITLE_FONT_PX * 1.3 + 2 if ytitle else 0)
        rgt = 14
        pw, ph = max(width - lft - rgt, 10), max(height - top - bot, 10)
        xs, ys = _extent(g, upto)
        *xlim, xstep = _axis_limits(*(xs or (None, None)), g.xmin, g.xmax, g.logx, 0.0, pw)
        if g.scroll and xs and g.xmin is not None and g.xmax is not None:
            d = max(xs[1] - float(g.xmax), 0.0)
            xlim = [float(g.xmin) + d, float(g.xmax) + d]
        *ylim, ystep = _axis_limits(*(ys or (None, None)), g.ymin, g.ymax, g.logy, 0.02, ph)
        xlim, ylim = tuple(xlim), tuple(ylim)
        key = (xlim, ylim, xstep, ystep, g.logx, g.logy, title, xtitle, ytitle, to_hex(fg),
               to_hex(bg), g.deleted, tuple((id(s), s._kind) for s in g.series),
               self._legend_entries_key())
        self._pending = (xlim, ylim, xstep, ystep, title, xtitle, ytitle, fg, bg,
                         (lft, rgt, top, bot))
        return key

    def apply(self) -> None:
        """Set what :meth:`compute` found on the axes (run under matplotlib's default style)."""
        from matplotlib.ticker import LogLocator, MultipleLocator

        g, ax = self.g, self.ax
        left, bottom, width, height = self.box
        xlim, ylim, xstep, ystep, title, xtitle, ytitle, fg, bg, margins = self._pending
        lft, rgt, top, bot = margins
        ph = max(height - top - bot, 10)
        for s in g.series:
            self._artists(s)
        self.legend_artist()
        ax.set_xscale("log" if g.logx else "linear")
        ax.set_yscale("log" if g.logy else "linear")
        ax.set_xlim(*xlim)
        ax.set_ylim(*ylim)
        for axis, step in ((ax.xaxis, xstep), (ax.yaxis, ystep)):
            if step > 0:
                axis.set_major_locator(MultipleLocator(step))
            else:
                axis.set_major_locator(LogLocator())
        # the widest y tick label sets the left margin
        ticks = [t for t in ax.yaxis.get_major_locator()() if ylim[0] <= t <= ylim[1]]
        labels = ax.yaxis.get_major_formatter().format_ticks(ticks) if ticks else [""]
        widest = max((4 if str(s).startswith("$") else len(str(s)) for s in labels),
                     default=1)                     # a log axis's 10^n: about 4 wide
        lft += widest * TICK_FONT_PX * 0.62 + 6
        pw = max(width - lft - rgt, 10)
        W, H = self.fig.bbox.width, self.fig.bbox.height
        ax.set_position([(left + lft) / W, (bottom + bot) / H, pw / W, ph / H])
        ax.set_facecolor(bg)
        for spine in ax.spines.values():
            spine.set_color(fg)
        ax.tick_params(colors=fg)
        ax.grid(True, color=fg, alpha=0.15, linewidth=_px_to_pt(1))
        ax.set_title(title, fontsize=_px_to_pt(TITLE_FONT_PX), color=fg, pad=4,
                     parse_math=False)
        ax.set_xlabel(xtitle, fontsize=_px_to_pt(TITLE_FONT_PX), color=fg, labelpad=2,
                      parse_math=False)
        ax.set_ylabel(ytitle, fontsize=_px_to_pt(TITLE_FONT_PX), color=fg, labelpad=4,
                      parse_math=False)
        ax.set_visible(not g.deleted)


class _Figure:
    """A reusable Agg figure holding graphs stacked one above the other, drawn by blitting:
    the static parts are drawn again only when limits, titles or colours change."""

    def __init__(self, gs: Sequence[graph], width: int, heights: Sequence[int]) -> None:
        from matplotlib import style
        from matplotlib.backends.backend_agg import FigureCanvasAgg
        from matplotlib.figure import Figure

        self.graphs = list(gs)
        self.width = int(width)
        self.height = int(sum(heights))
        with style.context("default"):
            self.fig = Figure(figsize=(self.width / DPI, max(self.height, 1) / DPI), dpi=DPI,
                              facecolor="white")
            self.canvas = FigureCanvasAgg(self.fig)
            self.panels: list[_Panel] = []
            top = self.height
            for g, h in zip(self.graphs, heights):
                top -= h
                self.panels.append(_Panel(self.fig, g, 0, top, self.width, h))
        self._key: tuple | None = None
        self._background = None
        self._pixels: np.ndarray | None = None
        self._legends: list = []
        self._out = np.empty((self.height, self.width, 3), np.uint8)

    def render(self, upto: int | None = None) -> np.ndarray:
        """The figure with the data so far (the first ``upto`` points a series), (h, w, 3) uint8.

        The static parts (axes, ticks, titles, legends) are drawn only when they change,
        and saved; a frame restores them, draws the data and puts the legends back on top.
        """
        from matplotlib import style

        if self.height == 0:
            return np.zeros((0, self.width, 3), np.uint8)
        key = tuple(p.compute(upto) for p in self.panels)
        if key != self._key or self._background is None:
            with style.context("default"):
                for p in self.panels:
                    p.apply()
                self.canvas.draw()                  # animated artists are left out
                self._background = self.canvas.copy_from_bbox(self.fig.bbox)
                self._pixels = np.asarray(self.canvas.buffer_rgba())
                renderer = self.canvas.get_renderer()
                self._legends = []
                for p in self.panels:
                    if p.legend is not None and not p.g.deleted:
                        p.legend.draw(renderer)
                        self._legends.append(self.canvas.copy_from_bbox(
                            self._whole_pixels(p.legend.get_window_extent(renderer))))
            self._key = key
        self.canvas.restore_region(self._background)
        renderer = self.canvas.get_renderer()
        for p in self.panels:
            arts = p.update(upto)
            if p.g.deleted:
                continue
            for a in arts:
                if a.get_visible():
                    a.draw(renderer)
        for region in self._legends:
            self.canvas.restore_region(region)
        rgba = self._pixels
        for c in range(3):                          # faster than one strided copy
            self._out[..., c] = rgba[..., c]
        return self._out.copy()


    def _whole_pixels(self, box):
        """``box`` grown to whole pixels (and one more each side), inside the figure."""
        from matplotlib.transforms import Bbox

        x0, y0 = max(np.floor(box.x0) - 1, 0), max(np.floor(box.y0) - 1, 0)
        x1 = min(np.ceil(box.x1) + 1, self.width)
        y1 = min(np.ceil(box.y1) + 1, self.height)
        return Bbox([[x0, y0], [x1, y1]])


_figures: dict[tuple[int, int, int], _Figure] = {}


def draw(g: graph, width: int | None = None, height: int | None = None,
         upto: int | None = None) -> np.ndarray:
    """One graph as an image.

    Parameters
    ----------
    g : graph
        The graph.
    width, height : int, optional
        Size in pixels (default: the graph's own).
    upto : int, optional
        Draw only the first ``upto`` points plotted into each series.

    Returns
    -------
    numpy.ndarray
        (height, width, 3) uint8 RGB.
    """
    w = int(g.width if width is None else width)
    h = int(g.height if height is None else height)
    key = (id(g), w, h)
    fig = _figures.get(key)
    if fig is None or fig.graphs[0] is not g:
        fig = _figures[key] = _Figure([g], w, [h])
    return fig.render(upto)


def write_images(gs: Iterable[graph], folder: str | Path, stem: str) -> list[Path]:
    """Each graph as a PNG at its own size: ``{stem}-graph1.png``, ``{stem}-graph2.png``, ...

    Returns
    -------
    list of Path
        The files written, in the graphs' order.
    """
    from PIL import Image

    folder = Path(folder)
    folder.mkdir(parents=True, exist_ok=True)
    paths = []
    for i, g in enumerate(gs, 1):
        path = folder / f"{stem}-graph{i}.png"
        Image.fromarray(draw(g)).save(path)
        paths.append(path)
    return paths


class GraphStrip:
    """Graphs stacked into one strip for a video, each ``width`` x ``height`` px.

    The figure is made once and redrawn by blitting each frame: only the data (and the
    legend) are drawn unless an axis's limits, a title or a colour changed. To keep
    that rare, autoscaled axes end on round tick values.
    """

    def __init__(self, gs: Sequence[graph], width: int, height: int = 240) -> None:
        self.graphs = list(gs)
        self.width, self.height = int(width), int(height)
        self._fig = _Figure(self.graphs, self.width, [self.height] * len(self.graphs))

    @property
    def size(self) -> tuple[int, int]:
        """(width, total height) in pixels."""
        return self.width, self.height * len(self.graphs)

    def draw(self, upto: int | None = None) -> np.ndarray:
        """All graphs with their data so far, (total height, width, 3) uint8."""
        return self._fig.render(upto)
