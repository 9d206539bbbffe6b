"""Where a frame of VPython's AtomicSolid demo goes: springscene's renderer taken apart.

AtomicSolid (vpython-jupyter ``Demos_no_notebook``: 64 atoms, 144 helix springs) at
900 x 600, its first frame (the program up to its ``while True`` loop), drawn by
:class:`springscene.vpython.draw.renderer.Renderer` draft and anti-aliased, and timed part by
part (best of a few repeats, ms):

* ``sync``: the program's objects to meshes (numpy: placing the helices and spheres);
* ``upload``: VTK's extra cost of a render after the meshes changed (its vertex
  buffers rebuilt) over a render of an unchanged scene;
* ``render``: ``vtkRenderWindow.Render`` of an unchanged scene, all of it in Mesa's
  llvmpipe, and the same with one batch shown at a time, with back faces drawn, with
  GlowScript's fragment-shader rules removed (``materials.shade_as_glowscript``),
  unlit, with the spheres at 10 slices instead of 30 (same pixels covered, a ninth of
  the triangles), and anti-aliased with the back faces culled in front (front faces
  culled: the MSAA rasterisation of the visible triangles left out);
* ``readback``: ``GetPixelData`` of the frame.

Run ``.venv/bin/python benchmarks/bench_render_cost.py`` (about a minute). The demo is
read from ``$SPRINGSCENE_DEMOS`` (default /work/demos).
"""

from __future__ import annotations

import math
import os
import random
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

REPEATS = 6


def atomic_solid(antialias: bool):
    """A Renderer holding AtomicSolid's first frame, drawn once for its camera."""
    import springscene.vpython.api as vp  # noqa: PLC0415  heavy: vtk, pyvista
    from springscene.vpython.draw.renderer import Renderer  # noqa: PLC0415  heavy: vtk, pyvista

    folder = Path(os.environ.get("SPRINGSCENE_DEMOS", "/work/demos"))
    src = (folder / "AtomicSolid.py").read_text().split("while True:")[0]
    vp.reset()
    vp.scene.width, vp.scene.height = 900, 600
    names = {k: getattr(vp, k) for k in dir(vp) if not k.startswith("_")}
    names.update(pi=math.pi, sqrt=math.sqrt)
    random.seed(1)
    exec(src.replace("from vpython import *", ""), names)
    r = Renderer(vp.scene, antialias=antialias)
    r.frame()
    _touch(vp)
    r.frame()                      # redrawn at the level of detail for the camera
    return r, vp


def _touch(vp) -> None:
    for o in vp.scene._objects:
        o._dirty = True


def _best(fn, repeats: int = REPEATS) -> float:
    times = []
    for _ in range(repeats):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return 1000 * min(times)


def _modified(r) -> None:
    for b in r._batches.values():
        if b.actor is not None:
            b.mesh.GetPoints().Modified()


def frame_parts(r, vp) -> dict:
    """sync, upload, render and readback of one frame, ms."""
    from vtkmodules.vtkCommonCore import vtkUnsignedCharArray  # noqa: PLC0415  heavy: vtk, pyvista

    win = r.window.ren_win
    buf = vtkUnsignedCharArray()
    win.Render()
    parts = {"sync": _best(lambda: (_touch(vp), r.sync())),
             "render": _best(win.Render)}
    parts["upload"] = _best(lambda: (_modified(r), win.Render())) - parts["render"]
    parts["readback"] = _best(lambda: win.GetPixelData(0, 0, r.width - 1, r.height - 1, 0,
                                                       buf, 0))
    return parts


def render_variants(r) -> dict:
    """Render of an unchanged scene, ms, under each change (undone after)."""
    win = r.window.ren_win
    batches = {k[0]: b for k, b in r._batches.items() if b.actor is not None}
    out = {"as drawn": _best(win.Render)}
    for name, b in batches.items():
        for other in batches.values():
            other.actor.SetVisibility(other is b)
        out[f"{name}s alone"] = _best(win.Render)
    for b in batches.values():
        b.actor.SetVisibility(True)
    props = [b.actor.GetProperty() for b in batches.values()]
    for p in props:
        p.SetBackfaceCulling(False)
    out["back faces drawn"] = _best(win.Render)
    for p in props:
        p.SetBackfaceCulling(True)
        p.SetFrontfaceCulling(True)          # VTK culls one side only: the front one now
    out["front faces culled instead"] = _best(win.Render)
    for p in props:
        p.SetFrontfaceCulling(False)
    for b in batches.values():
        b.actor.GetShaderProperty().ClearAllFragmentShaderReplacements()
    out["no GlowScript shader rules"] = _best(win.Render)
    for p in props:
        p.LightingOff()
    out["unlit"] = _best(win.Render)
    for p in props:
        p.LightingOn()
    for b in batches.values():
        b._shade()
    return out


def sphere_slices(r, vp) -> tuple[float, float]:
    """Spheres alone at 30 slices and at 10 (same pixels, a ninth of the triangles)."""
    from springscene.vpython.geometry.lod import LevelOfDetail  # noqa: PLC0415  heavy: vtk

    win = r.window.ren_win
    batches = {k[0]: b for k, b in r._batches.items() if b.actor is not None}
    for name, b in batches.items():
        b.actor.SetVisibility(name == "sphere")
    at30 = _best(win.Render)
    saved, r.lod = r.lod, LevelOfDetail(sphere_steps=(10,))
    try:
        _touch(vp)
        r.sync()
        for name, b in batches.items():
            b.actor.SetVisibility(name == "sphere")
        return at30, _best(win.Render)
    finally:
        r.lod = saved


def main() -> None:
    from springscene.view import backend  # noqa: PLC0415  heavy: vtk, pyvista

    backend.select("auto")
    for antialias in (False, True):
        r, vp = atomic_solid(antialias)
        sizes = ", ".join(f"{k[0]} {b.mesh.n_cells} triangles"
                          for k, b in r._batches.items() if b.actor is not None)
        print(f"AtomicSolid, 900 x 600, {'anti-aliased (4x MSAA)' if antialias else 'draft'}"
              f" ({sizes}), ms:")
        parts = frame_parts(r, vp)
        print("  " + ", ".join(f"{k} {v:.1f}" for k, v in parts.items())
              + f"  (about {1000 / sum(parts.values()):.1f} frames/s before encoding)")
        for name, ms in render_variants(r).items():
            print(f"  render, {name:<28} {ms:7.1f}")
        at30, at10 = sphere_slices(r, vp)
        print(f"  render, spheres alone at 30 / 10 slices  {at30:.1f} / {at10:.1f}")
        r.close()
    print(f"(numpy {np.__version__}; LP_NUM_THREADS={os.environ.get('LP_NUM_THREADS', 'unset')})")


if __name__ == "__main__":
    main()
