"""The process state a VPython program runs in, set up in one place and put back whole.

A program runs in springscene's own interpreter as ``__main__``, so for its run the
process must look like the one VPython gives it: ``import vpython`` (and ``visual``)
finds springscene's API, ``sys.argv`` is the program's, its folder is first on
``sys.path``, what it prints is also kept for the page, ``rate`` and ``sleep`` move the
run's clock, ``scene.capture`` writes pictures, a canvas's size is measured by its
renderer, a VPython 6 program gets its lenient vectors and ``time.clock``.
:class:`ProgramSession` is that state as one context manager: every change is undone on
exit, in the reverse order, however the program ended; the modules the program imported
from its own folder are forgotten, so a second run in this process imports them afresh.

:data:`program_end_hooks` are called with the program's error (None when it ended
normally) as soon as it has ended, before anything is put back: a fork of the program
(:mod:`.lineage`) ends there.
"""

from __future__ import annotations

import contextlib
import sys
import time
from pathlib import Path
from typing import Callable, Iterator

from .. import api
from ..api import runtime
from ..api.canvases import canvas
from ..api.vectors import set_lenient
from ..dialects import compiling, visual6

#: called with the program's error (or None) once it has ended, before the state is put back
program_end_hooks: list[Callable[[BaseException | None], None]] = []


class ProgramSession(contextlib.ExitStack):
    """The process as a program of ``dialect`` at ``path`` sees it, while the block runs.

    ``timeline`` is the clock ``rate`` and ``sleep`` advance; ``capture(cv, name)`` saves
    a canvas's picture; ``measure(cv)`` brings a canvas's renderer up to date (for its
    size); ``stdout`` replaces ``sys.stdout`` (a tee that keeps what is printed).
    """

    def __init__(self, path: Path, dialect: compiling.Dialect, timeline: runtime.Timeline,
                 capture: Callable, measure: Callable, stdout) -> None:
        super().__init__()
        self.path, self.dialect = path, dialect
        self.timeline, self.capture, self.measure, self.stdout = (timeline, capture, measure,
                                                                  stdout)

    def __enter__(self) -> ProgramSession:
        super().__enter__()
        try:
            folder = self.path.resolve().parent
            self.enter_context(_program_modules(folder))
            self.enter_context(_swapped(sys, "argv", [str(self.path)]))
            self.enter_context(_first_on_path(str(folder)))
            self.enter_context(_set(runtime.start, self.timeline, None))
            self.enter_context(_set(runtime.set_capture, self.capture, None))
            self.enter_context(_swapped(canvas, "_measurer", self.measure))
            vpython6 = self.dialect.kind == "vpython6"
            self.enter_context(_set(set_lenient, vpython6, False))
            if vpython6 and not hasattr(time, "clock"):   # (gone in Python 3.8)
                self.enter_context(_swapped(time, "clock", time.perf_counter))
            self.enter_context(_swapped(sys, "stdout", self.stdout))
            self.push(_program_ended)
        except BaseException:
            self.close()
            raise
        return self


def _program_ended(exc_type, exc, tb) -> None:
    for hook in list(program_end_hooks):
        hook(exc)


@contextlib.contextmanager
def _swapped(owner, name: str, value) -> Iterator[None]:
    """``owner.name`` is ``value`` within the block; before and after as it was (absent
    stays absent)."""
    missing = object()
    saved = getattr(owner, name, missing)
    setattr(owner, name, value)
    try:
        yield
    finally:
        if saved is missing:
            delattr(owner, name)
        else:
            setattr(owner, name, saved)


@contextlib.contextmanager
def _set(setter: Callable, value, after) -> Iterator[None]:
    """``setter(value)`` for the block, ``setter(after)`` once it ends."""
    setter(value)
    try:
        yield
    finally:
        setter(after)


@contextlib.contextmanager
def _first_on_path(folder: str) -> Iterator[None]:
    saved = list(sys.path)
    sys.path.insert(0, folder)
    try:
        yield
    finally:
        sys.path[:] = saved


@contextlib.contextmanager
def _program_modules(folder: Path) -> Iterator[None]:
    """``vpython`` and ``visual`` (with ``visual.graph`` and the rest) importing
    springscene's API within the block; afterwards the modules as they were, and those
    the program imported from its own folder forgotten."""
    found = {"vpython": api, **visual6.modules(api)}
    saved = {name: sys.modules.get(name) for name in found}
    before = set(sys.modules)
    sys.modules.update(found)
    try:
        yield
    finally:
        for name, module in saved.items():
            if module is None:
                sys.modules.pop(name, None)
            else:
                sys.modules[name] = module
        for name in set(sys.modules) - before:
            file = getattr(sys.modules[name], "__file__", None)
            if file and Path(file).resolve().is_relative_to(folder):
                del sys.modules[name]
