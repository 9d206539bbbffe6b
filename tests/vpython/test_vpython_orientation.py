"""``axis`` and ``up`` given together in a constructor, turned as VPython 7.6.5 turns them.

vpython.py ``standardAttributes.setup`` takes ``axis``, then ``size``, then ``up`` (attrLists
``['axis', 'size', 'up']``): setting axis turns the default up (0, 1, 0) by the rotation
taking (1, 0, 0) to the axis (vector.py ``adjust_up``, only when axis and up are not
already square); setting up then turns the *axis* by the rotation taking that up to the
given one (``adjust_axis``). So up stays exactly as given and the axis moves. GlowScript
receives the two already square and keeps them. The expected numbers below were computed
with real VPython 7.6.5's own ``vector.py`` functions; the pictures are real VPython's.
"""

from __future__ import annotations

import numpy as np
import pytest

import springscene.vpython.api as vpython_module
from springscene.vpython.draw.renderer import Renderer

# (axis, up) given -> (axis, up) VPython 7.6.5 ends with (its vector.py adjust_up/adjust_axis)
CASES = [
    ((0, 1, 0), (1, 1, 0), (0.707107, -0.707107, 0.0), (1, 1, 0)),
    ((1, 1, 1), (0, 1, 0), (1.322781, 0.0, 1.118146), (0, 1, 0)),
    ((1, 0.5, 0.3), (0.2, 1, 1), (1.133795, -0.233378, 0.006619), (0.2, 1, 1)),
    ((1, 0.3, 0), (0, 0.5, 1), (1.02699, 0.168026, -0.084013), (0, 0.5, 1)),
    ((1, 1, 0), (1, 0, 1), (1.0, 0.0, -1.0), (1, 0, 1)),
    ((1, 1, 0), (0, 0, 1), (1.0, 1.0, 0.0), (0, 0, 1)),     # already square: nothing turns
    ((-1, 0, 0), (0, 1, 1), (-1.0, 0.0, 0.0), (0, 1, 1)),
]
KINDS = ["box", "cylinder", "cone", "pyramid", "arrow", "helix", "ellipsoid", "sphere", "ring"]


@pytest.fixture
def vp():
    vpython_module.reset()
    return vpython_module


def unit(v) -> np.ndarray:
    v = np.asarray(v, float)
    return v / np.linalg.norm(v)


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("axis, up, want_axis, want_up", CASES)
def test_up_stays_as_given_and_the_axis_turns(vp, kind, axis, up, want_axis, want_up):
    obj = getattr(vp, kind)(axis=vp.vector(*axis), up=vp.vector(*up))
    assert obj.up.value == pytest.approx(list(want_up), abs=1e-9)
    assert unit(obj.axis.value) == pytest.approx(unit(want_axis), abs=1e-5)
    assert abs(unit(obj.axis.value) @ unit(obj.up.value)) < 1e-9      # square, as drawn


def test_box_keeps_its_length_when_the_axis_turns(vp):
    b = vp.box(axis=vp.vector(1, 1, 1), up=vp.vector(0, 1, 0), size=vp.vector(1.5, 0.3, 0.8))
    assert b.axis.mag == pytest.approx(1.5) and b.size.value == pytest.approx([1.5, 0.3, 0.8])
    assert unit(b.axis.value) == pytest.approx(unit((1.322781, 0.0, 1.118146)), abs=1e-5)


def test_setting_up_later_follows_the_same_rule(vp):
    b = vp.box(axis=vp.vector(0, 1, 0))
    b.up = vp.vector(1, 1, 0)
    made = vp.box(axis=vp.vector(0, 1, 0), up=vp.vector(1, 1, 0))
    assert b.axis.value == pytest.approx(made.axis.value) and b.up.value == made.up.value


def green_and_orange_boxes(img: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    a = img[..., :3].astype(int)
    green = a[..., 1] - np.maximum(a[..., 0], a[..., 2]) > 40
    orange = (a[..., 0] > 120) & (a[..., 1] > 50) & (a[..., 2] < 40) & (a[..., 0] - a[..., 1] > 40)
    out = []
    for mask in (green, orange):
        rows, cols = np.nonzero(mask)
        out.append(np.array([cols.min(), rows.min(), cols.max(), rows.max()]))
    return out[0], out[1]


def test_turned_objects_are_drawn_where_real_vpython_draws_them(vp):
    """Pixel boxes (x0, y0, x1, y1) measured on real VPython 7.6.5's picture of this scene.

    Before the rule was followed the green box stood upright (up turned, not the axis)
    and the cylinder pointed up and to the right instead of lying nearly level.
    """
    vp.scene.width, vp.scene.height = 480, 320
    vp.scene.background = vp.color.white
    vp.scene.range = 3
    vp.box(pos=vp.vector(2, 1, 0), axis=vp.vector(0, 1, 0), up=vp.vector(1, 1, 0),
           size=vp.vector(1.5, 0.3, 0.8), color=vp.color.green)
    vp.cylinder(pos=vp.vector(-2.5, -1.5, 0), axis=vp.vector(1, 1, 1), up=vp.vector(0, 1, 0),
                radius=0.3, color=vp.color.orange)
    r = Renderer(vp.scene)
    try:
        green, orange = green_and_orange_boxes(r.frame())
    finally:
        r.close()
    assert np.abs(green - [308, 66, 391, 141]).max() <= 2, green
    assert np.abs(orange - [90, 224, 175, 282]).max() <= 2, orange
