"""VPython programs run headless: speed against references measured in the same run.

1. A thousand moving spheres (`make bench`), 640 x 400, 4x MSAA, frames read back
   (no encoding, so the drawing is what is compared):
   - per-object: one PyVista actor per sphere, moved with ``SetPosition`` each
     frame (what a direct translation of ``ball.pos = ...`` to VTK does);
   - batched, 30 x 30: springscene's renderer (one mesh per kind, points rewritten
     in place) with VPython's sphere everywhere;
   - batched: the same with its level of detail (fewer slices for spheres a few
     pixels across).
2. The wiki program: ``springscene vpython examples/wiki_spring.py`` against
   ``springscene render configs/wiki.toml`` of the same scene, 3 s of MP4 each.

Rounds are interleaved and the best of each is kept.
"""

from __future__ import annotations

import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from springscene import config, render  # noqa: E402
from springscene.vpython.runner import run_program  # noqa: E402

N_SPHERES = 1000
RADIUS = 0.1             # atoms of a crystal: small beside their spacing (1)
FRAMES = 60
SECONDS = 3.0
ROUNDS = 3


def _grid(n: int) -> np.ndarray:
    i = np.arange(n)
    return np.column_stack([i % 10, i // 10 % 10, i // 100]).astype(float)


def per_object() -> float:
    """One actor per sphere; each frame moves every actor."""
    import pyvista as pv

    from springscene.view.scene import MULTI_SAMPLES, grab
    from vtkmodules.vtkCommonCore import vtkUnsignedCharArray

    pl = pv.Plotter(off_screen=True, window_size=(640, 400))
    pl.ren_win.SetMultiSamples(MULTI_SAMPLES)
    base = _grid(N_SPHERES)
    actors = []
    for p in base:
        a = pl.add_mesh(pv.Sphere(radius=RADIUS, center=(0, 0, 0), theta_resolution=30,
                                  phi_resolution=30), color="red", smooth_shading=True)
        a.SetPosition(*p)
        actors.append(a)
    pl.camera_position = [(4.5, 4.5, 30), (4.5, 4.5, 4.5), (0, 1, 0)]
    buf = vtkUnsignedCharArray()
    start = time.perf_counter()
    for f in range(FRAMES):
        shift = 0.01 * f
        for a, p in zip(actors, base):
            a.SetPosition(p[0], p[1], p[2] + shift)
        grab(pl.ren_win, 640, 400, buf)
    seconds = time.perf_counter() - start
    pl.close()
    return seconds


def batched(lod: bool = True) -> float:
    """springscene's renderer: the same spheres as VPython objects, moved by the program.

    ``lod=False`` keeps VPython's 30 x 30 spheres at every size (no level of detail).
    """
    import springscene.vpython as vp
    from springscene.vpython import draw
    from springscene.vpython.draw import Renderer

    saved = draw.SPHERE_LOD
    if not lod:
        draw.SPHERE_LOD = ((30, 0.0),)

    vp.reset()
    balls = [vp.sphere(pos=vp.vector(*p), radius=RADIUS, color=vp.color.red)
             for p in _grid(N_SPHERES)]
    r = Renderer(vp.scene)
    r.frame()
    start = time.perf_counter()
    for _ in range(FRAMES):
        for b in balls:
            b.pos = b.pos + vp.vector(0, 0, 0.01)
        r.frame()
    seconds = time.perf_counter() - start
    r.close()
    draw.SPHERE_LOD = saved
    return seconds


def wiki_program(out: Path) -> float:
    start = time.perf_counter()
    run_program(ROOT / "examples" / "wiki_spring.py", out, duration=SECONDS, page=False)
    return time.perf_counter() - start


def wiki_render(out: Path) -> float:
    start = time.perf_counter()
    render.render_video(config.load(ROOT / "configs" / "wiki.toml"), out, duration=SECONDS)
    return time.perf_counter() - start


def main() -> None:
    from springscene.view import backend

    backend.select("auto")
    best = {name: float("inf") for name in ("per-object", "batched, 30 x 30", "batched",
                                            "render", "vpython")}
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        for _ in range(ROUNDS):
            best["per-object"] = min(best["per-object"], per_object())
            best["batched, 30 x 30"] = min(best["batched, 30 x 30"], batched(lod=False))
            best["batched"] = min(best["batched"], batched())
            best["render"] = min(best["render"], wiki_render(tmp / "r.mp4"))
            best["vpython"] = min(best["vpython"], wiki_program(tmp / "v.mp4"))
    frames = int(round(SECONDS * 50))
    print(f"{N_SPHERES} moving spheres, 640 x 400, {FRAMES} frames (best of {ROUNDS}):")
    for name in ("per-object", "batched, 30 x 30", "batched"):
        print(f"  {name:<17} {FRAMES / best[name]:7.1f} frames/s "
              f"({best['per-object'] / best[name]:.1f}x per-object)")
    print(f"wiki scene, 900 x 600, {frames} frames to MP4 (set-up included):")
    print(f"  springscene render           {frames / best['render']:6.1f} frames/s")
    print(f"  springscene vpython program  {frames / best['vpython']:6.1f} frames/s "
          f"({best['render'] / best['vpython']:.2f}x render's speed)")


if __name__ == "__main__":
    main()
