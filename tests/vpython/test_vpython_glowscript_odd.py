"""Old and odd Web VPython: GlowScript 1.x and 2.x headers and names, JavaScript headers
refused, RapydScript's syntax that Python lacks (``else if``, ``return x = y``, a ``def``
used as an expression, ``nonlocal`` of a program variable), and VPython 7 programs
converted from GlowScript that still use its names."""

from __future__ import annotations

import textwrap

import numpy as np
import pytest

from conftest import ROOT, run_cli
from springscene.vpython import api as vp
from springscene.vpython.dialects import compiling, glowscript, rapydscript
from springscene.vpython.run.options import RunOptions
from springscene.vpython.run.runner import run_program

PROGRAMS = ROOT / "tests" / "vpython_programs"


def write(tmp_path, source: str, name: str = "prog.py"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(source).lstrip("\n"))
    return path


def run_source(source: str, version: str = "3.2") -> dict:
    """A Web VPython program's source compiled as springscene does and run in plain
    Python with the helpers its translation calls."""
    dialect = compiling.Dialect("glowscript", f"GlowScript {version}", version)
    code = compiling.compile_program(textwrap.dedent(source), "<prog>", dialect)
    names = dict(compiling.HELPERS)
    exec(code, names)
    names["__dialect__"] = dialect
    return names


# ---- headers -----------------------------------------------------------------------------

@pytest.mark.parametrize("version", ["1.0", "1.1", "2.0", "2.1", "2.2", "2.5", "2.9", "3.0"])
def test_every_glowscript_version_is_web_vpython(version):
    d = compiling.detect(f"GlowScript {version} VPython\nsphere()\n")
    assert (d.kind, d.name, d.version, d.language) == (
        "glowscript", f"GlowScript {version}", version, "VPython")


@pytest.mark.parametrize("first, language", [
    ("GlowScript 2.7 RapydScript", "RapydScript"),
    ("GlowScript 2.7 JavaScript", "JavaScript"),
    ("JavaScript 3.2", "JavaScript"),
    ("GlowScript 2.7", ""),                       # no language: JavaScript to GlowScript
    ("Web VPython 3.2 nodictionary", "VPython"),
    ("GlowScript 3.3dev VPython", "VPython"),
])
def test_the_language_of_a_header(first, language):
    d = compiling.detect(f"{first}\nx = 1\n")
    assert d.kind == "glowscript" and d.language == language


@pytest.mark.parametrize("source, kind, converted", [
    ("# GlowScript 1.1 VPython\nball = sphere()\n", "glowscript", ""),     # saved as .py
    ("#GlowScript 3.0 VPython\nfrom vpython import *\n", "vpython7", "3.0"),
    ("from vpython import *\n#GlowScript 1.1 VPython\nsphere()\n", "vpython7", "1.1"),
    ("#GlowScript 1.1 VPython\nfrom visual import *\n", "vpython6", ""),
    ("# -*- coding: utf-8 -*-\nGlowScript 2.1 VPython\nsphere()\n", "glowscript", ""),
    ("from vpython import *\n# a GlowScript program\nsphere()\n", "vpython7", ""),
])
def test_a_header_left_as_a_comment(source, kind, converted):
    d = compiling.detect(source)
    assert (d.kind, d.converted) == (kind, converted)


def test_a_header_after_a_coding_line_is_blanked():
    src = "# -*- coding: utf-8 -*-\nGlowScript 2.1 VPython\nx = 1\n"
    assert compiling.strip_header(src).splitlines() == ["# -*- coding: utf-8 -*-", "", "x = 1"]


@pytest.mark.parametrize("first", ["GlowScript 2.7 JavaScript", "JavaScript 3.2",
                                   "GlowScript 2.7"])
def test_a_javascript_program_is_refused_in_one_line(tmp_path, first):
    prog = write(tmp_path, f"{first}\nvar b = box({{pos: vec(1, 0, 0)}})\n")
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 2
    assert proc.stderr.count("\n") == 1 and "Traceback" not in proc.stderr
    assert "JavaScript" in proc.stderr and "not a VPython program" in proc.stderr
    assert not (tmp_path / "x.png").exists()


def test_a_header_without_language_runs_when_it_is_python(tmp_path):
    prog = write(tmp_path, "GlowScript 2.7\nb = box()\nprint('ran', b.size.x)\n")
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 0, proc.stderr
    assert "ran 1" in proc.stdout


# ---- RapydScript's syntax ----------------------------------------------------------------

def test_else_if_and_its_spacings_are_elif():
    src = ("if a:\n    x = 1\nelse if b:\n    x = 2\nelse  if(c):\n    x = 3\n"
           "else\tif d: x = 4\nelse:\n    s = 'else if e'\n")
    done = rapydscript.translate(src)
    assert done.source.splitlines() == [
        "if a:", "    x = 1", "elif b:", "    x = 2", "elif(c):", "    x = 3",
        "elif d: x = 4", "else:", "    s = 'else if e'"]
    assert done.else_if == [3, 5, 7]


@pytest.mark.parametrize("n, branch", [(-1, "neg"), (0, "zero"), (5, "small"), (50, "big")])
def test_else_if_takes_the_branch_rapydscript_takes(n, branch):
    names = run_source(f"""
        def classify(n):
            if n < 0:
                return "neg"
            else if n == 0:
                return "zero"
            else if n < 10:
                return "small"
            else:
                return "big"
        got = classify({n})
    """)
    assert names["got"] == branch


def test_return_assign_binds_where_javascript_binds():
    # the values RapydScript-NG (GlowScript's lib/rapydscript/compiler.js) gives this
    # program run in node, the program inside GlowScript's def __main__()
    names = run_source("""
        level = 0
        count = 10
        def raise_level(step):
            return level = level + step      # the program's level: no local of that name
        def local_only(step):
            count = 1
            return count = count + step      # a local: the program's count untouched
        def outer():
            inner_v = 1
            def inner():
                return inner_v = 5           # the enclosing function's
            inner()
            return inner_v
        def aug(k):
            return count += k
        r1 = raise_level(2)
        r2 = local_only(5)
        r3 = outer()
        r4 = aug(4)
    """)
    assert (names["r1"], names["level"]) == (2, 2)
    assert (names["r2"], names["r3"], names["r4"], names["count"]) == (6, 5, 14, 14)
    assert names["__dialect__"].notes == [
        "lines 5, 8, 12, 16: `return x = y` read as `x = y; return x` (RapydScript's "
        "syntax, as GlowScript reads it)"]


def test_return_assign_after_a_colon_on_one_line():
    names = run_source("""
        best = 0
        def keep(v):
            if v > best: return best = v
            return best
        got = [keep(3), keep(1)]
    """)
    assert (names["got"], names["best"]) == ([3, 3], 3)      # RapydScript-NG: 3 3 3


def test_return_of_a_comparison_or_a_keyword_call_is_left_alone():
    src = "def f(a):\n    return a == 1\ndef g(a):\n    return h(b=a)\nx = y = 2\n"
    assert rapydscript.translate(src).source == src


def test_anonymous_defs_become_named_functions_on_their_lines():
    src = ("x = 0\n"
           "run(def (k):\n"
           "    global x\n"
           "    x = k\n"
           ", def (k):\n"
           "    return k\n"
           ")\n"
           "double = def(v): return 2*v\n")
    done = rapydscript.translate(src)
    assert done.source.splitlines() == [
        "x = 0",
        "def anonymous_def_2(k):",
        "    global x",
        "    x = k",
        "def anonymous_def_5(k):",
        "    return k",
        "run(anonymous_def_2,anonymous_def_5)",
        "def double(v): return 2*v"]
    assert done.anonymous_def == [2, 5, 8] and done.moved == {7: 2}


def test_a_def_as_an_argument_runs_as_rapydscript_runs_it():
    names = run_source("""
        count = 10
        calls = []
        def run(f):
            f(3)
        run(def (k):
            nonlocal count
            count = count * k
            calls.append(k)
        )
        double = def(x): return 2*x
        d = double(21)
    """)
    assert (names["count"], names["calls"], names["d"]) == (30, [3], 42)
    assert names["__dialect__"].notes[-1] == (
        "line 7: `nonlocal` of a program variable read as `global` (RapydScript's syntax, "
        "as GlowScript reads it)")


def test_defs_in_lists_and_dicts_inside_a_block():
    names = run_source("""
        handlers = {}
        if True:
            handlers["a"] = [def (x):
                return x + 1
            , def (x):
                return x * 10
            ]
            table = {'k': def (v):
                return -v
            }
        got = [handlers["a"][0](1), handlers["a"][1](2), table['k'](3)]
    """)
    assert names["got"] == [2, 20, -3]                       # RapydScript-NG: 2 20 -3


def test_a_program_that_parses_is_not_translated():
    names = run_source("""
        s = "else if"
        def f(a=1):
            return a == 1
        ok = f()
    """)
    assert names["ok"] is True and names["__dialect__"].notes == []


def test_rapydscript_forms_program_runs_and_draws(tmp_path):
    frames = []
    result = run_program(PROGRAMS / "gs_rapydscript_forms.py", tmp_path / "v.mp4",
                         RunOptions(page=False, canvas_only=True, fps=2, duration=1),
                         on_frame=lambda i, img: frames.append(img.astype(int)))
    notes = "\n".join(result.notes)
    assert "lines 12, 14: `else if` read as `elif`" in notes
    assert "line 20: `return x = y`" in notes
    assert "lines 29, 35: a `def` used as an expression" in notes
    assert "line 30: `nonlocal`" in notes
    img = frames[-1]
    rows = {}
    for name, rgb in (("blue", (0, 0, 255)), ("green", (0, 255, 0)), ("red", (255, 0, 0))):
        mask = (np.abs(img - np.array(rgb)).max(axis=-1) < 90)
        assert mask.sum() > 200, name                 # each branch's ball is drawn
        rows[name] = np.nonzero(mask)[0].mean()
    # red raised to level 1.5 by the return assignment, blue lowered to -1.5 by the def
    assert rows["red"] < rows["green"] - 30 and rows["blue"] > rows["green"] + 30


def test_rapydscript_forms_program_prints_what_rapydscript_computes(tmp_path):
    proc = run_cli("vpython", PROGRAMS / "gs_rapydscript_forms.py", "--out", tmp_path / "x.png")
    assert proc.returncode == 0, proc.stderr
    assert "raised 1.5 level 1.5 ball0 y -1.5" in proc.stdout
    assert "springscene: note: lines 12, 14: `else if` read as `elif` (RapydScript's " \
           "syntax, as GlowScript reads it)" in proc.stderr


def test_traceback_points_at_the_source_lines(tmp_path):
    prog = write(tmp_path, """
        GlowScript 3.2 VPython
        def call(f, n):
            return f(n)
        if False:
            pass
        else if True:
            out = call(def (k):
                y = k
                return y / 0
            , 1)
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 1
    err = proc.stderr
    assert f'File "{prog}", line 7, in <module>\n    out = call(def (k):' in err
    assert f'File "{prog}", line 3, in call' in err
    assert f'File "{prog}", line 9, in anonymous_def_7\n    return y / 0' in err
    assert "ZeroDivisionError" in err
    # how the program was read stands above its traceback, once
    note = "springscene: note: line 6: `else if` read as `elif`"
    assert err.count(note) == 1 and err.index(note) < err.index("Traceback")


def test_a_real_syntax_error_is_reported_at_its_line(tmp_path):
    prog = write(tmp_path, """
        GlowScript 3.2 VPython
        x = 1
        if x:
            pass
        else if x == 2:
            pass
        y = (3 +
        print(y)
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 1
    assert f'File "{prog}", line 7' in proc.stderr and "SyntaxError" in proc.stderr
    plain = write(tmp_path, "GlowScript 3.2 VPython\nif x\n    pass\n", "plain.py")
    proc = run_cli("vpython", plain, "--out", tmp_path / "y.png")
    assert proc.returncode == 1
    assert f'File "{plain}", line 2' in proc.stderr and "expected ':'" in proc.stderr


def test_vpython7_programs_are_never_translated(tmp_path):
    prog = write(tmp_path, "from vpython import *\nif 1:\n    pass\nelse if 2:\n    pass\n")
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 1 and "SyntaxError" in proc.stderr


# ---- GlowScript's runtime leniencies of this kind ----------------------------------------

def test_extra_arguments_and_arrays_in_text_as_javascript():
    names = run_source("""
        def cl(x, y):
            return x + y
        total = cl(1, 2, 3)
        axes = ['a', 'c', 'b']
        text = 'axis: ' + axes + '!'
        letters = []
        letters += "ab"
    """)
    assert names["total"] == 3 and names["text"] == "axis: a,c,b!"
    assert names["letters"] == ["a", "b"]


# ---- GlowScript 1.x and 2.0 --------------------------------------------------------------

def test_glowscript_1_1_lab_runs_with_its_names(tmp_path):
    proc = run_cli("vpython", PROGRAMS / "gs_old_header_lab.py", "--out", tmp_path / "x.png")
    assert proc.returncode == 0, proc.stderr
    assert "written for GlowScript 1.1" in proc.stderr
    # version is the header's; caption.text() writes plain text, append() adds to it
    assert "1.1 t = 0 &lt;s&gt; done" in proc.stdout.splitlines()
    assert (tmp_path / "x-graph1.png").exists()                 # gdisplay's graph


@pytest.mark.parametrize("version, has_true", [("1.1", True), ("2.2", True), ("2.3", False),
                                               ("3.2", False)])
def test_true_and_false_before_rapydscript_ng(version, has_true):
    names = glowscript.names(vp, version)
    assert ("true" in names) is has_true and names["version"] == [version, "glowscript"]


def test_jquery_caption_calls_only_before_2_1():
    src = "scene.caption.text('a')\n"
    old = compiling.Dialect("glowscript", "GlowScript 2.0", "2.0")
    new = compiling.Dialect("glowscript", "GlowScript 2.1", "2.1")
    assert "__gs_jquery__" in compiling.compile_program(src, "<p>", old).co_names
    assert "__gs_jquery__" not in compiling.compile_program(src, "<p>", new).co_names


# ---- VPython 7 converted from GlowScript -------------------------------------------------

def test_converted_program_gets_glowscripts_names_with_a_note(tmp_path):
    proc = run_cli("vpython", PROGRAMS / "vp7_converted_glowscript.py",
                   "--out", tmp_path / "x.png")
    assert proc.returncode == 0, proc.stderr
    assert "x = 0.9" in proc.stdout                   # range(0, 1, 0.05): 20 steps
    assert ("springscene: note: display, gdisplay: GlowScript's names, given to this "
            "program converted from GlowScript 2.7 (VPython 7 has none)") in proc.stderr
    assert "range() of floats: GlowScript's range" in proc.stderr
    assert (tmp_path / "x-graph1.png").exists()


def test_converted_program_keeps_its_own_names_and_python_range(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        #GlowScript 3.0 VPython
        def display(**options):
            return canvas(**options)
        scene = display(title="mine")
        print(list(range(3)))
    """)
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 0, proc.stderr
    assert "[0, 1, 2]" in proc.stdout
    assert "GlowScript's name" not in proc.stderr and "range()" not in proc.stderr


def test_a_converted_programs_syntax_error_is_reported_as_python_does(tmp_path):
    prog = write(tmp_path, "from vpython import *\n#GlowScript 3.0 VPython\nif x\n    pass\n")
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 1
    assert proc.stderr.startswith(f'  File "{prog}", line 3') and "ast.py" not in proc.stderr


def test_a_vpython7_program_not_converted_gets_no_glowscript_names(tmp_path):
    prog = write(tmp_path, "from vpython import *\nscene = display()\n")
    proc = run_cli("vpython", prog, "--out", tmp_path / "x.png")
    assert proc.returncode == 1 and "NameError: name 'display'" in proc.stderr


def test_mag_of_an_object_is_undefined_as_in_glowscript():
    # vectors.js: mag(A) is A.mag; a sphere has none (the corpus's hardSphereGasItv reads it)
    import springscene.vpython.api as vp
    from springscene.vpython.dialects import glowscript
    vp.reset()
    given = glowscript.names(vp)
    ball = vp.sphere()
    assert given["mag"](ball) is None and given["hat"](ball) is None
    assert given["mag"](vp.vector(3, 4, 0)) == 5 and given["mag2"](vp.vector(3, 4, 0)) == 25
    assert given["hat"](vp.vector(0, 2, 0)).equals(vp.vector(0, 1, 0))
