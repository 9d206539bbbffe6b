"""Helices drawn into their batch: all helices of one look as one mesh at the renderer's
level of detail, redrawn when the camera asks for another, their far side skipped when
their wires are thin on screen (:mod:`..geometry.helices` makes the meshes)."""

from __future__ import annotations

import numpy as np

from ..geometry import helices, placement
from ..geometry.lod import DEFAULT, LevelOfDetail
from . import culling

def draw(batch, objs, view, style, full: bool = False, lod: LevelOfDetail = DEFAULT) -> None:
    """Put the helices ``objs`` into ``batch`` (triangles rebuilt only when the groups
    or their detail change); the batch hidden when no helix has a length. Autoscale
    bounds helices by VPython's rule (:mod:`.autoscale`), so no bounds are made here."""
    a = helices.helix_arrays(objs)
    m = helices.mesh(objs, view, triangles=False, full=full, bounds=False, arrays=a, lod=lod)
    if m is None:
        batch.hide()
        return
    points, normals, _, rgb, _, signature = m
    signature = ("helix",) + signature
    cells = None
    if signature != batch.signature:
        cells = placement.vtk_cells(np.concatenate([
            placement.tile(helices.template(c, w, n, s).triangles,
                           len(helices.template(c, w, n, s).s), k)
            + start for (c, w, n, s, k), start in zip(signature[1:], _starts(signature[1:]))]))
    batch.set(points, normals, rgb, cells, signature, style)
    # GlowScript culls nothing: a thick wire's open ends show its inside (the fidelity
    # scene's hanging helix: IoU 0.973 culled, 0.981 not); a wire a few pixels thick
    # hides its far side (AtomicSolid: 0.002 % of pixels differ), so that goes
    culling.cull_back_faces(batch, style if _thin(a, view) else {**style, "opacity": 0.0})
    batch.helix_arrays = a      # :func:`detail_changed` asks again when the camera moves


def detail_changed(batch, view, full: bool, lod: LevelOfDetail = DEFAULT) -> bool:
    """Whether ``batch``'s helices (drawn by :func:`draw`) need another level of detail
    for ``view``: any group's chords or sides differ from those drawn."""
    a = batch.helix_arrays
    drawn = {(c, w): (n, s) for c, w, n, s, _ in batch.signature[1:]}
    return any(helices.detail(a, idx, view, full, lod) != drawn.get(shape)
               for shape, idx in helices.groups(a).items())


THIN_WIRE_PX = 4.0     # px: a wire radius on screen below which its back faces are culled
                       # (AtomicSolid at 900 x 600: 3.4 px, culled: 0.002 % of pixels differ)


def _thin(a: dict, view) -> bool:
    """Every wire (of :func:`..geometry.helices.helix_arrays` ``a``) under :data:`THIN_WIRE_PX` in radius
    on screen."""
    if view is None:
        return False
    end = a["pos"] + a["R"][:, :, 0] * a["length"][:, None]
    ppu = np.maximum(helices.pixels_per_unit(view, a["pos"], a["radius"] + a["wire"]),
                     helices.pixels_per_unit(view, end, a["radius"] + a["wire"]))
    return bool(np.max(a["wire"] * ppu) < THIN_WIRE_PX)


def _starts(groups) -> list[int]:
    sizes = [len(helices.template(c, w, n, s).s) * k for c, w, n, s, k in groups]
    return list(np.cumsum([0] + sizes[:-1]))
