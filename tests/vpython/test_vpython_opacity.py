"""Transparent objects (opacity < 1) coloured as real VPython colours them.

The pictures in tests/baselines/opacity/ are real VPython 7.6.5's own (GlowScript 3.2, WebGL
on SwiftShader in headless Chromium: as benchmarks/fidelity/realvpython.py takes them, ``canvas.screenshot``)
of the programs below, run unchanged. springscene draws the same programs and is held to them
with CIEDE2000 colour differences: at chosen points (the shadow side of a half-transparent
sphere, its bright rim, the inner faces of a half-transparent box, a back-facing triangle) and
over the whole picture. Before GlowScript's rules (springscene/vpython/materials.py) these
points were off by dE00 7-48; they are now within 0.5.
"""

from pathlib import Path

import imageio.v3 as iio
import numpy as np
import pytest
from skimage.color import deltaE_ciede2000, rgb2lab

import springscene.vpython.api as vpmod
from springscene.view.scene import MULTI_SAMPLES
from springscene.vpython.draw.renderer import Renderer

REAL = Path(__file__).resolve().parents[1] / "baselines" / "opacity"

POINT_DE = 2.5          # dE00 allowed at a chosen point (before: 7-48)
MEAN_DE = 1.0           # mean dE00 over the drawn pixels (issue 14's target per object: 2)
BAD_DE, BAD_SHARE = 5.0, 0.01    # at most 1 % of the picture off by more than dE00 5
MIN_IOU = 0.98          # drawn pixels (not background) of the two pictures

PROGRAMS = {
    "sphere_box_black": """\
from vpython import *
box(pos=vector(0, 0, -1.5), size=vector(3, 2, 0.5), color=color.blue)
sphere(pos=vector(0, 0, 0), radius=1, color=color.red, opacity=0.5)
""",
    "box_half": """\
from vpython import *
scene.forward = vector(-0.5, -0.6, -1)
box(pos=vector(0, 0, 0), size=vector(2, 1.5, 1), color=color.cyan, opacity=0.5)
""",
    "two_overlap": """\
from vpython import *
sphere(pos=vector(-0.5, 0, 0), radius=1, color=color.yellow, opacity=0.5)
sphere(pos=vector(0.5, 0, -0.5), radius=1, color=color.green, opacity=0.5)
""",
    "tri_alpha": """\
from vpython import *
box(pos=vector(0, 0, -1), size=vector(3, 2, 0.2), color=color.orange)
a = vertex(pos=vector(-1, -1, 0), color=color.red, opacity=0.5)
b = vertex(pos=vector(1, -1, 0), color=color.green, opacity=0.5)
c = vertex(pos=vector(1, 1, 0), color=color.blue, opacity=0.5)
d = vertex(pos=vector(-1, 1, 0), color=color.white, opacity=0.5)
quad(vs=[a, b, c, d])
e = vertex(pos=vector(-1.5, -0.5, 0.5), color=color.yellow, normal=vector(0, 0, -1))
f = vertex(pos=vector(-0.5, -0.5, 0.5), color=color.yellow, normal=vector(0, 0, -1))
g = vertex(pos=vector(-1, 0.5, 0.5), color=color.yellow, normal=vector(0, 0, -1))
triangle(vs=[e, f, g])
""",
}

# (row, column): what is there; real VPython's colour is read from its picture
POINTS = {
    "sphere_box_black": {
        (245, 310): "shadow side: the far inner face, lit with its outward normal",
        (260, 300): "lower shadow side over the box",
        (219, 238): "bright rim: the 0.3 light's highlight, in the first light's colour",
        (205, 298): "inside, below the highlights",
        (115, 305): "top of the sphere over the black background",
    },
    "box_half": {
        (200, 350): "inner back face seen through the front",
        (70, 400): "inner face behind the top",
        (150, 150): "inner left face",
        (250, 540): "right face",
    },
    "two_overlap": {
        (200, 320): "both spheres overlapping (four layers)",
        (280, 250): "shadow side of the yellow sphere",
        (250, 380): "shadow side of the green sphere",
        (200, 400): "green sphere alone",
    },
    "tri_alpha": {
        (250, 185): "opaque triangle whose normals face away: ambient only",
        (200, 320): "quad of vertex opacity 0.5 over the box",
        (250, 420): "quad corner",
    },
}


@pytest.fixture
def vp():
    vpmod.reset()
    return vpmod


def draw(vp, name: str) -> np.ndarray:
    names = {k: getattr(vp, k) for k in dir(vp) if not k.startswith("_")}
    exec(PROGRAMS[name].replace("from vpython import *\n", ""), names)  # noqa: S102
    r = Renderer(vp.scene)
    try:
        return r.frame()
    finally:
        r.close()


def de00(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    return deltaE_ciede2000(rgb2lab(a), rgb2lab(b))


@pytest.mark.parametrize("name", list(PROGRAMS))
def test_transparent_scene_matches_real_vpython(vp, name):
    real = iio.imread(REAL / f"{name}.png")[..., :3]
    ours = draw(vp, name)
    assert ours.shape == real.shape
    de = de00(real, ours)
    off = {what: (real[p].tolist(), ours[p].tolist(), round(float(de[p]), 2))
           for p, what in POINTS[name].items() if de[p] > POINT_DE}
    assert not off, f"{name}: (real, springscene, dE00) at {off}"
    drawn_real = np.any(real != real[0, 0], axis=-1)
    drawn_ours = np.any(ours != ours[0, 0], axis=-1)
    iou = (drawn_real & drawn_ours).sum() / (drawn_real | drawn_ours).sum()
    assert iou >= MIN_IOU
    assert de[drawn_real | drawn_ours].mean() <= MEAN_DE
    assert (de > BAD_DE).mean() <= BAD_SHARE


def test_points_are_where_the_rules_matter():
    """The chosen points are not background and not where any shading would do: in the
    real pictures the shadow side is darker than the lit side and the rim brighter than
    its neighbour a few pixels in."""
    real = iio.imread(REAL / "sphere_box_black.png")[..., :3].astype(int)
    assert real[245, 310, 0] < real[205, 298, 0] - 15          # shadow side darker
    assert real[219, 238].sum() > real[219, 250].sum() + 60    # a bright rim
    box = iio.imread(REAL / "box_half.png")[..., :3].astype(int)
    assert box[70, 400, 1] < box[150, 150, 1] - 30             # inner faces unlike
    tri = iio.imread(REAL / "tri_alpha.png")[..., :3].astype(int)
    assert tri[250, 185].tolist() == [84, 84, 0]                # 0.33 x yellow: ambient only


def test_opacity_change_switches_peeling_and_back(vp):
    """A scene peels (without anti-aliasing, as GlowScript's texture passes) only while
    something is transparent; made opaque again it is drawn exactly as before."""
    vp.box(pos=vp.vector(0, 0, -1.5), size=vp.vector(3, 2, 0.5), color=vp.color.blue)
    ball = vp.sphere(color=vp.color.red)
    r = Renderer(vp.scene)
    try:
        opaque = r.frame()
        assert not r.window.renderer.GetUseDepthPeeling()
        assert r.window.ren_win.GetMultiSamples() == MULTI_SAMPLES
        ball.opacity = 0.5
        half = r.frame()
        assert r.window.renderer.GetUseDepthPeeling()
        assert r.window.ren_win.GetMultiSamples() == 0
        # the centre: half the lit red over the blue box behind it
        assert half[200, 320, 0] < opaque[200, 320, 0] - 50
        assert half[200, 320, 2] > opaque[200, 320, 2] + 40
        ball.opacity = 1
        again = r.frame()
        assert not r.window.renderer.GetUseDepthPeeling()
        assert np.array_equal(again, opaque)
    finally:
        r.close()
