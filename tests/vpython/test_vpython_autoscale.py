"""VPython's autoscale (GlowScript 3.2 lib/glow/autoscale.js): the 8 corners of each object's
oriented box, curves by their points, ranges that grow at every render and never shrink
(unless the extent falls below a third). The expected numbers are worked out here from
VPython's rule, independently of springscene's code."""

from __future__ import annotations

import itertools
import math
import textwrap

import numpy as np
import pytest

import springscene.vpython.api
from springscene.vpython.draw import autoscale
from springscene.vpython.core.canvases import canvas
from springscene.vpython.geometry.object_meshes import object_mesh
from springscene.vpython.run.runner import run_program
from springscene.vpython.run.options import RunOptions

C = 1 / math.tan(math.pi / 6)          # cot(fov/2), fov = pi/3


@pytest.fixture
def vp():
    springscene.vpython.api.reset()
    return springscene.vpython.api


def vpython_range(boxes, w=640, h=400):
    """compute_autoscale over axis-aligned boxes [(lo, hi), ...] around center 0."""
    zx = zy = 0.0
    for lo, hi in boxes:
        xx, yy, zz = np.maximum(np.abs(lo), np.abs(hi))
        zx, zy = max(zx, xx * C + zz), max(zy, yy * C + zz)
    if zx * h / w > zy:
        return 1.1 * (h / w) * zx / C
    return 1.1 * zy / C


def corner_box(start, axis, up, size):
    """find_extent by hand: z = norm(axis x up), y = z x axis, corners from ``start``."""
    x = np.asarray(axis, float) / np.linalg.norm(axis)
    z = np.cross(x, np.asarray(up, float))
    z /= np.linalg.norm(z)
    y = np.cross(z, x)
    pts = [np.asarray(start, float) + a * size[0] * x + b * size[1] * y + c * size[2] * z
           for a, b, c in itertools.product((0, 1), (-0.5, 0.5), (-0.5, 0.5))]
    return np.min(pts, axis=0), np.max(pts, axis=0)


def measured(vp):
    autoscale.at_render()
    return vp.scene._autoscaled_range


def test_tilted_box_is_bounded_by_its_eight_corners(vp):
    # box(size=(2, 1, 0.5)) along (1, 1, 0): corners at +-1.5/sqrt 2 in x and y, 0.25 in z
    b = vp.box(axis=vp.vector(1, 1, 0))
    b.size = vp.vector(2, 1, 0.5)
    half = 1.5 / math.sqrt(2)
    want = 1.1 * (half * C + 0.25) / C          # zy decides: zx h/w < zy
    assert measured(vp) == pytest.approx(want, rel=1e-12)
    assert vp.scene.range == pytest.approx(want, rel=1e-12)


def test_tilted_helix_is_bounded_as_a_cylinder_not_by_its_wire(vp):
    axis, up = np.array([1, 1, 0.5]), np.array([0.0, 1.0, 0.0])
    h = vp.helix(pos=vp.vector(-1, -1, 0), axis=vp.vector(*axis), radius=0.3, coils=6,
                 thickness=0.2)
    up = np.array(h.up.value)
    L = np.linalg.norm(axis)
    want = vpython_range([corner_box((-1, -1, 0), axis, up, (L, 0.6, 0.6))])
    assert measured(vp) == pytest.approx(want, rel=1e-12)
    # not the mesh: the box's corners reach past the coil (the wire's 0.1 is left out)
    pts = object_mesh(h)[0]
    assert vpython_range([(pts.min(axis=0), pts.max(axis=0))]) < want * 0.99


def test_arrow_and_ring_boxes(vp):
    vp.arrow(pos=vp.vector(-2, -1, 0), axis=vp.vector(3, 2, 1))
    L = math.sqrt(14)
    sw, hw, hl = 0.1 * L, 0.2 * L, 0.3 * L
    A = np.array([3, 2, 1]) / L
    up = np.array(vp.scene.objects[0].up.value)
    shaft = corner_box((-2, -1, 0), A, up, (L - hl, sw, sw))
    head = corner_box(np.array([-2, -1, 0]) + A * (L - hl), A, up, (hl, hw, hw))
    box = (np.minimum(shaft[0], head[0]), np.maximum(shaft[1], head[1]))
    assert measured(vp) == pytest.approx(vpython_range([box]), rel=1e-12)


def test_curve_is_bounded_by_its_points_not_its_radius(vp):
    vp.curve(pos=[vp.vector(-3, 0, 0), vp.vector(2, 1, 0)], radius=0.5)
    assert measured(vp) == pytest.approx(vpython_range([((-3, 0, 0), (2, 1, 0))]))


def test_points_each_bounded_pixel_ones_by_their_position(vp):
    vp.points(pos=[vp.vector(-3, 0, 0), vp.vector(0, 0, 2)], radius=5)
    # each point apart: zx = max(3 c, 0 + 2) (one box round both would give 3 c + 2)
    want = 1.1 * (400 / 640) * (3 * C) / C
    assert measured(vp) == pytest.approx(want)
    vp.reset()
    vp.points(pos=[vp.vector(-3, 0, 0)], radius=0.5, size_units="world")
    assert measured(vp) == pytest.approx(1.1 * (400 / 640) * (3.5 * C + 0.5) / C)


def test_range_grows_at_every_render_and_never_shrinks(vp):
    b = vp.box()
    first = measured(vp)
    assert first == pytest.approx(vpython_range([((-0.5,) * 3, (0.5,) * 3)]))
    b.pos = vp.vector(4, 0, 0)
    far = measured(vp)
    assert far == pytest.approx(vpython_range([((-0.5, -0.5, -0.5), (4.5, 0.5, 0.5))]))
    b.pos = vp.vector(0, 0, 0)           # back home: VPython keeps the room it made
    assert measured(vp) == far


def test_range_follows_a_fall_below_a_third(vp):
    big = vp.box(size=vp.vector(30, 30, 30))
    vp.box()
    big_range = measured(vp)
    big.visible = False                  # the extent now 1/30 of the last: range follows
    small = measured(vp)
    assert small == pytest.approx(vpython_range([((-0.5,) * 3, (0.5,) * 3)]))
    assert small < big_range / 3


def test_an_animation_that_goes_out_and_comes_back_keeps_its_range(tmp_path):
    prog = tmp_path / "outback.py"
    prog.write_text(textwrap.dedent("""
        from vpython import *
        b = box(color=color.cyan)
        for i in range(201):
            rate(100)
            b.pos = vector(8*sin(pi*i/200), 0, 0)
    """))
    run_program(prog, tmp_path / "out.png", RunOptions(page=False))
    cv = canvas._all[0]
    b = cv._objects[0]
    assert abs(b.pos.x) < 1e-9                      # it came back
    # renders at 60 Hz saw it near x = 8: the range is about the far one (x up to 8.5)
    far = vpython_range([((-0.5, -0.5, -0.5), (8.5, 0.5, 0.5))])
    assert far * 0.99 < cv._range_now() <= far * (1 + 1e-12)


def test_autoscale_off_freezes_what_autoscale_reached(vp):
    b = vp.box()
    measured(vp)
    b.pos = vp.vector(3, 0, 0)
    r = measured(vp)
    vp.scene.autoscale = False
    b.pos = vp.vector(30, 0, 0)
    autoscale.at_render()
    assert vp.scene.range == pytest.approx(r)


def _random_passes(vp, rng, passes: int = 60) -> list[float]:
    """The range after each of ``passes`` autoscale passes over a canvas whose solids are
    added, deleted, hidden and shown again, moved, turned and resized, with the centre
    moved now and then."""
    objs, ranges = [], []
    kinds = (vp.sphere, vp.box, vp.cylinder, vp.helix, vp.cone)
    for _ in range(passes):
        for _ in range(int(rng.integers(0, 6))):
            objs.append(kinds[int(rng.integers(len(kinds)))](
                pos=vp.vector(*rng.normal(size=3) * 3), size=vp.vector(*rng.random(3) + 0.1)))
        for o in list(objs):
            roll = rng.random()
            if roll < 0.05:
                o.visible = False
                objs.remove(o)
                del o
            elif roll < 0.15:
                o.visible = not o.visible
            elif roll < 0.35:
                o.pos = o.pos + vp.vector(*rng.normal(size=3))
            elif roll < 0.45:
                o.axis = vp.vector(*rng.normal(size=3))
            elif roll < 0.5:
                o.size = vp.vector(*rng.random(3) * 2 + 0.1)
        if rng.random() < 0.05:
            vp.scene.center = vp.vector(*rng.normal(size=3))
        ranges.append(measured(vp))
    return ranges


def test_solids_in_columns_bound_as_one_by_one(vp, monkeypatch):
    """Autoscale's columns (autoscale._Block: ids, digests and boxes of the solids, worked
    through in chunks, here of 7) give the ranges the object-by-object path gives, pass
    after pass, through objects added, deleted (their ids reused), hidden and shown
    again (their extent kept), moved, turned and resized, and a centre that moves."""
    monkeypatch.setattr(autoscale, "CHUNK", 7)
    columns = _random_passes(vp, np.random.default_rng(5))
    vp.reset()
    monkeypatch.setattr(autoscale, "BULK", ())
    one_by_one = _random_passes(vp, np.random.default_rng(5))
    assert len(columns) == 60 and len(set(columns)) > 5
    assert columns == pytest.approx(one_by_one, rel=1e-12)


def test_digest_tells_rows_apart():
    """Two rows of floats that differ in one bit have different digests; equal rows the
    same (the key an object's box is kept by)."""
    rows = np.random.default_rng(1).normal(size=(1000, 12))
    flipped = rows.copy()
    flipped.view(np.uint64)[:, 7] ^= np.uint64(1)
    assert np.array_equal(autoscale.digest(rows), autoscale.digest(rows.copy()))
    assert np.all(autoscale.digest(rows) != autoscale.digest(flipped))
    assert len(set(autoscale.digest(rows).tolist())) == 1000
