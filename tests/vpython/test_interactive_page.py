"""The interactive page (springscene.vpython.page.interactive): a recording replayed by
GlowScript's own library in one HTML file, opened from the disk in headless Chromium.

The recordings are written in the documented format (tests/vpython/recordings.py). The
browser tests are marked slow (a Chromium each module, WebGL in software on 2 cores).
"""

from __future__ import annotations

import errno
import gzip
import json
import os
import re
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

import recordings
from browser import Browser, require_chromium
from springscene import jobs
from springscene.errors import OutputError
from springscene.view import imagediff
from springscene.vpython.record import reader
from springscene.vpython.page import glow_library
from springscene.vpython.page.interactive import write_interactive_page
from springscene.vpython.page.replay_data import replay_data
from springscene.vpython.page.safe_html import sanitize

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "benchmarks" / "fidelity"))
import harness  # noqa: E402  benchmarks/fidelity: the scenes, their ids variants
from idscene import PALETTE  # noqa: E402

MB = 1e6
# a seek, then GlowScript's next render done: the milliseconds from the seek to the picture
SEEK_DRAWN_JS = """
var done = arguments[arguments.length - 1], s = window.springscene, c = s.canvas(0);
var t0 = performance.now();
s.seek(arguments[0]);
function drawn() { c.unbind("draw_complete", drawn); done(performance.now() - t0); }
c.bind("draw_complete", drawn);
"""
INJECTION = "</script><script>window.pwned=1</script><!--"


@pytest.fixture(scope="module")
def glow():
    """GlowScript's library as `make setup` cached it (the tests download nothing)."""
    try:
        return glow_library.library(download=False)
    except OutputError as e:
        if os.environ.get("SPRINGSCENE_REQUIRE_BACKENDS"):
            pytest.fail(f"GlowScript's library is required here (make setup): {e}")
        pytest.skip(f"{e} (make setup caches it)")


@pytest.fixture(scope="module")
def browser(glow):
    require_chromium()
    b = Browser()
    yield b
    b.close()


@pytest.fixture(scope="module")
def spring_page(tmp_path_factory, glow):
    folder = tmp_path_factory.mktemp("spring")
    rec = recordings.spring(folder / "spring.jsonl", seconds=4.0)
    return write_interactive_page(rec, folder / "spring.html", video=folder / "spring.mp4")


# ---- the file ------------------------------------------------------------------------

def test_the_page_is_one_file_that_fetches_nothing(spring_page):
    text = spring_page.read_text(encoding="utf-8")
    assert not re.search(r"<(script|img|link|iframe)[^>]*\s(src|href)=", text, re.I)
    assert "Copyright (C) 2015 by John Coady, Ruth Chabay, and Bruce Sherwood" in text
    assert 'href="spring.mp4"' in text          # the video, beside the page
    # five script elements and the data's: nothing in them ended one early
    assert text.count("</script>") == 5


def test_the_atomic_solid_page_is_at_most_5_mb(tmp_path, glow):
    rec = recordings.crystal(tmp_path / "crystal.jsonl", seconds=10.0)
    page = write_interactive_page(rec, tmp_path / "crystal.html")
    size = page.stat().st_size
    print(f"AtomicSolid-like page (64 spheres, 144 helices, 10 s at 25 fps): "
          f"{size / MB:.2f} MB, recording {rec.stat().st_size / MB:.2f} MB")
    assert size <= 5 * MB


@pytest.mark.slow
def test_the_recorded_atomic_solid_page_is_at_most_5_mb(tmp_path, glow):
    program = tmp_path / "atomic_solid.py"
    program.write_text(recordings.ATOMIC_SOLID)
    rec = tmp_path / "atomic_solid.jsonl"
    jobs.vpython(program, rec, supervised=False, duration=10)      # the recording alone
    page = write_interactive_page(rec, tmp_path / "atomic_solid.html")
    size = page.stat().st_size
    print(f"AtomicSolid recorded by springscene (10 s at 25 fps, pos, axis, up and size "
          f"moving): page {size / MB:.2f} MB, recording {rec.stat().st_size / MB:.2f} MB")
    assert size <= 5 * MB


def test_timelines_keep_the_changes_and_dense_ones_keep_no_frames(tmp_path):
    rec = recordings.spring(tmp_path / "s.jsonl", seconds=1.0)
    data = replay_data(rec)
    ball = next(o for o in data["objects"] if o["id"] == 3)
    dim, _, count, dense, first = ball["n"]["pos"]
    assert (dim, count, dense, first) == (3, 26, 1, 0)
    assert "pos" not in next(o for o in data["objects"] if o["id"] == 1)["n"] or \
        next(o for o in data["objects"] if o["id"] == 1)["n"]["pos"][2] == 1
    assert len(data["times"]) == 26 and data["times"][25] == 1.0


def test_what_was_printed_after_the_last_frame_shows_at_the_last_frame(tmp_path):
    rec = recordings.spring(tmp_path / "s.jsonl", seconds=1.0, printed="step\n")
    lines = rec.read_text().splitlines()
    end = json.loads(lines[-1])
    end["end"]["printed"] = "done\n"
    rec.write_text("\n".join(lines[:-1] + [json.dumps(end)]) + "\n")
    data = replay_data(rec)
    assert data["printed"] == "step\nstep\ndone\n"
    assert data["printed_at"] == [[0, 5], [25, 10], [25, 15]]


def test_a_gzip_recording_reads_as_the_plain_one(tmp_path):
    rec = recordings.spring(tmp_path / "s.jsonl", seconds=0.5)
    packed = tmp_path / "s.jsonl.gz"
    packed.write_bytes(gzip.compress(rec.read_bytes()))
    assert replay_data(packed) == replay_data(rec)


def test_a_recording_cut_short_gives_its_whole_frames(tmp_path, glow):
    rec = recordings.spring(tmp_path / "s.jsonl", seconds=1.0)
    lines = rec.read_text().splitlines()
    cut = tmp_path / "cut.jsonl"
    cut.write_text("\n".join(lines[:11]) + "\n" + lines[11][:40])
    assert len(replay_data(cut)["times"]) == 10
    assert write_interactive_page(cut, tmp_path / "cut.html").stat().st_size > 0


# ---- titles and captions --------------------------------------------------------------

@pytest.mark.parametrize("markup, kept", [
    ("<b>k</b> = 5<script>alert(1)</script>", "<b>k</b> = 5"),
    ('<img src=x onerror="alert(1)">t', "t"),
    ('<a href="javascript:alert(1)">go</a>', "<a>go</a>"),
    ('<a href="https://vpython.org">vp</a>', '<a href="https://vpython.org">vp</a>'),
    ('<p style="color: red" onclick="x()">r</p>', '<p style="color: red">r</p>'),
    ('<p style="background: url(http://x)">u</p>', "<p>u</p>"),
    ("<svg><script>1</script></svg>x<iframe src=y></iframe>", "x"),
    ("a < b & c\n  d", "a &lt; b &amp; c\n  d"),
    ("<!-- x --><!--vpython-widget-3-->", "<!--vpython-widget-3-->"),
    ('<div style="position: fixed; inset: 0">false page</div>', "<div>false page</div>"),
])
def test_titles_and_captions_keep_formatting_only(markup, kept):
    assert sanitize(markup) == kept


# ---- GlowScript's library -------------------------------------------------------------

def _no_network(monkeypatch, tmp_path):
    monkeypatch.setenv("SPRINGSCENE_GLOW_DIR", str(tmp_path / "glow"))
    monkeypatch.setattr(glow_library, "_installed", lambda: None)
    monkeypatch.setattr(glow_library, "_found", {})


def test_no_library_and_no_network_is_one_line_naming_what_to_do(monkeypatch, tmp_path):
    _no_network(monkeypatch, tmp_path)

    def pip_without_network(cmd, **kw):
        return subprocess.CompletedProcess(cmd, 1, "", "ERROR: Could not find a version "
                                           "that satisfies the requirement vpython==7.6.5")
    monkeypatch.setattr(glow_library.subprocess, "run", pip_without_network)
    rec = recordings.spring(tmp_path / "s.jsonl", seconds=0.2)
    with pytest.raises(OutputError) as raised:
        write_interactive_page(rec, tmp_path / "s.html")
    message = str(raised.value)
    assert "\n" not in message and raised.value.errno == errno.ENETUNREACH
    assert "SPRINGSCENE_GLOW_DIR" in message and "pip download vpython==7.6.5" in message
    assert message.endswith(f"writing {tmp_path / 's.html'}")
    assert not (tmp_path / "s.html").exists()
    # the next hour's runs say so at once, without asking pip again
    calls = []
    monkeypatch.setattr(glow_library.subprocess, "run",
                        lambda cmd, **kw: calls.append(cmd) or pip_without_network(cmd))
    with pytest.raises(OutputError, match="failed less than an hour ago"):
        write_interactive_page(rec, tmp_path / "s.html")
    assert calls == []
    with pytest.raises(OutputError, match="could not be downloaded"):
        glow_library.library(retry=True)                  # the explicit fetch tries again
    assert len(calls) == 1


def test_a_wheel_put_in_the_cache_is_enough(monkeypatch, tmp_path, glow):
    _no_network(monkeypatch, tmp_path)
    folder = tmp_path / "glow"
    folder.mkdir()
    with zipfile.ZipFile(folder / "vpython-7.6.5-cp311-none-any.whl", "w") as z:
        for name, member in glow_library._IN_WHEEL.items():
            z.writestr(member, (glow.folder / name).read_bytes()
                       if name != "LICENSE.txt" else glow.license_text.encode())
    found = glow_library.library()
    assert found.folder == folder and found.glow_js == glow.glow_js
    assert sorted(p.name for p in folder.iterdir() if not p.suffix == ".whl") == \
        sorted(glow_library.FILES)


def test_a_changed_file_in_the_cache_is_not_used(monkeypatch, tmp_path, glow):
    _no_network(monkeypatch, tmp_path)
    folder = tmp_path / "glow"
    folder.mkdir()
    for name in glow_library.FILES:
        src = glow.folder / name if name != "LICENSE.txt" else None
        (folder / name).write_bytes(src.read_bytes() if src else glow.license_text.encode())
    (folder / "glow.min.js").write_text("window.pwned = 1;")
    assert glow_library._cached() is None


# ---- in the browser -------------------------------------------------------------------

def _ball_y(k: int) -> float:
    return recordings.spring_position(k)[1]


@pytest.mark.slow
def test_the_page_draws_from_the_disk_with_no_network(browser, spring_page):
    browser.open(spring_page)
    assert browser.js("return performance.getEntriesByType('resource').length") == 0
    picture = browser.canvas_picture()
    assert picture.shape == (400, 640, 3)
    lit = picture.max(axis=2) > 40                 # the objects on the black background
    assert 0.005 < lit.mean() < 0.5
    # the ball (blue) where the recording has it at frame 0
    blue = (picture[..., 2] > 150) & (picture[..., 0] < 80)
    assert blue.sum() > 100
    assert browser.js("return window.springscene.object(3).pos.y") == pytest.approx(_ball_y(0))


@pytest.mark.slow
def test_nothing_the_program_wrote_runs(browser, tmp_path):
    rec = recordings.spring(
        tmp_path / "evil.jsonl", seconds=0.4,
        title='<img src=x onerror="window.pwned=2"><b>bold</b>' + INJECTION,
        caption='<script>window.pwned=3</script><i onclick="window.pwned=4">it</i>',
        label_text=INJECTION, printed=INJECTION + "\n")
    text = rec.read_text()
    text = text.replace('"title": "y(t)"', '"title": ' + repr(INJECTION).replace("'", '"'))
    rec.write_text(text)
    widgets = [
        {"kind": "button", "text": '<img src=x onerror="window.pwned=5">go', "seq": 1,
         "color": (0, 0, 0), "background": (1, 1, 1), "anchor": "caption"},
        {"kind": "wtext", "text": "<b>w</b><script>window.pwned=6</script>", "seq": 2,
         "anchor": "caption"},
        {"kind": "slider", "min": 0, "max": 1, "step": 0.1, "value": 0.5, "length": 200,
         "width": 10, "vertical": False, "anchor": "title", "seq": 3}]
    page = write_interactive_page(rec, tmp_path / "evil.html", widgets=widgets)
    browser.open(page)
    browser.js("window.springscene.seek(5)")
    assert browser.js("return window.pwned") is None
    printed = browser.js("return document.querySelector('.vp-print').textContent")
    assert INJECTION in printed
    title = browser.js("return window.springscene.canvas(0).title_anchor[0].innerHTML")
    assert "<b>bold</b>" in title and "<img" not in title and "<script" not in title
    caption = browser.js("return window.springscene.canvas(0).caption_anchor[0].innerHTML")
    assert caption.startswith("<i>it</i><button") and "<img" not in caption
    assert browser.js("""return [...document.querySelectorAll('#vp-page button, #vp-page input')]
                         .map(e => e.disabled)""") == [True, True]
    assert '<span class="vp-wtext"><b>w</b></span>' in caption
    assert browser.js("return window.springscene.object(5).text") == INJECTION


@pytest.mark.slow
def test_seeking_shows_the_recordings_values_backwards_too_and_fast(browser, spring_page):
    browser.open(spring_page)
    timings = []
    for k in (80, 3, 100, 57, 0, 99, 21, 20, 64, 1):
        timings.append(browser.js("return window.springscene.seek(arguments[0])", k))
        got = browser.js("""var s = window.springscene, b = s.object(3), h = s.object(2),
                            c = s.object(4);
                            return [s.frame(), b.pos.x, b.pos.y, b.pos.z, h.axis.y, h.size.x,
                                    c.npoints, c.point(c.npoints - 1).pos.y,
                                    s.canvas(0).range, s.object(5).visible]""", k)
        y = _ball_y(k)
        assert got[0] == k
        assert got[1:4] == pytest.approx([0.0, y, 0.0], abs=1e-6)
        assert got[4] == pytest.approx(y - 0.05, abs=1e-6)
        assert got[5] == pytest.approx(abs(y - 0.05), abs=1e-6)
        assert got[6] == min(k + 1, 20)             # the trail: retain 20, dropped in front
        assert got[7] == pytest.approx(y, abs=1e-6)
        assert got[8] == pytest.approx(0.8 + 0.001 * k if k else 0.8)
        assert got[9] is (k < recordings.LABEL_GONE)           # deleted at that frame
    drawn = [browser.driver.execute_async_script(SEEK_DRAWN_JS, k) for k in (90, 10, 55)]
    print(f"seek: max {max(timings):.1f} ms, mean {np.mean(timings):.1f} ms to set the "
          f"frame; to GlowScript's next picture of it {max(drawn):.0f} ms at most")
    assert max(timings) <= 100


@pytest.mark.slow
def test_the_users_camera_stays_until_follow(browser, spring_page):
    browser.open(spring_page)
    browser.js("window.springscene.seek(10)")
    assert browser.js("return window.springscene.user_camera(0)") is False
    browser.js("window.springscene.canvas(0).__range = 3")    # as GlowScript's mouse wheel
    browser.js("window.springscene.seek(30)")
    assert browser.js("return window.springscene.user_camera(0)") is True
    assert browser.js("return window.springscene.canvas(0).range") == 3
    browser.js("window.springscene.follow()")
    assert browser.js("return window.springscene.canvas(0).range") == pytest.approx(0.83)


@pytest.mark.slow
def test_glowscripts_mouse_turns_and_zooms_and_the_users_camera_stays(browser, spring_page):
    from selenium.webdriver.common.action_chains import ActionChains  # noqa: PLC0415
    from selenium.webdriver.common.actions.wheel_input import ScrollOrigin  # noqa: PLC0415

    browser.open(spring_page)
    browser.js("window.springscene.seek(10)")
    element = browser.js("return window.springscene.canvas(0).__overlay_element")
    forward = browser.js("var f = window.springscene.canvas(0).forward; return [f.x, f.y, f.z]")
    ActionChains(browser.driver).scroll_from_origin(ScrollOrigin.from_element(element),
                                                    0, 300).perform()
    browser.wait("return window.springscene.canvas(0).__range > 0.82", 5)  # zoomed out
    # a right-button drag across the canvas (GlowScript turns the camera with it)
    x, y = browser.js("var r = arguments[0].getBoundingClientRect(); "
                      "return [r.left + r.width / 2, r.top + r.height / 2]", element)
    mouse = [("mousePressed", x, 0)] + [("mouseMoved", x + dx, 2) for dx in range(20, 120, 20)]
    for kind, at, buttons in mouse + [("mouseReleased", x + 100, 0)]:
        browser.driver.execute_cdp_cmd("Input.dispatchMouseEvent", {
            "type": kind, "x": at, "y": y, "button": "right", "buttons": buttons,
            "clickCount": 1})
    turned = browser.js("var f = window.springscene.canvas(0).forward; return [f.x, f.y, f.z]")
    assert turned != pytest.approx(forward)                     # GlowScript's spin
    browser.js("window.springscene.seek(40)")
    assert browser.js("return window.springscene.user_camera(0)") is True
    assert browser.js("var f = window.springscene.canvas(0).forward; return [f.x, f.y, f.z]") \
        == pytest.approx(turned)
    assert browser.js("return document.querySelector('.vp-follow').disabled") is False


@pytest.mark.slow
def test_ten_seconds_play_in_ten_seconds(browser, tmp_path):
    rec = recordings.spring(tmp_path / "ten.jsonl", seconds=10.0)
    page = write_interactive_page(rec, tmp_path / "ten.html")
    browser.open(page)
    browser.js("window.springscene.play()")
    playback = browser.wait("return window.springscene.playback", 20)
    print(f"10 s played in {playback['wall_s']:.3f} s of wall clock, "
          f"{playback['frames_shown']} of {playback['frames']} frames shown")
    assert playback["program_s"] == pytest.approx(10.0)
    assert abs(playback["wall_s"] - 10.0) <= 0.5
    assert browser.js("return window.springscene.frame()") == 250
    browser.js("var s = document.querySelector('.vp-speed'); s.value = '4'; "
               "s.dispatchEvent(new Event('change')); window.springscene.play()")
    fast = browser.wait("return window.springscene.playback", 10)
    print(f"at 4x: {fast['wall_s']:.3f} s")
    assert fast["speed"] == 4 and abs(fast["wall_s"] - 2.5) <= 0.5


# ---- real programs, recorded ------------------------------------------------------------

# scenes whose program ends before the first frame: the recording's one frame is the end
PICTURE_SCENES = ("helices", "labels", "curves", "texture")


def _recorded(program: Path, folder: Path, name: str, **options) -> tuple[Path, np.ndarray]:
    """springscene's still of ``program`` (the canvas alone) and the run's recording."""
    rec, still = folder / f"{name}.jsonl", folder / f"{name}.png"
    jobs.vpython(program, still, supervised=False, record=str(rec), page=False,
                 canvas_only=True, **options)
    return rec, np.asarray(Image.open(still).convert("RGB"))


@pytest.mark.slow
@pytest.mark.parametrize("scene", PICTURE_SCENES)
def test_the_replayed_canvas_is_real_vpythons_and_springscenes_picture(browser, scene,
                                                                       tmp_path):
    ids_program, table = harness.write_ids_program(scene, tmp_path)
    pictures, stills = {}, {}
    for name, program in (("scene", harness.SCENES / f"{scene}.py"), ("ids", ids_program)):
        rec, stills[name] = _recorded(program, tmp_path, f"{scene}.{name}")
        browser.open(write_interactive_page(rec, tmp_path / f"{scene}.{name}.html"))
        browser.js("window.springscene.seek(window.springscene.frames - 1)")
        pictures[name] = browser.canvas_picture()
    Image.fromarray(pictures["scene"]).save(tmp_path / f"{scene}.page.png")
    names = [f"object {k}" for k in range(len(json.loads(table.read_text())))]
    real = {suffix: np.asarray(Image.open(harness.REFERENCE / f"{scene}{suffix}.png")
                               .convert("RGB")) for suffix in ("", ".ids")}
    for against, (a, a_ids) in {"real VPython": (real[""], real[".ids"]),
                                "springscene's still": (stills["scene"], stills["ids"])}.items():
        result = imagediff.compare_scene(pictures["scene"], a, pictures["ids"], a_ids,
                                         PALETTE, names=names)
        print(f"{scene} against {against}: IoU "
              f"{', '.join(f'{o.iou:.3f}' for o in result.objects)}; mean ΔE00 "
              f"{result.mean_de:.2f}; ΔE00 > 5 on {result.over_percent:.2f} % of pixels")
        assert all(o.iou >= 0.98 for o in result.objects), (against, result.objects)
        assert result.mean_de <= 2 and result.over_percent <= 1, against


@pytest.mark.slow
def test_a_recorded_program_seeks_to_the_readers_values(browser, tmp_path):
    program = ROOT / "springscene" / "examples" / "spring_graph.py"
    rec, _ = _recorded(program, tmp_path, "spring_graph", duration=2)
    page = write_interactive_page(rec, tmp_path / "spring_graph.html")
    run = reader.read(rec)
    browser.open(page)
    ball, spring = run["ball"], run["spring"]
    for k in (40, 3, run.frames - 1, 17, 0):
        browser.js("window.springscene.seek(arguments[0])", k)
        got = browser.js("""var s = window.springscene, b = s.object(arguments[0]),
                            h = s.object(arguments[1]);
                            return [[b.pos.x, b.pos.y, b.pos.z], [h.axis.x, h.axis.y, h.axis.z],
                                    s.canvas(0).range]""", ball.id, spring.id)
        assert got[0] == pytest.approx(ball.value("pos", k), rel=1e-6, abs=1e-7)
        assert got[1] == pytest.approx(spring.value("axis", k), rel=1e-6, abs=1e-7)
    assert browser.js("return document.querySelectorAll('.vp-graph canvas').length") == 2


def _by_colour(im: np.ndarray) -> dict[str, np.ndarray]:
    """The page's spring scene by colour: red ball, cyan spring, grey holder on white."""
    r, g, b = (im[..., i].astype(int) for i in range(3))
    return {"ball": (r > 120) & (g < 90) & (b < 90),
            "spring": (g > 120) & (b > 120) & (r < 110),
            "holder": (abs(r - g) < 12) & (abs(g - b) < 12) & (r < 200)}


def _assert_the_spring_scene_matches(picture, still, what: str) -> None:
    """The issue's picture targets (mean ΔE00 ≤ 2, ≤ 1 % of pixels over 5; IoU 0.98 for
    the ball and holder, 0.95 for the thin spring, whose anti-aliased rim falls outside a
    colour mask)."""
    de = imagediff.ciede2000(picture, still)
    ours, theirs = _by_colour(picture), _by_colour(still)
    ious = {k: imagediff.iou(ours[k], theirs[k]) for k in ours}
    print(f"{what}: IoU {ious}; mean ΔE00 {de.mean():.2f}; "
          f"ΔE00 > 5 on {100 * (de > 5).mean():.2f} % of pixels")
    assert de.mean() <= 2 and (de > 5).mean() <= 0.01
    assert ious["ball"] >= 0.98 and ious["holder"] >= 0.98 and ious["spring"] >= 0.95


@pytest.mark.slow
def test_mid_run_the_replayed_canvas_is_springscenes_still_at_that_time(browser, tmp_path):
    """The wiki's spring with graphs cut at 1 s: the page at its last frame against
    springscene's still at that time. Objects by their colours (red ball, cyan spring,
    grey holder on white): the spring is a thin helix, whose anti-aliased rim colours fall
    outside a colour test, so its bound is looser than the ids scenes' 0.98."""
    program = ROOT / "springscene" / "examples" / "spring_graph.py"
    rec, still = _recorded(program, tmp_path, "spring_graph", duration=1.0)
    browser.open(write_interactive_page(rec, tmp_path / "spring_graph.html"))
    browser.js("window.springscene.seek(window.springscene.frames - 1)")
    picture = browser.canvas_picture()
    _assert_the_spring_scene_matches(picture, still, "spring_graph at 1 s")


# ---- the page's own scene, from its config ------------------------------------------------

def test_a_configs_scene_is_recorded_as_vpythons_box_helix_and_sphere(tmp_path):
    """``springscene render wiki.toml --out wiki.html``'s recording: the ball where the
    physics puts it at every frame, the spring along ball.pos - holder.pos."""
    from springscene import config, render
    from springscene.model.timeline import frame_steps
    from springscene.vpython.page.scene_recording import record_scene

    cfg = config.load(ROOT / "configs" / "wiki.toml")
    frames = record_scene(cfg, tmp_path / "wiki.jsonl", duration=2.0)
    run = reader.read(tmp_path / "wiki.jsonl")
    steps = frame_steps(2.0, cfg.render.fps, cfg.physics.dt)
    assert frames == run.frames == len(steps) == 100
    traj = render.simulate(cfg, 2.0)
    assert np.array_equal(run["ball"].pos, traj.pos[steps])
    assert np.array_equal(run["spring"].axis, run["ball"].pos - run["holder"].pos)
    assert [run[n].kind for n in ("holder", "spring", "ball")] == ["box", "helix", "sphere"]
    assert run["spring"].first["coils"] == 15 and run["ball"].first["size"] == [0.05] * 3
    cv = run.canvases[0]
    assert (cv["width"], cv["height"], cv["title"]) == (900, 600,
                                                        "Ball and Spring Model of Matter")
    assert cv["range"] == pytest.approx(0.1790085296108589)    # VPython's autoscale


def test_render_to_html_writes_the_page(tmp_path, cli, glow):
    proc = cli("render", ROOT / "configs" / "wiki.toml", "--out", tmp_path / "wiki.html",
               "--duration", "1")
    assert proc.returncode == 0 and "wrote" in proc.stdout, proc.stderr
    page = (tmp_path / "wiki.html").read_text()
    assert "<title>Ball and Spring Model of Matter</title>" in page and "glow.min.js" in page
    assert [p.name for p in tmp_path.iterdir()] == ["wiki.html"]        # nothing left
    proc = cli("render", ROOT / "configs" / "wiki.toml", "--out", tmp_path / "w.html",
               "--duration", "0")
    assert proc.returncode == 2 and proc.stderr.count("\n") == 1, proc.stderr
    assert not (tmp_path / "w.html").exists()


def test_a_lattice_configs_scene_is_its_atoms_and_bonds_at_its_speed(tmp_path):
    """A chain of aluminium atoms: spheres on the physics' positions at every frame, the
    held ends gray, coloured by displacement as the video colours them, bonds along the
    atoms; the page plays the video's picoseconds a second."""
    from springscene import build, config
    from springscene.model.timeline import frame_steps, play
    from springscene.vpython.page.scene_recording import record_scene

    cfg = config.load(ROOT / "configs" / "chain-aluminum.toml")
    record_scene(cfg, tmp_path / "chain.jsonl", duration=2e-12)
    run = reader.read(tmp_path / "chain.jsonl")
    r = cfg.render
    steps = frame_steps(2e-12, r.fps, cfg.physics.dt, r.speed)
    system = build.system(cfg)
    expected = np.array([s.pos.copy() for s in play(system, steps)])
    atoms, bonds = run["atoms"], run["bonds"]
    assert len(atoms) == len(system.pos) and len(bonds) == len(system.i)
    assert np.array_equal(np.stack([a.pos for a in atoms], axis=1), expected)
    assert np.allclose(bonds[0].axis, expected[:, 1] - expected[:, 0])
    assert run.header["time_scale"] == r.speed and run.times[-1] < 1e-11
    assert atoms[0].first["color"] == [0.5, 0.5, 0.5]                    # held: gray
    colours = np.stack([a.color for a in atoms[1:-1]])       # (atoms, frames, 3)
    assert np.ptp(colours, axis=1).max() > 0.1            # coloured by their displacement


@pytest.mark.slow
def test_the_wiki_page_is_springscenes_still(browser, tmp_path, cli):
    """The wiki config's page at t = 0.5 s against ``springscene still --time 0.5`` (below
    the title band the still draws into its picture): the same scene, drawn by GlowScript."""
    cfg = ROOT / "configs" / "wiki.toml"
    cli("render", cfg, "--out", tmp_path / "wiki.html", "--duration", "1", check=True)
    cli("still", cfg, "--time", "0.5", "--out", tmp_path / "still.png", check=True)
    browser.open(tmp_path / "wiki.html")
    browser.js("window.springscene.seek(25)")
    picture = browser.canvas_picture()[40:]
    still = np.asarray(Image.open(tmp_path / "still.png").convert("RGB"))[40:]
    _assert_the_spring_scene_matches(picture, still, "wiki page at 0.5 s")


@pytest.mark.slow
def test_the_page_runs_inside_a_notebooks_sandboxed_frame(browser, tmp_path, spring_page):
    """What a notebook shows (springscene.results.page_frame): the whole page in an iframe's
    srcdoc, sandboxed; GlowScript draws there and the player works."""
    from springscene.results import page_frame

    outer = tmp_path / "notebook.html"
    outer.write_text("<html><body><h1>a notebook</h1>"
                     + page_frame(spring_page.read_text(encoding="utf-8"), 900)
                     + "</body></html>", encoding="utf-8")
    browser.driver.get(outer.resolve().as_uri())
    try:
        browser.driver.switch_to.frame(0)
        browser.wait("return !!(window.springscene && window.springscene.ready)", 30)
        browser.js("window.springscene.pause(); window.springscene.seek(10)")
        picture = browser.canvas_picture()
        drawn = (picture != picture[0, 0]).any(axis=2)       # anything on the background
        assert drawn.sum() > 1000 and browser.js("return window.springscene.frame()") == 10
    finally:
        browser.driver.switch_to.default_content()


@pytest.mark.slow
def test_a_hostile_programs_page_runs_none_of_its_text(browser, tmp_path):
    """A program that prints, titles, captions, labels and plots ``</script>`` and HTML,
    run to its page by springscene itself: nothing it wrote runs; its text shows as text."""
    prog = tmp_path / "hostile.py"
    prog.write_text(
        "from vpython import *\n"
        f"evil = {INJECTION!r} + '<img src=x onerror=\"window.pwned=7\">'\n"
        "scene.title = evil\n"
        "scene.caption = '<svg onload=\"window.pwned=8\"></svg>' + evil\n"
        "label(pos=vector(0, 1, 0), text=evil)\n"
        "g = graph(title=evil, xtitle=evil)\n"
        "c = gcurve(label=evil)\n"
        "b = sphere(texture=evil)\n"
        "for i in range(5):\n"
        "    rate(10)\n"
        "    print(evil)\n"
        "    c.plot(i, i)\n")
    jobs.vpython(prog, tmp_path / "hostile.html", supervised=False, duration=0.5, fps=10)
    browser.open(tmp_path / "hostile.html")
    browser.js("window.springscene.seek(window.springscene.frames - 1)")
    assert browser.js("return window.pwned") is None
    assert browser.js("return document.querySelectorAll('#vp-page script, #vp-page img, "
                      "#vp-page svg').length") == 0
    assert INJECTION in browser.js("return document.querySelector('.vp-print').textContent")
