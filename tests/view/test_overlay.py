"""Overlays: a clock in the scene, a y(t) graph below it, energy bars beside it.

One overlay video and one plain video of the wiki scene (0.5 s at 20 fps, 10
frames each) are rendered through the CLI; the panels' pixels are checked against
where their axes put the data, and one composed frame against a baseline.
"""

from __future__ import annotations

from pathlib import Path

import imageio.v3 as iio
import numpy as np
import pytest

from conftest import BASELINES, ROOT, WIKI, run_cli
from imagecompare import MAX_BAD_FRACTION, MAX_MEAN_DIFF, check, compare
from springscene import build, config, render
from springscene.model import physics
from springscene.view.overlay import ENERGY_BARS, OVERLAYS, TRACE_COLOR, parse_overlays

DURATION, FPS = 0.5, 20          # frame f at t = f / 20 s: frame 5 is t = 0.25 s
W, H = 900, 600                  # the wiki scene
CLOCK = (slice(0, 48), slice(0, 160))   # the scene's top-left corner, where the clock is
ALL = ("time", "graph", "energy")


def read_mp4(path: Path) -> tuple[tuple[int, int], list[np.ndarray]]:
    import imageio_ffmpeg

    reader = imageio_ffmpeg.read_frames(str(path))
    meta = reader.__next__()
    w, h = meta["size"]
    return (w, h), [np.frombuffer(f, np.uint8).reshape(h, w, 3) for f in reader]


@pytest.fixture(scope="module")
def cfg():
    return config.override(config.load(WIKI), "render", duration=DURATION, fps=FPS)


@pytest.fixture(scope="module")
def videos(tmp_path_factory):
    """(size, frames) of the overlay video and of the plain one, same config and times,
    at the high quality (CRF 15: less H.264 noise between the two layouts)."""
    d = tmp_path_factory.mktemp("overlay")
    out = {}
    for name, extra in (("overlay", ("--overlay", ",".join(ALL))), ("plain", ())):
        path = d / f"{name}.mp4"
        run_cli("render", WIKI, "--duration", DURATION, "--fps", FPS, "--quiet", "-q", "high",
                *extra,
                "--out", path, check=True)
        out[name] = read_mp4(path)
    return out


@pytest.fixture(scope="module")
def layout(cfg):
    """The panels as the render lays them out (same config: same axes, same pixels)."""
    return render.make_overlays(cfg, ALL)


def states(cfg, frames):
    """The system at each frame's time, as the render steps it."""
    s = build.system(cfg)
    for f in frames:
        physics.step(s, int(round(f / (FPS * cfg.physics.dt))) - s.steps)
        yield s


def near(img: np.ndarray, color, tol: int = 60) -> np.ndarray:
    """Pixels within ``tol`` (0-255, any channel) of ``color`` (0-1 floats)."""
    c = np.rint(np.asarray(color) * 255).astype(int)
    return np.abs(img.astype(int) - c).max(axis=-1) <= tol


# ---- names ------------------------------------------------------------------------------

def test_parse_overlays():
    assert parse_overlays("time, graph,time") == ("time", "graph")
    assert parse_overlays("") == ()
    assert parse_overlays(",".join(OVERLAYS)) == OVERLAYS


def test_unknown_overlay_is_bad_input(tmp_path, cli):
    out = tmp_path / "v.mp4"
    proc = cli("render", WIKI, "--overlay", "clock", "--out", out)
    assert proc.returncode == 2
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and "--overlay" in lines[0] and "'clock'" in lines[0]
    assert list(tmp_path.iterdir()) == []


# ---- layout without a renderer ------------------------------------------------------------

def test_clock_alone_keeps_the_frame(cfg):
    ov = render.make_overlays(cfg, ("time",))
    img = np.zeros((H, W, 3), np.uint8)
    assert ov.size == (W, H) and not ov.panels
    assert ov.compose(img, build.system(cfg)) is img


def test_frame_size_per_overlay(cfg):
    assert render.make_overlays(cfg, ("graph",)).size == (900, 600 + 240)
    assert render.make_overlays(cfg, ("energy",)).size == (900 + 320, 600)
    assert render.make_overlays(cfg, ALL).size == (900 + 320, 600 + 240)


def test_narrow_scene_gets_a_readable_graph():
    small = config.from_dict({"scene": {"width": 200, "height": 150, "background": "black"},
                              "render": {"duration": 1.0}})
    assert render.make_overlays(small, ("energy",)).size == (200 + 320, 360)   # bars at least 360 tall
    ov = render.make_overlays(small, ("graph", "energy"))
    assert ov.size == (360 + 320, 150 + 240)     # the graph at least 360 wide
    img = np.full((150, 200, 3), 7, np.uint8)
    frame = ov.compose(img, build.system(small))
    assert frame.shape == (390, 680, 3)
    assert np.array_equal(frame[:150, :200], img)
    assert (frame[:150, 200:360] == 0).all()            # padded with the scene's black
    assert (frame[150:390, :360] < 250).any()           # the graph is drawn


def test_energy_bars_thermal_grows_total_flat():
    """Damped: the thermal bar grows, the total (K + Us + Ug + thermal) stays put."""
    damped = config.override(config.load(ROOT / "configs" / "damped.toml"), "render",
                             duration=4.0)
    ov = render.make_overlays(damped, ("energy",))
    x0 = W
    heights = []
    s = build.system(damped)
    for n in (0, 200, 400):
        physics.step(s, n - s.steps)
        frame = ov.compose(np.zeros((H, W, 3), np.uint8), s)
        heights.append(bar_heights(frame[:, x0:], ov.energy))
    thermal = [h["thermal"] for h in heights]
    total = [h["total"] for h in heights]
    assert thermal[0] == 0 and thermal[0] < thermal[1] < thermal[2]
    # flat up to Euler-Cromer's own energy wobble, which the bars (about equilibrium,
    # 1/2 k A^2 tall) show at under 1 %
    assert max(total) - min(total) <= 0.01 * max(total)


def bar_heights(panel: np.ndarray, energy) -> dict[str, int]:
    """Pixel height of each bar: its colour down its centre column."""
    ax = energy.ax
    h = energy.height
    out = {}
    for i, (label, color) in enumerate(ENERGY_BARS):
        col = int(round(ax.transData.transform((i, 0))[0]))
        top, bottom = (int(round(h - y)) for y in ax.transData.transform(
            [(i, ax.get_ylim()[1]), (i, ax.get_ylim()[0])])[:, 1])
        out[label] = int(near(panel[top + 2:bottom - 2, col], color, 40).sum())
    return out


def expected_heights(energy, e) -> dict[str, float]:
    ax = energy.ax
    zero = ax.transData.transform((0, 0))[1]
    values = np.array(energy.values(e)) / energy.scale
    return {label: abs(ax.transData.transform((0, v))[1] - zero)
            for (label, _), v in zip(ENERGY_BARS, values)}


# ---- the rendered video -------------------------------------------------------------------

def test_video_frame_size(videos):
    size, frames = videos["overlay"]
    assert size == (W + 320, H + 240) and len(frames) == 10
    assert videos["plain"][0] == (W, H)


def test_scene_region_is_the_plain_scene(videos):
    """Overlays only read the state: the scene is the same but for the clock's corner."""
    _, over = videos["overlay"]
    _, plain = videos["plain"]
    for a, b in zip(over, plain):
        scene, ref = a[:H, :W].copy(), b.copy()
        assert (near(scene[CLOCK], (0, 0, 0), 80)).sum() > 50      # the clock's letters
        assert not near(ref[CLOCK], (0, 0, 0), 80).any()
        scene[CLOCK] = ref[CLOCK] = 0
        diff = np.abs(scene.astype(int) - ref.astype(int)).max(axis=2)
        assert diff.mean() < 0.5 and (diff > 24).mean() < 0.001    # H.264 noise only
    assert not np.array_equal(over[0][CLOCK], over[5][CLOCK])      # the clock ticks


def test_graph_trace_advances_with_time(videos, layout, cfg):
    _, frames = videos["overlay"]
    g = layout.graph
    right = []
    for f, s in zip(range(1, 10), states(cfg, range(1, 10))):
        panel = frames[f][H:H + g.height, :g.width]
        cols = np.flatnonzero(near(panel, TRACE_COLOR, 70).any(axis=0))
        x, y = g.ax.transData.transform((s.t, s.pos[1, 1]))
        dot = g.dot.get_markersize() * 100 / 72 / 2       # radius in px at 100 dpi
        assert cols.max() == pytest.approx(x + dot, abs=2.5)
        right.append(cols.max())
        rows = np.flatnonzero(near(panel[:, int(round(x))], TRACE_COLOR, 70))
        assert (rows.min() + rows.max()) / 2 == pytest.approx(g.height - y, abs=2.5)
    assert np.all(np.diff(right) > 0)


def test_energy_bars_follow_the_energies(videos, layout, cfg):
    _, frames = videos["overlay"]
    e = layout.energy
    seen = []
    for f, s in zip((0, 3, 5), states(cfg, (0, 3, 5))):
        got = bar_heights(frames[f][:, W:], e)
        want = expected_heights(e, physics.energies(s))
        for label in ("K", "U", "total"):
            assert got[label] == pytest.approx(want[label], abs=3), label
        seen.append(got)
    for label in ("K", "U"):                    # t = 0 at the bottom, 0.15 s past equilibrium
        assert abs(seen[0][label] - seen[1][label]) > 20          # bars move...
    # ...the total does not, up to Euler-Cromer's energy wobble (1/2 k A^2 tall bars show it)
    assert abs(seen[0]["total"] - seen[2]["total"]) <= 0.02 * seen[0]["total"]


def test_overlay_frame_matches_baseline(videos, cfg, regen):
    """The composed frame at t = 0.25 s, lossless, against a committed baseline; the
    video's frame 5 is that frame up to H.264 noise, and its scene part is the still."""

    ov = render.make_overlays(cfg, ALL)
    s = next(states(cfg, [5]))
    with render.make_scene(cfg, s) as scene:
        ov.update_scene(scene, s)
        frame = ov.compose(scene.frame(), s)
    assert frame.shape == (H + 240, W + 320, 3)
    check(frame, BASELINES / "overlay_t0.25.png", regen)
    still = iio.imread(BASELINES / "wiki_t0.25.png")[..., :3].copy()
    scene_part = frame[:H, :W].copy()
    scene_part[CLOCK] = still[CLOCK] = 0
    bad, mean = compare(scene_part, still)
    assert bad <= MAX_BAD_FRACTION and mean <= MAX_MEAN_DIFF
    diff = np.abs(videos["overlay"][1][5].astype(int) - frame.astype(int)).max(axis=2)
    assert diff.mean() < 1.0 and (diff > 24).mean() < 0.01
