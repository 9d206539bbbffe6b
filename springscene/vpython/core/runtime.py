"""The program clock: ``rate`` and ``sleep`` advance it, and frames are taken on it.

Each ``rate(n)`` call is one loop iteration and advances the program clock by
1/n s; ``sleep(t)`` by t s. The scene as it stands at a call is what shows until
the next one, so every video frame whose time f/fps falls in that span is taken
there. The clock is kept as an exact fraction: ``rate(100)`` at 50 frames/s
takes a frame at exactly every second call, for any length of run.

When the run has all its frames, the call raises :class:`Stop`, a
``BaseException`` a program's own ``except Exception`` cannot swallow.
"""

from __future__ import annotations

import math
import time
import warnings
from fractions import Fraction
from typing import Callable

MAX_DENOMINATOR = 10 ** 9


RENDERS_PER_SECOND = 60      # GlowScript draws (and moves attached trails) at 60 Hz
# rate(n) above this is "as fast as it goes": VPython then runs the loop at the computer's
# pace, so each iteration takes the program time it took to compute (at least 1/MAX_RATE s)
MAX_RATE = 100_000


class Stop(BaseException):
    """Raised inside the program when the video has all its frames."""


class Timeline:
    """The clock of one run and the frames due on it.

    Parameters
    ----------
    fps : int
        Video frames per program second.
    max_frames : int | None
        Stop the program once this many frames are taken (None: never).
    take : callable
        Called with no arguments for each frame due; it draws and stores it.
    """

    def __init__(self, fps: int, max_frames: int | None, take: Callable[[], None]) -> None:
        self.fps = fps
        self.max_frames = max_frames
        self.take = take
        self.clock = Fraction(0)
        self.frames = 0
        self.calls = 0
        self.renders = 0
        self.capped_rate = None     # the largest rate(n) run at the machine's pace instead
        self.wall: float | None = None   # when the last such rate() call returned
        self.on_render: Callable[[], None] | None = None   # at VPython's render rate
        self.sleeps = 0                  # sleep() calls
        self.last_call: tuple[str, object] = ("", None)  # ("rate", n) or ("sleep", t): why
        self.last_span = Fraction(0)     # the program time the last call moved on by
        self.repeats = 0                 # frames that show the same scene as the one before
        self.slowest = None              # the smallest rate(n) that repeated frames

    @property
    def seconds(self) -> float:
        return float(self.clock)

    def advance(self, span: Fraction) -> None:
        """Show the scene as it is for ``span`` program seconds."""
        end = self.clock + span
        self.last_span = span
        if self.on_render is not None and Fraction(self.renders, RENDERS_PER_SECOND) < end:
            # a browser renders 60 times a second; while the program waits nothing moves,
            # so the renders due in this span see one scene: one call stands for them all
            self.on_render()
            self.renders = math.ceil(end * RENDERS_PER_SECOND)
        taken = 0
        while Fraction(self.frames, self.fps) < end:
            if self.max_frames is not None and self.frames >= self.max_frames:
                break
            self.take()
            self.frames += 1
            taken += 1
        if taken > 1 and self.frames > taken and self.last_call[0] == "rate":
            # one loop iteration shown in several frames (a sleep() shows a still scene on
            # purpose; the first frames wait for the start)
            self.repeats += taken - 1
            self.slowest = min(self.last_call[1], self.slowest or self.last_call[1])
        self.clock = end
        if self.max_frames is not None and self.frames >= self.max_frames:
            raise Stop


_current: Timeline | None = None
_last: Timeline | None = None


def start(timeline: Timeline | None) -> None:
    """Make ``timeline`` the clock ``rate`` and ``sleep`` advance (None: no clock)."""
    global _current, _last
    _current = timeline
    _last = timeline or _last


def last() -> Timeline | None:
    """The clock of the run now, or of the last run (where it stopped)."""
    return _last


def current() -> Timeline | None:
    """The clock ``rate`` and ``sleep`` advance now (None outside a run)."""
    return _current


def _span(value, what: str) -> Fraction:
    try:
        if isinstance(value, (str, bytes)):       # (Fraction would read "0.5"; time.sleep not)
            raise TypeError
        span = Fraction(value)
    except (OverflowError, ValueError):           # a number, but nan or inf
        raise ValueError(f"{what} must be finite, got {value}") from None
    except TypeError:
        raise TypeError(f"{what} must be a number, not {type(value).__name__}") from None
    return span.limit_denominator(MAX_DENOMINATOR) if span.denominator > MAX_DENOMINATOR \
        else span


def rate(n) -> None:
    """One loop iteration at most ``n`` times a program second: the clock moves 1/n s."""
    try:
        ok = n >= 1
    except TypeError:
        raise TypeError(f"rate value must be a number, not {type(n).__name__}") from None
    if not ok:
        raise ValueError("rate value must be greater than or equal to 1")
    if _current is not None:
        _current.calls += 1
        _current.last_call = ("rate", n)
        if n > MAX_RATE:           # "as fast as it goes": the machine's pace, not 1e15 a second
            _current.capped_rate = max(_current.capped_rate or 0, n)
            _current.advance(_machine_pace(_current))
            _current.wall = time.perf_counter()
            return
        _current.wall = None
        _current.advance(1 / _span(n, "rate value"))


def _machine_pace(timeline: Timeline) -> Fraction:
    """One iteration of a loop run as fast as it goes: the program time is the time the
    iteration took to compute (our own drawing left out), at least 1/MAX_RATE s."""
    now = time.perf_counter()
    took = now - timeline.wall if timeline.wall is not None else 0.0
    return max(Fraction(1, MAX_RATE), Fraction(took).limit_denominator(10**9))


def sleep(dt) -> None:
    """Wait ``dt`` program seconds: the scene shows, unchanged, for that long."""
    span = _span(dt, "sleep time")
    if span < 0:
        raise ValueError("sleep time must not be negative")
    if _current is not None:
        _current.wall = None
        _current.sleeps += 1
        _current.last_call = ("sleep", dt)
        _current.advance(span)


def wait() -> None:
    """A wait for a user who never comes: one video frame of program time passes."""
    if _current is not None:
        _current.wall = None
        _current.advance(Fraction(1, _current.fps))


_capture: Callable | None = None


def set_capture(fn: Callable | None) -> None:
    """Who saves ``scene.capture(name)`` pictures in this run (None: nobody)."""
    global _capture
    _capture = fn


def capturer() -> Callable | None:
    """Who saves ``scene.capture`` pictures now (:func:`set_capture`)."""
    return _capture


def capture(cv, name: str) -> None:
    if _capture is None:       # a program run by python itself: no renderer, no pictures
        warnings.warn(f"scene.capture({name!r}) saved nothing: pictures are taken only when "
                      "the program runs under `springscene vpython PROGRAM --out ...` (or "
                      "springscene.run_vpython)", UserWarning, stacklevel=3)
        return
    _capture(cv, name)
