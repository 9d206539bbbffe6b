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
3. VPython's own demos (vpython-jupyter ``Demos_no_notebook``: AtomicSolid at
   900 x 600, HardSphereGas, Stars, RotatingBoxes at their own canvas sizes), run
   as programs to MP4, draft and anti-aliased: steady frames/s with springscene's
   level of detail (helices, spheres) and back-face culling against full detail
   (VPython's 60 x 16 helices, 30 x 30 spheres, both sides drawn) in the same run
   (helices batched in both). The demos are read from the folder
   ``$SPRINGSCENE_DEMOS`` (default /work/demos); missing ones are skipped.

Rounds are interleaved and the best of each is kept.
Where AtomicSolid's frame goes, part by part: ``benchmarks/bench_render_cost.py``.
"""

from __future__ import annotations

import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from springscene import config, render  # noqa: E402
from springscene.vpython.run.runner import run_program  # noqa: E402
from springscene.vpython.run.options import RunOptions

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
    import springscene.vpython.api as vp
    from springscene.vpython.draw.renderer import Renderer
    from springscene.vpython.geometry import lod as levels

    vp.reset()
    balls = [vp.sphere(pos=vp.vector(*p), radius=RADIUS, color=vp.color.red)
             for p in _grid(N_SPHERES)]
    r = Renderer(vp.scene, lod=levels.DEFAULT if lod else levels.FULL)
    r.frame()
    start = time.perf_counter()
    for _ in range(FRAMES):
        for b in balls:
            b.pos = b.pos + vp.vector(0, 0, 0.01)
        r.frame()
    seconds = time.perf_counter() - start
    r.close()
    return seconds


def wiki_program(out: Path) -> float:
    start = time.perf_counter()
    run_program(ROOT / "examples" / "wiki_spring.py", out,
                RunOptions(duration=SECONDS, page=False, canvas_only=True))
    return time.perf_counter() - start


def wiki_render(out: Path) -> float:
    start = time.perf_counter()
    render.render_video(config.load(ROOT / "configs" / "wiki.toml"), out, duration=SECONDS)
    return time.perf_counter() - start


DEMOS = (("AtomicSolid", (900, 600)), ("HardSphereGas", None), ("Stars", None),
         ("RotatingBoxes", None))
DEMO_FRAMES = 9          # the first 3 (set-up) are not timed
DEMO_ROUNDS = 2


COARSE = 0.3                        # --lod for the programs with helices
HELICAL = ("AtomicSolid", "lattice")


def demo_fps(program: Path, size, antialias: bool, lod: bool, tmp: Path,
             coarse: float | None = None) -> float:
    """Steady frames/s of a demo run to MP4 (frames 3 on), with or without level of detail
    (``coarse``: helices within that many pixels, ``springscene vpython --lod``)."""
    import random

    from springscene.vpython.draw import culling
    from springscene.vpython.geometry import lod as levels

    src = program.read_text()
    if size is not None:
        src = src.replace("from vpython import *", "from vpython import *\n"
                          f"scene.width = {size[0]}; scene.height = {size[1]}", 1)
    prog = tmp / program.name
    prog.write_text(src)
    saved = culling.cull_back_faces
    if not lod:
        culling.cull_back_faces = lambda *args: None
    times: list[float] = []
    random.seed(1)
    try:
        run_program(prog, tmp / "demo.mp4",
                    RunOptions(frames=DEMO_FRAMES, antialias=antialias, page=False,
                               canvas_only=True, lod=coarse if lod else levels.FULL),
                    on_frame=lambda i, image: times.append(time.perf_counter()))
    finally:
        culling.cull_back_faces = saved
    steady = times[3:]
    return (len(steady) - 1) / (steady[-1] - steady[0])


def demos(tmp: Path) -> None:
    """VPython's demos where they are (not in this repository), and always
    examples/lattice.py at AtomicSolid's 900 x 600: a 4 x 4 x 4 crystal on 144 helices."""
    folder = Path(os.environ.get("SPRINGSCENE_DEMOS", "/work/demos"))
    found = [(folder / f"{name}.py", size) for name, size in DEMOS
             if (folder / f"{name}.py").is_file()]
    if not found:
        print(f"VPython demos: none in {folder} (set SPRINGSCENE_DEMOS); only the lattice")
    found.append((ROOT / "examples" / "lattice.py", (900, 600)))
    print(f"VPython programs to MP4 (--canvas-only), steady frames/s (best of {DEMO_ROUNDS}), "
          "level of detail against full detail:")
    for path, size in found:
        name = path.stem
        best = {}
        for _ in range(DEMO_ROUNDS):
            for aa in (False, True):
                for lod in (False, True, COARSE) if name in HELICAL else (False, True):
                    fps = demo_fps(path, size, aa, bool(lod), tmp,
                                   COARSE if lod == COARSE else None)
                    best[aa, lod] = max(best.get((aa, lod), 0.0), fps)
        where = f" at {size[0]} x {size[1]}" if size else ""
        print(f"  {name}{where}:")
        for aa in (False, True):
            print(f"    {'anti-aliased' if aa else 'draft':<13} {best[aa, True]:6.1f} frames/s "
                  f"(full detail {best[aa, False]:5.1f}, {best[aa, True] / best[aa, False]:.2f}x)"
                  + (f"; --lod {COARSE}: {best[aa, COARSE]:.1f} "
                     f"({best[aa, COARSE] / best[aa, False]:.2f}x)" if name in HELICAL else ""))


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
    with tempfile.TemporaryDirectory() as tmp:
        demos(Path(tmp))


if __name__ == "__main__":
    main()
