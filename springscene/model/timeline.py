"""Time as the video sees it: which step each frame shows, and a system run frame by frame.

A video of ``duration`` simulated seconds at ``fps`` frames per video second and
``speed`` simulated seconds per video second shows, in frame f, the step nearest
t = f speed / fps. Numbers are checked here, and a bad one names its flag.
"""

from __future__ import annotations

import contextlib
import math
from typing import Iterator

import numpy as np

from ..errors import UserError
from . import physics

MAX_STEPS = 10_000_000    # about 4 to 15 minutes of stepping; past it a typo, not a plan
_limit = [MAX_STEPS]      # what step_at allows now (:func:`step_limit`)
MAX_FRAMES = 360_000      # two hours at 50 fps


def _time(flag: str, value) -> float:
    """``value`` as a finite time >= 0; otherwise an error naming ``flag``."""
    if isinstance(value, bool) or not isinstance(value, (int, float)):
        raise UserError(f"{flag} must be a number, got {type(value).__name__}")
    if not math.isfinite(value):
        raise UserError(f"{flag} must be finite, got {value}")
    if value < 0:
        raise UserError(f"{flag} must be >= 0, got {float(value):g}")
    return float(value)


@contextlib.contextmanager
def step_limit(limit: int | None) -> Iterator[None]:
    """Within the block, runs of up to ``limit`` steps are allowed (``--max-steps``);
    None keeps :data:`MAX_STEPS`."""
    if limit is not None and (isinstance(limit, bool) or not isinstance(limit, int)
                              or limit < 1):
        raise UserError(f"--max-steps must be a whole number >= 1, got {limit}")
    saved = _limit[0]
    _limit[0] = saved if limit is None else limit
    try:
        yield
    finally:
        _limit[0] = saved


def current_limit() -> int:
    """The most steps a run may take now (:func:`step_limit`)."""
    return _limit[0]


def step_at(time_s: float, dt: float, flag: str = "--time") -> int:
    """Index of the step nearest ``time_s`` (>= 0, within the step limit: :data:`MAX_STEPS`
    unless :func:`step_limit` says otherwise)."""
    time_s = _time(flag, time_s)
    limit = _limit[0]
    if time_s / dt > limit:
        raise UserError(f"{flag} {time_s:g} is {time_s / dt:.3g} steps of dt = {dt:g} s; "
                        f"the limit is {limit:,} steps (--max-steps N allows more)")
    return int(round(time_s / dt))


def frame_steps(duration: float, fps: int, dt: float, speed: float = 1.0) -> np.ndarray:
    """Step index of each video frame: frame f shows the step nearest t = f speed / fps.

    ``speed`` is simulated seconds per video second (1: real time), so the video
    lasts ``duration / speed`` seconds.
    """
    step_at(duration, dt, "--duration")
    frames = duration / speed * fps
    if frames > MAX_FRAMES:
        raise UserError(f"--duration {duration:g} at --fps {fps} and --speed {speed:g} is "
                        f"{frames:.3g} frames; the limit is {MAX_FRAMES:,}")
    n = int(round(frames))
    return np.rint(np.arange(n) * (speed / (fps * dt))).astype(np.int64)


def play(system: physics.System, steps) -> Iterator[physics.System]:
    """Step ``system`` in place to each of ``steps`` (ascending) and yield it there."""
    for target in steps:
        physics.step(system, int(target) - system.steps)
        yield system
