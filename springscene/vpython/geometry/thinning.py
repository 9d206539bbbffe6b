"""Curves drawn for the camera's view: GL draws nothing of a segment much under a pixel,
so a thin line (or tube) of thousands of points is thinned on screen before drawing.

:func:`thin_line` drops the points closer than ``LINE_MIN_SEGMENT_PX`` along the line
on screen (the renderer draws thin curves once the camera is placed). Autoscale bounds
them by VPython's own rule (:mod:`..draw.autoscale`).
"""

from __future__ import annotations

import numpy as np

LINE_MIN_SEGMENT_PX = 1.5  # px: shorter segments of a thin line are merged


def thin_line(chunk, view, min_px: float = LINE_MIN_SEGMENT_PX):
    """A polyline's points (positions, colours, radii) with those closer than ``min_px``
    along it on the screen dropped: GL draws nothing of a segment much under a pixel,
    so a curve of thousands of points would come out dotted or not at all."""
    pos = chunk[0]
    if len(pos) <= 2:
        return chunk
    pixels = view.project(pos)
    seen = np.isfinite(pixels).all(axis=1)        # a point in the camera's plane: kept
    seg = np.linalg.norm(np.diff(pixels, axis=0), axis=1)
    seg = np.where(np.isfinite(seg), seg, min_px)
    along = np.concatenate([[0.0], np.cumsum(seg)])
    step = np.floor(along / min_px)
    keep = np.concatenate([[True], step[1:] != step[:-1]]) | ~seen
    keep[-1] = True
    if keep.all():
        return chunk
    return tuple(a[keep] for a in chunk)
