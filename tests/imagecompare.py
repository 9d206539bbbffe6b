"""Image regression with a stated tolerance.

Two images match when they have the same size, at most ``MAX_BAD_FRACTION`` of
their pixels differ by more than ``PIXEL_TOLERANCE`` (0-255) in any channel, and
the mean absolute difference is at most ``MAX_MEAN_DIFF``. The tolerance absorbs
the rasteriser's anti-aliasing noise between Mesa's EGL and OSMesa drivers; a
ball moved by one pixel or a changed colour fails it.
"""

from __future__ import annotations

from pathlib import Path

import imageio.v3 as iio
import numpy as np

PIXEL_TOLERANCE = 24
MAX_BAD_FRACTION = 0.0005
MAX_MEAN_DIFF = 0.2


def compare(image: np.ndarray, baseline: np.ndarray) -> tuple[float, float]:
    """(fraction of pixels off by more than the tolerance, mean absolute difference)."""
    assert image.shape == baseline.shape, f"size {image.shape} != baseline {baseline.shape}"
    diff = np.abs(image.astype(np.int16) - baseline.astype(np.int16))
    return float((diff.max(axis=2) > PIXEL_TOLERANCE).mean()), float(diff.mean())


def check(image: np.ndarray, baseline_path: Path, regen: bool) -> None:
    if regen or not baseline_path.exists():
        if not regen:
            raise AssertionError(f"no baseline {baseline_path}; run `make baselines`")
        baseline_path.parent.mkdir(parents=True, exist_ok=True)
        iio.imwrite(baseline_path, image)
        return
    bad, mean = compare(image, iio.imread(baseline_path)[..., :3])
    assert bad <= MAX_BAD_FRACTION and mean <= MAX_MEAN_DIFF, (
        f"{baseline_path.name}: {bad:.4%} of pixels off by > {PIXEL_TOLERANCE} "
        f"(allowed {MAX_BAD_FRACTION:.2%}), mean difference {mean:.3f} (allowed {MAX_MEAN_DIFF})")
