"""A batch's programs run on this machine, ``jobs`` at a time.

Each program is a process of its own, forked by the batch's warm process (:mod:`.warm`),
or started fresh (:func:`.job.start`) where that cannot be; a thread here starts one,
waits for it and hands it on (``done``), then takes the next. The processes do the
work, so the threads only wait. A stop (Ctrl-C, SIGTERM: raised in the main thread)
stops the waiting: no program starts after it, each running one is asked to stop (its
process ends its program's and removes its files) and is left out, and what finished
before stays. An error in ``done`` (the index could not be written) stops the batch the
same way and is raised here.
"""

from __future__ import annotations

import os
import subprocess
import sys
import threading
from typing import Callable, Iterable

from . import job
from .warm import Warm

POLL = 0.1        # s: how often the main thread looks up from waiting (a stop comes then)


class _Pool:
    """The programs still to run, the processes running, and whether to stop."""

    def __init__(self, items: Iterable, start: Callable) -> None:
        self.items, self.start = iter(items), start
        self.lock = threading.Lock()
        self.running: set[subprocess.Popen] = set()
        self.stopped = threading.Event()
        self.finished = threading.Event()       # every worker has returned
        self.workers = 0
        self.errors: list[BaseException] = []

    def next(self):
        with self.lock:
            return None if self.stopped.is_set() else next(self.items, None)

    def stop_all(self) -> None:
        self.stopped.set()
        with self.lock:
            for process in self.running:
                job.stop(process)

    def work(self, done: Callable) -> None:
        """Run programs until none is left or the batch stops."""
        try:
            self._work(done)
        finally:
            with self.lock:
                self.workers -= 1
                if not self.workers:
                    self.finished.set()

    def _work(self, done: Callable) -> None:
        while (item := self.next()) is not None:
            process = self.start(item.request)
            with self.lock:
                self.running.add(process)
                if self.stopped.is_set():       # (a stop while it started)
                    job.stop(process)
            process.wait()
            with self.lock:
                self.running.discard(process)
            if self.stopped.is_set():
                item.discard()
                return
            try:
                done(item, process.returncode)
            except BaseException as exc:      # (raised in the main thread)
                self.errors.append(exc)
                self.stop_all()


def run_local(items: list, jobs: int, done: Callable, env: dict | None = None,
              warm: bool = True) -> None:
    """Run each item's job (``item.request``), ``jobs`` at a time, in a warm process's
    forks (unless ``warm`` is False) with the environment ``env``; ``done(item,
    status)`` once each has ended, in the thread that waited for it; ``item.discard()``
    for one stopped part way."""
    if not items:
        return
    server = None
    try:
        if warm and hasattr(os, "fork"):
            server = Warm(env)
            if server.failure() is not None:
                print(f"springscene: batch: no warm process ({server.failure()}); "
                      "each program starts fresh", file=sys.stderr)
        _run(items, jobs, done, lambda request: (server and server.start(request))
             or job.start(request, env))
    finally:
        if server is not None:
            server.close()


def _run(items: list, jobs: int, done: Callable, start: Callable) -> None:
    pool = _Pool(items, start)
    pool.workers = max(1, min(jobs, len(items)))
    for n in range(pool.workers):
        threading.Thread(target=pool.work, args=(done,), daemon=True,
                         name=f"springscene-batch-{n}").start()
    # waited for on an event, never by Thread.join: a KeyboardInterrupt in join can leave
    # a running thread taken for ended (Python before 3.13)
    try:
        while not pool.finished.wait(POLL):
            pass
    except BaseException:
        pool.stop_all()
        while not pool.finished.wait(POLL):
            pass
        raise
    if pool.errors:
        raise pool.errors[0]
