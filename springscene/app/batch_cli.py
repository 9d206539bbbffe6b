"""``springscene batch PROGRAMS... --out-dir DIR``: a class's programs to videos and an index.

Flags, progress and exit statuses; the work is :func:`springscene.batch.runs.run_batch`.
Exit 0 once every program has run (whatever each program did: its row says), 1 when
springscene could not finish one (a write that failed), 2 for bad input, 130 on Ctrl-C
(the programs finished by then kept, the index written for them).
"""

from __future__ import annotations

import argparse
import os
import shutil
import sys
import tempfile
from pathlib import Path

from ..batch.grading import test_options
from ..batch.runs import DEFAULT_DURATION, DEFAULT_TIMEOUT, Settings, run_batch
from ..errors import UserError
from ..progress import tqdm_class
from ..video import DEFAULT_QUALITY, QUALITIES, VIDEO_SUFFIXES
from ..view.backend import BACKENDS
from ..vpython.run.options import DEFAULT_FPS, RunOptions, check_request
from ..vpython.run.report import machine_memory, memory_limit, size_text

FORMATS = tuple(suffix[1:] for suffix in VIDEO_SUFFIXES)


def add_batch_command(sub) -> None:
    s = sub.add_parser("batch", help="many VPython programs (a class's) to videos, pages, "
                       "summaries and one index page")
    s.add_argument("programs", nargs="+", metavar="PROGRAM",
                   help="program files, or folders of them: a .py file per student, or a "
                   "folder per student")
    s.add_argument("--out-dir", required=True, metavar="DIR",
                   help="where each program's files go (DIR/NAME/), with index.html, "
                   "summary.csv and summary.json (made if missing)")
    s.add_argument("--jobs", type=int, metavar="N",
                   help="programs run at once (default: the machine's cores)")
    s.add_argument("--scheduler", metavar="ADDRESS",
                   help="run the programs on this Dask cluster (tcp://host:8786) instead "
                   "of here (pip install 'springscene[dask]')")
    s.add_argument("--duration", type=float,
                   help=f"program seconds to film (default: the tests' vpython_program "
                   f"marker's, or with --tests until the program ends (at most 10 s); "
                   f"else {DEFAULT_DURATION:g})")
    s.add_argument("--fps", type=int,
                   help=f"frames per program second (default: the tests' marker's, else "
                   f"{DEFAULT_FPS})")
    s.add_argument("--timeout", type=float, metavar="S",
                   help=f"stop a program after S seconds of wall clock (default: the tests' "
                   f"marker's, else {DEFAULT_TIMEOUT:g})")
    s.add_argument("--max-memory", metavar="SIZE",
                   help="stop a program when it uses more memory, e.g. 500M or 2G (default: "
                   "half the machine's, shared among --jobs)")
    s.add_argument("--format", default="mp4", choices=FORMATS, help="the videos' format")
    s.add_argument("--tests", type=Path, metavar="FILE",
                   help="grading.py: test functions run on each program's recording")
    s.add_argument("--no-sandbox", action="store_true",
                   help="run the programs without the sandbox (they can read and write what "
                   "you can)")
    s.add_argument("--force", action="store_true",
                   help="run every program again (default: skip those done since they changed)")
    s.add_argument("--quiet", action="store_true", help="no progress bar, no line a program")
    s.add_argument("--backend", default="auto", choices=BACKENDS,
                   help="off-screen OpenGL: EGL, OSMesa, or auto (EGL if present)")
    s.add_argument("--draft", action="store_true", help="no anti-aliasing (faster)")
    s.add_argument("-q", "--quality", default=DEFAULT_QUALITY, choices=QUALITIES,
                   help="the videos' encoding: low, medium (the default) or high")


def settings_of(args: argparse.Namespace, jobs: int) -> Settings:
    """The flags as a batch's settings, checked before anything is written."""
    marked = test_options(args.tests) if args.tests is not None else {}
    asked = _asked(args, marked)
    frames = marked.get("frames") if args.duration is None else None
    options = RunOptions(duration=None if frames else asked["duration"], frames=frames,
                         fps=asked["fps"], backend=args.backend, antialias=not args.draft,
                         quality=args.quality)
    suffix = f".{args.format}"
    with tempfile.NamedTemporaryFile(suffix=".py") as probe:     # the options alone checked
        check_request(probe.name, Path(tempfile.gettempdir()) / f"check{suffix}", options)
    timeout = asked["timeout"]
    if not (timeout > 0 and timeout != float("inf")):
        raise UserError(f"--timeout {timeout:g}: must be a number of seconds above 0")
    max_memory = args.max_memory or marked.get("max_memory")
    if max_memory is None:
        max_memory = size_text(max(memory_limit(None) // jobs, 256 << 20)) \
            if machine_memory() else None
    else:
        memory_limit(max_memory)
    return Settings(options=options, suffix=suffix, timeout=timeout,
                    max_memory=max_memory, sandbox=not args.no_sandbox, tests=args.tests)


def _asked(args: argparse.Namespace, marked: dict) -> dict:
    """Duration, frames per second and timeout: the flag's, else what the tests' marker
    asks (``vpython_program("lab.py", duration=5, fps=100)``), else the batch's default;
    with tests, the run they would have (``springscene grade``'s: to the program's end, at
    most 10 s) rather than the batch's 3 s."""
    defaults = {"duration": None if args.tests is not None else DEFAULT_DURATION,
                "fps": DEFAULT_FPS, "timeout": DEFAULT_TIMEOUT}
    return {key: getattr(args, key) if getattr(args, key) is not None else
            marked.get(key, default) for key, default in defaults.items()}


def run_batch_command(args: argparse.Namespace) -> int:
    jobs = args.jobs if args.jobs is not None else (os.cpu_count() or 1)
    if jobs < 1:
        raise UserError(f"--jobs {jobs}: must be at least 1")
    settings = settings_of(args, jobs)
    show = _Progress(args.quiet)
    try:
        rows = run_batch(args.programs, args.out_dir, settings, jobs=jobs,
                         scheduler=args.scheduler, force=args.force, on_row=show.row,
                         on_plan=show.plan)
    finally:
        show.close()
    counts: dict[str, int] = {}
    for row in rows:
        counts[row["status"]] = counts.get(row["status"], 0) + 1
    if not args.quiet:
        said = ", ".join(f"{n} {status}" for status, n in sorted(counts.items()))
        print(f"wrote {Path(args.out_dir) / 'index.html'}: {len(rows)} programs ({said})")
    return 1 if counts.get("failed") else 0


class _Progress:
    """A bar with the time left on a terminal; else a line a program (nothing, quiet)."""

    def __init__(self, quiet: bool) -> None:
        self.quiet, self.bar = quiet, None

    def plan(self, total: int, skipped: int) -> None:
        if self.quiet:
            return
        if skipped:
            print(f"springscene: {skipped} of {total} programs done before (--force runs "
                  "them again)", file=sys.stderr)
        if sys.stderr.isatty() and total > skipped:
            size = shutil.get_terminal_size((80, 24))      # (a pty no one sized: 80 x 24)
            self.bar = tqdm_class()(total=total - skipped, desc="programs", unit=" program",
                                    file=sys.stderr, leave=False, ncols=size.columns,
                                    nrows=size.lines)

    def row(self, row: dict) -> None:
        if self.quiet:
            return
        line = (f"{row['name']}: {row['status']}" + (f" ({row['detail']})" if row.get("detail")
                                                      else "")
                + (f", {row['program_seconds']:.2f} s of program time"
                   if row.get("program_seconds") is not None else "")
                + (f", in {row['wall_seconds']:.1f} s" if row.get("wall_seconds") else "")
                + (f", grade {row['score']:g}/{row['max_score']:g}"
                   if row.get("max_score") is not None and row.get("score") is not None else ""))
        if self.bar is not None:
            self.bar.write(line, file=sys.stdout)
            self.bar.update(1)
        else:
            print(line, flush=True)

    def close(self) -> None:
        if self.bar is not None:
            self.bar.close()
