"""Programs you can test: ``springscene.run_vpython`` with no ``out`` gives a ``Run``
(the recording read back), the ``vpython_run`` fixture of the pytest plugin, ``Run.trace``'s
columns and CSV, and the grading example (examples/grading) run as an instructor runs it.

Numbers are checked against closed forms: a ball moved along a line is that line to the
last bit, the wiki program's ball is ``springscene simulate``'s. Runs are in this process
(``supervised=False``) but where the supervised run itself is the point (marked slow).
"""

from __future__ import annotations

import csv
import gc
import gzip
import json
import sys
import textwrap

import numpy as np
import pytest

import springscene
from conftest import ROOT
from springscene import config, render
from springscene.errors import ProgramError, UserError
from springscene.results import Graph, Run, Video
from springscene.vpython.record import trace
from springscene.vpython.record.reader import read as read_recording

EXAMPLES = ROOT / "examples"
GRADING = EXAMPLES / "grading"

LINE = """
    from vpython import *
    ball = sphere(pos=vector(1, 0, 0.5), radius=0.1)
    n = 0
    while True:
        rate(100)
        n += 1
        t = n / 100
        ball.pos = vector(1 + 2 * t, -3 * t, 0.5)
"""

# a bit of everything a test reads: a list of objects, one made late and one deleted, a
# label, a graph with two series, printed lines (one after the loop), globals
LAB = """
    from vpython import *
    k = 12
    m = 0.25
    g = vector(0, -9.8, 0)
    ready = True
    atoms = [sphere(pos=vector(i, 0, 0), radius=0.1) for i in range(3)]
    tag = label(pos=vector(0, 1, 0), text="start", xoffset=20, height=14)
    doomed = box(pos=vector(0, -1, 0))
    arrow_late = None
    plot = graph(title="rise", xtitle="t (s)", ytitle="y (m)")
    up = gcurve(color=color.red, label="y")
    down = gdots(color=color.blue, label="-y")
    for i in range(20):
        rate(10)
        t = (i + 1) / 10
        atoms[1].pos.y = t
        up.plot(t, t)
        down.plot(t, -t)
        if i == 5:
            doomed.delete()
        if i == 9:
            arrow_late = arrow(pos=vector(0, 0, 0), axis=vector(1, 0, 0))
            tag.text = "half"
        print("step", i)
    print("done")
"""


def write(tmp_path, source: str, name: str = "prog.py"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(source))
    return path


def run_here(program, out=None, **options) -> Run:
    """``run_vpython`` in this process (no child Python: the fast tier)."""
    return springscene.run_vpython(program, out, supervised=False, **options)


# ---- run_vpython with no out: a Run -------------------------------------------------------

def test_a_ball_moved_along_a_line_is_the_line_to_the_last_bit(tmp_path):
    run = run_here(write(tmp_path, LINE), duration=2, fps=50)
    assert isinstance(run, Run) and run.frames == 100 and run.ended == "duration"
    assert np.array_equal(run.times, np.arange(100) / 50)
    pos = run["ball"].pos
    assert np.array_equal(pos[:, 0], 1 + 2 * run.times)        # frame f: t = f / 50 exactly
    assert np.array_equal(pos[:, 1], -3 * run.times)
    assert np.all(pos[:, 2] == 0.5)
    assert np.array_equal(run.at(1.0)["ball"].pos, [3.0, -3.0, 0.5])
    assert run.frame_at(1.019) == 50 and run.at(1.019).t == 1.0     # the frame shown then
    assert run.recording is None and run.result.ended == "duration"


def test_the_wiki_program_is_simulate_bit_for_bit():
    run = run_here(EXAMPLES / "wiki_spring.py", frames=50)
    traj = render.simulate(config.load(ROOT / "configs" / "wiki.toml"), 1.0)
    assert np.array_equal(run["ball"].pos, traj.pos[2 * np.arange(50)])
    assert np.array_equal(run["spring"].axis, run["ball"].pos - run["holder"].pos)
    assert run.globals["k"] == 15 and run.globals["m"] == 0.1 and run.globals["L0"] == 0.1


def test_a_run_reads_objects_graphs_printed_text_and_globals(tmp_path):
    run = run_here(write(tmp_path, LAB), fps=10)
    assert run.ended == "program" and run.frames == 21      # 20 rate()s, then the end
    # objects: in the order made, by kind, by the program's names
    assert [o.kind for o in run.objects] == ["sphere"] * 3 + ["label", "box", "arrow"]
    assert run.of_kind("sphere") == run.objects.of_kind("sphere") == run["atoms"]
    assert np.array_equal(run["atoms"][1].pos[:, 1], run.times)    # frame f: after f moves
    assert run["arrow_late"].born == 10 and np.isnan(run["arrow_late"].pos[:10]).all()
    doomed = run.of_kind("box")[0]                  # (a deleted object: no name at the end)
    assert doomed.deleted == 6 and np.isnan(doomed.pos[6:]).all()
    assert run["tag"].text[0] == "start" and run["tag"].text[-1] == "half"
    with pytest.raises(KeyError, match=r"no global variable 'bal' .*names: arrow_late, atoms, tag\)"):
        run["bal"]
    # graphs: each with its titles and series, a series by its label
    (plot,) = run.graphs
    assert isinstance(plot, Graph) and (plot.title, plot.xtitle, plot.ytitle) == (
        "rise", "t (s)", "y (m)")
    assert [s.kind for s in plot] == ["gcurve", "gdots"] and len(plot) == 2
    xy = plot["y"].points()
    # the points plotted up to the last frame: the scene the program left at its end
    assert np.array_equal(xy[:, 0], run.times[1:]) and np.array_equal(xy[:, 0], xy[:, 1])
    assert np.array_equal(plot["-y"].points()[:, 1], -xy[:, 1]) and plot[1] is plot["-y"]
    with pytest.raises(KeyError, match="no series labelled 'z' .*labels: 'y', '-y'"):
        plot["z"]
    assert run.series == plot.series
    # what it printed, the line after its loop too; its globals at the end
    assert run.printed == "".join(f"step {i}\n" for i in range(20)) + "done\n"
    assert run.globals["k"] == 12 and run.globals["m"] == 0.25 and run.globals["ready"] is True
    assert np.array_equal(run.globals["g"], [0, -9.8, 0]) and run.globals["t"] == 2.0
    assert repr(run) == ("<Run prog.py: 21 frames at 10 fps, 0 to 2 s, ended by program; "
                         "6 objects (atoms, tag, arrow_late); 1 graph>")


def test_record_keeps_the_recording_and_a_jsonl_out_is_a_run(tmp_path):
    program = write(tmp_path, LINE)
    kept = run_here(program, duration=0.5, fps=20, record=tmp_path / "r.jsonl.gz")
    assert kept.recording == tmp_path / "r.jsonl.gz"
    with gzip.open(kept.recording, "rt") as fh:
        assert json.loads(fh.readline())["format"] == "springscene-recording"
    again = springscene.vpython.record.reader.read(kept.recording)
    assert np.array_equal(again["ball"].pos, kept["ball"].pos)
    plain = run_here(program, tmp_path / "s.jsonl", duration=0.5, fps=20)
    assert isinstance(plain, Run) and plain.recording == tmp_path / "s.jsonl"
    assert np.array_equal(plain["ball"].pos, kept["ball"].pos)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["prog.py", "r.jsonl.gz", "s.jsonl"]


@pytest.mark.parametrize("record, message", [
    ("r.txt", "--record {}/r.txt: the recording is a .jsonl or .jsonl.gz file"),
    ("nowhere/r.jsonl", "--record {}/nowhere/r.jsonl: folder"),
])
def test_a_bad_record_is_refused_before_the_run(tmp_path, record, message):
    program = write(tmp_path, "from vpython import *\nprint('ran')\n")
    with pytest.raises(UserError, match=message.format(tmp_path).replace(".", r"\.")):
        run_here(program, record=tmp_path / record)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["prog.py"]


def test_a_program_error_is_a_program_error_with_the_run_up_to_it(tmp_path, monkeypatch):
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    monkeypatch.setattr("tempfile.tempdir", str(scratch))    # where a Run's run goes
    program = write(tmp_path, """
        from vpython import *
        b = sphere()
        for i in range(5):
            rate(10)
        raise ValueError("no more data")
    """)
    with pytest.raises(ProgramError, match="no more data") as raised:
        run_here(program, record=tmp_path / "kept.jsonl")
    run = raised.value.run                   # the run up to the error, kept as asked
    assert run.ended == "error" and run.error["type"] == "ValueError" and run.times[-1] == 0.5
    assert run.frames == 26              # 25 frames at 50 fps in 0.5 s, and the error's scene
    assert read_recording(tmp_path / "kept.jsonl").error == run.error
    del run, raised
    gc.collect()
    assert list(scratch.iterdir()) == []


def test_a_program_error_before_the_first_frame_leaves_nothing(tmp_path, monkeypatch):
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    monkeypatch.setattr("tempfile.tempdir", str(scratch))
    program = write(tmp_path, """
        from vpython import *
        b = sphere()
        raise ValueError("no data at all")
    """)
    with pytest.raises(ProgramError, match="no data at all") as raised:
        run_here(program, record=tmp_path / "kept.jsonl")
    assert raised.value.run is None
    assert list(scratch.iterdir()) == [] and not (tmp_path / "kept.jsonl").exists()


def test_a_video_with_record_has_its_run(tmp_path):
    program = write(tmp_path, LINE)
    video = run_here(program, tmp_path / "v.png", duration=0.3, fps=10, draft=True,
                     page=False, record=tmp_path / "v.jsonl")
    assert isinstance(video, Video) and video.path == tmp_path / "v.png"
    assert isinstance(video.run, Run) and video.run.recording == tmp_path / "v.jsonl"
    assert np.array_equal(video.run["ball"].pos[:, 0], 1 + 2 * video.run.times)


# ---- Run.trace: columns with units, CSV ------------------------------------------------------

def test_trace_columns_have_units_and_the_csv_is_the_numbers_exactly(tmp_path):
    run = run_here(write(tmp_path, LAB), fps=10)
    ball = run.trace("atoms[1]", tmp_path / "atom.csv")
    assert list(ball)[:4] == ["t [s]", "pos.x [m]", "pos.y [m]", "pos.z [m]"]
    assert {"axis.x [m]", "size.z [m]", "up.y", "color.r", "color.b", "opacity", "visible"} \
        <= set(ball)
    assert not any("texture" in name for name in ball)                   # text: left out
    with open(tmp_path / "atom.csv", newline="") as fh:
        rows = list(csv.reader(fh))
    assert rows[0] == list(ball) and len(rows) == 1 + run.frames
    for i, name in enumerate(rows[0]):
        assert np.array_equal([float(r[i]) for r in rows[1:]], ball[name]), name
    assert rows[1][rows[0].index("visible")] == "1"                      # a flag as 1 or 0
    # an object made late: empty cells before; a label's offsets and height in pixels
    late = run.trace("arrow_late")
    assert np.isnan(late["pos.x [m]"][:10]).all() and "shaftwidth [m]" in late
    tag = run.trace("tag")
    assert {"xoffset [px]", "height [px]", "pos.y [m]"} <= set(tag)
    assert tag["xoffset [px]"][0] == 20 and not any(n.startswith("text") for n in tag)
    run.trace("arrow_late", tmp_path / "late.csv")
    first = (tmp_path / "late.csv").read_text().splitlines()[1]
    assert first.startswith("0,,,,")


def test_trace_units_follow_vpythons_own_pixels_and_world_units(tmp_path):
    run = run_here(write(tmp_path, """
        from vpython import *
        dots = points(pos=[vector(0, 0, 0)], radius=3)
        big = points(pos=[vector(1, 0, 0)], radius=0.2, size_units="world")
        path = curve(pos=[vector(0, 0, 0), vector(1, 1, 0)], radius=0.05)
        pinned = label(pixel_pos=True, pos=vector(20, 30, 0), text="pinned")
        rate(10)
    """), fps=10)
    assert run.trace("dots")["radius [px]"][0] == 3
    assert run.trace("big")["radius [m]"][0] == 0.2
    assert {"origin.x [m]", "radius [m]", "axis.x [m]"} <= set(run.trace("path"))
    pinned = run.trace("pinned")
    assert pinned["pos.x [px]"][0] == 20 and pinned["pixel_pos"][0] == 1


@pytest.mark.parametrize("name, message", [
    ("bal", "--trace bal: prog.py has no global variable 'bal' holding an object (its "
            "names: arrow_late, atoms[0..2], tag)"),
    ("atoms", "--trace atoms: atoms holds 3 objects; name one of them, atoms[0] to atoms[2]"),
    ("atoms[3]", "--trace atoms[3]: atoms holds 3 objects"),
    ("tag[0]", "--trace tag[0]: tag is one object (label), not a list; trace it as tag"),
    ("a b", "--trace 'a b': not a variable name"),
    ("pos.x", "--trace 'pos.x': not a variable name"),
])
def test_trace_names_what_the_program_has(tmp_path, name, message):
    rec = springscene.vpython.record.reader.read(
        run_here(write(tmp_path, LAB), fps=10, record=tmp_path / "r.jsonl").recording)
    with pytest.raises(UserError) as caught:
        trace.write_traces(rec, [(name, tmp_path / "x.csv")])
    assert str(caught.value).startswith(message) and "\n" not in str(caught.value)
    assert not (tmp_path / "x.csv").exists()


def test_trace_paths_sit_beside_the_output():
    assert trace.trace_path("renders/run.mp4", "ball").as_posix() == "renders/run-ball.csv"
    assert trace.trace_path("run.jsonl", "atoms[12]").name == "run-atoms-12.csv"


# ---- the pytest plugin's vpython_run fixture ---------------------------------------------

class _Reports:
    """The outcome and message of each test of an inner pytest session."""

    def __init__(self) -> None:
        self.outcomes: dict[str, str] = {}
        self.messages: dict[str, str] = {}

    def pytest_runtest_logreport(self, report) -> None:
        if report.when == "call" or report.outcome != "passed":
            name = report.nodeid.split("::")[-1]
            self.outcomes[name] = report.outcome
            self.messages[name] = report.longreprtext


def inner_pytest(*args) -> _Reports:
    """pytest run in this process on ``args`` (springscene's plugin loads by its entry
    point, as in any project that installs springscene; hypothesis's, which imports
    hypothesis at the session's end, 0.5 s, is left out; the test files imported as
    importlib does, leaving sys.path as it was)."""
    reports = _Reports()
    status = pytest.main(["-q", "-p", "no:cacheprovider", "-p", "no:hypothesispytest",
                          "--import-mode=importlib", *map(str, args)], plugins=[reports])
    assert status in (0, 1), status
    return reports


def test_the_fixture_runs_a_marked_program_once_for_every_test(tmp_path):
    write(tmp_path, LINE.replace("rate(100)", "rate(100)\n        if n == 0: print('ran')"),
          "lab.py")
    write(tmp_path, LINE.replace("1 + 2 * t", "5 + 2 * t"), "other.py")
    tests = write(tmp_path, """
        import pytest
        pytestmark = pytest.mark.vpython_program("lab.py", duration=1, fps=10,
                                                 supervised=False)
        seen = []

        @pytest.fixture
        def run(vpython_run):
            return vpython_run()

        def test_first(run):
            seen.append(run)
            assert run.program == "lab.py" and run.frames == 10

        def test_second(run, vpython_run):
            seen.append(run)
            assert vpython_run(duration=0.5).frames == 5          # other options: a new run

        def test_same_run(run):
            assert all(r is run for r in seen) and run.printed == "ran\\n"

        def test_any_program(vpython_run):
            run = vpython_run("other.py", duration=0.2, fps=10, supervised=False)
            assert run["ball"].pos[1, 0] == 5 + 2 * 0.1
    """, "test_lab.py")
    reports = inner_pytest(tests)
    assert reports.outcomes == dict.fromkeys(
        ["test_first", "test_second", "test_same_run", "test_any_program"], "passed"), \
        reports.messages
    # --springscene-program runs another program where the marker names one
    path = list(sys.path)
    reports = inner_pytest(tests, "--springscene-program", tmp_path / "other.py")
    assert reports.outcomes["test_first"] == "failed"
    assert sys.path == path
    assert "'other.py' == 'lab.py'" in reports.messages["test_first"]


def test_a_program_that_raises_fails_each_test_with_its_traceback_once(tmp_path, monkeypatch):
    write(tmp_path, """
        from vpython import *
        with open("runs.txt", "a") as fh:
            fh.write("ran\\n")
        b = sphere()
        rate(10)
        b.pos.x = 1 / 0
    """, "broken.py")
    tests = write(tmp_path, """
        import pytest
        pytestmark = pytest.mark.vpython_program("broken.py", supervised=False)

        def test_a(vpython_run):
            vpython_run()

        def test_b(vpython_run):
            vpython_run()

    """, "test_broken.py")
    unmarked = write(tmp_path, """
        def test_no_program(vpython_run):
            vpython_run()
    """, "test_unmarked.py")
    monkeypatch.chdir(tmp_path)                      # where the program writes runs.txt
    reports = inner_pytest(tests, unmarked)
    assert reports.outcomes["test_a"] == reports.outcomes["test_b"] == "failed"
    for name in ("test_a", "test_b"):
        assert "ZeroDivisionError" in reports.messages[name]
        assert 'broken.py", line 7' in reports.messages[name]
    assert (tmp_path / "runs.txt").read_text() == "ran\n"        # one run for both
    assert reports.outcomes["test_no_program"] == "failed"
    assert reports.messages["test_no_program"].startswith(
        "vpython_run() names no program and test_unmarked.py::test_no_program has no "
        "vpython_program marker: call vpython_run('lab.py') or mark the module")


# ---- the grading example, as an instructor runs it -----------------------------------------

@pytest.mark.slow        # the plugin's supervised run: a child Python per program
def test_the_grading_example_passes_the_lab_and_fails_the_wrong_one():
    reports = inner_pytest(GRADING / "test_spring_lab.py")
    assert set(reports.outcomes.values()) == {"passed"} and len(reports.outcomes) == 4, \
        reports.messages
    wrong = inner_pytest(GRADING / "test_spring_lab.py", "--springscene-program",
                         GRADING / "spring_lab_wrong.py")
    assert wrong.outcomes["test_period_is_two_pi_root_m_over_k"] == "failed"
    assert ("period 0.4967 s measured from the block's motion, expected 2 pi sqrt(m/k) = "
            "0.9935 s (m = 0.5 kg, k = 20 N/m): off by -50.0%, more than 2%"
            ) in wrong.messages["test_period_is_two_pi_root_m_over_k"]
    assert wrong.outcomes["test_energy_is_conserved"] == "failed"
    assert wrong.outcomes["test_prints_its_period"] == "passed"   # it measures its own motion


@pytest.mark.slow        # run_vpython's supervised run: a child Python
def test_run_vpython_runs_supervised_by_default(tmp_path):
    program = write(tmp_path, LINE)
    run = springscene.run_vpython(program, duration=0.4, fps=10, timeout=60)
    assert run.result.peak_memory and run.frames == 4          # measured by the supervisor
    assert np.array_equal(run["ball"].pos[:, 0], 1 + 2 * run.times)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["prog.py"]
