"""Helices drawn into their batch: as GlowScript draws them, a curve of chords each a
ray-cast capsule (:func:`draw_capsules`, into a :class:`.capsules.CapsuleBatch`), or all
helices of one look as one mesh (:func:`draw`); either at the renderer's level of detail,
redrawn when the camera asks for another; a mesh's far side skipped when its wires are
thin on screen (:mod:`..geometry.helices` makes the meshes and the chords)."""

from __future__ import annotations

import numpy as np

from ..geometry import helices, placement
from ...view.geometry import CHORDS_PER_COIL
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


MIN_CAPSULE_CHORDS = 2000   # a look's helices are capsules from this many chords (renderer)


def chords(objs) -> int:
    """The chords of the helices ``objs`` at VPython's full detail (60 a coil)."""
    return int(sum(round(float(o._coils) * CHORDS_PER_COIL) for o in objs))


def draw_capsules(batch, objs, view, style, full: bool = False,
                  lod: LevelOfDetail = DEFAULT) -> None:
    """Put the helices ``objs`` into the capsule batch ``batch`` as GlowScript draws a
    helix: the curve through its ``coils * 60 + 1`` centre-line points, each chord a
    capsule of the wire's radius in the helix's colour (:mod:`.capsules`; its wire a true
    circle, so only the chords have a level of detail). A group of helices small on
    screen gets fewer chords a coil, drafted or anti-aliased: the fewest of
    :data:`..geometry.helices.CHORD_STEPS` whose chords stray at most ``lod.capsule_px``
    (0.1 px by default) from the coil's circle as its nearest helix is seen
    (:func:`..geometry.helices.capsule_chords`; ``full`` is the meshes' rule, not used).
    Every helix's chords are made in one numpy pass per group; the batch's arrays are
    rewritten in place."""
    a = helices.helix_arrays(objs)
    batch.helix_arrays, batch.helix_chords = a, {}
    parts = []
    for shape, idx in helices.groups(a).items():
        chords = helices.capsule_chords(a, idx, view, lod.capsule_px)
        line, slope = helices.centre_lines(*shape, chords, a["pos"][idx], a["R"][idx],
                                           a["length"][idx], a["radius"][idx])
        n = line.shape[1] - 1
        rgb = np.clip(np.rint(a["color"][idx] * 255), 0, 255).astype(np.uint8)
        wire = np.repeat(a["wire"][idx][:, None], n, axis=1)
        joined = -wire                 # a joint's radius negative (:mod:`.capsules`)
        parts.append((line[:, :-1].reshape(-1, 3), line[:, 1:].reshape(-1, 3),
                      np.concatenate([wire[:, :1], joined[:, 1:]], axis=1).ravel(),
                      np.concatenate([joined[:, :-1], wire[:, -1:]], axis=1).ravel(),
                      np.repeat(rgb, n, axis=0),
                      slope[:, :-1].reshape(-1, 3), slope[:, 1:].reshape(-1, 3)))
        batch.helix_chords[shape] = chords
    if not parts:
        batch.hide()
        return
    start, end, r_start, r_end, rgb, t_start, t_end = (np.concatenate(c) for c in zip(*parts))
    batch.set_segments(start, end, r_start, r_end, rgb, rgb, style, view, (t_start, t_end))


def detail_changed(batch, view, full: bool, lod: LevelOfDetail = DEFAULT) -> bool:
    """Whether ``batch``'s helices (drawn by :func:`draw` or :func:`draw_capsules`) need
    another level of detail for ``view``: any group's chords or sides differ from those
    drawn."""
    a = batch.helix_arrays
    chords = getattr(batch, "helix_chords", None)
    if chords is not None:
        return any(helices.capsule_chords(a, idx, view, lod.capsule_px) != chords.get(shape)
                   for shape, idx in helices.groups(a).items())
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
