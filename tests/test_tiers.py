"""The two tiers of tests (tests/conftest.py): the rules that mark a test slow, the guard
that keeps a new Python out of the fast tier, and the ``cli`` fixture that runs the
command line in this process as a new process would run it."""

from __future__ import annotations

import ast
import logging
import os
import signal
import subprocess
import sys
import types
import warnings
from pathlib import Path

import imageio_ffmpeg
import matplotlib
import pytest

import conftest
from conftest import ROOT, run_cli
from springscene.app import cli as command

VENV_BIN = Path(sys.prefix) / "bin"


# ---- the guard -------------------------------------------------------------------------------

@pytest.mark.parametrize("program", ["python3", "springscene", "pip"])
def test_the_guard_refuses_a_new_python_in_the_fast_tier(request, program):
    """The interpreter, the command (its console script) and a #!python script alike."""
    assert request.node.get_closest_marker("slow") is None
    with pytest.raises(pytest.fail.Exception, match=r"is in the fast tier \(not marked slow\) "
                       r"but starts a new Python .*: mark it slow .* or run it in-process"):
        subprocess.run([str(VENV_BIN / program), "--version"], capture_output=True)


def test_the_guard_refuses_a_fork_in_the_fast_tier():
    with pytest.raises(pytest.fail.Exception, match="but forks the test process: mark it slow"):
        os.fork()


def test_the_guard_lets_other_programs_through():
    """ffmpeg (springscene's videos), mount and the like stay in the fast tier."""
    proc = subprocess.run([imageio_ffmpeg.get_ffmpeg_exe(), "-version"], capture_output=True)
    assert proc.returncode == 0 and proc.stdout.startswith(b"ffmpeg version")
    assert subprocess.run(["true"]).returncode == 0


@pytest.mark.slow
def test_a_slow_test_may_start_a_python():
    proc = subprocess.run([str(VENV_BIN / "python3"), "-c", "print(6 * 7)"],
                          capture_output=True, text=True)
    assert proc.stdout == "42\n"


# ---- the rules -------------------------------------------------------------------------------

def _runs_the_command():
    return run_cli("--version")


def _through_a_helper():
    return _runs_the_command()


def _in_a_nested_function():
    def inner():
        return subprocess.run([sys.executable, "-c", "pass"])
    return inner


def _none():
    return subprocess.run(["true"])


def _item(function, fixtures=()):
    """What the rules read of a collected test: its function and its fixtures'."""
    defs = {f.__name__: [types.SimpleNamespace(func=f)] for f in fixtures}
    return types.SimpleNamespace(function=function,
                                 _fixtureinfo=types.SimpleNamespace(name2fixturedefs=defs))


@pytest.mark.parametrize("item, starts", [
    (_item(_runs_the_command), True),
    (_item(_through_a_helper), True),
    (_item(_in_a_nested_function), True),
    (_item(_none), False),
    (_item(_none, fixtures=[_through_a_helper]), True),
    (_item(_none, fixtures=[_none]), False),
], ids=["run_cli", "a helper", "nested", "neither", "a fixture", "a plain fixture"])
def test_rule_two_reads_the_tests_code_its_fixtures_and_their_helpers(item, starts):
    assert conftest._starts_python(item) is starts


def test_every_long_test_names_a_test_function_of_its_file():
    tests = {}
    for entry, seconds in conftest.LONG_TESTS.items():
        path, name = entry.split("::")
        if path not in tests:
            tree = ast.parse((ROOT / path).read_text())
            tests[path] = {n.name for n in tree.body if isinstance(n, ast.FunctionDef)}
        assert name.startswith("test_") and name in tests[path], entry
        assert seconds > 0


def _test(path: str, name: str, function=_none):
    return types.SimpleNamespace(path=ROOT / path, originalname=name, name=name,
                                 function=function, _fixtureinfo=None)


@pytest.mark.parametrize("item, slow", [
    (_test("tests/reliability/test_command.py", "test_x"), True),
    (_test("tests/test_clean_install.py", "test_x"), True),
    (_test("tests/app/test_install.py", "test_x"), True),
    (_test("tests/app/test_readme.py", "test_x"), True),
    (_test(*next(iter(conftest.LONG_TESTS)).split("::")), True),
    (_test("tests/app/test_bad_input.py", "test_x", _runs_the_command), True),
    (_test("tests/app/test_bad_input.py", "test_x"), False),
    (_test("tests/app/test_readme_other.py", "test_x"), False),
], ids=["reliability", "clean install", "install", "readme", "long", "run_cli", "fast",
        "a name like a place"])
def test_the_rules_mark_what_they_say(item, slow):
    assert conftest._slow_by_rule(item) is slow


def test_this_file_is_in_the_tiers_its_marks_say(request):
    assert request.node.get_closest_marker("slow") is None
    here = {item.originalname: item.get_closest_marker("slow") is not None
            for item in request.session.items if item.path == request.node.path}
    assert here.get("test_a_slow_test_may_start_a_python", True)
    assert here["test_the_guard_lets_other_programs_through"] is False


def test_a_fast_test_that_ran_long_is_named_at_the_end(monkeypatch):
    monkeypatch.setattr(conftest, "_long_fast_tests", [])
    over = conftest.FAST_LIMIT_S + 1
    for nodeid, keywords, when in (("tests/x.py::test_fast", {}, "call"),
                                   ("tests/x.py::test_slow", {"slow": 1}, "call"),
                                   ("tests/x.py::test_setup", {}, "setup")):
        conftest.pytest_runtest_logreport(types.SimpleNamespace(
            when=when, passed=True, keywords=keywords, duration=over, nodeid=nodeid))
    lines = []
    conftest.pytest_terminal_summary(types.SimpleNamespace(section=lines.append,
                                                           line=lines.append))
    assert lines[0] == "tiers: fast tests that ran long" and len(lines) == 2
    assert lines[1].startswith(f"{over:.1f} s  tests/x.py::test_fast: in the fast tier")


# ---- the cli fixture: as a new process --------------------------------------------------------

def test_cli_gives_what_a_new_process_gives(cli):
    """A failing command: its exit status, its one line, nothing written; relative names
    are read from the checkout, as run_cli's processes read them."""
    proc = cli("simulate", "missing.toml", "--out", "t.csv")
    assert isinstance(proc, subprocess.CompletedProcess)
    assert (proc.returncode, proc.stdout) == (2, "")
    assert proc.stderr == "springscene: error: missing.toml: no such config file\n"
    assert not (ROOT / "t.csv").exists()


def test_cli_shows_what_python_would_print(cli, monkeypatch):
    def run(args):
        print("out")
        os.write(2, b"from C\n")
        warnings.warn("careful", UserWarning)
        warnings.warn("old", DeprecationWarning)              # hidden, as Python hides it
        logging.getLogger("somelib").warning("somelib says")
        logging.getLogger("somelib").info("not this")
        return 3

    monkeypatch.setattr(command, "_run", run)
    proc = cli("info")
    assert proc.returncode == 3 and proc.stdout == "out\n"
    lines = proc.stderr.splitlines()
    assert "from C" in lines and "somelib says" in lines
    assert any(line.endswith("UserWarning: careful") for line in lines)
    assert "old" not in proc.stderr and "not this" not in proc.stderr


def test_cli_exits_as_argparse_and_python_do(cli, monkeypatch):
    version = cli("--version")
    assert version.returncode == 0 and version.stdout.startswith("springscene ")
    usage = cli("bogus")
    assert usage.returncode == 2 and usage.stderr.startswith("springscene: error: ")
    with pytest.raises(AssertionError, match="springscene bogus failed:"):
        cli("bogus", check=True)

    def leave(args):
        sys.exit("a message")

    monkeypatch.setattr(command, "_run", leave)
    proc = cli("info")
    assert proc.returncode == 1 and proc.stderr == "a message\n"


def test_cli_leaves_this_process_as_it_was(cli, monkeypatch, tmp_path):
    """What a command changes dies with its process: here it is put back."""
    monkeypatch.chdir(tmp_path)
    seen = {}

    def run(args):
        seen["folder"] = os.getcwd()
        os.chdir("/")
        os.environ["SPRINGSCENE_TIERS_TEST"] = "1"
        signal.signal(signal.SIGTERM, signal.SIG_IGN)
        matplotlib.rcParams["lines.linewidth"] = 42
        logging.disable(logging.WARNING)
        return 0

    monkeypatch.setattr(command, "_run", run)
    handler, width = signal.getsignal(signal.SIGTERM), matplotlib.rcParams["lines.linewidth"]
    disabled = logging.root.manager.disable
    assert cli("info").returncode == 0
    assert seen["folder"] == str(ROOT)                  # run_cli's processes run there too
    assert os.getcwd() == str(tmp_path)
    assert "SPRINGSCENE_TIERS_TEST" not in os.environ
    assert signal.getsignal(signal.SIGTERM) is handler
    assert matplotlib.rcParams["lines.linewidth"] == width
    assert logging.root.manager.disable == disabled
