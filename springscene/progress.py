"""Progress, with the time left, for long runs: a bar on a terminal, nothing elsewhere.

A run of more than :data:`LONG_RUN` steps (about 20 s of recording the ball's state,
``physics.run``, on this project's 2-core machine) shows a ``tqdm`` bar on stderr with
its rate and an estimate of the time left; shorter runs, and runs whose stderr is not a
terminal (a pipe, CI, a notebook's captured output), show nothing.
"""

from __future__ import annotations

import contextlib
import shutil
import sys
import warnings
from typing import Callable, Iterator

LONG_RUN = 200_000     # steps


def tqdm_class() -> type:
    """tqdm's bar for where this runs: a widget in Jupyter, text on a terminal (the choice
    ``tqdm.auto`` makes, without the asyncio it loads, about 6 MB)."""
    with warnings.catch_warnings():      # tqdm calls its notebook mode "experimental"
        warnings.filterwarnings("ignore", message="Using `tqdm.autonotebook.tqdm`")
        from tqdm.autonotebook import tqdm  # noqa: PLC0415  heavy: tqdm
    return tqdm


@contextlib.contextmanager
def steps(total: int, what: str) -> Iterator[Callable[[int], None] | None]:
    """A callback ``advance(n)`` for ``total`` steps of ``what``, or None when the run is
    short or stderr is not a terminal (then the caller steps in one go)."""
    if total < LONG_RUN or not sys.stderr.isatty():
        yield None
        return
    # the terminal's size; 80 x 24 where it says 0 x 0 (a pty no one sized, as a harness
    # or a container makes: tqdm would hide its bar below a screen of no rows)
    size = shutil.get_terminal_size((80, 24))
    with tqdm_class()(total=total, desc=what, unit=" steps", unit_scale=True, leave=False,
              file=sys.stderr, ncols=size.columns, nrows=size.lines) as bar:
        yield bar.update
