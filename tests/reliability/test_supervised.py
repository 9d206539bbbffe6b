"""The supervised run of a VPython program (issue 16): the program runs in a child process,
only finished files reach the output folder, and every way a program can end is one line
with the right exit status."""

from __future__ import annotations

import os
import re
import signal
import subprocess
import sys
import textwrap
import time
from pathlib import Path

import pytest

from conftest import ROOT, run_cli
from springscene.errors import ProgramError
from springscene.vpython.run.runner import ProgramExit, run_program
from springscene.vpython.run.options import RunOptions
from springscene.vpython.run import supervise
from springscene.vpython.run.supervise import RunEnded, run_supervised
from springscene.vpython.run.report import parse_size

SPRINGSCENE = str(Path(sys.executable).parent / "springscene")   # the installed command

TINY = "from vpython import *\nscene.width = 64\nscene.height = 48\nb = sphere()\n"


def program(tmp_path: Path, body: str, name: str = "prog.py") -> Path:
    path = tmp_path / name
    path.write_text(TINY + textwrap.dedent(body))
    return path


@pytest.fixture
def outdir(tmp_path) -> Path:
    folder = tmp_path / "out"
    folder.mkdir()
    return folder


def lines(proc) -> list[str]:
    return proc.stderr.strip().splitlines()


def test_a_run_moves_its_finished_files_into_place_and_nothing_else(tmp_path, outdir):
    prog = program(tmp_path, """
        for i in range(3):
            rate(50)
            b.pos.x += 0.1
        scene.capture("shot")
    """)
    proc = run_cli("vpython", prog, "--frames", "10", "--out", outdir / "x.mp4", check=True)
    assert sorted(os.listdir(outdir)) == ["shot.png", "x.html", "x.mp4"]
    assert "3 frames" in proc.stdout and "peak memory" in proc.stdout
    peak = proc.stdout.split("peak memory ")[1].split()[0]
    assert 50 << 20 < parse_size(peak) < 4 << 30


ENDINGS = [
    # (the program's end, exit status, what the one line says)
    ("import sys; sys.exit(3)", 3, "the program exited with status 3 (sys.exit)"),
    ("import os; os._exit(0)", 1, "ended with status 0 (os._exit?) before its output was "
                                  "finished"),
    ("import os; os._exit(7)", 7, "ended with status 7 (os._exit?)"),
    ("import os, signal; os.kill(os.getpid(), signal.SIGTERM)", 143,
     "the program was killed by SIGTERM"),
    ("import os, signal; os.kill(os.getpid(), signal.SIGKILL)", 137,
     "the program was killed by SIGKILL"),
    ("import ctypes; ctypes.string_at(0)", 139, "killed by SIGSEGV (a crash: segmentation"),
]


@pytest.mark.parametrize("end, status, said", ENDINGS,
                         ids=["sys.exit", "os._exit0", "os._exit7", "sigterm", "sigkill",
                              "segfault"])
def test_every_abnormal_end_is_one_line_its_status_and_nothing_left(tmp_path, outdir, end,
                                                                     status, said):
    prog = program(tmp_path, f"""
        for i in range(3):      # a video under way: frames sent to the encoder
            rate(50)
        {end}
    """)
    proc = run_cli("vpython", prog, "--frames", "20", "--out", outdir / "x.mp4")
    assert proc.returncode == status, proc.stderr
    assert len(lines(proc)) == 2, proc.stderr           # the dialect, then the one line
    last = lines(proc)[-1]
    assert last.startswith(f"springscene: {prog}: ") and said in last
    # where it was: the clock at the last frame (0.04 s) or after the last rate (0.06 s)
    assert re.search(r"at 0\.0[46] s of program time \(3 frames\); nothing written \(peak "
                     r"memory \d+M\)$", last), last
    assert os.listdir(outdir) == []


def test_sys_exit_with_a_message_prints_it_as_python_does(tmp_path, outdir):
    prog = program(tmp_path, "import sys\nsys.exit('no data file')\n")
    proc = run_cli("vpython", prog, "--out", outdir / "x.png")
    assert proc.returncode == 1
    assert lines(proc)[1:] == ["no data file", lines(proc)[-1]]
    assert "exited with status 1" in lines(proc)[-1] and os.listdir(outdir) == []


def test_the_programs_traceback_stays_and_the_files_up_to_it_are_whole(tmp_path, outdir):
    prog = program(tmp_path, "rate(50)\nscene.capture('early')\n1/0\n")
    proc = run_cli("vpython", prog, "--out", outdir / "x.mp4")
    assert proc.returncode == 1
    assert f'File "{prog}", line 7' in proc.stderr and "ZeroDivisionError" in proc.stderr
    assert lines(proc)[-1] == ("springscene: the video ends at the program's error, at "
                               "t = 0.02 s (frame 1)")
    # the video up to the error, its page and the capture: moved out whole, nothing hidden
    assert sorted(os.listdir(outdir)) == ["early.png", "x.html", "x.mp4"]


def test_an_error_before_the_first_frame_leaves_nothing(tmp_path, outdir):
    prog = program(tmp_path, "scene.capture('early')\n1/0\nrate(50)\n")
    proc = run_cli("vpython", prog, "--out", outdir / "x.mp4")
    assert proc.returncode == 1 and "ZeroDivisionError" in proc.stderr
    assert "ends at the program's error" not in proc.stderr
    assert os.listdir(outdir) == []                  # the capture too: no frame was taken


def test_a_thread_left_running_does_not_keep_springscene_alive(tmp_path, outdir):
    prog = program(tmp_path, """
        import threading, time
        threading.Thread(target=time.sleep, args=(300,), name="worker").start()
        rate(50)
    """)
    start = time.monotonic()
    proc = run_cli("vpython", prog, "--frames", "2", "--out", outdir / "x.mp4", check=True)
    assert time.monotonic() - start < 60
    assert "thread 'worker' running after its end" in proc.stderr
    assert sorted(os.listdir(outdir)) == ["x.html", "x.mp4"]


def test_timeout_stops_the_program_with_124(tmp_path, outdir):
    prog = program(tmp_path, "while True:\n    pass\n")
    start = time.monotonic()
    proc = run_cli("vpython", prog, "--timeout", "1.5", "--out", outdir / "x.mp4")
    assert proc.returncode == 124 and time.monotonic() - start < 30
    assert "stopped by --timeout 1.5 s (wall clock)" in lines(proc)[-1]
    assert os.listdir(outdir) == []


def test_max_memory_stops_a_memory_hog_with_137(tmp_path, outdir):
    prog = tmp_path / "hog.py"
    prog.write_text("import numpy as np\nkeep = []\nwhile True:\n"
                    "    keep.append(np.ones(10_000_000))\n")          # 80 MB a turn
    proc = run_cli("vpython", prog, "--max-memory", "300M", "--out", outdir / "x.mp4")
    assert proc.returncode == 137, proc.stderr
    last = lines(proc)[-1]
    assert "over --max-memory 300M" in last and "nothing written" in last
    used = parse_size(last.split("it used ")[1].split()[0])
    assert 300 << 20 < used < 800 << 20    # polled every 20 ms: caught early (a loaded CI
    #                                        machine may be late by a few 80 MB turns)
    assert os.listdir(outdir) == []


@pytest.mark.parametrize("args, message", [
    (["--max-memory", "lots"], "--max-memory lots: give a size such as 500M or 2G"),
    (["--max-memory", "10"], "too little"),
    (["--max-memory", "99999999999999999999999T"], "more than any machine has; give at most 1024T"),
    (["--max-memory=-2G"], "--max-memory -2G"),
    (["--timeout", "0"], "--timeout 0: must be a number of seconds above 0"),
    (["--timeout", "nan"], "--timeout nan"),
])
def test_bad_limits_are_one_line_exit_2(tmp_path, outdir, args, message):
    proc = run_cli("vpython", program(tmp_path, ""), "--out", outdir / "x.mp4", *args)
    assert proc.returncode == 2 and len(lines(proc)) == 1, proc.stderr
    assert message in proc.stderr and os.listdir(outdir) == []


STALLS = [      # (the program after TINY's 4 lines, why, the lines it can be at)
    ("import time\nwhile True:\n    rate(100000)\n    time.sleep(0.02)\n",
     "rate(100000) advances program time 1e-05 s a call", (7, 8)),
    ("rate(50)\nwhile True:\n    pass\n", "no rate() or sleep() call in", (6, 7)),
    ("while True:\n    sleep(0)\n", "sleep(0) advances program time 0 s a call", (5, 6)),
    ("import re\nre.match('(a+)+b', 'a' * 40)\n", "one long call holds Python", ()),
]


@pytest.mark.parametrize("body, why, at", STALLS,
                         ids=["slow-rate", "no-rate", "sleep0", "holds-python"])
def test_no_frame_for_a_while_says_why(tmp_path, outdir, body, why, at, monkeypatch):
    monkeypatch.setattr(supervise, "STALL_AGAIN", 1.0)     # (a loaded machine: VTK may
    said = []                                                # take seconds to load)
    with pytest.raises(RunEnded) as ended:
        run_supervised(program(tmp_path, body), outdir / "x.mp4", RunOptions(frames=5),
                       timeout=6, stall_after=1.5, say=said.append)
    assert ended.value.status == 124
    line = next((line for line in said if why in line), said)
    assert "no frame for" in line and why in line, said
    if at:                                          # the clock, and where the program is
        assert "the next frame comes when it passes" in line
        assert any(f"(at line {n} of prog.py)" in line for n in at), line
    assert os.listdir(outdir) == []


def test_a_stop_signal_to_springscene_ends_the_child_and_leaves_nothing(tmp_path, outdir):
    prog = program(tmp_path, "while True:\n    sleep(0)\n")
    proc = subprocess.Popen([SPRINGSCENE, "vpython", str(prog), "--out",
                             str(outdir / "x.mp4")], cwd=ROOT, stderr=subprocess.PIPE,
                            text=True)
    time.sleep(3)
    proc.send_signal(signal.SIGTERM)
    _, err = proc.communicate(timeout=60)
    assert proc.returncode == 143, err
    assert err.strip().splitlines()[-1] == "springscene: interrupted (SIGTERM)"
    assert os.listdir(outdir) == []
    for cmdline in Path("/proc").glob("[0-9]*/cmdline"):      # the child is gone too
        try:
            assert str(outdir).encode() not in cmdline.read_bytes()
        except OSError:
            pass


# ---- canvas sizes set by a program -------------------------------------------------------

@pytest.mark.parametrize("setting, said", [
    ("scene.width = 100000", "scene.width = 100000: a canvas width must be 1 to 8192 pixels"),
    ("scene.height = 0", "scene.height = 0: a canvas height must be 1 to 8192 pixels"),
    ("scene.width = float('nan')", "scene.width = nan: a canvas width must be"),
    ("scene.height = 'big'", "scene.height = 'big': a canvas height must be a number"),
    ("c = canvas(width=9000)", "canvas.width = 9000: a canvas width must be"),
])
def test_canvas_sizes_are_checked_where_the_program_sets_them(tmp_path, setting, said):
    prog = tmp_path / "size.py"
    prog.write_text(f"from vpython import *\nb = sphere()\n{setting}\nrate(10)\n")
    with pytest.raises(ProgramError) as error:
        run_program(prog, tmp_path / "x.png")
    assert str(error.value).startswith(f"springscene: {prog}, line 3: {said}")
    assert "\n" not in str(error.value) and not list(tmp_path.glob("*x*"))


def test_canvas_size_error_on_the_command_line_is_one_line(tmp_path, outdir):
    prog = tmp_path / "size.py"
    prog.write_text("from vpython import *\nsphere()\nscene.width = 100000\nrate(10)\n")
    proc = run_cli("vpython", prog, "--out", outdir / "x.mp4")
    assert proc.returncode == 1 and len(lines(proc)) == 2
    assert lines(proc)[1] == (f"springscene: {prog}, line 3: scene.width = 100000: a canvas "
                              "width must be 1 to 8192 pixels")
    assert os.listdir(outdir) == []


def test_sizes_within_bounds_are_kept_as_given(tmp_path):
    prog = tmp_path / "ok.py"
    prog.write_text("from vpython import *\nscene.width = 8192.5\nscene.height = 1\n"
                    "scene.width = 33.7\nsphere()\n")
    r = run_program(prog, tmp_path / "x.png", RunOptions(canvas_only=True, page=False))
    assert r.size == (33, 1)


def test_sys_exit_in_the_library_call_carries_pythons_status(tmp_path):
    prog = tmp_path / "e.py"
    prog.write_text("import sys\nsys.exit(259)\n")
    with pytest.raises(ProgramExit) as error:
        run_program(prog, tmp_path / "x.png")
    assert error.value.status == 3 and "status 3" in str(error.value)


def test_sizes_parse_like_the_flag_says():
    assert parse_size("500M") == 500 << 20 and parse_size("2G") == 2 << 30
    assert parse_size("1.5g") == 3 << 29 and parse_size("300MiB") == 300 << 20
    assert parse_size("4096") == 4096
    for bad in ("", "G", "1e3M", "-1G", "2 X"):
        with pytest.raises(ValueError):
            parse_size(bad)


def test_a_folder_left_by_a_run_killed_outright_goes_with_the_next_run(tmp_path, outdir):
    dead = outdir / ".x.png.999999999.abcd1234.run"        # no such process
    alive = outdir / f".x.png.{os.getpid()}.abcd1234.run"  # a run under way (this one)
    for folder in (dead, alive):
        folder.mkdir()
        (folder / "x.png").write_bytes(b"partial")
    run_supervised(program(tmp_path, ""), outdir / "x.png", RunOptions(page=False))
    assert sorted(os.listdir(outdir)) == [alive.name, "x.png"]


@pytest.fixture
def full_disk(tmp_path):
    """A 60 kB tmpfs (root can mount one; skipped otherwise)."""
    folder = tmp_path / "small"
    folder.mkdir()
    if subprocess.run(["mount", "-t", "tmpfs", "-o", "size=60k", "tmpfs", str(folder)],
                      capture_output=True).returncode != 0:
        pytest.skip("cannot mount a tmpfs here (needs root)")
    yield folder
    subprocess.run(["umount", str(folder)], check=True)


def test_a_full_disk_is_one_line_naming_the_users_file_and_nothing_is_left(tmp_path,
                                                                            full_disk):
    prog = program(tmp_path, """
        import random
        scene.width, scene.height = 320, 240
        while True:
            rate(50)
            scene.background = vector(random.random(), random.random(), random.random())
    """)
    proc = run_cli("vpython", prog, "--frames", "60", "--out", full_disk / "x.gif")
    assert proc.returncode == 1, proc.stderr
    assert lines(proc)[1:] == [f"springscene: no space left on device writing "
                               f"{full_disk / 'x.gif'}"]
    assert os.listdir(full_disk) == []
