"""The installed ``springscene`` command: a standard Python console script.

It is pip's script for the entry point ``springscene = springscene.app.signals:main``, so
``python -m springscene.app``, pdb and cProfile run the same code. These tests run the
command of the Python running them (``Path(sys.executable).parent / "springscene"``):
``make setup``'s editable install, or the real install of ``.ci/run``'s legs.
"""

from __future__ import annotations

import importlib.metadata
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import WIKI, default_stop_signals
from springscene.app import signals

BIN = Path(sys.executable).parent
COMMAND = BIN / "springscene"
STOPS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
MASK = sum(1 << (s - 1) for s in STOPS)

installed = pytest.mark.skipif(not COMMAND.exists(), reason="springscene is not installed here")


def _start(*args, command=(str(COMMAND),), preexec_fn=default_stop_signals) -> subprocess.Popen:
    return subprocess.Popen([*command, *map(str, args)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, preexec_fn=preexec_fn)


def _still(out: Path, **kw) -> subprocess.Popen:
    return _start("still", WIKI, "--draft", "--out", out / "x.png", **kw)


def _mask(pid: int, field: str) -> int | None:
    """A signal mask of /proc/PID/status (``SigBlk``, ``SigCgt``), or None once gone."""
    try:
        status = Path(f"/proc/{pid}/status").read_text()
    except (FileNotFoundError, ProcessLookupError):
        return None
    return next(int(line.split()[1], 16) for line in status.splitlines()
                if line.startswith(f"{field}:"))


def _wait_for_handlers(proc: subprocess.Popen) -> None:
    """Until the process catches SIGTERM: springscene's handlers are in."""
    deadline = time.monotonic() + 60
    while (_mask(proc.pid, "SigCgt") or 0) & (1 << (signal.SIGTERM - 1)) == 0:
        assert proc.poll() is None and time.monotonic() < deadline, proc.communicate()
        time.sleep(0.002)


def _outcome(proc: subprocess.Popen, out: Path) -> tuple[int, list[str], list[str]]:
    _, err = proc.communicate(timeout=120)
    return proc.returncode, err.strip().splitlines(), sorted(p.name for p in out.iterdir())


# ---- what is installed --------------------------------------------------------------------

def test_the_command_is_the_packages_one_console_script():
    """One console script, ``springscene``, for :func:`springscene.app.signals.main`; no
    other command of springscene's beside it."""
    dist = importlib.metadata.distribution("springscene")
    scripts = {ep.name: ep.value for ep in dist.entry_points
               if ep.group == "console_scripts"}
    assert scripts == {"springscene": "springscene.app.signals:main"}
    assert [ep.load() for ep in importlib.metadata.entry_points(
        group="console_scripts", name="springscene")] == [signals.main]


@installed
def test_the_installed_command_is_pips_script_for_the_entry_point():
    assert "from springscene.app.signals import main" in COMMAND.read_text()
    assert sorted(p.name for p in BIN.glob("*springscene*")) == ["springscene"]


# ---- one way in, several ways to run it ---------------------------------------------------

@pytest.mark.parametrize("how", ["command", "python -m springscene.app",
                                 "cProfile on the command", "cProfile -m springscene.app",
                                 "pdb on the command"])
def test_every_way_of_running_it_is_the_same_command(tmp_path, how):
    """The console script is a Python file, so a profiler or a debugger can run it."""
    if how.endswith("on the command") or how == "command":
        if not COMMAND.exists():
            pytest.skip("springscene is not installed here")
    py = sys.executable
    args, stdin = {
        "command": ([str(COMMAND)], None),
        "python -m springscene.app": ([py, "-m", "springscene.app"], None),
        "cProfile on the command": ([py, "-m", "cProfile", "-o", tmp_path / "p", COMMAND],
                                    None),
        "cProfile -m springscene.app": ([py, "-m", "cProfile", "-o", tmp_path / "p", "-m",
                                         "springscene.app"], None),
        "pdb on the command": ([py, "-m", "pdb", COMMAND], "continue\n"),
    }[how]
    proc = subprocess.run([*map(str, args), "--version"], input=stdin, capture_output=True,
                          text=True, timeout=120, cwd=tmp_path)
    assert (proc.returncode, proc.stderr) == (0, ""), proc.stderr
    assert "springscene 0.1.0" in proc.stdout
    if "cProfile" in how:
        assert (tmp_path / "p").stat().st_size > 0
    bad = subprocess.run([*map(str, args), "still", "missing.toml", "--out", "x.png"],
                         input=stdin, capture_output=True, text=True, timeout=120,
                         cwd=tmp_path)
    if how.startswith("pdb"):                 # pdb and cProfile keep the program's exit
        assert "Exit status: 2" in bad.stdout, bad.stdout     # status to themselves
    elif "cProfile" not in how:
        assert bad.returncode == 2, bad.stderr
    assert bad.stderr.splitlines() == [
        "springscene: error: missing.toml: no such config file"], bad.stderr


# ---- stop signals -------------------------------------------------------------------------

@installed
@pytest.mark.parametrize("signum", STOPS, ids=[s.name for s in STOPS])
def test_a_signal_to_the_installed_command_is_one_line_and_leaves_nothing(tmp_path, signum):
    """Sent once its handlers are in (numpy, the command line and VTK loading, the scene
    being drawn): one line, 128 + n, no file."""
    for delay in (0.0, 0.4):
        out = tmp_path / str(delay)
        out.mkdir()
        proc = _still(out)
        _wait_for_handlers(proc)
        time.sleep(delay)
        proc.send_signal(signum)
        assert _outcome(proc, out) == (
            128 + signum, [f"springscene: interrupted ({signum.name})"], [])


def test_python_m_springscene_app_handles_signals_alike(tmp_path):
    proc = _still(tmp_path, command=(sys.executable, "-m", "springscene.app"))
    _wait_for_handlers(proc)
    proc.send_signal(signal.SIGTERM)
    assert _outcome(proc, tmp_path) == (143, ["springscene: interrupted (SIGTERM)"], [])


@installed
def test_a_signal_at_any_moment_of_start_up_ends_it_or_is_handled(tmp_path):
    """From the exec on. Before the handlers are in, Python's defaults: the signal ends the
    process, nothing written; a SIGINT may print Python's KeyboardInterrupt traceback (exit
    1 when it stops ``import site``), or, raised in one of importlib's callbacks, be only
    reported (``Exception ignored``) while the run goes on to its end, its output whole.
    Once they are in, the one line and 128 + n. Never a partial output."""
    handled = 0
    for i in range(30):
        signum = STOPS[i % 3]
        out = tmp_path / str(i)
        out.mkdir()
        proc = _still(out)
        time.sleep(0.3 * (i / 29) ** 2)     # 0 to 0.3 s, dense at first: start-up and after
        proc.send_signal(signum)
        status, err, left = _outcome(proc, out)
        if status == 128 + signum:
            assert (err, left) == ([f"springscene: interrupted ({signum.name})"], []), i
            handled += 1
            continue
        assert signum == signal.SIGINT or (status, err) == (-signum, []), (i, status, err)
        if status == 0:                             # lost by Python, not by springscene
            assert err[0].startswith("Exception ignored") and left == ["x.png"], (i, err)
        else:
            assert status in (-signum, 1) and left == [], (i, status, err, left)
        assert not err or err[-1].startswith("KeyboardInterrupt"), (i, err)
    assert handled                                  # the last moments are well past start-up


@installed
def test_the_running_command_is_named_springscene_and_keeps_the_callers_blocked_signals(
        tmp_path):
    """``pgrep -x springscene`` finds it; a signal the caller blocked stays blocked: a
    SIGHUP sent meanwhile changes nothing, the run ends with its video."""
    def hup_blocked() -> None:
        default_stop_signals()
        signal.pthread_sigmask(signal.SIG_BLOCK, [signal.SIGHUP])

    proc = _start("render", WIKI, "--draft", "--duration", "1", "--out", tmp_path / "x.gif",
                  preexec_fn=hup_blocked)
    _wait_for_handlers(proc)
    assert Path(f"/proc/{proc.pid}/comm").read_text() == "springscene\n"
    assert _mask(proc.pid, "SigBlk") & MASK == 1 << (signal.SIGHUP - 1)
    proc.send_signal(signal.SIGHUP)
    assert _outcome(proc, tmp_path) == (0, [], ["x.gif"])
