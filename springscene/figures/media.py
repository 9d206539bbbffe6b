"""The wiki page's pictures of the scene itself: a film strip of one period in stills
(:func:`filmstrip_frames`, :func:`filmstrip_figure`) and the oscillation as a looping
real-time GIF under 2 MB (:func:`make_gif`). The still at t = 0 is
:func:`springscene.render.still`'s.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from fractions import Fraction
from pathlib import Path

import numpy as np

from .. import build, config, render
from ..model import timeline
from ..science import theory
from ..settings import Config
from ..view.plotstyle import new_figure, style
from .oscillator import period_of

FILMSTRIP_FRAMES = 6
GIF_MAX_BYTES = 2_000_000
# (width, height, fps, periods) tried in turn until the GIF fits GIF_MAX_BYTES
GIF_ATTEMPTS = ((450, 300, 25, 2), (450, 300, 20, 1), (360, 240, 20, 1), (300, 200, 15, 1))


@dataclass
class Filmstrip:
    """One period in stills, cropped alike, for :func:`filmstrip_figure`."""
    tiles: list[np.ndarray]       # cropped frames, all the same size
    times: list[float]            # simulated time of each (s)
    period: float                 # T (s)
    equilibrium_row: int | None   # pixel row of the ball's centre at equilibrium, in a tile
    labels: list[str] = field(default_factory=list)


def filmstrip_frames(cfg: Config, *, n: int = FILMSTRIP_FRAMES, backend: str = "auto",
                     antialias: bool = True) -> Filmstrip:
    """n stills at t = 0, T/n, ..., (n-1)T/n, cropped around spring and ball alike."""

    T = period_of(cfg)
    dt = cfg.physics.dt
    steps = [int(round(c * T / n / dt)) for c in range(n)]
    osc = theory.Oscillator.from_config(cfg)
    axis = np.asarray(osc.axis)
    r = cfg.ball.radius
    system = build.system(cfg)
    with render.make_scene(cfg, system, antialias=antialias, backend=backend) as scene:
        # a dry pass first, so that autoscale has seen every state and one view serves all
        balls = []
        for probe in timeline.play(build.system(cfg), steps):
            scene.update(probe)
            balls.append(probe.pos[1].copy())
        frames = []
        for state in timeline.play(system, steps):
            scene.update(state)
            frames.append(scene.frame())
        view = scene.view
    h, w = frames[0].shape[:2]
    cam_right = np.cross(view.focal_point - view.position, view.up)
    cam_right /= np.linalg.norm(cam_right)
    cam_up = np.asarray(view.up, float) / np.linalg.norm(view.up)
    holder = np.asarray(cfg.holder.pos, float)
    size = np.asarray(cfg.holder.size, float)
    pts = [holder - axis * size[1] / 2]               # the middle of the holder's lower face
    for b in balls:
        pts += [b + r * cam_right, b - r * cam_right, b - r * cam_up, b + r * cam_up]
    px = view.project(np.array(pts))
    pad = 14
    c0, c1 = px[:, 0].min() - pad, px[:, 0].max() + pad
    r0, r1 = px[:, 1].min() - 3 * pad, px[:, 1].max() + pad
    centre = (c0 + c1) / 2
    half = max((c1 - c0) / 2, 55)                      # room for the time label
    c0, c1 = int(max(0, round(centre - half))), int(min(w, round(centre + half)))
    r0, r1 = int(max(0, round(r0))), int(min(h, round(r1)))
    tiles = [f[r0:r1, c0:c1] for f in frames]
    eq_row = int(round(view.project(np.asarray(osc.equilibrium))[1])) - r0
    times = [s * dt for s in steps]
    labels = [_fraction_label(Fraction(c, n)) for c in range(n)]
    return Filmstrip(tiles, times, T, eq_row if 0 <= eq_row < r1 - r0 else None, labels)


def _fraction_label(f: Fraction) -> str:
    """0, T/6, T/3, T/2, 2T/3, ... for a fraction of the period."""
    if f == 0:
        return "0"
    return f"{'' if f.numerator == 1 else f.numerator}T/{f.denominator}" if f.denominator > 1 \
        else f"{f.numerator}T"


def filmstrip_figure(strip: Filmstrip, gap: int = 8):
    """The tiles side by side at their own pixels, labelled with their times; a dashed
    line (behind the objects) marks the equilibrium."""
    tiles = [t.copy() for t in strip.tiles]
    th, tw = tiles[0].shape[:2]
    if strip.equilibrium_row is not None:
        row = strip.equilibrium_row
        for tile in tiles:
            line = tile[row]
            background = np.all(line > 235, axis=-1)          # only over the white background
            dash = (np.arange(tw) // 6) % 2 == 0
            line[background & dash] = (120, 120, 120)
    header = 64
    width = len(tiles) * tw + (len(tiles) + 1) * gap
    canvas = np.full((th + gap, width, 3), 255, np.uint8)
    for c, tile in enumerate(tiles):
        x = gap + c * (tw + gap)
        canvas[0:th, x:x + tw] = tile
    with style():
        fig = new_figure(th + gap + header, width)
        fig.set_layout_engine(None)
        fig.figimage(canvas, xo=0, yo=0, origin="upper")
        H = th + gap + header
        for c, t in enumerate(strip.times):
            x = (gap + c * (tw + gap) + tw / 2) / width
            label = strip.labels[c] if strip.labels else ""
            fig.text(x, 1 - 30 / H, label, ha="center", va="center", fontsize=12,
                     fontweight="bold")
            fig.text(x, 1 - 50 / H, f"t = {t:.2f} s", ha="center", va="center", fontsize=11)
        fig.text(0.5, 1 - 10 / H, f"One period, T = {strip.period:.3f} s "
                 "(dashed: equilibrium)", ha="center", va="center", fontsize=11, color="#333333")
    return fig


def make_gif(cfg: Config, out: Path, *, backend: str = "auto", antialias: bool = True
             ) -> tuple[render.RenderStats, tuple[int, int, int, int]]:
    """The oscillation as a looping real-time GIF under :data:`GIF_MAX_BYTES`: smaller,
    slower or shorter until it fits."""
    T = period_of(cfg)
    for width, height, fps, periods in GIF_ATTEMPTS:
        # no title: VTK's title font does not shrink with the canvas
        small = config.override(cfg, "scene", width=width, height=height, title="")
        frames = max(1, int(round(periods * T * fps)))
        stats = render.render_video(small, out, duration=frames / fps, fps=fps, backend=backend,
                                    antialias=antialias)
        if out.stat().st_size < GIF_MAX_BYTES:
            break
    else:
        out.unlink(missing_ok=True)
        raise RuntimeError(f"{out}: no GIF under {GIF_MAX_BYTES:,} bytes")
    assert out.stat().st_size < GIF_MAX_BYTES
    return stats, (width, height, fps, periods)

