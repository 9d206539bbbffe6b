"""The supervised run's remaining holes (issue 16, a hostile campaign): processes the
program forks or leaves, ``scene.capture`` names, a closed ``sys.stdout``, a program that
kills springscene itself, a PNG written with almost no space left. Each run: its exit
status, its exact stderr, and nothing beside the output but the files it should write."""

from __future__ import annotations

import errno
import os
import signal
import subprocess
import sys
import time
from pathlib import Path

import imageio.v3 as iio
import numpy as np
import pytest

from conftest import ROOT, small_disk
from springscene.vpython.run.report import Watch, stall_line

import test_supervised
from test_supervised import SPRINGSCENE, program

outdir = test_supervised.outdir          # the fixture: an empty output folder

DIALECT = "written for VPython 7"


def run(*args, timeout: float = 120) -> subprocess.CompletedProcess:
    """springscene in a fresh process, its output streams captured: a process the program
    left holding them would keep this waiting (until ``timeout``, then the test fails)."""
    return subprocess.run([SPRINGSCENE, *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, timeout=timeout)


def lines(proc) -> list[str]:
    return proc.stderr.strip().splitlines()


def clean_run(proc, prog: Path) -> None:
    """Exit 0 and only the dialect line on stderr."""
    assert proc.returncode == 0, proc.stderr
    assert lines(proc) == [f"springscene: {prog}: {DIALECT}"], proc.stderr


def processes_naming(text: str) -> list[int]:
    """The live processes (zombies aside) whose command line contains ``text``."""
    found = []
    for entry in Path("/proc").glob("[0-9]*"):
        try:
            if text.encode() in (entry / "cmdline").read_bytes() and \
                    (entry / "stat").read_bytes().rsplit(b")", 1)[1].split()[0] != b"Z":
                found.append(int(entry.name))
        except (OSError, IndexError):
            pass
    return found


def gone(text: str, within: float = 5.0) -> bool:
    """No process names ``text`` (after at most ``within`` s: a SIGKILL is delivered at once,
    but a dying process lingers an instant)."""
    end = time.monotonic() + within
    while processes_naming(text):
        if time.monotonic() > end:
            return False
        time.sleep(0.05)
    return True


# ---- processes the program starts ----------------------------------------------------------

FORKS = {
    # a fork that sleeps (it holds, unless let go, the encoder's stdin and the report pipe)
    "fork": """
        import os, time
        for i in range(5):
            rate(50)
            b.pos.x += 0.01
        if os.fork() == 0:
            time.sleep(1000)
            os._exit(0)
    """,
    # the same in a session of its own (out of the child's process group), from the start
    "setsid": """
        import os, time
        if os.fork() == 0:
            os.setsid()
            time.sleep(1000)
            os._exit(0)
        for i in range(5):
            rate(50)
            b.pos.x += 0.01
    """,
    # a daemon made by a double fork: its parent ends, it is nobody's child but the run's
    "double-fork": """
        import os, time
        for i in range(5):
            rate(50)
        if os.fork() == 0:
            os.setsid()
            if os.fork() == 0:
                time.sleep(1000)
            os._exit(0)
    """,
    # a worker fork the program itself stops with SIGTERM (the copy's SIGTERM is Python's)
    "sigterm-fork": """
        import os, signal, time
        pid = os.fork()
        if pid == 0:
            time.sleep(1000)
            os._exit(0)
        for i in range(5):
            rate(50)
        os.kill(pid, signal.SIGTERM)
        assert os.waitpid(pid, 0)[1] == signal.SIGTERM
    """,
    # a plain subprocess left running
    "subprocess": """
        import subprocess
        subprocess.Popen(["sleep", "987.654"])
        for i in range(5):
            rate(50)
    """,
}


@pytest.mark.parametrize("kind", FORKS)
def test_processes_the_program_leaves_neither_hold_nor_outlive_the_run(tmp_path, outdir,
                                                                       kind):
    prog = program(tmp_path, FORKS[kind])
    start = time.monotonic()
    proc = run("vpython", prog, "--out", outdir / "x.mp4", timeout=90)
    assert time.monotonic() - start < 60              # the sleeps are 1000 s
    clean_run(proc, prog)
    assert proc.stdout.startswith(f"wrote {outdir / 'x.mp4'}: 5 frames"), proc.stdout
    assert sorted(os.listdir(outdir)) == ["x.html", "x.mp4"]
    assert gone(str(outdir)) and gone("987.654")    # the child, its forks, the sleep


@pytest.mark.parametrize("ending", ["pass", "sys.exit(5)", "1 / 0"])
def test_a_fork_that_runs_on_to_the_programs_end_writes_nothing(tmp_path, outdir, ending):
    """A fork that does not ``os._exit``: its copy of the program runs on and ends (falls
    off the end, exits, raises) without finishing, moving or removing the run's files
    (its springscene epilogue would close the encoder and move its file away)."""
    prog = program(tmp_path, f"""
        import os, sys, time
        for i in range(3):
            rate(50)
        if os.fork() == 0:
            {ending}
        else:
            time.sleep(1)           # the copy ends first
            for i in range(3):
                rate(50)
            scene.capture("shot")
    """)
    proc = run("vpython", prog, "--out", outdir / "x.mp4")
    assert proc.returncode == 0, proc.stderr
    said = lines(proc)
    if ending == "1 / 0":                   # the copy's own traceback, as Python's
        assert said[-1] == "ZeroDivisionError: division by zero", said
        said = said[:1]
    assert said == [f"springscene: {prog}: {DIALECT}"], proc.stderr
    assert proc.stdout.startswith(f"wrote {outdir / 'x.mp4'}: 6 frames"), proc.stdout
    assert sorted(os.listdir(outdir)) == ["shot.png", "x.html", "x.mp4"]


# ---- scene.capture names -------------------------------------------------------------------

CAPTURES = [
    # (the name the program gives, the file beside the output)
    ("'c' * 300", "c" * 237 + ".png"),         # cut: its temporary name fits 255 bytes
    ("'a\\x00b'", "a_b.png"),
    ("'two\\nlines'", "two_lines.png"),
    ("'../sub/dir/name'", "name.png"),
    ("'/'", "x-capture.png"),
    ("'.hidden'", "x-capture.hidden.png"),
    ("'snap.PNG'", "snap.PNG.png"),             # GlowScript's exact test of '.png'
    ("'\\ud800' + 'x'", "?x.png"),                 # a lone surrogate: no UTF-8 for it
]


@pytest.mark.parametrize("name, file", CAPTURES,
                         ids=["long", "nul", "newline", "folders", "slash", "hidden", "png",
                              "surrogate"])
def test_capture_names_are_sanitised(tmp_path, outdir, name, file):
    prog = program(tmp_path, f"rate(50)\nscene.capture({name})\n")
    proc = run("vpython", prog, "--out", outdir / "x.mp4")
    clean_run(proc, prog)
    assert sorted(os.listdir(outdir)) == sorted([file, "x.html", "x.mp4"])


def test_capture_after_the_program_changes_folder(tmp_path, outdir):
    prog = program(tmp_path, f"import os\nrate(50)\nos.chdir({str(tmp_path)!r})\n"
                             "scene.capture('moved')\n")
    proc = run("vpython", prog, "--out", outdir / "x.mp4")
    clean_run(proc, prog)
    assert sorted(os.listdir(outdir)) == ["moved.png", "x.html", "x.mp4"]
    assert not (tmp_path / "moved.png").exists()


def test_a_name_captured_twice_is_the_last_capture(tmp_path, outdir):
    prog = program(tmp_path, """
        rate(50)
        scene.background = color.red
        scene.capture("a")
        scene.background = color.blue
        scene.capture("a")
    """)
    proc = run("vpython", prog, "--out", outdir / "x.mp4")
    clean_run(proc, prog)
    assert sorted(os.listdir(outdir)) == ["a.png", "x.html", "x.mp4"]
    corner = iio.imread(outdir / "a.png")[0, 0, :3]
    assert np.array_equal(corner, [0, 0, 255]), corner


def test_a_capture_that_cannot_be_written_is_one_line_at_the_programs_line(tmp_path,
                                                                          outdir):
    """An empty name is named after the output; with an output name near the limit that
    name is too long for a file: one line at the program's line, exit 1, nothing left."""
    prog = program(tmp_path, "rate(50)\nscene.capture('')\n")
    out = outdir / ("o" * 236 + ".mp4")
    proc = run("vpython", prog, "--out", out)
    assert proc.returncode == 1, proc.stderr
    assert lines(proc)[1:] == [f"springscene: {prog}, line 6: scene.capture(''): cannot be "
                               "written beside the output (File name too long)"]
    assert os.listdir(outdir) == []


# ---- the program's streams -----------------------------------------------------------------

def test_a_program_that_closes_stdout_still_gets_its_video(tmp_path, outdir):
    prog = program(tmp_path, """
        import sys
        sys.stdout.close()
        for i in range(5):
            rate(50)
            b.pos.x += 0.01
    """)
    proc = run("vpython", prog, "--out", outdir / "x.mp4")
    clean_run(proc, prog)
    assert proc.stdout.startswith(f"wrote {outdir / 'x.mp4'}: 5 frames"), proc.stdout
    assert sorted(os.listdir(outdir)) == ["x.html", "x.mp4"]


# ---- springscene killed outright -----------------------------------------------------------

@pytest.mark.parametrize("own_handler", [False, True], ids=["plain", "own-sigterm-handler"])
def test_a_program_that_kills_springscene_leaves_nothing(tmp_path, outdir, own_handler):
    """SIGKILL cannot be handled by springscene; its child sees its parent gone (SIGTERM
    from the kernel), removes the hidden run folder with its partial video, and ends. A
    program that took SIGTERM for itself is caught by the next report, which finds no
    parent."""
    prog = program(tmp_path, f"""
        import os, signal, time
        if {own_handler}:
            signal.signal(signal.SIGTERM, lambda *a: None)
        for i in range(10):
            rate(50)
        os.kill(os.getppid(), signal.SIGKILL)
        time.sleep(60)
    """)
    proc = run("vpython", prog, "--out", outdir / "x.mp4")
    assert proc.returncode == -signal.SIGKILL
    assert lines(proc) == [f"springscene: {prog}: {DIALECT}"]
    assert gone(str(outdir), within=10)
    assert os.listdir(outdir) == []


def test_springscene_killed_while_the_program_is_in_one_long_c_call_leaves_nothing(
        tmp_path, outdir):
    """The kernel's SIGTERM is handled in Python, which ``sum(range(10**11))`` does not
    reach; the watcher process kills the child (and its group) and removes the folder, so
    no orphan runs on without springscene's limits."""
    prog = program(tmp_path, """
        rate(50)
        sum(range(10**11))
    """)
    proc = subprocess.Popen([SPRINGSCENE, "vpython", str(prog), "--out",
                             str(outdir / "x.mp4")], cwd=ROOT, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    deadline = time.monotonic() + 60
    while not list(outdir.iterdir()):                  # the run folder: the child is up
        assert time.monotonic() < deadline and proc.poll() is None
        time.sleep(0.05)
    time.sleep(2)                                      # the program is in its long call
    proc.kill()
    proc.wait()
    assert gone(str(prog), within=10)
    assert os.listdir(outdir) == []


def test_a_programs_multiprocessing_worker_finishes_as_under_python(tmp_path, outdir):
    """Python joins a non-daemon worker still running at the program's end (it was killed
    with what the program left)."""
    prog = program(tmp_path, """
        import multiprocessing as mp
        def late():
            import time
            time.sleep(0.5)
            print("late worker done", flush=True)
        if __name__ == "__main__":
            for i in range(3):
                rate(50)
            mp.Process(target=late).start()
    """)
    proc = run("vpython", prog, "--out", outdir / "x.mp4")
    clean_run(proc, prog)
    assert "late worker done" in proc.stdout
    assert sorted(os.listdir(outdir)) == ["x.html", "x.mp4"]


def test_a_parent_dead_before_the_child_watched_it_is_caught(tmp_path):
    """The parent may die before the child asks to be told (PR_SET_PDEATHSIG): the child
    compares its parent to the expected one, and cleans up at once."""
    folder = tmp_path / ".x.mp4.123.abcdefgh.run"
    folder.mkdir()
    (folder / ".x.mp4.partial.mp4").write_bytes(b"partial")
    code = ("import sys; from pathlib import Path; from springscene.vpython.run import lineage; "
            "lineage.die_with_parent(999999999, Path(sys.argv[1])); print('still here')")
    proc = subprocess.run([sys.executable, "-c", code, str(folder)], cwd=ROOT,
                          capture_output=True, text=True, timeout=60,
                          start_new_session=True)          # it kills its process group
    assert proc.returncode == -signal.SIGKILL and "still here" not in proc.stdout
    assert not folder.exists()


# ---- a PNG with almost no space left -------------------------------------------------------

@pytest.fixture
def nearly_full(tmp_path):
    """A 64 kB tmpfs filled to under 4 kB free (a mount needs root: skipped otherwise)."""
    for disk in small_disk(tmp_path, "64k"):
        with open(disk / "filler", "wb", buffering=0) as f:
            try:
                while True:
                    f.write(b"\0" * 512)
            except OSError as exc:
                assert exc.errno == errno.ENOSPC
        with open(disk / "filler", "r+b") as f:
            f.truncate(os.path.getsize(disk / "filler") - 1500)
        yield disk


def test_a_vpython_png_with_no_space_is_one_line(tmp_path, nearly_full):
    prog = program(tmp_path, "scene.width = 320\nscene.height = 240\n"
                             "import random\nfor i in range(50):\n"
                             "    sphere(pos=vector(random.random(), random.random(), 0), "
                             "color=vector(random.random(), random.random(), 1))\n")
    proc = run("vpython", prog, "--out", nearly_full / "x.png")
    assert proc.returncode == 1, proc.stderr
    assert lines(proc) == [f"springscene: {prog}: {DIALECT}",
                           f"springscene: no space left on device writing "
                           f"{nearly_full / 'x.png'}"], proc.stderr
    assert os.listdir(nearly_full) == ["filler"]


# ---- what is said while no frame comes -----------------------------------------------------

def test_no_frame_after_the_programs_end_says_the_video_is_being_finished():
    """The program has ended (its clock is no longer current) while its files are being
    finished: not 'no rate() or sleep() call'."""
    watch = Watch(Path("prog.py"), 1 << 40, None, 10.0, 30.0, print)
    watch.progress({"kind": "progress", "started": True, "clock": 0.12, "frames": 6,
                    "fps": 50, "calls": 6, "call": "rate", "arg": 50.0, "span": 0.02,
                    "line": None, "ended": True})
    watch.last_at = time.monotonic() + 10       # (reports still come)
    line = stall_line(watch, watch.waiting + 10.4)
    assert line == ("springscene: prog.py: no frame for 10 s of wall clock: the program has "
                    "ended, at 0.12 s of program time (6 frames); its video is being "
                    "finished")


def test_a_capture_name_that_is_not_text_is_vpythons_type_error():
    from springscene.vpython.core.canvases import capture_name

    with pytest.raises(TypeError, match="'filename' for Capture must be a string."):
        capture_name(3)
    assert capture_name("x" * 1_000_000) == "x" * 237 + ".png"     # cut at once, not char by char
