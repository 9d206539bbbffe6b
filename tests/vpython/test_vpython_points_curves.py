"""Points and thin curves drawn as GlowScript 3.2 draws them (WebGLRenderer.js ``render``):
a pixel-sized point is a lit sphere 20 s across (radius 0) or 2 s radius across, a curve
of radius 0 a lit tube of radius 4 range / width (2 s), with s = 2 range / width; so on a
640 x 400 canvas (200 px per range) 12.5 px, 1.25 radius px and 2.5 px, at any range."""

from __future__ import annotations

import numpy as np
import pytest

import springscene.vpython.api
from springscene.vpython.geometry import point_meshes
from springscene.vpython.draw.renderer import Renderer


@pytest.fixture
def vp():
    springscene.vpython.api.reset()
    return springscene.vpython.api


def frame_of(vp):
    r = Renderer(vp.scene)
    try:
        return r.frame().astype(int), r
    finally:
        r.close()


def extent(img: np.ndarray, row: int, col: int, reach: int = 20) -> tuple[int, int]:
    """Width and height in px of the bright blob round (row, col) (above 24 of 255), the
    way real VPython's pictures measure: its 12.5 px points are 13 x 13 px, its radius-8
    points 11 x 10 px, its thin curves 3 px across."""
    grey = img.max(axis=2) if img.ndim == 3 else img
    win = grey[row - reach:row + reach + 1, col - reach:col + reach + 1] > 24
    rows, cols = np.nonzero(win)
    return int(cols.max() - cols.min() + 1), int(rows.max() - rows.min() + 1)


def test_sizes_follow_vpython_rule():
    # s = 2 range / width; radius 0: 20 s; radius r: 2 s r; curve: 4 range / width
    assert point_meshes.point_diameters(np.array([0.0, 8.0]), 10.0, 640) == \
        pytest.approx([20 * 20 / 640, 2 * 20 / 640 * 8])
    assert point_meshes.thin_radius(10.0, 640) == pytest.approx(40 / 640)
    assert point_meshes.thin_radii(np.array([0.0, 0.3]), 10.0, 640) == \
        pytest.approx([40 / 640, 0.3])


@pytest.mark.parametrize("rng", [2.0, 10.0])
def test_pixel_points_are_lit_balls_of_vpython_size_at_any_range(vp, rng):
    vp.scene.range = rng
    s = rng / 200                                    # world units per px
    vp.points(pos=[vp.vector(-60 * s, 0, 0)], color=vp.color.white)           # 12.5 px
    vp.points(pos=[vp.vector(60 * s, 0, 0)], radius=8, color=vp.color.white)  # 10 px
    img, _ = frame_of(vp)
    grey = img.max(axis=2)
    for col, want in ((320 - 60, (12, 14)), (320 + 60, (10, 11))):
        w, h = extent(img, 200, col)
        assert want[0] <= w <= want[1] and want[0] <= h <= want[1]
        ball = grey[200 - 4:200 + 5, col - 4:col + 5]
        assert ball.max() - ball.min() > 40             # shaded, not a flat disc


@pytest.mark.parametrize("rng", [2.0, 10.0])
def test_thin_curve_is_a_lit_tube_2_5_px_wide_at_any_range(vp, rng):
    vp.scene.range = rng
    vp.curve(pos=[vp.vector(-rng, 0, 0), vp.vector(rng, 0, 0)], color=vp.color.white)
    img, _ = frame_of(vp)
    grey = img.max(axis=2).astype(float)
    widths = [(grey[190:211, c] > 24).sum() for c in range(250, 390, 10)]
    assert np.median(widths) == 3                     # 2.5 px, as VPython's
    # lit, not one flat colour: its faces towards the lights brighter than the others
    col = grey[190:211, 320]
    assert col.max() > 150 and col[col > 24].min() < col.max() - 30


def test_thin_curve_and_points_redrawn_when_the_range_grows(vp):
    c = vp.curve(pos=[vp.vector(-1, 0, 0), vp.vector(1, 0, 0)], color=vp.color.white)
    vp.points(pos=[vp.vector(0, 0.5, 0)], color=vp.color.white)
    r = Renderer(vp.scene)
    try:
        shots = [(r.frame(), vp.scene.range)]
        c.append(vp.vector(3, 0, 0))               # autoscale grows the range
        shots.append((r.frame(), vp.scene.range))
        assert shots[1][1] > 2.5 * shots[0][1]
        for img, rng in shots:
            w, h = extent(img, round(200 - 0.5 * 200 / rng), 320, reach=9)
            assert 12 <= w <= 14
            assert (img.max(axis=2)[185:216, 250] > 24).sum() == 3
    finally:
        r.close()
