"""A supervised run's child forked from a warm process instead of started fresh.

A batch keeps one warm process (:mod:`springscene.batch.warm`): springscene, VTK's
modules, pyvista and matplotlib imported and matplotlib's fonts loaded, one thread, no
window or GL context ever made. Its job processes are forks of it, and each of them
starts its program's child (:mod:`.child`) as a fork of itself (:func:`start`), which
begins where a fresh interpreter would be after its imports: about a second and a half
of processor time sooner. A sandboxed child is always a fresh interpreter, started by
bubblewrap.

What promises a forked child the state of a fresh one:

- it is a fork of a process that never drew: no GL, EGL or llvmpipe state is copied;
- :func:`ready` is False in a process with a second thread (a fork copies the calling
  thread alone, so a lock held by another would stay held), and anywhere but in a warm
  process: the child is then started fresh, as always;
- in the child (:func:`_as_fresh`): its own process group; the descriptors it did not
  open pointed at ``/dev/null`` (the report pipe and the standard streams kept); the
  signal handlers an exec and Python's start would leave (an ignored signal stays
  ignored), none blocked; numpy's global random state seeded
  anew (Python's ``random`` is, by Python); the environment is its parent's, as a fresh
  child's (the warm process gives its job processes the batch's).

What a forked child keeps of the warm process, by design or as the price of not starting
again: numpy's BLAS on one thread (the warm process sets ``OPENBLAS_NUM_THREADS=1``
before loading it, since OpenBLAS starts its threads as it loads); the warm process's
string hashes (every fork orders a set of strings alike); the modules it imported, found
before a program's own file of the same name; and in its memory, as ``--max-memory``
watches it, the pages it shares with the warm process (the probe program of
tests/batch/test_warm.py: 100 MB resident at its start against a fresh child's 56 MB,
whose imports come later; at the run's peak 232 MB against 268 MB).
"""

from __future__ import annotations

import atexit
import contextlib
import os
import signal
import sys
import threading
import traceback

from . import child

_WARM = {"on": False}


def make_warm() -> None:
    """This process is warm: children are forked from it while it has one thread."""
    _WARM["on"] = True


def ready() -> bool:
    """Whether a child may be forked from this process now."""
    return bool(_WARM["on"]) and threads() == 1


def threads() -> int:
    """The threads of this process, as the kernel counts them (OpenBLAS's and other
    libraries' included, which Python does not know of)."""
    try:
        return len(os.listdir("/proc/self/task"))
    except OSError:
        return threading.active_count() + 1         # unknown: never taken for one


def start(keep: int, argv: list[str]) -> int:
    """Fork the child: it runs ``child.main(argv)`` as ``python -c`` would and exits, with
    ``keep`` (its report pipe) open. Returns its pid."""
    for stream in (sys.stdout, sys.stderr):
        stream.flush()
    pid = os.fork()
    if pid:
        # (here too, so that a kill of its group made before the child has run reaches it)
        with contextlib.suppress(OSError):
            os.setpgid(pid, pid)
        return pid
    code = 1
    try:
        _as_fresh(keep)
        code = child.main(argv)
        _join_threads()
    except SystemExit as exc:
        code = exit_status(exc)
    except BaseException:                    # (as Python shows an uncaught error)
        traceback.print_exc()
    finally:
        end(code)
    return 0                                 # (never reached: the child has exited)


def _as_fresh(keep: int) -> None:
    """The forked child made what a fresh interpreter is (the module's list)."""
    os.setpgid(0, 0)
    signal.set_wakeup_fd(-1)
    # as an exec: a signal caught above is at its default, an ignored one stays ignored;
    # then as Python starts: Ctrl-C raises KeyboardInterrupt, unless it is ignored
    for signum in signal.valid_signals():
        if callable(signal.getsignal(signum)):
            signal.signal(signum, signal.SIG_DFL)
    if signal.getsignal(signal.SIGINT) == signal.SIG_DFL:
        signal.signal(signal.SIGINT, signal.default_int_handler)
    signal.pthread_sigmask(signal.SIG_SETMASK, ())
    _release_descriptors(keep)
    _WARM["on"] = False                      # (the program's own forks are not warm)
    numpy = sys.modules.get("numpy")
    if numpy is not None:
        numpy.random.seed()


def _release_descriptors(keep: int) -> None:
    """Every descriptor but the standard streams and ``keep`` pointed at ``/dev/null``:
    the pipes and files of the processes above are let go of (a pipe's reader sees its
    end), and a number an object above still holds stays taken, so that a late close of
    it can close nothing of the program's."""
    null = os.open(os.devnull, os.O_RDWR | os.O_CLOEXEC)
    try:
        for name in os.listdir("/proc/self/fd"):
            fd = int(name)
            if fd > 2 and fd not in (keep, null):
                try:
                    os.dup2(null, fd, inheritable=False)
                except OSError:             # (the listing's own descriptor, now closed)
                    pass
    finally:
        os.close(null)


def _join_threads() -> None:
    """As the interpreter's end waits for the threads the program left running (its
    supervisor kills it instead when it reported them)."""
    for thread in threading.enumerate():
        if thread is not threading.main_thread() and not thread.daemon:
            thread.join()


def exit_status(exc: SystemExit) -> int:
    """The exit status Python gives ``sys.exit(code)``."""
    if exc.code is None:
        return 0
    if isinstance(exc.code, int):
        return exc.code & 0xFF
    print(exc.code, file=sys.stderr)
    return 1


def end(code: int) -> None:
    """The interpreter's end: the exit functions, the streams flushed, then the exit."""
    try:
        atexit._run_exitfuncs()
        for stream in (sys.stdout, sys.stderr):
            stream.flush()
    finally:
        os._exit(code)
