"""Stop signals: SIGINT, SIGTERM and SIGHUP stop every command alike.

:func:`main` is the ``springscene`` command (the package's console script; ``python -m
springscene.app`` runs the same). It installs the handlers before anything else is
imported (numpy, VTK), then runs :func:`springscene.app.cli.main`. A signal raises
:class:`Interrupted` (a ``KeyboardInterrupt`` carrying the signal) in the main thread, so
the ``with``/``finally`` blocks on the way out (``outputs.atomic_path``, a figure set's
staging folder, an encoder being closed) remove what they wrote; the command says
``springscene: interrupted (SIGTERM)`` on one line and exits 128 + the signal's number
(130, 143, 129). Once the command has returned, a signal changes nothing.

A signal in the interpreter's own start-up, before :func:`main` has put its handlers in
(some tens of ms), meets Python's defaults, with nothing written yet: SIGTERM and SIGHUP
end the process by the signal (the shell's 143 or 129, no line); SIGINT does too, or
prints Python's own ``KeyboardInterrupt`` traceback (130; 1 when it stops ``import site``),
or, raised in one of importlib's callbacks, is only reported (``Exception ignored``) and
the command runs on.

From the handlers on, four rules make that hold at any moment:

- **Not inside a C extension's start-up.** VTK's compiled modules import their
  dependencies from C and do not survive an exception raised in those imports (a
  segfault); a signal arriving there waits until the import has returned.
- **Never lost.** An exception raised in Python code that C code called can be swallowed
  by the C code (``PyObject_HasAttr``, a dict lookup, an extension's optional import):
  until the interruption is reported, a watchdog thread simulates the signal again every
  :data:`RETRY_S`, and a new :class:`Interrupted` is raised once the last one is gone
  (garbage) without having been reported; where Python cannot pass one on (a weak
  reference's callback, ``__del__``) it is not printed either.
- **Once.** While an :class:`Interrupted` is on its way out, later signals change
  nothing, so a second Ctrl-C cannot cut a clean-up short (the :data:`FORCE_AFTER`-th
  leaves at once).
- **No interpreter teardown after a signal.** Once the clean-up is done, the process
  leaves with ``os._exit``: a half-imported or half-used VTK is never finalised.

A signal ignored when the process starts stays ignored (``nohup``; a shell's background
job ignores SIGINT). A supervised child process can call :func:`install` as its first act
too. A parent that supervises one (``springscene vpython``) is interrupted like any
command: its ``finally`` kills the child's process group and removes the child's temporary
folder on the way out.
"""

from __future__ import annotations

import _thread
import importlib
import importlib.machinery
import os
import signal
import sys
import threading
import time
import weakref

SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)
RETRY_S = 0.05          # the watchdog simulates the signal again this often until reported
FORCE_AFTER = 3         # signals from outside: at this many the process leaves at once


class Interrupted(KeyboardInterrupt):
    """A stop signal, raised in the main thread; exit status 128 + ``signum``."""

    def __init__(self, signum: int) -> None:
        super().__init__(signal.Signals(signum).name)
        self.signum = signum

    @property
    def name(self) -> str:
        return signal.Signals(self.signum).name

    @property
    def status(self) -> int:
        return 128 + self.signum


class _State:
    """What the handler knows between calls (reset by :func:`install`)."""

    def __init__(self) -> None:
        self.received: list[int] = []    # the signals from outside, in order
        self.raised = None               # a weak reference to the last Interrupted raised
        self.done = False                # reported, or the command returned
        self.resent = False              # the next call is the watchdog's, not a signal's
        self.wake = threading.Event()    # set by the first signal: the watchdog starts


_state = _State()


def install() -> None:
    """Handle SIGINT, SIGTERM and SIGHUP as :class:`Interrupted` (call in the main thread,
    as early as possible: before heavy imports).
    A signal ignored when the process started stays ignored, as POSIX asks (``nohup``
    ignores SIGHUP; a shell's background job, SIGINT)."""
    global _state
    _state = _State()
    # started here, not in the handler: a thread started from a signal handler would wait
    # forever for threading's lock if the signal came while the main thread held it
    threading.Thread(target=_watchdog, args=(_state,), daemon=True,
                     name="springscene-signals").start()
    for signum in SIGNALS:
        if signal.getsignal(signum) is not signal.SIG_IGN:
            signal.signal(signum, _handler)
    if sys.unraisablehook is not _unraisable:
        _unraisable.previous = sys.unraisablehook
        sys.unraisablehook = _unraisable


def _unraisable(unraisable) -> None:
    """An :class:`Interrupted` raised where Python cannot pass it on (a weak reference's
    callback, ``__del__``) is not printed: the watchdog raises a new one."""
    if not isinstance(unraisable.exc_value, Interrupted):
        _unraisable.previous(unraisable)


def received() -> int | None:
    """The first stop signal received since :func:`install`, or None."""
    return _state.received[0] if _state.received else None


def _handler(signum: int, frame) -> None:
    st = _state
    resent, st.resent = st.resent, False
    if st.done:
        return
    if not resent:
        st.received.append(signum)
        if len(st.received) >= FORCE_AFTER:
            _leave(128 + st.received[0])
    st.wake.set()
    if _in_extension_import(frame) or _on_its_way(st):
        return
    raise _new_interruption(st)          # no local name: the frame would keep it alive


def _new_interruption(st: _State) -> Interrupted:
    stop = Interrupted(st.received[0])
    st.raised = weakref.ref(stop)
    logging = sys.modules.get("logging")     # (not imported here: the handlers come first)
    if logging is not None:                  # libraries' notes while cleaning up (ffmpeg's
        logging.disable(logging.WARNING)     # "no frames written") would add lines
    return stop


def _on_its_way(st: _State) -> bool:
    """Whether the last :class:`Interrupted` still exists: propagating, or being handled."""
    return st.raised is not None and st.raised() is not None


def _watchdog(st: _State) -> None:
    """Once a signal came, simulate the first one again (no system call is interrupted)
    until it is reported."""
    st.wake.wait()
    while True:
        time.sleep(RETRY_S)
        if st.done or st is not _state:
            return
        st.resent = True
        _thread.interrupt_main(st.received[0])


def _in_extension_import(frame) -> bool:
    """Whether ``frame`` runs inside a compiled extension module's initialisation (an
    import made from C code, as VTK's modules make), where an exception is not safe."""
    extension = importlib.machinery.ExtensionFileLoader
    while frame is not None:
        code = frame.f_code
        if code.co_name in ("create_module", "exec_module") \
                and code.co_filename.startswith("<frozen importlib"):
            if isinstance(frame.f_locals.get("self"), extension):
                return True
        frame = frame.f_back
    return False


def interruption(exc: BaseException) -> KeyboardInterrupt | None:
    """The interruption behind ``exc``: itself, or the one it was raised from (a class
    body's ``__set_name__`` turns any exception into a RuntimeError), or None."""
    seen = set()
    while exc is not None and id(exc) not in seen:
        if isinstance(exc, KeyboardInterrupt):
            return exc
        seen.add(id(exc))
        exc = exc.__cause__ or exc.__context__
    return None


def report(exc: KeyboardInterrupt) -> int:
    """Say on one line that the command was interrupted, and by which signal; return the
    exit status (130 for a plain ``KeyboardInterrupt``). Later signals change nothing."""
    _state.done = True
    signum = getattr(exc, "signum", signal.SIGINT)
    print(f"springscene: interrupted ({signal.Signals(signum).name})", file=sys.stderr)
    return 128 + signum


def _leave(status: int) -> None:
    """Exit now, without the interpreter's teardown (see the module's notes)."""
    for stream in (sys.stdout, sys.stderr):
        try:
            stream.flush()
        except (OSError, ValueError):
            pass
    os._exit(status)


def _too_late() -> None:
    """The command is done: a signal from now on changes nothing. Ignored, not only left to
    the handler, so the interpreter's teardown (which puts back the default actions of the
    handlers it knows) cannot end a finished run by the signal, its output whole."""
    _state.done = True
    for signum in SIGNALS:
        if signal.getsignal(signum) is _handler:
            signal.signal(signum, signal.SIG_IGN)


def main(argv: list[str] | None = None) -> int:
    """The ``springscene`` command: the handlers first, then the command line."""
    install()
    try:
        # imported here, after the handlers: a signal while numpy and the command line load
        # is an Interrupted like any other
        cli = importlib.import_module("springscene.app.cli")
        status = cli.main(argv)
        _too_late()
    except BaseException as exc:
        stop = interruption(exc)
        if stop is None:
            _too_late()             # argparse's exit (--version, a bad flag), a bug: done
            raise
        status = report(stop)
    if received() is not None:
        _leave(status)
    return status
