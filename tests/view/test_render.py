"""Rendered frames: geometry in the picture, image regression on both backends, end-to-end outputs."""

from __future__ import annotations

import csv
import math

import imageio.v3 as iio
import numpy as np
import pytest

from conftest import BASELINES, WIKI, require_backend, run_cli
from imagecompare import MAX_BAD_FRACTION, MAX_MEAN_DIFF, check, compare
from springscene import build, config, render
from springscene.model import physics

TIMES = (0.0, 0.13, 0.25, 0.38)   # bottom, middle, top, middle of the first period


@pytest.fixture(scope="module")
def scene(wiki_cfg):

    sc = render.make_scene(wiki_cfg, build.system(wiki_cfg))
    yield sc
    sc.close()


def ball_centroid(img):
    """Centre of the red ball's silhouette (bounding box: the highlight and the wire
    in front of it do not bias it) and its pixel count."""
    red = (img[..., 0] > 120) & (img[..., 1] < 100) & (img[..., 2] < 100)
    rows, cols = np.nonzero(red)
    return (cols.min() + cols.max() + 1) / 2, (rows.min() + rows.max() + 1) / 2, red.sum()


@pytest.mark.parametrize("y", [-0.06, -0.185, -0.24], ids=["compressed", "hanging", "stretched"])
def test_spring_mesh_spans_holder_to_ball_centre(scene, wiki_cfg, y):
    s = build.system(config.override(wiki_cfg, "ball", pos=(0.01, y, 0.0)))
    meshes_before = list(scene.spring_meshes)
    n_actors = len(scene.window.renderer.actors)
    scene.update(s)
    mesh = scene.spring_meshes[0]
    assert scene.spring_meshes == meshes_before and len(scene.window.renderer.actors) == n_actors
    rings = np.asarray(mesh.points).reshape(-1, 16, 3).mean(axis=1)   # centre line
    axis = s.pos[1] - s.pos[0]
    u = axis / np.linalg.norm(axis)
    along = (rings - s.pos[0]) @ u
    off = np.linalg.norm((rings - s.pos[0]) - along[:, None] * u, axis=1)
    assert along[0] == pytest.approx(0, abs=1e-12)                    # starts at the holder
    assert along[-1] == pytest.approx(np.linalg.norm(axis), abs=1e-12)  # ends at the ball centre
    assert np.allclose(off, wiki_cfg.spring.radius, rtol=0.02)          # coiled around that line


def test_ball_pixel_follows_world_position(scene, wiki_cfg):
    s = build.system(wiki_cfg)
    seen = []
    for t in TIMES:
        physics.step(s, int(round(t / s.dt)) - s.steps)
        scene.update(s)
        col, row, n = ball_centroid(scene.frame())
        want_col, want_row = scene.view.project(s.pos[1])
        assert n > 1000
        assert col == pytest.approx(want_col, abs=1.0)
        assert row == pytest.approx(want_row, abs=1.5)
        seen.append(row)
    assert seen[2] < seen[1] < seen[0]      # it really moves: up from the bottom


@pytest.mark.parametrize("backend_name", ["egl", "osmesa"])
@pytest.mark.parametrize("t", [0.0, 0.25])
def test_still_matches_baseline(tmp_path, backend_name, t, regen):
    require_backend(backend_name)
    out = tmp_path / "still.png"
    run_cli("still", WIKI, "--time", t, "--backend", backend_name, "--out", out, check=True)
    img = iio.imread(out)
    assert img.shape == (600, 900, 3)
    check(img, BASELINES / f"wiki_t{t:.2f}.png", regen and backend_name == "egl")


def test_baseline_tolerance_catches_a_ball_moved_one_pixel(wiki_cfg):
    """The stated tolerance is tight enough: the ball 1 px lower fails it."""

    base = iio.imread(BASELINES / "wiki_t0.00.png")
    s = build.system(wiki_cfg)
    with render.make_scene(wiki_cfg, s) as scene:    # its own scene: autoscale starts afresh
        same = scene.frame()
        px = 2 * scene.view.position[2] * math.tan(scene.view.fov / 2) / wiki_cfg.scene.height
        s.pos[1, 1] -= px                  # one pixel's worth of world at the ball's depth
        scene.update(s)
        moved = scene.frame()
    assert compare(same, base) == (0.0, 0.0)
    bad, mean = compare(moved, base)
    assert bad > MAX_BAD_FRACTION or mean > MAX_MEAN_DIFF


def test_title_contrasts_with_background(wiki_cfg):

    dark = config.from_dict({"scene": {"background": "black"}})
    with render.make_scene(dark, build.system(dark)) as sc:
        top = sc.frame()[:30]
    assert top.max() > 200                 # white letters on black


def test_info_reports_each_backend():
    for name, cls in (("egl", "vtkEGLRenderWindow"), ("osmesa", "vtkOSOpenGLRenderWindow")):
        require_backend(name)
        proc = run_cli("info", "--backend", name, check=True)
        assert f"render window: {cls}" in proc.stdout
        assert "GL renderer:" in proc.stdout and "vtk: 9." in proc.stdout


def test_simulate_csv(tmp_path, cli, wiki_cfg):
    out = tmp_path / "traj.csv"
    cli("simulate", WIKI, "--duration", 1.0, "--out", out, check=True)
    with open(out) as fh:
        rows = list(csv.reader(fh))
    assert rows[0] == ["t [s]", "x [m]", "y [m]", "z [m]", "px [kg m/s]", "py [kg m/s]",
                       "pz [kg m/s]", "K [J]", "Us [J]", "Ug [J]", "E [J]", "E_thermal [J]"]
    data = np.array(rows[1:], dtype=float)
    assert len(data) == 101 and data[0, 0] == 0 and data[-1, 0] == pytest.approx(1.0)
    ref = physics.run(build.system(wiki_cfg), 100)
    assert np.array_equal(data[:, 2], ref.pos[:, 1])          # full precision round trip
    assert np.allclose(data[:, 10], data[:, 7] + data[:, 8] + data[:, 9])
    m = wiki_cfg.ball.m
    assert np.allclose(data[:, 7], (data[:, 4:7] ** 2).sum(axis=1) / (2 * m))


def test_render_mp4(tmp_path):
    import imageio_ffmpeg

    out = tmp_path / "v.mp4"
    run_cli("render", WIKI, "--duration", 1.0, "--draft", "--quiet", "--out", out, check=True)
    reader = imageio_ffmpeg.read_frames(str(out))
    meta = reader.__next__()
    assert meta["size"] == (900, 600) and meta["fps"] == 50
    frames = [np.frombuffer(f, np.uint8).reshape(600, 900, 3) for f in reader]
    assert len(frames) == 50
    # the first frame is t = 0: the ball where the still puts it
    col, row, _ = ball_centroid(frames[0])
    still_col, still_row, _ = ball_centroid(iio.imread(BASELINES / "wiki_t0.00.png"))
    assert (col, row) == pytest.approx((still_col, still_row), abs=1.0)
    # and frame 12 (t = 0.24 s, near the top) has it higher
    assert ball_centroid(frames[12])[1] < row - 50


def test_render_gif(tmp_path):
    out = tmp_path / "v.gif"
    run_cli("render", WIKI, "--duration", 0.5, "--fps", 25, "--draft", "--out", out, check=True)
    frames = iio.imread(out, index=None)
    assert frames.shape == (12, 600, 900, 3)        # round(0.5 s * 25 fps)
    meta = iio.immeta(out, index=0)
    assert meta["duration"] == 40 and meta.get("loop") == 0


def test_gif_delays_keep_real_time():
    from springscene.outputs import gif_delays

    d = gif_delays(90, 30)                 # 33.3 ms a frame: 30, 40, 30, ... ms
    assert set(d) == {30, 40} and sum(d) == 3000
    assert gif_delays(5, 50) == [20] * 5


def test_interrupted_render_leaves_no_file(tmp_path, wiki_cfg, monkeypatch):
    from springscene import render

    out = tmp_path / "v.mp4"
    calls = []
    real_step = physics.step

    def boom(*a, **k):         # interrupt at frame 5, after four frames were encoded
        calls.append(1)
        if len(calls) == 5:
            raise KeyboardInterrupt
        return real_step(*a, **k)

    monkeypatch.setattr(render.physics, "step", boom)
    with pytest.raises(KeyboardInterrupt):
        render.render_video(wiki_cfg, out, duration=1.0, antialias=False)
    assert len(calls) == 5
    assert list(tmp_path.iterdir()) == []


def test_frame_times_are_whole_steps_in_real_time():
    from springscene.render import frame_steps

    steps = frame_steps(10.0, 50, 0.01)
    assert len(steps) == 500 and steps[0] == 0 and steps[-1] == 998
    assert np.all(np.diff(steps) == 2)
    assert math.isclose(len(steps) / 50, 10.0)


def test_driven_holder_moves_with_its_support():
    """A driven support's box follows the support node; the spring still starts there."""

    cfg = config.override(config.load(WIKI.parent / "driven.toml"), "drive", amplitude=0.03,
                          omega=3.0)
    s = build.system(cfg)
    with render.make_scene(cfg, s, antialias=False) as sc:
        physics.step(s, 52)
        sc.update(s)
        holder = sc.window.renderer.actors
        offset = s.pos[0] - np.asarray(cfg.holder.pos)
        assert offset[1] == pytest.approx(0.03 * math.sin(3.0 * 0.52))
        boxes = [a for a in holder.values()
                 if len(a.GetPosition()) == 3 and np.allclose(a.GetPosition(), offset)]
        assert len(boxes) == 1
        rings = np.asarray(sc.spring_meshes[0].points).reshape(-1, 16, 3).mean(axis=1)
        assert rings[0, 1] == pytest.approx(s.pos[0, 1], abs=1e-12)   # the helix starts there
