"""Image regression with a stated tolerance: the project's tests on springscene's own
comparator (:mod:`springscene.view.compare`) and pytest plugin
(:func:`springscene.pytest_plugin.verify`).

Two images match when they have the same size, at most ``MAX_BAD_FRACTION`` of
their pixels differ by more than ``PIXEL_TOLERANCE`` (0-255) in any channel, and
the mean absolute difference is at most ``MAX_MEAN_DIFF``. The tolerance absorbs
the rasteriser's anti-aliasing noise between Mesa's EGL and OSMesa drivers; a
ball moved by one pixel or a changed colour fails it. A failed comparison leaves the
new picture and a diff image in the folder its message names.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from springscene import pytest_plugin
from springscene.view import compare as comparator

PIXEL_TOLERANCE = comparator.PIXEL_TOLERANCE
MAX_BAD_FRACTION = comparator.TOLERANCE
MAX_MEAN_DIFF = comparator.MAX_MEAN_DIFF


def compare(image: np.ndarray, baseline: np.ndarray) -> tuple[float, float]:
    """(fraction of pixels off by more than the tolerance, mean absolute difference)."""
    assert image.shape == baseline.shape, f"size {image.shape} != baseline {baseline.shape}"
    result = comparator.compare(image, baseline)
    return result.bad_fraction, result.mean_difference


def check(image: np.ndarray, baseline_path: Path, regen: bool) -> None:
    """``image`` against the baseline (written instead when ``regen``); a missing
    baseline fails (`make baselines` writes them)."""
    __tracebackhide__ = True
    pytest_plugin.verify(image, baseline_path, regen=regen, missing="fail")
