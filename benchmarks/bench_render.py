"""Render speed against two references measured in the same run (`make bench`).

All at the wiki scene's 900 x 600, the same meshes and the same anti-aliasing
(4x MSAA unless marked draft), each writing an H.264 MP4:

- floor:  the scene with nothing moving: render + read back + encode;
- naive:  a line-by-line PyVista translation of the wiki loop, VPython-style
          vector physics, the spring mesh rebuilt (Spline + tube) and its actor
          re-added every frame (in the scene's own window), each frame read back;
- springscene: ``render_video`` (spring points rewritten in place);
- draft:  ``render_video`` without anti-aliasing.

Rounds are interleaved and the best of each is kept, so the ratios compare
runs made under the same machine load.
"""

from __future__ import annotations

import math
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from springscene import build, config, render  # noqa: E402
from springscene.model import physics  # noqa: E402
from springscene.view.geometry import HelixFrame, HelixTube  # noqa: E402
from springscene.outputs import VideoWriter  # noqa: E402

SECONDS = 3.0
ROUNDS = 3


def _frames(cfg) -> int:
    return len(render.frame_steps(SECONDS, cfg.render.fps, cfg.physics.dt))


def floor(cfg, out: Path) -> float:

    n = _frames(cfg)
    with render.make_scene(cfg, build.system(cfg)) as scene, VideoWriter(out, cfg.render.fps,
                                                         (cfg.scene.width, cfg.scene.height)) as w:
        start = time.perf_counter()
        for _ in range(n):
            w.write(scene.frame())
        w.close()
        return time.perf_counter() - start


def naive(cfg, out: Path) -> float:
    """The wiki loop translated line by line to PyVista."""
    import pyvista as pv

    from springscene.view import window
    from springscene.view.scene import grab as scene_grab
    from vtkmodules.vtkCommonCore import vtkUnsignedCharArray


    n = _frames(cfg)
    k, L0, m, dt = cfg.spring.k, cfg.spring.L0, cfg.ball.m, cfg.physics.dt
    g = np.array(cfg.physics.g)
    holder_pos = np.array(cfg.holder.pos)
    ball_pos, ball_p = np.array(cfg.ball.pos), np.array(cfg.ball.p)
    with render.make_scene(cfg, build.system(cfg)) as scene, VideoWriter(out, cfg.render.fps,
                                                         (cfg.scene.width, cfg.scene.height)) as w:
        win = scene.window
        material = scene.spring_actors[0].GetProperty()
        for actor in scene.spring_actors:        # the naive loop draws its own spring
            win.remove_actor(actor)
        ball = scene.ball_actors[0]
        tube = HelixTube(cfg.spring.radius, cfg.spring.thickness, cfg.spring.coils)
        frame = HelixFrame()
        spring = None
        buffer = vtkUnsignedCharArray()
        start = time.perf_counter()
        steps_per_frame = round(1 / (cfg.render.fps * dt))
        for _ in range(n):
            for _ in range(steps_per_frame):
                L = ball_pos - holder_pos
                Fs = -k * (np.linalg.norm(L) - L0) * (L / np.linalg.norm(L))
                Fnet = Fs + m * g
                ball_p = ball_p + Fnet * dt
                ball_pos = ball_pos + (ball_p / m) * dt
            axis = ball_pos - holder_pos           # spring.axis = ball.pos - holder.pos
            centre = tube.centerline(np.linalg.norm(axis)) @ frame.set_axis(axis).T + holder_pos
            if spring is not None:
                win.remove_actor(spring)
            spring = window.mesh_actor(pv.Spline(centre, len(centre)).tube(
                radius=cfg.spring.thickness / 2, n_sides=16), smooth_shading=True)
            win.add_actor(spring)
            spring.SetProperty(material)
            ball.SetPosition(*ball_pos)
            w.write(scene_grab(win.ren_win, cfg.scene.width, cfg.scene.height, buffer))
        w.close()
        return time.perf_counter() - start


def ours(cfg, out: Path, antialias: bool = True) -> float:
    """``render_video``'s frame loop and encoder flush: the same window the others time."""
    return render.render_video(cfg, out, duration=SECONDS, antialias=antialias).loop_seconds


def physics_steps_per_second(cfg) -> float:
    s = build.system(cfg)
    n = 20000
    start = time.perf_counter()
    physics.step(s, n)
    return n / (time.perf_counter() - start)


def main() -> None:
    cfg = config.load(ROOT / "configs" / "wiki.toml")
    n = _frames(cfg)
    cases = {"floor": floor, "naive": naive, "springscene": ours,
             "draft": lambda c, o: ours(c, o, antialias=False)}
    times: dict[str, list[float]] = {k: [] for k in cases}
    with tempfile.TemporaryDirectory() as tmp:
        for r in range(ROUNDS):
            for name, fn in cases.items():
                times[name].append(fn(cfg, Path(tmp) / f"{name}{r}.mp4"))
    best = {k: min(v) for k, v in times.items()}
    print(f"springscene render benchmark: wiki scene {cfg.scene.width}x{cfg.scene.height}, "
          f"{n} frames ({SECONDS:g} s of video), best of {ROUNDS} interleaved rounds")
    print(f"{'case':<12} {'s/run':>7} {'frames/s':>9} {'x floor':>8}  (spread of rounds)")
    for name, t in best.items():
        spread = statistics.pstdev(times[name]) / statistics.mean(times[name])
        print(f"{name:<12} {t:7.2f} {n / t:9.1f} {t / best['floor']:8.2f}  (+-{spread:.0%})")
    print(f"springscene is {best['naive'] / best['springscene']:.2f}x faster than the naive "
          f"translation and {best['springscene'] / best['floor']:.2f}x the floor; "
          f"draft runs at {n / best['draft']:.0f} frames/s "
          f"({n / best['draft'] / cfg.render.fps:.1f}x real time)")
    print(f"physics alone: {physics_steps_per_second(cfg):,.0f} Euler-Cromer steps/s "
          f"(real time needs {1 / cfg.physics.dt:.0f}; "
          f"period {2 * math.pi * math.sqrt(cfg.ball.m / cfg.spring.k):.4f} s)")


if __name__ == "__main__":
    main()
