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

``on_end(error)`` is called with the program's error (None when it ended normally) as
soon as it has ended, before anything is put back: a fork of the program ends there
(:func:`.lineage.end_if_copy`).
"""

from __future__ import annotations

import contextlib
import sys
import time
from pathlib import Path
from typing import Callable, Iterator

from .. import api
from ..core import runtime
from ..core.canvases import canvas
from ..core.vectors import is_lenient, set_lenient
from ..dialects import compiling, visual6

class ProgramSession(contextlib.ExitStack):
    """The process as a program of ``dialect`` at ``path`` sees it, while the block runs.

    ``timeline`` is the clock ``rate`` and ``sleep`` advance; ``capture(cv, name)`` saves
    a canvas's picture; ``measure(cv)`` brings a canvas's renderer up to date (for its
    size); ``stdout`` replaces ``sys.stdout`` (a tee that keeps what is printed);
    ``on_end(error)``, if given, is called when the program has ended.
    """

    def __init__(self, path: Path, dialect: compiling.Dialect, timeline: runtime.Timeline,
                 capture: Callable, measure: Callable, stdout,
                 on_end: Callable[[BaseException | None], None] | None = None) -> None:
        super().__init__()
        self.path, self.dialect = path, dialect
        self.timeline, self.capture, self.measure, self.stdout = (timeline, capture, measure,
                                                                  stdout)
        self.on_end = on_end

    def __enter__(self) -> ProgramSession:
        super().__enter__()
        try:
            folder = self.path.resolve().parent
            self.enter_context(_program_modules(folder))
            self.enter_context(_swapped(sys, "argv", [str(self.path)]))
            self.enter_context(_first_on_path(str(folder)))
            self.enter_context(_set(runtime.start, self.timeline, runtime.current()))
            self.enter_context(_set(runtime.set_capture, self.capture, runtime.capturer()))
            self.enter_context(_swapped(canvas, "_measurer", self.measure))
            vpython6 = self.dialect.kind == "vpython6"
            self.enter_context(_set(set_lenient, vpython6, is_lenient()))
            if vpython6 and not hasattr(time, "clock"):   # (gone in Python 3.8)
                self.enter_context(_swapped(time, "clock", time.perf_counter))
            self.enter_context(_swapped(sys, "stdout", self.stdout))
            if self.on_end is not None:
                self.push(lambda exc_type, exc, tb: self.on_end(exc))
        except BaseException:
            self.close()
            raise
        return self


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
    the program imported from its own folder forgotten (not springscene's own, nor those
    of this Python's installation, should the program's folder hold them)."""
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
            if file and _the_programs(Path(file).resolve(), folder):
                del sys.modules[name]


_KEPT = (Path(sys.prefix).resolve(), Path(sys.base_prefix).resolve(),
         Path(api.__file__).resolve().parents[2])     # this Python's, and springscene


def _the_programs(file: Path, folder: Path) -> bool:
    """Whether a module's ``file`` is one of the program's own (in its folder, not in this
    Python's installation nor springscene)."""
    return file.is_relative_to(folder) and not any(file.is_relative_to(k) for k in _KEPT)
