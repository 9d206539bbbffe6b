"""The batch's warm process: each program's job process forked from it, not started fresh.

Starting a job process, and its program's child importing VTK, pyvista and matplotlib,
would cost every program the same processor time again. Instead the batch starts one
warm process (:func:`serve`, a fresh interpreter with the jobs' environment) which does
all of that once, loads matplotlib's fonts, and then forks a job process for each
program it is sent. That job process is what :func:`.job.start` would have started: its
own session, ``log.txt`` as its output, the program's folder as its working folder, the
jobs' environment as the batch gave it, ``SIGTERM`` when the warm process dies (which
dies with the batch); it runs :func:`.job.run`, and forks its program's child from itself
when the program runs unsandboxed (:mod:`springscene.vpython.run.forked` says what makes
that child a fresh one). A sandboxed program's child is a fresh interpreter inside
bubblewrap, as always.

The warm process never draws, so no GL state is ever forked, and it keeps one thread:
OpenBLAS, which starts its threads as it loads, is asked for one (``OPENBLAS_NUM_THREADS``,
restored in the job processes, whose numpy keeps that one thread). Were it to have a
second thread anyway, it says so and ends, and the batch starts every job fresh
(:meth:`Warm.start` is None), as it does if the warm process cannot start or dies.

Between the batch and the warm process: one JSON request a line on its stdin (a job's
request, :func:`.job.request`), one JSON line a reply on its stdout: ``{"ready": true}``
once it is warm; ``{"job": K, "pid": N}`` (or ``{"error": ...}``) for the K-th request,
in their order; ``{"job": K, "ended": S}`` when that job's process has ended (S as
``Popen.returncode``). At the end of its stdin it waits for its job processes and ends.
"""

from __future__ import annotations

import contextlib
import gc
import json
import os
import queue
import select
import signal
import subprocess
import sys
import tempfile
import threading
import time
import traceback

from ..view.plotstyle import agg_figure
from ..vpython.run import child  # noqa: F401  (what a program's child imports of springscene)
from ..vpython.run import forked, lineage
from ..vpython.run.sandbox import unavailable
from . import job

# (the environment kept as it was before any import, to be the job processes')
SERVE = (f"{job.START}; import os; environment = dict(os.environ); "
         "from springscene.batch.warm import serve; serve(environment)")
# what the warm process sets for itself: one BLAS thread (see above)
_OWN = {"OPENBLAS_NUM_THREADS": "1"}
WAIT_GONE = 0.05          # s between looks at a job process whose warm process died
WARM_UP = 300.0           # s the warm process may take to import (a loaded machine)
REPLY = 60.0              # s it may take to fork a job process
CLOSE = 30.0              # s its job processes may take to end once it is closed or dead


def serve(environment: dict) -> None:
    """The warm process (started by :class:`Warm`, with :data:`_OWN` in its environment
    ``environment`` and, as its argument, those variables as the batch gave them)."""
    given = json.loads(sys.argv[1])
    environment = {name: value for name, value in {**environment, **given}.items()
                   if value is not None}
    _warm_up()
    if forked.threads() != 1:
        print(f"springscene: the warm process has {forked.threads()} threads; "
              "jobs start fresh", file=sys.stderr)
        sys.exit(1)
    forked.make_warm()
    gc.freeze()                 # (what is imported stays shared with the forks)
    _Server(environment).loop()


def _warm_up() -> None:
    """What every job and run imports (the program's child imports VTK, pyvista and
    matplotlib as it first draws or graphs), matplotlib's fonts, loaded as it first draws
    text, and whether a sandbox can be made here."""
    import matplotlib.backends.backend_agg  # noqa: F401, PLC0415  heavy: warming up
    import matplotlib.transforms  # noqa: F401, PLC0415  heavy: warming up
    import PIL.Image  # noqa: F401, PLC0415  heavy: warming up
    import pyvista.core  # noqa: F401, PLC0415  heavy: warming up
    import vtkmodules.util.numpy_support  # noqa: F401, PLC0415  heavy: warming up
    import vtkmodules.vtkFiltersGeometry  # noqa: F401, PLC0415  heavy: warming up
    import vtkmodules.vtkRenderingAnnotation  # noqa: F401, PLC0415  heavy: warming up
    import vtkmodules.vtkRenderingFreeType  # noqa: F401, PLC0415  heavy: warming up
    import vtkmodules.vtkRenderingOpenGL2  # noqa: F401, PLC0415  heavy: warming up

    unavailable()               # (the sandbox's trial run, its answer kept by the forks)

    figure = agg_figure(160, 120)
    axes = figure.add_subplot()
    axes.plot([0, 1], [0, 1], label="x")
    axes.set_xlabel("t (s)")
    axes.legend()
    figure.canvas.draw()


class _Server:
    """The warm process's loop: requests in, job processes forked, their ends reported."""

    def __init__(self, environment: dict) -> None:
        self.environment = environment         # the jobs' environment, as the batch gave it
        self.children: dict[int, int] = {}     # pid: the job's number
        self.count, self.buffer = 0, b""
        self.wake, self.wake_write = os.pipe()
        os.set_blocking(self.wake, False)
        os.set_blocking(self.wake_write, False)
        signal.signal(signal.SIGCHLD, lambda signum, frame: None)
        signal.set_wakeup_fd(self.wake_write, warn_on_full_buffer=False)

    def say(self, message: dict) -> None:
        os.write(1, (json.dumps(message) + "\n").encode())

    def loop(self) -> None:
        self.say({"ready": True})
        reading = True
        while reading or self.children:
            ready = select.select([0, self.wake] if reading else [self.wake], [], [])[0]
            if 0 in ready:
                reading = self.requests()
            if self.wake in ready:
                with contextlib.suppress(BlockingIOError):
                    while os.read(self.wake, 512):
                        pass
            self.reap()

    def requests(self) -> bool:
        """The requests read now, each one's job process forked; False at their end."""
        data = os.read(0, 1 << 16)
        *lines, self.buffer = (self.buffer + data).split(b"\n")
        for line in lines:
            self.fork(json.loads(line))
        return bool(data)

    def fork(self, request: dict) -> None:
        self.count += 1
        try:
            pid = os.fork()
        except OSError as exc:
            self.say({"job": self.count, "error": str(exc)})
            return
        if pid == 0:
            self.become_job(request)
        self.children[pid] = self.count
        self.say({"job": self.count, "pid": pid})

    def reap(self) -> None:
        while self.children:
            try:
                pid, wait = os.waitpid(-1, os.WNOHANG)
            except ChildProcessError:
                return
            if not pid:
                return
            number = self.children.pop(pid, None)
            if number is not None:
                self.say({"job": number, "ended": os.waitstatus_to_exitcode(wait)})

    def become_job(self, request: dict) -> None:
        """In the forked process: the job process :func:`.job.start` would start."""
        code = 1
        try:
            parent = os.getppid()
            signal.set_wakeup_fd(-1)
            signal.signal(signal.SIGCHLD, signal.SIG_DFL)
            for fd in (self.wake, self.wake_write):
                os.close(fd)
            os.setsid()
            job.die_with_parent()
            if os.getppid() != parent:              # the warm process died just now
                os._exit(1)
            _streams(job.log_of(request))
            os.environ.clear()
            os.environ.update(self.environment)
            os.chdir(job.working_folder(request))
            code = job.run(request)
        except SystemExit as exc:
            code = forked.exit_status(exc)
        except BaseException:
            traceback.print_exc()
        finally:
            forked.end(code)


def _streams(log) -> None:
    """Standard input from ``/dev/null``, standard output and error into ``log``."""
    null = os.open(os.devnull, os.O_RDONLY)
    os.dup2(null, 0)
    os.close(null)
    out = os.open(log, os.O_WRONLY | os.O_CREAT | os.O_TRUNC, 0o644)
    os.dup2(out, 1)
    os.dup2(out, 2)
    os.close(out)


class Warm:
    """The batch's side of its warm process (started here, with the jobs' environment
    ``env``); :meth:`close` ends it once its job processes have ended."""

    def __init__(self, env: dict | None) -> None:
        self.asking = threading.Lock()           # one request and its reply at a time
        self.lock = threading.Lock()             # what the reader thread writes
        self.replies: queue.Queue = queue.Queue()
        self.ended: dict[int, int] = {}          # a job's number: its exit status
        self.waiting: dict[int, threading.Event] = {}
        self.count, self.dead = 0, False
        self.errors = tempfile.TemporaryFile()
        env = dict(os.environ if env is None else env)
        given = {name: env.get(name) for name in _OWN}
        self.process = subprocess.Popen(
            [sys.executable, "-c", SERVE, json.dumps(given)], stdin=subprocess.PIPE,
            stdout=subprocess.PIPE, stderr=self.errors, env={**env, **_OWN},
            start_new_session=True, preexec_fn=job.die_with_parent)
        try:
            threading.Thread(target=self._read, name="springscene-batch-warm",
                             daemon=True).start()
            self.ready = self._reply(WARM_UP) is not None
        except BaseException:                     # (Ctrl-C while it warms up)
            self.process.kill()
            self.close()
            raise
        if not self.ready:
            self.process.kill()

    def start(self, request: dict) -> "WarmJob | None":
        """The job's process forked in the warm process; None when it cannot be (the
        caller starts it fresh)."""
        with self.asking:
            if self.dead or not self.ready:
                return None
            try:
                self.process.stdin.write((json.dumps(request) + "\n").encode())
                self.process.stdin.flush()
            except OSError:
                return None
            self.count += 1
            reply = self._reply(REPLY)
        if reply is None or "pid" not in reply or reply.get("job") != self.count:
            return None
        return WarmJob(self, self.count, reply["pid"])

    def wait(self, number: int, pid: int) -> int:
        """The exit status of job ``number`` (process ``pid``), once it has ended."""
        with self.lock:
            event = self.waiting.setdefault(number, threading.Event())
            if self.dead:
                event.set()
        event.wait()
        with self.lock:
            status = self.ended.pop(number, None)
            self.waiting.pop(number, None)
        if status is None:                        # the warm process died before it
            _wait_gone(pid)
            return 1
        return status

    def failure(self) -> str | None:
        """Why the warm process could not serve (its last line), or None."""
        if self.ready and not self.dead:
            return None
        self.errors.seek(0)
        lines = self.errors.read().decode(errors="replace").strip().splitlines()
        return lines[-1] if lines else f"ended with status {self.process.poll()}"

    def close(self) -> None:
        with contextlib.suppress(OSError):
            self.process.stdin.close()
        try:
            self.process.wait(timeout=CLOSE)
        except subprocess.TimeoutExpired:
            self.process.kill()
            self.process.wait()
        self.errors.close()

    def _reply(self, timeout: float) -> dict | None:
        """The warm process's next reply; None if it is dead or has said nothing for
        ``timeout`` s (then it serves no more: its running jobs go on)."""
        try:
            reply = self.replies.get(timeout=timeout)
        except queue.Empty:
            reply = None
        if reply is None:
            self.dead = True
        return reply

    def _read(self) -> None:
        try:
            for line in self.process.stdout:
                with contextlib.suppress(ValueError):
                    self._heard(json.loads(line))
        finally:
            with self.lock:
                self.dead = True
                for event in self.waiting.values():
                    event.set()
            self.replies.put(None)

    def _heard(self, message) -> None:
        if not isinstance(message, dict):         # (not a reply: nothing else writes there)
            return
        if "ended" in message:
            with self.lock:
                self.ended[message["job"]] = message["ended"]
                self.waiting.setdefault(message["job"], threading.Event()).set()
        else:
            self.replies.put(message)


class WarmJob:
    """A job process forked in the warm process, as much of a ``Popen`` as a batch uses."""

    def __init__(self, warm: Warm, number: int, pid: int) -> None:
        self.warm, self.number, self.pid, self.returncode = warm, number, pid, None

    def wait(self) -> int:
        if self.returncode is None:
            self.returncode = self.warm.wait(self.number, self.pid)
        return self.returncode


def _wait_gone(pid: int) -> None:
    """Until process ``pid`` (a job whose warm process died, which the kernel has asked
    to end) has ended, for at most :data:`CLOSE` s."""
    deadline = time.monotonic() + CLOSE
    while not lineage.gone(pid, pid) and time.monotonic() < deadline:
        time.sleep(WAIT_GONE)
