"""The batch's warm process (springscene.batch.warm, springscene.vpython.run.forked).

A batch's job processes are forked from one warm process, and an unsandboxed program's
child from its job process. The program must not be able to tell: a probe program
(tests/vpython_programs/batch_probe.py) prints what it finds as it starts, forked and
fresh, and the two must agree but for what is random (which must differ from fork to
fork) and the ``/dev/null`` a fork's released descriptors point at; the videos must be
byte-identical. Where the warm process cannot start, or dies, the jobs start fresh.
"""

from __future__ import annotations

import json
import os
import signal
import time
from collections import Counter
from pathlib import Path
from types import SimpleNamespace

import pytest

from conftest import ROOT, process_alive
from springscene.batch import job, local, warm
from springscene.batch.plan import RESULT
from springscene.vpython.run import lineage
from springscene.vpython.run.options import RunOptions

# each test starts the warm process, a fresh interpreter, and job processes through it
pytestmark = pytest.mark.slow

PROBE = ROOT / "tests" / "vpython_programs" / "batch_probe.py"
HANGS = ROOT / "tests" / "vpython_programs" / "batch_hangs.py"


def request(program: Path, folder: Path, **options) -> dict:
    return job.request(program, folder, program.stem, suffix=".mp4",
                       options=RunOptions(**{"duration": 1.0, "fps": 25, **options}),
                       timeout=60, max_memory="1G", sandbox=False, readable=(),
                       folder_of_its_own=False, tests=None, settings={})


def probe(folder: Path) -> dict:
    line = next(line for line in (folder / job.LOG).read_text().splitlines()
                if line.startswith("PROBE "))
    return json.loads(line[len("PROBE "):])


@pytest.fixture(scope="module")
def runs(tmp_path_factory):
    """The probe run twice forked from one warm process, then once fresh."""
    base = tmp_path_factory.mktemp("warm")
    # the batch's environment, given to both alike (this process's own, as Python knows
    # it: a library here may have added to the C library's, which only a child inherits)
    env = {**os.environ, "SPRINGSCENE_PROBE": "given"}
    server = warm.Warm(env)
    try:
        assert server.failure() is None
        forks = [server.start(request(PROBE, base / name)) for name in ("one", "two")]
        statuses = [fork.wait() for fork in forks]
    finally:
        server.close()
    statuses.append(job.start(request(PROBE, base / "fresh"), env).wait())
    return base, statuses


def test_forked_and_fresh_jobs_both_run_the_program(runs):
    base, statuses = runs
    assert statuses == [0, 0, 0]
    for name in ("one", "two", "fresh"):
        row = json.loads((base / name / RESULT).read_text())
        assert (row["status"], row["frames"]) == ("ran", 25), name


def test_the_program_was_forked_from_the_warm_process_or_started_fresh(runs):
    base, _ = runs
    assert "springscene.batch.warm import serve" in probe(base / "one")["started_as"]
    assert "springscene.vpython.run.child import main" in probe(base / "fresh")["started_as"]


def test_a_forked_program_finds_what_a_fresh_one_finds(runs):
    base, _ = runs
    forked, fresh = probe(base / "one"), probe(base / "fresh")
    for fact in ("own_group", "handlers", "blocked", "openblas", "environment", "argv", "name",
                 "threads"):
        assert forked[fact] == fresh[fact], fact
    assert forked["own_group"] and forked["blocked"] == []
    assert forked["environment"]["SPRINGSCENE_PROBE"] == "given"
    assert forked["path"] == fresh["path"]
    assert Path(forked["cwd"]).name == "one" and Path(fresh["cwd"]).name == "fresh"
    # its open files are the fresh one's, and /dev/null where the fork let go of its parents'
    opened = Counter(forked["descriptors"])
    assert set(opened) - set(fresh["descriptors"]) <= {"null"}
    assert opened - Counter({"null": opened["null"]}) == \
        Counter(fresh["descriptors"]) - Counter({"null": fresh["descriptors"].count("null")})


def test_each_fork_has_its_own_random_numbers(runs):
    base, _ = runs
    one, two = probe(base / "one"), probe(base / "two")
    assert one["numpy"] != two["numpy"] and one["random"] != two["random"]


def test_forked_and_fresh_videos_are_byte_identical(runs):
    base, _ = runs
    videos = [(base / name / "batch_probe.mp4").read_bytes() for name in ("one", "two", "fresh")]
    assert videos[0] == videos[1] == videos[2]


def test_no_warm_process_then_none_is_used(monkeypatch):
    monkeypatch.setattr(warm, "SERVE", "import sys; sys.exit('springscene: no warmth here')")
    server = warm.Warm(None)
    try:
        assert server.failure() == "springscene: no warmth here"
        assert server.start({"folder": "/nonexistent"}) is None
    finally:
        server.close()


def test_a_warm_process_that_dies_ends_its_jobs_and_serves_no_more(tmp_path):
    """Killed outright while a program runs: its job ends (SIGTERM from the kernel), the
    program's processes with it, and the batch starts the next jobs fresh."""
    server = warm.Warm(None)
    try:
        running = server.start(request(HANGS, tmp_path / "hangs", duration=30.0))
        log = tmp_path / "hangs" / job.LOG
        deadline = time.monotonic() + 60
        while not lineage.descendants(running.pid) and time.monotonic() < deadline:
            time.sleep(0.1)
        program = lineage.descendants(running.pid)       # the program's process, ...
        assert program
        os.kill(server.process.pid, signal.SIGKILL)
        assert running.wait() == 1
        assert not any(process_alive(pid) for pid in program), log.read_text()
        assert server.start(request(PROBE, tmp_path / "after")) is None
    finally:
        server.close()


def test_without_a_warm_process_the_batch_starts_its_jobs_fresh(monkeypatch, tmp_path, capsys):
    monkeypatch.setattr(warm, "SERVE", "import sys; sys.exit('springscene: no warmth here')")
    items = [SimpleNamespace(request=request(PROBE, tmp_path / name, duration=0.2),
                             discard=lambda: None) for name in ("one", "two")]
    ended = {}
    local.run_local(items, 2, lambda item, status: ended.update({item.request["folder"]:
                                                                 status}))
    assert sorted(ended.values()) == [0, 0]
    for name in ("one", "two"):
        assert "springscene.batch.job import main" in _parent_command(tmp_path / name)
        assert "springscene.vpython.run.child import main" in \
            probe(tmp_path / name)["started_as"]
    assert "no warm process (springscene: no warmth here); each program starts fresh" \
        in capsys.readouterr().err


def _parent_command(folder: Path) -> str:
    """How the job process that ran the probe in ``folder`` was started (its log's line)."""
    return probe(folder)["parent_started_as"]


def test_signals_ignored_where_the_batch_runs_stay_ignored_as_in_a_fresh_program(tmp_path):
    """A batch started in the background (``&``, ``nohup``) ignores SIGINT or SIGHUP, and
    so do its fresh children; a forked one must too (and a caught signal is at its
    default, as after an exec)."""
    ignored = (signal.SIGINT, signal.SIGHUP)
    saved = {signum: signal.signal(signum, signal.SIG_IGN) for signum in ignored}
    try:
        server = warm.Warm(dict(os.environ))
        try:
            assert server.start(request(PROBE, tmp_path / "forked")).wait() == 0
        finally:
            server.close()
        assert job.start(request(PROBE, tmp_path / "fresh"), dict(os.environ)).wait() == 0
    finally:
        for signum, handler in saved.items():
            signal.signal(signum, handler)
    forked, fresh = probe(tmp_path / "forked"), probe(tmp_path / "fresh")
    assert forked["handlers"] == fresh["handlers"]
    assert forked["handlers"]["SIGINT"] == forked["handlers"]["SIGHUP"] == "1"  # SIG_IGN
