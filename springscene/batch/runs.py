"""``springscene batch``: many programs to their videos, pages and rows, and the index.

:func:`run_batch` finds the programs (:mod:`.plan`), skips those done before, runs the
rest on this machine (:mod:`.local`) or on a Dask cluster (:mod:`.cluster`), and after
each program writes ``index.html``, ``summary.csv`` and ``summary.json`` (:mod:`.index`)
for what is done. Each program's files are made in a hidden staging folder
(``DIR/.NAME.staging-PID``) and swapped into place whole once it has ended: a program
stopped part way leaves its earlier files (or none), never half of them.
"""

from __future__ import annotations

import json
import os
import shutil
import threading
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from ..errors import UserError
from ..outputs import check_writable_folder, remove_if_abandoned
from ..vpython.run.options import RunOptions
from ..vpython.run.sandbox import unavailable as no_sandbox
from . import job
from .cluster import connect, run_cluster, sandbox_missing
from .index import write_index
from .local import run_local
from .plan import RESULT, Program, find_programs, finished_row

DEFAULT_DURATION = 3.0          # program seconds a video, unless --duration
DEFAULT_TIMEOUT = 120.0         # s of wall clock a program may take, unless --timeout


@dataclass(frozen=True)
class Settings:
    """What every program of a batch is asked: the run's options (``duration``, ``fps``,
    ``antialias``, ``quality``, ...), the video's ``suffix``, the limits, the sandbox and
    the tests."""

    options: RunOptions = field(default_factory=lambda: RunOptions(duration=DEFAULT_DURATION))
    suffix: str = ".mp4"
    timeout: float | None = DEFAULT_TIMEOUT
    max_memory: str | None = None
    sandbox: bool = True
    tests: Path | None = None

    def fingerprint(self) -> dict:
        """The settings as a row keeps them: a rerun asked otherwise runs the program again."""
        return json.loads(json.dumps({    # (as read back from result.json: lists)
            "options": self.options.to_request(), "suffix": self.suffix,
            "timeout": self.timeout, "max_memory": self.max_memory, "sandbox": self.sandbox,
            "tests": None if self.tests is None else str(self.tests.resolve())}))


@dataclass
class Item:
    """One program to run: its staging folder and the job's request."""

    program: Program
    staging: Path
    request: dict

    def discard(self) -> None:
        shutil.rmtree(self.staging, ignore_errors=True)


class Batch:
    """A batch under way: its rows so far, written out after each program."""

    def __init__(self, programs: list[Program], out_dir: Path, settings: Settings,
                 on_row: Callable[[dict], None] | None) -> None:
        self.programs, self.out_dir, self.settings = programs, out_dir, settings
        self.rows: dict[str, dict] = {}
        self.lock = threading.Lock()           # (programs end in several threads)
        self.on_row = on_row or (lambda row: None)

    def item(self, program: Program) -> Item:
        final = self.out_dir / program.key
        staging = final.parent / f".{final.name}.staging-{os.getpid()}"
        s = self.settings
        request = job.request(program.path.resolve(), staging.resolve(), program.stem,
                              suffix=s.suffix, options=s.options, timeout=s.timeout,
                              max_memory=s.max_memory, sandbox=s.sandbox,
                              readable=tuple(p.resolve() for p in program.readable),
                              folder_of_its_own=program.folder,
                              tests=None if s.tests is None else s.tests.resolve(),
                              settings=s.fingerprint())
        return Item(program, staging, request)

    def done(self, item: Item, status: int) -> None:
        """A program's job has ended: its folder swapped into place, its row added, the
        index and summaries written again."""
        row = _read_row(item.staging, status)
        with self.lock:
            _swap(item.staging, self.out_dir / item.program.key)
            self.add(item.program, row)

    def add(self, program: Program, row: dict) -> None:
        self.rows[program.key] = row = self.named(program, row)
        self.write()
        self.on_row(row)

    def named(self, program: Program, row: dict) -> dict:
        """A job's row with the program's name and path (as given here)."""
        return {**row, "name": program.key, "program": str(program.path),
                "settings": self.settings.fingerprint()}

    def write(self) -> None:
        rows = [self.rows[p.key] for p in self.programs if p.key in self.rows]
        write_index(self.out_dir, rows, len(self.programs))


def _read_row(staging: Path, status: int) -> dict:
    """The job's row (``result.json``); a job that ended without one (springscene's own
    failure) is a ``failed`` row naming the last line of its log."""
    try:
        return json.loads((staging / RESULT).read_text())
    except (OSError, ValueError):
        pass
    try:
        lines = (staging / job.LOG).read_text(errors="replace").strip().splitlines()
    except OSError:
        lines = []
    return {"status": "failed", "detail": lines[-1] if lines else
            f"the program's process ended with status {status}", "frames": 0,
            "program_seconds": None, "wall_seconds": None, "files": {"log": job.LOG}
            if (staging / job.LOG).is_file() else {}}


def _swap(staging: Path, final: Path) -> None:
    """``staging`` becomes ``final``; the folder it replaces is removed after."""
    old = final.parent / f".{final.name}.old-{os.getpid()}"
    if final.exists():
        os.replace(final, old)
    os.replace(staging, final)
    shutil.rmtree(old, ignore_errors=True)


def prepare_out_dir(out_dir: Path) -> None:
    """``DIR`` made if missing and writable (bad input otherwise); what a batch killed
    outright left (staging folders whose process is gone) removed."""
    try:
        out_dir.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise UserError(f"--out-dir {out_dir}: cannot make it ({exc.strerror})") from None
    if not out_dir.is_dir():
        raise UserError(f"--out-dir {out_dir}: is not a folder")
    check_writable_folder(out_dir, out_dir / "index.html", "--out-dir")
    for left in out_dir.rglob(".*.staging-*"):
        remove_if_abandoned(left, left.name.rsplit("-", 1)[-1])
    for left in out_dir.rglob(".*.old-*"):
        remove_if_abandoned(left, left.name.rsplit("-", 1)[-1])


def run_batch(paths: list[str], out_dir: str | Path, settings: Settings = Settings(), *,
              jobs: int | None = None, scheduler: str | None = None, force: bool = False,
              on_row: Callable[[dict], None] | None = None,
              on_plan: Callable[[int, int], None] | None = None) -> list[dict]:
    """Run the programs of ``paths`` (files and folders: :mod:`.plan`) into ``out_dir``,
    ``jobs`` at a time (default: the machine's cores) or on the Dask cluster at
    ``scheduler``; the rows, in the order of the programs' names. ``on_plan(total,
    skipped)`` is told before anything runs, ``on_row(row)`` after each program."""
    programs = find_programs(paths)
    out_dir = Path(out_dir)
    if jobs is not None and jobs < 1:
        raise UserError(f"--jobs {jobs}: must be at least 1")
    if settings.tests is not None and not settings.tests.is_file():
        raise UserError(f"--tests {settings.tests}: no such file")
    client = connect(scheduler) if scheduler is not None else None
    try:
        if settings.sandbox:
            _check_sandbox(client)
        prepare_out_dir(out_dir)
        return _run(Batch(programs, out_dir, settings, on_row), client, jobs, force, on_plan)
    finally:
        if client is not None:
            client.close()


def _check_sandbox(client) -> None:
    """Bad input where the programs cannot run in a sandbox (here, or on a worker)."""
    why = no_sandbox() if client is None else sandbox_missing(client)
    if why is not None:
        raise UserError(f"no sandbox {'here' if client is None else 'on the cluster'}: {why} "
                        "(--no-sandbox runs the programs without one)")


def _run(batch: Batch, client, jobs: int | None, force: bool,
         on_plan: Callable[[int, int], None] | None) -> list[dict]:
    """The programs not done before, run here (``jobs`` at a time) or on ``client``'s
    cluster; every program's row."""
    programs, out_dir, settings = batch.programs, batch.out_dir, batch.settings
    todo = []
    for program in programs:
        row = None if force else finished_row(program, out_dir, settings.fingerprint(),
                                              settings.tests)
        if row is None:
            todo.append(batch.item(program))
        else:
            batch.rows[program.key] = batch.named(program, row)
    if on_plan is not None:
        on_plan(len(programs), len(programs) - len(todo))
    batch.write()
    if client is not None:
        run_cluster(client, todo, batch.done, settings.tests)
    else:
        jobs = jobs or os.cpu_count() or 1
        run_local(todo, jobs, batch.done, env=job_environment(jobs))
    return [batch.rows[p.key] for p in programs]


def job_environment(jobs: int) -> dict | None:
    """The environment of each job: llvmpipe's threads (``LP_NUM_THREADS``) shared out
    among the jobs running at once, unless the user set them."""
    if "LP_NUM_THREADS" in os.environ:
        return None
    cores = os.cpu_count() or 1
    return {**os.environ, "LP_NUM_THREADS": str(max(1, cores // jobs))}
