"""Run a VPython program headless and turn it into a video (or a still) and a page.

The program is the user's own code, run in this process as ``__main__`` with
``vpython`` (and the older ``visual``) importing springscene's module; no sandbox
is promised. Its clock is :mod:`springscene.vpython.api.runtime`'s: frames are taken
on ``rate`` calls, and the run ends when the program ends or when the video has
its frames. An exception in the program is reported with the program's own
traceback (its file and line, springscene's frames left out): :class:`ProgramError`;
``sys.exit(n)`` is :class:`ProgramExit` with Python's status. ``springscene vpython``
runs this in a child process that owns nothing (:mod:`.supervise`, :mod:`.child`).
"""

from __future__ import annotations

import numbers
import os
import sys
import time
import traceback
import types
from dataclasses import dataclass, field
from pathlib import Path

from .. import api as vp
from ...errors import OutputError, ProgramError, UserError
from ...outputs import VIDEO_FORMATS, atomic_path, check_output, check_video_fps, write_png
from ..api import attachments, runtime, widgets
from ..draw import autoscale, renderer
from ..dialects import compiling, glowscript, visual6
from ..api.vectors import set_lenient
from ..api.canvases import CanvasSizeError, canvas
from ..page.film import Film, Printed
from ..api.graphs import graphs
from ..page import graph_images
from ..page.html_page import write_page

FORMATS = VIDEO_FORMATS + (".png",)
DEFAULT_FPS = 50
DEFAULT_DURATION = 10.0          # program seconds, when neither --duration nor --frames
MAX_FRAMES = 360_000             # two hours at 50 frames/s
MAX_FPS = 1000                   # frames per program second
OVERLAYS = ("graph",)
_PACKAGE = str(Path(__file__).resolve().parents[2])        # springscene itself


@dataclass
class ProgramResult:
    path: Path
    frames: int
    fps: int
    program_seconds: float       # the program clock when the run ended
    seconds: float               # wall time
    ended: str                   # "program" (it ended), "duration" or "frames"
    size: tuple[int, int] | None = None                   # the video's (width, height)
    dialect: str = "VPython 7"                            # what the program was written for
    page: Path | None = None
    images: list[Path] = field(default_factory=list)      # graphs and scene.capture()s
    notes: list[str] = field(default_factory=list)        # what ran without a user
    peak_memory: int | None = None    # bytes, the run's largest resident set (a supervised run)


class ProgramExit(ProgramError):
    """The program called ``sys.exit`` with a failure: ``status`` is the exit status
    Python would give (an int's low byte, 1 for anything else, whose text is ``said``)."""

    def __init__(self, path: Path, code) -> None:
        if isinstance(code, int):
            self.status, self.said = (code % 256) or 1, None
        else:
            self.status, self.said = 1, str(code)
        super().__init__(f"{path}: the program exited with status {self.status}"
                         + (f" ({self.said})" if self.said is not None else ""))


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


def _user_traceback(exc: BaseException) -> str:
    """The traceback of ``exc`` with springscene's own frames dropped.

    With the environment variable ``SPRINGSCENE_DEBUG`` set, every frame is kept
    (for finding a fault in springscene itself).
    """
    tbe = traceback.TracebackException.from_exception(exc)
    if os.environ.get("SPRINGSCENE_DEBUG"):
        return "".join(tbe.format()).rstrip("\n")

    def strip(t: traceback.TracebackException | None, seen: set) -> None:
        if t is None or id(t) in seen:
            return
        seen.add(id(t))
        t.stack = traceback.StackSummary.from_list(
            [f for f in t.stack if not str(Path(f.filename).resolve()).startswith(_PACKAGE)])
        strip(t.__cause__, seen)
        strip(t.__context__, seen)

    strip(tbe, set())
    return "".join(tbe.format()).rstrip("\n")


def _program_line(exc: BaseException) -> str:
    """``"prog.py, line 3: "``: the program's innermost frame in ``exc``'s traceback."""
    where = ""
    for frame in traceback.extract_tb(exc.__traceback__):
        if not str(Path(frame.filename).resolve()).startswith(_PACKAGE):
            where = f"{frame.filename}, line {frame.lineno}: "
    return where


def _install_modules():
    """Make ``import vpython`` import springscene's module, and ``visual`` (with
    ``visual.graph`` and the rest) VPython 6's names on it (:mod:`..dialects.visual6`)."""
    found = {"vpython": vp, **visual6.modules(vp)}
    saved = {name: sys.modules.get(name) for name in found}
    sys.modules.update(found)
    return saved


def _forget_program_modules(before: set, folder: Path) -> None:
    """Unload the modules the program imported from its own folder: a second run in this
    process imports them afresh (with the new ``scene``)."""
    for name in set(sys.modules) - before:
        file = getattr(sys.modules[name], "__file__", None)
        if file and Path(file).resolve().is_relative_to(folder):
            del sys.modules[name]


def _restore_modules(saved: dict) -> None:
    for name, module in saved.items():
        if module is None:
            sys.modules.pop(name, None)
        else:
            sys.modules[name] = module


MAX_LOD_PX = 5.0      # --lod: coarser than this and helices lose their shape


def check_lod(px) -> None:
    """``lod`` (``--lod``): None, or a number of pixels more than 0 and at most
    :data:`MAX_LOD_PX`; anything else is a one-line :class:`UserError`."""
    if px is None:
        return
    ok = isinstance(px, numbers.Real) and not isinstance(px, bool) and 0 < px <= MAX_LOD_PX
    if not ok:                               # nan fails the comparison
        raise UserError(f"--lod {px!r}: the level of detail must be more than 0 and at "
                        f"most {MAX_LOD_PX:g} pixels")


def run_program(program, out, *, duration: float | None = None, frames: int | None = None,
                fps: int = DEFAULT_FPS, backend: str = "auto", antialias: bool = True,
                overlays: tuple[str, ...] = (), page: bool = True, canvas_only: bool = False,
                on_frame=None, on_dialect=None, quality: str = "medium",
                lod: float | None = None) -> ProgramResult:
    """Run a VPython program and write its video (MP4, GIF) or final still (PNG).

    A frame is the program's page as VPython lays it out (titles, canvases, captions,
    graphs: :mod:`..page.film`), or with ``canvas_only`` the first canvas alone at its own
    size. Beside ``out`` go ``<out's name>.html`` (the page VPython would show, with the
    video), the program's graphs as PNGs, and any ``scene.capture`` PNGs.
    ``on_frame(index, image)`` is called for each frame taken (for tests);
    ``on_dialect(dialect)`` once the program's dialect is known, before it runs.
    ``lod``: helices drawn coarser, within ``lod`` pixels (:func:`..draw.renderer.coarser_detail`).
    """
    path, out, still, budget, limit = _check_request(program, out, duration, frames, fps,
                                                     overlays)
    check_lod(lod)
    code, dialect = _compile(path)
    if on_dialect is not None:
        on_dialect(dialect)
    vp.reset()
    graph_images.reset()          # the graph figures of an earlier run in this process
    start = time.perf_counter()
    images: list[Path] = []
    with atomic_path(out) as tmp, renderer.coarser_detail(lod):
        film = Film(None if still else tmp, fps, overlays, backend, antialias, on_frame,
                    canvas_only, quality=quality)

        capture = _capturer(out, film, images)
        # a still only needs the end: the clock runs, no frame is taken on it
        timeline = runtime.Timeline(fps, budget, (lambda: None) if still else film.take)
        # at each of VPython's renders: attached trails and arrows move, autoscale widens
        timeline.on_render = lambda: (attachments.update(), autoscale.at_render())
        ended = _execute(code, path, dialect, timeline, capture, limit, film)
        attachments.update()      # the render after the program's last step
        try:
            if still:
                picture = film.still()
                write_png(tmp, picture)
                film.size = (picture.shape[1], picture.shape[0])
            elif film.frames == 0:            # no rate(): the final scene is the video
                film.take()
        finally:
            film.close(True)
        result = ProgramResult(out, 1 if still else film.frames, fps, timeline.seconds,
                               time.perf_counter() - start, ended,
                               size=film.writer.size if film.writer is not None else film.size,
                               dialect=dialect.name)
    result.images = images + _write_extras(out, result, page, still, film.printed.text(),
                                           canvas_only)
    result.notes = film.notes + widgets.notes() + _timing_notes(timeline, fps, ended, duration)
    return result


def _timing_notes(timeline: runtime.Timeline, fps: int, ended: str,
                  duration: float | None) -> list[str]:
    """What the user should know about the run's clock: a rate() too fast to keep, frames
    that repeat, the default duration."""
    notes = []
    if timeline.capped_rate is not None:
        notes.append(f"rate({timeline.capped_rate:g}) ran as fast as it goes: each "
                     "iteration took the time it took to compute (at least "
                     f"1/{runtime.MAX_RATE:,} s), as in VPython")
    if timeline.repeats:
        notes.append(f"{timeline.repeats} of {timeline.frames} frames repeat the one "
                     f"before: the program's rate({timeline.slowest:g}) moves it "
                     f"{timeline.slowest:g} times a program second, and --fps is {fps} "
                     "(a lower --fps gives each frame its own picture)")
    if ended == "duration" and duration is None:
        notes.append(f"stopped at {DEFAULT_DURATION:g} s of program time "
                     "(the default; use --duration or --frames)")
    return notes


def _capturer(out: Path, film: Film, images: list[Path]):
    """``scene.capture(name)``: the canvas saved beside ``out`` (``capture("")``, which
    would be a hidden ".png", as ``<out>-capture.png``)."""
    def capture(cv, name: str) -> None:
        name = Path(name).name
        if name.startswith("."):
            name = f"{out.stem}-capture{name}"
        target = out.parent / name
        write_png(target, film.renderer(cv).frame())
        images.append(target)

    return capture


def _check_request(program, out, duration: float | None, frames: int | None, fps: int,
                   overlays: tuple[str, ...]) -> tuple[Path, Path, bool, int, str]:
    """The program, the checked output, whether it is a still, and the frame budget
    (how many frames, and what ``ended`` says when they are all taken)."""
    path = _check_program(program)
    out = check_output(out, FORMATS)
    for name in overlays:
        if name not in OVERLAYS:
            raise UserError(f"--overlay: unknown overlay {name!r} (choose from "
                            f"{', '.join(OVERLAYS)})")
    still = out.suffix.lower() == ".png"
    if still and frames is not None:
        raise UserError("--frames: a .png output is one still; leave --frames out")
    budget, limit = _frame_budget(duration, frames, fps)
    if not still:
        check_video_fps(out, fps)
    return path, out, still, budget, limit


def _compile(path: Path) -> tuple[types.CodeType, compiling.Dialect]:
    """The program's code and dialect; a syntax error is reported with the program's own
    traceback."""
    try:
        source = path.read_text(encoding="utf-8-sig")
    except UnicodeDecodeError:
        raise UserError(f"{path}: not a UTF-8 text file") from None
    dialect = compiling.detect(source)
    try:
        return compiling.compile_program(source, str(path), dialect), dialect
    except SyntaxError as exc:
        raise ProgramError(_user_traceback(exc)) from None


def _execute(code: types.CodeType, path: Path, dialect: compiling.Dialect,
             timeline: runtime.Timeline, capture, limit: str, film: Film) -> str:
    """Run the program as ``__main__`` on ``timeline``; how it ended ("program" or
    ``limit``). Its modules, ``sys.argv`` and ``sys.path`` are put back afterwards."""
    saved = _install_modules()
    modules_before = set(sys.modules)
    saved_argv, saved_path = sys.argv, list(sys.path)
    sys.argv = [str(path)]
    sys.path.insert(0, str(path.resolve().parent))
    runtime.start(timeline)
    runtime.set_capture(capture)
    canvas._measurer = lambda cv: film.renderer(cv).sync()
    set_lenient(dialect.kind == "vpython6")
    old_clock = _old_time_clock(dialect)
    names = {"__name__": "__main__", "__file__": str(path), "__builtins__": __builtins__,
             "input": widgets.program_input}
    if dialect.kind == "glowscript":
        names.update(glowscript.names(vp), **compiling.HELPERS)
    ended, ok = "program", False
    saved_stdout = sys.stdout
    sys.stdout = film.printed = Printed(saved_stdout)
    try:
        exec(code, names)
        ok = True
    except runtime.Stop:
        ended, ok = limit, True
    except SystemExit as exc:
        if exc.code not in (None, 0):
            raise ProgramExit(path, exc.code) from None
        ok = True
    except (KeyboardInterrupt, OutputError):   # a stop signal; a write that failed
        raise
    except CanvasSizeError as exc:   # one line, at the program's line that set the size
        raise ProgramError(f"springscene: {_program_line(exc)}{exc}") from None
    except BaseException as exc:     # the program's own error, with its own traceback
        raise ProgramError(_user_traceback(exc)) from None
    finally:
        sys.stdout = saved_stdout
        runtime.start(None)
        runtime.set_capture(None)
        canvas._measurer = None
        set_lenient(False)
        old_clock()
        sys.argv, sys.path[:] = saved_argv, saved_path
        _restore_modules(saved)
        _forget_program_modules(modules_before, path.resolve().parent)
        if not ok:
            film.close(False)
    return ended


def _old_time_clock(dialect: compiling.Dialect):
    """VPython 6 programs were written for Pythons that had ``time.clock`` (gone in 3.8):
    for their runs it is ``time.perf_counter``. Returns the undo."""
    if dialect.kind != "vpython6" or hasattr(time, "clock"):
        return lambda: None
    time.clock = time.perf_counter
    return lambda: delattr(time, "clock")


def _write_extras(out: Path, result: ProgramResult, page: bool, still: bool,
                  printed: str = "", canvas_only: bool = False) -> list[Path]:
    """The program's graphs as PNGs and the page (``out`` named ``.html``) beside ``out``."""
    written = list(graph_images.write_images(graphs(), out.parent, out.stem)) if graphs() else []
    if page:
        cv = next((c for c in canvas._all if c._objects), canvas.get_selected())
        kind = "image" if still else ("gif" if out.suffix.lower() == ".gif" else "video")
        result.page = write_page(out.with_suffix(".html"), title_html=cv.title,
                                 caption_html=cv.caption, media=out.name, media_kind=kind,
                                 width=result.size[0] if result.size else int(cv.width),
                                 height=result.size[1] if result.size else int(cv.height),
                                 graph_images=[p.name for p in written],
                                 widgets=widgets.widgets_in_order(), printed=printed,
                                 page_video=not canvas_only)
    return written
