"""One home for matplotlib's look in springscene: the figures' style and the video panels'.

- :func:`style`: the wiki figures' style (:data:`STYLE`, Okabe-Ito colours), whatever
  the user's matplotlibrc says;
- :func:`panel_style`: matplotlib's defaults at a given font size, for the panels drawn
  into videos (the y(t) graph, the energy bars, the lattice's colour bar);
- :func:`new_figure` / :func:`agg_figure`: figures on the Agg canvas, no pyplot and no
  global state; :func:`figure_image`: a figure as an RGB array.

matplotlib is imported by the functions that draw (heavy: about 0.7 s), so a command
that draws nothing never loads it.
"""

from __future__ import annotations

import contextlib
from typing import Iterator

import numpy as np

DPI = 100
WIDTH_IN = 8.0                 # 800 px: the wiki page's width

# Okabe-Ito: distinguishable with the common colour-vision deficiencies
BLUE, VERMILLION, GREEN, PURPLE = "#0072B2", "#D55E00", "#009E73", "#CC79A7"
ORANGE, SKY, BLACK, GREY = "#E69F00", "#56B4E9", "#000000", "#777777"

STYLE = {
    "font.family": "DejaVu Sans",
    "mathtext.fontset": "dejavusans",
    "font.size": 12,
    "axes.titlesize": 13,
    "axes.labelsize": 12,
    "xtick.labelsize": 11,
    "ytick.labelsize": 11,
    "legend.fontsize": 10.5,
    "figure.titlesize": 14,
    "axes.grid": True,
    "grid.color": "#dddddd",
    "grid.linewidth": 0.7,
    "axes.spines.top": False,
    "axes.spines.right": False,
    "axes.formatter.use_mathtext": False,
    "axes.formatter.useoffset": False,
    "lines.linewidth": 1.6,
    "legend.framealpha": 0.92,
    "legend.edgecolor": "#cccccc",
    "figure.facecolor": "white",
    "axes.facecolor": "white",
    "savefig.facecolor": "white",
    "figure.dpi": DPI,
    "savefig.dpi": DPI,
    "figure.constrained_layout.use": True,
    "svg.fonttype": "path",
    "svg.hashsalt": "springscene",
    "svg.image_inline": True,
    "path.simplify": True,
}
PNG_METADATA = {"Software": None}
SVG_METADATA = {"Date": None, "Creator": None}


@contextlib.contextmanager
def style() -> Iterator[None]:
    """Matplotlib's defaults plus :data:`STYLE`, whatever the user's matplotlibrc says."""
    import matplotlib  # noqa: PLC0415  heavy: matplotlib
    from cycler import cycler  # noqa: PLC0415  heavy: matplotlib

    with matplotlib.rc_context():
        matplotlib.rcdefaults()
        matplotlib.rcParams.update(STYLE)
        matplotlib.rcParams["axes.prop_cycle"] = cycler(
            color=[BLUE, VERMILLION, GREEN, PURPLE, ORANGE, SKY, BLACK])
        yield


def new_figure(height_px: int = 500, width_px: int = round(WIDTH_IN * DPI)):
    """An Agg figure (no pyplot, no global state) of the given size in pixels."""
    return agg_figure(width_px, height_px)


def figure_image(fig) -> np.ndarray:
    """The figure as an (h, w, 3) uint8 array, exactly as the PNG has it."""
    with style():
        fig.canvas.draw()
        return np.asarray(fig.canvas.buffer_rgba())[..., :3].copy()


@contextlib.contextmanager
def panel_style(font_size: float) -> Iterator[None]:
    """matplotlib's defaults with ``font_size`` (pt), for the panels drawn into videos."""
    from matplotlib import rc_context  # noqa: PLC0415  heavy: matplotlib
    from matplotlib import style as mpl_style  # noqa: PLC0415  heavy: matplotlib

    with mpl_style.context("default"), rc_context({"font.size": font_size}):
        yield


def _inches(px: int, dpi: int) -> float:
    """``px`` at ``dpi`` in inches, as many pixels again once matplotlib truncates inches x
    dpi (253 / 100 * 100 is 252.99999999999997: a millionth of a pixel more then; sizes
    that come back whole, the SVGs' 576 pt among them, stay exactly as they were)."""
    inches = px / dpi
    return inches if int(inches * dpi) >= px else (px + 1e-6) / dpi


def agg_figure(width_px: int, height_px: int, dpi: int = DPI, **kwargs):
    """An Agg figure of ``width_px`` x ``height_px`` pixels at ``dpi`` (no pyplot)."""
    from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: PLC0415  heavy: matplotlib
    from matplotlib.figure import Figure  # noqa: PLC0415  heavy: matplotlib

    fig = Figure(figsize=(_inches(width_px, dpi), _inches(height_px, dpi)), dpi=dpi, **kwargs)
    FigureCanvasAgg(fig)
    return fig
