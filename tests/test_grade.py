"""Grades: ``springscene grade`` and :mod:`springscene.batch.grading`, an instructor's pytest
tests run on a program's recorded run; the pytest plugin's ``--springscene-run`` (a
recording's run in place of a program's), ``--springscene-run-failed`` and ``weight``.

The plugin's paths run in this process (the fast tier); whatever grades a program starts
a pytest and a supervised run of its own (marked slow).
"""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

import springscene
from conftest import ROOT
from springscene.batch import grading
from springscene.batch.grade_report import message_of
from springscene.errors import UserError
from springscene.vpython.run.sandbox import unavailable as no_sandbox

GRADING = ROOT / "examples" / "grading"
LAB_TESTS = GRADING / "test_spring_lab.py"
PERIOD = "test_period_is_two_pi_root_m_over_k"
LAB_TEST_NAMES = [PERIOD, "test_energy_is_conserved", "test_prints_its_period",
                  "test_plots_its_energy_and_the_total_is_flat"]

# a ball moving along x at 2 m/s; it raises at t = 0.5 s when BREAK is set
MOVER = """
    from vpython import *
    BREAK = False
    ball = sphere(pos=vector(0, 0, 0), radius=0.1)
    t = 0
    while t < 1:
        rate(100)
        t += 0.01
        ball.pos.x = 2 * t
        if BREAK and t > 0.5:
            raise ValueError("the spring broke")
"""

# the instructor's tests of MOVER: two on its run (one worth 2), one that needs no run
MOVER_TESTS = """
    import pytest

    pytestmark = pytest.mark.vpython_program("mover.py", fps=10, timeout=60)

    @pytest.fixture
    def run(vpython_run):
        return vpython_run()

    @pytest.mark.weight(2)
    def test_speed(run):
        x, t = run["ball"].pos[:, 0], run.times
        speed = (x[-1] - x[0]) / (t[-1] - t[0])
        assert abs(speed - 2) < 0.05, f"speed {speed:.3f} m/s, expected 2 m/s"

    def test_reaches_two_metres(run):
        assert run["ball"].pos[-1, 0] > 1.9, (
            f"the ball ends at x = {run['ball'].pos[-1, 0]:.2f} m, not 2 m")

    def test_honour_code():
        assert 1 + 1 == 2
"""


def write(folder, source: str, name: str):
    path = folder / name
    path.write_text(textwrap.dedent(source))
    return path


def check_gradescope(data: dict, tests: int) -> None:
    """``data`` in the format of Gradescope's results.json: the fields and their types,
    the score the sum of the tests'."""
    assert set(data) == {"score", "execution_time", "output", "visibility",
                         "stdout_visibility", "tests"}
    assert isinstance(data["score"], float) and isinstance(data["execution_time"], int)
    assert isinstance(data["output"], str)
    assert data["visibility"] in ("hidden", "after_due_date", "after_published", "visible")
    assert len(data["tests"]) == tests
    for test in data["tests"]:
        assert set(test) == {"name", "score", "max_score", "status", "output", "visibility"}
        assert isinstance(test["name"], str) and isinstance(test["output"], str)
        assert isinstance(test["score"], float) and isinstance(test["max_score"], float)
        assert test["status"] in ("passed", "failed")
        assert test["score"] == (test["max_score"] if test["status"] == "passed" else 0)
    assert data["score"] == sum(t["score"] for t in data["tests"])


# ---- the pytest plugin: a recording's run, a failed run, the outcomes (in this process) ------

def inner_pytest(*args) -> dict:
    """pytest run in this process with the outcomes plugin; what it wrote."""
    status = pytest.main(["-q", "-p", "no:cacheprovider", "-p", "no:hypothesispytest",
                          "--import-mode=importlib", "-p", "springscene.batch.grade_report",
                          *map(str, args)])
    assert status in (0, 1), status
    return status


def outcomes(tmp_path, *args) -> dict:
    target = tmp_path / "outcomes.json"
    inner_pytest("--springscene-outcomes", target, *args)
    found = json.loads(target.read_text())
    return {t["name"]: t for t in found["tests"]}


def test_springscene_run_gives_the_recordings_run_and_nothing_runs(tmp_path):
    mover = write(tmp_path, MOVER, "mover.py")
    recording = tmp_path / "mover.jsonl"
    springscene.run_vpython(mover, recording, fps=10, supervised=False)
    tests = write(tmp_path, MOVER_TESTS, "test_mover.py")
    mover.write_text("raise SystemExit('the program must not run')\n")
    found = outcomes(tmp_path, tests, "--springscene-run", recording)
    assert {name: t["outcome"] for name, t in found.items()} == dict.fromkeys(
        ["test_speed", "test_reaches_two_metres", "test_honour_code"], "passed")
    assert found["test_speed"]["weight"] == 2 and found["test_honour_code"]["weight"] == 1
    assert found["test_speed"]["options"] == {"fps": 10, "timeout": 60}


def test_a_recording_up_to_the_programs_error_is_its_run_so_far(tmp_path):
    mover = write(tmp_path, MOVER.replace("BREAK = False", "BREAK = True"), "mover.py")
    recording = tmp_path / "broken.jsonl"
    with pytest.raises(springscene.errors.ProgramError):
        springscene.run_vpython(mover, recording, fps=10, supervised=False)
    run = springscene.pytest_plugin.read_run(recording)
    assert run.ended == "error" and run.error["type"] == "ValueError"
    tests = write(tmp_path, MOVER_TESTS, "test_mover.py")
    found = outcomes(tmp_path, tests, "--springscene-run", recording)
    assert found["test_speed"]["outcome"] == "passed"          # graded as far as it went
    assert found["test_reaches_two_metres"]["outcome"] == "failed"
    assert found["test_reaches_two_metres"]["message"] == (
        f"the ball ends at x = {run['ball'].pos[-1, 0]:.2f} m, not 2 m")


def test_springscene_run_failed_fails_the_tests_that_ask_for_the_run(tmp_path):
    write(tmp_path, MOVER, "mover.py")
    tests = write(tmp_path, MOVER_TESTS, "test_mover.py")
    line = "the program raised NameError: name 'sphre' is not defined (line 3)"
    found = outcomes(tmp_path, tests, "--springscene-run-failed", line)
    assert found["test_speed"]["outcome"] == found["test_reaches_two_metres"]["outcome"] \
        == "failed"
    assert found["test_speed"]["message"] == line
    assert found["test_honour_code"]["outcome"] == "passed"


def test_a_missing_recording_is_a_usage_error(tmp_path, capsys):
    tests = write(tmp_path, MOVER_TESTS, "test_mover.py")
    status = pytest.main(["-q", "-p", "no:cacheprovider", str(tests),
                          "--springscene-run", str(tmp_path / "none.jsonl")])
    assert status == pytest.ExitCode.USAGE_ERROR
    assert "--springscene-run" in capsys.readouterr().err


@pytest.mark.parametrize("error, message", [
    (AssertionError("period 0.4967 s, expected 0.9935 s\nassert 0.5 <= 0.02\n +  where"),
     "period 0.4967 s, expected 0.9935 s"),
    (AssertionError("assert 0.5 <= 0.02\n +  where 0.5 = abs(-0.5)"), "assert 0.5 <= 0.02"),
    (KeyError("'spring': the program has ball, wall"),
     "KeyError: \"'spring': the program has ball, wall\""),
    (springscene.errors.ProgramError("Traceback (most recent call last):\n  File "
                                     "\"lab.py\", line 3\nNameError: name 'x' is not defined"),
     "NameError: name 'x' is not defined"),
])
def test_a_failed_tests_message_is_its_own_first_lines(error, message):
    assert message_of(error) == message


# ---- grades, one program at a time (each a pytest and a supervised run of their own) --------

@pytest.mark.slow
def test_the_lab_scores_full_marks(cli, tmp_path):
    results = tmp_path / "results.json"
    done = cli("grade", GRADING / "spring_lab.py", "--tests", LAB_TESTS, "--results", results,
               "--no-sandbox")
    assert done.returncode == 0, done.stderr
    assert "spring_lab.py: 4 of 4 tests passed, 5/5 points" in done.stdout
    data = json.loads(results.read_text())
    check_gradescope(data, 4)
    assert data["score"] == 5.0 and [t["name"] for t in data["tests"]] == LAB_TEST_NAMES
    assert data["output"].startswith("spring_lab.py: 501 frames, 5.00 s of program time, "
                                     "ended by program")


@pytest.mark.slow
def test_the_wrong_lab_fails_the_period_naming_the_measured_and_expected(cli, tmp_path):
    results = tmp_path / "results.json"
    done = cli("grade", GRADING / "spring_lab_wrong.py", "--tests", LAB_TESTS,
               "--results", results, "--no-sandbox")
    assert done.returncode == 0, done.stderr
    assert "spring_lab_wrong.py: 1 of 4 tests passed, 1/5 points" in done.stdout
    data = json.loads(results.read_text())
    check_gradescope(data, 4)
    period = data["tests"][0]
    assert period["name"] == PERIOD and period["status"] == "failed"
    assert (period["score"], period["max_score"]) == (0.0, 2.0)          # its weight
    assert period["output"].startswith(
        "period 0.4967 s measured from the block's motion, expected 2 pi sqrt(m/k) = "
        "0.9935 s (m = 0.5 kg, k = 20 N/m): off by -50.0%")
    assert f"FAIL  0/2  {PERIOD}\n        period 0.4967 s measured" in done.stdout
    assert [t["status"] for t in data["tests"]][2] == "passed"     # it prints its own period


@pytest.mark.slow
def test_a_program_raising_before_its_first_frame_fails_the_tests_of_its_run(tmp_path):
    write(tmp_path, "from vpython import *\nball = sphre()\n", "mover.py")
    tests = write(tmp_path, MOVER_TESTS, "test_mover.py")
    grades = grading.grade_program(tmp_path / "mover.py", tests, sandbox=False)
    assert grades.error is None
    by_name = {t.name: t for t in grades.tests}
    line = ("the program raised NameError: name 'sphre' is not defined (line 2) before its "
            "first frame")
    assert by_name["test_speed"].message == by_name["test_reaches_two_metres"].message == line
    assert by_name["test_honour_code"].passed
    assert (grades.score, grades.max_score) == (1, 4)
    assert grades.output.startswith(line) and "Traceback" in grades.output
    check_gradescope(grading.gradescope_results(grades), 3)


@pytest.mark.slow
def test_a_program_raising_later_is_graded_on_its_run_up_to_the_error(tmp_path):
    write(tmp_path, MOVER.replace("BREAK = False", "BREAK = True"), "mover.py")
    tests = write(tmp_path, MOVER_TESTS, "test_mover.py")
    grades = grading.grade_program(tmp_path / "mover.py", tests, sandbox=False)
    assert [(t.name, t.passed) for t in grades.tests] == [
        ("test_speed", True), ("test_reaches_two_metres", False), ("test_honour_code", True)]
    assert grades.output.startswith("the program raised ValueError: the spring broke "
                                    "(line 11) at t = 0.5")
    assert "graded on its run up to then" in grades.output.splitlines()[0]


@pytest.mark.slow
def test_a_program_that_runs_out_of_time_is_graded_and_results_written(cli, tmp_path):
    write(tmp_path, "from vpython import *\nball = sphere()\nwhile True:\n    pass\n",
          "mover.py")
    tests = write(tmp_path, MOVER_TESTS, "test_mover.py")
    results = tmp_path / "results.json"
    done = cli("grade", tmp_path / "mover.py", "--tests", tests, "--results", results,
               "--timeout", "3", "--no-sandbox")
    assert done.returncode == 0, done.stderr
    data = json.loads(results.read_text())
    check_gradescope(data, 3)
    assert "stopped by --timeout 3 s" in data["output"]
    assert data["tests"][0]["output"] == data["output"]
    assert data["score"] == 1.0                               # the one that needs no run


@pytest.mark.slow
def test_test_options_are_the_markers_and_bad_tests_are_one_line(tmp_path):
    tests = write(tmp_path, MOVER_TESTS.replace("timeout=60", "timeout=60, draft=True"),
                  "test_mover.py")
    assert grading.test_options(tests) == {"fps": 10, "timeout": 60}
    bare = write(tmp_path, "def test_nothing():\n    pass\n", "test_bare.py")
    assert grading.test_options(bare) == {}
    broken = write(tmp_path, "def test_x(:\n    pass\n", "test_broken.py")
    with pytest.raises(UserError, match=r"^test_broken.py: the tests could not be collected: "
                       r"SyntaxError") as caught:
        grading.test_options(broken)
    assert "\n" not in str(caught.value)
    heavy = write(tmp_path, "import pytest\n\n@pytest.mark.weight('a lot')\n"
                  "def test_x():\n    pass\n", "test_heavy.py")
    with pytest.raises(UserError, match=r"test_heavy.py::test_x: weight\('a lot'\): the "
                       "points must be a number of 0 or more"):
        grading.test_options(heavy)
    mixed = write(tmp_path, """
        import pytest

        @pytest.mark.vpython_program("a.py", fps=10)
        def test_a(vpython_run):
            pass

        @pytest.mark.vpython_program("a.py", fps=20)
        def test_b(vpython_run):
            pass
    """, "test_mixed.py")
    with pytest.raises(UserError, match="ask for different runs"):
        grading.test_options(mixed)


@pytest.mark.parametrize("args, message", [
    (["{tmp}/prog.py", "--tests", "{tmp}/none.py"], "--tests {tmp}/none.py: no such file"),
    (["{tmp}/prog.py", "--tests", "{tmp}/prog.txt"],
     "--tests {tmp}/prog.txt: the tests are a pytest file (.py)"),
    (["{tmp}/none.py", "--tests", "{tmp}/tests.py"], "{tmp}/none.py: no such program file"),
    (["{tmp}/prog.py", "--tests", "{tmp}/tests.py", "--results", "{tmp}/out.txt"],
     "--results {tmp}/out.txt: unknown output format '.txt'"),
    (["{tmp}/prog.py", "--tests", "{tmp}/tests.py", "--results", "{tmp}/no/results.json"],
     "--results {tmp}/no/results.json: folder {tmp}/no does not exist"),
    (["{tmp}/prog.py", "--tests", "{tmp}/tests.py", "--fps", "ten"],
     "grade: argument --fps: invalid int value: 'ten'"),
])
def test_bad_input_is_one_line_and_exit_2(cli, tmp_path, args, message):
    write(tmp_path, MOVER, "prog.py")
    write(tmp_path, MOVER, "prog.txt")
    write(tmp_path, MOVER_TESTS, "tests.py")
    done = cli("grade", *[a.format(tmp=tmp_path) for a in args])
    assert done.returncode == 2 and done.stdout == ""
    assert done.stderr.count("\n") == 1 and "Traceback" not in done.stderr
    assert message.format(tmp=tmp_path) in done.stderr, done.stderr


# ---- in the sandbox, and on Gradescope ------------------------------------------------------

def gradescope_folders(tmp_path, program: str) -> Path:
    """Gradescope's /autograder in ``tmp_path``: the submission (``program``, a file of
    the grading example), the autograder's source (the tests), an empty results folder."""
    root = tmp_path / "autograder"
    for name in ("submission", "source", "results"):
        (root / name).mkdir(parents=True)
    shutil.copy(GRADING / program, root / "submission" / "lab.py")
    shutil.copy(LAB_TESTS, root / "source")
    return root


needs_sandbox = pytest.mark.skipif(no_sandbox() is not None,
                                   reason=f"no sandbox here: {no_sandbox()}")


@needs_sandbox
@pytest.mark.slow
def test_run_autograder_grades_a_submission_as_gradescope_runs_it(tmp_path):
    root = gradescope_folders(tmp_path, "spring_lab_wrong.py")
    script = (GRADING / "run_autograder").read_text()
    assert len(script.splitlines()) == 3
    local = tmp_path / "run_autograder"
    local.write_text(script.replace("/autograder/", f"{root}/"))
    env = {**os.environ, "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}"}
    done = subprocess.run(["sh", str(local)], cwd=root, env=env, capture_output=True,
                          text=True, timeout=600)
    assert done.returncode == 0, done.stderr
    data = json.loads((root / "results" / "results.json").read_text())
    check_gradescope(data, 4)
    assert (data["score"], data["tests"][0]["status"]) == (1.0, "failed")
    assert "lab.py: 1 of 4 tests passed, 1/5 points" in done.stdout


@needs_sandbox
@pytest.mark.slow
def test_a_sandboxed_program_cannot_read_the_tests(tmp_path, monkeypatch):
    root = gradescope_folders(tmp_path, "spring_lab.py")
    tests = root / "source" / "test_spring_lab.py"
    program = root / "submission" / "lab.py"
    program.write_text(f"leak = open({str(tests)!r}).read()\n" + program.read_text())
    monkeypatch.chdir(root)                        # (a program named from here)
    grades = grading.grade_program(Path("submission/lab.py"), tests)
    assert grades.output.startswith("the program raised FileNotFoundError: [Errno 2] No such "
                                    f"file or directory: '{tests}' (line 1) before its first "
                                    "frame"), grades.output
    assert grades.score == 0 and len(grades.tests) == 4
    # beside the tests, it reads its own file alone
    beside = root / "source" / "lab.py"
    beside.write_text(program.read_text())
    assert grading.program_sandbox(beside, tests).readable == (str(beside),)
    assert grading.program_sandbox(program, tests).readable == (str(root / "submission"),)
