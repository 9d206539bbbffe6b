"""Overlays drawn into the video around the 3D scene: a clock, a y(t) graph, energy bars.

The 3D scene keeps its size; the video frame grows around it::

    +-----------------+--------+
    |  scene (w x h)  | energy |      graph:  below the scene, as VPython puts its graphs
    |  t = 1.23 s     |  bars  |      energy: beside it, about equilibrium (K <-> U)
    +-----------------+        |      time:   a clock in the scene's top-left corner
    |  y(t) graph     |        |              (a text actor of the scene itself)
    +-----------------+--------+

The panels are matplotlib figures drawn off-screen (Agg) with blitting: the
static parts (axes, ticks, labels) are drawn once and saved, and each frame only
restores that background and draws the moving artists (the trace, its dot, the
bars) into it. Their axis limits are fixed from a pre-run of the same
(deterministic) simulation, so nothing rescales while the video plays. The
panels only read the state: the physics is the same with or without overlays.
"""

from __future__ import annotations

import numpy as np

from ..errors import UserError
from ..model import physics
from ..settings import SceneCfg
from ..units import si_prefix
from .plotstyle import agg_figure, panel_style

OVERLAYS = ("time", "graph", "energy")

GRAPH_HEIGHT = 240       # px, the y(t) graph under the scene
GRAPH_MIN_WIDTH = 360    # px; a narrower scene gets a graph this wide (the scene padded)
ENERGY_WIDTH = 320       # px, the energy bars beside the scene
ENERGY_MIN_HEIGHT = 360  # px
DPI = 100
PANEL_BACKGROUND = (255, 255, 255)
FONT_SIZE = 11           # pt at DPI: about 15 px

TRACE_COLOR = (0.0, 0.3, 0.8)
# (label, colour) of each energy bar, VPython's colours darkened where pure ones are
# unreadable on white; U is Us + Ug measured from the ball at rest at equilibrium
ENERGY_BARS = (
    ("K", (0.9, 0.0, 0.0)),                 # red
    ("U", (0.0, 0.65, 0.8)),                # cyan, like the spring
    ("thermal", (1.0, 0.55, 0.0)),          # orange
    ("total", (0.0, 0.0, 0.0)),             # black
)


def parse_overlays(text: str | None, flag: str = "--overlay") -> tuple[str, ...] | None:
    """``"time,graph"`` as ("time", "graph"); ``"none"`` as (); None (not given) as None,
    which leaves the choice to the config (:func:`springscene.render.make_overlays`: a
    lattice's video gets its clock). Unknown names are bad input."""
    if text is None:
        return None
    if str(text).strip().lower() == "none":
        return ()
    names = tuple(dict.fromkeys(n.strip() for n in str(text).split(",") if n.strip()))
    if str(text).strip() and not names:
        raise UserError(f"{flag} {text!r}: no overlay named (use a comma list of "
                        f"{', '.join(OVERLAYS)})")
    unknown = [n for n in names if n not in OVERLAYS]
    if unknown:
        raise UserError(f"{flag} {text!r}: unknown overlay {unknown[0]!r} "
                        f"(use a comma list of {', '.join(OVERLAYS)})")
    return names


def clock_text(t: float, speed: float = 1.0, duration: float = 0.0) -> str:
    """The clock's text: ``t = 1.23 s``; in ps or fs when the video's simulated span (its
    ``duration``, or a video second, ``speed``, when longer) is that short."""
    scale, prefix = si_prefix(max(speed, duration), largest="", smallest="f", tolerance=0.5)
    return f"t = {t / scale:.2f} {prefix}s"


INK_LEVEL = 40          # levels of 255 off the background that count as drawn


def clock_top(image: np.ndarray, background, *, margin: int, width: int,
              height: int) -> int:
    """Pixels from the top edge for the clock's top: ``margin``, or, when something is
    already drawn where the clock would go (a long title reaching into the top-left
    corner), the first empty row below it plus ``margin`` / 2."""
    ink = np.abs(image.astype(np.int16) - np.rint(np.asarray(background) * 255)).max(axis=2)
    inked = (ink > INK_LEVEL)[:, :margin + width].any(axis=1)
    if not inked[:margin + height].any():
        return margin
    empty = np.flatnonzero(~inked[margin:]) + margin
    below = empty[empty > np.flatnonzero(inked[:margin + height])[-1]]
    return int(below[0]) + margin // 2 if len(below) else margin


def _limits(values, include: tuple[float, ...] = (), pad: float = 0.08,
            floor: float = 1e-3) -> tuple[float, float]:
    """Axis limits: the finite ``values`` and ``include`` widened by ``pad`` of their span
    (of their size, or ``floor``, when they are all one value)."""
    v = np.asarray(values, float).ravel()
    v = np.concatenate([v[np.isfinite(v)], include])
    if len(v) == 0:
        return -1.0, 1.0
    lo, hi = float(v.min()), float(v.max())
    span = hi - lo
    if not span > 0:
        span = max(abs(lo), floor)
    return lo - pad * span, hi + pad * span


class _Panel:
    """A matplotlib figure of ``width`` x ``height`` pixels drawn with Agg and blitting."""

    def __init__(self, width: int, height: int) -> None:
        self.width, self.height = int(width), int(height)
        self.fig = agg_figure(self.width, self.height, DPI, facecolor="white")
        self.canvas = self.fig.canvas
        self._background = None
        self.static: np.ndarray | None = None            # (h, w, 3) the panel, frozen
        self.region: tuple[slice, slice] = (slice(0), slice(0))   # rows, cols that move

    def _freeze(self, ax, pad: int = 0) -> None:
        """Lay the figure out once, draw its static parts (the animated artists left out)
        and keep them: the whole panel as :attr:`static`, and the pixels of ``ax`` (``pad``
        px wider) as the background every frame restores before drawing the moving parts."""
        from matplotlib.transforms import Bbox  # noqa: PLC0415  heavy: matplotlib

        for artist in ax.get_children():       # lay out by the static parts only
            if artist.get_animated():
                artist.set_in_layout(False)
        self.fig.tight_layout(pad=0.5)
        self.canvas.draw()
        b = ax.bbox
        x0, y0 = max(int(np.floor(b.x0)) - pad, 0), max(int(np.floor(b.y0)) - pad, 0)
        x1 = min(int(np.ceil(b.x1)) + pad, self.width)
        y1 = min(int(np.ceil(b.y1)) + pad, self.height)
        self._background = self.canvas.copy_from_bbox(Bbox([[x0, y0], [x1, y1]]))
        self.region = (slice(self.height - y1, self.height - y0), slice(x0, x1))
        self._pixels = np.asarray(self.canvas.buffer_rgba())
        self.static = np.ascontiguousarray(self._pixels[..., :3])
        self._renderer = self.canvas.get_renderer()

    def _blit(self, artists) -> np.ndarray:
        """Restore the background and draw ``artists`` over it; the RGBA pixels of
        :attr:`region` (a view of the canvas, valid until the next call)."""
        self.canvas.restore_region(self._background)
        for a in artists:
            a.draw(self._renderer)
        return self._pixels[self.region]


def _rgb_into(dst: np.ndarray, rgba: np.ndarray) -> None:
    """``dst[...] = rgba[..., :3]``, a channel at a time (4x faster than numpy's strided copy)."""
    for c in range(3):
        dst[..., c] = rgba[..., c]


class GraphPanel(_Panel):
    """The ball's y(t) growing frame by frame, like a VPython ``gcurve`` under the canvas.

    Parameters
    ----------
    traj : Trajectory
        The pre-run: row n is step n. Its t and y fix the axes and are the trace.
    duration : float
        The x axis runs from 0 to ``duration`` (s).
    """

    def __init__(self, width: int, traj, duration: float, height: int = GRAPH_HEIGHT) -> None:
        super().__init__(width, height)
        t, y = np.asarray(traj.t), np.asarray(traj.pos[:, 1])
        with panel_style(FONT_SIZE):
            ax = self.fig.add_subplot()
            ax.set_xlim(0.0, max(float(duration), float(t[-1]), 1e-9))
            ax.set_ylim(*_limits(y))
            ax.set_xlabel("t (s)", labelpad=2)
            ax.set_ylabel("y (m)")
            ax.set_title("y of the ball", fontsize=FONT_SIZE, pad=6)
            ax.grid(True, color="0.88", linewidth=0.8)
            ax.set_axisbelow(True)
            (self.trace,) = ax.plot([], [], color=TRACE_COLOR, linewidth=1.6, animated=True)
            (self.dot,) = ax.plot([], [], "o", color=TRACE_COLOR, markersize=6, animated=True,
                                  clip_on=False)      # whole at the axes' ends too
            self.ax = ax
            self._freeze(ax, pad=8)          # the dot may stick out of the axes
        # at most one point per pixel column of the axes: drawing the trace costs about
        # 0.6 us a point, so a frame costs the same whatever dt and the duration are
        stride = max(1, int(np.ceil(len(t) / ax.bbox.width)))
        self._t, self._y = t[::stride], y[::stride]

    def draw(self, t: float, y: float) -> np.ndarray:
        """The trace up to time ``t`` and a dot at (t, y): the RGBA pixels of :attr:`region`."""
        k = int(np.searchsorted(self._t, t, side="left"))
        self.trace.set_data(np.append(self._t[:k], t), np.append(self._y[:k], y))
        self.dot.set_data([t], [y])
        return self._blit((self.trace, self.dot))


class EnergyPanel(_Panel):
    """Bars of K, U, thermal and total energy, as PhET's Masses and Springs, about
    equilibrium so that the exchange between K and U shows.

    U is Us + Ug measured from ``u_rest``, their value with the ball at rest at
    equilibrium (the figure energy.png's lower panel does the same): a free oscillation
    trades K and U between 0 and 1/2 k A^2 (3 mJ on the page), where Us and Ug apart
    each swing by m g A about some 25 mJ and would squash the exchange to a sliver.
    The total is K + U + thermal. Without ``u_rest`` the lowest Us + Ug of the run is
    the zero (the ball passes equilibrium once a half period). The y axis, in J with an
    SI prefix (mJ on the page), is fixed from the pre-run ``traj`` (every bar's whole
    range, and 0).
    """

    def __init__(self, height: int, traj, width: int = ENERGY_WIDTH,
                 u_rest: float | None = None) -> None:
        from matplotlib.collections import PolyCollection  # noqa: PLC0415  heavy: matplotlib

        super().__init__(width, height)
        with panel_style(FONT_SIZE):
            ax = self.fig.add_subplot()
            x = np.arange(len(ENERGY_BARS))
            labels = [label for label, _ in ENERGY_BARS]
            # the bars as one collection of rectangles: one draw call a frame
            half = 0.35
            self._verts = np.zeros((len(x), 4, 2))
            self._verts[:, :, 0] = x[:, None] + [-half, half, half, -half]
            self.bars = PolyCollection(self._verts, facecolors=[c for _, c in ENERGY_BARS],
                                       edgecolors="none", animated=True)
            ax.add_collection(self.bars, autolim=False)
            ax.set_xlim(-0.5, len(x) - 0.5)
            self.u_rest = (float(np.min(traj.Us + traj.Ug)) if u_rest is None
                           else float(u_rest))
            lo, hi = _limits(self.values(traj), include=(0.0,))
            self.scale, prefix = si_prefix(max(abs(lo), abs(hi)), largest="", smallest="n")
            ax.set_ylim(lo / self.scale, hi / self.scale)
            ax.set_xticks(x, labels, fontsize=FONT_SIZE - 1)
            ax.axhline(0.0, color="black", linewidth=1.0)
            ax.set_title(f"energy ({prefix}J)", fontsize=FONT_SIZE, pad=6)
            ax.set_xlabel("U = $U_s + U_g$, 0 at rest at equilibrium",
                          fontsize=FONT_SIZE - 2)
            ax.grid(True, axis="y", color="0.88", linewidth=0.8)
            ax.set_axisbelow(True)
            ax.tick_params(axis="x", length=0)
            self.ax = ax
            self._freeze(ax)

    def values(self, e) -> tuple:
        """(K, U, thermal, total) in J, from Energies or a Trajectory's arrays; drawn
        in units of :attr:`scale` J."""
        u = e.Us + e.Ug - self.u_rest
        return (e.K, u, e.E_thermal, e.K + u + e.E_thermal)

    def draw(self, e) -> np.ndarray:
        """The bars at :class:`~springscene.model.physics.Energies` ``e``: the RGBA pixels of
        :attr:`region`."""
        self._verts[:, 2:, 1] = np.array(self.values(e))[:, None] / self.scale
        self.bars.set_verts(self._verts)       # from 0 up to the value (down when negative)
        return self._blit((self.bars,))


class Overlays:
    """The overlays of a render: a clock in the scene, a graph below it, energy bars beside it.

    Parameters
    ----------
    canvas : SceneCfg
        The scene's canvas (its size and background).
    overlays : tuple of str
        Names from :data:`OVERLAYS`; empty for the plain scene.
    trajectory : Trajectory, optional
        A pre-run of the same system from t = 0, at least to the last frame (it fixes
        the graph's and the bars' axes and is the graph's trace); needed by the graph
        and the energy bars.
    duration : float
        The video's simulated seconds (the graph's time axis).
    speed : float
        Simulated seconds per video second (the clock's unit).
    u_rest : float, optional
        Us + Ug at rest at equilibrium (J), the zero of the energy bars' U
        (:class:`EnergyPanel`).

    Use per frame, after the system is stepped and the scene updated::

        overlays.update_scene(scene, system)    # the clock (a text actor of the scene)
        frame = overlays.compose(scene.frame(), system)
    """

    def __init__(self, canvas: SceneCfg, overlays: tuple[str, ...] = (), trajectory=None, *,
                 duration: float = 0.0, speed: float = 1.0,
                 u_rest: float | None = None) -> None:
        overlays = tuple(overlays)
        for name in overlays:
            if name not in OVERLAYS:
                raise ValueError(f"unknown overlay {name!r} (use {', '.join(OVERLAYS)})")
        if ("graph" in overlays or "energy" in overlays) and trajectory is None:
            raise ValueError("the graph and energy overlays need the run's trajectory")
        self.names = overlays
        self.speed, self.duration = speed, duration
        self._canvas = canvas
        self._clock_top: int | None = None
        self.scene_size = (canvas.width, canvas.height)
        w, h = self.scene_size
        self.graph = self.energy = None
        left = w
        if "graph" in overlays:
            self.graph = GraphPanel(max(w, GRAPH_MIN_WIDTH), trajectory, duration)
            left = self.graph.width
        height = h + (self.graph.height if self.graph is not None else 0)
        if "energy" in overlays:
            self.energy = EnergyPanel(max(height, ENERGY_MIN_HEIGHT), trajectory,
                                      u_rest=u_rest)
            height = self.energy.height
        self.size = (left + (self.energy.width if self.energy is not None else 0), height)
        self._frame = None
        if self.graph is not None or self.energy is not None:
            # the frame buffer holds the panels' static parts; each compose() rewrites
            # the scene and the panels' moving regions only
            frame = np.empty((height, self.size[0], 3), np.uint8)
            frame[...] = PANEL_BACKGROUND
            if left > w:           # a scene narrower than its graph: pad with its background
                frame[:h, w:left] = np.rint(np.asarray(canvas.background) * 255)
            self._graph_at = self._energy_at = None
            if self.graph is not None:
                frame[h:h + self.graph.height, :self.graph.width] = self.graph.static
                self._graph_at = self._place(frame, self.graph, h, 0)
            if self.energy is not None:
                frame[:self.energy.height, left:] = self.energy.static
                self._energy_at = self._place(frame, self.energy, 0, left)
            self._frame = frame

    @staticmethod
    def _place(frame: np.ndarray, panel: _Panel, top: int, left: int) -> np.ndarray:
        """The view of ``frame`` where ``panel`` (its top-left at row ``top``, column
        ``left``) has its moving region."""
        rows, cols = panel.region
        return frame[top + rows.start:top + rows.stop, left + cols.start:left + cols.stop]

    @property
    def panels(self) -> bool:
        """True when the frame is larger than the scene."""
        return self._frame is not None

    def update_scene(self, scene, system) -> None:
        """Set the scene's clock to the system's time (before the scene is rendered); in
        the top-left corner, under the title when the title reaches into that corner
        (:func:`clock_top`, from one frame of the scene rendered before the clock)."""
        if "time" not in self.names:
            return
        text = clock_text(system.t, self.speed, self.duration)
        if self._clock_top is None:
            self._clock_top = scene.CLOCK_MARGIN
            if self._canvas.title.strip():
                self._clock_top = clock_top(
                    scene.frame(), self._canvas.background, margin=scene.CLOCK_MARGIN,
                    width=int(0.5 * scene.CLOCK_FONT_SIZE * (len(text) + 1)),
                    height=scene.CLOCK_FONT_SIZE)
        scene.set_clock(text, top=self._clock_top)

    def compose(self, scene_image: np.ndarray, system) -> np.ndarray:
        """The video frame: ``scene_image`` (h, w, 3) with the panels at ``system``'s state.

        Without graph and energy panels this is ``scene_image`` itself. With them it
        is one buffer, rewritten by the next call: copy it to keep it.
        """
        frame = self._frame
        if frame is None:
            return scene_image
        w, h = self.scene_size
        frame[:h, :w] = scene_image
        if self.graph is not None:
            node = int(system.free[0])
            _rgb_into(self._graph_at, self.graph.draw(system.t, float(system.pos[node, 1])))
        if self.energy is not None:
            _rgb_into(self._energy_at, self.energy.draw(physics.energies(system)))
        return frame
