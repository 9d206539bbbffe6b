"""Autoscale over many one-point ``points`` objects: an object nothing was added to since
it was measured is not measured again (a program of a million of them renders once
with each looked at twice), and the range is the one measuring every object gives."""

from __future__ import annotations

import math

import pytest

import springscene.vpython.api
from springscene.vpython.draw import autoscale

C = 1 / math.tan(math.pi / 6)          # cot(fov/2), fov = pi/3


@pytest.fixture
def vp():
    springscene.vpython.api.reset()
    return springscene.vpython.api


def test_unchanged_points_objects_are_not_measured_again(vp, monkeypatch):
    dots = [vp.points(pos=[vp.vector(i % 7 - 3, 0, 0)]) for i in range(500)]
    autoscale.at_render()
    first = vp.scene._autoscaled_range
    assert first == pytest.approx(1.1 * (400 / 640) * (3 * C) / C)
    calls = []
    real = autoscale.Extents._new_points
    monkeypatch.setattr(autoscale.Extents, "_new_points",
                        lambda self, o: calls.append(o) or real(self, o))
    autoscale.at_render()
    assert calls == [] and vp.scene._autoscaled_range == first
    dots[3].append(vp.vector(8, 0, 0))        # one object grows: it alone is measured
    autoscale.at_render()
    assert calls == [dots[3]]
    assert vp.scene._autoscaled_range == pytest.approx(1.1 * (400 / 640) * (8 * C) / C)
