"""The three dialects: which one a program is written in, GlowScript's header and
leniencies, VPython 6's names and vectors, and programs of each rendered to pictures."""

from __future__ import annotations

import ast
import importlib
import math
import textwrap

import numpy as np
import pytest

from conftest import ROOT, run_cli
from springscene.vpython import api as vp
from springscene.vpython.dialects import compiling, visual6
from springscene.vpython.run.runner import run_program
from springscene.vpython.run.options import RunOptions
from springscene.vpython.core.vectors import vector

PROGRAMS = ROOT / "tests" / "vpython_programs"
# the module (the package's ``vector`` attribute is the class)
vector_module = importlib.import_module("springscene.vpython.core.vectors")


def write(tmp_path, source: str, name: str = "prog.py"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(source).lstrip("\n"))
    return path


# ---- which dialect -----------------------------------------------------------------------

@pytest.mark.parametrize("first, kind, name", [
    ("GlowScript 3.2 VPython", "glowscript", "GlowScript 3.2"),
    ("GlowScript 2.7 VPython", "glowscript", "GlowScript 2.7"),
    ("Web VPython 3.2", "glowscript", "Web VPython 3.2"),
    ("  glowscript 3.0 vpython  ", "glowscript", "GlowScript 3.0"),
    ("from visual import *", "vpython6", "VPython 6"),
    ("import visual as v", "vpython6", "VPython 6"),
    ("from visual.graph import *", "vpython6", "VPython 6"),
    ("from vpython import *", "vpython7", "VPython 7"),
    ("import vpython", "vpython7", "VPython 7"),
    ("x = 1", "vpython7", "VPython 7"),
])
def test_detect(first, kind, name):
    d = compiling.detect(f"\n{first}\nsphere()\n")
    assert (d.kind, d.name) == (kind, name)


def test_vpython_import_wins_over_visual():
    assert compiling.detect("from vpython import *\nimport visual\n").kind == "vpython7"


def test_header_is_blanked_and_lines_keep_their_numbers():
    src = "GlowScript 3.2 VPython\nx = 1\ny = 2\n"
    out = compiling.strip_header(src)
    assert out.splitlines() == ["", "x = 1", "y = 2"]
    assert compiling.strip_header("x = 1\n") == "x = 1\n"


# ---- GlowScript's leniencies -------------------------------------------------------------

@pytest.mark.parametrize("a, b, expected", [
    ("t = ", 3.0, "t = 3"), ("t = ", 2.5, "t = 2.5"), (1, " s", "1 s"),
    ("ok: ", True, "ok: true"), ("a", "b", "ab"), (2, 3, 5),
])
def test_gs_add_joins_text_as_javascript(a, b, expected):
    assert compiling.gs_add(a, b) == expected


def _run_transformed(src: str) -> dict:
    tree = compiling.transform(ast.parse(textwrap.dedent(src)))
    names = dict(compiling.HELPERS)
    exec(compile(tree, "<t>", "exec"), names)
    return names


def test_only_sums_with_text_are_rewritten():
    tree = compiling.transform(ast.parse("a = b + c\nd = 'x' + e + f\n"))
    calls = [n for n in ast.walk(tree) if isinstance(n, ast.Call)]
    assert len(calls) == 2                    # ('x' + e) + f: both sums hold text
    plain = tree.body[0].value
    assert isinstance(plain, ast.BinOp)       # arithmetic left as it is, at full speed


def test_text_plus_number_in_a_program():
    names = _run_transformed("""
        t = 1.5
        s = "t = " + t + " s"
        n = 2
        s2 = str(n) + 1
        s3 = "x"
        s3 += " = " + 4
        v = 1 + 2
    """)
    assert (names["s"], names["s2"], names["s3"], names["v"]) == ("t = 1.5 s", "21", "x = 4", 3)


def test_glowscript_program_needs_no_imports(tmp_path):
    prog = write(tmp_path, """
        GlowScript 3.2 VPython
        ball = sphere(pos=vec(0, 0, 0), radius=0.5, color=color.red)
        label(pos=ball.pos, text="r = " + ball.radius)
        print("sqrt(2) = " + sqrt(2), pi > 3, random() < 1)
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 0, proc.stderr
    assert proc.stderr.splitlines()[0] == f"springscene: {prog}: written for GlowScript 3.2"
    assert "sqrt(2) = 1.4142135623730951 True True" in proc.stdout


def test_glowscript_syntax_error_names_the_program_line(tmp_path):
    prog = write(tmp_path, """
        Web VPython 3.2
        ball = sphere(
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 1
    assert f'File "{prog}", line 2' in proc.stderr


# ---- VPython 6 -----------------------------------------------------------------------------

@pytest.fixture
def lenient():
    vector_module.set_lenient(True)
    yield
    vector_module.set_lenient(False)


def test_vpython6_vectors(lenient):
    v = vector(1, 2, 3)
    assert v + (1, 1, 1) == vector(2, 3, 4) and v - [1, 2, 3] == (0, 0, 0)
    assert vector() == vector(0, 0, 0) and vector(1, 2) == vector(1, 2, 0)
    assert vector((4, 5, 6)) == vector(4, 5, 6) and vector(np.array([1.0, 2, 3])) == v
    assert len(v) == 3 and list(v) == [1, 2, 3] and abs(vector(3, 4, 0)) == 5
    x, y, z = v
    assert (x, y, z) == (1, 2, 3) and v.astuple() == (1, 2, 3)
    assert np.array([v, v]).shape == (2, 3)


def test_vpython7_vectors_stay_strict():
    v = vector(1, 2, 3)
    with pytest.raises(TypeError):
        v + (1, 1, 1)
    with pytest.raises(TypeError):
        vector(1, 2)
    with pytest.raises(TypeError):
        len(v)
    assert v != (1, 2, 3) and bool(vector(0, 0, 0))


def test_vpython6_namespace(lenient):
    names = visual6.namespace(vp)
    assert names["sqrt"](4.0) == 2.0 and isinstance(names["sqrt"](4.0), float)
    assert np.allclose(names["sin"](np.array([0.0, math.pi / 2])), [0, 1])   # arrays too
    assert names["random"].uniform is np.random.uniform and 0 <= names["random"]() < 1
    assert names["arange"] is np.arange
    assert names["max"] is max if "max" in names else True                    # builtin kept
    assert "max" not in names and "abs" not in names and "round" not in names
    assert names["mag"]((3, 4, 0)) == 5 and names["norm"]([0, 2, 0]) == vector(0, 1, 0)
    assert names["cross"]((1, 0, 0), (0, 1, 0)) == vector(0, 0, 1)
    assert names["dot"](np.array([1, 2]), np.array([3, 4])) == 11
    assert names["true"] is True and names["false"] is False
    assert names["any"](x > 5 for x in range(4)) is False           # a generator: Python's
    assert names["sum"](x for x in range(4)) == 6
    assert list(names["sum"](np.ones((2, 3)), -1)) == [3, 3]         # an array: numpy's
    assert names["display"] is vp.canvas and names["version"][0] == "6.11"
    assert names["float_"] is np.float64 and names["Inf"] == math.inf


def test_vpython6_modules_import(lenient):
    mods = visual6.modules(vp)
    assert {"visual", "visual.graph", "visual.controls", "visual.factorial",
            "visual.filedialog", "vis"} <= set(mods)
    assert mods["visual.factorial"].factorial(5) == 120.0
    assert mods["visual.filedialog"].get_file() is None
    assert mods["visual.graph"].gdisplay is vp.graph


def test_vpython6_program_runs(tmp_path):
    prog = write(tmp_path, """
        from visual import *
        from visual.graph import *
        scene = display(title="bounce", width=400, height=300, x=0, y=0)
        ball = sphere(pos=(0, 2, 0), radius=0.3, color=color.red)
        floor = box(pos=(0, 0, 0), size=(6, 0.1, 2))
        ball.velocity = vector(1, 0, 0)
        g = gdisplay(xtitle="t", ytitle="y")
        f = gcurve(gdisplay=g, color=color.blue)
        h = ghistogram(bins=arange(0, 3, 0.5), color=color.red)
        t, dt = 0, 0.01
        while t < 1:
            rate(100)
            ball.velocity.y = ball.velocity.y - 9.8*dt
            ball.pos = ball.pos + ball.velocity*dt
            if ball.y < 0.35: ball.velocity.y = abs(ball.velocity.y)
            f.plot(pos=(t, ball.y))
            t += dt
        ball.x += 0.5
        h.plot(data=[0.1, 0.2, 0.7, 1.2, 2.9])
        print(mag((3, 4, 0)), ball.pos.x == ball.x, len(ball.pos), sqrt(arange(4))[3])
        print(h._bars.data)
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.mp4")
    assert proc.returncode == 0, proc.stderr
    assert f"{prog}: written for VPython 6" in proc.stderr
    lines = proc.stdout.splitlines()
    assert lines[0] == "5.0 True 3 1.7320508075688772"
    assert lines[1] == "[[0.25, 2.0], [0.75, 1.0], [1.25, 1.0], [1.75, 0.0], [2.25, 0.0], " \
                       "[2.75, 1.0]]"


def test_vpython6_leniency_ends_with_the_run(tmp_path):
    prog = write(tmp_path, "from visual import *\nv = vector(1, 2)\n")
    run_program(prog, tmp_path / "x.png")
    assert not vector_module.is_lenient()
    with pytest.raises(TypeError):
        vector(1, 2)


def test_x_y_z_are_pos_in_vpython6_and_own_attributes_in_vpython7(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        b = sphere()
        b.x = 5
        print(b.x, b.pos.x)
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines()[0] == "5 0.0"


# ---- the course-style programs of tests/vpython_programs ---------------------------------

def _frames_of(program, tmp_path, **options) -> list[np.ndarray]:
    frames = []
    run_program(program, tmp_path / "v.mp4",
                RunOptions(page=False, fps=10, canvas_only=True, **options),
                on_frame=lambda i, img: frames.append(img.astype(int)))
    return frames


def _has(img, rgb, tol=40) -> int:
    return int((np.abs(img - np.array(rgb)).max(axis=-1) < tol).sum())


def test_glowscript_spring_lab_moves_the_ball_and_plots(tmp_path):
    frames = _frames_of(PROGRAMS / "gs_spring_lab.py", tmp_path, duration=2)
    assert len(frames) == 20
    first, last = frames[0], frames[-1]
    assert _has(first, (255, 255, 255)) > 100_000              # scene.background white
    orange = [np.nonzero((f[..., 0] > 200) & (f[..., 1] > 100) & (f[..., 1] < 190)
                         & (f[..., 2] < 60))[0].mean() for f in frames]
    assert max(orange) - min(orange) > 10                      # the ball oscillates
    assert _has(last, (0, 255, 255), 90) > 300                 # the cyan helix


def test_glowscript_orbit_with_tabs_leaves_a_trail(tmp_path):
    frames = _frames_of(PROGRAMS / "gs_orbit_tabs.py", tmp_path)
    last = frames[-1]
    white = (last.min(axis=-1) > 200)
    assert white.sum() > 150                                   # attach_trail's white curve
    assert _has(last, (0, 0, 255), 60) > 50                    # the Earth
    assert ((last[..., 1] > 150) & (last[..., 0] < 80)).sum() > 20   # the green arrow


def test_vpython6_bounce_with_a_frame(tmp_path):
    frames = _frames_of(PROGRAMS / "vp6_bounce_frame.py", tmp_path, duration=2)
    assert frames[0].shape == (400, 600, 3)                    # display(width=, height=)
    yellow = [(f[..., 0] > 180) & (f[..., 1] > 180) & (f[..., 2] < 80) for f in frames]
    assert all(y.sum() > 200 for y in yellow)                  # the pinwheel in its frame
    assert (yellow[0] != yellow[-1]).sum() > 200               # ... turning
    reds = [np.nonzero((f[..., 0] > 150) & (f[..., 1] < 60))[1].mean() for f in frames]
    assert reds[-1] - reds[0] > 30                             # the ball moves to the right


def test_vpython6_controls_wait_for_no_one(tmp_path):
    prog = write(tmp_path, """
        from visual import *
        from visual.controls import *
        c = controls(title="Controls", x=0, y=400, width=300, height=300, range=50)
        b = button(pos=(0, 0), width=10, height=10, text="Start", action=lambda: go())
        s = slider(pos=(-15, -10), length=30, min=0, max=10, value=3, action=lambda: None)
        t = toggle(pos=(10, 10), text0="off", text1="on", value=1, action=lambda: None)
        m = menu(pos=(0, 20), height=7, width=25, text="Options")
        m.items.append(("Red", lambda: None))
        sphere(color=color.red)
        while True:
            c.interact()
    """)
    result = run_program(prog, tmp_path / "x.mp4", RunOptions(duration=1, fps=10, page=False))
    assert (result.ended, result.frames) == ("duration", 10)
    assert any("controls.interact()" in n for n in result.notes)


def test_glowscript_list_append_of_several_items_is_a_push():
    names = dict(compiling.HELPERS)
    tree = compiling.transform(ast.parse("L = [1]\nL.append(2, 3)\nL.append(4)\n"))
    exec(compile(tree, "<t>", "exec"), names)
    assert names["L"] == [1, 2, 3, 4]


def test_what_a_program_prints_is_on_its_page_too(tmp_path):
    prog = write(tmp_path, """
        GlowScript 3.2 VPython
        sphere()
        print("KE = " + 2.0 + " J", "<b>")
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 0, proc.stderr
    assert "KE = 2 J <b>" in proc.stdout                        # to the terminal, as before
    page = (tmp_path / "x.html").read_text()       # the page's data: printed, as text
    assert '"printed":"KE = 2 J \\u003cb\\u003e\\n"' in page


def test_glowscript_leniencies_keep_python_meanings():
    names = _run_transformed("""
        class Money:
            def __init__(self, n): self.n = n
            def __radd__(self, other): return other + "$" + str(self.n)
        letters = []
        letters += "ab"
        paid = "total " + Money(5)
        flag = True
        same = flag is 1
        one = 1 is 1.0
        key = "left"
        left = key is "left"
        tiny = "dt = " + 1e-7 + ", " + 1e-5 + ", " + float("nan")
    """)
    assert names["letters"] == ["a", "b"] and names["paid"] == "total $5"
    assert (names["same"], names["one"], names["left"]) == (False, True, True)
    assert names["tiny"] == "dt = 1e-7, 0.00001, NaN"
