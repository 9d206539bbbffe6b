"""One VPython graph on matplotlib axes: how it is laid out and what is drawn on it.

VPython's default ("fast") graphs are Flot plots; :func:`_axis_limits` autoscales
an axis as Flot does (the data widened by a margin, out to whole ticks at 1, 2,
2.5 or 5 times a power of ten, :func:`_flot_step`), and :class:`_Panel` holds one
graph's axes in a figure: margins that fit its titles and tick labels, a white
plot area (a dark background lightened as GlowScript does), light grid lines in
the foreground colour, one set of artists per series (line, markers, moving dot;
dots; bars) and a legend at the upper right for the series that have a label.

The figures these panels sit in, and the pictures made of them, are
:mod:`.graph_images`'; the data is :mod:`..api.graphs`'s.
"""

from __future__ import annotations

import colorsys
import html
import re
from typing import Any

import numpy as np

from ..api.graphs import GraphSeries, graph, rgb_of

DPI = 100
TICK_FONT_PX = 12          # tick labels and legend
TITLE_FONT_PX = 14         # graph title and axis titles


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



def _dot_marker(series) -> str:
    """matplotlib's marker for a series' dots: VPython 6's ``gdots(shape="square")`` squares
    (a side of twice the radius, as its dots are a diameter across), else round."""
    return "s" if getattr(series, "shape", "round") == "square" else "o"


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
    # no span, or one below what a float can tell apart at this size (a constant that wobbles
    # in its last digits): widened as Flot widens none (matplotlib would widen it by 5 %
    # and tick it at the tiny step: quadrillions of ticks)
    degenerate = hi - lo <= 1e-12 * max(abs(lo), abs(hi))
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
    def _artists(self, s: GraphSeries) -> dict[str, Any]:
        from matplotlib.collections import PolyCollection  # noqa: PLC0415  heavy: matplotlib
        from matplotlib.lines import Line2D  # noqa: PLC0415  heavy: matplotlib

        got = self.artists.get(id(s))
        if got is not None and got["series"] is s:
            return got
        a: dict[str, Any] = {"series": s}
        if s._kind == "bars":
            a["bars"] = PolyCollection(np.zeros((0, 4, 2)), animated=True)
            self.ax.add_collection(a["bars"], autolim=False)
        elif s._kind == "points":
            (a["points"],) = self.ax.plot([], [], linestyle="none", marker=_dot_marker(s),
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
                rgb = rgb_of(s.color, "color")
                bars.set_facecolor((*rgb, 0.5))
                bars.set_edgecolor(rgb)
                bars.set_linewidth(_px_to_pt(1))
                bars.set_visible(show and len(p) > 0)
                out.append(bars)
            elif s._kind == "points":
                pts = a["points"]
                pts.set_data(p[:, 0], p[:, 1])
                pts.set_color(rgb_of(s.color, "color"))
                pts.set_markersize(_px_to_pt(2 * s.radius))
                pts.set_visible(show and len(p) > 0)
                out.append(pts)
            else:
                line, mk, dot = a["line"], a["markers"], a["dot"]
                line.set_data(p[:, 0], p[:, 1])
                line.set_color(rgb_of(s.color, "color"))
                line.set_linewidth(_px_to_pt(s.width))
                line.set_visible(show and len(p) > 0)
                mk.set_data(p[:, 0], p[:, 1])
                mk.set_color(rgb_of(s.marker_color, "marker_color"))
                mk.set_markersize(_px_to_pt(2 * s.radius))
                mk.set_visible(show and s.markers and len(p) > 0)
                dot.set_data(p[-1:, 0], p[-1:, 1])
                dot.set_color(rgb_of(s.dot_color, "dot_color"))
                dot.set_markersize(_px_to_pt(2 * s.dot_radius))
                dot.set_visible(show and s.dot and len(p) > 0)
                out += [line, mk, dot]
        return out

    def _legend_entries(self) -> list[GraphSeries]:
        return [s for s in self.g.series
                if s.visible and s.legend and s.label and not self.g.deleted]

    def _legend_entries_key(self) -> tuple:
        return tuple((s.label, rgb_of(s.color, "color"), s._kind) for s in self._legend_entries())

    def legend_artist(self):
        """The legend (made again only when what it lists changes), or None."""
        from matplotlib.lines import Line2D  # noqa: PLC0415  heavy: matplotlib
        from matplotlib.patches import Patch  # noqa: PLC0415  heavy: matplotlib

        entries = self._legend_entries()
        key = self._legend_entries_key()
        if key == self.legend_key:
            return self.legend
        if self.legend is not None:
            self.legend.remove()
            self.legend = None
        self.legend_key = key
        if entries:
            colors = [rgb_of(s.color, "color") for s in entries]
            handles = [Patch(facecolor=(*c, 0.5), edgecolor=c) if s._kind == "bars"
                       else Line2D([], [], color=c, linewidth=2,
                                   marker=_dot_marker(s) if s._kind == "points" else None,
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
        from matplotlib.colors import to_hex  # noqa: PLC0415  heavy: matplotlib

        g = self.g
        left, bottom, width, height = self.box
        title, xtitle, ytitle = plain_text(g.title), plain_text(g.xtitle), plain_text(g.ytitle)
        fg = rgb_of(g.foreground, "foreground")
        bg = _graph_background(rgb_of(g.background, "background"))
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
        from matplotlib.ticker import LogLocator, MultipleLocator  # noqa: PLC0415  heavy: matplotlib

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
