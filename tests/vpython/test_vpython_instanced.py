"""Template objects (spheres, boxes, cylinders, cones, pyramids) drawn as instances of one
unit mesh (springscene.vpython.draw.instanced): the same pictures as placing every vertex, a
few hundred bytes an object, and a level of detail from the first frame on."""

from __future__ import annotations

import math

import numpy as np
import pytest

import springscene.vpython.api as vp
from springscene.vpython.draw import renderer
from springscene.vpython.geometry import placement
from springscene.vpython.draw.renderer import Renderer
from springscene.vpython.draw.instanced import InstancedBatch, quaternions

from imagecompare import MAX_BAD_FRACTION, MAX_MEAN_DIFF, compare


@pytest.fixture(autouse=True)
def fresh(monkeypatch):
    """A fresh scene, its spheres all meshes: small ones are impostors otherwise
    (test_vpython_impostors.py)."""
    monkeypatch.setattr(renderer, "IMPOSTORS", False)
    vp.reset()
    yield
    vp.reset()


def _rotation(q: np.ndarray) -> np.ndarray:
    w, x, y, z = q
    return np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                     [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                     [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])


def test_quaternions_turn_as_the_frames_do():
    """Each branch of the conversion (trace largest, or one of the diagonal terms): the
    quaternion's rotation is the frame, to rounding."""
    rng = np.random.default_rng(3)
    axes = rng.normal(size=(200, 3))
    ups = rng.normal(size=(200, 3))
    R = placement.frames(axes, ups)
    special = np.array([np.eye(3), np.diag([1.0, -1, -1]), np.diag([-1.0, 1, -1]),
                        np.diag([-1.0, -1, 1])])
    R = np.concatenate([R, special])
    q = quaternions(R)
    assert np.allclose(np.linalg.norm(q, axis=1), 1)
    for qi, Ri in zip(q, R):
        assert np.allclose(_rotation(qi), Ri, atol=1e-12)


def _scene():
    """Every template kind, turned, stretched (an ellipsoid), in colours."""
    vp.scene.width, vp.scene.height = 320, 240
    vp.sphere(pos=vp.vector(-1.5, 0.8, 0), radius=0.5, color=vp.color.red)
    vp.ellipsoid(pos=vp.vector(0, 0.8, 0), axis=vp.vector(1, 0.4, 0.2), size=vp.vector(1.4, 0.6, 0.9),
                 color=vp.color.green)
    vp.box(pos=vp.vector(1.5, 0.8, 0), axis=vp.vector(1, 1, 0), up=vp.vector(0, 0.3, 1),
           size=vp.vector(0.8, 0.5, 0.3), color=vp.color.cyan)
    vp.cylinder(pos=vp.vector(-2, -1, 0), axis=vp.vector(1, 0.5, -0.5), radius=0.3,
                color=vp.color.orange)
    vp.cone(pos=vp.vector(0, -1.2, 0), axis=vp.vector(0.3, 1, 0.4), radius=0.4,
            color=vp.color.magenta)
    vp.pyramid(pos=vp.vector(1.3, -1, 0), axis=vp.vector(0, 0.2, 1), size=vp.vector(1, 0.7, 0.5),
               color=vp.color.yellow)
    for i in range(30):
        vp.sphere(pos=vp.vector(-2.5 + i * 0.17, -2, 0.2 * math.sin(i)), radius=0.06)


@pytest.mark.parametrize("antialias", [False, True], ids=["draft", "aa"])
def test_instances_draw_the_placed_meshes_picture(antialias, monkeypatch):
    """The same scene with every vertex placed in numpy and with instancing: within the
    image tolerance (the GPU places the same triangles in single precision)."""
    def picture(instancing: bool):
        monkeypatch.setattr(renderer, "INSTANCING", instancing)
        vp.reset()
        _scene()
        r = Renderer(vp.scene, antialias=antialias)
        image = r.frame()
        kinds = {k[0]: type(b) for k, b in r._batches.items()}
        r.close()
        return image, kinds

    placed, kinds = picture(False)
    assert InstancedBatch not in kinds.values()
    instanced, kinds = picture(True)
    assert all(kinds[k] is InstancedBatch for k in ("sphere", "box", "cylinder", "cone",
                                                     "pyramid"))
    bad, mean = compare(instanced, placed)
    assert placed.any() and bad <= MAX_BAD_FRACTION and mean <= MAX_MEAN_DIFF, (bad, mean)


def test_transparent_and_emissive_keep_placed_meshes():
    vp.scene.width, vp.scene.height = 200, 150
    vp.sphere(opacity=0.5)
    vp.box(emissive=True, pos=vp.vector(1, 0, 0))
    vp.sphere(pos=vp.vector(-1, 0, 0))
    r = Renderer(vp.scene, antialias=False)
    r.frame()
    kinds = {(k[0], k[1], k[3]): type(b) for k, b in r._batches.items()}
    r.close()
    assert kinds[("sphere", 0.5, False)] is not InstancedBatch
    assert kinds[("box", 1.0, True)] is not InstancedBatch
    assert kinds[("sphere", 1.0, False)] is InstancedBatch


def test_objects_added_and_removed_resize_the_instances():
    vp.scene.width, vp.scene.height = 200, 150
    vp.scene.range = 5
    balls = [vp.sphere(pos=vp.vector(i, 0, 0), radius=0.3) for i in range(3)]
    r = Renderer(vp.scene, antialias=False)
    one = r.frame()
    balls.append(vp.sphere(pos=vp.vector(-2, 0, 0), radius=0.3))
    two = r.frame()
    batch = [b for k, b in r._batches.items() if k[0] == "sphere"][0]
    assert batch.instances == 4 and not np.array_equal(one, two)
    balls[0].visible = False
    balls[3].visible = False
    three = r.frame()
    assert batch.instances == 2
    r.close()
    assert (three.astype(int) - one).any()
