"""How finely curved objects are drawn for the camera's view: the level of detail.

A polygon of ``n`` sides round a circle of ``r`` pixels strays from it by its sagitta,
``r (1 - cos(pi / n))``. Spheres and helices are drawn with the fewest slices, chords
and sides whose sagitta on screen stays within a tolerance (:func:`steps_for`), so that
a hundred thousand small spheres are a few million triangles, not 180 million, and the
picture stays within the image tolerance of VPython's full detail (at most 0.05 % of
pixels off by more than 24/255). A :class:`LevelOfDetail` is a renderer's setting, passed
down to what makes the meshes: :data:`DEFAULT`, :data:`FULL` (VPython's own detail
whatever the size, what the default is measured against), or :func:`coarser`
(``springscene vpython --lod PX``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from .meshes import SPHERE_SLICES

SPHERE_STEPS = (SPHERE_SLICES, 24, 20, 16, 14, 12, 10, 8, 6)   # slices, most first


def steps_for(radius_px: float, steps: tuple[int, ...], tolerance: float) -> int:
    """The fewest of ``steps`` (most first) whose polygon of that many sides around a
    circle of ``radius_px`` pixels stays within ``tolerance`` px of it."""
    best = steps[0]
    for n in steps:
        if radius_px * (1 - math.cos(math.pi / n)) <= tolerance:
            best = n
        else:
            break
    return best


@dataclass(frozen=True)
class LevelOfDetail:
    """The tolerances a renderer draws curved objects to.

    ``helix_px``: the largest sagitta, in pixels, of a helix mesh's chords (0.03 px keeps
    drafted pictures within the image tolerance: the lattice example 0.026 % of pixels
    off, AtomicSolid 0); ``side_share``: the wire's sides get this share of it (fewer
    sides also move the specular highlight, which the sagitta does not count);
    ``sphere_px`` and ``sphere_steps``: a sphere's slices likewise (the lattice example's
    atoms, 5 to 20 px, with no pixel off); ``antialiased_full``: anti-aliased pictures
    keep VPython's 60 x 16 helices (fewer moved AtomicSolid's highlights outside the
    tolerance: 40 x 16 0.091 %, 60 x 10 0.085 %); ``capsule_px``: the largest sagitta,
    in pixels, of a helix's chords drawn as capsules, drafted and anti-aliased (their wire
    is round whatever the chords, and shaded round its tangent: an AtomicSolid-like
    lattice at 900 x 600 with 32 chords a coil, 0.1 px, is as near VPython's full mesh as
    with 60, 0.17 % of pixels off by more than 24/255 against 0.28 % drafted, 0.51 against
    0.61 % anti-aliased; 0.3 px, 20 chords, 0.30 and 0.73 %).
    """

    helix_px: float = 0.03
    side_share: float = 0.5
    sphere_px: float = 0.1
    sphere_steps: tuple[int, ...] = SPHERE_STEPS
    antialiased_full: bool = True
    capsule_px: float = 0.1

    def sphere_slices(self, radius_px: float) -> int:
        """Slices for a sphere ``radius_px`` pixels across its radius: VPython's 30 from
        about 11 px up (the wiki's ball is about 40 px), 10 at 2 px, 6 under a pixel."""
        return steps_for(radius_px, self.sphere_steps, self.sphere_px)

    def full_helices(self, antialias: bool) -> bool:
        """Whether helices keep VPython's 60 x 16 whatever their size."""
        return antialias and self.antialiased_full


DEFAULT = LevelOfDetail()
#: VPython's own detail whatever the size: 60 chords a coil, 16 sides, 30 slices
FULL = LevelOfDetail(helix_px=0.0, sphere_steps=(SPHERE_SLICES,), capsule_px=0.0)


def coarser(px: float | None) -> LevelOfDetail:
    """Helices within ``px`` pixels of the true curves (the chords and the wire's sides
    alike), anti-aliased too: faster, and outside the image tolerance of full detail
    (AtomicSolid at 0.3 px: 3.6x the frames/s drafted, 5.7x anti-aliased, 1.4 and 2.5 %
    of pixels off by more than 24/255). None: :data:`DEFAULT`."""
    if px is None:
        return DEFAULT
    return LevelOfDetail(helix_px=px, side_share=1.0, antialiased_full=False,
                         capsule_px=max(px, DEFAULT.capsule_px))
