"""VPython 7's vertex, triangle and quad: their attributes and errors, and the pixels they
make: per-vertex colours where the vertices are, vertex changes in the next frame."""

from __future__ import annotations

import imageio.v3 as iio
import numpy as np
import pytest

from conftest import ROOT
from springscene.vpython.run.runner import run_program
from springscene.vpython.run.options import RunOptions

PROGRAMS = ROOT / "tests" / "vpython_programs"


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


def pixel(img, view, p, toward=None, t=0.15):
    """The pixel at world point ``p`` (moved a fraction ``t`` towards ``toward``)."""
    p = np.asarray(p, dtype=float)
    if toward is not None:
        p = p + t * (np.asarray(toward, dtype=float) - p)
    col, row = view.project(p)
    return img[int(round(row)), int(round(col))].astype(int)


# -- objects ------------------------------------------------------------------------------

def test_vertex_defaults_and_checks(vp):
    v = vp.vertex(pos=vp.vector(1, 2, 3))
    assert v.normal == vp.vector(0, 0, 1) and v.color == vp.vector(1, 1, 1)
    assert (v.opacity, v.shininess, v.emissive) == (1.0, 0.6, False)
    assert v.texpos == vp.vector(0, 0, 0) and v.bumpaxis == vp.vector(1, 0, 0)
    assert v.canvas is vp.scene
    with pytest.raises(AttributeError, match="z component of texpos"):
        v.texpos = vp.vector(0, 0, 1)
    v.red = 0.5
    assert v.color == vp.vector(0.5, 1, 1)
    v.mine = 7
    assert v.mine == 7
    v.rotate(angle=np.pi / 2, axis=vp.vector(0, 0, 1))          # about the origin (GlowScript)
    assert v.pos.value == pytest.approx([-2, 1, 3])
    assert v.normal.value == pytest.approx([0, 0, 1])
    with pytest.raises(TypeError):
        v.rotate(angle=1)


def test_triangle_and_quad_attributes_and_errors(vp):
    a, b, c, d = (vp.vertex(pos=vp.vector(x, y, 0)) for x, y in ((0, 0), (1, 0), (1, 1), (0, 1)))
    t = vp.triangle(vs=[a, b, c])
    assert t.vs == [a, b, c] and (t.v0, t.v1, t.v2) == (a, b, c) and t.visible
    q = vp.quad(v0=a, v1=b, v2=c, v3=d, texture=vp.textures.rug, bumpmap=vp.bumpmaps.stones)
    assert q.vs == [a, b, c, d] and q.texture == vp.textures.rug and isinstance(q, vp.triangle)
    assert a.triangleCount == 2
    t.v2 = d
    assert t.vs == [a, b, d] and c.triangleCount == 1
    for name in ("pos", "color", "size", "axis", "up", "opacity", "shininess", "emissive"):
        with pytest.raises(AttributeError, match=f"has no {name} attribute"):
            getattr(t, name)
    with pytest.raises(AttributeError, match="rotate the vertices"):
        q.rotate(angle=1)
    with pytest.raises(TypeError, match="Cannot clone a quad"):
        q.clone()
    with pytest.raises(AttributeError, match="v1 must be a vertex"):
        vp.triangle(v0=a, v1=vp.vector(0, 0, 0), v2=c)
    with pytest.raises(AttributeError, match="four vertex objects|4 vertex objects"):
        vp.quad(vs=[a, b, c])
    assert t in vp.scene.objects and a not in vp.scene.objects


# -- pictures -----------------------------------------------------------------------------

def test_per_vertex_colours_are_at_their_vertices(vp, renderer):
    P = [(-1.5, -1.5, 0), (1.5, -1.5, 0), (0, 1.5, 0)]
    vs = [vp.vertex(pos=vp.vector(*p), color=c, emissive=True)
          for p, c in zip(P, (vp.color.red, vp.color.green, vp.color.blue))]
    vp.triangle(vs=vs)
    img = renderer.frame()
    centre = np.mean(P, axis=0)
    for p, channel in zip(P, range(3)):
        px = pixel(img, renderer.view, p, toward=centre, t=0.1)
        assert px.argmax() == channel and px[channel] > 180, (p, px)
    middle = pixel(img, renderer.view, centre)
    assert np.all(np.abs(middle - middle.mean()) < 30) and middle.mean() > 60   # blended
    assert img[5, 5].tolist() == [0, 0, 0]


def test_a_quad_is_two_triangles_v0_v1_v2_and_v0_v2_v3(vp, renderer):
    P = [(-1, -1, 0), (1, -1, 0), (1, 1, 0), (-1, 1, 0)]
    colours = (vp.color.red, vp.color.green, vp.color.blue, vp.color.yellow)
    vp.quad(vs=[vp.vertex(pos=vp.vector(*p), color=c, emissive=True)
                for p, c in zip(P, colours)])
    img = renderer.frame()
    expected = [(255, 0, 0), (0, 255, 0), (0, 0, 255), (255, 255, 0)]
    for p, rgb in zip(P, expected):
        px = pixel(img, renderer.view, p, toward=(0, 0, 0), t=0.05)
        assert np.all(np.abs(px - rgb) < 40), (p, px)
    # the diagonal v0-v2 is shared: on it only red and blue mix (no green, no yellow)
    on_diagonal = pixel(img, renderer.view, (0.3, 0.3, 0))
    assert on_diagonal[1] < 40 and on_diagonal[0] > 60 and on_diagonal[2] > 60


def test_changing_a_vertex_changes_the_next_frame(vp, renderer):
    a = vp.vertex(pos=vp.vector(-1.5, -1, 0), color=vp.color.red, emissive=True)
    b = vp.vertex(pos=vp.vector(-0.5, -1, 0), color=vp.color.red, emissive=True)
    c = vp.vertex(pos=vp.vector(-1, 0, 0), color=vp.color.red, emissive=True)
    vp.triangle(vs=[a, b, c])
    before = renderer.frame()
    left = pixel(before, renderer.view, (-1, -0.7, 0))
    right = pixel(before, renderer.view, (1, -0.7, 0))
    assert left[0] > 200 and right[0] == 0
    for v in (a, b, c):
        v.pos.x += 2                      # in place, as Rug.py does
    after = renderer.frame()
    assert pixel(after, renderer.view, (-1, -0.7, 0))[0] == 0
    assert pixel(after, renderer.view, (1, -0.7, 0))[0] > 200
    c.color = vp.color.blue               # a colour change, too
    bluer = renderer.frame()
    assert pixel(bluer, renderer.view, (1, -0.2, 0), toward=(1, 0, 0), t=0.5)[2] > 100


def test_lit_from_the_side_the_normals_point_whatever_the_winding(vp, renderer):
    """GlowScript lights a triangle by its vertices' normals only; a clockwise one with
    normals towards the camera is as bright as a counter-clockwise one."""
    def tri(x0, clockwise):
        a, b, c = (vp.vertex(pos=vp.vector(x0 + dx, dy, 0)) for dx, dy in
                   ((-0.7, -1), (0.7, -1), (0, 1)))
        vp.triangle(vs=[a, c, b] if clockwise else [a, b, c])
    tri(-1, False)
    tri(1, True)
    img = renderer.frame()
    ccw = pixel(img, renderer.view, (-1, -0.3, 0))
    cw = pixel(img, renderer.view, (1, -0.3, 0))
    assert ccw.mean() > 150 and np.all(np.abs(cw - ccw) < 8)


def test_vertex_opacity_blends_with_what_is_behind(vp, renderer):
    vp.scene.background = vp.color.white
    vs = [vp.vertex(pos=vp.vector(x, y, 0), color=vp.color.blue, opacity=0.5, emissive=True)
          for x, y in ((-1, -1), (1, -1), (1, 1), (-1, 1))]
    vp.quad(vs=vs)
    img = renderer.frame()
    r, g, b = pixel(img, renderer.view, (0, 0, 0))
    assert b > 240 and 100 < r < 160 and 100 < g < 160


def test_a_textured_quad_follows_its_texpos(vp, renderer, tmp_path):
    image = np.zeros((8, 8, 3), dtype=np.uint8)
    image[:, :4] = (255, 0, 0)            # left half red
    image[:, 4:] = (0, 0, 255)            # right half blue
    iio.imwrite(tmp_path / "lr.png", image)
    P = [(-1, -1), (1, -1), (1, 1), (-1, 1)]
    T = [(0, 0), (1, 0), (1, 1), (0, 1)]
    vs = [vp.vertex(pos=vp.vector(x, y, 0), texpos=vp.vector(u, v, 0), emissive=True)
          for (x, y), (u, v) in zip(P, T)]
    q = vp.quad(vs=vs, texture=str(tmp_path / "lr.png"))
    img = renderer.frame()
    assert pixel(img, renderer.view, (-0.5, 0, 0)).tolist() == pytest.approx([255, 0, 0], abs=3)
    assert pixel(img, renderer.view, (0.5, 0, 0)).tolist() == pytest.approx([0, 0, 255], abs=3)
    for v, (u, w) in zip(vs, T):          # mirror the picture through texpos
        v.texpos = vp.vector(1 - u, w, 0)
    img = renderer.frame()
    assert pixel(img, renderer.view, (-0.5, 0, 0)).tolist() == pytest.approx([0, 0, 255], abs=3)
    q.visible = False
    img = renderer.frame()
    assert pixel(img, renderer.view, (-0.5, 0, 0)).tolist() == [0, 0, 0]


def test_triangles_go_into_a_compound_and_can_be_deleted(vp, renderer):
    vs = [vp.vertex(pos=vp.vector(x, y, 0), color=vp.color.green, emissive=True)
          for x, y in ((-1, -1), (1, -1), (0, 1))]
    t = vp.triangle(vs=vs)
    c = vp.compound([t], pos=vp.vector(0.5, 0, 0))
    assert not t.visible and c.size.x == pytest.approx(2) and c.size.y == pytest.approx(2)
    img = renderer.frame()
    assert pixel(img, renderer.view, (0.5, -0.5, 0))[1] > 200
    c.visible = False
    t2 = vp.triangle(vs=vs)
    assert pixel(renderer.frame(), renderer.view, (0, -0.5, 0))[1] > 200
    t2.delete()
    assert pixel(renderer.frame(), renderer.view, (0, -0.5, 0)).tolist() == [0, 0, 0]


def test_the_triangles_program_and_rug_like_sheets_run(tmp_path):
    frames = []
    result = run_program(PROGRAMS / "vp7_triangles.py", tmp_path / "t.mp4",
                         RunOptions(duration=0.4, fps=10, page=False),
                         on_frame=lambda i, im: frames.append(im))
    assert result.frames == 4 and not result.notes
    first, last = frames[0].astype(int), frames[-1].astype(int)
    assert (first.sum(axis=2) > 60).sum() > 5000
    assert np.abs(first - last).sum() > 0                 # the sheet's wave moved
