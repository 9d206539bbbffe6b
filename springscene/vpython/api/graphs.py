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
This module only records; the drawing is :mod:`..page.graph_layout` (one graph on
matplotlib axes, in VPython's look) and :mod:`..page.graph_images` (graphs as pictures:
:func:`..page.graph_images.draw`, :func:`..page.graph_images.write_images`,
:class:`..page.graph_images.GraphStrip`).
"""

from __future__ import annotations

from typing import Any, Sequence

import numpy as np

from ..core.attributes import Linked
from ..core.page_order import claim_slot
from ..core.vectors import is_lenient

__all__ = [
    "graph", "gcurve", "gdots", "gvbars", "ghbars", "gdisplay", "graphs", "reset",
]

PLOT_USAGE = ("Must be plot(x,y) or plot(pos=[x,y]) or plot([x,y]) or plot([x,y], ...) "
              "or plot([ [x,y], ... ])")

_made: list["graph"] = []
_selected: "graph | None" = None


# --------------------------------------------------------------------------- helpers

def rgb_of(value: Any, name: str) -> tuple[float, float, float]:
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


def _colour(value: Any, name: str) -> Any:
    """``value`` as given, once :func:`rgb_of` finds it a colour."""
    rgb_of(value, name)
    return value


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
        claim_slot(self)          # its place on the page, among the canvases
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
        rgb_of(self.foreground, "foreground")
        rgb_of(self.background, "background")
        for a in ("x", "y"):                      # GlowScript drops these silently
            args.pop(a, None)
        self.user_attributes: dict[str, Any] = dict(args)
        if self.scroll:
            if self.xmin is None or self.xmax is None:
                raise AttributeError(
                    "For a scrolling graph, both xmin and xmax must be specified.")
            if self.xmax <= self.xmin:
                raise AttributeError("For a scrolling graph, xmax must be greater than xmin.")
        self.series: list[GraphSeries] = []
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


class GraphSeries:
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
        rgb_of(self._color, "color")
        self.marker_color: Any = args.pop("marker_color", self._color)
        rgb_of(self.marker_color, "marker_color")
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
        rgb_of(self.dot_color, "dot_color")
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
    graph = Linked(readonly="graph cannot be modified",
                   doc="The graph this object belongs to (fixed when it is made).")
    color = Linked(_colour, doc="The colour, a vector (black by default).")

    @property
    def size(self) -> float:
        """Diameter of the dots in pixels (``2 * radius``)."""
        return 2 * self.radius

    @size.setter
    def size(self, value: float) -> None:
        self.radius = float(value) / 2

    def _count_afresh(self) -> None:
        self._iterations = 0

    interval = Linked(int, then="_count_afresh",
                      doc="Keep one ``plot`` call in ``interval`` (-1: all, 0: none).")
    visible = Linked(bool, doc="Whether the graph shows this object.")

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


class gcurve(GraphSeries):
    """Points joined by a line (VPython's ``gcurve``): ``color``, ``width`` (2 px),
    ``markers``/``marker_color``/``radius``, ``dot``/``dot_color``/``dot_radius``,
    ``label``, ``legend``, ``data``, ``interval``, ``visible``, ``graph``."""

    _kind = "lines"


class gdots(GraphSeries):
    """Points as dots (VPython's ``gdots``): ``radius`` (3 px) or ``size``, ``color``, ...

    A VPython 6 program may also give ``shape`` ('round' or 'square', VPython 6's
    ``gdots(shape=)``); square dots are drawn square.
    """

    _kind = "points"

    def __init__(self, **args: Any) -> None:
        shape = args.pop("shape", "round") if is_lenient() else "round"
        if shape not in ("round", "square"):
            raise AttributeError(f"gdots shape must be 'round' or 'square', not {shape!r}")
        super().__init__(**args)
        self.shape = shape
        self._tints: dict[tuple, gdots] = {}

    def plot(self, *args: Any, **kwargs: Any) -> None:
        """As every series plots; a VPython 6 program may also give each dot its colour
        (``plot(pos=(x, y), color=c)``, its examples/mandelbrot.py): the dot goes to this
        series' companion of that colour on the same graph (dots of one colour are drawn
        together, in the order plotted)."""
        colour = kwargs.pop("color", None) if is_lenient() else None
        if colour is None or tuple(rgb_of(colour, "color")) == tuple(rgb_of(self._color,
                                                                            "color")):
            return super().plot(*args, **kwargs)
        key = tuple(rgb_of(colour, "color"))
        tint = self._tints.get(key)
        if tint is None:
            tint = self._tints[key] = gdots(graph=self._graph, color=colour, visible=self._visible,
                                            radius=self.radius, shape=self.shape)
        tint.plot(*args, **kwargs)

    def delete(self) -> None:
        """Clear the dots, those plotted in their own colours too."""
        super().delete()
        for tint in self._tints.values():
            tint.delete()

    def _show_tints(self) -> None:
        for tint in self._tints.values():
            tint.visible = self._visible

    visible = Linked(bool, then="_show_tints",
                     doc="Whether the graph shows these dots (those in their own colours too).")


class gvbars(GraphSeries):
    """Vertical bars from 0 to y centred on x (VPython's ``gvbars``), ``delta`` wide (1)."""

    _kind = "bars"


class ghbars(GraphSeries):
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
