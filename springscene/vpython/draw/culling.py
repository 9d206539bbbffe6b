"""What VTK need not draw: the far side of opaque closed surfaces, and its frustum culler's
per-frame bounds."""

from __future__ import annotations

import numpy as np

def cull_back_faces(batch, style: dict, view=None, centres=None, radii=None) -> None:
    """Opaque closed surfaces (spheres, a helix's wire) skip their far side: its
    triangles face away from the camera and are hidden by the near side anyway, and
    llvmpipe's render of AtomicSolid takes about half the time (the picture differs
    in 0.001 % of pixels, by at most 37/255, anti-aliased). Transparent ones keep it.
    The triangles are counter-clockwise seen from outside. GlowScript culls nothing
    (WebGLRenderer.js leaves ``gl.CULL_FACE`` off), so with ``centres`` and ``radii``
    (spheres) nothing is culled unless a camera (``view``) is outside all of them."""
    if batch.actor is None:
        return
    cull = style["opacity"] >= 1
    if centres is not None:
        cull = cull and view is not None and bool(np.all(
            np.linalg.norm(centres - view.position, axis=1) > radii + 2 * view.near))
    batch.actor.GetProperty().SetBackfaceCulling(bool(cull))


def no_frustum_culler(renderer) -> None:
    """Drop VTK's frustum culler from ``renderer``. It skips only actors wholly outside
    the view (no pixel changes; AtomicSolid measured identical), but asks every actor
    for its bounds at every render, and a batch whose points moved has them recomputed
    over its cells (VTK 9.5 ``vtkPolyData::GetCellsBounds``): 4-8 ms a frame for
    AtomicSolid's 900,000 triangles. The renderer places its camera and clipping range
    itself (``apply_view``), so nothing else asks for them."""
    renderer.GetCullers().RemoveAllItems()
