"""``springscene batch``: a class's programs to videos, rows and one index page.

A class of four tiny programs (tests/vpython_programs/batch_*.py), one a student: alice's
runs, bob's raises, carol's hangs (no ``rate``) past ``--timeout`` and dave's blows up
past ``--max-memory``. Each runs in its own processes, two at a time; the rows, videos,
thumbnails and the index say what each did, and no program's end touches another's
files. Reruns skip what is done; Ctrl-C keeps what finished; bad input writes nothing; a
real Dask ``LocalCluster`` of two workers gives the same rows and byte-identical videos.
"""

from __future__ import annotations

import csv
import importlib.util
import io
import json
import os
import re
import shutil
import signal
import subprocess
import sys
import time
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

from conftest import ROOT, default_stop_signals, run_cli
from springscene.batch.plan import find_programs
from springscene.batch.runs import job_environment
from springscene.errors import UserError
from springscene.video import count_frames
from springscene.vpython.run.sandbox import unavailable as no_sandbox

PROGRAMS = ROOT / "tests" / "vpython_programs"
CLASS = {"alice": "batch_fine.py", "bob": "batch_raises.py", "carol": "batch_hangs.py",
         "dave": "batch_hog.py"}
FLAGS = ["--duration", "0.5", "--fps", "25", "--timeout", "20", "--max-memory", "600M"]
TIMES = ("wall_seconds", "peak_memory")        # what differs from run to run
# the class runs as by default, sandboxed, where a sandbox can be made
SANDBOX = [] if no_sandbox() is None else ["--no-sandbox"]


def make_class(folder: Path, names=tuple(CLASS)) -> Path:
    folder.mkdir(parents=True, exist_ok=True)
    for name in names:
        shutil.copy(PROGRAMS / CLASS[name], folder / f"{name}.py")
    return folder


@pytest.fixture(scope="module")
def ran(tmp_path_factory):
    """The class run once, two at a time (a program a student: a folder of .py files)."""
    base = tmp_path_factory.mktemp("batch")
    programs, out = make_class(base / "class"), base / "out"
    start = time.monotonic()
    proc = run_cli("batch", programs, "--out-dir", out, "--jobs", "2", *FLAGS, *SANDBOX)
    return proc, out, programs, time.monotonic() - start


def rows_of(out: Path) -> dict[str, dict]:
    return {row["name"]: row for row in json.loads((out / "summary.json").read_text())["rows"]}


def test_each_program_has_its_row(ran):
    proc, out, programs, _ = ran
    assert proc.returncode == 0, proc.stderr
    rows = rows_of(out)
    assert sorted(rows) == ["alice", "bob", "carol", "dave"]
    assert rows["alice"]["status"] == "ran" and rows["alice"]["detail"] == ""
    assert rows["alice"]["frames"] == 12              # 0.5 s at 25 frames/s (12.5, rounded)
    assert 0.44 <= rows["alice"]["program_seconds"] <= 0.5
    assert rows["bob"]["status"] == "error"
    assert rows["bob"]["detail"] == "ZeroDivisionError: float division by zero (line 12)"
    assert rows["bob"]["program_seconds"] == pytest.approx(0.22) and rows["bob"]["frames"] == 7
    assert rows["carol"]["status"] == "timeout"
    assert rows["carol"]["detail"] == "stopped by --timeout 20 s"
    assert rows["dave"]["status"] == "memory"
    assert rows["dave"]["detail"] == "stopped: over --max-memory 600M"
    assert rows["dave"]["program_seconds"] <= 0.2        # (as far as it had reported)
    for name, row in rows.items():
        assert row["program"] == str(programs / f"{name}.py")
        assert row["wall_seconds"] > 0
    assert "wrote" in proc.stdout and "4 programs (1 error, 1 memory, 1 ran, 1 timeout)" \
        in proc.stdout


def test_the_videos_and_thumbnails_are_there_and_only_theirs(ran):
    _, out, _, _ = ran
    assert count_frames(out / "alice" / "alice.mp4") == 12
    assert count_frames(out / "bob" / "bob.mp4") == 7            # up to the error
    for name in ("alice", "bob"):
        assert (out / name / f"{name}.html").stat().st_size > 10_000       # the player page
        assert (out / name / f"{name}.jsonl.gz").is_file()
    assert sorted(p.name for p in (out / "carol").iterdir()) == ["log.txt", "result.json"]
    assert sorted(p.name for p in (out / "dave").iterdir()) == ["log.txt", "result.json"]
    thumb = np.asarray(Image.open(out / "alice" / "thumbnail.png").convert("RGB")).astype(int)
    assert 240 <= thumb.shape[1] <= 320               # the page's width, at most 320 px
    orange = (thumb[..., 0] > 180) & (thumb[..., 1] > 60) & (thumb[..., 1] < 190) & \
        (thumb[..., 2] < 80)
    assert orange.sum() > 200                         # the ball, where the video ends
    assert "the ball ended at" not in (out / "alice" / "log.txt").read_text()   # (t < 5)
    assert "ZeroDivisionError" in (out / "bob" / "log.txt").read_text()
    assert "--timeout" in (out / "carol" / "log.txt").read_text()
    assert not [p for p in out.rglob(".*")]           # no staging folder left behind


def test_the_summaries_hold_the_same_rows(ran):
    _, out, _, _ = ran
    rows = rows_of(out)
    table = list(csv.DictReader(io.StringIO((out / "summary.csv").read_text())))
    assert [r["name"] for r in table] == sorted(rows)
    for r in table:
        assert r["status"] == rows[r["name"]]["status"]
        assert r["detail"] == rows[r["name"]]["detail"]
        assert float(r["wall_seconds"]) == rows[r["name"]]["wall_seconds"]


def test_the_index_shows_every_program_and_links_what_exists(ran):
    _, out, _, _ = ran
    page = (out / "index.html").read_text()
    assert "4 of 4 programs" in page
    for name, status in (("alice", "ran"), ("bob", "error"), ("carol", "timeout"),
                         ("dave", "memory")):
        card = page[page.index(f'id="{name}"'):].split('<div class="card"', 1)[0]
        assert f">{status}</span>" in card
    assert "ZeroDivisionError: float division by zero (line 12)" in page
    links = re.findall(r'(?:href|src)="([^"#]+)"', page)
    assert "alice/alice.html" in links and "alice/thumbnail.png" in links
    assert "bob/bob.mp4" in links and "carol/log.txt" in links
    assert not [link for link in links if not (out / link).is_file()]


def test_a_rerun_skips_what_is_done_and_force_runs_again(tmp_path):
    programs, out = make_class(tmp_path / "class", ["alice"]), tmp_path / "out"
    first = run_cli("batch", programs, "--out-dir", out, *FLAGS, "--no-sandbox")
    assert first.returncode == 0, first.stderr
    made = (out / "alice" / "result.json").stat().st_mtime_ns
    again = run_cli("batch", programs, "--out-dir", out, *FLAGS, "--no-sandbox")
    assert again.returncode == 0 and "1 of 1 programs done before" in again.stderr
    assert (out / "alice" / "result.json").stat().st_mtime_ns == made
    assert rows_of(out)["alice"]["status"] == "ran"
    longer = run_cli("batch", programs, "--out-dir", out, *FLAGS[2:], "--duration", "0.3",
                     "--no-sandbox")                  # asked otherwise: run again
    assert longer.returncode == 0 and rows_of(out)["alice"]["frames"] == 8    # 0.3 s
    forced = run_cli("batch", programs, "--out-dir", out, *FLAGS[2:], "--duration", "0.3",
                     "--no-sandbox", "--force")
    assert forced.returncode == 0 and "done before" not in forced.stderr
    assert (out / "alice" / "result.json").stat().st_mtime_ns > made


def test_ctrl_c_keeps_what_finished_and_a_valid_index(tmp_path):
    programs = make_class(tmp_path / "class", ["alice", "carol"])
    out = tmp_path / "out"
    proc = subprocess.Popen([str(Path(sys.executable).parent / "springscene"), "batch",
                             str(programs), "--out-dir", str(out), "--jobs", "2", *FLAGS[:4],
                             "--timeout", "120", "--no-sandbox"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True,
                            preexec_fn=default_stop_signals)
    deadline = time.monotonic() + 120
    while not (out / "alice" / "result.json").exists() and time.monotonic() < deadline:
        time.sleep(0.2)
    time.sleep(1)                    # carol is running (it never ends by itself)
    proc.send_signal(signal.SIGINT)
    stdout, stderr = proc.communicate(timeout=60)
    assert proc.returncode == 130, stderr
    assert stderr.strip().splitlines()[-1] == "springscene: interrupted (SIGINT)"
    summary = json.loads((out / "summary.json").read_text())
    assert summary["programs"] == 2 and summary["done"] == 1
    assert [row["name"] for row in summary["rows"]] == ["alice"]
    assert count_frames(out / "alice" / "alice.mp4") == 12
    assert sorted(p.name for p in out.iterdir()) == ["alice", "index.html", "summary.csv",
                                                     "summary.json"]
    assert not _running(programs / "carol.py", tmp_path)


def _running(program: Path, folder: Path) -> list[int]:
    """The processes whose command line names ``program`` (a job started fresh) or whose
    working folder is in ``folder`` (a job and its program forked from the warm process,
    whose command line is the warm process's)."""
    found = []
    for proc in Path("/proc").iterdir():
        try:
            if str(program).encode() in (proc / "cmdline").read_bytes() or \
                    Path(os.readlink(proc / "cwd")).is_relative_to(folder):
                found.append(int(proc.name))
        except (OSError, ValueError):
            pass
    return found


@pytest.mark.parametrize("args, message", [
    (["--out-dir", "{out}"], "the following arguments are required: PROGRAM"),
    (["{tmp}/nothere.py", "--out-dir", "{out}"], "nothere.py: no such file or folder"),
    (["{tmp}/empty", "--out-dir", "{out}"], "empty: no VPython program in this folder"),
    (["{tmp}/class", "--out-dir", "{out}", "--fps", "0"], "--fps 0: must be a whole number"),
    (["{tmp}/class", "--out-dir", "{out}", "--jobs", "0"], "--jobs 0: must be at least 1"),
    (["{tmp}/class", "--out-dir", "{out}", "--timeout", "-1"], "--timeout -1: must be"),
    (["{tmp}/class", "--out-dir", "{out}", "--max-memory", "lots"], "--max-memory lots"),
    (["{tmp}/class", "--out-dir", "{out}", "--duration", "0"], "--duration 0: must be"),
    (["{tmp}/class", "--out-dir", "{tmp}/afile/out"], "--out-dir {tmp}/afile/out: cannot make"),
    (["{tmp}/class", "{tmp}/other/alice.py", "--out-dir", "{out}"], "two programs named 'alice'"),
    (["{tmp}/class", "--out-dir", "{out}", "--tests", "{tmp}/grading.py"], "--tests"),
])
def test_bad_input_is_one_line_exit_2_and_nothing_written(cli, tmp_path, args, message):
    make_class(tmp_path / "class", ["alice"])
    make_class(tmp_path / "other", ["alice"])
    (tmp_path / "empty").mkdir()
    (tmp_path / "afile").write_text("not a folder")
    fill = {"tmp": tmp_path, "out": tmp_path / "out"}
    proc = cli("batch", *[a.format(**fill) for a in args])
    assert proc.returncode == 2
    assert len(proc.stderr.strip().splitlines()) == 1, proc.stderr
    assert proc.stderr.startswith("springscene: error: ")
    assert message.format(**fill) in proc.stderr
    assert not (tmp_path / "out").exists()


@pytest.mark.skipif(importlib.util.find_spec("distributed") is None,
                    reason="Dask's distributed is not installed (the test extra has it)")
def test_a_cluster_gives_the_same_rows_and_videos(ran, tmp_path):
    """Through a real Dask LocalCluster of two workers: the program's bytes go to a
    worker, its files come back into DIR as from the local run."""
    import distributed  # noqa: PLC0415  heavy: distributed (in the test extra)
    _, local, _, _ = ran
    programs = make_class(tmp_path / "class", ["alice", "bob", "dave"])
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=":0") as cluster:
        proc = run_cli("batch", programs, "--out-dir", tmp_path / "out", *FLAGS, *SANDBOX,
                       "--scheduler", cluster.scheduler_address)
    assert proc.returncode == 0, proc.stderr
    remote, here = rows_of(tmp_path / "out"), rows_of(local)
    assert sorted(remote) == ["alice", "bob", "dave"]
    for name, row in remote.items():
        # how far a program got when it was stopped is as far as it had reported by then
        # (a report every 0.25 s): a time too
        times = TIMES + ("program",) + (("program_seconds", "frames")
                                         if row["status"] in ("memory", "timeout") else ())
        same = {k: v for k, v in here[name].items() if k not in times}
        assert {k: v for k, v in row.items() if k not in times} == same
    # (bob's page shows his traceback, which names where the program was: not the same)
    for file in ("alice/alice.mp4", "alice/alice.html", "alice/thumbnail.png", "bob/bob.mp4",
                 "bob/thumbnail.png"):
        assert (tmp_path / "out" / file).read_bytes() == (local / file).read_bytes(), file


def test_llvmpipe_threads_are_shared_among_the_jobs(monkeypatch):
    monkeypatch.delenv("LP_NUM_THREADS", raising=False)
    monkeypatch.setattr(os, "cpu_count", lambda: 8)
    assert job_environment(2)["LP_NUM_THREADS"] == "4"
    assert job_environment(16)["LP_NUM_THREADS"] == "1"
    monkeypatch.setenv("LP_NUM_THREADS", "3")
    assert job_environment(2) is None                 # the user's own choice kept


def test_a_folder_a_student_reads_its_own_folder_a_file_a_student_only_itself(tmp_path):
    lab = tmp_path / "lab"
    make_class(lab, ["alice"])                                  # lab/alice.py
    (lab / "bob").mkdir()                                      # lab/bob/: one program
    (lab / "bob" / "spring.py").write_text("from vpython import *\n")
    (lab / "carol").mkdir()                                    # lab/carol/: two, and a module
    (lab / "carol" / "part1.py").write_text("GlowScript 3.2 VPython\nbox()\n")
    (lab / "carol" / "part2.py").write_text("from visual import *\n")
    (lab / "carol" / "helpers.py").write_text("def f(): pass\n")
    (lab / "notes").mkdir()                                    # no program: left alone
    (lab / "readme.txt").write_text("not a program")
    found = {p.key: p for p in find_programs([str(lab)])}
    assert list(found) == ["alice", "bob", "carol/part1", "carol/part2"]
    assert found["alice"].readable == (lab / "alice.py",) and not found["alice"].folder
    assert found["bob"].readable == (lab / "bob",) and found["bob"].stem == "bob"
    assert found["carol/part2"].path == lab / "carol" / "part2.py"
    assert found["carol/part2"].stem == "part2"


def test_names_that_clash_are_bad_input(tmp_path):
    make_class(tmp_path / "a", ["alice"])
    make_class(tmp_path / "b", ["alice"])
    with pytest.raises(UserError, match="two programs named 'alice'"):
        find_programs([str(tmp_path / "a"), str(tmp_path / "b" / "alice.py")])
    (tmp_path / "x.txt").write_text("print(1)")
    with pytest.raises(UserError, match="x.txt: not a Python program"):
        find_programs([str(tmp_path / "x.txt")])


@pytest.fixture
def needs_a_sandbox():
    """Skip (fail in CI) where no sandbox can be made."""
    why = no_sandbox()
    if why is not None:
        if os.environ.get("SPRINGSCENE_REQUIRE_BACKENDS"):
            pytest.fail(f"a sandbox is required here: {why}")
        pytest.skip(f"no sandbox here: {why}")


NOSY = """from vpython import *
# A student's lab that reads another student's work: the sandbox keeps it from them.
box()
rate(50)
print(open({other!r}).read())
"""


def test_a_program_cannot_read_another_students_and_says_so_in_its_row(needs_a_sandbox,
                                                                        tmp_path):
    programs = make_class(tmp_path / "class", ["alice"])
    (programs / "mallory.py").write_text(NOSY.format(other=str(programs / "alice.py")))
    proc = run_cli("batch", programs, "--out-dir", tmp_path / "out", *FLAGS)   # sandboxed
    assert proc.returncode == 0, proc.stderr
    rows = rows_of(tmp_path / "out")
    assert rows["alice"]["status"] == "ran"
    assert rows["mallory"]["status"] == "sandbox"
    assert rows["mallory"]["detail"] == ("FileNotFoundError: [Errno 2] No such file or "
                                         f"directory: '{programs / 'alice.py'}' (line 5)")
    assert "ball ended" not in (tmp_path / "out" / "mallory" / "log.txt").read_text()


def test_where_no_sandbox_can_be_made_batch_says_why_and_writes_nothing(cli, tmp_path,
                                                                          monkeypatch):
    monkeypatch.setattr("springscene.batch.runs.no_sandbox", lambda: "bwrap is not installed")
    make_class(tmp_path / "class", ["alice"])
    proc = cli("batch", tmp_path / "class", "--out-dir", tmp_path / "out")
    assert proc.returncode == 2
    assert proc.stderr == ("springscene: error: no sandbox here: bwrap is not installed "
                           "(--no-sandbox runs the programs without one)\n")
    assert not (tmp_path / "out").exists()


GRADING = """import pytest

pytestmark = pytest.mark.vpython_program("lab.py", duration=0.5, fps=25)


@pytest.fixture
def run(vpython_run):
    return vpython_run()


def test_it_draws_a_sphere(run):
    assert run.objects.of_kind("sphere"), "there is no sphere"


@pytest.mark.weight(2)
def test_the_ball_moves_right(run):
    x = run["ball"].pos[:, 0]
    assert x[-1] > x[0] + 0.1, f"the ball went from x = {x[0]:.2f} m to {x[-1]:.2f} m"
"""


def test_tests_grade_each_programs_recording(tmp_path):
    programs = make_class(tmp_path / "class", ["alice", "bob", "dave"])
    (tmp_path / "grading.py").write_text(GRADING)
    proc = run_cli("batch", programs, "--out-dir", tmp_path / "out", "--tests",
                   tmp_path / "grading.py", "--max-memory", "600M", *SANDBOX)
    assert proc.returncode == 0, proc.stderr
    rows = rows_of(tmp_path / "out")
    assert rows["alice"]["frames"] == 12                    # the marker's 0.5 s at 25 fps
    assert (rows["alice"]["score"], rows["alice"]["max_score"]) == (3.0, 3.0)
    assert [t["passed"] for t in rows["alice"]["tests"]] == [True, True]
    assert (rows["bob"]["score"], rows["bob"]["max_score"]) == (0.0, 3.0)   # (up to its error)
    failed = {t["name"]: t["message"] for t in rows["bob"]["tests"]}
    assert "there is no sphere" in failed["test_it_draws_a_sphere"]
    assert rows["dave"]["score"] == 0.0 and rows["dave"]["status"] == "memory"
    assert all("over --max-memory 600M" in t["message"] for t in rows["dave"]["tests"])
    table = list(csv.DictReader(io.StringIO((tmp_path / "out" / "summary.csv").read_text())))
    assert table[0]["test test_the_ball_moves_right"] == "pass"
    assert table[1]["test test_it_draws_a_sphere"].startswith("fail: ")
    page = (tmp_path / "out" / "index.html").read_text()
    assert "<b>3 / 3</b>" in page and "<b>0 / 3</b>" in page and "there is no sphere" in page
    again = run_cli("batch", programs, "--out-dir", tmp_path / "out", "--tests",
                    tmp_path / "grading.py", "--max-memory", "600M", *SANDBOX)
    assert "3 of 3 programs done before" in again.stderr
    (tmp_path / "grading.py").write_text(GRADING + "\n")       # the tests changed: again
    third = run_cli("batch", programs, "--out-dir", tmp_path / "out", "--tests",
                    tmp_path / "grading.py", "--max-memory", "600M", *SANDBOX)
    assert "done before" not in third.stderr and rows_of(tmp_path / "out")["alice"]["score"] == 3
