"""VPython's camera, in plain numpy: placement from center/forward/range/fov, autoscale, projection.

The numbers are GlowScript's (see ``shared/vpython-reference.md``): a perspective
camera with vertical field of view ``fov``, at ``center - norm(forward) * d`` where
``d = range / tan(fov/2)`` on a landscape canvas, near = d/100, far = 10 d.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np


@dataclass(frozen=True)
class View:
    """Everything a renderer needs to place a camera, and a projection to check it with."""

    position: np.ndarray
    focal_point: np.ndarray
    up: np.ndarray
    fov: float          # vertical, radians
    near: float
    far: float
    width: int
    height: int

    def project(self, points: np.ndarray) -> np.ndarray:
        """Pixel coordinates (column, row from the top) of world ``points`` (..., 3)."""
        points = np.asarray(points, dtype=float)
        fwd = self.focal_point - self.position
        fwd = fwd / np.linalg.norm(fwd)
        right = np.cross(fwd, self.up)
        if np.linalg.norm(right) < 1e-12:      # looking along up: x's side, as autoscale takes
            right = np.cross(fwd, (1.0, 0.0, 0.0))
        right /= np.linalg.norm(right)
        up = np.cross(right, fwd)
        rel = points - self.position
        depth = rel @ fwd
        half_h = math.tan(self.fov / 2)
        ndc_y = (rel @ up) / depth / half_h
        ndc_x = (rel @ right) / depth / (half_h * self.width / self.height)
        col = (ndc_x + 1) * self.width / 2
        row = (1 - ndc_y) * self.height / 2
        return np.stack([col, row], axis=-1)


def distance(range_: float, fov: float, width: int, height: int) -> float:
    """Camera distance from ``center`` for a given ``range`` (VPython's rule)."""
    d = range_ / math.tan(fov / 2)
    return d if width >= height else d * height / width


def view(center, forward, up, fov: float, range_: float, width: int, height: int) -> View:
    center = np.asarray(center, dtype=float)
    fwd = np.asarray(forward, dtype=float)
    fwd = fwd / np.linalg.norm(fwd)
    d = distance(range_, fov, width, height)
    return View(position=center - fwd * d, focal_point=center, up=np.asarray(up, dtype=float),
                fov=fov, near=d / 100, far=10 * d, width=width, height=height)


def autoscale_range(bounds: np.ndarray, center, fov: float, width: int, height: int) -> float:
    """The ``range`` VPython's autoscale sets for objects with axis-aligned ``bounds``.

    ``bounds`` is (n, 2, 3): the min and max corner of each object. For each
    object the largest |bbox - center| per axis gives xx, yy, zz; with
    c = cot(fov/2), zx = xx c + zz and zy = yy c + zz, maximised over objects.
    """
    b = np.asarray(bounds, dtype=float).reshape(-1, 2, 3) - np.asarray(center, dtype=float)
    ext = np.abs(b).max(axis=1)                     # (n, 3): xx, yy, zz per object
    c = 1.0 / math.tan(fov / 2)
    zx = float(np.max(ext[:, 0] * c + ext[:, 2]))
    zy = float(np.max(ext[:, 1] * c + ext[:, 2]))
    if width >= height:
        if zx * height / width > zy:
            return 1.1 * (height / width) * zx / c
        return 1.1 * zy / c
    if zy * width / height > zx:
        return 1.1 * (width / height) * zy / c
    return 1.1 * zx / c


class Autoscaler:
    """VPython's autoscale over time: the range follows the scene only when it grows,
    or when it shrinks below a third of the last extent."""

    def __init__(self) -> None:
        self.range: float | None = None

    def update(self, bounds, center, fov, width, height) -> float:
        r = autoscale_range(bounds, center, fov, width, height)
        if self.range is None or r > self.range or r < self.range / 3:
            self.range = r
        return self.range
