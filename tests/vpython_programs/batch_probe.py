from vpython import *
# What a program finds as it starts, printed as one line of JSON (tests/batch/test_warm.py):
# its process group, open files, signal handlers, environment, path and random state.
import json
import os
import random
import signal
import sys
import threading

import numpy


def kind(fd):
    try:
        target = os.readlink(f"/proc/self/fd/{fd}")
    except OSError:
        return None
    return "null" if target == os.devnull else target.split(":")[0] if ":[" in target else "file"


facts = {
    "own_group": os.getpgid(0) == os.getpid(),
    "descriptors": sorted(filter(None, (kind(fd) for fd in os.listdir("/proc/self/fd")))),
    "handlers": {s.name: str(signal.getsignal(s)) for s in
                 (signal.SIGINT, signal.SIGHUP, signal.SIGCHLD, signal.SIGUSR1, signal.SIGPIPE)},
    "blocked": sorted(signal.pthread_sigmask(signal.SIG_BLOCK, [])),
    "openblas": os.environ.get("OPENBLAS_NUM_THREADS"),
    "path": sys.path[1:], "argv": sys.argv, "name": __name__, "cwd": os.getcwd(),
    "threads": threading.active_count(),
    "numpy": numpy.random.random(), "random": random.random(),
    "started_as": open("/proc/self/cmdline", "rb").read().split(b"\0")[2].decode(),
    "parent_started_as": open(f"/proc/{os.getppid()}/cmdline", "rb").read().split(b"\0")[2]
    .decode(),
    "environment": dict(os.environ),
    "memory": [line.split()[1] for line in open("/proc/self/status")
               if line.startswith(("VmRSS:", "RssAnon:", "RssFile:"))],
}
print("PROBE " + json.dumps(facts))
ball = sphere(pos=vector(-1, 0, 0), radius=0.3, color=color.orange)
for step in range(100):
    rate(50)
    ball.pos.x = -1 + 0.01 * step
