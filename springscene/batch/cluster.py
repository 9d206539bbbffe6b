"""A batch's programs run on a Dask distributed cluster (``--scheduler ADDRESS``).

A worker may be another machine, without this one's files: each program goes to it as
bytes (the program, and its student's folder when it has one; the tests), and
:func:`run_remote` runs there the same job as a local run (:func:`.job.start`, sandboxed
as asked) in a temporary folder, sending back the bytes of every file it wrote. Here they
are written into the program's staging folder and handed on as a local run's are, so
``DIR`` holds the same files, whichever ran them. Workers need springscene installed
(``pip install springscene[dask]``) and, for the sandbox, bubblewrap; a worker thread
runs one program at a time (``--nthreads`` programs at once per worker).

Ctrl-C cancels the programs not started; those running on the workers run to their end
there, their results dropped.
"""

from __future__ import annotations

import shutil
import tempfile
from pathlib import Path
from typing import Callable

from ..errors import UserError
from ..vpython.run.sandbox import unavailable
from . import job

MAX_INPUT = 200 << 20          # bytes of a student's folder sent with their program


def _files(item) -> dict[str, bytes]:
    """What the worker needs of a program: its readable files, named as below their
    student's folder (or the program alone)."""
    program = item.program
    if not program.folder:
        return {program.path.name: program.path.read_bytes()}
    root = program.path.parent
    files, size = {}, 0
    for path in sorted(p for p in root.rglob("*") if p.is_file()):
        size += path.stat().st_size
        if size > MAX_INPUT:
            raise UserError(f"{root}: more than {MAX_INPUT >> 20} MB to send to the cluster")
        files[path.relative_to(root).as_posix()] = path.read_bytes()
    return files


def payload(item, tests: Path | None) -> dict:
    """The program's job as data for a worker."""
    program = item.program
    return {"files": _files(item), "program": program.path.name, "folder": program.folder,
            "request": item.request,
            "tests": None if tests is None else (tests.name, tests.read_bytes())}


def run_remote(data: dict) -> dict:
    """On a worker: the job run in a temporary folder; the files it wrote as bytes (named
    inside the program's folder) and its process's exit status."""
    with tempfile.TemporaryDirectory(prefix="springscene-batch-") as tmp:
        inputs, out = Path(tmp) / "in", Path(tmp) / "out"
        for name, content in data["files"].items():
            path = inputs / name
            path.parent.mkdir(parents=True, exist_ok=True)
            path.write_bytes(content)
        request = {**data["request"], "program": str(inputs / data["program"]),
                   "folder": str(out), "readable": [str(inputs)] if data["folder"] else [],
                   "cwd": str(inputs) if data["folder"] else None}
        if data["tests"] is not None:
            tests = Path(tmp) / "tests" / data["tests"][0]
            tests.parent.mkdir()
            tests.write_bytes(data["tests"][1])
            request["tests"] = str(tests)
        status = job.start(request).wait()
        written = {p.relative_to(out).as_posix(): p.read_bytes() for p in sorted(out.rglob("*"))
                   if p.is_file() and not any(part.startswith(".")
                                              for part in p.relative_to(out).parts)}
    return {"status": status, "files": written}


def _receive(item, result: dict) -> None:
    """A worker's files into the program's staging folder, as a local run leaves them."""
    shutil.rmtree(item.staging, ignore_errors=True)
    item.staging.mkdir(parents=True)
    for name, content in result["files"].items():
        path = item.staging / name
        path.parent.mkdir(parents=True, exist_ok=True)
        path.write_bytes(content)


def connect(address: str):
    """A client of the Dask cluster at ``address`` (bad input if there is none)."""
    try:
        from distributed import Client  # noqa: PLC0415  heavy: distributed (springscene[dask])
    except ImportError:
        raise UserError("--scheduler: Dask's distributed is not installed (pip install "
                        "'springscene[dask]')") from None
    try:
        return Client(address, timeout="10s")
    except (OSError, TimeoutError, ValueError) as exc:
        raise UserError(f"--scheduler {address}: cannot reach it ({exc})") from None


def sandbox_missing(client) -> str | None:
    """Why some worker of ``client``'s cluster cannot make a sandbox (naming it), or None."""
    for worker, why in sorted(client.run(unavailable).items()):
        if why is not None:
            return f"{worker}: {why}"
    return None


def run_cluster(client, items: list, done: Callable, tests: Path | None = None) -> None:
    """Run each item's job on the cluster of ``client``; ``done(item, status)`` as each
    comes back."""
    from distributed import as_completed  # noqa: PLC0415  heavy: distributed (springscene[dask])
    futures = {client.submit(run_remote, payload(item, tests), pure=False,
                             key=f"springscene-batch-{item.program.key}-{id(item)}"): item
               for item in items}
    try:
        for future in as_completed(futures):
            item = futures[future]
            try:
                result = future.result()
            except Exception as exc:            # the worker lost, the task failed
                result = {"status": -1, "files": {job.LOG: f"{exc!r}\n".encode()}}
            _receive(item, result)
            done(item, result["status"])
    except BaseException:
        client.cancel(list(futures))
        for item in futures.values():
            item.discard()
        raise
