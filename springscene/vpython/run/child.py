"""The child process of a supervised run (:mod:`.supervise`): the user's program runs here.

Started by the parent as a fresh interpreter (``python -c`` importing this module), or
in a batch forked from a warm process that never drew (:mod:`.forked`), so that no VTK or
EGL state is ever forked, with three arguments: the file descriptor of a pipe to the
parent, the parent's pid and the request as JSON. It runs :func:`.runner.run_program`
into the parent's private folder and tells the parent, one JSON object a line:
``dialect`` (before the program runs), ``progress`` (every :data:`PROGRESS_EVERY` s: the
program clock, frames, ``rate``/``sleep`` calls and the program's line now) and one
ending (``done`` with the result, or ``program``, ``exit``, ``user``, ``oserror``,
``interrupted``, ``internal``; a ``program`` error after the first frame carries the
result too, its files written up to the error).
Whatever is not said on the pipe (``os._exit``, a signal, a crash) the parent reads from
the exit status.
"""

from __future__ import annotations

import atexit
import gc
import json
import os
import sys
import threading
import time
import traceback
from pathlib import Path

from ...errors import ProgramError, UserError
from . import lineage
from ..core import runtime
from .options import RunOptions
from .runner import ProgramExit, ProgramRaised, _user_traceback, run_program

PROGRESS_EVERY = 0.25       # seconds of wall clock between progress reports


class Reporter:
    """Writes the messages to the parent; if the parent is gone, this process ends."""

    def __init__(self, fd: int) -> None:
        self.pipe = os.fdopen(fd, "w", encoding="utf-8")
        self.lock = threading.Lock()

    def send(self, kind: str, **fields) -> None:
        line = json.dumps({"kind": kind, **fields}, default=_plain) + "\n"
        with self.lock:
            try:
                self.pipe.write(line)
                self.pipe.flush()
            except (BrokenPipeError, OSError):  # nobody to report to: the parent was killed
                lineage.parent_gone()

    def end(self, kind: str, **fields) -> None:
        """How the run ended, once the program's output is flushed, with the names of the
        threads it left running (the parent ends this process rather than wait for them)."""
        flush_output()
        lineage.join_workers()          # its multiprocessing workers finish, as Python's
        lineage.end_descendants()       # what the program started dies with its run
        lingering = [t.name for t in threading.enumerate()
                     if t is not threading.main_thread() and not t.daemon and t.is_alive()]
        self.send(kind, threads=lingering, **fields,
                  progress=progress(runtime.last(), None))


def flush_output() -> None:
    """The program's printed output flushed, unless the program closed (or broke) a stream."""
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError, AttributeError):
            pass


def _plain(value):
    """A value JSON can carry: a number as a float, anything else as its repr."""
    try:
        return float(value)
    except (TypeError, ValueError, OverflowError):
        return repr(value)[:60]


def progress(timeline: runtime.Timeline | None, where: int | None) -> dict:
    """What the parent needs to say why no frame comes."""
    if timeline is None:
        return {"started": False, "line": where}
    kind, arg = timeline.last_call
    return {"started": True, "clock": float(timeline.clock), "frames": timeline.frames,
            "fps": timeline.fps, "calls": timeline.calls + timeline.sleeps, "call": kind, "arg": _plain(arg),
            "span": float(timeline.last_span), "line": where,
            "ended": runtime.current() is None}     # the program's end: its files finishing


def program_line(thread_id: int, program: str) -> int | None:
    """The line of ``program`` the thread ``thread_id`` is running now (innermost)."""
    frame = sys._current_frames().get(thread_id)
    while frame is not None:
        if frame.f_code.co_filename == program:
            return frame.f_lineno
        frame = frame.f_back
    return None


def _watch(reporter: Reporter, thread_id: int, program: str) -> None:
    while True:
        time.sleep(PROGRESS_EVERY)
        reporter.send("progress", **progress(runtime.last(), program_line(thread_id,
                                                                         program)))


def _watch_reads(folder: Path) -> set[str]:
    """The files in ``folder`` (the output's folder) that this process opens to read, from
    now on (an audit hook: the program's ``open`` calls among them): the parent will not
    write an output over one of them."""
    read: set[str] = set()
    folder = os.path.realpath(folder)

    def hook(event: str, args) -> None:
        if event != "open" or len(read) > 10_000 or isinstance(args[0], int):
            return
        mode, flags = args[1], args[2] or 0
        writes = any(c in mode for c in "wax+") if isinstance(mode, str) \
            else flags & (os.O_WRONLY | os.O_RDWR)
        if not writes:
            try:
                path = os.path.realpath(os.fsdecode(args[0]))
            except (TypeError, ValueError):
                return
            if os.path.dirname(path) == folder:
                read.add(path)

    sys.addaudithook(hook)
    return read


def _files(result, read: set[str]) -> dict:
    """A finished result as the parent reads it, to move its files into place."""
    return dict(path=str(result.path), frames=result.frames, fps=result.fps,
                read=sorted(read),
                program_seconds=result.program_seconds, ended=result.ended,
                size=list(result.size) if result.size else None, dialect=result.dialect,
                page=str(result.page) if result.page else None,
                recording=str(result.recording) if result.recording else None,
                images=list(dict.fromkeys(str(p) for p in result.images)),
                notes=result.notes, error=result.error)


def _raised(reporter: Reporter, exc: ProgramRaised, read: set[str]) -> None:
    """The program's own error: its traceback, and its files when the run wrote them up
    to the error (the parent moves them, then reports the error)."""
    if exc.result is None:
        reporter.end("program", message=exc.traceback, error=exc.error)
    else:
        reporter.end("program", message=exc.traceback, **_files(exc.result, read))


def run(reporter: Reporter, request: dict) -> None:
    """Run the request and report how it ended."""
    program, out = request["program"], request["out"]
    options = RunOptions.from_request(request["options"])
    read = _watch_reads(Path(out).parent.parent)     # out is in the private folder

    def on_frame(index: int, image) -> None:       # the parent knows where a death came
        reporter.send("progress", **progress(runtime.current(), None), taken=index + 1)

    try:
        result = run_program(program, out, options, on_frame=on_frame,
                             on_end=lineage.end_if_copy,
                             on_dialect=lambda d: reporter.send("dialect", name=d.name,
                                                                dialect_kind=d.kind,
                                                                notes=list(d.notes)))
    except ProgramExit as exc:
        reporter.end("exit", status=exc.status, said=exc.said, message=str(exc))
    except ProgramRaised as exc:
        _raised(reporter, exc, read)
    except ProgramError as exc:
        reporter.end("program", message=str(exc))
    except UserError as exc:
        reporter.end("user", message=str(exc))
    except OSError as exc:
        reporter.end("oserror", errno=exc.errno, strerror=exc.strerror,
                      reason=getattr(exc, "reason", None),
                      filename=str(exc.filename) if exc.filename else None)
    except KeyboardInterrupt as exc:
        # the program's own (springscene's Ctrl-C goes to the parent, which kills this
        # process group): its error, with its traceback, as Python would show it
        reporter.end("program", message=_user_traceback(exc))
    except Exception:                       # a fault in springscene itself
        reporter.end("internal", message=traceback.format_exc().rstrip("\n"))
    else:
        reporter.end("done", **_files(result, read))


def main(argv: list[str] | None = None) -> int:
    fd, parent, request = (argv or sys.argv[1:])[:3]
    request = json.loads(request)
    lineage.die_with_parent(int(parent), Path(request["out"]).parent,
                            request.pop("parent_thread", None))
    reporter = Reporter(int(fd))
    lineage.guard_forks(int(fd))
    threading.Thread(target=_watch, name="springscene-progress", daemon=True,
                     args=(reporter, threading.get_ident(),
                           str(Path(request["program"])))).start()
    run(reporter, request)
    if not any(t.is_alive() and not t.daemon for t in threading.enumerate()
               if t is not threading.main_thread()):
        gc.collect()                # the program's unclosed files are flushed and closed
        atexit._run_exitfuncs()     # its exit functions; then skip tearing down VTK (0.3 s)
        flush_output()
        os._exit(0)
    return 0                        # the parent ends the threads left running


if __name__ == "__main__":
    sys.exit(main())
