"""VPython in any notebook: ``%load_ext springscene`` and the ``%%vpython`` cell magic.

A ``%%vpython`` cell is a VPython program (VPython 7, VPython 6 or Web VPython; a cell
that imports nothing and has no GlowScript header gets VPython 7's names, as
``from vpython import *`` gives). It runs headless, supervised in a child process as
``springscene vpython`` runs it, and the cell shows the interactive page (GlowScript
drawing the run, with its player), or with ``--video`` the video. Nothing needs a
browser-side extension, so it works where VPython itself hangs (Colab, a notebook
without VPython's Jupyter extension)::

    %load_ext springscene

    %%vpython --duration 5
    ball = sphere(color=color.red)
    while True:
        rate(50)
        ball.pos.x += 0.01

The cell's program and outputs live in a folder of the kernel's, removed when the kernel
ends; ``--out FILE`` keeps the video (or page) where you ask.
"""

from __future__ import annotations

import argparse
import atexit
import itertools
import re
import shlex
import shutil
import sys
import tempfile
from pathlib import Path

from . import api
from .errors import ProgramError, UserError
from .vpython.run.supervise import RunEnded

__all__ = ["load_ipython_extension", "vpython_cell", "cell_program"]

_FOLDER: Path | None = None
_COUNT = itertools.count(1)
_IMPORTS = re.compile(r"^\s*(from\s+(vpython|visual)\b|import\s+(vpython|visual)\b)", re.M)
_HEADER = re.compile(r"^\s*(GlowScript|Web\s*VPython)\s", re.I)


def _folder() -> Path:
    """The kernel's folder for cell programs and their outputs (removed at its exit)."""
    global _FOLDER
    if _FOLDER is None:
        _FOLDER = Path(tempfile.mkdtemp(prefix="springscene-cells-"))
        atexit.register(shutil.rmtree, _FOLDER, True)
    return _FOLDER


def cell_program(source: str) -> str:
    """The cell as a program: as it is when it names its VPython (an import or a
    GlowScript header), else with ``from vpython import *`` first (line numbers in its
    tracebacks are then one more than the cell's)."""
    first = next((line for line in source.splitlines() if line.strip()), "")
    if _HEADER.match(first) or _IMPORTS.search(source):
        return source
    return "from vpython import *\n" + source


class _Parser(argparse.ArgumentParser):
    """The magic's flags; a bad one is one line (IPython's UsageError), no traceback."""

    def error(self, message: str):
        raise UserError(f"%%vpython: {message}")


def _parser() -> argparse.ArgumentParser:
    p = _Parser(prog="%%vpython", add_help=False)
    length = p.add_mutually_exclusive_group()
    length.add_argument("--duration", type=float)
    length.add_argument("--frames", type=int)
    p.add_argument("--fps", type=int, default=25)
    p.add_argument("--video", action="store_true")
    p.add_argument("--draft", action="store_true")
    p.add_argument("--out")
    p.add_argument("--timeout", type=float)
    p.add_argument("--max-memory")
    return p


def vpython_cell(line: str, cell: str):
    """Run a cell's VPython program; what the cell shows (a ``Run``, or a ``Video``)."""
    try:
        args = _parser().parse_args(shlex.split(line))
    except ValueError as exc:          # shlex: an unclosed quote
        raise UserError(f"%%vpython: {exc}") from None
    n = next(_COUNT)
    folder = _folder()
    program = folder / f"cell{n}.py"
    program.write_text(cell_program(cell), encoding="utf-8")
    options = {"duration": args.duration, "frames": args.frames, "fps": args.fps,
               "draft": args.draft, "timeout": args.timeout, "max_memory": args.max_memory}
    if args.video or (args.out and not args.out.endswith((".html", ".jsonl"))):
        out = args.out or folder / f"cell{n}.mp4"
        return api.run_vpython(program, out, page=False, **options)   # no page: shown as video
    return api.run_vpython(program, args.out, **options)


def load_ipython_extension(ipython) -> None:
    """``%load_ext springscene``: the ``%%vpython`` cell magic."""
    from IPython.core.error import UsageError  # noqa: PLC0415  heavy: IPython, in a notebook only

    def magic(line: str, cell: str):
        try:
            return vpython_cell(line, cell)
        except UserError as exc:
            raise UsageError(str(exc)) from None
        except (ProgramError, RunEnded) as exc:   # the program's own traceback, as a run's
            print(str(exc), file=sys.stderr)
            return None

    magic.__doc__ = __doc__
    ipython.register_magic_function(magic, magic_kind="cell", magic_name="vpython")
