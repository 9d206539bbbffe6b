"""springscene's command line: parse arguments, show progress, map errors to exit codes.

Bad input (a missing file, a bad key or flag) is one line on stderr and exit 2.
Everything a command does is a call into the ``springscene`` library.
"""

from __future__ import annotations

import argparse
import contextlib
import errno
import os
import shutil
import sys
import tempfile
import warnings
from pathlib import Path

from .. import config, jobs
from ..errors import OutputError, ProgramError, UserError
from ..model import timeline
from ..model.integrators import NAMES
from ..model.timeline import MAX_STEPS
from ..science.sweep import parse_omega, summary
from ..view.backend import BACKENDS
from .batch_cli import add_batch_command, run_batch_command
from .compare import add_compare_command, run_compare
from .grade_cli import add_grade_command, run_grade
from .starters import add_init_command, run_init, version
from . import oserrors, signals
from ..video import DEFAULT_QUALITY, QUALITIES
from ..view.info import info
from ..view.overlay import OVERLAYS, parse_overlays
from ..outputs import check_output, hidden_name
from ..vpython.record import trace
from ..vpython.record.reader import read as read_recording
from ..vpython.run.options import FORMATS, MAX_LOD_PX
from ..vpython.run.sandbox import Sandbox, own_folder
from ..vpython.run.supervise import RunEnded
from ..vpython.run.report import size_text

EXIT_BAD_INPUT = 2
EXIT_PROGRAM_ERROR = 1     # the user's VPython program raised
MAX_LINE = 1000            # characters of a message line (a long quoted name is cut)


class _Parser(argparse.ArgumentParser):
    """argparse that reports a usage error on one line, starting ``springscene:`` as every
    message does (a command's own: ``springscene: error: render: argument --fps: ...``)."""

    def error(self, message: str) -> None:  # type: ignore[override]
        command = self.prog.split(" ", 1)[1:]           # "springscene render": the command
        where = f"{command[0]}: " if command else ""
        self.exit(EXIT_BAD_INPUT, f"springscene: error: {where}{message}\n")


def _build_parser() -> argparse.ArgumentParser:
    p = _Parser(prog="springscene", description="Headless ball-and-spring scenes like VPython's.")
    p.add_argument("--version", action="version", version=version())
    sub = p.add_subparsers(dest="command", required=True, parser_class=_Parser)
    _add_numbers_commands(sub)
    _add_picture_commands(sub)
    _add_vpython_command(sub)
    add_batch_command(sub)
    add_compare_command(sub)
    add_init_command(sub)
    add_grade_command(sub)
    s = sub.add_parser("info", help="the off-screen backend, GL renderer and versions")
    s.add_argument("--backend", default="auto", choices=BACKENDS)
    return p


def _renders(sp: argparse.ArgumentParser, video: bool = False) -> None:
    sp.add_argument("--backend", default="auto", choices=BACKENDS,
                    help="off-screen OpenGL: EGL, OSMesa, or auto (EGL if present)")
    sp.add_argument("--draft", action="store_true", help="no anti-aliasing (faster)")
    if video:
        sp.add_argument("-q", "--quality", default=DEFAULT_QUALITY, choices=QUALITIES,
                        help="the video's encoding: low (quick, small), medium (the default) "
                        "or high (near lossless); --draft still sets the anti-aliasing")


def _physics(sp: argparse.ArgumentParser) -> None:
    sp.add_argument("--integrator", choices=NAMES,
                    help="time integrator (default: the config's, else euler-cromer)")
    sp.add_argument("--dt", type=float, help="time step in s (default: the config's)")
    _max_steps(sp)


def _max_steps(sp: argparse.ArgumentParser) -> None:
    sp.add_argument("--max-steps", type=int, metavar="N",
                    help=f"allow runs of up to N physics steps (default {MAX_STEPS:,}; "
                    "longer runs are refused before they start)")


def _add_numbers_commands(sub) -> None:
    """simulate, analyze and sweep: numbers, no pictures."""
    s = sub.add_parser("simulate", help="write the ball's trajectory as CSV")
    s.add_argument("config")
    s.add_argument("--duration", type=float, help="simulated seconds (default: the config's)")
    s.add_argument("--out", required=True, help="trajectory.csv")
    _physics(s)

    s = sub.add_parser("analyze", help="period, frequency, energy... measured beside theory")
    s.add_argument("config")
    s.add_argument("--duration", type=float, help="simulated seconds (default: the config's)")
    s.add_argument("--json", action="store_true", help="one JSON object instead of a table")
    _physics(s)

    s = sub.add_parser("sweep", help="steady-state amplitude against drive frequency")
    s.add_argument("config")
    s.add_argument("--omega", required=True, metavar="START:STOP:N",
                   help="N drive frequencies from START to STOP rad/s")
    s.add_argument("--periods", type=float, default=200,
                   help="drive periods of the slowest frequency to run (default 200)")
    s.add_argument("--out", help="curve.csv (omega [rad/s], frequency [Hz], amplitude [m], "
                   "theory [m])")
    _physics(s)


def _add_picture_commands(sub) -> None:
    """still, render and figures: pictures of a config."""
    s = sub.add_parser("still", help="render the scene at one time to PNG")
    s.add_argument("config")
    s.add_argument("--time", type=float, default=0.0, help="simulated time in s (nearest step)")
    s.add_argument("--out", required=True, help="frame.png")
    _renders(s)
    _physics(s)

    s = sub.add_parser("render", help="render the oscillation to a video (MP4, WebM, Ogg, GIF)")
    s.add_argument("config")
    s.add_argument("--duration", type=float, help="simulated seconds (default: the config's)")
    s.add_argument("--fps", type=int, help="frames per second (default: the config's)")
    s.add_argument("--speed", type=float,
                   help="simulated seconds per video second (default: the config's, "
                        "1 = real time)")
    s.add_argument("--out", required=True,
                   help="video.mp4, .webm (VP9), .ogv (Theora: both upload to a wiki), .gif, "
                   "or page.html: the scene as an interactive VPython page (GlowScript "
                   "draws it; turn, zoom, play and seek in any browser, from disk)")
    s.add_argument("--quiet", action="store_true", help="no progress bar")
    s.add_argument("--overlay", metavar="LIST",
                   help="comma list of: " + ", ".join(OVERLAYS)
                   + " (a clock, a y(t) graph under the scene, energy bars beside it), or "
                   "none (default: a lattice's clock, else none)")
    _renders(s, video=True)
    _physics(s)

    s = sub.add_parser("figures", help="the wiki page's figures, GIF and gallery snippet")
    s.add_argument("config")
    s.add_argument("--out", required=True, help="folder for the figures (created if missing)")
    s.add_argument("--prefix", default="", help="put before every file name, and the names "
                   "in figures.wiki (e.g. BallSpring_: no clash on a shared wiki)")
    _renders(s)
    _max_steps(s)


def _add_vpython_command(sub) -> None:
    s = sub.add_parser("vpython", help="run a VPython program headless: a video (or still) "
                       "and the page VPython would show")
    s.add_argument("program", help="a VPython program: VPython 7 (from vpython import *), "
                   "VPython 6 (from visual import *) or Web VPython (GlowScript header)")
    s.add_argument("--out", required=True,
                   help="video.mp4, .webm, .ogv, .gif, still.png, or run.jsonl (the "
                   "recording alone: docs/recording.md)")
    length = s.add_mutually_exclusive_group()
    length.add_argument("--duration", type=float,
                        help="program seconds to film (default 10, or until the program ends)")
    length.add_argument("--frames", type=int, help="frames to film")
    s.add_argument("--fps", type=int, default=50, help="frames per program second (default 50)")
    s.add_argument("--overlay", default="", metavar="LIST",
                   help="graph: the program's graphs under the canvas (with --canvas-only)")
    s.add_argument("--canvas-only", action="store_true",
                   help="the first canvas alone at its own size (what scene.capture saves), "
                   "not the page (title, canvases, captions, graphs)")
    s.add_argument("--no-page", action="store_true", help="write no OUT.html page")
    s.add_argument("--record", metavar="FILE",
                   help="also keep the run as data: each object, camera, graph and printed "
                   "line at each frame, in FILE (.jsonl or .jsonl.gz; docs/recording.md)")
    s.add_argument("--trace", action="append", default=[], metavar="NAME",
                   help="also write the object the program calls NAME (ball, or atoms[0] of a "
                   "list) over time as CSV beside OUT: OUT-NAME.csv, a row a frame, t [s], "
                   "pos.x [m], ... (SI by the wiki's convention); may be repeated")
    s.add_argument("--quiet", action="store_true", help="no summary line")
    s.add_argument("--timeout", type=float, metavar="S",
                   help="stop the program after S seconds of wall clock (exit 124)")
    s.add_argument("--max-memory", metavar="SIZE",
                   help="stop the program when it uses more memory, e.g. 500M or 2G "
                   "(exit 137; default: half the machine's)")
    s.add_argument("--sandbox", action="store_true",
                   help="run an untrusted program in a sandbox (bubblewrap): it reads only "
                   "its own folder, writes only its outputs, has no network")
    s.add_argument("--lod", type=_lod_pixels, metavar="PX",
                   help="draw helices with polygons within PX pixels of the true curves, "
                   "anti-aliased too (default: 0.03 drafted and VPython's full 60 x 16 "
                   "anti-aliased, within the image tolerance of VPython's own mesh; larger "
                   "is faster: 0.3 runs AtomicSolid 3-4.5x faster, 1.4-2.5 %% of its "
                   "pixels changed)")
    _renders(s, video=True)


def _lod_pixels(text: str) -> float:
    """``--lod``: a number of pixels, more than 0 and at most :data:`MAX_LOD_PX`."""
    try:
        px = float(text)
    except ValueError:
        raise argparse.ArgumentTypeError(f"{text!r} is not a number of pixels") from None
    if not 0 < px <= MAX_LOD_PX:           # nan fails both
        raise argparse.ArgumentTypeError(f"{text}: the level of detail must be more than 0 "
                                         f"and at most {MAX_LOD_PX:g} pixels")
    return px


def _check_out_is_not_input(args: argparse.Namespace) -> None:
    """``--out`` naming the config or program itself (saved under the output's extension)
    would overwrite the user's file: refused."""
    source = getattr(args, "config", None) or getattr(args, "program", None)
    out = getattr(args, "out", None)
    if not source or not out:
        return
    src, dst = Path(source), Path(out)
    try:
        same = dst.exists() and src.exists() and os.path.samefile(src, dst)
    except OSError:
        same = False
    if same or _resolved(src, "") == _resolved(dst, "--out "):
        raise UserError(f"--out {out}: is the input {source} itself; writing there would "
                        "overwrite it (choose another name)")


def _resolved(path: Path, flag: str) -> Path:
    """``path`` with its symbolic links followed; a loop of them is bad input, named."""
    try:
        os.stat(path)
        return path.resolve()
    except FileNotFoundError:
        return path.resolve()                         # (an output not written yet)
    except (RuntimeError, OSError) as exc:            # RuntimeError: resolve() before 3.13
        if isinstance(exc, OSError) and exc.errno != errno.ELOOP:
            return path.absolute()                    # (unreadable: said where it is read)
        raise UserError(f"{flag}{path}: cannot follow its symbolic links (a loop)") from None


def _run(args: argparse.Namespace) -> int:
    if args.command == "info":
        for key, value in info(args.backend).items():
            print(f"{key}: {value}")
        return 0
    if args.command == "compare":
        return run_compare(args)
    if args.command == "init":
        return run_init(args)
    if args.command == "batch":
        return run_batch_command(args)
    if args.command == "grade":
        return run_grade(args)
    _check_out_is_not_input(args)
    if args.command == "vpython":
        return _vpython(args)
    cfg = config.load(args.config)
    if hasattr(args, "dt"):
        cfg = config.override(cfg, "physics", integrator=args.integrator, dt=args.dt)
    with timeline.step_limit(args.max_steps):
        return _COMMANDS[args.command](cfg, args)


def _simulate(cfg: config.Config, args: argparse.Namespace) -> int:
    jobs.simulate(cfg, args.duration, args.out)
    print(f"wrote {args.out}")
    return 0


def _analyze(cfg: config.Config, args: argparse.Namespace) -> int:
    print(jobs.report(cfg, jobs.analyze(cfg, args.duration), as_json=args.json))
    return 0


def _sweep(cfg: config.Config, args: argparse.Namespace) -> int:
    result = jobs.sweep(cfg, parse_omega(args.omega), periods=args.periods, out=args.out)
    print(summary(result))
    if args.out is not None:
        print(f"wrote {args.out}")
    return 0


def _figures(cfg: config.Config, args: argparse.Namespace) -> int:
    for path in jobs.figures(cfg, args.out, backend=args.backend, antialias=not args.draft,
                             prefix=args.prefix):
        print(f"wrote {path}")
    return 0


def _still(cfg: config.Config, args: argparse.Namespace) -> int:
    jobs.still(cfg, args.time, args.out, backend=args.backend, antialias=not args.draft)
    print(f"wrote {args.out}")
    return 0


def _render(cfg: config.Config, args: argparse.Namespace) -> int:
    stats = jobs.render(cfg, args.out, duration=args.duration, fps=args.fps, speed=args.speed,
                        backend=args.backend, antialias=not args.draft,
                        overlays=parse_overlays(args.overlay), quality=args.quality,
                        on_warning=lambda m: print(f"springscene: warning: {m}", file=sys.stderr),
                        progress=not args.quiet and sys.stderr.isatty())
    if not args.quiet:
        print(f"wrote {stats.path}: {stats.frames} frames at {stats.fps} fps "
              f"in {stats.seconds:.1f} s ({stats.frames_per_second:.1f} frames/s)")
    return 0


_COMMANDS = {"simulate": _simulate, "analyze": _analyze, "sweep": _sweep, "figures": _figures,
             "still": _still, "render": _render}


def _dialect_said(args: argparse.Namespace, dialect) -> list[str]:
    """Which VPython the program was written for, and how it was read (a GlowScript
    program's RapydScript lines, the names given to a converted one), told before it runs
    so that they stand above its traceback if it raises; the notes told."""
    print(f"springscene: {args.program}: written for {dialect.name}", file=sys.stderr)
    for note in dialect.notes:
        print(f"springscene: note: {note}", file=sys.stderr)
    sys.stderr.flush()
    return list(dialect.notes)


def _vpython(args: argparse.Namespace) -> int:
    overlays = tuple(name.strip() for name in args.overlay.split(",") if name.strip())
    if args.overlay.strip() and not overlays:
        raise UserError(f"--overlay {args.overlay!r}: no overlay named (use graph)")
    traces = _traces(args)
    said: list[str] = []          # the notes on how the program was read, told before it ran
    try:
        with _trace_recording(args, traces) as record:
            result = jobs.vpython(args.program, args.out, duration=args.duration,
                                  frames=args.frames, fps=args.fps, backend=args.backend,
                                  antialias=not args.draft, overlays=overlays,
                                  page=not args.no_page, canvas_only=args.canvas_only,
                                  quality=args.quality, lod=args.lod, record=record,
                                  timeout=args.timeout, max_memory=args.max_memory,
                                  sandbox=Sandbox(own_folder(args.program))
                                  if args.sandbox else None,
                                  on_dialect=lambda d: said.extend(_dialect_said(args, d)))
            traced = read_recording(record or args.out) if traces else None
    except RunEnded as exc:         # os._exit, a signal, --timeout, --max-memory, sys.exit(n)
        print(one_line(str(exc)), file=sys.stderr)
        return exc.status
    if args.record is None:
        result.recording = None              # (--trace's own, removed)
    for note in result.notes:
        if note not in said:
            print(f"springscene: note: {note}", file=sys.stderr)
    if not args.quiet:
        print(f"wrote {result.path}: {result.frames} frame{'s' * (result.frames != 1)} "
              f"({result.program_seconds:.2f} s of program time, ended by "
              f"{result.ended}) in {result.seconds:.1f} s"
              + (f", peak memory {size_text(result.peak_memory)}" if result.peak_memory else ""))
        for path in ([result.page] if result.page else []) + result.images + (
                [result.recording] if result.recording else []):
            print(f"wrote {path}")
    for path in trace.write_traces(traced, traces) if traces else ():   # (a name it lacks: 2)
        if not args.quiet:
            print(f"wrote {path}")
    return 0


def _traces(args: argparse.Namespace) -> list[tuple[str, Path]]:
    """``--trace NAME``s checked before the run: each a name and its CSV beside ``--out``
    (``OUT-NAME.csv``), somewhere that can be written."""
    if args.trace:
        check_output(args.out, FORMATS)           # (--out's own error first)
    traces = {}
    for name in args.trace:
        name = trace.check_name(name)
        traces[name] = check_output(trace.trace_path(args.out, name), (".csv",), "--trace")
    return list(traces.items())


@contextlib.contextmanager
def _trace_recording(args: argparse.Namespace, traces: list):
    """The recording the run keeps: ``--record``'s, none for an ``--out`` that is the
    recording itself (``.jsonl``), or, for ``--trace`` alone, a file in a hidden folder beside
    ``--out`` (on its file system), removed after. The folder is named as the supervised
    run's own (``.OUT.PID.XXXXXXXX.run``), so one left by a springscene killed outright
    goes with theirs, at the next run to that output."""
    if not traces or args.record is not None or args.out.lower().endswith(".jsonl"):
        yield args.record
        return
    out = Path(args.out)
    folder = tempfile.mkdtemp(prefix=f"{hidden_name(out)}.{os.getpid()}.", suffix=".run",
                              dir=out.parent if str(out.parent) else ".")
    try:
        yield str(Path(folder) / "trace.jsonl")
    finally:
        shutil.rmtree(folder, ignore_errors=True)


def one_line(message: str) -> str:
    """``message`` on one line: a newline or other control character that came from the
    user's input (a TOML section name, a file name) is shown escaped, as Python writes it."""
    line = "".join(c if c.isprintable() else repr(c)[1:-1] for c in message)
    if len(line) > MAX_LINE:         # a name or value 100 kB long (an unknown key's name)
        line = f"{line[:MAX_LINE // 2]} ... ({len(line) - MAX_LINE:,} characters left out) " \
               f"... {line[-MAX_LINE // 2:]}"
    return line


def main(argv: list[str] | None = None) -> int:
    # a numerical blow-up is reported as one line (physics.step checks); numpy's overflow
    # warnings on the way there would only add lines
    warnings.filterwarnings("ignore", category=RuntimeWarning)
    args = _build_parser().parse_args(argv)
    try:
        return _run(args)
    except Exception as exc:
        stop = signals.interruption(exc)      # an error while a stop signal cleaned up
        if stop is None:
            return _failed(exc, args)
        return signals.report(stop)
    except KeyboardInterrupt as exc:      # or a stop signal (signals.Interrupted)
        return signals.report(exc)


def _failed(exc: Exception, args: argparse.Namespace) -> int:
    """``exc`` as one line (or the program's traceback) and its exit status."""
    try:
        raise exc
    except UserError as exc:
        print(f"springscene: error: {one_line(str(exc))}", file=sys.stderr)
        return EXIT_BAD_INPUT
    except ProgramError as exc:
        print(exc, file=sys.stderr)           # the program's own traceback
        return EXIT_PROGRAM_ERROR
    except OutputError as exc:       # a write that failed (no space, encoder): exit 1
        print(f"springscene: {one_line(str(exc))}", file=sys.stderr)
        return 1
    except BrokenPipeError:          # e.g. `springscene analyze ... | head`
        sys.stderr.close()
        return 0
    except OSError as exc:                # no space, a read-only folder: one line, exit 1
        print(f"springscene: {one_line(oserrors.line(exc, getattr(args, 'out', None)))}",
              file=sys.stderr)
        return oserrors.EXIT_WRITE_FAILED


if __name__ == "__main__":
    sys.exit(main())
