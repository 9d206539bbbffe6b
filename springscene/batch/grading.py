"""Grades: an instructor's pytest tests run on a VPython program's recorded run.

The instructor writes ordinary pytest against springscene's testing API (the ``run``
fixture built on ``vpython_run``, asserts with messages; ``examples/grading``)::

    pytestmark = pytest.mark.vpython_program("spring_lab.py", fps=100, timeout=120)

    @pytest.mark.weight(2)
    def test_period(run): ...

- :func:`test_options`: the run the tests ask for (the marker's options), read by
  collecting them.
- :func:`grade`: the tests run on a run already recorded (``springscene vpython --out
  run.jsonl``), each test's outcome, message and points; no program runs.
- :func:`grade_program`: one program run as data (supervised, sandboxed by default,
  nothing drawn), then graded: ``springscene grade``.
- :func:`gradescope_results` and :func:`table`: the grades as Gradescope's
  ``results.json`` and as lines to read.

The tests run in a pytest of their own (``python -m pytest TESTS --springscene-run
RECORDING -p springscene.batch.grade_report``): a fresh import of the tests each time,
nothing of them in this process. A program that raised after its first frame is graded
on its run up to the error (``run.ended == "error"``, ``run.error`` say so); one that
left no recording (raised before its first frame, stopped by ``timeout`` or
``max_memory``) fails every test that asks for its run with the reason, and the tests
that do not ask for it run as usual.
"""

from __future__ import annotations

import importlib.util
import json
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass, field
from importlib import metadata
from pathlib import Path

from ..errors import ProgramError, UserError
from ..outputs import atomic_path, check_output
from ..vpython.run.options import DEFAULT_FPS, RunOptions
from ..vpython.run.runner import ProgramRaised
from ..vpython.run.sandbox import Sandbox, own_folder, unavailable as no_sandbox
from ..vpython.run.supervise import RunEnded, run_supervised

RUN_OPTIONS = ("duration", "frames", "fps", "timeout", "max_memory")
# the marker's options that only change what is drawn: a graded run draws nothing
DRAWING_OPTIONS = ("backend", "draft", "canvas_only", "page", "overlays", "quality", "lod",
                   "supervised", "record")
TESTS_TIMEOUT = 600.0            # s of wall clock the instructor's tests may take
_ROOT = str(Path(__file__).resolve().parents[2])      # where springscene is
_PLUGIN = "springscene.pytest_plugin"


@dataclass
class TestOutcome:
    """One test's grade: ``message`` is what a failed (or skipped) test said, the
    assertion's own first lines."""

    __test__ = False             # (not a test class, in a test module that imports it)

    name: str
    passed: bool
    message: str = ""
    score: float = 0.0
    max_score: float = 1.0


@dataclass
class Grades:
    """A program's grades: its tests' outcomes and the points they sum to. ``error`` is
    the one line saying why the tests could not run (then ``tests`` is empty);
    ``output`` what the run said (how the program ended, its traceback), ``seconds`` the
    wall clock of the run and the tests."""

    tests: list[TestOutcome] = field(default_factory=list)
    score: float = 0.0
    max_score: float = 0.0
    error: str | None = None
    program: str = ""
    output: str = ""
    seconds: float = 0.0

    @classmethod
    def of(cls, tests: list[TestOutcome], **fields) -> Grades:
        return cls(tests, sum(t.score for t in tests), sum(t.max_score for t in tests),
                   **fields)

    @property
    def passed(self) -> int:
        return sum(t.passed for t in self.tests)


# ---- the tests: their options, and their run on a recording ---------------------------------

def test_options(tests: Path) -> dict:
    """The run options the tests ask for through their ``vpython_program`` marker
    (``fps``, ``duration``, ``frames``, ``timeout``, ``max_memory``; what changes only
    the drawing is left out), without the program; {} when no marker names any. A tests
    file that cannot be collected is a one-line :class:`UserError` naming it."""
    tests = _check_tests(tests)
    with tempfile.TemporaryDirectory(prefix="springscene-grade-") as folder:
        found = _collected(tests, _pytest(tests, Path(folder), ["--collect-only"]))
    asked = {json.dumps(t["options"], sort_keys=True, default=repr) for t in found["tests"]}
    if len(asked) > 1:
        raise UserError(f"{tests}: its tests' vpython_program markers ask for different "
                        "runs; springscene grade makes one run a program (mark the module)")
    options = found["tests"][0]["options"] if found["tests"] else {}
    unknown = sorted(set(options) - set(RUN_OPTIONS) - set(DRAWING_OPTIONS))
    if unknown:
        raise UserError(f"{tests}: the vpython_program marker's {', '.join(unknown)}: not "
                        f"an option of a run (use {', '.join(RUN_OPTIONS)})")
    return {key: value for key, value in options.items() if key in RUN_OPTIONS}


def grade(recording: Path | None, tests: Path, program: Path | None = None, *,
          failure: str | None = None) -> Grades:
    """The tests in ``tests`` run on the run recorded in ``recording`` (``.jsonl`` or
    ``.jsonl.gz``; docs/recording.md): ``vpython_run()`` gives that run wherever the tests
    ask for their program's. ``program`` is the submission (given to the tests as
    ``--springscene-program``). With no recording, ``failure`` is why: every test that
    asks for the run fails with it. Tests that could not run give ``Grades.error``."""
    tests = _check_tests(tests)
    if recording is None:
        if not failure:
            raise ValueError("grade: no recording and no failure saying why")
        args = ["--springscene-run-failed", failure]
    else:
        args = ["--springscene-run", str(Path(recording).resolve())]
    if program is not None:
        args += ["--springscene-program", str(Path(program).resolve())]
    name = Path(program).name if program is not None else ""
    with tempfile.TemporaryDirectory(prefix="springscene-grade-") as folder:
        try:
            found = _collected(tests, _pytest(tests, Path(folder), args))
        except UserError as exc:
            return Grades(error=str(exc), program=name)
    outcomes = [_outcome(t) for t in found["tests"] if t.get("outcome") in ("passed", "failed")]
    return Grades.of(outcomes, program=name)


def _outcome(test: dict) -> TestOutcome:
    passed = test["outcome"] == "passed"
    weight = float(test["weight"])
    return TestOutcome(test["name"], passed, "" if passed else test.get("message", ""),
                       weight if passed else 0.0, weight)


def _check_tests(tests) -> Path:
    path = Path(tests)
    if not path.is_file():
        raise UserError(f"--tests {tests}: no such file")
    if path.suffix != ".py":
        raise UserError(f"--tests {tests}: the tests are a pytest file (.py)")
    if importlib.util.find_spec("pytest") is None:
        raise UserError("springscene grade runs the tests with pytest, which is not "
                        "installed (pip install pytest)")
    return path.resolve()


def _pytest(tests: Path, folder: Path, args: list[str]) -> tuple[dict | None, str]:
    """pytest in a process of its own on ``tests``, from their folder: what the
    outcomes plugin wrote (None if nothing) and the last line pytest said."""
    outcomes = folder / "outcomes.json"
    command = [sys.executable, "-m", "pytest", str(tests), "-q", "--no-header",
               "-p", "no:cacheprovider", "-p", "springscene.batch.grade_report",
               "--springscene-outcomes", str(outcomes), *_plugin_args(), *args]
    env = {**os.environ, "PYTHONPATH": os.pathsep.join(
        [p for p in (os.environ.get("PYTHONPATH"), _ROOT) if p])}
    try:
        done = subprocess.run(command, cwd=tests.parent, env=env, capture_output=True,
                              text=True, timeout=TESTS_TIMEOUT, stdin=subprocess.DEVNULL)
    except subprocess.TimeoutExpired:
        raise UserError(f"{tests.name}: the tests took more than {TESTS_TIMEOUT:g} s") from None
    said = [line for line in (done.stdout + done.stderr).splitlines() if line.strip()]
    found = json.loads(outcomes.read_text()) if outcomes.is_file() else None
    return found, (said[-1].strip() if said else f"pytest ended with status {done.returncode}")


def _collected(tests: Path, ran: tuple[dict | None, str]) -> dict:
    """The outcomes of a pytest run on ``tests``; a file that could not be collected, or
    that holds no test, is a one-line :class:`UserError` naming it."""
    found, last = ran
    if found is None:
        raise UserError(f"{tests.name}: the tests could not run: {last}")
    if found["errors"]:
        error = found["errors"][0].removeprefix(f"{tests.name}: ")
        raise UserError(f"{tests.name}: the tests could not be collected: {error}")
    if not found["tests"]:
        raise UserError(f"{tests.name}: no tests in it (pytest collects test_* functions)")
    return found


def _plugin_args() -> list[str]:
    """springscene's pytest plugin named where pytest would not load it by itself (an
    uninstalled checkout, or plugin autoloading turned off); installed, pytest loads it
    by its entry point, and naming it again would load it twice."""
    installed = any(ep.value == _PLUGIN for ep in metadata.entry_points(group="pytest11"))
    if installed and not os.environ.get("PYTEST_DISABLE_PLUGIN_AUTOLOAD"):
        return []
    return ["-p", _PLUGIN]


# ---- one program: run as data, then graded ---------------------------------------------------

def grade_program(program: Path, tests: Path, *, sandbox: bool = True,
                  **overrides) -> Grades:
    """``program`` run as data (supervised, nothing drawn; in a sandbox that lets it read
    its own folder alone, unless ``sandbox=False``) with the options the tests ask for
    (``overrides``: ``timeout``, ``max_memory``, ``duration``, ``fps``, ``frames``, None
    for the tests'), then graded by :func:`grade`."""
    start = time.perf_counter()
    program = Path(program)
    if not program.is_file():
        raise UserError(f"{program}: no such program file")
    options = {**test_options(tests), **{k: v for k, v in overrides.items() if v is not None}}
    box = program_sandbox(program, Path(tests)) if sandbox else None
    with tempfile.TemporaryDirectory(prefix="springscene-grade-") as folder:
        recording, failure, said = record(program, Path(folder) / "run.jsonl", options, box)
        grades = grade(recording, tests, program, failure=failure)
    grades.output = said
    grades.seconds = time.perf_counter() - start
    return grades


def program_sandbox(program: Path, tests: Path) -> Sandbox:
    """The sandbox a graded program runs in: it reads its own folder (its file alone
    where that folder holds the tests, or is a home folder) and nothing else of the
    machine's files; where none can be made, a one-line :class:`UserError`."""
    why = no_sandbox()
    if why is not None:
        raise UserError(f"no sandbox for the program here: {why} (--no-sandbox runs it "
                        "without one)")
    readable = own_folder(program)
    if any(Path(tests).resolve().is_relative_to(path) for path in readable):
        readable = (str(program.resolve()),)
    return Sandbox(readable=readable)


def record(program: Path, out: Path, options: dict, sandbox: Sandbox | None = None
           ) -> tuple[Path | None, str | None, str]:
    """``program`` run to the recording ``out`` alone: (the recording, None, how the run
    ended). A program that raised after its first frame gives its recording up to the
    error; one that left none gives (None, why in one line, what it said)."""
    run_options = RunOptions(duration=options.get("duration"), frames=options.get("frames"),
                             fps=options.get("fps", DEFAULT_FPS), page=False)
    try:                          # (absolute: the sandbox's working folder is not ours)
        result = run_supervised(program.resolve(), out, run_options,
                                timeout=options.get("timeout"),
                                max_memory=options.get("max_memory"), sandbox=sandbox)
    except ProgramRaised as exc:
        line = _raised_line(exc)
        if exc.result is None:
            return None, line, f"{line}\n\n{exc.traceback}"
        return exc.result.path, None, (f"{line}; graded on its run up to then\n\n"
                                       f"{exc.traceback}")
    except ProgramError as exc:                  # (its source could not be compiled)
        text = str(exc).strip()
        line = f"the program could not run: {text.splitlines()[-1] if text else 'an error'}"
        return None, line, f"{line}\n\n{text}"
    except RunEnded as exc:                      # timeout, memory, sys.exit, a crash
        line = str(exc).removeprefix("springscene: ")
        return None, line, line
    return out, None, (f"{program.name}: {result.frames} frames, {result.program_seconds:.2f} "
                       f"s of program time, ended by {result.ended}")


def _raised_line(exc: ProgramRaised) -> str:
    """``the program raised ZeroDivisionError: division by zero (line 12) at t = 1.20 s``."""
    error = exc.error or {}
    where = f" (line {error['line']})" if error.get("line") else ""
    when = (f" at t = {exc.result.program_seconds:.2f} s" if exc.result is not None
            else " before its first frame")
    message = f": {error['message']}" if error.get("message") else ""
    return f"the program raised {error.get('type', 'an error')}{message}{where}{when}"


# ---- the grades as Gradescope's results.json and as a table ----------------------------------

def gradescope_results(grades: Grades) -> dict:
    """The grades in the format of Gradescope's autograder ``results.json``
    (gradescope-autograders.readthedocs.io, "Autograder Specifications"): the score, each
    test's name, score, max_score, status and output, the output about the whole run."""
    output = grades.output
    if grades.error is not None:
        output = f"The tests could not run: {grades.error}" + (f"\n\n{output}" if output else "")
    return {
        "score": grades.score,
        "execution_time": round(grades.seconds),
        "output": output,
        "visibility": "visible",
        "stdout_visibility": "hidden",
        "tests": [{"name": t.name, "score": t.score, "max_score": t.max_score,
                   "status": "passed" if t.passed else "failed", "output": t.message,
                   "visibility": "visible"} for t in grades.tests],
    }


def write_results(grades: Grades, path: Path) -> Path:
    """:func:`gradescope_results` written to ``path`` (``.json``), whole or not at all."""
    path = check_output(path, (".json",), "--results")
    with atomic_path(path) as tmp:
        tmp.write_text(json.dumps(gradescope_results(grades), indent=2) + "\n")
    return path


def table(grades: Grades) -> str:
    """The grades as lines to read: a head line, then a line a test (a failed test's
    message indented under it)."""
    head = grades.program or "the program"
    if grades.error is not None:
        return f"{head}: the tests could not run: {grades.error}"
    lines = [f"{head}: {grades.passed} of {len(grades.tests)} tests passed, "
             f"{_points(grades.score)}/{_points(grades.max_score)} points"]
    for t in grades.tests:
        lines.append(f"  {'pass' if t.passed else 'FAIL'}  "
                     f"{_points(t.score)}/{_points(t.max_score)}  {t.name}")
        lines += [f"        {line}" for line in t.message.splitlines()]
    return "\n".join(lines)


def _points(value: float) -> str:
    return f"{value:g}"
