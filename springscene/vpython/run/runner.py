"""Run a VPython program headless and turn it into a video (or a still) and a page.

The program is the user's own code, run in this process as ``__main__`` with
``vpython`` (and the older ``visual``) importing springscene's module; no sandbox
is promised. Its clock is :mod:`springscene.vpython.core.runtime`'s: frames are taken
on ``rate`` calls, and the run ends when the program ends or when the video has
its frames. An exception in the program is reported with the program's own
traceback (its file and line, springscene's frames left out): :class:`ProgramRaised`,
once the files up to the error are written when it came after the first frame (as
VPython's page shows the animation up to the error); ``sys.exit(n)`` is
:class:`ProgramExit` with Python's status. ``springscene vpython``
runs this in a child process that owns nothing (:mod:`.supervise`, :mod:`.child`).
"""

from __future__ import annotations

import contextlib
import errno
import importlib.metadata
import os
import tempfile
import sys
import time
import traceback
import types
from dataclasses import dataclass, field
from pathlib import Path
from typing import Callable

from ...errors import OutputError, ProgramError, UserError
from ...outputs import atomic_path, hidden_name, write_png
from .. import api as vp
from ..api import attachments
from ..core import runtime, widgets
from ..core.canvases import CanvasSizeError, canvas, canvases
from ..api.graphs import graphs
from ..dialects import compiling, glowscript, visual6
from ..draw import autoscale
from ..page import graph_images
from ..page.film import Film, Printed
from ..page.html_page import write_page
from ..page.interactive import write_interactive_page
from ..record.recorder import Recorder
from .options import DATA_FORMATS, DEFAULT_DURATION, RunOptions, check_request
from .session import ProgramSession

_PACKAGE = Path(__file__).resolve().parents[2]         # springscene itself
_EXAMPLES = _PACKAGE / "examples"                       # programs it ships: a user's own
_NONE = object()
PAGE_MAX_OBJECTS = 5_000     # a page beside a video or still: more objects, the picture page


def _ours(filename: str) -> bool:
    """Whether a traceback's frame is springscene's own code, not a program's (one of the
    examples it ships included)."""
    path = Path(filename).resolve()
    return path.is_relative_to(_PACKAGE) and not path.is_relative_to(_EXAMPLES)


@dataclass
class ProgramResult:
    path: Path
    frames: int
    fps: int
    program_seconds: float       # the program clock when the run ended
    seconds: float               # wall time
    ended: str                   # "program" (it ended), "duration", "frames" or "error"
    size: tuple[int, int] | None = None                   # the video's (width, height)
    dialect: str = "VPython 7"                            # what the program was written for
    page: Path | None = None
    recording: Path | None = None                         # --record's file
    images: list[Path] = field(default_factory=list)      # graphs and scene.capture()s
    notes: list[str] = field(default_factory=list)        # what ran without a user
    peak_memory: int | None = None    # bytes, the run's largest resident set (a supervised run)
    error: dict | None = None         # the program's error it ended at (ProgramRaised.error)


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


class ProgramRaised(ProgramError):
    """The program raised: ``str()`` is its own traceback, and, when the run's files up to
    the error were written (``result``, a :class:`ProgramResult` whose ``ended`` is
    ``"error"``), one line more saying where they end (:func:`ended_at_error`).

    ``error`` is what the recording's end line keeps (docs/recording.md): the exception's
    ``type`` and ``message``, the program time ``t`` it was raised at, the program's
    ``line`` and its ``traceback``. A program that raised before its first frame has no
    ``result``: nothing was written. :func:`springscene.run_vpython` gives the run up to
    the error as ``run`` (a ``Run``, when there is a recording) and ``video`` (a
    ``Video``, for a video or still output).
    """

    def __init__(self, traceback_text: str, error: dict,
                 result: ProgramResult | None = None) -> None:
        super().__init__(traceback_text)
        self.traceback, self.error, self.result = traceback_text, error, result
        self.run = self.video = None

    def __str__(self) -> str:
        if self.result is None:
            return self.traceback
        return f"{self.traceback}\n{ended_at_error(self.result)}"


def ended_at_error(result: ProgramResult) -> str:
    """The one line after the traceback of a program that raised once its frames had
    begun: the video (or still, recording, page) ends at the program's error, at its
    program time; the frame is the last one's index (its time ``frame / fps``)."""
    at = f"at t = {result.program_seconds:.2f} s"
    suffix = result.path.suffix.lower()
    if suffix == ".png":
        return f"springscene: the picture is the scene at the program's error, {at}"
    what = {".jsonl": "recording", ".html": "page"}.get(suffix, "video")
    return (f"springscene: the {what} ends at the program's error, {at} "
            f"(frame {max(result.frames - 1, 0)})")


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
            [f for f in t.stack if not _ours(f.filename)])
        strip(t.__cause__, seen)
        strip(t.__context__, seen)

    strip(tbe, set())
    return "".join(tbe.format()).rstrip("\n")


def _program_line(exc: BaseException) -> str:
    """``"prog.py, line 3: "``: the program's innermost frame in ``exc``'s traceback."""
    where = ""
    for frame in traceback.extract_tb(exc.__traceback__):
        if not _ours(frame.filename):
            where = f"{frame.filename}, line {frame.lineno}: "
    return where


def run_program(program, out, options: RunOptions = RunOptions(), *,
                on_frame: Callable | None = None, on_dialect: Callable | None = None,
                on_end: Callable | None = None) -> ProgramResult:
    """Run a VPython program and write its video (MP4, GIF, ...) or final still (PNG).

    A frame is the program's page as VPython lays it out (:mod:`..page.film`), or with
    ``options.canvas_only`` the first canvas alone. Beside ``out`` go its page
    (``.html``), graphs and ``scene.capture`` PNGs. ``on_frame(index, image)`` is called
    for each frame (tests), ``on_dialect(dialect)`` before the program runs, ``on_end(error)``
    once it ended (:class:`.session.ProgramSession`). A program that raises after its
    first frame has its files written up to the error, the scene at the error their last
    frame, and raises :class:`ProgramRaised` with them (``result``); before, nothing.
    """
    request = check_request(program, out, options)
    path, out, still = request.program, request.out, request.still
    data_only = out.suffix.lower() in DATA_FORMATS      # the recording (or its page) alone
    code, dialect = _compile(path)
    vp.reset()
    graph_images.reset()          # the graph figures of an earlier run in this process
    start = time.perf_counter()
    images: list[Path] = []
    names = _namespace(path, dialect)
    if on_dialect is not None:    # with its notes: how the program was read
        on_dialect(dialect)
    # the names the program is given, not its own (VPython 6's star import brings numpy's)
    given = {**(visual6.namespace(vp) if dialect.kind == "vpython6" else {}), **names}
    with contextlib.ExitStack() as files:
        tmp = files.enter_context(atomic_path(out))
        recorder = _recorder(files, path, out, tmp, options, dialect)
        film = Film(None if still or data_only else tmp, options.fps, options.overlays,
                    options.backend, options.antialias, on_frame, options.canvas_only,
                    quality=options.quality, lod=options.level_of_detail())
        # a still only needs the end: the clock runs, no frame is taken on it
        timeline = runtime.Timeline(options.fps, request.budget,
                                    _frame_taker(film, recorder, still, data_only, on_frame))
        # at each of VPython's renders: attached trails and arrows move, autoscale widens
        timeline.on_render = lambda: (attachments.update(), autoscale.at_render())
        ended, raised = _until_end(film, timeline, lambda: _execute(
            code, path, dialect, timeline, _capturer(out, film, images), request.limit, film,
            names, on_end, recorder))
        try:
            result = _finish(film, recorder, timeline, tmp, request, options, ended,
                             dialect.name, start, images,
                             lambda: _end(recorder, timeline, ended, names, given, raised))
        except Exception as failure:      # the program's error still comes first
            if raised is None:
                raise
            raise ProgramRaised(f"{raised.traceback}\nspringscene: nothing written: "
                                f"{failure}", raised.error) from None
    result.notes = dialect.notes + ([] if data_only else film.notes) + widgets.notes() + \
        _timing_notes(timeline, options.fps, ended, options.duration) + result.notes
    if raised is not None:
        result.error, raised.result = raised.error, result
        raise raised
    return result


def _until_end(film: Film, timeline: runtime.Timeline,
               execute: Callable[[], str]) -> tuple[str, ProgramRaised | None]:
    """Run the program (``execute``): how it ended, and its error when it raised after its
    first frame (its files up to the error are still to be written); an error before
    that, or any other, is raised with the film closed unwritten."""
    try:
        return execute(), None
    except ProgramRaised as exc:
        exc.error["t"] = timeline.seconds
        if timeline.frames > 0:
            return "error", exc
        film.close(False)
        raise
    except BaseException:
        film.close(False)
        raise


def _finish(film: Film, recorder: Recorder | None, timeline: runtime.Timeline, tmp: Path,
            request, options: RunOptions, ended: str, dialect: str, start: float,
            images: list[Path], end: Callable[[], dict]) -> ProgramResult:
    """The run's files once the program has ended (or raised): the last frames, the
    recording's end line (``end()``, once its last frame is taken), the graphs and the
    page."""
    out, still = request.out, request.still
    data_only = out.suffix.lower() in DATA_FORMATS
    attachments.update()      # the render after the program's last step
    _last_frames(film, recorder, timeline, tmp, still, data_only, ended)
    frames = (1 if still else recorder.frames if data_only else film.frames)
    result = ProgramResult(out, frames, options.fps,
                           timeline.seconds, time.perf_counter() - start, ended,
                           size=film.writer.size if film.writer is not None else film.size,
                           dialect=dialect)
    if recorder is not None:
        _close_recording(recorder, result, options, tmp, end())
    if not data_only:
        result.images = images + _write_extras(out, result, options.page, still,
                                               film.printed.text(), options.canvas_only,
                                               recorder)
    return result


def _close_recording(recorder: Recorder, result: ProgramResult, options: RunOptions,
                     tmp: Path, end: dict) -> None:
    """The recording finished with its ``end`` line; an ``.html`` output is its page."""
    recorder.close(end)
    if options.record is not None:
        result.recording = Path(options.record)
    if result.path.suffix.lower() == ".html":
        write_interactive_page(recorder.path, tmp, widgets=widgets.widgets_in_order())


def _last_frames(film: Film, recorder: Recorder | None, timeline: runtime.Timeline,
                 tmp: Path, still: bool, data_only: bool, ended: str) -> None:
    """The end of the run's pictures: a still's one picture; a video of a program that
    never called ``rate`` is its final scene, and one of a program that raised ends with
    the scene at its error (the frame after the last one taken: VPython's page shows that
    scene under the error). The recording also keeps the scene as the program left it,
    when it ended (or raised) after the last frame (what VPython's page shows then)."""
    try:
        if still:
            picture = film.still()
            write_png(tmp, picture)
            film.size = (picture.shape[1], picture.shape[0])
        elif (film.frames == 0 or ended == "error") and not data_only:
            film.take()         # (at an error: the scene the program left, one frame more)
        by_program = ended in ("program", "error")
        if recorder is not None and (recorder.frames == 0 or (
                by_program and timeline.seconds > (recorder.frames - 1) / recorder.fps)):
            autoscale.at_render()         # the browser's renders after the program's end
            # at the program's end; a run stopped by its limit shows the last frame time's scene
            recorder.take(timeline.seconds if by_program
                          else max(timeline.frames - 1, 0) / timeline.fps)
    finally:
        film.close(True)


def _recorder(files: contextlib.ExitStack, path: Path, out: Path, tmp: Path,
              options: RunOptions, dialect) -> Recorder | None:
    """The run's recorder, when the run keeps one: the output itself (``.jsonl``),
    ``--record``'s file (moved into place whole when the run ends well), or a hidden file
    beside ``out`` for the interactive page (``.html``, and the page beside a video or
    still), removed at the end."""
    suffix = out.suffix.lower()
    limit = None
    if suffix == ".jsonl":
        target = tmp
    elif options.record is not None:
        target = files.enter_context(atomic_path(Path(options.record)))
    elif suffix == ".html" or options.page:
        limit = None if suffix == ".html" else PAGE_MAX_OBJECTS
        fd, name = tempfile.mkstemp(prefix=f"{hidden_name(out)}.", suffix=".jsonl",
                                    dir=out.parent)
        os.close(fd)
        target = Path(name)
        files.callback(target.unlink, missing_ok=True)
    else:
        return None
    recorder = Recorder(target, options.fps, path.name, dialect.name, _version(), limit)
    files.callback(recorder.discard)      # closed, if the run ended before close()
    return recorder


def _version() -> str:
    try:
        return importlib.metadata.version("springscene")
    except importlib.metadata.PackageNotFoundError:
        return ""


def _frame_taker(film: Film, recorder: Recorder | None, still: bool, data_only: bool,
                 on_frame: Callable | None):
    """What the clock calls at each frame: the video's frame and the recording's (a
    recording alone tells ``on_frame(index, None)``)."""
    if recorder is None:
        return (lambda: None) if still else film.take
    if still:                # the picture is the end; the recording keeps the run's frames
        return recorder.take
    if data_only:
        def record() -> None:
            recorder.take()
            if on_frame is not None:
                on_frame(recorder.frames - 1, None)
        return record

    def take() -> None:
        film.take()
        recorder.take()
    return take


def _end(recorder: Recorder, timeline: runtime.Timeline, ended: str, names: dict,
         given: dict, raised: ProgramRaised | None = None) -> dict:
    """The recording's end line (docs/recording.md): the program's own globals, not the
    names VPython gave it (``given``, the namespace it started with, or ``vpython``'s);
    the program's error, when it ended in one."""
    own = {name: v for name, v in names.items()
           if given.get(name, _NONE) is not v and getattr(vp, name, _NONE) is not v}
    held, values = recorder.names(own)
    return {"t": timeline.seconds, "frames": recorder.frames, "ended": ended,
            "error": None if raised is None else raised.error,
            "names": held, "globals": values}


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


def _namespace(path: Path, dialect: compiling.Dialect) -> dict:
    """The globals a program runs in as ``__main__``."""
    names = {"__name__": "__main__", "__file__": str(path), "__builtins__": __builtins__,
             "input": widgets.program_input}
    if dialect.kind == "glowscript":
        names.update(glowscript.names(vp, dialect.version), **compiling.HELPERS)
    elif dialect.converted:             # a VPython 7 program converted from GlowScript
        given, note = glowscript.converted_names(vp, dialect.unbound, dialect.converted)
        names.update(given)
        dialect.notes.extend([note] if note else [])
    return names


def _execute(code: types.CodeType, path: Path, dialect: compiling.Dialect,
             timeline: runtime.Timeline, capture: Callable, limit: str, film: Film,
             names: dict, on_end: Callable | None = None,
             recorder: Recorder | None = None) -> str:
    """Run the program as ``__main__`` in its :class:`.session.ProgramSession`, in the
    globals ``names``; how it ended ("program" or ``limit``)."""
    film.printed = Printed(sys.stdout, also=recorder.printed if recorder else None)
    with ProgramSession(path, dialect, timeline, capture,
                        lambda cv: film.renderer(cv).sync(), film.printed, on_end):
        return _run(code, names, path, limit)


def _run(code: types.CodeType, names: dict, path: Path, limit: str) -> str:
    """``exec`` the program; how it ended, or its own error as springscene reports it:
    :class:`ProgramExit` for ``sys.exit`` with a failure, :class:`ProgramRaised` with the
    program's own traceback (a :class:`ProgramError` of one line for a canvas size it
    cannot have or a capture that cannot be written: nothing is written then)."""
    try:
        exec(code, names)
    except runtime.Stop:
        return limit
    except SystemExit as exc:
        if exc.code not in (None, 0):
            raise ProgramExit(path, exc.code) from None
    except (KeyboardInterrupt, OutputError):   # a stop signal; a write that failed
        raise
    except CanvasSizeError as exc:   # one line, at the program's line that set the size
        raise ProgramError(f"springscene: {_program_line(exc)}{exc}") from None
    except BaseException as exc:     # the program's own error, with its own traceback
        raise _raised(exc, path) from None
    return "program"


def _raised(exc: BaseException, path: Path) -> ProgramRaised:
    """The program's own exception as springscene reports it (its program time ``t`` is
    the clock's, filled in by the run; its ``line`` the program file's last line in the
    traceback, not one of a library the program called)."""
    told = _user_traceback(exc)
    frames = traceback.extract_tb(exc.__traceback__)
    lines = [f.lineno for f in frames if f.filename == str(path)] or \
        [f.lineno for f in frames if not _ours(f.filename)]
    return ProgramRaised(told, {"type": type(exc).__name__, "message": str(exc), "t": None,
                                "line": lines[-1] if lines else None, "traceback": told})


def _write_extras(out: Path, result: ProgramResult, page: bool, still: bool,
                  printed: str = "", canvas_only: bool = False,
                  recorder: Recorder | None = None) -> list[Path]:
    """The program's graphs as PNGs and the page (``out`` named ``.html``) beside ``out``:
    the run's interactive page (GlowScript replaying the recording, the video or still
    linked; a still's page opens at its picture, the scene the program left), or, where
    GlowScript's library cannot be had, the page with the picture."""
    written = list(graph_images.write_images(graphs(), out.parent, out.stem)) if graphs() else []
    if not page:
        return written
    html_out = out.with_suffix(".html")
    if recorder is not None and recorder.gave_up:
        result.notes.append(f"{html_out.name} shows the picture, not the interactive page: "
                            f"the scene has more than {PAGE_MAX_OBJECTS:,} objects")
    elif recorder is not None:
        try:
            result.page = write_interactive_page(recorder.path, html_out, video=out,
                                                 widgets=widgets.widgets_in_order(),
                                                 at_end=still)
            return written
        except OutputError as exc:
            if exc.errno != errno.ENETUNREACH:       # not the library: a write that failed
                raise
            result.notes.append(f"{html_out.name} shows the video, not the interactive "
                                f"page: {exc.reason}")
    cv = next((c for c in canvases() if c._objects), canvas.get_selected())
    kind = "image" if still else ("gif" if out.suffix.lower() == ".gif" else "video")
    result.page = write_page(html_out, title_html=cv.title,
                             caption_html=cv.caption, media=out.name, media_kind=kind,
                             width=result.size[0] if result.size else int(cv.width),
                             height=result.size[1] if result.size else int(cv.height),
                             graph_images=[p.name for p in written],
                             widgets=widgets.widgets_in_order(), printed=printed,
                             page_video=not canvas_only)
    return written
