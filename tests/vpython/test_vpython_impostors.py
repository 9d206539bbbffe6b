"""Small opaque spheres drawn as impostors (springscene.vpython.draw.impostors): which spheres,
their pictures against VPython's full 30-slice mesh (draft and anti-aliased, EGL and
OSMesa), and what a hundred thousand of them cost."""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap

import numpy as np
import pytest

import springscene.vpython.api as vp
from springscene.vpython.draw import impostors, renderer
from springscene.vpython.geometry import lod
from springscene.vpython.draw.renderer import Renderer
from springscene.vpython.draw.impostors import SphereBatch
from springscene.vpython.draw.instanced import InstancedBatch

from conftest import require_backend
from imagecompare import MAX_BAD_FRACTION, MAX_MEAN_DIFF, compare

# Impostors against full detail (VPython's 30-slice mesh): drafted, within the project's
# image tolerance (measured 0.004-0.041 % of pixels off, mean 0.006-0.068); anti-aliased,
# 0.08-0.14 % off, mean up to 0.55 (a highlight one pixel across lands on a pixel or its
# neighbour), where the cut-down meshes drawn before put 0.15-0.94 % off: bound 0.2 %.
AA_BAD_FRACTION = 0.002
AA_MEAN_DIFF = 0.6


@pytest.fixture(autouse=True)
def fresh():
    vp.reset()
    yield
    vp.reset()


def _cloud(n: int, radius: float, seed: int = 1) -> None:
    """``n`` spheres of ``radius`` in random colours in a 10-unit cube, seen whole."""
    rng = np.random.default_rng(seed)
    vp.scene.width, vp.scene.height = 480, 320
    for p, c in zip(rng.random((n, 3)) * 10, rng.random((n, 3))):
        vp.sphere(pos=vp.vector(*p), radius=radius, color=vp.vector(*c))
    vp.scene.center = vp.vector(5, 5, 5)


def _picture(antialias: bool, full: bool = False, backend_name: str = "auto"):
    r = Renderer(vp.scene, antialias=antialias, backend_name=backend_name,
                 lod=lod.FULL if full else lod.DEFAULT)
    r.frame()
    image = r.frame()                         # at the detail for the camera it placed
    batches = {k: b for k, b in r._batches.items() if k[0] == "sphere"}
    drawn = {k: (type(b), int(b.drawn_detail[1].sum())) for k, b in batches.items()}
    r.close()
    return image, drawn


def _edges(image: np.ndarray) -> int:
    """Pixels that are neither background nor like their four neighbours: outlines."""
    g = image.astype(int).sum(axis=2)
    inner = g[1:-1, 1:-1]
    flat = sum(np.abs(inner - g[1 + dy:g.shape[0] - 1 + dy, 1 + dx:g.shape[1] - 1 + dx])
               < 8 for dy, dx in ((0, 1), (0, -1), (1, 0), (-1, 0)))
    return int(((flat < 4) & (inner > 0)).sum())


@pytest.mark.parametrize("antialias", [False, True], ids=["draft", "aa"])
@pytest.mark.parametrize("n, radius", [(1000, 0.15), (3000, 0.08), (3000, 0.02)])
def test_impostors_draw_the_full_detail_spheres(n, radius, antialias):
    """Clouds of spheres under 5 px in radius: all impostors, drafted within the image
    tolerance of VPython's 30-slice meshes, anti-aliased within the bound above and
    along their outlines as meshes are (about as many blended outline pixels)."""
    _cloud(n, radius)
    image, drawn = _picture(antialias)
    full, drawn_full = _picture(antialias, full=True)
    assert list(drawn.values()) == [(SphereBatch, n)]
    assert list(drawn_full.values())[0][1] == 0               # full detail: meshes
    bad, mean = compare(image, full)
    if antialias:
        assert bad <= AA_BAD_FRACTION and mean <= AA_MEAN_DIFF, (bad, mean)
        assert 0.85 < _edges(image) / _edges(full) < 1.15
    else:
        assert bad <= MAX_BAD_FRACTION and mean <= MAX_MEAN_DIFF, (bad, mean)


def test_big_spheres_keep_the_mesh_and_ellipsoids_too():
    """A sphere over ~5.2 px of radius keeps a mesh (VPython's 30 slices for the biggest;
    an exact circle strays from its outline by more there); an ellipsoid among small
    spheres is not round, so it keeps a mesh too."""
    vp.scene.width, vp.scene.height = 400, 300
    vp.scene.range = 10
    vp.sphere(pos=vp.vector(-4, 0, 0), radius=3)                       # ~45 px
    small = [vp.sphere(pos=vp.vector(i, 3, 0), radius=0.1) for i in range(5)]
    vp.sphere(pos=vp.vector(0, -3, 0), radius=0.5)                     # ~8 px: a mesh
    vp.ellipsoid(pos=vp.vector(4, -3, 0), size=vp.vector(0.3, 0.2, 0.2))
    r = Renderer(vp.scene, antialias=False)
    r.frame()
    (key, batch), = [(k, b) for k, b in r._batches.items() if k[0] == "sphere"]
    assert isinstance(batch, SphereBatch)
    assert batch.drawn_detail[1].tolist() == [False] + [True] * 5 + [False, False]
    assert batch.instances == 3 and batch.drawn_detail[0] == 30           # the others' mesh
    assert batch.impostors.mesh.n_points == len(small)
    assert np.allclose(batch.impostors.mesh["radius"], 0.1 * impostors.EQUAL_AREA)
    r.close()


def test_zooming_in_turns_impostors_into_meshes():
    """The camera moving closer (range 20 to 1) redraws the same, unchanged spheres
    as meshes: their size on screen passed the threshold."""
    vp.scene.width, vp.scene.height = 300, 200
    vp.scene.range = 20
    balls = [vp.sphere(pos=vp.vector(i * 0.5, 0, 0), radius=0.2) for i in range(3)]
    r = Renderer(vp.scene, antialias=False)
    far = r.frame()
    (batch,) = [b for k, b in r._batches.items() if k[0] == "sphere"]
    assert batch.drawn_detail[1].all() and batch.no_meshes
    vp.scene.range = 1
    near = r.frame()
    assert not batch.drawn_detail[1].any() and batch.instances == len(balls)
    assert not batch.impostors.actor.GetVisibility()
    assert (near > 0).sum() > 50 * (far > 0).sum()
    r.close()


def test_every_frame_shows_the_spheres_as_the_camera_comes_and_goes():
    """Unchanged spheres, the camera moving near (meshes), far (impostors) and back,
    twice: each frame shows them (a part hidden at one detail is shown again)."""
    vp.scene.width, vp.scene.height = 300, 200
    for i in range(3):
        vp.sphere(pos=vp.vector(i * 0.5, 0, 0), radius=0.2)
    r = Renderer(vp.scene, antialias=False)
    lit = []
    for rng in (1, 20, 1, 20, 1):
        vp.scene.range = rng
        lit.append(int((r.frame().max(axis=2) > 0).sum()))
    r.close()
    assert lit[0] == lit[2] == lit[4] > 1000 and lit[1] == lit[3] > 0, lit


def test_a_negative_radius_keeps_its_mesh():
    """A sphere of negative radius is drawn as its mesh (a negative size), never as an
    impostor of negative radius, however small on screen."""
    vp.scene.width, vp.scene.height = 300, 200
    vp.scene.range = 20
    vp.sphere(radius=-0.2)
    vp.sphere(pos=vp.vector(2, 0, 0), radius=0.2)
    r = Renderer(vp.scene, antialias=False)
    r.frame()
    (batch,) = [b for k, b in r._batches.items() if k[0] == "sphere"]
    assert batch.drawn_detail[1].tolist() == [False, True]
    r.close()


def test_without_the_gl_extensions_spheres_stay_meshes(monkeypatch):
    monkeypatch.setattr(impostors, "_available", [False])
    _cloud(50, 0.1)
    image, drawn = _picture(False)
    assert list(drawn.values()) == [(InstancedBatch, 0)]
    assert image.any()


def test_hidden_and_transparent_spheres():
    """``visible = False`` hides an impostor; a sphere made transparent leaves the
    impostors' batch for a placed mesh (impostors are opaque only)."""
    vp.scene.width, vp.scene.height = 200, 150
    vp.scene.range = 10
    a = vp.sphere(pos=vp.vector(-2, 0, 0), radius=0.3, color=vp.color.red)
    b = vp.sphere(pos=vp.vector(2, 0, 0), radius=0.3, color=vp.color.green)
    r = Renderer(vp.scene, antialias=False)
    both = r.frame()
    assert (both[..., 0] > 150).any() and (both[..., 1] > 150).any()
    b.visible = False
    one = r.frame()
    assert (one[..., 0] > 150).any() and not (one[..., 1] > 150).any()
    a.opacity = 0.5
    r.frame()
    kinds = {(k[0], k[1]): type(bb) for k, bb in r._batches.items()}
    assert kinds == {("sphere", 0.5): renderer._Batch}
    r.close()


@pytest.mark.parametrize("backend_name", ["egl", "osmesa"])
def test_impostors_on_each_backend(backend_name, tmp_path):
    """The same picture from either off-screen backend (both Mesa's llvmpipe)."""
    require_backend(backend_name)
    prog = textwrap.dedent(f"""\
        import sys
        import numpy as np
        import springscene.vpython.api as vp
        from springscene.vpython.draw.renderer import Renderer
        rng = np.random.default_rng(1)
        vp.scene.width, vp.scene.height = 480, 320
        for p, c in zip(rng.random((300, 3)) * 10, rng.random((300, 3))):
            vp.sphere(pos=vp.vector(*p), radius=0.15, color=vp.vector(*c))
        vp.scene.center = vp.vector(5, 5, 5)
        r = Renderer(vp.scene, antialias=True, backend_name={backend_name!r})
        r.frame()
        np.save(sys.argv[1], r.frame())
        (batch,) = r._batches.values()
        print(int(batch.drawn_detail[1].sum()))
    """)
    _cloud(300, 0.15)
    full, _ = _picture(True, full=True)          # this process's backend (auto: EGL)
    path = tmp_path / "image.npy"
    proc = subprocess.run([sys.executable, "-c", prog, str(path)], capture_output=True,
                          text=True, timeout=300)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.split()[-1] == "300"          # all 300 drawn as impostors
    image = np.load(path)
    bad, mean = compare(image, full)
    assert bad <= AA_BAD_FRACTION and mean <= AA_MEAN_DIFF, (bad, mean)


MEMORY_PROGRAM = textwrap.dedent("""\
    import json, sys
    import numpy as np
    import springscene.vpython.api as vp
    from springscene.vpython.draw import renderer
    from springscene.vpython.draw.renderer import Renderer

    def rss():
        return int(open("/proc/self/statm").read().split()[1]) * 4096

    n, antialias, renderer.IMPOSTORS = int(sys.argv[1]), sys.argv[2] == "aa", sys.argv[3] == "1"
    vp.reset()
    r = Renderer(vp.scene, antialias=antialias)
    r.frame()
    before = rss()
    P = np.random.default_rng(1).random((n, 3)) * 10
    balls = [vp.sphere(pos=vp.vector(*p), radius=0.05) for p in P]
    r.frame()
    r.frame()
    print(json.dumps({"grew": rss() - before}))
""")


@pytest.mark.parametrize("antialias, impostors, bound", [
    ("draft", True, 900), ("aa", True, 900), ("draft", False, 10_000)])
def test_memory_of_many_small_spheres(tmp_path, antialias, impostors, bound):
    """What a small sphere (a pixel or two across) costs, everything counted (the Python
    objects, autoscale's record, the renderer's arrays, llvmpipe's buffers): 20,000 more
    spheres, measured in fresh processes. As impostors (one point whatever the
    anti-aliasing, 8,192 an actor): 0.64-0.65 KB (0.9-1.1 KB before the chunks and the
    shared vectors). As instances of a cut-down mesh, drafted: 2.7-5.2 KB
    (placing each sphere's vertices cost about 28 KB, and 90 KB in a first frame drawn
    at full detail); anti-aliased, llvmpipe's 4x multisampling holds about 60 bytes per
    triangle drawn: 20 KB a sphere."""
    prog = tmp_path / "mem.py"
    prog.write_text(MEMORY_PROGRAM)
    grew = []
    for n in (10000, 30000):
        out = subprocess.run([sys.executable, str(prog), str(n), antialias,
                              "1" if impostors else "0"],
                             capture_output=True, text=True, timeout=300, check=True)
        grew.append(json.loads(out.stdout.strip().splitlines()[-1])["grew"])
    per_sphere = (grew[1] - grew[0]) / 20000
    assert per_sphere < bound, per_sphere


def test_a_renderer_of_chunked_impostors_dropped_unclosed_is_freed(monkeypatch):
    """The observer that finishes each chunk's drawing holds the window weakly: a strong
    hold made a cycle through VTK (window, mapper, observer) Python's collector cannot see,
    and a renderer dropped without ``close()`` kept its window and buffers for good."""
    import gc
    import weakref

    monkeypatch.setattr(impostors, "CHUNK", 40)
    _cloud(100, 0.15)                                  # three chunks: two finishers
    r = Renderer(vp.scene, antialias=False)
    r.frame()
    (batch,) = [b for k, b in r._batches.items() if k[0] == "sphere"]
    assert len(batch.impostors.chunks) == 2
    window = weakref.ref(r.window.ren_win)
    del r, batch
    gc.collect()
    assert window() is None
