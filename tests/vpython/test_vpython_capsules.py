"""Curves drawn as ray-cast capsules (springscene.vpython.draw.capsules) and points through the
sphere impostors: which batches, their pictures against the tube and sphere meshes
(drafted and anti-aliased), depth against meshes, colour along a segment, and a turning
curve updated in place."""

from __future__ import annotations

import numpy as np
import pytest

import springscene.vpython.api as vp
from springscene.vpython.draw import capsules, renderer
from springscene.vpython.draw.capsules import CapsuleBatch
from springscene.vpython.draw.renderer import Renderer

from imagecompare import MAX_BAD_FRACTION, compare

# Capsules against VPython's 16-sided tube meshes, % of pixels off by more than 24/255:
# thin and coloured curves (radius 1-3 px) drafted 0.013-0.016 %, anti-aliased
# 0.08-0.12 %; thick (11 px) and tapered ones (per-point radii 1-8 px) drafted
# 0.07-0.14 %, anti-aliased 0.16-0.22 % (the true circle against the 16-gon's outline:
# 0.02 r apart at the vertices).
AA_BAD_FRACTION = 0.002
THICK_BAD_FRACTION = 0.002
THICK_AA_BAD_FRACTION = 0.003


@pytest.fixture(autouse=True)
def fresh(monkeypatch):
    vp.reset()
    yield
    vp.reset()


def _curve_scene(name: str) -> None:
    rng = np.random.default_rng(2)
    vp.scene.width, vp.scene.height = 360, 240
    t = np.linspace(0, 6.3, 120)
    if name == "thin":
        vp.curve(pos=[vp.vector(np.cos(u) * 3, np.sin(2 * u), np.sin(u)) for u in t],
                 color=vp.color.orange)
    elif name == "coloured":
        c = vp.curve(radius=0.05)
        for u in np.linspace(0, 12, 200):
            c.append(pos=vp.vector(u / 2 - 3, np.sin(u), np.cos(u)),
                     color=vp.vector(*rng.random(3)))
    elif name == "thick":
        vp.curve(pos=[vp.vector(np.cos(u) * 3, np.sin(2 * u), np.sin(u)) for u in t[::2]],
                 radius=0.15, color=vp.color.cyan)
        vp.sphere(radius=0.6, color=vp.color.red)
    elif name == "radii":
        c = vp.curve()
        for u in np.linspace(0, 12, 100):
            c.append(pos=vp.vector(u / 2 - 3, np.sin(u), np.cos(u)),
                     radius=0.02 + 0.12 * rng.random(), color=vp.vector(*(0.5 + 0.5 * rng.random(3))))


def _picture(antialias: bool, ray_cast: bool, monkeypatch):
    monkeypatch.setattr(renderer, "CAPSULES", ray_cast)
    r = Renderer(vp.scene, antialias=antialias)
    r.frame()
    image = r.frame()
    kinds = {k[0]: type(b) for k, b in r._batches.items()}
    r.close()
    return image, kinds


@pytest.mark.parametrize("antialias", [False, True], ids=["draft", "aa"])
@pytest.mark.parametrize("name", ["thin", "coloured", "thick", "radii"])
def test_capsules_draw_the_tube_meshes(name, antialias, monkeypatch):
    """Each scene as capsules and as VPython's tube meshes: within the bounds above."""
    _curve_scene(name)
    image, kinds = _picture(antialias, True, monkeypatch)
    vp.reset()
    _curve_scene(name)
    meshes, mesh_kinds = _picture(antialias, False, monkeypatch)
    curve_kind = "lines" if name in ("thin", "radii") else "tube"
    assert kinds[curve_kind] is CapsuleBatch and mesh_kinds[curve_kind] is renderer._Batch
    bad, _ = compare(image, meshes)
    thick = name in ("thick", "radii")
    bound = {(False, False): MAX_BAD_FRACTION, (True, False): AA_BAD_FRACTION,
             (False, True): THICK_BAD_FRACTION, (True, True): THICK_AA_BAD_FRACTION}
    assert bad <= bound[antialias, thick], bad
    assert (image.max(axis=2) > 24).sum() > 2000           # a curve was drawn


def _colour_at(image, row, col):
    return image[row, col].astype(int)


def test_depth_against_meshes_and_colour_along_a_segment():
    """A red-to-blue tube behind a green box is hidden by it and in front of a big white
    sphere shows over it; along the segment the colour blends, the end cap is blue."""
    vp.scene.width, vp.scene.height = 300, 200
    vp.scene.range = 5
    vp.scene.lights = []
    vp.scene.ambient = vp.color.gray(1)                  # unlit: the colours as they are
    c = vp.curve(radius=0.4)
    c.append(pos=vp.vector(-4, 0, 0), color=vp.color.red)
    c.append(pos=vp.vector(3, 0, 0), color=vp.color.blue)
    vp.box(pos=vp.vector(-1, 0, 2), size=vp.vector(1, 3, 0.2), color=vp.color.green)
    vp.sphere(pos=vp.vector(1.5, 0, -3), radius=1.8, color=vp.color.white)
    r = Renderer(vp.scene, antialias=False)
    image = r.frame()
    view = r.view
    r.close()

    def at(x, z=0.0):
        col, row = view.project(np.array([[x, 0.0, z]]))[0]
        return _colour_at(image, int(round(row)), int(round(col)))

    assert at(-1, 2)[1] > 200 and at(-1, 2)[0] < 50    # the box hides the tube
    assert at(1.5)[2] > at(1.5)[1] + 100                   # the tube over the sphere
    left, middle, cap = at(-3.6), at(0.3), at(3.2)
    assert left[0] > 200 and left[2] < 40                 # red at its start
    assert middle[0] > 80 and middle[2] > 80              # red and blue halfway
    assert cap[2] > 200 and cap[0] < 40                   # the hemisphere: the end's blue
    assert at(3.55).sum() < 30                            # past the cap


def test_a_turning_curve_updates_its_segments_in_place():
    """``c.rotate`` rewrites the batch's arrays: the same actor and mesh, no new cells;
    the picture turns."""
    vp.scene.width, vp.scene.height = 200, 150
    rng = np.random.default_rng(4)
    c = vp.curve(pos=[vp.vector(*p) for p in rng.random((300, 3)) * 2 - 1], radius=0.02)
    r = Renderer(vp.scene, antialias=False)
    first = r.frame()
    (batch,) = [b for k, b in r._batches.items() if k[0] == "tube"]
    actor, mesh, cells = batch.actor, batch.mesh, batch.mesh.GetPolys()
    c.rotate(angle=0.3, axis=vp.vector(0, 1, 0))
    second = r.frame()
    assert isinstance(batch, CapsuleBatch) and batch.segments == 299 + 299 // 8
    assert batch.actor is actor and batch.mesh is mesh and batch.mesh.GetPolys() is cells
    assert (np.abs(first.astype(int) - second.astype(int)).max(axis=2) > 24).mean() > 0.01
    for _ in range(20):                      # fewer segments: the same room, 20 drawn less
        c.pop()
    third = r.frame()
    assert batch.mesh.GetPolys() is cells and batch.segments == 299 + 299 // 8
    assert not np.array_equal(third, second)
    c.clear()
    assert not r.frame().any(axis=2).any()   # no segments: nothing drawn
    r.close()


def test_emissive_curves_and_missing_extensions_keep_meshes(monkeypatch):
    vp.scene.width, vp.scene.height = 200, 150
    vp.curve(pos=[vp.vector(-1, 0, 0), vp.vector(1, 0, 0)], radius=0.1, emissive=True)
    vp.curve(pos=[vp.vector(-1, 1, 0), vp.vector(1, 1, 0)], radius=0.1)
    r = Renderer(vp.scene, antialias=False)
    r.frame()
    kinds = {k[2]: type(b) for k, b in r._batches.items()}
    r.close()
    assert kinds == {True: renderer._Batch, False: CapsuleBatch}
    monkeypatch.setattr(capsules, "_available", [False])
    r = Renderer(vp.scene, antialias=False)
    image = r.frame()
    assert {type(b) for b in r._batches.values()} == {renderer._Batch}
    assert (image.max(axis=2) > 24).sum() > 500
    r.close()


def test_capsules_behind_a_transparent_sphere(monkeypatch):
    """With a transparent object the renderer peels GlowScript's layers (no MSAA): the
    capsules are drawn in its opaque pass and seen through the sphere as the meshes are
    (measured 0.025 % of pixels off)."""
    pictures = []
    for ray_cast in (True, False):
        vp.reset()
        vp.scene.width, vp.scene.height = 300, 200
        vp.curve(pos=[vp.vector(-3, -1, 0), vp.vector(0, 1, 0), vp.vector(3, -1, 0)],
                 radius=0.3, color=vp.color.yellow)
        vp.sphere(pos=vp.vector(0, 0, 1), radius=1.2, opacity=0.4, color=vp.color.cyan)
        image, kinds = _picture(True, ray_cast, monkeypatch)
        assert (kinds["tube"] is CapsuleBatch) == ray_cast
        pictures.append(image)
    bad, _ = compare(*pictures)
    assert bad <= MAX_BAD_FRACTION, bad
    column = pictures[0][40:100, 150].astype(int)          # the curve's top, in the sphere
    assert ((column[:, 0] > 100) & (column[:, 1] > 150)).any()   # yellow through cyan
