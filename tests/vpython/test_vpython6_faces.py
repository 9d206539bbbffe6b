"""VPython 6's faces and convex: their arrays as VPython 6 kept them, the meshes made of
them (triangles, normals, hulls), the pixels they draw, and programs through the runner."""

from __future__ import annotations

import json

import numpy as np
import pytest

from conftest import ROOT
from springscene.vpython.dialects import visual6
from springscene.vpython.draw import surface_meshes
from springscene.vpython.objects.array_surfaces import convex, faces
from springscene.vpython.objects.frames import frame
from springscene.vpython.run.options import RunOptions
from springscene.vpython.run.runner import run_program

PROGRAMS = ROOT / "tests" / "vpython_programs"
CUBE = np.array([(x, y, z) for x in (0, 1) for y in (0, 1) for z in (0, 1)], dtype=float)


@pytest.fixture
def vp():
    import springscene.vpython.api as vp

    vp.reset()
    vp.scene.width, vp.scene.height = 300, 300
    vp.scene.range = 2
    return vp


@pytest.fixture
def renderer(vp):
    from springscene.vpython.draw.renderer import Renderer

    r = Renderer(vp.scene, antialias=False)
    yield r
    r.close()


def pixel(img, view, p):
    col, row = view.project(np.asarray(p, dtype=float))
    return img[int(round(row)), int(round(col))].astype(int)


def volume(t: np.ndarray) -> float:
    """Signed volume enclosed by triangles (M, 3, 3): positive when wound outward."""
    return float(np.einsum("ij,ij->i", t[:, 0], np.cross(t[:, 1], t[:, 2])).sum() / 6)


# -- faces: arrays ------------------------------------------------------------------------

def test_faces_arrays_are_live_views_and_copies_when_set(vp):
    f = faces(pos=[(0, 0, 0), (1, 0, 0), (0, 1, 0)])
    assert f.pos.shape == (3, 3) and f.pos.dtype == np.float64
    assert f.color.tolist() == [[1, 1, 1]] * 3 and not f.normal.any()   # foreground, zero
    f.normal = f.pos                                    # copied, not shared
    f.normal[:, 2] = 1
    assert f.pos[:, 2].tolist() == [0, 0, 0] and f.normal[:, 2].tolist() == [1, 1, 1]
    f._dirty = False
    f.pos[0::3, 0] = 5                                  # in place: the next frame sees it
    assert f.pos[0, 0] == 5 and f._dirty
    assert f.x.tolist() == [5, 1, 0] and f.y.tolist() == [0, 0, 1]
    f.red = 0.25
    assert f.color[:, 0].tolist() == [0.25] * 3 and f.green.tolist() == [1, 1, 1]
    with pytest.raises(ValueError, match="pos must be an Nx3 array"):
        f.pos = [(1, 2, 3, 4)]
    with pytest.raises(ValueError, match="normal has 2 rows"):
        f.normal = [(0, 0, 1), (0, 0, 1)]


def test_a_colour_given_first_goes_to_every_vertex_set_later(vp):
    f = faces(color=vp.color.cyan)                      # faces_heightfield's way
    f.pos = [vp.vector(0, 0, 0), vp.vector(1, 0, 0), (0, 1, 0), (1, 1, 0)]
    assert f.color.tolist() == [[0, 1, 1]] * 4
    f.color = [(1, 0, 0)] * 2                           # N colours set the length of all
    assert len(f.pos) == 2 and len(f.normal) == 2
    f.normal = (0, 0, 1)                                # one normal for every vertex
    assert f.normal.tolist() == [[0, 0, 1]] * 2
    assert faces(pos=[(1, 2)]).pos.tolist() == [[1, 2, 0]]     # x, y: z is 0


def test_append_takes_pos_normal_and_colour_as_vpython6(vp):
    f = faces(color=(0, 0, 1))
    f.append(pos=(0, 0, 0))
    f.append(pos=(1, 0, 0), normal=(0, 0, 1), color=(1, 0, 0))
    f.append(pos=(0, 1, 0), normal=(0, 0, 1), green=0.5)
    assert f.pos.tolist() == [[0, 0, 0], [1, 0, 0], [0, 1, 0]]
    assert f.normal.tolist() == [[0, 0, 0], [0, 0, 1], [0, 0, 1]]
    assert f.color.tolist() == [[0, 0, 1], [1, 0, 0], [1, 0.5, 0]]   # the last one's, then green
    for k in range(40):                                 # past the first buffer
        f.append(pos=(k, 0, 0))
    assert len(f.pos) == 43 and f.pos[-1].tolist() == [39, 0, 0]


def test_make_normals_follows_the_winding_and_skips_a_last_part_triangle(vp):
    f = faces(pos=[(0, 0, 0), (2, 0, 0), (0, 2, 0),      # counter-clockwise from +z
                   (0, 0, 0), (0, 2, 0), (2, 0, 0),      # clockwise
                   (5, 5, 5)])
    f.make_normals()
    assert f.normal.tolist() == [[0, 0, 1]] * 3 + [[0, 0, -1]] * 3 + [[0, 0, 0]]


def test_make_twosided_adds_each_triangle_wound_back(vp):
    f = faces(pos=[(0, 0, 0), (1, 0, 0), (0, 1, 0), (3, 3, 3)],
              color=[(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1)])
    f.make_normals()
    f.make_twosided()
    assert len(f.pos) == 12                             # 4 padded to 6, then doubled
    assert f.pos[6:9].tolist() == [[0, 0, 0], [0, 1, 0], [1, 0, 0]]
    assert f.color[6:9].tolist() == [[1, 0, 0], [0, 0, 1], [0, 1, 0]]
    assert f.normal[6:9].tolist() == [[0, 0, -1]] * 3
    assert f.pos[3:6].tolist() == [[3, 3, 3]] * 3       # the last vertex copied


def test_smooth_averages_only_normals_alike(vp):
    def hinge(angle):
        """Two triangles sharing the edge (0,0,0)-(0,1,0), folded by ``angle``."""
        c, s = np.cos(angle), np.sin(angle)
        return faces(pos=[(0, 0, 0), (1, 0, 0), (0, 1, 0),
                          (0, 0, 0), (0, 1, 0), (-c, 0, s)])
    gentle = hinge(np.radians(10))
    gentle.make_normals()
    gentle.smooth()                                     # 10 degrees: averaged
    shared = gentle.normal[[0, 2, 3, 4]]
    assert np.allclose(shared, shared[0]) and np.allclose(np.linalg.norm(shared, axis=1), 1)
    assert np.allclose(gentle.normal[1], (0, 0, 1))     # an unshared vertex keeps its own
    sharp = hinge(np.radians(90))
    sharp.make_normals()
    before = sharp.normal.copy()
    sharp.smooth()                                      # 90 degrees: left alone
    assert np.array_equal(sharp.normal, before)
    sharp.smooth(0.5)                                   # cos 90 = 0 < 0.5: still alone
    assert np.array_equal(sharp.normal, before)
    sharp.smooth(-0.1)
    assert np.allclose(sharp.normal[0], np.array([1, 0, 1]) / np.sqrt(2))


# -- faces and convex: meshes -------------------------------------------------------------

def test_faces_mesh_is_its_whole_triangles_with_their_normals(vp):
    f = faces(pos=[(0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1)])
    points, normals, triangles, rgb = surface_meshes.faces_mesh(f)
    assert triangles.tolist() == [[0, 1, 2]] and len(points) == 3
    assert normals.tolist() == [[0, 0, 1]] * 3          # unset normals: the triangle's
    assert rgb.dtype == np.uint8 and rgb.tolist() == [[255, 255, 255]] * 3
    assert surface_meshes.faces_mesh(faces()) is None


def test_hull_of_a_cube_is_twelve_outward_triangles(vp):
    t = surface_meshes.hull(CUBE)
    assert t.shape == (12, 3, 3)
    assert volume(t) == pytest.approx(1.0)
    inside = np.vstack([CUBE, [(0.5, 0.5, 0.5), (0.2, 0.7, 0.4)]])
    assert surface_meshes.hull(inside).shape == (12, 3, 3)
    normals = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])
    out = np.einsum("ij,ij->i", normals, t.mean(axis=1) - 0.5)
    assert (out > 0).all()


def test_hull_of_points_on_a_sphere_uses_them_all(vp):
    rng = np.random.default_rng(3)
    p = rng.normal(size=(300, 3))
    p /= np.linalg.norm(p, axis=1, keepdims=True)
    t = surface_meshes.hull(np.vstack([p, 0.5 * p[:50]]))     # and points inside
    corners = np.unique(t.reshape(-1, 3), axis=0)
    assert len(corners) == 300 and len(t) == 2 * 300 - 4      # Euler: F = 2V - 4
    assert volume(t) == pytest.approx(4 / 3 * np.pi, rel=0.05)


def test_flat_and_degenerate_hulls(vp):
    a = np.arange(0, 2 * np.pi, 2 * np.pi / 6)
    hexagon = np.column_stack([np.cos(a), np.sin(a), np.zeros(6)])
    t = surface_meshes.hull(np.vstack([hexagon, [(0.1, 0.1, 0)]]))
    assert t.shape == (8, 3, 3)                         # 4 triangles, both ways round
    nz = np.cross(t[:, 1] - t[:, 0], t[:, 2] - t[:, 0])[:, 2]
    assert (nz[:4] > 0).all() and (nz[4:] < 0).all()
    assert np.abs(nz[:4]).sum() / 2 == pytest.approx(3 * np.sqrt(3) / 2)   # its area
    assert surface_meshes.hull([(0, 0, 0), (1, 1, 1), (2, 2, 2)]) is None
    assert surface_meshes.hull([(0, 0, 0), (1, 0, 0)]) is None


def test_convex_keeps_one_colour_and_grows_by_append(vp):
    c = convex(color=(0.5, 0, 0))
    assert len(c.pos) == 0 and surface_meshes.convex_mesh(c) is None
    for p in CUBE:
        c.append(pos=tuple(p))
    c.red = 1
    assert c.color == vp.vector(1, 0, 0) and c.green == 0
    points, normals, triangles, rgb = surface_meshes.convex_mesh(c)
    assert len(triangles) == 12 and rgb.tolist() == [[255, 0, 0]] * 36
    assert np.allclose(np.abs(normals).max(axis=1), 1)  # flat: each a cube face's normal
    c.pos[:, 0] += 10                                   # in place: a new hull
    assert surface_meshes.convex_mesh(c)[0][:, 0].min() == pytest.approx(10)
    assert surface_meshes.box(c) == ((10, 0, 0), (11, 1, 1))


def test_in_a_frame_the_points_are_the_frames(vp):
    fr = frame(pos=(2, 0, 0), axis=(0, 1, 0), up=(-1, 0, 0))   # x -> y, y -> -x
    f = faces(frame=fr, pos=[(0, 0, 0), (1, 0, 0), (0, 1, 0)], normal=(0, 0, 1))
    points, normals, _, _ = surface_meshes.faces_mesh(f)
    assert np.allclose(points, [(2, 0, 0), (2, 1, 0), (1, 0, 0)])
    assert np.allclose(normals, [(0, 0, 1)] * 3)
    c = convex(frame=fr, pos=CUBE)
    assert np.allclose(surface_meshes.box(c), ((1, 0, 0), (2, 1, 1)))
    assert f in fr._children and c in fr._children


def test_the_visual_namespace_has_them(vp):
    names = visual6.namespace(vp)
    assert names["faces"] is faces and names["convex"] is convex


# -- pictures -----------------------------------------------------------------------------

def test_faces_draw_their_vertex_colours_from_the_front_only(vp, renderer):
    P = [(-1.5, -1.5, 0), (1.5, -1.5, 0), (0, 1.5, 0)]
    f = faces(pos=P, color=[(1, 0, 0), (0, 1, 0), (0, 0, 1)], normal=(0, 0, 1))
    img = renderer.frame()
    centre = np.mean(P, axis=0)
    for p, channel in zip(P, range(3)):
        px = pixel(img, renderer.view, np.asarray(p) + 0.12 * (centre - p))
        assert px.argmax() == channel and px[channel] > 150, (p, px)
    assert pixel(img, renderer.view, (1.5, 1.5, 0)).tolist() == [0, 0, 0]
    f.pos = [P[0], P[2], P[1]]                          # clockwise: its back, not drawn
    img = renderer.frame()
    assert pixel(img, renderer.view, centre).tolist() == [0, 0, 0]
    f.make_normals()                                    # pointing away (clockwise) ...
    f.make_twosided()                                   # ... and the new front's towards it
    assert pixel(renderer.frame(), renderer.view, centre).sum() > 150   # the colours mixed


def test_faces_lit_by_their_normals(vp, renderer):
    toward = faces(pos=[(-1.8, -1, 0), (-0.2, -1, 0), (-1, 1, 0)], normal=(0, 0, 1))
    away = faces(pos=[(0.2, -1, 0), (1.8, -1, 0), (1, 1, 0)], normal=(0, 0, -1))
    img = renderer.frame()
    lit, dark = pixel(img, renderer.view, (-1, -0.5, 0)), pixel(img, renderer.view, (1, -0.5, 0))
    assert lit.mean() > 150 and dark.mean() < 0.6 * lit.mean() and dark.mean() > 10
    assert toward.visible and away.visible


def test_in_place_changes_and_frames_move_the_drawing(vp, renderer):
    f = faces(pos=[(-1.5, -1, 0), (-0.5, -1, 0), (-1, 0, 0)], color=vp.color.green)
    assert pixel(renderer.frame(), renderer.view, (-1, -0.7, 0))[1] > 100
    f.pos[:, 0] += 2                                    # in place, as VPython 6 programs do
    img = renderer.frame()
    assert pixel(img, renderer.view, (-1, -0.7, 0)).tolist() == [0, 0, 0]
    assert pixel(img, renderer.view, (1, -0.7, 0))[1] > 100
    fr = frame(pos=(0, 1.5, 0))
    f.frame = fr
    img = renderer.frame()
    assert pixel(img, renderer.view, (1, 0.8, 0))[1] > 100
    fr.visible = False
    assert pixel(renderer.frame(), renderer.view, (1, 0.8, 0)).tolist() == [0, 0, 0]


def test_a_convex_hull_is_drawn_flat_in_its_colour(vp, renderer):
    c = convex(pos=(CUBE - 0.5) * 2, color=vp.color.orange)
    img = renderer.frame()
    front = pixel(img, renderer.view, (0, 0, 1))
    assert front[0] > 150 and 50 < front[1] < 0.8 * front[0] and front[2] < 40
    assert pixel(img, renderer.view, (1.6, 1.6, 0)).tolist() == [0, 0, 0]
    c.opacity = 0.5
    vp.scene.background = vp.color.white
    r, g, b = pixel(renderer.frame(), renderer.view, (0, 0, 1))
    assert 40 < b < 100 and r > 150         # white through two orange layers: 1/4 of its blue


def test_autoscale_takes_their_points(vp, renderer):
    vp.scene.autoscale = True                           # from the range of 2
    faces(pos=[(-4, -4, 0), (4, -4, 0), (0, 4, 0)])
    renderer.frame()
    assert vp.scene.range > 4


# -- programs -----------------------------------------------------------------------------

def _frames(name, tmp_path, **options):
    frames = []
    result = run_program(PROGRAMS / name, tmp_path / "v.mp4",
                         RunOptions(page=False, fps=10, canvas_only=True, **options),
                         on_frame=lambda i, img: frames.append(img.astype(int)))
    return result, frames


def test_the_faces_tent_program(tmp_path):
    result, frames = _frames("vp6_faces_tent.py", tmp_path, duration=2)
    assert result.ended == "program" and len(frames) >= 10
    orange = [(f[..., 0] > 150) & (f[..., 1] > 60) & (f[..., 1] < 170) & (f[..., 2] < 60)
              for f in frames]
    assert all(o.sum() > 1500 for o in orange)         # the tent, turning in its frame
    assert (orange[0] != orange[-1]).sum() > 300
    yellow = [np.nonzero((f[..., 0] > 200) & (f[..., 1] > 200) & (f[..., 2] < 80))[0]
              for f in frames]
    assert yellow[0].size > 200 and yellow[-1].mean() < yellow[0].mean() - 5   # rising


def test_the_convex_gems_program(tmp_path):
    result, frames = _frames("vp6_convex_gems.py", tmp_path, duration=2)
    assert result.ended == "program"
    last = frames[-1]
    green = (last[..., 1] > 120) & (last[..., 0] < 60) & (last[..., 2] < 60)
    blue = (last[..., 2] > 120) & (last[..., 0] < last[..., 2] - 40)
    orange = (last[..., 0] > 180) & (last[..., 1] > 80) & (last[..., 1] < 180)
    assert green.sum() > 1000 and blue.sum() > 1000 and orange.sum() > 1000
    tips = [np.nonzero((f[..., 2] > 120) & (f[..., 0] < f[..., 2] - 40))[0].max()
            for f in (frames[0], last)]
    assert tips[1] > tips[0] + 10                       # the gem's tip went down


def test_a_recording_run_keeps_going_past_them(tmp_path):
    out = tmp_path / "run.jsonl"
    result = run_program(PROGRAMS / "vp6_faces_tent.py", out, RunOptions(fps=10, duration=1))
    assert result.frames == 10
    lines = [json.loads(x) for x in out.read_text().splitlines()]
    kinds = {o["kind"] for line in lines for o in line.get("new", [])}
    assert "faces" in kinds
