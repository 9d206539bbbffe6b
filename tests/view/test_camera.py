"""VPython's camera placement and autoscale."""

import math

import numpy as np
import pytest

from springscene.view import camera


def test_distance_is_sqrt3_range_for_fov_60():
    assert camera.distance(1.0, math.pi / 3, 900, 600) == pytest.approx(math.sqrt(3))
    assert camera.distance(1.0, math.pi / 3, 600, 900) == pytest.approx(math.sqrt(3) * 1.5)


def test_autoscale_of_the_wiki_scene_by_hand():
    # holder box 0.2 x 0.01 x 0.2 at the origin, ball r = 0.025 at y0, centre (0, -0.1, 0)
    y0 = -0.18533333333333335
    bounds = [[(-0.1, -0.005, -0.1), (0.1, 0.005, 0.1)],
              [(-0.025, y0 - 0.025, -0.025), (0.025, y0 + 0.025, 0.025)]]
    c = math.sqrt(3)
    zy_ball = abs(y0 - 0.025 + 0.1) * c + 0.025  # per object: its own yy and zz
    zy_holder = 0.105 * c + 0.1
    zy = max(zy_ball, zy_holder)
    zx = 0.1 * c + 0.1
    assert zx * 600 / 900 < zy
    assert camera.autoscale_range(bounds, (0, -0.1, 0), math.pi / 3, 900, 600) == pytest.approx(1.1 * zy / c)


def test_autoscale_wide_scene_uses_x():
    bounds = [[(-2, -0.1, -0.1), (2, 0.1, 0.1)]]
    c = math.sqrt(3)
    r = camera.autoscale_range(bounds, (0, 0, 0), math.pi / 3, 900, 600)
    assert r == pytest.approx(1.1 * (600 / 900) * (2 * c + 0.1) / c)


def test_autoscaler_grows_and_only_shrinks_below_a_third():
    a = camera.Autoscaler()
    small = [[(-1, -1, 0), (1, 1, 0)]]
    big = [[(-2, -2, 0), (2, 2, 0)]]
    tiny = [[(-0.1, -0.1, 0), (0.1, 0.1, 0)]]
    args = ((0, 0, 0), math.pi / 3, 900, 600)
    r1 = a.update(small, *args)
    r2 = a.update(big, *args)
    assert r2 == pytest.approx(2 * r1)
    assert a.update(small, *args) == r2       # shrinking by half: kept
    assert a.update(tiny, *args) < r2 / 3     # below a third: follows


def test_view_projects_center_to_middle():
    v = camera.view((0, -0.1, 0), (0, 0, -1), (0, 1, 0), math.pi / 3, 0.2, 900, 600)
    assert np.allclose(v.position, (0, -0.1, 0.2 * math.sqrt(3)))
    assert v.near == pytest.approx(v.far / 1000)
    col, row = v.project([(0, -0.1, 0), (0, 0.1, 0), (0, -0.3, 0)]).T
    assert np.allclose(col, 450)
    assert np.allclose(row, [300, 0, 600])    # range is the half-height at the centre plane


def test_a_view_looking_along_up_still_projects():
    # scene.forward = vector(0, -1, 0) with the default up: a program looking straight down
    import warnings
    v = camera.view((0, 0, 0), (0, -1, 0), (0, 1, 0), math.pi / 3, 10.0, 600, 400)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        px = v.project(np.array([[0.0, 0.0, 0.0], [5.0, 0.0, 0.0]]))
    assert np.isfinite(px).all()
    assert px[0] == pytest.approx([300, 200]) and px[1][1] < 200      # x is up the picture
