"""A batch's programs found and planned: which to run, where their files go, which are done.

``springscene batch`` takes files and folders. A file is one program. A folder holds one
submission per student, either way an instructor's download gives them:

- **a program per student**: each ``.py`` file directly in the folder is one program,
  named by its file name without ``.py`` (``alice.py`` is ``alice``); it may read only
  itself (:attr:`Program.readable`), never the other students' files beside it;
- **a folder per student**: each subfolder is one student, named by the subfolder; the
  program is its one ``.py`` file, or, where it has several, each of them that imports
  VPython (``vpython``, ``visual``) or starts with Web VPython's header (``alice/lab2``).
  A submission may read its own folder (a data file, a module of its own).

Deeper folders, files that are not ``.py`` and pytest's files (``test_*.py``,
``conftest.py``: the instructor's tests beside the programs) are left alone. Each program's files go
into a folder of the output named as the program (``DIR/alice/``, ``DIR/alice/lab2/``):
its video ``NAME.EXT``, interactive page ``NAME.html``, recording ``NAME.jsonl.gz``,
``thumbnail.png``, ``log.txt`` and ``result.json``, the row of the summary. A rerun
skips a program whose ``result.json`` is newer than the program (its folder's files,
for a folder per student) and the tests, and was made with the same options.
"""

from __future__ import annotations

import json
import os
import re
from dataclasses import dataclass, field
from pathlib import Path

from ..errors import UserError

RESULT = "result.json"        # a program's row, written last: the program is done
_VPYTHON = re.compile(r"^\s*(from|import)\s+(vpython|visual)\b|^\s*(Web VPython|GlowScript) ",
                      re.MULTILINE)
_NAME = re.compile(r"[^\w.+-]+")
_TAKEN = ("index.html", "summary.csv", "summary.json")     # the batch's own files in DIR


@dataclass(frozen=True)
class Program:
    """One submission: ``key`` names it and its folder in the output (``alice``,
    ``alice/lab2``); ``path`` is the program; ``readable``, what it may read besides
    (the program itself, or its student's folder); ``folder``: whether the student has
    a folder of their own."""

    key: str
    path: Path
    readable: tuple[Path, ...] = field(default=())
    folder: bool = False

    @property
    def stem(self) -> str:
        """The name of the program's files: its video ``STEM.mp4``, page ``STEM.html``."""
        return self.key.rsplit("/", 1)[-1]


def find_programs(paths: list[str]) -> list[Program]:
    """The programs of the files and folders ``paths``, in order of their names; bad
    input (a missing path, a folder with no program, two programs of one name) is one
    :class:`UserError`."""
    if not paths:
        raise UserError("batch: give the programs (files or folders of them)")
    programs: list[Program] = []
    for text in paths:
        path = Path(text)
        if path.is_file():
            _check_program_file(path)
            programs.append(_one_file(path))
        elif path.is_dir():
            found = _in_folder(path)
            if not found:
                raise UserError(f"{path}: no VPython program in this folder (.py files, or "
                                "one folder per student holding them)")
            programs.extend(found)
        else:
            raise UserError(f"{path}: no such file or folder")
    _check_unique(programs)
    return sorted(programs, key=lambda p: p.key)


def _check_program_file(path: Path) -> None:
    if path.suffix.lower() != ".py":
        raise UserError(f"{path}: not a Python program (.py)")
    if not os.access(path, os.R_OK):
        raise UserError(f"{path}: cannot read it")


def _one_file(path: Path) -> Program:
    return Program(_key_part(path.stem), path, (path,))


def _in_folder(folder: Path) -> list[Program]:
    """A folder's programs: its ``.py`` files, then one student a subfolder."""
    try:
        entries = sorted(folder.iterdir())
    except OSError as exc:
        raise UserError(f"{folder}: cannot read this folder ({exc.strerror})") from None
    programs = [_one_file(p) for p in entries if _program_file(p)]
    for sub in (p for p in entries if p.is_dir() and not p.name.startswith((".", "__"))):
        programs.extend(_student(sub))
    return programs


def _student(folder: Path) -> list[Program]:
    """A student's folder: its one program, or each of its VPython programs."""
    try:
        files = sorted(p for p in folder.iterdir() if _program_file(p))
    except OSError:
        return []
    if len(files) > 1:
        files = [p for p in files if _looks_like_vpython(p)]
    student = _key_part(folder.name)
    if len(files) == 1:
        return [Program(student, files[0], (folder,), folder=True)]
    return [Program(f"{student}/{_key_part(p.stem)}", p, (folder,), folder=True) for p in files]


def _program_file(path: Path) -> bool:
    """A ``.py`` file that is not pytest's (``test_*.py``, ``conftest.py``: an
    instructor's tests kept beside the programs)."""
    return path.suffix.lower() == ".py" and path.is_file() and \
        not path.name.startswith("test_") and path.name != "conftest.py"


def _looks_like_vpython(path: Path) -> bool:
    try:
        return bool(_VPYTHON.search(path.read_text(errors="replace")))
    except OSError:
        return False


def _key_part(name: str) -> str:
    """A name as a folder of the output: what a file name may hold, never ``..``."""
    part = _NAME.sub("_", name).strip(".") or "program"
    return f"_{part}" if part.lower() in _TAKEN else part


def _check_unique(programs: list[Program]) -> None:
    seen: dict[str, Path] = {}
    for program in programs:
        other = seen.setdefault(program.key, program.path)
        if other != program.path:
            raise UserError(f"{other} and {program.path}: two programs named "
                            f"{program.key!r} (give them in separate batches)")
        if any(key.startswith(program.key + "/") or program.key.startswith(key + "/")
               for key in seen if key != program.key):
            raise UserError(f"{program.path}: its name {program.key!r} clashes with a "
                            "student's folder of programs (give them in separate batches)")


def newest_input(program: Program, tests: Path | None = None) -> float:
    """When the program's inputs last changed: the program, its student's folder's files,
    and the tests."""
    times = [program.path.stat().st_mtime]
    if program.folder:
        times += [p.stat().st_mtime for p in program.path.parent.rglob("*") if p.is_file()]
    if tests is not None:
        times.append(tests.stat().st_mtime)
    return max(times)


def finished_row(program: Program, out_dir: Path, settings: dict,
                 tests: Path | None = None) -> dict | None:
    """The program's row from an earlier run, if that run is newer than its inputs and
    was asked the same (``settings``); else None (the program is to be run)."""
    result = out_dir / program.key / RESULT
    try:
        if result.stat().st_mtime <= newest_input(program, tests):
            return None
        row = json.loads(result.read_text())
    except (OSError, ValueError):
        return None
    if not isinstance(row, dict) or row.get("settings") != settings:
        return None
    return row
