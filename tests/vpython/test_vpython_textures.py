"""Textures as VPython draws them: GlowScript's texture coordinates on every object, the
``texture`` values VPython takes, the built-in pictures, and the pixels that come out."""

from __future__ import annotations

import math
import textwrap

import imageio.v3 as iio
import numpy as np
import pytest

from conftest import ROOT
from springscene.vpython.api import texture_images
from springscene.vpython.geometry.meshes import (LEFT, RIGHT, SIDES, ring, texture_parts,
                                                 textured_box, textured_cone, textured_cylinder,
                                                 textured_pyramid, textured_sphere)
from springscene.vpython.api.texturing import TextureSpec, spec_of, transform_uv
from springscene.vpython.run.runner import run_program
from springscene.vpython.run.options import RunOptions

PROGRAMS = ROOT / "tests" / "vpython_programs"


@pytest.fixture
def vp():
    import springscene.vpython.api as vp

    vp.reset()
    return vp


def notes():
    from springscene.vpython.core import widgets

    return widgets.notes()


# -- texture coordinates: GlowScript's lib/glow/mesh.js ------------------------------------

def test_sphere_poles_seam_and_longitudes_are_glowscripts():
    m = textured_sphere()
    assert len(m.points) == 31 * 31 and len(m.triangles) == 2 * 30 * 30
    u, v = m.uv[:, 0], m.uv[:, 1]
    y = m.points[:, 1]
    assert np.all(v[np.isclose(y, 0.5)] == 1) and np.all(v[np.isclose(y, -0.5)] == 0)
    assert np.allclose(y, 0.5 * np.cos(np.pi * (1 - v)))       # v = 1 - latitude index / N
    ring_ = np.abs(y) < 0.4999                                 # all but the poles
    seam = ring_ & ((u == 0) | (u == 1))
    assert seam.sum() == 2 * 29
    assert np.allclose(m.points[seam, 0], 0, atol=1e-12) and np.all(m.points[seam, 2] < 0)
    for u0, direction in ((0.25, (-1, 0, 0)), (0.5, (0, 0, 1)), (0.75, (1, 0, 0))):
        at = ring_ & np.isclose(u, u0)
        d = m.points[at] / np.linalg.norm(m.points[at], axis=1)[:, None]
        horizontal = d * [1, 0, 1]
        horizontal /= np.linalg.norm(horizontal, axis=1)[:, None]
        assert np.allclose(horizontal, direction, atol=1e-12)
    assert np.allclose(m.normals, m.points / 0.5)


def test_box_faces_take_the_whole_picture_upright():
    m = textured_box()
    assert m.uv.tolist() == [[0, 1], [0, 0], [1, 0], [1, 1]] * 6      # makeCube's texpos
    for face in range(6):
        p, n = m.points[4 * face:4 * face + 4], m.normals[4 * face]
        # u and v run along two edges of the face; seen from outside, u x v points out
        du = p[2] - p[1]                # (0,0) -> (1,0)
        dv = p[0] - p[1]                # (0,0) -> (0,1)
        assert np.allclose(np.cross(du, dv), n)
    front = m.points[16:20]
    assert np.allclose(front[m.uv[16:20, 0] == 1, 0], 0.5)              # +z face: u to +x
    assert np.allclose(front[m.uv[16:20, 1] == 1, 1], 0.5)              # and v up
    assert texture_parts(m, "box").tolist() == [RIGHT] * 4 + [LEFT] * 4 + [SIDES] * 16


def test_cylinder_caps_and_side_are_glowscripts():
    m = textured_cylinder()
    assert len(m.points) == 4 * 50 + 2
    parts = texture_parts(m, "cylinder")
    left, right, side = parts == LEFT, parts == RIGHT, parts == SIDES
    assert left.sum() == right.sum() == 51 and side.sum() == 100
    y, z = m.points[:, 1], m.points[:, 2]
    assert np.allclose(m.uv[left, 0], 0.5 * (1 + 2 * z[left]))
    assert np.allclose(m.uv[right, 0], 0.5 * (1 - 2 * z[right]))
    assert np.allclose(m.uv[left | right, 1], 0.5 + y[left | right])
    assert np.allclose(m.uv[side, 0], m.points[side, 0])               # u along the axis
    # v around: 0 at -y, 1 at +y, 0.5 at +-z: the picture goes round and back, no seam
    assert np.allclose(m.uv[side, 1], np.abs(np.arctan2(z[side], -y[side])) / np.pi)


def test_cone_pyramid_and_ring_are_glowscripts():
    cone = textured_cone()
    assert len(cone.points) == 1 + 3 * 201
    base = texture_parts(cone, "cone") == LEFT
    assert np.allclose(cone.uv[base, 0], 0.5 * (1 + 2 * cone.points[base, 2]))
    assert np.allclose(cone.uv[base, 1], 0.5 * (1 + 2 * cone.points[base, 1]))
    apex = cone.points[:, 0] == 1
    assert np.all(cone.uv[apex, 1] == 1) and np.all(cone.uv[~apex & ~base, 1] == 0)
    k = np.arange(201)
    assert np.allclose(cone.uv[2 + 3 * k, 0], 1 - k / 200)               # side rim: u = 1 - k/N
    assert np.allclose(cone.points[2], [0, 0, -0.5])                     # starting at -z
    pyr = textured_pyramid()
    assert pyr.uv[4:7].tolist() == [[0, 0], [0.25, 0], [0.125, 1]]      # top face
    assert texture_parts(pyr, "pyramid").tolist() == [LEFT] * 4 + [SIDES] * 12
    r = ring(1.0, 0.1, uv=True)
    assert len(r.points) == 61 * 21
    c, i = np.meshgrid(np.arange(61) / 60, np.arange(21) / 20, indexing="ij")
    assert np.allclose(r.uv, np.column_stack([c.ravel(), i.ravel()]))
    assert np.allclose(r.points[0], [0, 0, -0.9])                        # seam: back, inside
    assert np.all(texture_parts(r, "ring") == SIDES)


@pytest.mark.parametrize("spec, expected", [
    (TextureSpec("x", flipx=True), [[0.8, 0.3]]),
    (TextureSpec("x", flipy=True), [[0.2, 0.7]]),
    (TextureSpec("x", turn=1), [[0.3, 0.8]]),
    (TextureSpec("x", turn=2), [[0.8, 0.7]]),
    (TextureSpec("x", turn=3), [[0.7, 0.2]]),
    (TextureSpec("x", flipx=True, turn=1), [[0.3, 0.2]]),
])
def test_flips_and_turns_are_the_shaders(spec, expected):
    assert np.allclose(transform_uv(np.array([[0.2, 0.3]]), spec), expected)


# -- what a texture value means -----------------------------------------------------------

def test_names_urls_and_dicts(vp):
    assert vp.textures.earth == ":earth_texture.jpg" and vp.bumpmaps.stucco == ":stucco_bumpmap.jpg"
    names = [n for n in vars(vp.textures) if not n.startswith("_")]
    assert sorted(names) == sorted(texture_images.NAMES)
    assert spec_of(vp.textures.wood) == TextureSpec("builtin:wood")
    url = "https://s3.amazonaws.com/glowscript/textures/flower_texture.jpg"
    assert spec_of(url) == TextureSpec("builtin:flower")
    s = spec_of({"file": vp.textures.rug, "place": ["right", "sides"], "flipy": True, "turn": -3,
                 "bumpmap": vp.bumpmaps.stones})
    assert s == TextureSpec("builtin:rug", left=False, right=True, sides=True, flipy=True, turn=1,
                            bump="builtin:stones")
    assert spec_of({"file": vp.textures.rug, "place": "ends"})[1:4] == (True, True, False)
    assert spec_of(None) is None and not notes()


def test_an_unknown_url_or_missing_file_is_a_note_never_an_error(vp):
    assert spec_of("https://i.imgur.com/abc.jpg") is None
    assert spec_of("no_such_brick.jpg") is None
    assert spec_of({"bumpmap": vp.bumpmaps.rock}) is None
    assert len(notes()) == 3 and "i.imgur.com/abc.jpg" in notes()[0]
    spec_of("https://i.imgur.com/abc.jpg")
    assert len(notes()) == 3                                          # once each


# the wheel's RECORD (vpython-7.6.5.dist-info/RECORD): sha256, urlsafe base64, no padding
VPYTHON_RECORD = {
    "earth_texture.jpg": "yyVpq89KgmC2YtwLBAE3Nt7CnK3KvAGPgQuQvHYO0ds",
    "flower_texture.jpg": "ROHzoYuZ3cFci3IhcUjNEfiZD6SI6m8MK6craf1rj1U",
    "granite_texture.jpg": "Hj-WuhIM1ynSf0PO3BKGKqmP9nmB9J7j_hZxiCo4Kzc",
    "gravel_bumpmap.jpg": "BT4ZgOMKVaOqWJcFfYq-8Wjz9IUrTgPif5otbPBd_JE",
    "gravel_texture.jpg": "7Wws9Fgla3kxuIf2SRrqYcnj13s_JQAV-6S1VXC5bnM",
    "metal_texture.jpg": "r4DNpBW1tfT_XyNUFYw-OwVQ6Dfi6ccyPWr3k8Lys3E",
    "rock_bumpmap.jpg": "s82eR7GCBLoInkPTNQ9Jllo-DNumphbYUc8BbKPzeTs",
    "rock_texture.jpg": "f8MjGwTjmwUgXWaPlLWFJL1t2TtFFbto86g9Bsz9KPo",
    "rough_texture.jpg": "uxErPn3TXdeTRp1PUnyALfPTXlTFRU_rOpAx08cWl-0",
    "rug_texture.jpg": "Td8JaEER0NtPEdypHq9VRxuFzc5ctbF37wLP-cLrA1Q",
    "stones_bumpmap.jpg": "0HMVgD_vxxbWShFPuuYWT8VE4TSVbo_AhLD7xg6pblk",
    "stones_texture.jpg": "sXx38jOwzL2FeKDxThUAjW3tj7OMCHGnSVMJtlo_MKk",
    "stucco_bumpmap.jpg": "Rgc_EyFg-t1ofrUm2k6Qtx4axvqZ_99jnSgr25kZNZw",
    "stucco_texture.jpg": "NtdOzndRuv8ucv6NZM9iNFJZC6g1w_zNtApnlMDwBLQ",
    "wood_old_bumpmap.jpg": "7ya6xA6x-78DA8BcfnAmjVkUt11YK81mFF-Bi4APWIw",
    "wood_old_texture.jpg": "WbEWJntcC82sKKyBP80lhbtQxvz34LozUPzdmWLMhOQ",
    "wood_texture.jpg": "_mo8Sl-kpDNlLqZp0gpiVCx2LYUT-mxVaTxUu8DVWwk",
    "LICENSE-VPython.txt": "yYGFz27mxqAAQ5jDMqFPXhLkXYhP4aG_76e8XqmRE1c",   # LICENSE.txt
}
TEXTURE_DATA = ROOT / "springscene" / "vpython" / "data" / "vpython_textures"


def test_the_pictures_are_vpythons_own_files_unmodified():
    import base64
    import hashlib

    shipped = {p.name for p in TEXTURE_DATA.iterdir()}
    assert shipped == set(VPYTHON_RECORD)
    for name, digest in VPYTHON_RECORD.items():
        sha = hashlib.sha256((TEXTURE_DATA / name).read_bytes()).digest()
        assert base64.urlsafe_b64encode(sha).rstrip(b"=").decode() == digest, name
    assert {f"{n}_texture.jpg" for n in texture_images.NAMES} | \
        {f"{n}_bumpmap.jpg" for n in texture_images.BUMP_NAMES} == shipped - {"LICENSE-VPython.txt"}


def test_builtin_pictures_are_read_once_as_rgb():
    images = {n: texture_images.builtin_image(n) for n in texture_images.NAMES}
    assert all(im.dtype == np.uint8 and im.ndim == 3 and im.shape[2] == 3
               and not im.flags.writeable for im in images.values())
    assert texture_images.builtin_image("wood") is images["wood"]     # cached
    rough = images["rough"]                                          # a grey file, as RGB
    assert np.array_equal(rough[..., 0], rough[..., 2])
    wood, metal = images["wood"].astype(float), images["metal"].astype(float)
    assert wood[..., 0].mean() > wood[..., 2].mean() + 40             # wood is brown
    assert abs(metal[..., 0].mean() - metal[..., 2].mean()) < 20      # metal is grey
    earth = images["earth"].astype(float)
    assert earth.shape[1] == 2 * earth.shape[0]                       # equirectangular
    # the Pacific in the middle of the left quarter is blue; the Sahara is not
    h, w = earth.shape[:2]
    pacific = earth[h // 2 - 10:h // 2 + 10, w // 8 - 10: w // 8 + 10].reshape(-1, 3).mean(0)
    sahara = earth[int(h * 0.37), int(w * 0.53)]
    assert pacific[2] > pacific[0] + 60 and sahara[0] > sahara[2] + 30
    bump = texture_images.bump_image("stones").astype(float) / 255 * 2 - 1
    assert bump[..., 2].mean() > 0.8                      # normal maps: mostly straight out
    with pytest.raises(KeyError):
        texture_images.bump_image("earth")


def test_the_pictures_say_where_they_come_from():
    readme = (ROOT / "springscene" / "vpython" / "data" / "README.md").read_text()
    assert "vpython_textures/" in readme and "7.6.5" in readme and "MIT" in readme
    assert "22b98eb35d9fef8b43582680a80af40f357a6df760dd2b1d774383fb6641d3aa" in readme
    licence = (TEXTURE_DATA / "LICENSE-VPython.txt").read_text()
    assert "John Coady, Ruth Chabay, and Bruce Sherwood" in licence


# -- pictures -----------------------------------------------------------------------------

def _render(vp, size=(400, 400)):
    from springscene.vpython.draw.renderer import Renderer

    vp.scene.width, vp.scene.height = size
    r = Renderer(vp.scene, antialias=False)
    try:
        return r.frame().astype(int), r.view
    finally:
        r.close()


def _on_earth(lat: float, lon: float) -> np.ndarray:
    """A point of a unit sphere under the Earth map's (lat, lon), as GlowScript textures it."""
    phi = 2 * np.pi * (lon + 180) / 360
    c = math.cos(math.radians(lat))
    return np.array([-c * math.sin(phi), math.sin(math.radians(lat)), -c * math.cos(phi)])


def test_an_earth_has_blue_oceans_and_land_where_the_map_has_them(vp):
    vp.scene.range = 1.2
    vp.sphere(radius=1, texture=vp.textures.earth, shininess=0)
    img, view = _render(vp)

    def rgb(lat, lon):
        col, row = view.project(_on_earth(lat, lon))
        return img[int(round(row)) - 1:int(round(row)) + 2,
                   int(round(col)) - 1:int(round(col)) + 2].reshape(-1, 3).mean(axis=0)

    for lat, lon in ((0, -25), (-35, -15), (25, -45), (10, -35)):      # the Atlantic
        r, g, b = rgb(lat, lon)
        assert b > r + 25, (lat, lon, r, g, b)
    for lat, lon in ((23, 10), (23, 45), (-20, 25)):                   # Sahara, Arabia, Kalahari
        r, g, b = rgb(lat, lon)
        assert r > b + 10 and g > b, (lat, lon, r, g, b)
    r, g, b = rgb(48, 15)                                               # Europe: green
    assert g > b + 15 and g > r + 15
    r, g, b = rgb(0, 22)                                                # the Congo: green
    assert g > b + 10 and g >= r - 10
    north, south = rgb(50, 10), rgb(-50, 10)                            # Europe vs ocean
    assert north[0] > south[0] + 20


def test_the_texture_is_multiplied_by_the_colour(vp):
    vp.scene.range = 1
    vp.box(size=vp.vector(1.5, 1.5, 1.5), texture=vp.textures.flower, color=vp.color.red,
           shininess=0)                                      # no white highlight
    img, _ = _render(vp)
    lit = img.sum(axis=2) > 30
    assert lit.sum() > 20000
    assert img[lit][:, 1].max() < 12 and img[lit][:, 2].max() < 12      # no green, no blue
    assert img[lit][:, 0].std() > 10                                    # but a picture


def _two_colour_file(path):
    image = np.zeros((64, 64, 3), dtype=np.uint8)
    image[:32] = (255, 0, 0)           # top red
    image[32:] = (0, 0, 255)           # bottom blue
    iio.imwrite(path, image)


def test_a_local_image_file_is_a_texture_upright(vp, tmp_path, monkeypatch):
    _two_colour_file(tmp_path / "brick.png")
    monkeypatch.chdir(tmp_path)
    vp.scene.range = 1
    vp.box(size=vp.vector(1.5, 1.5, 0.1), texture="brick.png", emissive=True)
    img, view = _render(vp)
    col, row = view.project(np.array([0, 0.4, 0.05]))
    assert img[int(row), int(col)].tolist() == pytest.approx([255, 0, 0], abs=3)
    col, row = view.project(np.array([0, -0.4, 0.05]))
    assert img[int(row), int(col)].tolist() == pytest.approx([0, 0, 255], abs=3)


def test_place_textures_some_faces_and_leaves_the_rest_in_colour(vp, tmp_path):
    _two_colour_file(tmp_path / "t.png")
    vp.scene.range = 1.5
    vp.scene.forward = vp.vector(-1, 0, -1)
    vp.box(size=vp.vector(1, 1, 1), color=vp.color.green, emissive=True,
           texture={"file": str(tmp_path / "t.png"), "place": "right"})
    img, view = _render(vp)
    right = view.project(np.array([0.5, 0.3, 0]))          # +x face, upper half: red, untinted
    front = view.project(np.array([0, 0.3, 0.5]))          # +z face: the object's green
    assert img[int(right[1]), int(right[0])].tolist() == pytest.approx([255, 0, 0], abs=3)
    assert img[int(front[1]), int(front[0])].tolist() == pytest.approx([0, 255, 0], abs=3)


def test_an_unknown_url_is_noted_and_the_object_still_drawn(tmp_path):
    prog = tmp_path / "p.py"
    prog.write_text(textwrap.dedent("""\
        from vpython import *
        b = box(texture="https://example.com/bricks.jpg", color=color.orange)
        print(b.texture)
    """))
    result = run_program(prog, tmp_path / "p.png", RunOptions(page=False))
    assert any("https://example.com/bricks.jpg" in n and "no network" in n for n in result.notes)
    img = iio.imread(tmp_path / "p.png").astype(int)
    orange = (img[..., 0] > 150) & (img[..., 1] > 60) & (img[..., 2] < 40)
    assert orange.sum() > 5000


def test_textures_change_with_the_object_and_go_away_with_none(vp):
    vp.scene.range = 1
    b = vp.box(size=vp.vector(1.5, 1.5, 1.5), color=vp.color.white, emissive=True)
    plain, _ = _render(vp)
    b.texture = vp.textures.rug
    rug, _ = _render(vp)
    b.texture = None
    again, _ = _render(vp)
    assert np.array_equal(plain, again) and not np.array_equal(plain, rug)


def test_the_earth_and_moon_program(tmp_path):
    result = run_program(PROGRAMS / "vp7_textured_earth.py", tmp_path / "e.png",
                         RunOptions(duration=1, page=False))
    img = iio.imread(tmp_path / "e.png").astype(int)
    r, g, b = img[..., 0], img[..., 1], img[..., 2]
    assert ((b > r + 40) & (b > 80)).sum() > 200          # oceans
    assert ((g > b + 20) & (r > 60)).sum() > 50            # land
    assert not result.notes


def test_object_meshes_with_texture_coordinates_for_compounds(vp):
    from springscene.vpython.geometry.object_meshes import object_mesh
    from springscene.vpython.geometry.meshes import textured_box

    s = vp.sphere(radius=2, texture=vp.textures.earth)
    points, normals, triangles, rgb, uv = object_mesh(s, uv=True)
    assert len(points) == 961 and np.array_equal(uv, textured_sphere().uv)
    assert np.allclose(np.linalg.norm(points, axis=1), 2)
    b = vp.box(size=vp.vector(1.5, 1.5, 1.5), emissive=True)
    assert len(object_mesh(b, uv=True)[4]) == len(object_mesh(b)[0]) == 24
    s.visible = False
    c = vp.compound([b], texture=vp.textures.rug)
    assert np.array_equal(c._mesh.uv, textured_box().uv)   # it keeps its parts' texpos
    vp.scene.range = 1
    textured, view = _render(vp)
    c.texture = None
    c._dirty = True
    untextured, _ = _render(vp)
    assert not np.array_equal(untextured, textured)
    col, row = view.project(np.array([0, 0, 0.75]))          # the rug's dark red centre
    r, g, b_ = textured[int(row), int(col)]
    assert r > 50 and r > g + 40 and r > b_ + 40


@pytest.mark.parametrize("opacity", [1.0, 0.5])
def test_a_one_colour_texture_is_lit_as_that_colour_with_a_white_highlight(vp, tmp_path, opacity):
    """GlowScript multiplies the texel into the diffuse colour before lighting and adds the
    specular untinted (opaque_render_fragment.shader, peel_color_fragmentC1 ``lightAt``): a
    white sphere under a plain teal picture is drawn as a teal sphere, highlight and all."""
    teal = (20, 150, 170)
    iio.imwrite(tmp_path / "teal.png", np.full((16, 16, 3), teal, dtype=np.uint8))
    vp.scene.range = 1.2
    s = vp.sphere(radius=1, texture=str(tmp_path / "teal.png"), opacity=opacity)
    textured, _ = _render(vp)
    s.texture = None
    s.color = vp.vector(*teal) / 255
    plain, _ = _render(vp)
    rows, cols = np.mgrid[0:400, 0:400]
    inner = np.hypot(rows - 200, cols - 200) < 140       # inside both meshes' outlines
    diff = np.abs(textured - plain)[inner]
    assert diff.max() <= 6 and diff.mean() < 0.5
    top = textured[textured.sum(axis=2).argmax() // textured.shape[1]]
    assert top.max(axis=0)[0] > 60                   # the highlight is white: red appears


@pytest.mark.parametrize("transform", [{}, {"flipx": True}, {"turn": 1}, {"flipy": True, "turn": 3}])
def test_a_bump_map_bends_the_normal_along_glowscripts_bumpaxis(vp, tmp_path, transform):
    """opaque_render_fragment.shader: ``normal = Nb.x*bumpX + Nb.y*cross(normal, bumpX) +
    Nb.z*normal``, bumpX the box face's bumpaxis (mesh.js makeCube: the way the unflipped,
    unturned u grows, +x on the front face). A bump map of Nb = (1, 0, 0) everywhere turns
    the front face's normal to +x: it is lit as the plain box's right face is, whatever
    the flips and turns do to the picture."""
    iio.imwrite(tmp_path / "white.png", np.full((16, 16, 3), 255, dtype=np.uint8))
    iio.imwrite(tmp_path / "bump.png", np.full((16, 16, 3), (255, 128, 128), dtype=np.uint8))
    vp.scene.range = 1.5
    vp.scene.forward = vp.vector(-1, -0.3, -1)
    b = vp.box(size=vp.vector(1, 1, 1), shininess=0,
               texture={"file": str(tmp_path / "white.png"),
                        "bumpmap": str(tmp_path / "bump.png"), **transform})
    bumped, view = _render(vp)
    b.texture = None
    plain, _ = _render(vp)

    def at(img, point):
        col, row = view.project(np.array(point))
        return img[int(row) - 2:int(row) + 3, int(col) - 2:int(col) + 3].reshape(-1, 3).mean(0)

    front, right = (0, 0, 0.5), (0.5, 0, 0)
    assert np.abs(at(plain, front) - at(plain, right)).max() > 20     # the faces differ
    assert at(bumped, front) == pytest.approx(at(plain, right), abs=3)


def test_a_bump_map_that_cannot_be_had_is_a_note(vp, tmp_path):
    s = spec_of({"file": vp.textures.rock, "bumpmap": "no_such_bumps.jpg"})
    assert s == TextureSpec("builtin:rock") and "no_such_bumps.jpg" in notes()[-1]
    url = "https://s3.amazonaws.com/glowscript/textures/rock_bumpmap.jpg"
    assert spec_of({"file": vp.textures.rock, "bumpmap": url}).bump == "builtin:rock"
    iio.imwrite(tmp_path / "b.png", np.full((4, 4, 3), 128, dtype=np.uint8))
    assert spec_of({"file": vp.textures.rock, "bumpmap": str(tmp_path / "b.png")}).bump == \
        str((tmp_path / "b.png").resolve())


def test_a_cylinders_far_half_bends_its_bumps_the_other_way(vp, tmp_path):
    """mesh.js makeCylinder: the side's bumpaxis is +x (the way u grows) on the half whose
    v grows with the angle and -x on the other (mirrored) half: with Nb = (1, 0, 0) the
    near side (seen from +z) is lit as a +x face, the far side (seen from -z) as a -x face."""
    iio.imwrite(tmp_path / "white.png", np.full((16, 16, 3), 255, dtype=np.uint8))
    iio.imwrite(tmp_path / "bump.png", np.full((16, 16, 3), (255, 128, 128), dtype=np.uint8))
    texture = {"file": str(tmp_path / "white.png"), "bumpmap": str(tmp_path / "bump.png")}
    vp.scene.range = 1.5
    b = vp.box(size=vp.vector(1, 1, 1), shininess=0)
    faces = {}
    for forward, face in (((-1, 0, -1), (0.5, 0, 0)), ((1, 0, 1), (-0.5, 0, 0))):
        vp.scene.forward = vp.vector(*forward)
        img, view = _render(vp)
        col, row = view.project(np.array(face))
        faces[face[0] > 0] = img[int(row) - 2:int(row) + 3, int(col) - 2:int(col) + 3].mean((0, 1))
    assert np.abs(faces[True] - faces[False]).max() > 20                # +x and -x differ
    b.visible = False
    vp.cylinder(pos=vp.vector(-0.5, 0, 0), axis=vp.vector(1, 0, 0), radius=0.5, shininess=0,
                texture=texture)
    for forward, plus_x in (((0, 0, -1), True), ((0, 0, 1), False)):
        vp.scene.forward = vp.vector(*forward)
        img, view = _render(vp)
        col, row = view.project(np.array([0, 0, 0.5 if plus_x else -0.5]))
        side = img[int(row) - 2:int(row) + 3, int(col) - 2:int(col) + 3].mean((0, 1))
        assert side == pytest.approx(faces[plus_x], abs=4), plus_x
