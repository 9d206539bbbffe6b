"""What moves with something else, and the blank-video bugs: VPython 6 frames and
materials, attach_trail/attach_arrow/attach_light, curve axis/rotate, thin curves of
thousands of points, autoscale turned off (or range read) before the first frame,
GlowScript's float range and slow rate, and input() with no terminal."""

from __future__ import annotations

import math
import textwrap

import imageio.v3 as iio
import numpy as np
import pytest

from conftest import run_cli
from springscene.vpython.run.runner import run_program
from springscene.vpython.run.options import RunOptions


def write(tmp_path, source: str, name: str = "prog.py"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(source).lstrip("\n"))
    return path


def still(tmp_path, source: str) -> np.ndarray:
    prog = write(tmp_path, source)
    run_program(prog, tmp_path / "x.png", RunOptions(page=False, canvas_only=True))
    return iio.imread(tmp_path / "x.png").astype(int)


def centre_of(mask: np.ndarray) -> tuple[float, float]:
    rows, cols = np.nonzero(mask)
    assert len(rows), "colour not found"
    return cols.mean(), rows.mean()


def red(img):
    return (img[..., 0] > 120) & (img[..., 1] < 60) & (img[..., 2] < 60)


def green(img):
    return (img[..., 1] > 120) & (img[..., 0] < 60) & (img[..., 2] < 60)


def blue(img):
    return (img[..., 2] > 120) & (img[..., 0] < 60) & (img[..., 1] < 60)


# ---- VPython 6 frames and materials -----------------------------------------------------

def test_frame_places_and_turns_its_objects(tmp_path):
    img = still(tmp_path, """
        from visual import *
        scene.range = 4
        f = frame(pos=(2, 0, 0))
        box(frame=f, pos=(1, 0, 0), size=(0.5, 0.5, 0.5), color=color.red)
        g = frame(frame=f, pos=(0, -1, 0))
        sphere(frame=g, pos=(0, 0, 0), radius=0.25, color=color.green)
        sphere(pos=(0, 0, 0), radius=0.25, color=color.blue)
        f.rotate(angle=pi/2, axis=(0, 0, 1), origin=(0, 0, 0))
    """)
    cx, cy = centre_of(blue(img))                 # the world's origin, at the centre
    px = 200 / 4                                  # 400 px high for range 4: 50 px a unit
    rx, ry = centre_of(red(img))                  # frame at (0, 2), box at local x=1: (0, 3)
    gx, gy = centre_of(green(img))                # nested frame at local (0,-1): (1, 2)
    assert abs(rx - cx) < 3 and abs((cy - ry) / px - 3) < 0.1
    assert abs((gx - cx) / px - 1) < 0.1 and abs((cy - gy) / px - 2) < 0.1


def test_invisible_frame_hides_its_objects_and_conversions(tmp_path):
    prog = write(tmp_path, """
        from visual import *
        f = frame(pos=(1, 2, 3), axis=(0, 1, 0))
        b = box(frame=f, pos=(1, 0, 0), color=color.red)
        sphere(pos=(4, 0, 0), color=color.blue)
        print(f.frame_to_world(b.pos), f.world_to_frame((1, 3, 3)), len(f.objects))
        f.visible = False
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines()[0] == "<1, 3, 3> <1, 0, 0> 1"
    img = iio.imread(tmp_path / "x.png").astype(int)
    assert not red(img).any() and blue(img).any()


def test_materials_draw_as_textures_or_glow(tmp_path):
    img = still(tmp_path, """
        from visual import *
        scene.range = 2
        sphere(pos=(-1, 0, 0), radius=0.8, material=materials.earth)
        box(pos=(1, 0, 0), size=(1, 1, 1), color=color.red, material=materials.emissive)
    """)
    left, right = img[:, :320], img[:, 320:]
    assert ((left[..., 2] > left[..., 0] + 40) & (left[..., 2] > 80)).sum() > 300   # oceans
    lit = right[(right[..., 0] > 60)]
    assert np.percentile(lit[..., 1], 90) < 5      # emissive: red, no highlight
    # VPython's materials.emissive (and GlowScript's emissive, lightAt): red x
    # min(1, 1.1 (1.5 N.V)^0.4): the face turned to the eye full red, the side face seen
    # at a grazing angle darker; no lights (flat before: all 255)
    assert (lit[..., 0] == 255).sum() > 10000
    side = (lit[..., 0] > 60) & (lit[..., 0] < 200)
    assert side.sum() > 300


# ---- attached things, curves -------------------------------------------------------------

def test_attach_trail_and_arrow_follow_at_each_render(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        scene.range = 5
        ball = sphere(pos=vector(-4, 0, 0), radius=0.2, color=color.red)
        ball.v = vector(0, 2, 0)
        trail = attach_trail(ball, color=color.green)
        a = attach_arrow(ball, "v", scale=0.5, color=color.blue)
        for i in range(80):
            rate(20)
            ball.pos = ball.pos + vector(0.1, 0, 0)
    """)
    run_program(prog, tmp_path / "x.png", RunOptions(page=False))
    img = iio.imread(tmp_path / "x.png").astype(int)
    cols = np.nonzero(green(img))[1]
    assert cols.min() < 320 - 150 and cols.max() > 320 + 150    # the trail from -4 to +4
    from springscene.vpython.api.attachments import _arrows, _trails
    assert len(_trails) == 1 and 60 <= len(_trails[0]._trail._pts) <= 81
    assert _arrows[0].pos.x == pytest.approx(4.0) and _arrows[0].axis.y == 1.0
    bx, by = centre_of(blue(img))
    assert bx > 320 + 150 and by < 200            # the arrow above the ball at the right


def test_scene_objects_lists_no_trail_curve_as_vpython7_does(tmp_path):
    """VPython 7's ``canvas.objects`` (vpython.py) lists the visible Python objects: a
    make_trail trail is drawn by the browser and is not one, an attach_trail is listed as
    itself. Real VPython 7.6.5 printed ['attach_trail', 'sphere', 'arrow', 'sphere'] for
    this program (a set: any order); the trails still draw and still autoscale."""
    prog = write(tmp_path, f"""
        from vpython import *
        b = sphere(radius=0.2, color=color.red, make_trail=True)
        c = sphere(pos=vector(2, 0, 0), radius=0.2, color=color.blue)
        t = attach_trail(c, color=color.green)
        a = attach_arrow(c, "axis", color=color.yellow)
        for i in range(40):
            rate(20)
            b.pos = b.pos + vector(0, 0.15, 0)
            c.pos = c.pos + vector(0, -0.15, 0)
        with open("{tmp_path / 'objs.txt'}", "w") as f:
            f.write(" ".join(sorted(type(o).__name__ for o in scene.objects)))
        t.delete()
        with open("{tmp_path / 'after.txt'}", "w") as f:
            f.write(" ".join(sorted(type(o).__name__ for o in scene.objects)))
    """)
    run_program(prog, tmp_path / "x.png", RunOptions(page=False, canvas_only=True))
    listed = (tmp_path / "objs.txt").read_text().split()
    assert listed == ["arrow", "attach_trail", "sphere", "sphere"]
    assert (tmp_path / "after.txt").read_text().split() == ["arrow", "sphere", "sphere"]
    img = iio.imread(tmp_path / "x.png").astype(int)
    rows = np.nonzero(red(img))[0]
    assert rows.max() - rows.min() > 150          # the make_trail trail drawn, 0 to 6 up
    from springscene.vpython.core.canvases import canvas
    assert canvas._all[0]._autoscaled_range > 3   # range covers the trails (6 up, 6 down)


def test_clear_trail_after_make_trail_false_clears_the_whole_trail(tmp_path):
    """GlowScript (primitives.js): ``make_trail = False`` stops the object's attach_trail,
    ``clear_trail()`` clears all of it -- what the fidelity harness's ids pictures do; the
    trail stayed drawn before. A trail turned off and not cleared stays drawn."""
    img = still(tmp_path, """
        from vpython import *
        scene.range = 5
        a = sphere(pos=vector(-4, 2, 0), radius=0.2, color=color.red, make_trail=True)
        b = sphere(pos=vector(-4, -2, 0), radius=0.2, color=color.green, make_trail=True)
        for i in range(40):
            rate(20)
            a.pos = a.pos + vector(0.2, 0, 0)
            b.pos = b.pos + vector(0.2, 0, 0)
        a.make_trail = False
        a.clear_trail()
        b.make_trail = False
    """)
    rows, cols = np.nonzero(red(img))
    assert cols.max() - cols.min() < 30           # the red ball alone, no trail
    cols = np.nonzero(green(img))[1]
    assert cols.max() - cols.min() > 200          # the green trail kept


def test_curve_axis_size_and_rotate_place_its_points(tmp_path):
    img = still(tmp_path, """
        from vpython import *
        scene.range = 4
        c = curve(pos=[vector(0, 0, 0), vector(2, 0, 0)], radius=0.1, color=color.red)
        c.rotate(angle=pi/2, axis=vector(0, 0, 1), origin=vector(0, 0, 0))
        c.size = vector(1.5, 1, 1)
        sphere(radius=0.1, color=color.blue)
    """)
    cx, cy = centre_of(blue(img))
    rows, cols = np.nonzero(red(img))
    assert abs(cols.mean() - cx) < 3                           # now along +y
    assert abs((cy - rows.min()) / 50 - 3) < 0.15              # 2 long, scaled 1.5 along axis


def test_a_thin_curve_of_thousands_of_points_is_a_solid_line(tmp_path):
    img = still(tmp_path, """
        from vpython import *
        c = curve(color=color.yellow)
        for i in range(5000):
            c.append(vector(-5 + 10*i/4999, 0, 0))
    """)
    yellow = (img[..., 0] > 100) & (img[..., 1] > 100) & (img[..., 2] < 60)
    cols = np.unique(np.nonzero(yellow)[1])
    span = cols.max() - cols.min() + 1
    assert span > 500 and len(cols) / span > 0.95              # lit along its whole length


# ---- the range before the first frame ----------------------------------------------------

def test_autoscale_off_before_the_first_frame_keeps_the_objects_in_view(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        sphere(pos=vector(0, 0, 0), radius=0.5, color=color.red)
        box(pos=vector(1.5, 0, 0), size=vector(0.5, 0.5, 0.5), color=color.green)
        scene.autoscale = False
        print(round(scene.range, 3))
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    rng = float(proc.stdout.splitlines()[0])
    assert 1 < rng < 4                             # from the objects, not the default 10
    img = iio.imread(tmp_path / "x.png").astype(int)
    assert red(img).sum() > 5000 and green(img).sum() > 1000


def test_range_read_before_a_frame_is_measured(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        sphere(radius=2)
        print(scene.range)
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert 2 < float(proc.stdout.splitlines()[0]) < 6


# ---- GlowScript and no user --------------------------------------------------------------

def test_glowscript_float_range_rate_below_one_and_hoisting(tmp_path):
    prog = write(tmp_path, """
        GlowScript 3.2 VPython
        button(bind=go, text="go")
        n = 0
        for x in range(0, 1, 0.25):
            n += 1
        for i in range(5/2):
            n += 10
        rate(0.5)
        def go(b):
            pass
        print(n, sqrt(-1e-17) != sqrt(-1e-17), Math.floor(2.5))
    """)
    result = run_program(prog, tmp_path / "x.mp4", RunOptions(fps=10, page=False))
    assert result.program_seconds == 2.0 and result.frames == 20
    proc = run_cli("vpython", prog, "--out", tmp_path / "y.png")
    assert proc.stdout.splitlines()[0] == "34 True 2"


def test_input_with_no_terminal_answers_and_says_so(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        n = int(input("How many? "))
        for i in range(n):
            sphere(pos=vector(i, 0, 0))
        print("made", n)
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 0 and "made 1" in proc.stdout
    assert "input('How many? '): no user at a terminal; answered '1'" in proc.stderr
    assert math.isfinite(1.0)


def test_rate_above_the_machine_runs_at_the_machines_pace(tmp_path):
    """``rate(1e15)`` means "as fast as it goes": a slow iteration takes the program time
    it took, so a heavy loop still reaches the end of a short video."""
    prog = write(tmp_path, """
        from vpython import *
        import time
        b = sphere()
        while True:
            rate(1e15)
            time.sleep(0.01)             # a heavy iteration: 10 ms of computing
            b.pos.x += 0.01
    """)
    result = run_program(prog, tmp_path / "x.mp4", RunOptions(duration=0.5, fps=10, page=False))
    assert result.ended == "duration" and result.frames == 5
    assert any("ran as fast as it goes" in n for n in result.notes)


def test_a_thin_circle_is_thinned_again_when_the_camera_zooms(tmp_path):
    """Thinned for the first (far) view, a 2000-point circle must be a circle again once
    the program zooms in, not the polygon of a few points the far view left."""
    img = still(tmp_path, """
        from vpython import *
        c = curve(color=color.yellow)
        for i in range(2001):
            c.append(vector(cos(2*pi*i/2000), sin(2*pi*i/2000), 0))
        scene.range = 300
        rate(10)
        scene.range = 1.2
    """)
    yellow = (img[..., 0] > 100) & (img[..., 1] > 100) & (img[..., 2] < 60)
    rows, cols = np.nonzero(yellow)
    r = np.hypot(cols - 320, rows - 200)
    assert abs(np.median(r) - 200 / 1.2) < 3 and r.std() < 2.5     # on the circle


def test_vpython6_display_keyword_points_and_trails_in_frames(tmp_path):
    img = still(tmp_path, """
        from visual import *
        first = display(width=400, height=400, range=5)
        second = display(width=300, height=300)
        sphere(display=first, pos=(-3, 0, 0), radius=0.5, color=color.blue)
        first.select()                          # what follows goes to the first display
        f = frame(pos=(3, 2, 0))
        points(frame=f, pos=[(0, -2, 0)], size=12, color=color.red)
        ball = sphere(frame=f, pos=(0, 0, 0), radius=0.2, color=color.green, make_trail=True)
        for i in range(10):
            rate(100)
            ball.pos = ball.pos + (0, -0.1, 0)
        print(2 * 0.5 * arange(1)[0] + 1.0, (1, 2, 3) + vector(1, 0, 0))
    """)
    assert img.shape[:2] == (400, 400)                        # the first display is shown
    bx, by = centre_of(blue(img))
    rx, ry = centre_of(red(img))                              # the point at (3, 0) in world
    assert abs(bx - 80) < 4 and abs(by - 200) < 4 and abs(rx - 320) < 4 and abs(ry - 200) < 4


def test_vpython6_numpy_scalars_times_vectors_stay_vectors(tmp_path):
    prog = write(tmp_path, """
        from visual import *
        v = arange(3)[2] * vector(1, 0, 0)
        w = acos(1.0) * vector(0, 1, 0) + (1, 2, 3) - vector(0, 2, 0)
        print(type(v).__name__, v.x, w)
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines()[0] == "vector 2.0 <1, 0, 3>"


def test_attach_trail_pps_and_a_long_sleep_are_quick(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        b = sphere()
        t = attach_trail(b, pps=5)
        for i in range(100):
            rate(100)
            b.pos.x += 0.01
        print(len(t._trail._pts))
        sleep(100000)
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.mp4", "--duration", "2")
    assert proc.returncode == 0, proc.stderr
    assert 4 <= int(proc.stdout.splitlines()[0]) <= 6           # 1 s at 5 points a second
