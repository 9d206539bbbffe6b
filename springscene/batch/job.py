"""One program of a batch: run as ``springscene vpython`` runs it, to its folder and its row.

Each program has a process of its own, forked from the batch's warm process
(:mod:`.warm`) or started fresh (:func:`start`), whose stdout and stderr are the
program's ``log.txt`` (what it printed, its traceback, the supervisor's diagnoses), so
that programs running side by side never mix their output and no program's crash, hang
or memory blow-up reaches another's files. That process (:func:`run`) runs the program
supervised (:func:`springscene.vpython.run.supervise.run_supervised`, with ``--timeout``
and ``--max-memory``) into the program's staging folder, makes the thumbnail from the
video's last frame, grades the recording when there are tests, and writes the row,
``result.json``, last. The same process runs, started fresh, on a Dask worker
(:mod:`.cluster`), there in a temporary folder.

A row says how the run ended (``status``): ``ran``; ``error`` (the program raised:
``detail`` is the error's first line, and the files up to it are there); ``exit``
(``sys.exit`` with a failure); ``timeout``; ``memory`` (over ``--max-memory``);
``crashed`` (killed by a signal); ``sandbox`` (the program raised at something the
sandbox kept from it: another's file, the home folder, the network; ``detail`` is its
error); ``refused`` (springscene would not run it: not a program it can read, no
sandbox); ``failed`` (a file could not be written).
"""

from __future__ import annotations

import ctypes
import json
import os
import re
import signal
import subprocess
import sys
import time
from pathlib import Path

from ..errors import OutputError, ProgramError, UserError
from ..outputs import atomic_path
from ..video import ffmpeg_exe
from ..vpython.run.options import RunOptions
from ..vpython.run.runner import ProgramExit, ProgramRaised, ProgramResult
from ..vpython.run.sandbox import Sandbox
from ..vpython.run.supervise import EXIT_TIMEOUT, RunEnded, run_supervised
from .grading import grade
from .plan import RESULT

LOG = "log.txt"
THUMBNAIL = "thumbnail.png"
THUMBNAIL_WIDTH = 320               # px: the index's cards
WHOLE = 250     # frames: x264's key frame interval; a seek in a shorter video decodes it all
_ROOT = str(Path(__file__).resolve().parents[2])      # where springscene is
# how a job's interpreter starts: not the working folder on the path (the program's folder
# is), and this springscene found last where no installation provides it
START = f"import sys; sys.path.pop(0); sys.path.append({_ROOT!r})"
_WHERE = re.compile(r"at ([-+.\deE]+) s of program time \((\d+) frame")
# what a supervisor's line says of how the run was stopped, the same wherever it ran (not
# the memory used when it was stopped, which varies)
_STOPPED = re.compile(r"(stopped by --timeout \S+ s|over --max-memory [^\s,]+|the program was "
                      r"killed by [^(]*?\S(?= \(| at| before)|the program exited with status \d+)")


_PATH = re.compile(r"'(/[^']*)'")          # the path an OSError's message names
_FILE_ERRORS = ("FileNotFoundError", "PermissionError", "OSError", "IsADirectoryError",
                "NotADirectoryError")
_NETWORK_ERRORS = ("ConnectionRefusedError", "gaierror")
_NETWORK_WORDS = ("Network is unreachable", "Temporary failure in name resolution")


def request(program: Path, folder: Path, stem: str, *, suffix: str, options: RunOptions,
            timeout: float | None, max_memory: str | None, sandbox: bool,
            readable: tuple[Path, ...], folder_of_its_own: bool, tests: Path | None,
            settings: dict) -> dict:
    """What :func:`main` is asked: the program, its staging ``folder`` and the run's
    options, as JSON-ready data; ``settings`` go into the row as they are (a rerun
    compares them). A program with a folder of its own (``folder_of_its_own``) runs in
    it (its data files found as in its author's folder), else in its staging folder."""
    return {"program": str(program), "folder": str(folder), "stem": stem, "suffix": suffix,
            "options": options.to_request(), "timeout": timeout, "max_memory": max_memory,
            "sandbox": sandbox, "readable": [str(p) for p in readable if p != program],
            "cwd": str(program.parent) if folder_of_its_own else None,
            "tests": None if tests is None else str(tests), "settings": settings}


def start(job: dict, env: dict | None = None) -> subprocess.Popen:
    """:func:`main` in a fresh interpreter, in a session of its own (a terminal's Ctrl-C
    reaches the batch, which ends it), writing ``log.txt`` in the staging folder; killed
    by the kernel if the thread that started it dies."""
    code = f"{START}; from springscene.batch.job import main; sys.exit(main())"
    with open(log_of(job), "wb") as log:
        return subprocess.Popen([sys.executable, "-c", code, json.dumps(job)],
                                cwd=working_folder(job),
                                stdin=subprocess.DEVNULL, stdout=log, stderr=subprocess.STDOUT,
                                start_new_session=True, env=env, preexec_fn=die_with_parent)


def log_of(job: dict) -> Path:
    """The job's ``log.txt``, in its staging folder (made here)."""
    folder = Path(job["folder"])
    folder.mkdir(parents=True, exist_ok=True)
    return folder / LOG


def working_folder(job: dict) -> Path:
    """Where the job's process (and its program) runs: the program's own folder when it has
    one of its own, else the staging folder."""
    return Path(job.get("cwd") or job["folder"])


def die_with_parent() -> None:
    """SIGTERM when the thread that started this process ends (PR_SET_PDEATHSIG)."""
    if sys.platform == "linux":
        ctypes.CDLL(None, use_errno=True).prctl(1, signal.SIGTERM, 0, 0, 0)


def stop(process: subprocess.Popen) -> None:
    """Ask a job's process to stop (it ends its program's process and removes its folder);
    the process alone if it has no session of its own yet (just forked)."""
    for kill in (os.killpg, os.kill):
        try:
            kill(process.pid, signal.SIGTERM)
            return
        except ProcessLookupError:
            continue
        except PermissionError:
            return


def main() -> int:
    """The job's process started fresh (:func:`start`): its request is its argument."""
    return run(json.loads(sys.argv[1]))


def run(job: dict) -> int:
    """The job's process: the program run, its thumbnail and grades, ``result.json``."""
    folder, start_time = Path(job["folder"]), time.monotonic()
    row = _run(job)
    row["wall_seconds"] = round(time.monotonic() - start_time, 3)
    row["settings"] = job["settings"]
    if row["status"] == "interrupted":
        return 130
    video = folder / f"{job['stem']}{job['suffix']}"
    if video.is_file():
        try:
            _thumbnail(video, folder / THUMBNAIL, row.get("frames") or 0)
        except (OSError, subprocess.SubprocessError) as exc:      # (the row says the rest)
            print(f"springscene: no thumbnail: {exc}", file=sys.stderr)
    if job["tests"] is not None:
        row.update(_graded(job, folder, row))
    row["files"] = {kind: name for kind, name in (
        ("video", video.name), ("page", f"{job['stem']}.html"),
        ("recording", f"{job['stem']}.jsonl.gz"), ("thumbnail", THUMBNAIL), ("log", LOG))
        if (folder / name).is_file()}
    sys.stdout.flush()
    with atomic_path(folder / RESULT) as tmp:
        tmp.write_text(json.dumps(row, indent=1, sort_keys=True) + "\n")
    return 0


def _graded(job: dict, folder: Path, row: dict) -> dict:
    """The tests run on the program's recording (up to its error, if it raised); with
    none, every test that asks for the run fails with how the run ended."""
    recording = folder / f"{job['stem']}.jsonl.gz"
    failure = None if recording.is_file() else f"the program's run: {row['status']}" + (
        f" ({row['detail']})" if row.get("detail") else "")
    grades = grade(recording if failure is None else None, Path(job["tests"]),
                   Path(job["program"]), failure=failure)
    if grades.error:
        print(f"springscene: grading: {grades.error}", file=sys.stderr)
    return {"score": grades.score, "max_score": grades.max_score, "grade_error": grades.error,
            "tests": [{"name": t.name, "passed": t.passed, "message": t.message,
                       "score": t.score, "max_score": t.max_score} for t in grades.tests]}


def _run(job: dict) -> dict:
    """The program run supervised, as a row (its status and what it reached)."""
    folder, program = Path(job["folder"]), Path(job["program"])
    options = RunOptions.from_request({**job["options"],
                                       "record": str(folder / f"{job['stem']}.jsonl.gz")})
    out = folder / f"{job['stem']}{job['suffix']}"
    sandbox = Sandbox(readable=tuple(job["readable"])) if job["sandbox"] else None
    try:
        result = run_supervised(program, out, options, timeout=job["timeout"],
                                max_memory=job["max_memory"], sandbox=sandbox,
                                say=lambda line: print(line, file=sys.stderr, flush=True))
    except ProgramRaised as exc:
        print(exc, file=sys.stderr)
        refused = sandbox is not None and refused_by_sandbox(exc.error)
        return {**_reached(exc.result), "status": "sandbox" if refused else "error",
                "detail": _error_line(exc.error)}
    except ProgramExit as exc:
        print(exc, file=sys.stderr)
        return {**_reached(None), "status": "exit", "detail": f"exited with status {exc.status}"}
    except ProgramError as exc:
        print(exc, file=sys.stderr)
        return {**_reached(None), "status": "error", "detail": _last_line(str(exc))}
    except RunEnded as exc:
        print(exc, file=sys.stderr)
        return _ended(exc, program)
    except UserError as exc:
        print(f"springscene: error: {exc}", file=sys.stderr)
        return {**_reached(None), "status": "refused", "detail": _local(str(exc), program)}
    except OutputError as exc:
        print(f"springscene: {exc}", file=sys.stderr)
        return {**_reached(None), "status": "failed", "detail": exc.reason}
    return {**_reached(result), "status": "ran", "detail": ""}


def _reached(result: ProgramResult | None) -> dict:
    """How far the run got: frames, program time, how it ended, its peak memory."""
    if result is None:
        return {"frames": 0, "program_seconds": None, "ended": None, "dialect": None,
                "peak_memory": None}
    return {"frames": result.frames, "program_seconds": round(result.program_seconds, 6),
            "ended": result.ended, "dialect": result.dialect, "peak_memory": result.peak_memory}


def _error_line(error: dict) -> str:
    """``ZeroDivisionError: division by zero (line 12)``: the error's first line."""
    message = (error.get("message") or "").strip().splitlines()
    text = f"{error.get('type', 'Error')}: {message[0]}" if message else error.get("type", "")
    return text + (f" (line {error['line']})" if error.get("line") else "")


def refused_by_sandbox(error: dict) -> bool:
    """Whether a sandboxed program's error is the sandbox's refusal: a file there is (or a
    folder, for a write) that the program could not read or write, or the network."""
    kind, message = error.get("type"), error.get("message") or ""
    if kind in _NETWORK_ERRORS or any(words in message for words in _NETWORK_WORDS):
        return True
    path = _PATH.search(message)
    if kind not in _FILE_ERRORS or path is None:
        return False
    if kind == "FileNotFoundError":
        return os.path.lexists(path[1])
    return os.path.lexists(path[1]) or os.path.isdir(os.path.dirname(path[1]))


def _last_line(text: str) -> str:
    """A traceback's last line (``SyntaxError: invalid syntax``), its program's folder
    left out."""
    lines = [line.strip() for line in text.strip().splitlines() if line.strip()]
    return lines[-1] if lines else "the program failed"


def _local(text: str, program: Path) -> str:
    """A line with the program's own folder left out (the same line wherever it ran)."""
    return text.replace(f"{program.parent}{os.sep}", "")


def _ended(exc: RunEnded, program: Path) -> dict:
    """A run the supervisor ended (``--timeout``, ``--max-memory``, a signal): its row."""
    line = str(exc)
    if exc.status in (128 + signal.SIGTERM, 128 + signal.SIGHUP, 128 + signal.SIGINT) \
            and "interrupted" in line:
        return {"status": "interrupted"}
    where = _WHERE.search(line)
    stopped = _STOPPED.search(line)
    status = ("timeout" if exc.status == EXIT_TIMEOUT else
              "memory" if "--max-memory" in line else
              "exit" if "exited with status" in line else
              "crashed" if "killed by" in line else "failed")
    return {"frames": int(where[2]) if where else 0,
            "program_seconds": float(where[1]) if where else None, "ended": None,
            "dialect": None, "peak_memory": None, "status": status,
            "detail": (f"stopped: {stopped[1]}" if status == "memory" else stopped[1])
            if stopped else _local(line.split(": ", 2)[-1], program)}


def _thumbnail(video: Path, out: Path, frames: int) -> None:
    """The video's last frame (its ``frames``-th), :data:`THUMBNAIL_WIDTH` px wide (less if
    it is smaller). A video of up to :data:`WHOLE` frames is decoded whole and that frame
    alone scaled and written; a longer one, or where the frame is not found so (a format
    that does not decode every frame it counts), from half a second before its end (from
    the last key frame before), or from the start where a format cannot seek so."""
    scale = f"scale='min({THUMBNAIL_WIDTH},iw)':-2"
    last = [["-threads", "1", "-i", str(video), "-vf", f"select='eq(n,{frames - 1})',{scale}",
             "-fps_mode", "passthrough", "-frames:v", "1"]] if 0 < frames <= WHOLE else []
    with atomic_path(out) as tmp:
        for how in (*last, ["-sseof", "-0.5", "-i", str(video), "-vf", scale],
                     ["-i", str(video), "-vf", scale]):
            subprocess.run([ffmpeg_exe(), "-hide_banner", "-nostdin", "-loglevel", "error",
                            *how, "-update", "1", "-y", str(tmp)], check=False,
                           stdin=subprocess.DEVNULL, timeout=120)
            if tmp.exists() and tmp.stat().st_size:
                return
        raise OutputError("no frame to make the thumbnail of", out)


if __name__ == "__main__":
    sys.exit(main())
