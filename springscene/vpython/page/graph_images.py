"""Graphs as pictures: one graph as an image, PNGs of them, and the strip under a video.

:func:`draw` gives one graph (optionally only the first ``upto`` points of each
series, so a video can show it growing), :func:`write_images` writes each graph
as a PNG at its own size, and :class:`GraphStrip` stacks all graphs under the
video. Each is a reusable Agg figure of :class:`.graph_layout._Panel` s redrawn
cheaply by blitting: the static parts (axes, ticks, titles, legends) are drawn
again only when they change. Drawing uses matplotlib's default style
(:func:`springscene.view.plotstyle.panel_style`), whatever the user's matplotlibrc says.

:func:`reset` forgets the figures kept for :func:`draw` (a run starts with it: the
figures of an earlier run in this process let go).
"""

from __future__ import annotations

from pathlib import Path
from typing import Iterable, Sequence

import numpy as np

from ...view.plotstyle import agg_figure, panel_style
from ..api.graphs import graph
from .graph_layout import DPI, _Panel

# matplotlib's default font size (pt): panel_style at it is matplotlib's default style
MATPLOTLIB_FONT_PT = 10.0


class _Figure:
    """A reusable Agg figure holding graphs stacked one above the other, drawn by blitting:
    the static parts are drawn again only when limits, titles or colours change."""

    def __init__(self, gs: Sequence[graph], width: int, heights: Sequence[int]) -> None:
        self.graphs = list(gs)
        self.width = int(width)
        self.height = int(sum(heights))
        with panel_style(MATPLOTLIB_FONT_PT):
            self.fig = agg_figure(self.width, max(self.height, 1), DPI, facecolor="white")
            self.canvas = self.fig.canvas
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
        if self.height == 0:
            return np.zeros((0, self.width, 3), np.uint8)
        key = tuple(p.compute(upto) for p in self.panels)
        if key != self._key or self._background is None:
            with panel_style(MATPLOTLIB_FONT_PT):
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
        from matplotlib.transforms import Bbox  # noqa: PLC0415  heavy: matplotlib

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
    from PIL import Image  # noqa: PLC0415  heavy: Pillow

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


def reset() -> None:
    """Forget the figures kept for :func:`draw` (before running another program)."""
    _figures.clear()
