"""Emissive objects glow as real VPython draws them: not flat, dimmed towards the outline.

GlowScript (VPython 7.6.5's GlowScript 3.2, shaders/opaque_render_fragment.shader and
peel_color_fragmentC1-C4, ``lightAt``) ignores the lights for an emissive surface and
draws ``color * min(1, 1.1*(1.5*N.V)^0.4)``, N.V the cosine between the surface normal and
the direction to the eye at that point. springscene/vpython/materials.py
(:func:`shade_emissive`) writes that rule into VTK's fragment shader.

tests/baselines/emissive/ holds real VPython's own pictures (benchmarks/fidelity/realvpython.py's method,
``canvas.screenshot``) of the program below, on black and on white. Before the rule
springscene drew emissive objects flat (VTK unlit: ambient + diffuse, 1.2x the colour):
mean dE00 6.6 (black) and 5.6 (white) over the objects' pixels against real VPython,
half of those pixels off by more than 5; with it 0.2 and 0.4.
"""

from __future__ import annotations

import math
from pathlib import Path

import imageio.v3 as iio
import numpy as np
import pytest

from springscene.view import imagediff
from springscene.vpython.draw.materials import glow_factor
from springscene.vpython.run.runner import run_program
from springscene.vpython.run.options import RunOptions

REAL = Path(__file__).resolve().parents[1] / "baselines" / "emissive"

MIXED = """\
from vpython import *
scene.width, scene.height = 480, 320
scene.background = color.{bg}
scene.range = 3.2
sphere(pos=vector(-2.2, 0.9, 0), radius=0.8, color=color.orange, emissive=True)
sphere(pos=vector(0, 0.9, 0), radius=0.8, color=color.white, emissive=True)
box(pos=vector(2.2, 0.9, 0), size=vector(1.2, 1.2, 1.2), axis=vector(1, 0, 1), color=color.cyan, emissive=True)
cylinder(pos=vector(-2.6, -1.4, 0), axis=vector(2.2, 0.4, -0.8), radius=0.5, color=color.green, emissive=True)
sphere(pos=vector(1.6, -1.3, 0), radius=0.8, color=color.magenta, emissive=True, opacity=0.5)
"""


def draw(tmp_path, source: str, name: str = "prog") -> np.ndarray:
    prog = tmp_path / f"{name}.py"
    prog.write_text(source)
    run_program(prog, tmp_path / f"{name}.png", RunOptions(page=False, canvas_only=True))
    return iio.imread(tmp_path / f"{name}.png")[..., :3].astype(float) / 255


def test_glow_factor_is_glowscripts_formula():
    assert glow_factor(1.0) == 1.0                                  # facing the eye
    assert glow_factor(0.0) == 0.0                                  # at the outline
    assert glow_factor(-0.5) == 0.0
    assert glow_factor(0.2) == pytest.approx(1.1 * 0.3 ** 0.4)      # 0.677
    edge = (1 / 1.1) ** 2.5 / 1.5            # where 1.1*(1.5 d)^0.4 reaches 1: d = 0.525
    assert glow_factor(edge - 0.01) < 0.995 and glow_factor(edge + 0.01) == 1.0


@pytest.mark.parametrize("bg", ["black", "white"])
def test_emissive_objects_match_real_vpython(tmp_path, bg):
    """Spheres, a turned box, a cylinder and a half-transparent sphere, all emissive."""
    real = iio.imread(REAL / f"mixed_{bg}.png")[..., :3].astype(float) / 255
    ours = draw(tmp_path, MIXED.format(bg=bg))
    de = imagediff.ciede2000(real, ours)
    back = real[0, 0]
    drawn = (np.abs(real - back).max(-1) > 0.02) | (np.abs(ours - back).max(-1) > 0.02)
    assert drawn.sum() > 20000
    assert de[drawn].mean() < 1.0                      # measured 0.21 / 0.36 (flat: 6.6 / 5.6)
    assert (de[drawn] > 5).mean() < 0.02               # measured 0.6 % / 0.8 % (flat: 51 / 39 %)
    # the orange sphere (centre 130, 115; its outline at x = 85 in both pictures): full
    # colour at its centre, darker and darker towards its outline (flat, it was 1.2x
    # orange throughout: red 1, green 0.72)
    row = ours[115, :, 0]
    assert ours[115, 130] == pytest.approx([1.0, 0.6, 0.0], abs=0.01)   # color.orange
    assert row[92] == 1.0 > row[89] > row[87] > row[86] and row[86] < 0.8


def test_glow_follows_the_angle_to_the_eye(tmp_path):
    """A grey emissive sphere, each pixel against the formula at the N.V that pixel's
    ray meets (the camera of VPython's range 2: distance 2*sqrt(3), vertical fov 60)."""
    ours = draw(tmp_path, """\
from vpython import *
scene.width, scene.height = 300, 300
scene.range = 2
sphere(radius=1, color=vector(0.5, 0.5, 0.5), emissive=True)
""")
    d = 2 * math.sqrt(3)
    ys, xs = np.mgrid[0:300, 0:300]
    t = math.tan(math.pi / 6)
    rays = np.stack([(xs + 0.5 - 150) / 150 * t, (150 - ys - 0.5) / 150 * t,
                     -np.ones_like(xs, dtype=float)], axis=-1)
    rays /= np.linalg.norm(rays, axis=-1, keepdims=True)
    eye = np.array([0.0, 0.0, d])
    b = rays @ eye
    disc = b ** 2 - (eye @ eye - 1)
    hit = disc > 0
    s = -b - np.sqrt(np.where(hit, disc, 0))
    normal = eye + s[..., None] * rays                 # unit sphere: the point is the normal
    cos = -(normal * rays).sum(-1)
    expected = 0.5 * glow_factor(cos)
    inside = hit & (disc > 0.02)                       # away from the anti-aliased outline
    err = np.abs(ours[..., 0] - expected)[inside]
    assert inside.sum() > 10000
    assert err.mean() < 0.01 and np.percentile(err, 99) < 0.03
    ring = inside & (cos < 0.3)                         # the darkened rim is drawn darker
    assert ours[..., 0][ring].mean() < 0.45 and ours[150, 150, 0] == pytest.approx(0.5, abs=0.01)


def test_a_half_transparent_emissive_sphere_shows_both_sides_glowing(tmp_path):
    """Real VPython: a 0.5-opaque emissive magenta sphere over black is 0.75 magenta at its
    centre (192 in mixed_black.png): its far side glows as its near one does, not black."""
    real = iio.imread(REAL / "mixed_black.png")[..., :3].astype(int)
    ours = draw(tmp_path, MIXED.format(bg="black"))
    y, x = 160 + int(1.3 / 3.2 * 160), 240 + int(1.6 / 3.2 * 160)
    assert real[y, x, 0] == pytest.approx(192, abs=3)
    assert ours[y, x] * 255 == pytest.approx([192, 0, 192], abs=4)


def test_emissive_turned_off_is_lit_again(tmp_path):
    """A box made emissive and then not: lit by the lights again, not glowing. Seen from
    behind, its face (normal -z) gets the ambient 0.2 and 0.3 x 0.44 of the second light:
    about 0.33 grey, where glowing it is white."""
    ours = draw(tmp_path, """\
from vpython import *
scene.width, scene.height = 200, 200
scene.forward = vector(0, 0, 1)
b = box(size=vector(1, 1, 1), color=color.white, emissive=True)
rate(30)
b.emissive = False
""")
    assert ours[100, 100] == pytest.approx([0.33, 0.33, 0.33], abs=0.05)
