"""VPython 6's Polygon shapes and their arithmetic, its extrusion(pos=path), textures made
from numbers, display.info(), the 3D text's own frame, gdots(shape=), and the modules
that gave all of visual: values, and programs through the runner (pixels)."""

from __future__ import annotations

import math

import numpy as np
import pytest

from conftest import ROOT
from springscene.vpython.api import texture_images, texturing
from springscene.vpython.core.vectors import set_lenient, vector
from springscene.vpython.dialects import visual6
from springscene.vpython.dialects.visual6_modules import (PictureMaterials, TextFrame,
                                                          framed_text, picture)
from springscene.vpython.dialects.visual6_shapes import (PathPoints, Polygon, as_polygon,
                                                         extrusion)
from springscene.vpython.objects.frames import frame
from springscene.vpython.run.options import RunOptions
from springscene.vpython.run.runner import run_program

PROGRAMS = ROOT / "tests" / "vpython_programs"


@pytest.fixture
def vp():
    import springscene.vpython.api as vp

    vp.reset()
    set_lenient(True)
    yield vp
    set_lenient(False)


@pytest.fixture
def v6(vp):
    return visual6.namespace(vp)


def square(side: float, at=(0.0, 0.0)) -> Polygon:
    h = side / 2
    x, y = at
    return Polygon([(x - h, y - h), (x + h, y - h), (x + h, y + h), (x - h, y + h)])


# -- Polygon ---------------------------------------------------------------------------------

def test_polygon_arithmetic_union_difference_intersection_xor():
    a, b = square(2), square(2, at=(1, 0))
    assert (a + b).area() == pytest.approx(6) and len(a + b) == 1
    assert (a | b).area() == pytest.approx(6)
    assert (a - b).area() == pytest.approx(2)
    assert (a & b).area() == pytest.approx(2)
    x = a ^ b
    assert x.area() == pytest.approx(4) and len(x) == 2 and x.isHole() == [False, False]
    assert (square(2, at=(5, 5)) & a).area() == 0 and len(square(2, at=(5, 5)) & a) == 0


def test_a_hole_cut_inside_is_a_hole_contour_and_its_area_is_taken_away():
    ring = square(4) - square(2)
    assert len(ring) == 2 and ring.isHole() == [False, True]
    assert ring.area() == pytest.approx(12) and ring.area(1) == pytest.approx(4)
    assert ring.isSolid(0) and not ring.isSolid(1)
    xs = sorted(x for x, _ in ring.contour(1))
    assert xs[0] == pytest.approx(-1) and xs[-1] == pytest.approx(1)
    groups = ring.groups()                        # as the extrusion takes it: outline, hole
    assert len(groups) == 1 and len(groups[0]) == 2
    assert all(np.array_equal(c[0], c[-1]) for c in groups[0])
    refilled = ring + square(2)                   # the hole filled again
    assert len(refilled) == 1 and refilled.area() == pytest.approx(16)


def test_polygon_scale_shift_rotate_in_place_about_the_box_centre():
    p = square(2, at=(3, 1))
    assert p.center() == pytest.approx((3, 1)) and p.boundingBox() == pytest.approx((2, 4, 0, 2))
    p.scale(0.5, 2)
    assert p.boundingBox() == pytest.approx((2.5, 3.5, -1, 3))
    p.shift(-3, 0)
    assert p.center() == pytest.approx((0, 1))
    p.rotate(math.pi / 2)
    assert p.boundingBox() == pytest.approx((-2, 2, 0.5, 1.5))
    assert p.nPoints() == 4 and p.orientation(0) == 1
    assert isinstance(p.contour(0), list) and isinstance(p[0][0], tuple)


def test_the_shapes_library_gives_polygons_and_keeps_a_thick_figure_s_hole(v6):
    shapes = v6["shapes"]
    c = shapes.circle(radius=1)
    assert isinstance(c, Polygon) and c.area() == pytest.approx(math.pi, rel=0.01)
    frame_ = shapes.rectangle(width=4, height=2, thickness=0.25)
    assert frame_.isHole() == [False, True] and frame_.area() < 8
    crescent = shapes.circle() - shapes.circle(pos=(-0.5, 0))       # medusa.py's
    assert len(crescent) == 1 and 0 < crescent.area() < math.pi * 0.25
    assert v6["Polygon"] is Polygon
    arc = v6["paths"].arc(radius=3, angle2=math.pi)
    assert isinstance(arc, PathPoints) and arc.pos == list(arc) and len(arc) > 10
    assert as_polygon([[0, 0], [1, 0], [0, 1], [0, 0]]).area() == pytest.approx(0.5)


# -- extrusion -------------------------------------------------------------------------------

def test_an_extrusion_takes_its_path_as_pos_and_keeps_per_point_arrays(vp):
    e = extrusion(pos=[(0, 0, 0), (0, 0, -2), (0, 0, -4)], shape=square(2) - square(1),
                  scale=[(1, 1), (2, 0.5), (1, 1)], twist=0.1, color=vp.color.red)
    assert e.pos.shape == (3, 3) and e.pos[2].tolist() == [0, 0, -4]
    assert e.scale.tolist() == [[1, 1], [2, 0.5], [1, 1]]
    assert e.xscale.tolist() == [1, 2, 1] and e.yscale.tolist() == [1, 0.5, 1]
    assert e.twist.tolist() == [0, 0.1, 0.1] and e.color.tolist() == [[1, 0, 0]] * 3
    pts = e._mesh.points * e._size0 + np.array(e._origin._xyz())
    assert np.ptp(pts[:, 0]) == pytest.approx(4, rel=0.02)       # 2 wide, x2 at the middle
    assert np.ptp(pts[:, 2]) == pytest.approx(4, rel=0.02)
    assert len(e._mesh.points) > 32                                # walls of both contours


def test_a_scale_pair_a_number_and_xyz_arrays(vp):
    e = extrusion(pos=[(0, 0, 0), (1, 0, 0)], shape=square(1), scale=(2, 3))
    assert e.scale.tolist() == [[2, 3], [2, 3]]
    e = extrusion(pos=[(0, 0, 0), (1, 0, 0), (2, 0, 0)], shape=square(1), scale=[1, 2, 3])
    assert e.xscale.tolist() == [1, 2, 3] == e.yscale.tolist()
    arc = np.linspace(0, math.pi, 5)
    e = extrusion(pos=(0.2, 0, 0), y=np.cos(arc), z=-np.sin(arc), shape=square(0.1))
    assert e.pos.shape == (5, 3) and e.x.tolist() == [0.2] * 5
    assert e.z.tolist() == pytest.approx((-np.sin(arc)).tolist())


def test_a_polygon_path_goes_counter_clockwise_in_the_xz_plane_and_closes(vp):
    loop = Polygon([(0, 0), (0, 2), (2, 2), (2, 0)])          # clockwise in x, y
    e = extrusion(pos=loop, shape=square(0.2))
    assert e.pos.shape == (5, 3) and e.pos[0].tolist() == e.pos[-1].tolist()
    assert not e.pos[:, 1].any()                               # y = 0: the xz plane
    x, mz = e.pos[:-1, 0], -e.pos[:-1, 2]                      # (x, -z) seen from above
    area = 0.5 * np.sum(x * np.roll(mz, -1) - np.roll(x, -1) * mz)
    assert area == pytest.approx(4)                            # counter-clockwise


def test_a_string_shape_and_a_path_of_one_point(vp):
    e = extrusion(pos=[(0, 0, 0), (0, 0, -0.5)], shape="ab")
    assert len(e._mesh.points) > 100
    flat = extrusion(shape=square(2))                          # no path: a flat face
    pts = flat._mesh.points * flat._size0
    assert np.ptp(pts[:, 0]) == pytest.approx(2) and np.ptp(pts[:, 2]) < 1e-3


def _world_points(e) -> np.ndarray:
    return e._mesh.points * np.array(e._size._xyz()) + np.array(e._pos._xyz())


def test_setting_an_array_later_makes_the_surface_again_in_place(vp):
    e = extrusion(pos=[(0, 0, 0), (0, 0, -2)], shape=square(1), color=vp.color.red)
    before = _world_points(e)
    assert np.ptp(before[:, 0]) == pytest.approx(1)
    e.xscale = 3
    assert e.xscale.tolist() == [3, 3]
    after = _world_points(e)
    assert np.ptp(after[:, 0]) == pytest.approx(3) and np.ptp(after[:, 1]) == pytest.approx(1)
    assert after[:, 0].mean() == pytest.approx(before[:, 0].mean())   # in the same place
    e._dirty = False                  # drawn
    e.pos[1][2] = -5                  # in place: seen as a change, drawn anew
    assert e._dirty and _world_points(e)[:, 2].min() == pytest.approx(-5)
    e.color = vp.color.green          # one colour for every point
    assert e.color.tolist() == [[0, 1, 0]] * 2
    assert _world_points(e)[:, 2].min() == pytest.approx(-5)        # (the surface made)
    assert (e._vertex_rgb() == [0, 255, 0]).all()
    e.pos = [(0, 0, 0), (1, 0, 0), (2, 0, 0)]                  # a longer path
    assert e.scale.shape == (3, 2) and e.color.shape == (3, 3)
    assert np.ptp(_world_points(e)[:, 0]) == pytest.approx(2)


# -- textures from numbers -------------------------------------------------------------------

def test_texture_data_becomes_a_picture_as_vpython6_read_it():
    lum = picture([[0, 1], [0.5, 0]])
    assert lum.shape == (2, 2, 3) and lum.dtype == np.uint8
    assert lum[0, 1].tolist() == [255] * 3 and lum[1, 0].tolist() == [128] * 3
    rgb = picture(np.array([[[255, 0, 0]]], np.uint8))
    assert rgb[0, 0].tolist() == [255, 0, 0]
    rgba = picture(np.zeros((2, 2, 4)))
    assert rgba.shape == (2, 2, 3)
    assert picture([[0.0]], channels=["opacity"])[0, 0].tolist() == [255] * 3
    with pytest.raises(ValueError, match="values per pixel"):
        picture(np.zeros((2, 2, 5)))
    with pytest.raises(ValueError, match="Channel combination"):
        picture(np.zeros((2, 2, 3)), channels=["luminance"])


def test_materials_texture_is_drawn_by_the_renderer_s_texture_code(vp):
    materials = PictureMaterials(object())
    m = materials.texture(data=[[0, 1], [1, 0]], mapping="sign", interpolate=False)
    assert m.texture_value["place"] == "right"
    spec = texturing.spec_of(m.texture_value)
    assert spec is not None and (spec.left, spec.right, spec.sides) == (False, True, False)
    image = texturing.image_of(spec.source)
    assert image.shape[0] >= 256 and image[0, 0].tolist() == [0] * 3      # sharp: enlarged
    assert image[0, -1].tolist() == [255] * 3 and image[-1, 0].tolist() == [255] * 3
    smooth = materials.texture(data=[[0, 1], [1, 0]], mapping="spherical")
    assert texturing.image_of(texturing.spec_of(smooth.texture_value).source).shape == (2, 2, 3)
    assert texturing.spec_of(smooth.texture_value).covers_all
    with pytest.raises(ValueError, match="Unknown mapping"):
        materials.texture(data=[[0]], mapping="sideways")
    b = vp.box(material=m)
    assert b.texture == m.texture_value
    texturing.reset()                                  # a new run forgets the pictures
    assert not texture_images.is_kept(m.texture_value["file"])


def test_targa_files_round_trip(tmp_path):
    data = np.zeros((4, 8, 3), np.uint8)
    data[0, :, 0] = 255                               # the top row red
    PictureMaterials.saveTGA(tmp_path / "stripe", data)
    back = PictureMaterials.loadTGA(str(tmp_path / "stripe"))
    assert back.shape == (4, 8, 3) and back[0, 0].tolist() == [255, 0, 0]
    assert back[1, 0].tolist() == [0, 0, 0]


# -- the small ones --------------------------------------------------------------------------

def test_display_info_text_frame_gdots_shape_and_full_modules(vp, v6):
    assert v6["scene"].info().startswith(("OpenGL renderer active.", "Renderer inactive."))
    assert v6["display"] is vp.canvas
    t = v6["text"](text="L", height=0.5, pos=vector(1, 2, 3))
    assert isinstance(t.frame, TextFrame) and t.frame.pos.equals(vector(1, 2, 3))
    t.frame.pos = vector(0, 1, 0)
    assert t.pos.equals(vector(0, 1, 0)) and t.frame.frame is None
    g = vp.gdots(shape="square", size=2)
    assert g.shape == "square"
    set_lenient(False)                                # VPython 7 refuses it
    with pytest.raises(AttributeError, match="shape is not an attribute"):
        vp.gdots(shape="square")
    found = visual6.modules(vp)
    for name in ("visual.controls", "visual.text"):
        module = found[name]
        assert module.rate is vp.rate and module.scene is vp.scene and "sphere" in module.__all__
    assert found["visual.text"].text is not found["visual"].text     # its own stroke text
    assert found["visual.controls"].slider is not vp.slider


def test_framed_text_keeps_frame_as_a_parent_setter(vp):
    Text = framed_text(vp.text)
    f = frame(pos=(5, 0, 0))
    t = Text(text="x", frame=f)
    assert t._frame is f and t.frame.frame is f


# -- programs through the runner -------------------------------------------------------------

def _frames(name: str, tmp_path, **options):
    frames: list[np.ndarray] = []
    result = run_program(PROGRAMS / name, tmp_path / "v.mp4",
                         RunOptions(page=False, fps=10, canvas_only=True, **options),
                         on_frame=lambda i, img: frames.append(img.astype(int)))
    return result, frames


def test_the_extruded_washer_program(tmp_path, capsys):
    result, frames = _frames("vp6_extruded_washer.py", tmp_path, duration=2)
    assert result.ended == "program" and len(frames) >= 10
    assert "2 True 3.216 (3, 3) [1.98, 1.98] 5" in capsys.readouterr().out
    first, last = frames[0], frames[-1]
    cyan = (last[..., 1] > 150) & (last[..., 2] > 150) & (last[..., 0] < 80)
    red = (last[..., 0] > 150) & (last[..., 1] < 80) & (last[..., 2] < 80)
    yellow = (last[..., 0] > 150) & (last[..., 1] > 120) & (last[..., 2] < 80)
    assert cyan.sum() > 2000 and red.sum() > 1000 and yellow.sum() > 500
    warm = [((f[..., 0] > 150) & (f[..., 2] < 80)).sum() for f in (first, last)]
    assert warm[1] > 1.3 * warm[0]                    # the column grew as its scale was set
    rows, cols = np.nonzero(red)
    top = last[rows.min():rows.min() + 60, cols.min():cols.max()]   # the top face: a hole
    dark = (top.max(axis=-1) < 90)
    assert dark.sum() > 100


def test_the_texture_checks_program(tmp_path):
    result, frames = _frames("vp6_texture_checks.py", tmp_path, duration=2)
    assert result.ended == "program"

    def black_squares(img: np.ndarray) -> int:
        """Black squares along a row an eighth of the way down the left box's front face
        (its shaded side, a few pixels at the right, left out)."""
        left = img[:, : img.shape[1] // 2]
        box_ = np.abs(left - 204).max(axis=-1) > 30
        rows, cols = np.nonzero(box_.any(axis=1))[0], np.nonzero(box_.any(axis=0))[0]
        front = cols.min() + int(0.9 * (cols.max() - cols.min()))
        row = left[rows.min() + (rows.max() - rows.min()) // 8, cols.min():front]
        dark = (row.max(axis=-1) < 60).astype(int)
        starts, ends = np.nonzero(np.diff(dark) == 1)[0], np.nonzero(np.diff(dark) == -1)[0]
        return int(sum(1 for a in starts if (ends[ends > a] - a > 5).any()))

    first, last = frames[0], frames[-1]
    assert black_squares(first) == 1 and black_squares(last) == 2    # 2, then 4 a side
    h, w = first.shape[:2]
    right = first[h // 4: 3 * h // 4, w // 2:]
    red = (right[..., 0] > 180) & (right[..., 1] < 80) & (right[..., 2] < 80)
    blue = (right[..., 2] > 180) & (right[..., 0] < 80) & (right[..., 1] < 80)
    assert red.sum() > 2000 and blue.sum() > 2000                  # the sign, as drawn
    orange = (first[..., 0] > 180) & (first[..., 1] > 100) & (first[..., 1] < 180)
    assert orange.sum() > 1500                                     # colour x picture


def test_the_controls_text_program(tmp_path, capsys):
    result, frames = _frames("vp6_controls_text.py", tmp_path, duration=2)
    assert result.ended == "program"
    out = capsys.readouterr().out
    assert "square 0.0 1.0" in out
    assert "OpenGL renderer active." in out or "Renderer inactive." in out
    last = frames[-1]
    yellow = np.nonzero((last[..., 0] > 180) & (last[..., 1] > 180) & (last[..., 2] < 80))
    red = np.nonzero((last[..., 0] > 150) & (last[..., 1] < 60) & (last[..., 2] < 60))
    assert yellow[0].size > 200 and red[0].size > 1000
    assert yellow[0].mean() < red[0].mean() - 40                   # the text over the ball
