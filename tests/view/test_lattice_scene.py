"""The model of matter drawn: atoms where the camera puts them, bonds from centre to centre,
arrays rewritten in place, colours that follow the quantity, baselines on both backends."""

from __future__ import annotations

import math

import imageio.v3 as iio
import numpy as np
import pytest

from conftest import BASELINES, require_backend, run_cli
from imagecompare import check
from springscene import build, config, render
from springscene.model import physics
from springscene.view import camera
from springscene.view import lattice_scene as ls
from springscene.view.geometry import HelixBatch, HelixFrame, HelixTube, frames_from_up
from springscene.view.scene import AMBIENT, LIGHTS

W, H = 450, 300

# a small aluminium crystal, as configs/crystal.toml (oblique camera, coloured by speed)
CRYSTAL = """
[scene]
title = "a 3 x 3 x 3 crystal"
width = 450
height = 300

[camera]
forward = [-0.55, -0.45, -1.0]

[lattice]
shape = [3, 3, 3]
density = 2700.0
fixed = "start"

[bond]
k = 16.0

[atom]
molar_mass = 0.027

[start]
temperature = 300.0
seed = 3

[physics]
dt = 2e-15

[render]
duration = 1e-12
speed = 2e-13
color_by = "speed"
"""

# the page's ball and spring repeated: a chain, default camera, no colour map
CHAIN = """
[scene]
title = "a chain"
width = 450
height = 300

[lattice]
shape = [6]
spacing = 0.10
fixed = "ends"

[bond]
k = 15.0

[atom]
m = 0.10
radius = 0.025

[start]
kick = [0.5, 0, 0]

[physics]
dt = 0.01

[render]
duration = 2.0
"""

BASELINE_CONFIGS = {"crystal3": (CRYSTAL, 4e-13), "chain6": (CHAIN, 0.5)}


def from_toml(text: str, **sections) -> config.Config:
    import tomllib

    data = tomllib.loads(text)
    for section, values in sections.items():
        data.setdefault(section, {}).update(values)
    return config.from_dict(data)


def chain(n=3, fixed="ends", **sections) -> config.Config:
    """A macroscopic chain along x (d = 0.1 m), small canvas, no title."""
    data = {"scene": {"title": "", "width": W, "height": H},
            "lattice": {"shape": [n], "spacing": 0.1, "fixed": fixed},
            "bond": {"k": 15.0}, "atom": {"m": 0.1, "radius": 0.025},
            "physics": {"dt": 0.01}, "render": {"duration": 1.0}}
    for section, values in sections.items():
        data.setdefault(section, {}).update(values)
    return config.from_dict(data)


def crystal(**sections) -> config.Config:
    return from_toml(CRYSTAL, **sections)


def red_box_centre(img):
    """Centre of the bounding box of the red (free atom) pixels, and their count; the
    shadowed side of a red ball is dark red, so red is "red well above green and blue"."""
    r, g, b = (img[..., k].astype(int) for k in range(3))
    red = (r > 30) & (2 * g < r) & (2 * b < r)
    rows, cols = np.nonzero(red)
    return (cols.min() + cols.max() + 1) / 2, (rows.min() + rows.max() + 1) / 2, red.sum()


def silhouette_box_centre(view, centre, radius):
    """Pixel centre of the bounding box of a sphere's perspective silhouette: the planes
    through the eye tangent to the sphere (an off-axis sphere's outline is an ellipse
    whose centre lies farther out than its centre's projection)."""
    fwd = view.focal_point - view.position
    fwd = fwd / np.linalg.norm(fwd)
    right = np.cross(fwd, view.up)
    right /= np.linalg.norm(right)
    up = np.cross(right, fwd)
    rel = np.asarray(centre, float) - view.position
    x, y, z = rel @ right, rel @ up, rel @ fwd
    half_h = math.tan(view.fov / 2)
    half_w = half_h * view.width / view.height

    def ndc(a):                 # the two tangent directions' tangents, averaged in ndc
        phi, spread = math.atan2(a, z), math.asin(radius / math.hypot(a, z))
        return (math.tan(phi - spread) + math.tan(phi + spread)) / 2

    return ((ndc(x) / half_w + 1) * view.width / 2, (1 - ndc(y) / half_h) * view.height / 2)


def cyan(img):
    """Bond pixels: cyan, lit or in shadow (green and blue well above red)."""
    r, g, b = (img[..., k].astype(int) for k in range(3))
    return (g > 30) & (b > 30) & (2 * r < g) & (2 * r < b)


# ---- baselines on both backends, through the command line's still -----------------------

@pytest.mark.parametrize("backend_name", ["egl", "osmesa"])
@pytest.mark.parametrize("name", list(BASELINE_CONFIGS))
def test_still_matches_baseline(tmp_path, name, backend_name, regen):
    require_backend(backend_name)
    text, t = BASELINE_CONFIGS[name]
    path = tmp_path / f"{name}.toml"
    path.write_text(text)
    out = tmp_path / "still.png"
    run_cli("still", path, "--time", t, "--backend", backend_name, "--out", out, check=True)
    img = iio.imread(out)
    assert img.shape == (H, W, 3)
    check(img, BASELINES / "lattice" / f"{name}.png", regen and backend_name == "egl")


# ---- geometry of the frames ----------------------------------------------------------------

def test_atom_pixels_land_where_the_camera_projects():
    cfg = chain(3, bond={"style": "line"})
    s = build.system(cfg)
    with render.make_scene(cfg, s) as sc:
        seen = []
        for offset in [(0, 0, 0), (0.01, 0.03, 0), (-0.02, -0.04, 0.01)]:
            s.pos[1] = build.lattice(cfg).sites()[1] + offset
            sc.update(s)
            col, row, n = red_box_centre(sc.frame())
            want_col, want_row = silhouette_box_centre(sc.view, s.pos[1], 0.025)
            assert n > 200
            assert col == pytest.approx(want_col, abs=1.0)
            assert row == pytest.approx(want_row, abs=1.0)
            seen.append(row)
        assert seen[1] < seen[0] < seen[2]            # up, then down: it really moves


def test_helix_mesh_spans_atom_centre_to_centre():
    cfg = crystal(bond={"style": "helix"})
    s = build.system(cfg)
    physics.step(s, 100)
    s.pos[13] += (0.1e-10, -0.2e-10, 0.15e-10)       # a bond well off its rest direction
    with render.make_scene(cfg, s, color_range=(0.0, 1.0)) as sc:
        h = sc.helix
        rings = np.asarray(sc.bonds.points, float).reshape(len(s.i), h.n_rings, h.sides, 3)
        centre = rings.mean(axis=2)                   # the wire's centre line
        start, axis = s.pos[s.i], s.pos[s.j] - s.pos[s.i]
        length = np.linalg.norm(axis, axis=1)
        u = axis / length[:, None]
        rel = centre - start[:, None, :]
        along = np.einsum("snk,sk->sn", rel, u)
        off = np.linalg.norm(rel - along[..., None] * u[:, None, :], axis=2)
        d = sc.lattice.d
        assert np.allclose(along[:, 0], 0, atol=1e-5 * d)          # from atom i's centre
        assert np.allclose(along[:, -1], length, atol=1e-5 * d)    # to atom j's centre
        assert np.allclose(off, ls.HELIX_RADIUS * d, rtol=1e-3)    # coiled round that line
        # the normals are unit and point from the wire's centre line outwards
        normals = np.asarray(sc.bonds.point_data["Normals"], float).reshape(rings.shape)
        assert np.allclose(np.linalg.norm(normals, axis=-1), 1, atol=1e-5)
        wire = rings - centre[:, :, None, :]
        cos = np.einsum("snmk,snmk->snm", wire, normals) / np.linalg.norm(wire, axis=-1)
        assert cos.min() > 0.999


def test_cylinder_sticks_span_atom_centres():
    cfg = chain(2, fixed="start", bond={"style": "cylinder", "radius": 0.01},
                atom={"radius": 0.002})
    s = build.system(cfg)
    s.pos[1] += (0.03, 0, 0)                          # a stretched bond
    with render.make_scene(cfg, s) as sc:
        assert np.allclose(np.asarray(sc.bonds.points), (s.pos[0] + s.pos[1]) / 2)
        img = sc.frame()
        rows, cols = np.nonzero(cyan(img))
        # flat ends at the atoms' centres: seen in perspective, each end's disc reaches
        # farthest out on the picture at its rim nearest the camera
        rim = np.array([0, 0, 0.01])
        c0, c1 = sc.view.project(s.pos[:2] + rim)[:, 0]
        assert cols.min() == pytest.approx(c0, abs=1.5)       # the stick ends at atom 0
        assert cols.max() + 1 == pytest.approx(c1, abs=1.5)   # and at atom 1
        assert (rows.min() + rows.max() + 1) / 2 == pytest.approx(H / 2, abs=1.0)


@pytest.mark.parametrize("style", ["helix", "cylinder", "line"])
def test_update_rewrites_the_same_objects_in_place(style):
    cfg = crystal(bond={"style": style})
    s = build.system(cfg)
    with render.make_scene(cfg, s, color_range=(0.0, 1000.0)) as sc:
        first = sc.frame()
        ren = sc.window.renderer
        objects = (sc.atoms, sc.bonds, sc.atom_actor, sc.bond_actor)
        addresses = (sc.atoms.GetPoints().__this__, sc.bonds.GetPoints().__this__)
        n_props = ren.GetViewProps().GetNumberOfItems()
        atoms_before = np.array(sc.atoms.points)
        bonds_before = np.array(sc.bonds.points)
        physics.step(s, 60)
        sc.update(s)
        later = sc.frame()
        assert (sc.atoms, sc.bonds, sc.atom_actor, sc.bond_actor) == objects
        assert (sc.atoms.GetPoints().__this__, sc.bonds.GetPoints().__this__) == addresses
        assert ren.GetViewProps().GetNumberOfItems() == n_props
        assert sc.atoms.n_points == len(atoms_before) and sc.bonds.n_points == len(bonds_before)
        assert np.allclose(sc.atoms.points, s.pos.astype(np.float32))
        assert not np.array_equal(sc.atoms.points, atoms_before)
        if style != "line":          # lines are drawn on the atoms' own points
            assert not np.array_equal(sc.bonds.points, bonds_before)
        else:
            assert sc.bonds.GetPoints() is sc.atoms.GetPoints()
        assert not np.array_equal(first, later)


def test_held_atoms_are_gray_and_smaller():
    cfg = chain(3)
    with render.make_scene(cfg, build.system(cfg)) as sc:
        rgb = np.asarray(sc.atoms.point_data["rgb"])
        assert (rgb[[0, 2]] == 128).all() and tuple(rgb[1]) == (255, 0, 0)
        r = np.asarray(sc.atoms.point_data["radius"])
        assert r[1] == pytest.approx(0.025) and r[0] == r[2] == pytest.approx(0.6 * 0.025)
    assert ls.held_color((0.45, 0.45, 0.45)) != (0.45,) * 3
    assert max(abs(a - b) for a, b in zip(ls.held_color((0.45,) * 3), (0.45,) * 3)) > 0.2


# ---- colour by a quantity ------------------------------------------------------------------

def test_color_bar_is_drawn_with_its_title_and_scale():
    cfg = crystal()
    s = build.system(cfg)
    with render.make_scene(cfg, s) as sc:
        img = sc.frame()
        bar = sc.color_bar
        assert sc.color_title == "speed (km/s)" or sc.color_title == "speed (m/s)"
        region = img[bar.box].reshape(-1, 3).astype(int)
        for colour in (sc.lut[0], sc.lut[LUT_MID], sc.lut[-1]):      # the map's colours
            assert (np.abs(region - colour).max(axis=1) <= 6).sum() > 10
        assert (region.max(axis=1) < 40).sum() > 50                # black labels
        box = bar.box
    plain = crystal(render={"color_by": "none"})
    with render.make_scene(plain, build.system(plain)) as sc:
        assert sc.color_bar is None
        region = sc.frame()[box].reshape(-1, 3).astype(int)
        assert (np.abs(region - ls.colormap_table()[-1]).max(axis=1) <= 6).sum() == 0


LUT_MID = ls.LUT_SIZE // 2


def test_color_bar_text_is_white_on_a_dark_background():
    cfg = crystal(scene={"background": "black"})
    with render.make_scene(cfg, build.system(cfg)) as sc:
        region = sc.frame()[sc.color_bar.box]
        assert (region.min(axis=2) > 215).sum() > 50


def test_atom_colours_follow_the_quantity():
    """A fast atom takes the top colour, a still one the bottom, in the arrays and the picture."""
    cfg = chain(5, render={"color_by": "speed"})
    s = build.system(cfg)
    m = s.m[1]
    s.p[1] = (0, 0, 0)
    s.p[2] = (0.5 * m, 0, 0)            # the middle of the range
    s.p[3] = (0, 2.0 * m, 0)            # beyond the top: the top colour
    with render.make_scene(cfg, s, color_range=(0.0, 1.0)) as sc:
        rgb = np.asarray(sc.atoms.point_data["rgb"])
        assert np.array_equal(rgb[1], sc.lut[0])
        assert np.array_equal(rgb[2], sc.lut[LUT_MID])
        assert np.array_equal(rgb[3], sc.lut[-1])
        assert np.array_equal(rgb[[0, 4]], np.full((2, 3), 128))  # held: gray, not mapped
        img = sc.frame().astype(float)
        for atom, index in ((1, 0), (2, LUT_MID), (3, -1)):
            col, row = np.round(sc.view.project(s.pos[atom])).astype(int)
            centre = img[row - 1:row + 2, col - 1:col + 2].reshape(-1, 3).mean(axis=0)
            # the ray through the centre meets the ball where its normal faces the eye:
            # VPython's diffuse shading there (the highlight is elsewhere)
            n = sc.view.position - s.pos[atom]
            n /= np.linalg.norm(n)
            shade = AMBIENT + sum(i * max(float(n @ d) / np.linalg.norm(d), 0.0)
                                  for d, i in LIGHTS)
            assert centre == pytest.approx(shade * sc.lut[index], abs=6)
        s.p[3] = (0, 0, 0)              # the same scene recolours when the atom stops
        sc.update(s)
        assert np.array_equal(np.asarray(sc.atoms.point_data["rgb"])[3], sc.lut[0])


def test_color_range_is_fixed_for_the_whole_video():
    cfg = chain(8, start={"kick": [0.5, 0, 0]}, render={"color_by": "speed", "duration": 2.0})
    lo, hi = render.lattice_color_range(cfg)
    s = build.system(cfg)
    values = []
    for target in render.frame_steps(2.0, cfg.render.fps, cfg.physics.dt):
        physics.step(s, int(target) - s.steps)
        values.append(ls.scalar("speed", s, None)[~s.fixed])
    values = np.concatenate(values)
    assert lo == 0 and np.quantile(values, ls.COLOR_QUANTILE) <= hi <= 1.34 * values.max()
    assert hi == ls.nice_ceil(hi)                       # a round number
    # the scene keeps it while the atoms move, and make_scene (video and still) gets it
    s = build.system(cfg)
    with render.make_scene(cfg, s, antialias=False) as sc:
        assert sc.color_range == (lo, hi)
        physics.step(s, 50)
        sc.update(s)
        assert sc.color_range == (lo, hi)
        assert sc.unit == ("mm/s", 1e-3) and sc.color_title == "speed (mm/s)"
    # a still within the video has the video's colours, even with a faster atom ...
    fast = build.system(cfg)
    physics.step(fast, 150)
    fast.p[3] = (3 * hi * fast.m[3], 0, 0)
    with render.make_scene(cfg, fast, antialias=False) as sc:
        assert sc.color_range == (lo, hi)
    # ... and one later than the video's end widens them to what its state shows
    physics.step(fast, 60)                              # past 2 s
    fast.p[3] = (3 * hi * fast.m[3], 0, 0)
    with render.make_scene(cfg, fast, antialias=False) as sc:
        assert sc.color_range[1] >= 2.5 * hi


def test_displacement_is_from_each_atoms_site():
    cfg = chain(4, render={"color_by": "displacement"})
    s = build.system(cfg)
    sites = build.lattice(cfg).sites()
    s.pos[1] += (0.003, 0.004, 0)
    assert ls.scalar("displacement", s, sites) == pytest.approx([0, 0.005, 0, 0])


@pytest.mark.parametrize("kind,high,unit", [
    ("displacement", 4e-11, ("pm", 1e-12)), ("displacement", 0.05, ("mm", 1e-3)),
    ("displacement", 2.0, ("m", 1.0)), ("speed", 1000.0, ("km/s", 1e3)),
    ("speed", 800.0, ("m/s", 1.0)), ("speed", 0.3, ("mm/s", 1e-3))])
def test_display_units_read_well(kind, high, unit):
    assert ls.display_unit(kind, high) == unit


@pytest.mark.parametrize("x,want", [(0.73, 0.8), (1240.0, 1500.0), (1.0, 1.0), (3.1e-11, 4e-11),
                                    (9.0, 10.0), (2.2, 2.5)])
def test_nice_ceil(x, want):
    assert ls.nice_ceil(x) == pytest.approx(want, rel=1e-12)


# ---- bond styles ------------------------------------------------------------------------

def test_each_bond_style_renders_and_differs():
    images = {}
    for style in ("helix", "cylinder", "line"):
        cfg = crystal(bond={"style": style}, render={"color_by": "none"})
        with render.make_scene(cfg, build.system(cfg)) as sc:
            assert sc.bond_style == style
            images[style] = sc.frame().astype(int)
            assert cyan(images[style]).sum() > 500
    for a, b in (("helix", "cylinder"), ("helix", "line"), ("cylinder", "line")):
        assert np.abs(images[a] - images[b]).mean() > 1.0, (a, b)


def test_auto_style_takes_helices_up_to_the_limit():
    cfg = crystal()
    assert ls.bond_style(cfg.bond.style, ls.HELIX_MAX_BONDS) == "helix"
    assert ls.bond_style(cfg.bond.style, ls.HELIX_MAX_BONDS + 1) == "cylinder"
    assert ls.bond_style(crystal(bond={"style": "line"}).bond.style, 10) == "line"


def test_helix_batch_is_helix_tube_for_each_spring():
    rng = np.random.default_rng(1)
    pos, axes = rng.normal(size=(4, 3)), rng.normal(size=(4, 3))
    frames = np.stack([HelixFrame().set_axis(a) for a in axes])
    batch = HelixBatch(4, 0.015, 0.003, 7)
    pts, nrm = batch.points(pos, axes, frames)
    tube = HelixTube(0.015, 0.003, 7)
    m = batch.points_per_helix
    for k in range(4):
        p1, n1 = tube.points(pos[k], axes[k], frames[k])
        assert np.allclose(pts[k * m:(k + 1) * m], p1, rtol=0, atol=1e-14)
        assert np.allclose(nrm[k * m:(k + 1) * m], n1, rtol=0, atol=1e-14)
    assert np.array_equal(batch.faces()[:len(tube.faces())], tube.faces())
    # Gram-Schmidt frames: X along the axis, Y the up made perpendicular, right-handed
    F = frames_from_up(axes, np.tile([0.0, 1.0, 0.0], (4, 1)))
    assert np.allclose(F[:, :, 0], axes / np.linalg.norm(axes, axis=1)[:, None])
    assert np.allclose(np.linalg.det(F), 1.0)


# ---- camera, title, clock -----------------------------------------------------------------

def same_view(a: camera.View, b: camera.View) -> None:
    for field in ("position", "focal_point", "up", "fov", "near", "far"):
        assert np.allclose(getattr(a, field), getattr(b, field), rtol=1e-12, atol=0), field


def test_default_camera_autoscale_is_vpythons():
    cfg = chain(6, bond={"style": "cylinder"})
    s = build.system(cfg)
    with render.make_scene(cfg, s) as sc:
        c = cfg.camera
        want = camera.autoscale_range(sc.object_bounds(s), c.center, c.fov, W, H)
        same_view(sc.view, camera.view(c.center, c.forward, c.up, c.fov, want, W, H))


def test_oblique_camera_keeps_every_atom_in_the_picture():
    cfg = crystal(lattice={"shape": [4, 4, 4]})
    s = build.system(cfg)
    with render.make_scene(cfg, s) as sc:
        v = sc.view
        fwd = (v.focal_point - v.position) / np.linalg.norm(v.focal_point - v.position)
        depth = (s.pos - v.position) @ fwd
        r_px = sc.atom_radius / (2 * depth * math.tan(v.fov / 2)) * H
        px = v.project(s.pos)
        assert (px[:, 0] - r_px).min() > 0 and (px[:, 0] + r_px).max() < W
        assert (px[:, 1] - r_px).min() > 0 and (px[:, 1] + r_px).max() < H


def test_range_from_the_config_is_kept():
    cfg = chain(4, camera={"range": 0.5})
    with render.make_scene(cfg, build.system(cfg)) as sc:
        c = cfg.camera
        same_view(sc.view, camera.view(c.center, c.forward, c.up, c.fov, 0.5, W, H))


def test_title_and_clock_are_drawn():
    cfg = chain(4, scene={"title": "Ball and Spring Model of Matter"})
    with render.make_scene(cfg, build.system(cfg)) as sc:
        img = sc.frame()
        assert (img[:30].max(axis=2) < 60).sum() > 100          # black title letters
        corner = img[:40, :120].copy()
        sc.set_clock("t = 1.23 ps")
        assert (sc.frame()[:40, :120].max(axis=2) < 60).sum() > (corner.max(axis=2) < 60).sum() + 50


@pytest.mark.parametrize("n,chunks", [(1, 1), (5, 3), (1000, 7), (20, 1)])
@pytest.mark.parametrize("q", [0.5, 0.999, 1.0])
def test_streamed_quantile_is_numpys(n, chunks, q):
    rng = np.random.default_rng(n + chunks)
    parts = [rng.exponential(size=n) for _ in range(chunks)]
    want = np.quantile(np.concatenate(parts), q)
    assert ls.streamed_quantile(iter(parts), n * chunks, q) == pytest.approx(want, rel=1e-12)
