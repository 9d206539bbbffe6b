"""VPython programs run headless: the wiki program against the engine, the clock,
objects and their links, the batched renderer, errors, and the examples' pictures."""

from __future__ import annotations

import math
import textwrap
from fractions import Fraction

import imageio.v3 as iio
import numpy as np
import pytest

from conftest import BASELINES, ROOT, WIKI, run_cli
from imagecompare import check, compare
from imagecompare import MAX_BAD_FRACTION, MAX_MEAN_DIFF
from springscene import config, render
from springscene.view import camera
from springscene.vpython.core import runtime
from springscene.vpython.run.runner import run_program
from springscene.vpython.run.options import RunOptions

EXAMPLES = ROOT / "examples"
VP_BASELINES = BASELINES / "vpython"


def write(tmp_path, source: str, name: str = "prog.py"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(source))
    return path


def ball_of(cv_index: int = 0):
    from springscene.vpython.core.canvases import canvas

    return next(o for o in canvas._all[cv_index]._objects if o._kind == "sphere")


# ---- the wiki program --------------------------------------------------------------------

def test_wiki_program_follows_simulate_bit_for_bit(tmp_path):
    seen = []
    result = run_program(EXAMPLES / "wiki_spring.py", tmp_path / "w.mp4", RunOptions(frames=50),
                         on_frame=lambda i, img: seen.append(ball_of().pos.value))
    assert (result.frames, result.ended) == (50, "frames")
    traj = render.simulate(config.load(WIKI), 1.0)
    expected = traj.pos[2 * np.arange(50)]          # rate(100) at 50 frames/s: every 2nd step
    assert np.array_equal(np.array(seen), expected)  # exact, not approximate


TITLE_BAND = 40       # rows of `springscene still`'s title (it ends at row 30)


def test_wiki_program_frames_match_render(tmp_path):
    """Frames at t = 0 and 0.25 s against the baselines `springscene still` renders
    (below the title band: `still` writes the title into the picture, VPython puts it
    on the page above the canvas)."""
    images = []
    run_program(EXAMPLES / "wiki_spring.py", tmp_path / "w.mp4",
                RunOptions(frames=2, fps=4, canvas_only=True),
                on_frame=lambda i, img: images.append(img))
    for image, name in zip(images, ("wiki_t0.00.png", "wiki_t0.25.png")):
        bad, mean = compare(image[TITLE_BAND:], iio.imread(BASELINES / name)[TITLE_BAND:, :, :3])
        assert bad <= MAX_BAD_FRACTION and mean <= MAX_MEAN_DIFF, (name, bad, mean)


def test_wiki_program_writes_video_and_page(tmp_path):
    proc = run_cli("vpython", EXAMPLES / "wiki_spring.py", "--out", tmp_path / "wiki.mp4",
                   "--duration", "0.5", "--canvas-only", check=True)
    assert "wrote" in proc.stdout
    import imageio_ffmpeg

    reader = imageio_ffmpeg.read_frames(str(tmp_path / "wiki.mp4"))
    meta = next(reader)
    assert meta["size"] == (900, 600) and meta["fps"] == 50
    assert sum(1 for _ in reader) == 25
    page = (tmp_path / "wiki.html").read_text()            # named after the video
    assert "<title>Ball and Spring Model of Matter</title>" in page
    assert 'href="wiki.mp4"' in page and "glow.min.js" in page    # the page, the video linked
    assert sorted(p.name for p in tmp_path.iterdir()) == ["wiki.html", "wiki.mp4"]


def test_the_video_is_the_page_title_canvas_caption(tmp_path):
    """By default a frame is VPython's page: 8 px margins on #f1f2f4, the title above
    the canvas, the caption below; the page shows that video once and no text twice."""
    frames = []
    r = run_program(EXAMPLES / "wiki_spring.py", tmp_path / "w.mp4", RunOptions(frames=1),
                    on_frame=lambda i, img: frames.append(img))
    img = frames[0]
    white = (img == 255).all(axis=2)            # the canvas: the wiki scene is on white
    rows, cols = np.nonzero(white)
    top, left = rows.min(), cols.min()
    assert (left, rows.max() - top + 1, cols.max() - left + 1) == (8, 600, 900)
    assert 8 + 14 <= top <= 8 + 20               # one title line, 16 px in Chromium
    assert 8 + 2 * 14 <= img.shape[0] - (rows.max() + 1) <= 8 + 2 * 18 + 1  # 2 caption lines
    assert tuple(img[2, 2]) == (241, 242, 244)
    title = img[8:top, 8:908]
    assert (title.min(axis=2) < 100).sum() > 300        # dark text drawn there
    page = r.page.read_text()
    assert r.page.name == "w.html" and page.count('href="w.mp4"') == 1    # the video linked
    assert "<title>Ball and Spring" in page
    assert r.size == (img.shape[1], img.shape[0]) and img.shape[1] % 2 == 0


# ---- the clock ---------------------------------------------------------------------------

def clock(fps=50, max_frames=None):
    taken = []
    tl = runtime.Timeline(fps, max_frames, lambda: taken.append(tl.clock))
    return tl, taken


def test_rate_takes_a_frame_on_every_call_whose_span_holds_a_frame_time():
    tl, taken = clock(50)
    runtime.start(tl)
    try:
        for _ in range(100_000):              # 1000 program seconds of rate(100)
            runtime.rate(100)
    finally:
        runtime.start(None)
    assert tl.clock == 1000 and len(taken) == 50_000
    assert taken[:3] == [0, Fraction(2, 100), Fraction(4, 100)]
    assert taken[-1] == Fraction(49_999, 50)   # exact after 100,000 calls


def test_slow_rate_and_sleep_repeat_the_scene():
    tl, taken = clock(50)
    runtime.start(tl)
    try:
        runtime.rate(10)          # shows for 0.1 s: 5 frames of this state
        runtime.sleep(0.04)       # 2 more
    finally:
        runtime.start(None)
    assert len(taken) == 7 and taken == [0, 0, 0, 0, 0, Fraction(1, 10), Fraction(1, 10)]


def test_the_last_frame_stops_the_program():
    tl, taken = clock(50, max_frames=3)
    runtime.start(tl)
    try:
        with pytest.raises(runtime.Stop):
            while True:
                runtime.rate(100)
    finally:
        runtime.start(None)
    assert len(taken) == 3 and tl.calls == 5


def test_rate_below_one_is_vpythons_error():
    with pytest.raises(ValueError, match="greater than or equal to 1"):
        runtime.rate(0.5)


@pytest.mark.parametrize("value, error, message", [
    (float("nan"), ValueError, "sleep time must be finite, got nan"),
    (float("inf"), ValueError, "sleep time must be finite, got inf"),
    ("0.5", TypeError, "sleep time must be a number, not str"),
])
def test_a_sleep_of_no_length_says_what_it_was_given(value, error, message):
    """``sleep(nan)`` said "must be a number, not float"."""
    runtime.start(runtime.Timeline(fps=10, max_frames=None, take=lambda: None))
    try:
        with pytest.raises(error, match=f"^{message}$"):
            runtime.sleep(value)
    finally:
        runtime.start(None)


def test_program_without_rate_is_one_frame_and_png_is_the_end(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        b = sphere(color=color.red)
        b.pos = vector(1, 0, 0)
    """)
    r = run_program(prog, tmp_path / "a.mp4", RunOptions(page=False))
    assert (r.frames, r.ended) == (1, "program")
    r = run_program(prog, tmp_path / "a.png", RunOptions(page=False, canvas_only=True))
    img = iio.imread(tmp_path / "a.png")
    assert img.shape == (400, 640, 3) and r.frames == 1
    red = (img[..., 0] > 100) & (img[..., 1] < 60)
    cols = np.nonzero(red)[1]
    assert cols.mean() > 320 + 20              # moved right of centre: the final scene


def test_a_program_that_ends_ends_the_video(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        b = sphere()
        for i in range(30):
            rate(100)
            b.pos.x = b.pos.x + 0.01
    """)
    r = run_program(prog, tmp_path / "a.gif", RunOptions(page=False))
    assert (r.frames, r.ended) == (15, "program")
    assert r.program_seconds == pytest.approx(0.30)


# ---- objects: VPython's links between attributes -----------------------------------------

@pytest.fixture
def vp():
    import springscene.vpython.api as vp

    vp.reset()
    return vp


def test_sizes_radii_and_axes(vp):
    s = vp.sphere(radius=0.5)
    assert s.size.value == [1, 1, 1]
    s.axis = vp.vector(0, 3, 0)               # a sphere's axis leaves its size
    assert s.size.value == [1, 1, 1] and s.radius == 0.5
    c = vp.cylinder(axis=vp.vector(0, 2, 0), radius=0.1)
    assert c.length == 2 and c.size.value == [2, 0.2, 0.2]
    c.length = 4
    assert c.axis.value == [0, 4, 0]
    c.size = vp.vector(1, 0.5, 0.5)
    assert c.axis.value == [0, 1, 0] and c.radius == 0.25
    c.axis.y = 3                               # in place: the length follows
    assert c.length == 3
    b = vp.box(length=2, height=3, width=4)
    assert b.size.value == [2, 3, 4] and b.axis.value == [2, 0, 0]
    r = vp.ring(radius=1, thickness=0.1)
    assert r.size.value == pytest.approx([0.2, 2.2, 2.2]) and r.radius == pytest.approx(1)
    a = vp.arrow(axis=vp.vector(0, 0, 2))
    assert a.length == 2 and a.shaftwidth == 0
    h = vp.helix(radius=0.015)
    assert h.coils == 5 and h.thickness == pytest.approx(0.0015)


def test_up_turns_with_the_axis_as_in_vpython(vp):
    h = vp.helix(axis=vp.vector(0, -0.2, 0))    # a hanging spring from the default axis
    assert h.up.value == pytest.approx([1, 0, 0], abs=1e-15)
    h.axis = vp.vector(0, -0.25, 0)            # already square to up: unchanged
    assert h.up.value == pytest.approx([1, 0, 0], abs=1e-15)


def test_user_attributes_clone_and_rotate(vp):
    ball = vp.sphere(pos=vp.vector(1, 0, 0), mass=2.0, color=vp.color.orange)
    ball.p = vp.vector(0, 1, 0)
    assert ball.mass == 2.0 and ball.p.y == 1
    twin = ball.clone(pos=vp.vector(0, 2, 0))
    assert twin.color.value == [1, 0.6, 0] and twin.pos.value == [0, 2, 0]
    assert not hasattr(twin, "mass")               # VPython copies only what it draws
    ball.rotate(angle=math.pi / 2, axis=vp.vector(0, 0, 1), origin=vp.vector(0, 0, 0))
    assert ball.pos.value == pytest.approx([0, 1, 0], abs=1e-15)


def test_in_place_changes_mark_the_object(vp):
    ball = vp.sphere()
    ball._dirty = False
    ball.pos.x = 2
    assert ball._dirty and ball.pos.x == 2
    ball._dirty = False
    ball.color.y = 0.5
    assert ball._dirty


def test_trails_and_curves(vp):
    ball = vp.sphere(make_trail=True, retain=3, interval=1)   # a point at each pos change
    for x in range(5):
        ball.pos = vp.vector(x, 0, 0)
    assert [p["pos"].x for p in ball._trail._pts] == [2, 3, 4]
    c = vp.curve(vp.vector(0, 0, 0), vp.vector(1, 0, 0))
    c.append(pos=vp.vector(2, 0, 0), color=vp.color.red)
    c.append([vp.vector(3, 0, 0), vp.vector(4, 0, 0)])
    assert c.npoints == 5 and c.point(2)["color"].value == [1, 0, 0]
    c.modify(0, y=1)
    assert c.point(0)["pos"].value == [0, 1, 0]
    with pytest.raises(AttributeError):
        c.pos


def test_names_vpython_lacks_name_themselves(vp):
    for name in ("text", "extrusion", "triangle", "quad", "vertex", "attach_trail",
                 "attach_arrow", "textures", "bumpmaps", "shapes", "paths"):
        assert name in vp.__all__ and callable(getattr(vp, name)) or name in (
            "textures", "bumpmaps", "shapes", "paths")
    with pytest.raises(AttributeError, match="no_such_thing"):
        vp.no_such_thing


def test_canvas_defaults_and_camera(vp):
    s = vp.scene
    assert (s.width, s.height, s.fov) == (640, 400, math.pi / 3)
    assert s.background.value == [0, 0, 0] and s.ambient.value == pytest.approx([0.2] * 3)
    assert [lt.color.value for lt in s.lights] == [pytest.approx([0.8] * 3),
                                                   pytest.approx([0.3] * 3)]
    s.range = 2
    assert not s.autoscale
    assert s.camera.pos.value == pytest.approx([0, 0, 2 * math.sqrt(3)])
    s.camera.pos = vp.vector(1, 0, 5)
    assert s.center.value == pytest.approx([1, 0, 5 - 2 * math.sqrt(3)])


# ---- the renderer ------------------------------------------------------------------------

def test_a_thousand_spheres_are_one_batch_updated_in_place(vp):
    """A thousand small spheres: one actor holding a centre, radius and colour each
    (impostors, :mod:`springscene.vpython.draw.impostors`: they are a few pixels across),
    rewritten in place when they move."""
    from springscene.vpython.draw.renderer import Renderer
    from springscene.vpython.draw.impostors import EQUAL_AREA

    balls = [vp.sphere(pos=vp.vector(i % 10, i // 10 % 10, i // 100), radius=0.15,
                       color=vp.color.red) for i in range(1000)]
    r = Renderer(vp.scene)
    try:
        first = r.frame()
        actors = list(r.window.renderer.actors.values())
        spheres = [b for key, b in r._batches.items() if key[0] == "sphere"]
        assert len(spheres) == 1 and spheres[0].no_meshes
        mesh = spheres[0].impostors.mesh
        assert mesh.n_points == 1000
        assert np.allclose(mesh.points[1], [1, 0, 0])
        assert np.allclose(mesh["radius"], 0.15 * EQUAL_AREA)
        mtime = mesh.GetPoints().GetMTime()
        r.frame()                                       # nothing moved: nothing rewritten
        assert mesh.GetPoints().GetMTime() == mtime
        for b in balls:
            b.pos = b.pos + vp.vector(0, 0, 0.5)
        r.frame()
        assert spheres[0].impostors.mesh is mesh and mesh.GetPoints().GetMTime() > mtime
        assert np.allclose(mesh.points[1], [1, 0, 0.5])
        assert list(r.window.renderer.actors.values()) == actors     # no actor added
        assert first.shape == (400, 640, 3)
    finally:
        r.close()


def test_autoscale_and_projection_put_objects_where_vpython_does(vp):
    from springscene.vpython.draw.renderer import Renderer

    vp.scene.background = vp.color.white
    vp.sphere(pos=vp.vector(2, 1, 0), radius=0.1, color=vp.color.red)   # small: a dot
    vp.box(pos=vp.vector(-1, -1, 0), size=vp.vector(0.5, 0.5, 0.5), color=vp.color.blue)
    r = Renderer(vp.scene)
    try:
        img = r.frame()
        bounds = np.array([[[1.9, 0.9, -0.1], [2.1, 1.1, 0.1]],
                           [[-1.25, -1.25, -0.25], [-0.75, -0.75, 0.25]]])
        assert vp.scene.range == pytest.approx(
            camera.autoscale_range(bounds, (0, 0, 0), math.pi / 3, 640, 400))
        rgb = img.astype(int)
        red = (rgb[..., 0] - rgb[..., 1] > 30) & (rgb[..., 0] - rgb[..., 2] > 30)  # lit or not
        rows, cols = np.nonzero(red)
        col, row = r.view.project(np.array([2.0, 1.0, 0.0]))
        assert abs((cols.min() + cols.max() + 1) / 2 - col) < 1.5
        assert abs((rows.min() + rows.max() + 1) / 2 - row) < 1.5
    finally:
        r.close()


# ---- errors ------------------------------------------------------------------------------

def test_program_error_is_its_own_traceback_exit_1(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        ball = sphere()
        v = ball.pos + 1
    """)
    out = tmp_path / "x.mp4"
    proc = run_cli("vpython", prog, "--out", out)
    assert proc.returncode == 1
    assert f'File "{prog}", line 4, in <module>' in proc.stderr
    said, traceback = proc.stderr.split("\n", 1)
    assert said == f"springscene: {prog}: written for VPython 7"
    assert "TypeError" in traceback and "springscene" not in traceback
    assert not out.exists() and not list(tmp_path.glob(".x.mp4*"))


def test_syntax_error_and_exit_status(tmp_path):
    proc = run_cli("vpython", write(tmp_path, "from vpython import *\nwhile True\n"),
                   "--out", tmp_path / "x.mp4")
    assert proc.returncode == 1 and "SyntaxError" in proc.stderr and "line 2" in proc.stderr
    proc = run_cli("vpython", write(tmp_path, "import sys\nsys.exit(3)\n", "e.py"),
                   "--out", tmp_path / "x.mp4")
    assert proc.returncode == 3 and "status 3" in proc.stderr      # as Python exits


@pytest.mark.parametrize("args, message", [
    (["missing.py", "--out", "{tmp}/x.mp4"], "no such program file"),
    (["{prog}", "--out", "{tmp}/x.txt"], "unknown output format"),
    (["{prog}", "--out", "{tmp}/x.mp4", "--duration", "1", "--frames", "3"], "not allowed with"),
    (["{prog}", "--out", "{tmp}/x.mp4", "--fps", "0"], "--fps 0"),
    (["{prog}", "--out", "{tmp}/x.mp4", "--duration", "-1"], "--duration -1"),
    (["{prog}", "--out", "{tmp}/x.mp4", "--overlay", "energy"], "unknown overlay"),
    (["{prog}", "--out", "{tmp}/x.gif", "--fps", "60"], "GIF"),
])
def test_bad_flags_are_one_line_exit_2(tmp_path, cli, args, message):
    prog = write(tmp_path, "from vpython import *\nsphere()\n")
    args = [a.format(tmp=tmp_path, prog=prog) for a in args]
    proc = cli("vpython", *args)
    assert proc.returncode == 2, proc.stderr
    assert message in proc.stderr and len(proc.stderr.strip().splitlines()) == 1
    assert not list(tmp_path.glob("x.*"))


def test_interaction_runs_without_a_user(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        def setk(s):
            raise RuntimeError("never called")
        k = slider(bind=setk, min=1, max=30, value=15)
        button(bind=setk, text="Run")
        scene.bind("click", setk)
        ev = scene.waitfor("click")
        scene.caption = f"k = {k.value}"
        sphere()
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png", "--canvas-only", check=True)
    assert "slider" in proc.stderr and "waitfor" in proc.stderr and "bind" in proc.stderr
    page = (tmp_path / "x.html").read_text()
    assert "k = 15" in page and "disabled" in page


# ---- the examples, against baselines -----------------------------------------------------

EXAMPLE_STILLS = [("projectile", None), ("bounce", 1.5), ("lattice", 0.3),
                  ("spring_graph", 1.0)]


@pytest.mark.parametrize("name, duration", EXAMPLE_STILLS, ids=[n for n, _ in EXAMPLE_STILLS])
def test_example_stills(tmp_path, regen, name, duration):
    r = run_program(EXAMPLES / f"{name}.py", tmp_path / f"{name}.png",
                    RunOptions(duration=duration))
    check(iio.imread(tmp_path / f"{name}.png"), VP_BASELINES / f"{name}.png", regen)
    for image in r.images:                      # graphs: matplotlib, pinned, deterministic
        check(iio.imread(image)[..., :3], VP_BASELINES / image.name, regen)
    assert r.page is not None and r.page.exists()


# ---- what the review found ---------------------------------------------------------------

def test_compound_keeps_its_parts_size_and_turns_without_resizing(vp):
    from springscene.vpython.geometry.object_meshes import object_mesh

    c = vp.compound([vp.box(size=vp.vector(2, 0.3, 0.3)),
                     vp.sphere(pos=vp.vector(1, 0, 0), radius=0.3)])
    assert c.size.value == pytest.approx([2.3, 0.6, 0.6], abs=0.01)   # the sphere is facets
    points = object_mesh(c)[0]
    assert points.min(axis=0) == pytest.approx([-1, -0.3, -0.3], abs=0.005)
    assert points.max(axis=0) == pytest.approx([1.3, 0.3, 0.3], abs=0.005)
    c.axis = vp.vector(0, 0, 1)
    assert c.size.value == pytest.approx([2.3, 0.6, 0.6], abs=0.01)
    assert np.ptp(object_mesh(c)[0], axis=0) == pytest.approx([0.6, 0.6, 2.3], abs=0.005)


def test_up_and_rotate_move_axis_and_up_together(vp):
    b = vp.box()
    b.up = vp.vector(1, 1, 0)                 # not square to the axis: the axis turns
    assert b.axis.dot(b.up) == pytest.approx(0, abs=1e-12)
    b = vp.box()
    b.rotate(angle=math.pi, axis=vp.vector(0, 0, 1))
    assert b.axis.value == pytest.approx([-1, 0, 0], abs=1e-12)
    assert b.up.value == pytest.approx([0, -1, 0], abs=1e-12)


def test_trail_off_and_on_starts_a_new_trail(vp):
    from springscene.vpython.api import attachments

    ball = vp.sphere(pos=vp.vector(0, 0, 0), make_trail=True)
    ball.pos = vp.vector(1, 0, 0)
    attachments.update()                      # a render: the trail takes the position
    first = ball._trail
    ball.make_trail = False
    ball.pos = vp.vector(0, 5, 0)
    attachments.update()
    ball.make_trail = True
    ball.pos = vp.vector(1, 5, 0)
    attachments.update()
    assert [p["pos"].value for p in first._pts] == [[0, 0, 0], [1, 0, 0]]
    assert [p["pos"].value for p in ball._trail._pts] == [[0, 5, 0], [1, 5, 0]]


def test_no_lights_is_ambient_only_and_ambient_changes_show(vp):
    from springscene.vpython.draw.renderer import Renderer

    vp.scene.lights = []
    vp.box(size=vp.vector(4, 4, 0.1), color=vp.color.red)
    r = Renderer(vp.scene, antialias=False)
    try:
        assert tuple(r.frame()[200, 320]) == pytest.approx((51, 0, 0), abs=2)   # 0.2 * 255
        vp.scene.ambient = vp.color.gray(0.6)
        assert tuple(r.frame()[200, 320]) == pytest.approx((153, 0, 0), abs=2)
    finally:
        r.close()


def test_cleared_and_deleted_objects_leave_the_picture(vp):
    from springscene.vpython.draw.renderer import Renderer

    vp.scene.background = vp.color.white
    c = vp.curve(vp.vector(-1, 0, 0), vp.vector(1, 0, 0), color=vp.color.red, radius=0.1)
    s = vp.sphere(pos=vp.vector(0, 1, 0), radius=0.3, color=vp.color.blue)
    vp.box(pos=vp.vector(0, -1, 0), size=vp.vector(0.1, 0.1, 0.1))      # keeps the range
    r = Renderer(vp.scene)
    try:
        img = r.frame().astype(int)
        assert ((img[..., 0] - img[..., 2]) > 100).any() and ((img[..., 2] - img[..., 0]) > 100).any()
        c.clear()
        s.delete()
        img = r.frame().astype(int)
        assert not ((img[..., 0] - img[..., 2]) > 100).any()       # no red
        assert not ((img[..., 2] - img[..., 0]) > 100).any()       # no blue
    finally:
        r.close()


def test_waits_in_a_loop_end_with_the_video(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        while True:
            ev = scene.waitfor("click")
            sphere(pos=ev.pos)
    """)
    r = run_program(prog, tmp_path / "x.mp4", RunOptions(duration=0.2, page=False))
    assert (r.frames, r.ended) == (10, "duration")


def test_visual_and_module_imports_and_a_second_run_reimports_local_modules(tmp_path):
    write(tmp_path, "from vpython import *\nscene.background = color.white\n", "look.py")
    prog = write(tmp_path, """
        import look
        from visual import *
        import vpython as vp
        ball = vp.sphere(color=color.red)
        display  # VPython 6's name for a canvas
    """)
    for _ in range(2):
        run_program(prog, tmp_path / "x.png", RunOptions(page=False, canvas_only=True))
        assert tuple(iio.imread(tmp_path / "x.png")[5, 5]) == (255, 255, 255)
