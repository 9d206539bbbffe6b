"""Signals from the first instant (issue 16): the installed ``springscene`` command.

The command is a POSIX sh launcher (``app/springscene``) that starts the Python entry
installed beside it (``_springscene``) with SIGINT, SIGTERM and SIGHUP blocked, so one
that comes while the interpreter starts (where Python would print a ``KeyboardInterrupt``
traceback, or fail to import ``site`` and exit 1) is held until springscene's handlers are
in. These tests run the command of the Python running them: ``make test``'s editable
install, or the real install of ``.ci/run``'s legs.
"""

from __future__ import annotations

import os
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import WIKI
from springscene.app import signals

BIN = Path(sys.executable).parent
COMMAND = BIN / "springscene"
STOPS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
MASK = sum(1 << (s - 1) for s in STOPS)


def _default_signals() -> None:
    """The stop signals at their defaults and unblocked in the child, whatever this test
    inherited (a shell's background job ignores SIGINT)."""
    for signum in signals.SIGNALS:
        signal.signal(signum, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, signals.SIGNALS)


def _start(*args, env=None) -> subprocess.Popen:
    return subprocess.Popen([str(COMMAND), *map(str, args)], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, env=env,
                            preexec_fn=_default_signals)


def _still(tmp_path: Path, env=None) -> subprocess.Popen:
    return _start("still", WIKI, "--draft", "--out", tmp_path / "x.png", env=env)


def _mask(pid: int, field: str) -> int | None:
    """A signal mask of /proc/PID/status (``SigBlk``, ``SigCgt``), or None once gone."""
    try:
        status = Path(f"/proc/{pid}/status").read_text()
    except (FileNotFoundError, ProcessLookupError):
        return None
    return next(int(line.split()[1], 16) for line in status.splitlines()
                if line.startswith(f"{field}:"))


def _is_entry(pid: int) -> bool:
    """Whether the process is the Python entry yet (not the launcher's shell or env)."""
    try:
        return b"_springscene" in Path(f"/proc/{pid}/cmdline").read_bytes()
    except (FileNotFoundError, ProcessLookupError):
        return False


def _outcome(proc: subprocess.Popen, tmp_path: Path) -> tuple[int, list[str], list[str]]:
    _, err = proc.communicate(timeout=120)
    return proc.returncode, err.strip().splitlines(), sorted(p.name for p in tmp_path.iterdir())


@pytest.mark.skipif(not COMMAND.exists(), reason="springscene is not installed here")
@pytest.mark.parametrize("signum", STOPS, ids=[s.name for s in STOPS])
def test_a_signal_held_through_the_interpreters_start_up_is_handled(tmp_path, signum):
    """Caught while the entry's interpreter starts, signals still blocked and springscene's
    handlers not in yet: held, then handled as during the run (one line, 128 + n)."""
    for _ in range(20):
        proc = _still(tmp_path)
        held = False
        while proc.poll() is None:
            blocked, caught = _mask(proc.pid, "SigBlk"), _mask(proc.pid, "SigCgt")
            if blocked is None or caught & (1 << (signal.SIGTERM - 1)):
                break                                  # too late: the handlers are in
            if blocked & MASK == MASK and _is_entry(proc.pid):
                proc.send_signal(signum)
                held = True
                break
        if held:
            status, err, left = _outcome(proc, tmp_path)
            assert status == 128 + signum, err
            assert err == [f"springscene: interrupted ({signum.name})"]
            assert left == []
            return
        proc.kill()
        proc.communicate()
    pytest.fail("never caught the entry starting with the stop signals blocked")


@pytest.mark.skipif(not COMMAND.exists(), reason="springscene is not installed here")
def test_a_signal_at_any_moment_of_start_up_ends_it_cleanly(tmp_path):
    """From the launcher's first instant through the interpreter's start-up: either the
    signal ends the process at once (the ~ms before ``env`` blocks it; nothing written, no
    word) or it is handled (one line); never a traceback, exit 0 or 1, or a file left."""
    handled = 0
    for i in range(24):
        signum = STOPS[i % 3]
        out = tmp_path / str(i)
        out.mkdir()
        proc = _still(out)
        time.sleep(i * 0.002)
        proc.send_signal(signum)
        status, err, left = _outcome(proc, out)
        assert left == [], (i, status, err)
        if status == -signum:
            assert err == [], (i, err)
        else:
            assert (status, err) == (128 + signum, [f"springscene: interrupted ({signum.name})"])
            handled += 1
    assert handled >= 12                     # most moments are past the launcher's first ms


@pytest.mark.skipif(not COMMAND.exists(), reason="springscene is not installed here")
def test_an_env_without_block_signal_still_starts_the_command(tmp_path):
    """Busybox's env, or coreutils' before 8.31: no ``--block-signal``; the command runs."""
    fake = tmp_path / "env"
    fake.write_text("#!/bin/sh\necho 'env: unrecognized option' >&2\nexit 125\n")
    fake.chmod(0o755)
    env = {**os.environ, "PATH": f"{tmp_path}:{os.environ.get('PATH', '/usr/bin:/bin')}"}
    proc = _start("--version", env=env)
    out, err = proc.communicate(timeout=120)
    assert (proc.returncode, err) == (0, "")
    assert out.startswith("springscene ")
    out = tmp_path / "out"
    out.mkdir()
    proc = _still(out, env=env)                      # signals work as they did before
    _wait_for_handlers(proc)
    proc.send_signal(signal.SIGTERM)
    assert _outcome(proc, out) == (143, ["springscene: interrupted (SIGTERM)"], [])


@pytest.mark.skipif(not COMMAND.exists(), reason="springscene is not installed here")
def test_a_link_to_the_command_finds_its_entry(tmp_path):
    link = tmp_path / "springscene"
    link.symlink_to(COMMAND)
    proc = subprocess.run([str(link), "--version"], capture_output=True, text=True,
                          timeout=120)
    assert (proc.returncode, proc.stderr) == (0, "")
    assert proc.stdout.startswith("springscene ")


@pytest.mark.skipif(not COMMAND.exists(), reason="springscene is not installed here")
def test_a_launcher_without_its_entry_says_so_in_one_line(tmp_path):
    alone = tmp_path / "springscene"
    shutil.copy(COMMAND, alone)
    proc = subprocess.run([str(alone), "--version"], capture_output=True, text=True,
                          timeout=120)
    assert proc.returncode == 127
    assert proc.stderr.splitlines() == [
        f"springscene: error: {tmp_path}/_springscene is missing: reinstall springscene "
        "(pip install springscene)"]


def _wait_for_handlers(proc: subprocess.Popen) -> None:
    deadline = time.monotonic() + 60
    while (_mask(proc.pid, "SigCgt") or 0) & (1 << (signal.SIGTERM - 1)) == 0:
        assert proc.poll() is None and time.monotonic() < deadline, proc.communicate()
        time.sleep(0.002)


@pytest.mark.skipif(not COMMAND.exists(), reason="springscene is not installed here")
def test_the_running_command_is_named_springscene_and_keeps_the_callers_blocked_signals(
        tmp_path):
    """``pgrep -x springscene`` finds it (not the entry's ``_springscene``); a signal the
    caller blocked itself stays blocked (the launcher unblocks only what it blocked): a
    SIGHUP sent meanwhile changes nothing, the run ends with its still."""
    def hup_blocked() -> None:
        _default_signals()
        signal.pthread_sigmask(signal.SIG_BLOCK, [signal.SIGHUP])

    proc = subprocess.Popen([str(COMMAND), "render", WIKI, "--draft", "--duration", "1",
                             "--out", tmp_path / "x.gif"], stdout=subprocess.PIPE,
                            stderr=subprocess.PIPE, text=True, preexec_fn=hup_blocked)
    _wait_for_handlers(proc)
    assert Path(f"/proc/{proc.pid}/comm").read_text() == "springscene\n"
    blocked = _mask(proc.pid, "SigBlk")
    assert blocked & MASK == 1 << (signal.SIGHUP - 1)
    proc.send_signal(signal.SIGHUP)
    status, err, left = _outcome(proc, tmp_path)
    assert (status, err, left) == (0, [], ["x.gif"])


@pytest.mark.skipif(not COMMAND.exists(), reason="springscene is not installed here")
@pytest.mark.parametrize("how", ["folder with =", "empty PATH entry"])
def test_the_command_runs_from_any_folder_name_and_lookup(tmp_path, how):
    """A folder name with ``=`` (``env`` would read the entry as a setting, and run the
    first argument instead); a bare name found through an empty PATH entry (``$0`` with no
    slash)."""
    if how == "folder with =":
        folder = tmp_path / "v=1"
        folder.symlink_to(BIN, target_is_directory=True)
        args, cwd, env = [str(folder / "springscene"), "--version"], tmp_path, None
    else:
        args = ["sh", "-c", "springscene --version"]
        cwd, env = BIN, {**os.environ, "PATH": ":/usr/bin:/bin"}
    proc = subprocess.run(args, cwd=cwd, env=env, capture_output=True, text=True,
                          timeout=120)
    assert (proc.returncode, proc.stderr) == (0, "")
    assert proc.stdout.startswith("springscene ")
