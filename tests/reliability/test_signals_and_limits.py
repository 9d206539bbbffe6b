"""Nothing left behind (issue 16): stop signals at any moment, figure sets replaced whole,
writes that fail, and hostile inputs (a FIFO or a device as the config, huge files,
titles and step counts).

Each command runs in a fresh process, as a user runs it; every run has a timeout so a
regression (a FIFO read that waits forever) fails instead of hanging.
"""

from __future__ import annotations

import errno
import hashlib
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import pytest

from conftest import ROOT, WIKI, run_cli, small_disk

from springscene import config
from springscene.app import oserrors, signals
from springscene.errors import UserError
from springscene.figures import files

DAMPED = ROOT / "configs" / "damped.toml"
TIMEOUT = 120
SPRINGSCENE = str(Path(sys.executable).parent / "springscene")   # the installed command


def _default_signals() -> None:
    """In the child before it starts: the stop signals at their defaults, even when this
    test runs where they are ignored (a shell's background job ignores SIGINT, and an
    ignored signal stays ignored, as POSIX asks)."""
    for signum in signals.SIGNALS:
        signal.signal(signum, signal.SIG_DFL)


def _start(*args) -> subprocess.Popen:
    """The installed command in a fresh process, as a user runs it."""
    return subprocess.Popen([SPRINGSCENE, *map(str, args)], cwd=ROOT,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=_default_signals)


def _handlers_installed(pid: int) -> bool:
    """Whether the process catches SIGTERM yet (springscene's handlers are in)."""
    try:
        status = Path(f"/proc/{pid}/status").read_text()
    except FileNotFoundError:
        return True                                    # already gone: let the asserts say
    caught = next(int(line.split()[1], 16) for line in status.splitlines()
                  if line.startswith("SigCgt:"))
    return bool(caught & (1 << (signal.SIGTERM - 1)))


def _wait_for_handlers(proc: subprocess.Popen) -> None:
    deadline = time.monotonic() + 30
    while not _handlers_installed(proc.pid):
        assert time.monotonic() < deadline, "springscene never installed its signal handlers"
        time.sleep(0.002)


def _interrupt(proc: subprocess.Popen, signum: int, delay: float) -> tuple[int, list[str]]:
    """Send ``signum`` ``delay`` s after the handlers are in; the exit status and stderr."""
    _wait_for_handlers(proc)
    time.sleep(delay)
    proc.send_signal(signum)
    _, err = proc.communicate(timeout=TIMEOUT)
    return proc.returncode, err.strip().splitlines()


# ---- signals --------------------------------------------------------------------------

# moments after the handlers are in: numpy and the command line loading (0), VTK's
# compiled modules loading (0.3, 0.6 on a quiet machine), frames being encoded (1, 2)
MOMENTS = [(signal.SIGINT, 0.0), (signal.SIGTERM, 0.3), (signal.SIGHUP, 0.6),
           (signal.SIGINT, 1.0), (signal.SIGTERM, 2.0)]


@pytest.mark.parametrize("signum, delay", MOMENTS,
                         ids=[f"{signal.Signals(s).name}-{d}s" for s, d in MOMENTS])
def test_a_signal_at_any_moment_of_a_render_stops_it_cleanly(tmp_path, signum, delay):
    proc = _start("render", WIKI, "--duration", 6, "--out", tmp_path / "x.mp4", "--draft",
                  "--quiet")
    status, err = _interrupt(proc, signum, delay)
    assert status == 128 + signum, err                 # 130, 143, 129: not -11, not 0
    assert err == [f"springscene: interrupted ({signal.Signals(signum).name})"]
    assert list(tmp_path.iterdir()) == []              # no x.mp4, no hidden .x.mp4.*


# the end of a program that must see its signal raised again while it keeps busy
BUSY_THEN_REPORT = """\
    start = time.monotonic()
    while time.monotonic() - start < 5:
        sum(range(1000))
    print("lost")
except signals.Interrupted as exc:
    print("raised again", exc.name)
"""

# a program that installs springscene's handlers and is sent SIGTERM inside a try
SIGTERMED = """
import os, signal, time
from springscene.app import signals
signals.install()
try:
    try:
        os.kill(os.getpid(), signal.SIGTERM)
        time.sleep(5)
"""

SWALLOWED = SIGTERMED + """\
    except BaseException:
        pass                  # swallowed, as C code calling Python may swallow it
""" + BUSY_THEN_REPORT

CLEAN_UP = SIGTERMED + """\
    finally:
        os.kill(os.getpid(), signal.SIGINT)      # a second signal during the clean-up
        time.sleep(0.5)
        print("clean-up finished")
except signals.Interrupted as exc:
    print(signals.report(exc))
"""


IN_A_CALLBACK = """
import gc, os, signal, time, weakref
from springscene.app import signals
signals.install()

class Thing:
    pass

def callback(ref):                     # Python prints what a weakref callback raises
    os.kill(os.getpid(), signal.SIGHUP)
    start = time.monotonic()
    while time.monotonic() - start < 1:
        sum(range(100))

try:
    thing = Thing()
    ref = weakref.ref(thing, callback)
    del thing
""" + BUSY_THEN_REPORT


@pytest.mark.parametrize("code, expected", [
    (SWALLOWED, ["raised again SIGTERM"]),
    (CLEAN_UP, ["clean-up finished", "143"]),
    (IN_A_CALLBACK, ["raised again SIGHUP"]),
])
def test_an_interruption_is_never_lost_and_never_cuts_a_clean_up_short(code, expected):
    proc = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                          text=True, timeout=60, preexec_fn=_default_signals)
    assert proc.stdout.splitlines() == expected, proc.stderr
    assert "Exception ignored" not in proc.stderr and "Traceback" not in proc.stderr


def test_an_interruption_wrapped_in_another_exception_is_found():
    stop = signals.Interrupted(signal.SIGTERM)
    try:
        try:
            raise stop
        except KeyboardInterrupt as exc:    # what type() does to __set_name__'s exception
            raise RuntimeError("Error calling __set_name__") from exc
    except RuntimeError as wrapped:
        assert signals.interruption(wrapped) is stop
    assert signals.interruption(ValueError("no")) is None


def test_a_signal_ignored_from_the_start_stays_ignored():
    """``nohup`` (SIGHUP ignored) and a shell's background job (SIGINT ignored)."""
    code = ("import os, signal, time\n"
            "signal.signal(signal.SIGHUP, signal.SIG_IGN)\n"
            "from springscene.app import signals\n"
            "signals.install()\n"
            "os.kill(os.getpid(), signal.SIGHUP)\n"
            "time.sleep(0.3)\n"
            "print(signal.getsignal(signal.SIGHUP) is signal.SIG_IGN, signals.received())\n")
    proc = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                          text=True, timeout=60, preexec_fn=_default_signals)
    assert proc.stdout.split() == ["True", "None"], proc.stderr


# a command run in-process; an object whose __del__ runs in the interpreter's teardown
# sends the process SIGTERM there, after the command is done
LATE = """
import os, signal, sys, time
from springscene.app import signals

class Late:
    def __del__(self):
        os.kill(os.getpid(), signal.SIGTERM)
        time.sleep(0.2)
        print("survived", flush=True)

late = Late()
sys.exit(signals.main(sys.argv[1:]))
"""


@pytest.mark.parametrize("args", [["--version"], ["still", WIKI, "--draft", "--out", "x.png"]],
                         ids=["argparse-exit", "still"])
def test_a_signal_in_the_teardown_of_a_finished_command_changes_nothing(tmp_path, args):
    """Once the command is done, its output whole, a signal comes too late: the exit status
    stays the command's (it was killed by the signal, no line, in the campaign's 9 of 293)."""
    proc = subprocess.run([sys.executable, "-c", LATE, *map(str, args)], cwd=tmp_path,
                          capture_output=True, text=True, timeout=120,
                          preexec_fn=_default_signals)
    assert (proc.returncode, proc.stdout.splitlines()[-1]) == (0, "survived"), proc.stderr


def _fingerprint(folder: Path) -> dict[str, str]:
    return {p.name: hashlib.sha256(p.read_bytes()).hexdigest() for p in folder.iterdir()}


def _old_set(folder: Path) -> dict[str, str]:
    folder.mkdir()
    for name in ("scene.png", "energy.png", "energy.svg", "figures.wiki", "notes.txt"):
        (folder / name).write_text(f"the old {name}\n")
    return _fingerprint(folder)


def test_figures_interrupted_over_an_existing_set_leave_it_intact(tmp_path):
    out = tmp_path / "wiki"
    before = _old_set(out)
    proc = _start("figures", DAMPED, "--out", out, "--draft")
    _wait_for_handlers(proc)
    deadline = time.monotonic() + 60          # until the new set is being built beside
    while not any(p.name.startswith(files.STAGING_PREFIX) for p in out.iterdir()):
        assert time.monotonic() < deadline and proc.poll() is None, proc.stderr.read()
        time.sleep(0.01)
    status, err = _interrupt(proc, signal.SIGTERM, 1.0)
    assert (status, err) == (143, ["springscene: interrupted (SIGTERM)"])
    assert _fingerprint(out) == before                 # every old file, and nothing else


def _fake_set(staging: Path, names=("scene.png", "energy.png", "figures.wiki")) -> None:
    for name in names:
        (staging / name).write_text(f"the new {name}\n")


def test_a_figure_set_replaces_the_old_one_whole_and_keeps_other_files(tmp_path):
    out = tmp_path / "wiki"
    _old_set(out)
    with files.figure_set(out) as staging:
        assert staging.parent == out and staging.name.startswith(files.STAGING_PREFIX)
        _fake_set(staging)
    assert (out / "scene.png").read_text() == "the new scene.png\n"
    assert (out / "figures.wiki").read_text() == "the new figures.wiki\n"
    assert (out / "energy.svg").read_text() == "the old energy.svg\n"    # not in the new set
    assert (out / "notes.txt").read_text() == "the old notes.txt\n"
    assert not [p for p in out.iterdir() if p.name.startswith(".")]


@pytest.mark.parametrize("stop_at", [1, 2, 3, 4, 5])
def test_a_swap_stopped_half_way_puts_the_old_set_back(tmp_path, monkeypatch, stop_at):
    """A stop signal between any two of the swap's renames: the old set, whole."""
    out = tmp_path / "wiki"
    before = _old_set(out)
    real_replace, calls = os.replace, []

    def replace(src, dst):
        calls.append(src)
        if len(calls) == stop_at:
            raise signals.Interrupted(signal.SIGTERM)
        real_replace(src, dst)

    monkeypatch.setattr(files.os, "replace", replace)
    with pytest.raises(signals.Interrupted):
        with files.figure_set(out) as staging:
            _fake_set(staging)
    monkeypatch.setattr(files.os, "replace", real_replace)
    assert _fingerprint(out) == before


def test_a_failed_set_leaves_no_folder_it_created(tmp_path):
    out = tmp_path / "new" / "wiki"
    with pytest.raises(OSError):
        with files.figure_set(out) as staging:
            _fake_set(staging)
            raise OSError(errno.ENOSPC, "No space left on device", str(staging / "x.png"))
    assert not out.exists()


def test_an_os_error_names_the_users_file_not_its_temporary():
    staged = f"renders/wiki/{files.STAGING_PREFIX}k2j4_x1a/.energy.png.ab3_9xyz.png"
    enospc = OSError(errno.ENOSPC, "No space left on device", staged)
    assert oserrors.line(enospc) == "no space left on device writing renders/wiki/energy.png"
    no_name = OSError(errno.EROFS, "Read-only file system")
    assert oserrors.line(no_name, "out.csv") == "read-only file system writing out.csv"
    denied = PermissionError(errno.EACCES, "Permission denied", "data/in.txt")
    assert oserrors.line(denied) == "permission denied: data/in.txt"


def test_an_interruption_carries_its_signal_and_exit_status():
    stop = signals.Interrupted(signal.SIGHUP)
    assert isinstance(stop, KeyboardInterrupt)
    assert (stop.name, stop.status) == ("SIGHUP", 129)


# ---- a full disk ----------------------------------------------------------------------

@pytest.fixture
def full_disk(tmp_path):
    """A 48 kB tmpfs (root only): room for a small CSV, not for a trajectory or a set."""
    yield from small_disk(tmp_path, "48k")


def test_a_full_disk_is_one_line_and_leaves_nothing(full_disk):
    proc = run_cli("simulate", WIKI, "--out", full_disk / "run.csv")
    assert proc.returncode == 1
    assert proc.stderr.splitlines() == [f"springscene: no space left on device writing "
                                        f"{full_disk / 'run.csv'}"]
    proc = run_cli("figures", WIKI, "--out", full_disk / "wiki", "--draft")
    assert proc.returncode == 1
    line, = proc.stderr.splitlines()
    assert line.startswith("springscene: no space left on device writing "
                           f"{full_disk / 'wiki'}/"), line
    assert files.STAGING_PREFIX not in line
    assert list(full_disk.iterdir()) == []             # no file, no empty folder


# ---- hostile inputs -------------------------------------------------------------------

def _refused(*args) -> str:
    proc = subprocess.run([SPRINGSCENE, *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, timeout=60)
    assert proc.returncode == 2, proc.stderr
    line, = proc.stderr.splitlines()
    return line


def test_a_fifo_as_the_config_is_refused_without_waiting(tmp_path):
    fifo = tmp_path / "wiki.toml"
    os.mkfifo(fifo)
    line = _refused("simulate", fifo, "--out", tmp_path / "t.csv")
    assert line == f"springscene: error: {fifo}: is a named pipe (FIFO), not a config file"


@pytest.mark.parametrize("device", ["/dev/zero", "/dev/urandom"])
def test_a_device_as_the_config_is_refused(tmp_path, device):
    line = _refused("simulate", device, "--out", tmp_path / "t.csv")
    assert line == f"springscene: error: {device}: is a character device, not a config file"


def test_a_huge_config_file_is_refused_unparsed(tmp_path):
    big = tmp_path / "big.toml"
    big.write_text(WIKI.read_text() + "#" * config.MAX_CONFIG_BYTES)
    with pytest.raises(UserError, match=r"big.toml: is over 1,000,000 bytes"):
        config.load(big)


def _variant(tmp_path: Path, old: str, new: str) -> Path:
    text = WIKI.read_text()
    assert old in text
    path = tmp_path / "variant.toml"
    path.write_text(text.replace(old, new))
    return path


@pytest.mark.parametrize("old, new, message", [
    ('title = "Ball and Spring Model of Matter"', 'title = "' + "spring " * 15_000 + '"',
     "[scene] title must be at most 300 characters, got 105,000"),
    ('color = "red"', 'color = "' + "r" * 100_000 + '"',
     "[ball] color must be at most 100 characters, got 100,000"),
    ('background = "white"', 'background = "' + "w" * 5_000 + '"',
     "[scene] background must be at most 100 characters, got 5,000"),
])
def test_huge_text_values_are_refused_by_key(tmp_path, old, new, message):
    path = _variant(tmp_path, old, new)
    with pytest.raises(UserError) as caught:
        config.load(path)
    assert str(caught.value) == f"{path}: {message}"


def test_a_title_up_to_the_limit_is_kept(tmp_path):
    title = "spring " * (config.MAX_TITLE // 7)
    path = _variant(tmp_path, '"Ball and Spring Model of Matter"', f'"{title}"')
    assert config.load(path).scene.title == title


def test_a_tiny_dt_is_refused_at_once_naming_dt_and_the_step_count(tmp_path):
    path = _variant(tmp_path, "dt = 0.01", "dt = 1e-8")
    start = time.monotonic()
    line = _refused("simulate", path, "--out", tmp_path / "t.csv")
    assert time.monotonic() - start < 30
    assert "1e+09 steps of dt = 1e-08 s" in line and "the limit is 10,000,000" in line, line
    assert not (tmp_path / "t.csv").exists()


def test_a_still_at_t0_with_a_tiny_dt_steps_nothing(tmp_path):
    path = _variant(tmp_path, "dt = 0.01", "dt = 1e-8")
    start = time.monotonic()
    proc = run_cli("still", path, "--time", 0, "--out", tmp_path / "s.png", "--draft")
    assert proc.returncode == 0, proc.stderr
    assert time.monotonic() - start < 60 and (tmp_path / "s.png").stat().st_size > 1000
