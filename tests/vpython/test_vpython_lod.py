"""Helices batched and drawn at a level of detail by their size on screen (geometry.helices, geometry.lod).

VPython's helix (primitives.js ``helix.__update``): ``coils * 60 + 1`` centre-line
points, a 16-sided tube of radius thickness/2 (size.y/40 when 0). At full detail the
batched mesh is exactly the single-helix tube (HelixTube's numbers); with a view, a
small helix gets fewer chords and sides, the fewest whose polygons stay within
the level of detail's pixels of the true circles (geometry.lod).
"""

from __future__ import annotations

import contextlib
import io
import math

import numpy as np
import pytest

import springscene.vpython.api as vp
from springscene import jobs
from springscene.app import cli
from springscene.errors import UserError
from springscene.view import camera
from springscene.view.geometry import HelixTube
from springscene.vpython.geometry import helices, lod, object_meshes, placement
from springscene.vpython.draw import culling, renderer
from springscene.vpython.draw.renderer import Renderer
from springscene.vpython.run.options import RunOptions
from springscene.vpython.run.supervise import run_supervised

from imagecompare import MAX_BAD_FRACTION, MAX_MEAN_DIFF, compare


@pytest.fixture(autouse=True)
def fresh():
    vp.reset()
    yield
    vp.reset()


@pytest.fixture
def helix_meshes(monkeypatch):
    """Helices drawn as meshes (as where the GL lacks the capsules' extensions): the tests
    of the meshes' level of detail and culling."""
    monkeypatch.setattr(renderer, "HELIX_CAPSULES", False)


def _helices():
    return [vp.helix(pos=vp.vector(1, 2, 3), axis=vp.vector(0.3, -2, 0.5), radius=0.2,
                     coils=7, thickness=0.05, color=vp.color.orange),
            vp.helix(pos=vp.vector(-1, 0, 0), axis=vp.vector(1, 0, 0), ccw=False, coils=2.5,
                     radius=0.5, color=vp.color.cyan),
            vp.helix(pos=vp.vector(0, 1, 0), axis=vp.vector(0, 3, 0), coils=7, radius=0.1)]


def test_full_detail_batch_is_each_helix_tube():
    """Three helices (two of one shape) in one mesh: each is HelixTube's tube, VPython's
    60 chords a coil and 16 sides, vertex for vertex."""
    hs = _helices()
    points, normals, tris, rgb, bounds, sig = helices.mesh(hs)
    assert sorted(g[:4] for g in sig) == [(2.5, False, 60, 16), (7.0, True, 60, 16)]
    got = {}
    start = 0
    for coils, ccw, _, _, m in sig:                      # groups in first-seen order
        n = (int(round(coils * 60)) + 1) * 16
        got[(coils, ccw)] = [points[start + i * n:start + (i + 1) * n] for i in range(m)]
        start += m * n
    for h, key in zip(hs, [(7.0, True), (2.5, False), (7.0, True)]):
        tube = HelixTube(h.radius, h.thickness, h.coils, h.ccw)
        R = placement.frames(np.array([h.axis.value]), np.array([h.up.value]))[0]
        want, want_n = tube.points(h.pos.value, np.array(h.axis.value), R)
        mine = got[key].pop(0)
        assert np.allclose(mine, want, atol=1e-12)
    assert len(tris) == (7 * 60 * 16 * 2) * 2 + 2.5 * 60 * 16 * 2
    assert tris.max() == len(points) - 1
    assert np.allclose(np.linalg.norm(normals, axis=1), 1)
    # bounds at full detail: the vertices' own
    n7 = (7 * 60 + 1) * 16
    assert np.allclose(bounds[0], [points[:n7].min(0), points[:n7].max(0)])


def test_default_wire_is_a_twentieth_of_the_radius():
    h = vp.helix(radius=0.4, axis=vp.vector(2, 0, 0))
    a = helices.helix_arrays([h])
    assert a["wire"][0] == pytest.approx(0.02)           # size.y / 40
    h.thickness = 0.1
    assert helices.helix_arrays([h])["wire"][0] == pytest.approx(0.05)


def test_zero_length_helix_is_not_drawn():
    h = vp.helix(axis=vp.vector(0, 0, 0))
    assert helices.mesh([h]) is None
    assert len(helices.mesh([h, vp.helix()])[0]) == (5 * 60 + 1) * 16


@pytest.mark.parametrize("radius_px, full", [(1000.0, True), (10.0, False), (2.0, False)])
def test_steps_keep_the_sagitta_under_the_tolerance(radius_px, full):
    tol = lod.DEFAULT.helix_px
    n = lod.steps_for(radius_px, helices.CHORD_STEPS, tol)
    assert (n == 60) == full
    if not full:
        assert radius_px * (1 - math.cos(math.pi / n)) <= tol
        finer = helices.CHORD_STEPS[helices.CHORD_STEPS.index(n) - 1]
        assert n == helices.CHORD_STEPS[-1] or \
            radius_px * (1 - math.cos(math.pi / finer)) <= tol


def _view(rng: float, w=900, h=600):
    return camera.view(np.zeros(3), np.array([0, 0, -1.0]), np.array([0, 1.0, 0]),
                       math.pi / 3, rng, w, h)


def test_detail_follows_the_size_on_screen():
    """A helix of radius 0.15 and wire 0.025 (AtomicSolid's) seen near, far and very far:
    the nearer, the finer; close up VPython's full 60 x 16."""
    h = vp.helix(pos=vp.vector(-0.2, 0, 0), axis=vp.vector(0.4, 0, 0), radius=0.15,
                 thickness=0.05)
    sig = [helices.mesh([h], _view(rng))[5][0][2:4] for rng in (0.3, 15.0, 300.0)]
    assert sig[0] == (60, 16)
    assert sig[1][0] < 60 and sig[1][1] < 16
    assert sig[2][0] <= sig[1][0] and sig[2][1] <= sig[1][1]
    assert sig[2] == (helices.CHORD_STEPS[-1], helices.SIDE_STEPS[-1])


def test_lod_mesh_stays_near_the_full_one():
    """At its level of detail each helix's vertices lie on the same tube: every LOD
    vertex is within the wire's radius of the full-detail centre line, and the bounds
    still hold the full-detail mesh."""
    h = vp.helix(pos=vp.vector(-0.2, 0, 0), axis=vp.vector(0.4, 0.1, 0), radius=0.15,
                 thickness=0.05)
    full = helices.mesh([h])
    coarse = helices.mesh([h], _view(15.0))
    assert len(coarse[0]) < len(full[0]) / 2
    centre = full[0].reshape(-1, 16, 3).mean(axis=1)
    d = np.linalg.norm(coarse[0][:, None] - centre[None], axis=2).min(axis=1)
    assert np.all(np.abs(d - 0.025) < 0.025 * 0.05 + 1e-3)
    lo, hi = coarse[4][0]
    assert np.all(full[0].min(0) >= lo - 1e-9) and np.all(full[0].max(0) <= hi + 1e-9)


@pytest.mark.usefixtures("helix_meshes")
def test_renderer_draws_a_lattice_of_helices_in_one_batch():
    """144 helices, one actor, drawn (draft) from the first frame at the detail for their
    size: the camera is placed before anything is drawn. Close to VPython's full detail:
    these helices (4 px in coil radius, a wire under a pixel) have edges a few
    hundredths of a pixel from full detail's, which flips whole pixels where an edge
    crosses a pixel's centre (0.13 % of them; the image tolerance is 0.05 %)."""
    def lattice_picture(level):
        vp.reset()
        vp.scene.width, vp.scene.height = 300, 200
        for i in range(12):
            for j in range(12):
                vp.helix(pos=vp.vector(i, j, 0), axis=vp.vector(0.6, 0, 0),
                         radius=0.15, thickness=0.05, color=vp.color.orange)
        r = Renderer(vp.scene, antialias=False, lod=level)
        image = r.frame()
        batches = [b for k, b in r._batches.items() if k[0] == "helix"]
        r.close()
        assert len(batches) == 1 and batches[0].signature[1][4] == 144
        return image, batches[0].signature[1][2:4]

    at_detail, detail = lattice_picture(lod.DEFAULT)
    assert detail != (60, 16)
    full, full_detail = lattice_picture(lod.FULL)
    assert full_detail == (60, 16)
    bad, mean = compare(at_detail, full)
    assert full.any() and bad <= 0.002 and mean <= MAX_MEAN_DIFF, (bad, mean)


@pytest.mark.usefixtures("helix_meshes")
def test_zooming_in_redraws_unchanged_objects_in_more_detail():
    """Objects that do not move keep their level of detail only while the camera does:
    the range shrinking (autoscale zooming in as a program runs, or the program setting
    it) redraws them finer, with no object touched."""
    vp.scene.width, vp.scene.height = 300, 200
    vp.scene.range = 60
    vp.sphere(radius=0.5)
    vp.helix(pos=vp.vector(1, 0, 0), radius=0.3, thickness=0.05)
    r = Renderer(vp.scene, antialias=False)
    r.frame()
    far = {k[0]: b.signature for k, b in r._batches.items()}
    vp.scene.range = 1.5
    r.frame()
    near = {k[0]: b.signature for k, b in r._batches.items()}
    r.close()
    assert far["sphere"][1][1] < near["sphere"][1][1] == lod.SPHERE_STEPS[0]
    assert far["helix"][1][2:4] < near["helix"][1][2:4] == (60, 16)


def _outward(points, normals, tris) -> np.ndarray:
    """Each triangle's winding normal (counter-clockwise) dotted with its vertices' normal."""
    a, b, c = points[tris[:, 0]], points[tris[:, 1]], points[tris[:, 2]]
    face = np.cross(b - a, c - a)
    return np.einsum("ij,ij->i", face, normals[tris].mean(axis=1))


def test_helix_and_sphere_triangles_face_out():
    """Back faces are culled on them: every triangle must be counter-clockwise from outside."""
    for view in (None, _view(3.0)):
        points, normals, tris, *_ = helices.mesh(_helices(), view, triangles=True) \
            if view is None else helices.mesh(_helices()[:1], view)
        assert np.all(_outward(points, normals, tris) > 0)
    for slices in (30, 10):
        t = object_meshes.template("sphere", slices)
        ok = _outward(t.points, t.normals, t.triangles)
        area = np.linalg.norm(np.cross(t.points[t.triangles[:, 1]] - t.points[t.triangles[:, 0]],
                                       t.points[t.triangles[:, 2]] - t.points[t.triangles[:, 0]]),
                              axis=1)
        assert np.all((ok > 0) | (area < 1e-12))          # degenerate pole triangles aside


@pytest.mark.usefixtures("helix_meshes")
def test_back_faces_culled_only_when_hidden():
    """Opaque spheres seen from outside: culled. Opaque helices: culled when their wire
    is thin on screen (under THIN_WIRE_PX in radius), not when it is thick (its open
    ends show its inside, as in GlowScript, which culls nothing). A camera inside a sphere (GlowScript draws its
    inside) or a transparent one: not culled."""
    vp.scene.width, vp.scene.height = 200, 150
    vp.scene.range = 3                                    # no autoscale: the camera stays
    ball = vp.sphere(radius=0.5)
    spring = vp.helix(pos=vp.vector(1, 0, 0), thickness=0.4)   # wire 10 px in radius
    r = Renderer(vp.scene, antialias=False)
    r.frame()
    ball.pos = vp.vector(0, 0, 0.01)
    r.frame()
    culled = {k[0]: b.actor.GetProperty().GetBackfaceCulling() for k, b in r._batches.items()}
    assert culled == {"sphere": 1, "helix": 0}
    vp.scene.range = 40                                   # the helix a few pixels long
    r.frame()
    spring.pos = vp.vector(1, 0, 0.01)
    r.frame()
    helix = [b for k, b in r._batches.items() if k[0] == "helix"][0]
    assert helix.signature[1][2] < helices.CHORDS_PER_COIL
    assert helix.actor.GetProperty().GetBackfaceCulling() == 1
    vp.scene.range = 3
    ball.radius = 100                                     # the camera is now inside it
    r.frame()
    ball.pos = vp.vector(0, 0, 0)
    r.frame()
    sphere = [b for k, b in r._batches.items() if k[0] == "sphere"][0]
    assert sphere.actor.GetProperty().GetBackfaceCulling() == 0
    r.close()
    style = {"opacity": 0.5}
    culling.cull_back_faces(sphere, style)           # actor gone: nothing to do


def test_wire_sides_take_a_share_of_the_tolerance():
    """The wire's sides are held to helix_px * side_share (fewer sides move the specular
    highlight, not only the outline); the coil's chords to helix_px."""
    h = vp.helix(pos=vp.vector(-0.2, 0, 0), axis=vp.vector(0.4, 0, 0), radius=0.15,
                 thickness=0.05)
    view = _view(15.0)
    a = helices.helix_arrays([h])
    chords, sides = helices.detail(a, np.array([0]), view)
    ppu = helices.pixels_per_unit(view, np.array([[0.2, 0, 0]]), 0.175)[0]
    wire_px, coil_px = 0.025 * ppu, 0.15 * ppu
    tol = lod.DEFAULT.helix_px * lod.DEFAULT.side_share
    assert lod.DEFAULT.side_share < 1
    assert wire_px * (1 - math.cos(math.pi / sides)) <= tol
    coarser = helices.SIDE_STEPS[helices.SIDE_STEPS.index(sides) + 1]
    assert wire_px * (1 - math.cos(math.pi / coarser)) > tol
    assert (chords, sides) == (lod.steps_for(coil_px, helices.CHORD_STEPS, lod.DEFAULT.helix_px),
                               lod.steps_for(wire_px, helices.SIDE_STEPS, tol))


def _lattice(n: int) -> list:
    """AtomicSolid's look: atoms of radius 0.3 a unit apart, springs of radius 0.15 and
    thickness 0.05 between them."""
    vp.scene.center = vp.vector(1, 1, 1) * (n - 1) / 2
    springs = []
    steps = (vp.vector(1, 0, 0), vp.vector(0, 1, 0), vp.vector(0, 0, 1))
    for x in range(n):
        for y in range(n):
            for z in range(n):
                p = vp.vector(x, y, z)
                vp.sphere(pos=p, radius=0.3, color=vp.vector(0, 0.58, 0.69))
                springs += [vp.helix(pos=p + 0.15 * d, axis=0.7 * d, radius=0.15,
                                     thickness=0.05, color=vp.color.orange)
                            for d in steps if max((p + d).value) < n]
    return springs


def _lattice_picture(size, antialias: bool, level: lod.LevelOfDetail):
    """The 2 x 2 x 2 lattice drawn at ``level``: its picture and its helix batch's
    signature (the chords and sides drawn)."""
    vp.reset()
    vp.scene.width, vp.scene.height = size
    _lattice(2)
    r = Renderer(vp.scene, antialias=antialias, lod=level)
    image = r.frame()
    sig = [b.signature for k, b in r._batches.items() if k[0] == "helix"][0]
    r.close()
    return image, sig


@pytest.mark.usefixtures("helix_meshes")
@pytest.mark.parametrize("antialias", [False, True], ids=["draft", "aa"])
@pytest.mark.parametrize("size", [(450, 300), (300, 200)])
def test_lattice_at_its_detail_is_within_the_image_tolerance(size, antialias):
    """AtomicSolid's springs, a few pixels thick, drawn at their level of detail: within
    the project's image tolerance of VPython's full 60 x 16 (at most 0.05 % of pixels
    off by more than 24/255, mean under 0.2); drafted with the sagitta allowed 0.3 px,
    outside it. Anti-aliased they are at full detail."""

    full, _ = _lattice_picture(size, antialias, lod.FULL)
    at_detail, sig = _lattice_picture(size, antialias, lod.DEFAULT)
    assert sig[1][4] == 12 and (sig[1][2:4] == (60, 16) or not antialias)
    bad, mean = compare(at_detail, full)
    assert bad <= MAX_BAD_FRACTION and mean <= MAX_MEAN_DIFF, (bad, mean, sig)
    if not antialias:                                   # a looser sagitta: outside it
        coarse, sig = _lattice_picture(size, antialias, lod.LevelOfDetail(helix_px=0.3))
        assert sig[1][2:4] < (60, 16) and compare(coarse, full)[0] > MAX_BAD_FRACTION


def test_no_frustum_culler_and_the_same_picture():
    """The renderer drops VTK's frustum culler (bounds over every cell at every frame);
    a scene with objects in and out of view draws the same with it put back."""
    from vtkmodules.vtkRenderingCore import vtkFrustumCoverageCuller  # noqa: PLC0415  heavy: vtk

    vp.scene.width, vp.scene.height = 200, 150
    vp.scene.range = 2
    vp.sphere(pos=vp.vector(0.5, 0, 0), radius=0.5, color=vp.color.red)
    vp.helix(pos=vp.vector(-1.5, -0.5, 0), axis=vp.vector(1, 1, 0), radius=0.3)
    vp.box(pos=vp.vector(40, 0, 0))                        # out of view
    r = Renderer(vp.scene, antialias=False)
    assert r.window.renderer.GetCullers().GetNumberOfItems() == 0
    without = r.frame()
    r.window.renderer.GetCullers().AddItem(vtkFrustumCoverageCuller())
    with_culler = r.frame()
    r.close()
    assert without.any() and np.array_equal(without, with_culler)


# ---- --lod: coarser helices on request ---------------------------------------------------

# --lod 0.3 against full detail (the lattice below and AtomicSolid at 900 x 600, measured):
# 1.4-2.5 % of pixels off by more than 24/255, mean about 1 level of 255
COARSE_BAD_FRACTION = 0.03
COARSE_MEAN_DIFF = 1.5


@pytest.mark.usefixtures("helix_meshes")
@pytest.mark.parametrize("antialias", [False, True], ids=["draft", "aa"])
def test_a_coarser_level_draws_fewer_polygons_near_the_full_picture(antialias):
    """``springscene vpython --lod 0.3`` (:func:`lod.coarser`): AtomicSolid-like springs
    with fewer chords and sides, anti-aliased too, the picture within the stated bound of
    full detail but outside the image tolerance."""

    def picture(level):
        return _lattice_picture((450, 300), antialias, level)

    full, _ = picture(lod.FULL)
    coarse, sig = picture(lod.coarser(0.3))
    chords, sides = sig[1][2:4]
    assert chords < 60 and sides < 16
    bad, mean = compare(coarse, full)
    assert MAX_BAD_FRACTION < bad <= COARSE_BAD_FRACTION and mean <= COARSE_MEAN_DIFF
    assert lod.coarser(None) is lod.DEFAULT
    _, default_sig = picture(lod.DEFAULT)
    if antialias:
        assert default_sig[1][2:4] == (60, 16)
    else:                                   # the default's finer detail than --lod 0.3's
        assert default_sig[1][2] > chords and default_sig[1][3] > sides


@pytest.mark.parametrize("value, message", [
    ("0", "--lod: 0: the level of detail must be more than 0 and at most 5 pixels"),
    ("-1", "--lod: -1: the level of detail must be more than 0 and at most 5 pixels"),
    ("nan", "--lod: nan: the level of detail must be more than 0 and at most 5 pixels"),
    ("6", "--lod: 6: the level of detail must be more than 0 and at most 5 pixels"),
    ("x", "--lod: 'x' is not a number of pixels")])
def test_lod_flag_refuses_what_is_not_a_detail(tmp_path, value, message):
    prog = tmp_path / "p.py"
    prog.write_text("from vpython import *\nhelix()\n")
    with pytest.raises(SystemExit) as exc, contextlib.redirect_stderr(io.StringIO()) as err:
        cli.main(["vpython", str(prog), "--out", str(tmp_path / "x.png"), f"--lod={value}"])
    assert exc.value.code == 2
    lines = err.getvalue().strip().splitlines()
    assert len(lines) == 1 and lines[0].endswith(message), lines
    assert not (tmp_path / "x.png").exists()


@pytest.mark.parametrize("value", ["0.3", float("nan"), -1, 0, 50, True])
def test_lod_option_of_the_library_is_checked_as_the_flag(tmp_path, value):
    """``jobs.vpython(..., lod=...)`` (the API's ``run_vpython``): the flag's rule, one
    line naming --lod, before anything runs."""
    prog = tmp_path / "p.py"
    prog.write_text("from vpython import *\nhelix()\n")
    with pytest.raises(UserError, match="^--lod .*: the level of detail must be more than 0"):
        jobs.vpython(prog, tmp_path / "x.png", lod=value)
    assert not (tmp_path / "x.png").exists()


@pytest.mark.slow                  # the supervised child is a new Python
def test_a_level_of_detail_reaches_the_supervised_child(tmp_path):
    """RunOptions.lod as a LevelOfDetail (VPython's full detail) or as --lod's pixels goes
    through the supervised child's request and draws there."""
    prog = tmp_path / "p.py"
    prog.write_text("from vpython import *\nhelix(radius=0.1, coils=20)\n")
    for level in (lod.FULL, 0.3):
        r = run_supervised(prog, tmp_path / "p.png", RunOptions(lod=level, page=False))
        assert r.frames == 1 and (tmp_path / "p.png").stat().st_size > 0
