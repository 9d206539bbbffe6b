"""The processes around a supervised run's child (:mod:`.child`, where the program runs).

- **Forks of the program.** A program's ``os.fork()`` copies springscene's pipes: the
  report pipe to the parent and the encoder's (ffmpeg's) stdin. A copy that lingers would
  hold the encoder's input open, ffmpeg would wait for its end and the run with it; in the
  copy they are pointed at ``/dev/null`` (:func:`guard_forks`). A copy whose program ends
  (it falls off the end, raises or calls ``sys.exit``) ends there, as Python would end it,
  without springscene's epilogue (which would finish, move or remove the run's files).
- **What the program leaves.** The child is a child subreaper (Linux): what the program
  started and left (a daemon made with ``setsid``, a double fork) stays its descendant,
  and :func:`end_descendants` kills them all once the run has reported, so that nothing
  the program started outlives the run or holds springscene's output streams open.
- **springscene killed outright** (SIGKILL, the OOM killer): the kernel sends the child
  SIGTERM (``PR_SET_PDEATHSIG``); seeing its parent gone, it removes the private run
  folder, kills what it started and itself (:func:`die_with_parent`). The same happens
  when a report finds the pipe to the parent closed.
- **In a sandbox** (:mod:`.sandbox`) springscene is outside the child's PID namespace and
  cannot be watched from inside (parent ``0``): bubblewrap kills the sandbox with
  springscene (``--die-with-parent``), and a janitor outside removes the run's folder
  (:mod:`.supervise`). A report that finds the pipe closed ends the run here.
"""

from __future__ import annotations

import atexit
import ctypes
import os
import shutil
import signal
import sys
import threading
import time
from pathlib import Path

from ...errors import ProgramError
from ... import video

PR_SET_PDEATHSIG = 1
PR_SET_CHILD_SUBREAPER = 36
PF_EXITING = 0x4           # a task's flag (/proc/PID/stat) from the start of its exit
_state = {"parent": None, "thread": None, "folder": None, "pid": None, "copy": False}
_ending = threading.RLock()
_on_term = None             # the child's SIGTERM handler (a fork of the program gets Python's)


def _prctl(option: int, value: int) -> bool:
    try:
        return ctypes.CDLL(None, use_errno=True).prctl(option, value, 0, 0, 0) == 0
    except (OSError, AttributeError):       # not Linux
        return False


def die_with_parent(parent: int, folder: Path, thread: int | None = None) -> None:
    """SIGTERM when ``parent`` (its thread ``thread``, which started this process) dies,
    even by SIGKILL; then :func:`orphaned`. A parent that died before this call is caught
    by comparing ``os.getppid()``. The child is also made a subreaper of what the program
    leaves. ``parent`` 0: the child runs in a sandbox (above), which ends it with
    springscene."""
    _state.update(parent=parent, thread=thread, folder=Path(folder), pid=os.getpid())
    _prctl(PR_SET_CHILD_SUBREAPER, 1)
    if not parent:
        return

    def on_term(signum, frame) -> None:
        if os.getpid() == _state["pid"] and parent_dead():
            orphaned()
        signal.signal(signal.SIGTERM, signal.SIG_DFL)  # anyone else's SIGTERM: as Python's
        os.kill(os.getpid(), signal.SIGTERM)

    global _on_term
    _on_term = on_term
    signal.signal(signal.SIGTERM, on_term)
    _prctl(PR_SET_PDEATHSIG, signal.SIGTERM)
    if os.getppid() != parent:           # died before the request: no signal will come
        orphaned()
    _start_watcher()


def _start_watcher() -> None:
    """A watcher process, for when this one cannot clean up: the kernel's SIGTERM is handled
    in Python, which a program stuck in one long C call (a huge ``sum(range(...))``) does
    not reach; then springscene's limits are gone with it. Once springscene is dead, the
    watcher gives this process :data:`GRACE` s to end by itself, then kills it and its
    process group and removes the run's folder. Forked here, before the program starts:
    no thread and no fork hook yet. It ends when this process ends (the run's end kills
    it with the rest of what this process started)."""
    child = os.getpid()
    if os.fork():
        return
    try:
        while os.getppid() == child:
            time.sleep(WATCH_EVERY)
            if gone(_state["parent"], _state["thread"] or _state["parent"]):
                deadline = time.monotonic() + GRACE
                while os.getppid() == child and time.monotonic() < deadline:
                    time.sleep(WATCH_EVERY / 4)
                if os.getppid() == child:                  # stuck: not in Python
                    os.kill(child, signal.SIGKILL)
                    _remove_run_folder()
                    os.killpg(os.getpgid(0), signal.SIGKILL)
                break
    finally:
        os._exit(0)


WATCH_EVERY = 0.1       # s between the watcher's looks at springscene
GRACE = 1.0             # s the child has to clean up by itself once springscene is gone


def parent_gone() -> None:
    """The pipe to the parent is closed: if the parent died, :func:`orphaned`; if it is
    alive it has finished with this process (and ends it): just end."""
    if _state["parent"] is not None and parent_dead():
        orphaned()
    os._exit(1)


def parent_dead() -> bool:
    """Whether the parent is dead or dying. The kernel's signal comes as the parent's thread
    that started this process exits, and the pipe closes as its last thread does: the
    parent's other threads may still be exiting, so ``os.getppid()`` may not have changed
    yet. That thread's own state tells (``/proc``: exiting, a zombie, or gone). In a
    sandbox the closed pipe is the only sign: springscene is gone or has done with it."""
    parent, thread = _state["parent"], _state["thread"] or _state["parent"]
    if not parent:
        return True
    if os.getppid() != parent:
        return True
    return gone(parent, thread)


def gone(parent: int, thread: int) -> bool:
    """Whether process ``parent``'s thread ``thread`` (its pid for its main thread) is
    exiting, a zombie or gone (``/proc``)."""
    if not os.path.isdir("/proc/self/task"):
        return False
    try:
        with open(f"/proc/{parent}/task/{thread}/stat", "rb") as f:
            fields = f.read().rsplit(b")", 1)[1].split()
    except FileNotFoundError:
        return True
    except (OSError, IndexError):
        return False
    return fields[0] in (b"Z", b"X") or bool(int(fields[6]) & PF_EXITING)


def orphaned() -> None:
    """springscene is gone: nobody will move or remove the run's files. Remove its private
    folder (only one named as :mod:`.supervise` makes them), kill what this process
    started, and end (its process group with it). Never in a fork of the program (whose
    parent is this process): the run's folder is not its to remove."""
    if os.getpid() != _state["pid"]:
        os._exit(1)
    # once a thread: a report that finds the pipe closed and the signal may both come
    # (the other thread waits for the end); the kernel signals again as each of the
    # parent's threads exits, which re-enters here in this thread (and ends it anew)
    _ending.acquire()
    end_descendants()
    _remove_run_folder()
    if os.getpgid(0) == os.getpid():
        os.killpg(os.getpid(), signal.SIGKILL)
    os._exit(128 + signal.SIGKILL)


def _remove_run_folder() -> None:
    """The run's private folder (only one named as :mod:`.supervise` makes them)."""
    folder = _state["folder"]
    if folder is not None and folder.name.startswith(".") and folder.name.endswith(".run"):
        shutil.rmtree(folder, ignore_errors=True)


def processes() -> dict[int, list[int]]:
    """Each live process's children (zombies left out), from ``/proc``."""
    children: dict[int, list[int]] = {}
    try:
        names = [name for name in os.listdir("/proc") if name.isdigit()]
    except OSError:                 # (no file descriptor left: the program took them all)
        return children
    for name in names:
        try:
            with open(f"/proc/{name}/stat", "rb") as f:
                fields = f.read().rsplit(b")", 1)[1].split()
        except (OSError, IndexError):
            continue
        if len(fields) > 1 and fields[0] != b"Z":
            children.setdefault(int(fields[1]), []).append(int(name))
    return children


def descendants(pid: int | None = None) -> list[int]:
    """The live descendants of ``pid`` (this process)."""
    children, found = processes(), []
    todo = list(children.get(pid or os.getpid(), ()))
    while todo:
        p = todo.pop()
        found.append(p)
        todo.extend(children.get(p, ()))
    return found


def join_workers() -> None:
    """Wait for the program's non-daemon ``multiprocessing`` workers, as Python does at exit
    (multiprocessing's own exit function joins them; daemonic ones are ended)."""
    mp = sys.modules.get("multiprocessing")
    if mp is None:
        return
    for worker in mp.active_children():
        if not worker.daemon:
            worker.join()


def end_descendants(rounds: int = 20) -> None:
    """Kill every live descendant of this process (SIGKILL), again while any is left (a
    process forking meanwhile; orphans re-parented here)."""
    if not os.path.isdir("/proc"):
        return
    for _ in range(rounds):
        alive = descendants()
        if not alive:
            return
        for pid in alive:
            try:
                os.kill(pid, signal.SIGKILL)
            except OSError:
                pass
        time.sleep(0.005)


# ---- forks of the program ------------------------------------------------------------

def guard_forks(report_fd: int) -> None:
    """From now on, a fork of this process lets go of ``report_fd`` and the encoders' pipes,
    and ends when its program ends (:func:`end_if_copy`, the run's ``on_end``)."""
    def in_copy() -> None:
        if os.getpid() == _state["pid"]:
            return
        _state["pid"], _state["copy"] = None, True    # a copy: never the run's process again
        if signal.getsignal(signal.SIGTERM) is _on_term:
            signal.signal(signal.SIGTERM, signal.SIG_DFL)   # Python's own again
        for fd in [report_fd, *video.pipe_fds()]:
            _to_devnull(fd)

    os.register_at_fork(after_in_child=in_copy)


def _to_devnull(fd: int) -> None:
    """``fd`` made /dev/null (the number stays valid: whoever holds it writes nowhere)."""
    try:
        null = os.open(os.devnull, os.O_WRONLY)
    except OSError:
        return
    try:
        os.dup2(null, fd)
    except OSError:
        pass
    finally:
        os.close(null)


def end_if_copy(error: BaseException | None) -> None:
    """In a fork of the program, its end is the process's end, as Python would end it:
    ``sys.exit(n)``'s status (and text), 1 with its traceback for an error, else 0; the
    copy's output flushed and its exit functions run, springscene's epilogue skipped."""
    if not _state["copy"]:                   # the run's own process
        return
    status = 0
    if hasattr(error, "status"):                # sys.exit(n) (said: sys.exit("text"))
        status = error.status
        if getattr(error, "said", None) is not None:
            _say(error.said)
    elif isinstance(error, ProgramError):       # raised: its own traceback
        status = 1
        _say(str(error))
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):
            pass
    atexit._run_exitfuncs()
    os._exit(status)


def _say(text: str) -> None:
    try:
        print(text, file=sys.stderr, flush=True)
    except (OSError, ValueError):
        pass
