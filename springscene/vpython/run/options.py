"""What a VPython run is asked to do: :class:`RunOptions`, and the checks a request passes
before anything runs (the program readable, the output's format, the frame budget).

Every refusal is one line naming the flag (``--fps``, ``--duration``, ``--lod``, ...),
the same for the command line and the Python API.
"""

from __future__ import annotations

import dataclasses
import numbers
import os
from dataclasses import dataclass
from pathlib import Path
from typing import NamedTuple

from ...errors import UserError
from ...outputs import VIDEO_FORMATS, check_output, check_video_fps
from ..geometry.lod import LevelOfDetail, coarser

DATA_FORMATS = (".jsonl", ".html")   # the run's recording, or its interactive page: no video
FORMATS = VIDEO_FORMATS + (".png",) + DATA_FORMATS
RECORD_SUFFIXES = (".jsonl", ".jsonl.gz")
DEFAULT_FPS = 50
DEFAULT_DURATION = 10.0          # program seconds, when neither --duration nor --frames
MAX_FRAMES = 360_000             # two hours at 50 frames/s
MAX_FPS = 1000                   # frames per program second
OVERLAYS = ("graph",)
MAX_LOD_PX = 5.0                 # --lod: coarser than this and helices lose their shape


@dataclass(frozen=True)
class RunOptions:
    """How a program is run and drawn.

    ``duration`` (program seconds) or ``frames`` bound the video (neither: the default
    duration); ``fps`` frames a program second; ``backend`` (``auto``, ``egl``,
    ``osmesa``); ``antialias`` (False: ``--draft``); ``overlays`` drawn under the canvas
    (``graph``); ``page``: the HTML page beside the output; ``canvas_only``: the first
    canvas alone rather than the page; ``quality`` of the video encoding; ``lod``: helices
    drawn within ``lod`` pixels of the true curves (None: the default detail; a
    :class:`~..geometry.lod.LevelOfDetail` as it is, such as ``lod.FULL``, VPython's own
    detail, which benchmarks measure against); ``record``: a file (``.jsonl`` or
    ``.jsonl.gz``) to keep the run's recording in (docs/recording.md).
    """

    duration: float | None = None
    frames: int | None = None
    fps: int = DEFAULT_FPS
    backend: str = "auto"
    antialias: bool = True
    overlays: tuple[str, ...] = ()
    page: bool = True
    canvas_only: bool = False
    quality: str = "medium"
    lod: float | LevelOfDetail | None = None
    record: str | None = None

    def level_of_detail(self) -> LevelOfDetail:
        """What the renderers draw with."""
        return self.lod if isinstance(self.lod, LevelOfDetail) else coarser(self.lod)

    def to_request(self) -> dict:
        """The options as JSON-ready data, for a supervised run's child."""
        return dataclasses.asdict(self)

    @classmethod
    def from_request(cls, data: dict) -> RunOptions:
        """The options :meth:`to_request` gave."""
        lod = data["lod"]
        if isinstance(lod, dict):
            lod = LevelOfDetail(**{**lod, "sphere_steps": tuple(lod["sphere_steps"])})
        return cls(**{**data, "overlays": tuple(data["overlays"]), "lod": lod})


class Request(NamedTuple):
    """A checked request: the program, the output, whether it is a still, and the frame
    budget (how many frames, and what ``ended`` says when they are all taken)."""

    program: Path
    out: Path
    still: bool
    budget: int
    limit: str


def check_request(program, out, options: RunOptions) -> Request:
    """The program and output checked against ``options``: one-line :class:`UserError`s
    naming the flag for anything a run cannot do."""
    check_lod(options.lod)
    path = _check_program(program)
    out = check_output(out, FORMATS)
    duration, frames, fps = options.duration, options.frames, options.fps
    for name in options.overlays:
        if name not in OVERLAYS:
            raise UserError(f"--overlay: unknown overlay {name!r} (choose from "
                            f"{', '.join(OVERLAYS)})")
    check_record(options.record, out)
    still = out.suffix.lower() == ".png"
    if still and frames is not None:
        raise UserError("--frames: a .png output is one still; leave --frames out")
    budget, limit = _frame_budget(duration, frames, fps)
    if not still and out.suffix.lower() not in DATA_FORMATS:
        check_video_fps(out, fps)
    return Request(path, out, still, budget, limit)


def check_record(record, out: Path | None = None) -> None:
    """``--record FILE``: a ``.jsonl`` or ``.jsonl.gz`` file other than the output (if
    any), in a folder that exists."""
    if record is None:
        return
    path = Path(record)
    if not str(record).strip() or not path.name.lower().endswith(RECORD_SUFFIXES):
        raise UserError(f"--record {record}: the recording is a .jsonl or .jsonl.gz file")
    if out is None:
        check_output(path, (".jsonl", ".gz"), "--record")
        return
    if out.suffix.lower() == ".jsonl":
        raise UserError(f"--record {record}: the output {out.name} is the recording already")
    if os.path.abspath(path) == os.path.abspath(out):
        raise UserError(f"--record {record}: the same file as --out")
    check_output(path, (".jsonl", ".gz"), "--record")


def check_lod(px) -> None:
    """``lod`` (``--lod``): None, or a number of pixels more than 0 and at most
    :data:`MAX_LOD_PX`; anything else is a one-line :class:`UserError`."""
    if px is None:
        return
    if isinstance(px, LevelOfDetail):
        if not px.sphere_steps or not all(isinstance(n, int) and n >= 3
                                          for n in px.sphere_steps):
            raise UserError(f"lod {px!r}: sphere_steps must be whole numbers of 3 or more")
        return
    ok = isinstance(px, numbers.Real) and not isinstance(px, bool) and 0 < px <= MAX_LOD_PX
    if not ok:                               # nan fails the comparison
        raise UserError(f"--lod {px!r}: the level of detail must be more than 0 and at "
                        f"most {MAX_LOD_PX:g} pixels")


def _check_program(program) -> Path:
    path = Path(program)
    if not str(program).strip():
        raise UserError("program: give a VPython program (a .py file)")
    if not path.is_file():
        raise UserError(f"{path}: no such program file")
    if not os.access(path, os.R_OK):
        raise UserError(f"{path}: cannot read it")
    return path


def _frame_budget(duration: float | None, frames: int | None, fps: int) -> tuple[int, str]:
    if not isinstance(fps, int) or fps <= 0:
        raise UserError(f"--fps {fps}: must be a whole number above 0")
    if fps > MAX_FPS:
        raise UserError(f"--fps {fps}: the limit is {MAX_FPS} frames per program second")
    if frames is not None:
        if frames <= 0:
            raise UserError(f"--frames {frames}: must be at least 1")
        if frames > MAX_FRAMES:
            raise UserError(f"--frames {frames}: the limit is {MAX_FRAMES:,}")
        return frames, "frames"
    if duration is None:
        duration = DEFAULT_DURATION
    elif not duration > 0 or duration != duration or duration == float("inf"):
        raise UserError(f"--duration {duration:g}: must be a number of seconds above 0")
    if duration * fps > MAX_FRAMES:
        raise UserError(f"--duration {duration:g} at --fps {fps} is {duration * fps:,.0f} "
                        f"frames; the limit is {MAX_FRAMES:,}")
    n = int(round(duration * fps))
    if n > MAX_FRAMES:
        raise UserError(f"--duration {duration:g} at --fps {fps} is {n:,} frames; "
                        f"the limit is {MAX_FRAMES:,}")
    return max(n, 1), "duration"
