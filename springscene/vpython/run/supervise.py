"""A supervised run: the user's program runs in a child process; this process owns the output.

The child (:mod:`.child`: a fresh interpreter, or in a batch a fork of a warm process that
never drew, :mod:`.forked`; nothing is forked after a GL context exists) writes the
video, the page, the graphs and ``scene.capture`` pictures into a private hidden folder
beside ``out``; only when it reports them finished are they moved into place here, one
``os.replace`` each (the video last). Whatever the child does, the folder is removed and
the run ends in one of these ways (:class:`RunEnded` carries the status and the one
line):

============================================  ====================================
the program ends (or ``sys.exit(0)``)          the files, exit 0
it raises                                      its own traceback, exit 1 (after its
                                               first frame, with the files up to the
                                               error: :class:`.runner.ProgramRaised`)
``sys.exit(n)``                                exit n, as Python gives
``os._exit(n)`` before the video is finished   exit n (1 for ``os._exit(0)``)
killed by a signal (a segfault, the OOM        exit 128 + signal
killer's SIGKILL)
over ``--max-memory``                          killed, exit 137 (as the OOM killer's)
over ``--timeout``                             killed, exit 124 (as coreutils' timeout)
a thread left running after the program ends   the files, the child killed, exit 0
processes it started (forks, daemons)          the files, those killed (:mod:`.lineage`)
============================================  ====================================

With a :class:`.sandbox.Sandbox`, the child interpreter starts inside bubblewrap (its
command line from :mod:`.sandbox`): the process watched here is bwrap's, the memory is the
sandboxed interpreter's and its children's (:class:`.report.SandboxMemory`), a kill ends
the sandbox's first process and so everything inside, and bwrap's ``128 + signal`` of a
killed interpreter is read as that signal. A read or write outside the sandbox is the
program's own error (exit 1). Where no sandbox can be made, :class:`UserError` says why.

Each abnormal ending is one line with the peak memory and the program time reached.
While no frame comes for :data:`STALL_AFTER` s of wall clock, the reason is said (what
``rate``/``sleep`` do to the program clock, or the program's line when it calls neither).
"""

from __future__ import annotations

import contextlib
import dataclasses
import errno
import glob
import json
import os
import select
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
import types
from pathlib import Path
from typing import Callable

from ...errors import OutputError, ProgramError, UserError
from ...outputs import hidden_name, remove_if_abandoned
from . import forked
from .options import RunOptions, check_request
from .runner import ProgramRaised, ProgramResult
from .report import (SandboxMemory, Watch, ended_line, memory_limit, parse_size, peak_of,
                     rss_of)
from .sandbox import Sandbox, command as sandbox_command, unavailable as no_sandbox

POLL = 0.02                 # s: how often the child's memory and the clock are checked
# the child in a process group of its own (Popen's process_group is Python 3.11's)
_OWN_GROUP = {"process_group": 0} if sys.version_info >= (3, 11) else {"preexec_fn": os.setpgrp}
GRACE = 5.0                 # s the child may take to exit after its report
STALL_AFTER = 10.0          # s of wall clock without a frame before the reason is said
STALL_AGAIN = 30.0          # s between further such lines
EXIT_TIMEOUT = 124
EXIT_MEMORY = 128 + signal.SIGKILL
_ROOT = str(Path(__file__).resolve().parents[3])      # where springscene is


class RunEnded(Exception):
    """The run ended without its files: ``status`` is the exit status, ``str()`` the line."""

    def __init__(self, status: int, line: str) -> None:
        super().__init__(line)
        self.status = status


def run_supervised(program, out, options: RunOptions = RunOptions(), *,
                   timeout: float | None = None, max_memory: int | str | None = None,
                   on_dialect: Callable | None = None, say: Callable | None = None,
                   stall_after: float = STALL_AFTER,
                   sandbox: Sandbox | None = None) -> ProgramResult:
    """:func:`.runner.run_program`'s run in a child process, with ``timeout`` (seconds of
    wall clock) and ``max_memory`` (bytes, or a size such as ``"2G"``), inside ``sandbox``
    if one is given. ``say(line)`` gets the diagnoses while no frame comes (default:
    stderr). Raises :class:`RunEnded`, :class:`ProgramError` or :class:`UserError`."""
    why = no_sandbox() if sandbox is not None else None
    if why is not None:
        raise UserError(f"--sandbox: no sandbox here: {why}")
    checked = check_request(program, out, options)
    path, out = checked.program, checked.out
    limit = memory_limit(max_memory)
    if timeout is not None and not (timeout > 0 and timeout != float("inf")):
        raise UserError(f"--timeout {timeout:g}: must be a number of seconds above 0")
    watch = Watch(path, limit, timeout, stall_after, STALL_AGAIN,
                  say or (lambda line: print(line, file=sys.stderr, flush=True)))
    _remove_abandoned(out)
    try:
        # absolute: the program may change its working folder before it writes there
        folder = Path(tempfile.mkdtemp(prefix=f"{hidden_name(out)}.{os.getpid()}.", suffix=".run",
                                       dir=os.path.abspath(out.parent or ".")))
    except OSError as exc:
        raise UserError(f"--out {out}: cannot write there ({exc.strerror})") from None
    try:
        with _stop_signals(), _janitor(folder, sandbox is not None):
            # the child writes every file in the private folder; they move out when whole
            child_options = options if options.record is None else dataclasses.replace(
                options, record=str(folder / Path(options.record).name))
            # (absolute in a sandbox: the child starts in another working folder there)
            shown = str(path) if sandbox is None else os.path.abspath(path)
            request = {"program": shown, "out": str(folder / out.name),
                       "options": child_options.to_request(),
                       "parent_thread": threading.get_native_id()}   # (see .lineage)
            jail = None if sandbox is None else sandbox_command(sandbox, path, folder)
            report = _supervise(_start(request, jail), watch, on_dialect)
            return _finish(report, watch, folder, out,
                           Path(options.record) if options.record is not None else None)
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def _remove_abandoned(out: Path) -> None:
    """The private folders of earlier runs to ``out`` whose springscene was killed outright
    (SIGKILL leaves no chance to clean up): their process is gone, so they go too."""
    for folder in (out.parent or Path(".")).glob(f"{glob.escape(hidden_name(out))}.*.run"):
        remove_if_abandoned(folder, folder.name[:-len(".run")].rsplit(".", 2)[-2])


@contextlib.contextmanager
def _stop_signals():
    """SIGTERM and SIGHUP end the run like an error (the child killed, the folder removed,
    exit 128 + signal) where nobody handles them already (``springscene.app.signals``
    does for the command)."""
    def stop(signum, frame):
        raise RunEnded(128 + signum, f"springscene: interrupted ({signal.Signals(signum).name})")

    saved = {}
    if threading.current_thread() is threading.main_thread():
        for signum in (signal.SIGTERM, signal.SIGHUP):
            if signal.getsignal(signum) == signal.SIG_DFL:
                saved[signum] = signal.signal(signum, stop)
    try:
        yield
    finally:
        for signum, handler in saved.items():
            signal.signal(signum, handler)


# removes the folder named by $0 once its stdin ends (a second try if a dying process
# inside was still writing there)
_SWEEP = 'read _; rm -rf -- "$0" 2>/dev/null || { sleep 1; rm -rf -- "$0"; }'


@contextlib.contextmanager
def _janitor(folder: Path, needed: bool):
    """For a sandboxed run: a shell outside the sandbox that removes the run's folder if
    springscene is killed outright (SIGKILL: bwrap then kills everything inside, and
    nobody there could remove it). It waits for the end of a pipe only this process
    holds; the run's end here ends it."""
    if not needed:
        yield
        return
    janitor = subprocess.Popen(["/bin/sh", "-c", _SWEEP, str(folder)], stdin=subprocess.PIPE,
                               stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL,
                               **_OWN_GROUP)
    try:
        yield
    finally:
        janitor.kill()
        janitor.wait()
        janitor.stdin.close()


def _start(request: dict, jail: list[str] | None = None) -> subprocess.Popen:
    """The child: a fresh interpreter in its own process group (a terminal's Ctrl-C reaches
    this process, which ends the child), reporting on a pipe; started by ``jail`` (a
    sandbox's command line), if given, which knows no parent (``0``: see :mod:`.lineage`)
    and reads nothing from this process's terminal. In a warm process (a batch's job) an
    unsandboxed child is forked from it (:mod:`.forked`)."""
    read, write = os.pipe()
    argv = [str(write), str(0 if jail else os.getpid()), json.dumps(request)]
    # not the working folder on the path (the program's own folder goes there), and this
    # springscene found last where no installation provides it
    code = (f"import sys; sys.path.pop(0); sys.path.append({_ROOT!r}); "
            "from springscene.vpython.run.child import main; sys.exit(main())")
    try:
        if jail is None and forked.ready():
            child = types.SimpleNamespace(pid=forked.start(write, argv), returncode=None)
        else:
            child = subprocess.Popen([*(jail or []), sys.executable, "-c", code, *argv],
                                     pass_fds=(write,), **_OWN_GROUP,
                                     stdin=subprocess.DEVNULL if jail else None)
    except BaseException:
        os.close(read)
        raise
    finally:
        os.close(write)
    child.report_fd = read
    child.sandbox = SandboxMemory(child.pid) if jail else None
    return child


def _supervise(child: subprocess.Popen, watch: Watch, on_dialect) -> dict:
    """Read the child's reports until it has ended; its last report (or none) with its
    exit status under ``"process_status"``. Once the child has ended, what it wrote and
    this loop had not read yet is read to the end (a report written just before it
    exited is not lost)."""
    state = {"buffer": b"", "report": None}
    fd, status = child.report_fd, None
    try:
        while status is None:
            if fd is not None and select.select([fd], [], [], POLL)[0]:
                fd = _read(fd, state, watch, on_dialect)
            elif fd is None:
                time.sleep(POLL)
            status = _check(child, watch, state["report"])
        drained = time.monotonic() + GRACE      # (bounded: not a pipe someone keeps full)
        while fd is not None and select.select([fd], [], [], 0)[0] and \
                time.monotonic() < drained:
            fd = _read(fd, state, watch, on_dialect)
    finally:
        if fd is not None:
            os.close(fd)
        _kill(child)
    return {**(state["report"] or {}), "process_status": status}


def _read(fd: int, state: dict, watch: Watch, on_dialect) -> int | None:
    """One read of the report pipe, its whole lines handled; None once it is closed."""
    data = os.read(fd, 1 << 16)
    if not data:
        os.close(fd)
        fd = None
    state["buffer"] += data
    *lines, state["buffer"] = state["buffer"].split(b"\n")
    for message in map(_message, lines):
        if message["kind"] == "progress":
            if state["report"] is None:
                watch.progress(message)
        elif message["kind"] == "dialect":
            watch.dialect = message["name"]
            if on_dialect is not None:
                on_dialect(types.SimpleNamespace(name=message["name"],
                                                 kind=message["dialect_kind"],
                                                 notes=message.get("notes", [])))
        elif state["report"] is None:
            state["report"] = message
            if message.get("progress", {}).get("started"):
                watch.progress(message["progress"])
            watch.reported = time.monotonic()
    return fd


def _message(line: bytes) -> dict:
    try:
        message = json.loads(line)
    except ValueError:                  # not the child's report (the program wrote there)
        return {"kind": "progress"}
    return message if isinstance(message, dict) and "kind" in message else {"kind": "progress"}


def _check(child: subprocess.Popen, watch: Watch, report: dict | None) -> int | None:
    """The child's exit status once it has ended (or been ended here), else None."""
    pid, wait, usage = os.wait4(child.pid, os.WNOHANG)
    if pid:
        child.returncode = _status(child, wait)
        watch.peak = max(watch.peak, usage.ru_maxrss * 1024)
        return child.returncode
    rss, peak = child.sandbox() if child.sandbox else (rss_of(child.pid), peak_of(child.pid))
    watch.peak = max(watch.peak, peak)
    if report is not None:
        if report.get("threads") or time.monotonic() - watch.reported > GRACE:
            _kill(child)        # its work is done; a thread it left would keep it forever
            return 0
        return None
    if rss > watch.limit:
        _kill(child)
        watch.killed = ("memory", rss)
    elif watch.timeout is not None and time.monotonic() - watch.start > watch.timeout:
        _kill(child)
        watch.killed = ("timeout", None)
    else:
        watch.check_stall()
        return None
    return -signal.SIGKILL


def _status(child: subprocess.Popen, wait: int) -> int:
    """The child's exit status: bwrap's ``128 + n`` for an interpreter killed by signal
    ``n`` is that signal's ``-n`` (as a child killed outside a sandbox)."""
    status = os.waitstatus_to_exitcode(wait)
    if child.sandbox and 128 < status <= 128 + signal.SIGRTMAX:
        return 128 - status
    return status


def _kill(child: subprocess.Popen) -> None:
    """End the child and its process group at once (what the program started in it too,
    even when the child itself has already ended; in a sandbox its first process, whose
    death ends everything inside), and reap the child."""
    first = child.sandbox.first() if child.sandbox and child.returncode is None else None
    if first is not None:
        with contextlib.suppress(ProcessLookupError, PermissionError):
            os.kill(first, signal.SIGKILL)
    try:
        os.killpg(child.pid, signal.SIGKILL)
    except (ProcessLookupError, PermissionError):
        pass
    if child.returncode is not None:
        return
    try:
        _, wait, _ = os.wait4(child.pid, 0)
        child.returncode = _status(child, wait)
    except ChildProcessError:
        child.returncode = -signal.SIGKILL


def _finish(report: dict, watch: Watch, folder: Path, out: Path,
            record: Path | None = None) -> ProgramResult:
    """The result when the child reported its files finished (moved into place here);
    otherwise the error that says how the run ended."""
    kind = report.get("kind")
    if kind == "done":
        return _move(report, watch, folder, out, record)
    if kind == "program" and report.get("error") is not None:    # (files up to the error)
        raise ProgramRaised(report["message"], report["error"],
                            _move(report, watch, folder, out, record)
                            if "frames" in report else None)
    if kind == "program":
        raise ProgramError(report["message"])
    if kind == "user":
        raise UserError(report["message"])
    if kind == "oserror":                # a write that failed: named as the user's file
        raise _output_error(report, out)
    if kind == "interrupted":          # (a child of an older springscene)
        raise ProgramError(f"{watch.program}: the program raised KeyboardInterrupt")
    if kind == "internal":              # a fault in springscene: its traceback, for a report
        print(report["message"], file=sys.stderr)
        raise RunEnded(1, f"springscene: internal error running {watch.program} (above)")
    if kind == "exit" and report.get("said"):
        print(report["said"], file=sys.stderr)         # as Python prints sys.exit("...")
    status, line = ended_line(report, watch)
    raise RunEnded(status, line)


def _output_error(report: dict, out: Path) -> OutputError:
    """The child's failed write, naming the file the user asked for: a temporary
    ``.NAME.XXXXXXXX.SUFFIX`` in the private folder is ``NAME`` beside ``out``."""
    name = Path(report["filename"] or out.name).name
    if name.startswith(".") and name.count(".") >= 3:
        name = name[1:].rsplit(".", 2)[0]
    reason = report.get("reason") or (report["strerror"] or "cannot write").lower()
    return OutputError(reason, out.parent / name, report["errno"] or errno.EIO)


def _move(report: dict, watch: Watch, folder: Path, out: Path,
          record: Path | None = None) -> ProgramResult:
    """The finished files from ``folder`` into ``out``'s folder (``--record``'s to its
    own), the video last."""
    def placed(name: str | None) -> Path | None:
        return None if name is None else out.parent / Path(name).name

    # a name captured twice is one file (the last capture); the video's own name last
    images = [p for p in dict.fromkeys(placed(p) for p in report["images"]) if p != out]
    page = placed(report["page"])
    recording = record if report.get("recording") and record is not None else None
    sources = {target: folder / target.name for target in images + [out]}
    if page:
        sources[page] = folder / page.name
    if recording is not None:
        sources[recording] = folder / Path(report["recording"]).name
    targets = list(dict.fromkeys(images + ([page] if page else [])
                                 + ([recording] if recording else []))) + [out]
    read = set(report.get("read", ()))
    for target in targets:
        if os.path.realpath(target) in read:
            raise UserError(f"--out {out}: the program read {target.name}; writing there "
                            "would overwrite it (choose another name)")
    for target in targets:
        if not sources[target].is_file():
            raise RunEnded(1, f"springscene: {watch.program}: the run reported "
                              f"{target.name} finished but did not write it")
    if recording is not None:           # --record on another file system: copied there first
        sources[recording] = _beside(sources[recording], recording)
    with _signals_held():               # all of them in place, or (SIGKILL aside) none
        for target in targets:
            os.replace(sources[target], target)
    notes = list(report["notes"])
    if report.get("threads"):
        notes.append(f"the program left {_threads(report['threads'])} running after its "
                     "end; stopped once the video was finished")
    return ProgramResult(out, report["frames"], report["fps"], report["program_seconds"],
                         time.monotonic() - watch.start, report["ended"],
                         size=tuple(report["size"]) if report["size"] else None,
                         dialect=report["dialect"], page=page, recording=recording,
                         images=images, notes=notes,
                         peak_memory=watch.peak, error=report.get("error"))


def _beside(source: Path, target: Path) -> Path:
    """``source`` where an ``os.replace`` onto ``target`` can take it: itself on the same
    file system, else a hidden copy beside ``target``, flushed to the disk (removed if the
    copy fails: a write error is one line naming ``target``)."""
    folder = target.parent if str(target.parent) else Path(".")
    if os.stat(source).st_dev == os.stat(folder).st_dev:
        return source
    fd, name = tempfile.mkstemp(prefix=f"{hidden_name(target)}.", suffix=target.suffix,
                                dir=folder)
    staged = Path(name)
    try:
        with os.fdopen(fd, "wb") as dst, open(source, "rb") as src:
            shutil.copyfileobj(src, dst)
            dst.flush()
            os.fsync(dst.fileno())
        os.chmod(staged, 0o644)
    except OSError as exc:
        staged.unlink(missing_ok=True)
        raise OutputError(exc.strerror or "cannot write", target, exc.errno or errno.EIO) \
            from None
    return staged


@contextlib.contextmanager
def _signals_held():
    """SIGINT, SIGTERM and SIGHUP held back (delivered after the block)."""
    stops = {signal.SIGINT, signal.SIGTERM, signal.SIGHUP}
    held = threading.current_thread() is threading.main_thread()
    if held:
        saved = signal.pthread_sigmask(signal.SIG_BLOCK, stops)
    try:
        yield
    finally:
        if held:
            signal.pthread_sigmask(signal.SIG_SETMASK, saved)


def _threads(names: list[str]) -> str:
    shown = ", ".join(repr(n) for n in names[:3]) + (" ..." if len(names) > 3 else "")
    return f"thread{'s' * (len(names) > 1)} {shown}"


__all__ = ["run_supervised", "RunEnded", "Sandbox", "parse_size", "EXIT_TIMEOUT",
           "EXIT_MEMORY"]
