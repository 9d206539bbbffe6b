"""The interactive page's points (trails, curves, series) packed a block at a time.

A trail's new points come as ``[x, y, z]`` lists each frame; they become rows of
x, y, z, r, g, b, radius (-1 colour and 0 radius: the object's own) in one numpy
block, the same rows the point-by-point reading gives for every form a point takes.
"""

from __future__ import annotations

import zlib
import base64

import numpy as np
import pytest

from springscene.vpython.page import replay_data as R


@pytest.mark.parametrize("points, width", [
    ([[1, 2, 3], [4.5, 5, 6]], 7),
    ([[1, 2], [3, 4]], 2),
    ([[1, 2, 3, [0.1, 0.2, 0.3], 0.5], [1, 2, 3]], 7),
    ([[1, 2, 3, None]], 7),
    ([[1, True, 3]], 7),
    ([[float("nan"), 2, 3]], 7),
    ([[1, 2, 3]], 2),
    ([[1, 2, 3, "a"]], 7),
    ([], 7),
])
def test_rows_at_once_are_the_rows_point_by_point(points, width):
    one_by_one = np.array([v for p in points for v in R._row(p, width)], float)
    assert np.array_equal(R._rows(points, width).ravel(), one_by_one, equal_nan=True)


def test_a_trails_segments_over_frames():
    seg = R._Segments(R._POINT_WIDTH)
    seg.change(0, reset=[[0, 0, 0]])
    seg.change(1, append=[[1, 0, 0], [2, 0, 0]])
    seg.change(2, drop=1, append=[[3, 1, 0]])
    assert seg.states == [(0, 0, 0, 1), (1, 0, 0, 3), (2, 0, 1, 4)]
    buf = R._Buffers()
    offsets, _, n = seg.encoded(buf)
    assert n == 3 and offsets == [0]
    rows = np.concatenate(buf.floats).reshape(-1, 7)
    assert rows[:, 0].tolist() == [0, 1, 2, 3] and rows[3, 1] == 1
    assert (rows[:, 3:6] == -1).all() and (rows[:, 6] == 0).all()


def test_packed_numbers_come_back():
    a = np.arange(1000, dtype="<f4") / 7
    packed = base64.b64decode(R._packed([a], "<f4"))
    back = np.frombuffer(zlib.decompress(packed), np.uint8).reshape(4, -1).T.copy()
    assert np.array_equal(back.view("<f4").ravel(), a)
