"""What the supervisor of a run (:mod:`.supervise`) measures and says: the child's memory
(``/proc/PID/status``; in a sandbox, the sandboxed interpreter's and its children's),
``--max-memory`` sizes, why no frame comes, and how a run ended.

Sizes are binary, written as the flag takes them: ``500M`` is 500 × 2^20 bytes.
"""

from __future__ import annotations

import math
import re
import signal
import time
from pathlib import Path

from ...errors import UserError
from . import lineage

DEFAULT_SHARE = 0.5          # of the machine's (or the container's) memory, by default
MIN_MEMORY = 100 << 20       # a run needs about 200M for Python, numpy and VTK anyway
_UNITS = {"": 1, "K": 1 << 10, "M": 1 << 20, "G": 1 << 30, "T": 1 << 40}
_SIZE = re.compile(r"\s*(\d+(?:\.\d*)?|\.\d+)\s*([KMGT]?)(?:I?B)?\s*", re.IGNORECASE)


def parse_size(text: str) -> int:
    """``"2G"``, ``"500M"``, ``"1.5g"``, ``"300MiB"``, ``"4096"`` (bytes) → bytes."""
    match = _SIZE.fullmatch(str(text))
    if match is None:
        raise ValueError(f"not a size: {text!r}")
    return int(float(match[1]) * _UNITS[match[2].upper()])


def size_text(n: float) -> str:
    """Bytes as the flag writes them: ``312M``, ``1.5G``."""
    for unit in ("T", "G", "M", "K"):
        if n >= _UNITS[unit]:
            value = n / _UNITS[unit]
            return f"{value:.4g}{unit}" if value < 100 and unit in "GT" else \
                f"{value:.0f}{unit}"
    return f"{n:.0f}"


def _status_field(pid: int, name: str) -> int:
    """A ``kB`` field of ``/proc/PID/status`` in bytes (0 where there is none)."""
    try:
        with open(f"/proc/{pid}/status", encoding="ascii") as f:
            for line in f:
                if line.startswith(name + ":"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    return 0


def rss_of(pid: int) -> int:
    return _status_field(pid, "VmRSS")


def peak_of(pid: int) -> int:
    return _status_field(pid, "VmHWM")


def pss_of(pid: int) -> int:
    """A process's proportional set size (pages it shares counted as its share), in bytes;
    its resident size where the kernel has no ``smaps_rollup``."""
    try:
        with open(f"/proc/{pid}/smaps_rollup", encoding="ascii") as f:
            for line in f:
                if line.startswith("Pss:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    return rss_of(pid)


RESCAN = 0.25               # s between looks for the processes a sandboxed program started


class SandboxMemory:
    """The memory of a sandboxed run, whose child here is bubblewrap's: the interpreter is
    its grandchild (under the sandbox's first process). ``()`` gives ``(now, peak)``: the
    interpreter's resident size, plus the proportional sizes of the processes it started
    (forks share its pages: counted once), looked for every :data:`RESCAN` s."""

    def __init__(self, root: int) -> None:
        self.root, self.interpreter = root, None
        self.started: int = 0           # the started processes' memory at the last look
        self.next_look = 0.0

    def __call__(self) -> tuple[int, int]:
        now = time.monotonic()
        if now >= self.next_look or self.interpreter is None:
            self.next_look = now + RESCAN
            self._look()
        if self.interpreter is None:
            return 0, 0
        current = rss_of(self.interpreter) + self.started
        return current, max(current, peak_of(self.interpreter))

    def _look(self) -> None:
        children = lineage.processes()
        first = children.get(self.root, [])
        inside = children.get(first[0], []) if first else []
        self.interpreter = inside[0] if inside else None
        if self.interpreter is None:
            return
        todo, started = list(children.get(self.interpreter, ())), []
        while todo:
            pid = todo.pop()
            started.append(pid)
            todo.extend(children.get(pid, ()))
        self.started = sum(pss_of(pid) for pid in started)

    def first(self) -> int | None:
        """The sandbox's first process (its init: killing it ends all inside), if any."""
        first = lineage.processes().get(self.root, [])
        return first[0] if first else None


def machine_memory() -> int:
    """The memory this machine (or its container's cgroup) has, in bytes."""
    total = _status_field_of("/proc/meminfo", "MemTotal")
    try:
        limit = Path("/sys/fs/cgroup/memory.max").read_text().strip()
        if limit.isdigit():
            total = min(total, int(limit)) if total else int(limit)
    except OSError:
        pass
    return total


def _status_field_of(file: str, name: str) -> int:
    try:
        for line in Path(file).read_text().splitlines():
            if line.startswith(name + ":"):
                return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    return 0


MAX_MEMORY = 1 << 50        # 1024T: a size beyond any machine's is a typo, not a limit


def memory_limit(max_memory) -> int:
    """``--max-memory`` in bytes: a size (``"2G"``), bytes, or None for the default share."""
    if max_memory is None:
        total = machine_memory()
        return int(total * DEFAULT_SHARE) if total else 1 << 62
    try:
        limit = parse_size(max_memory) if isinstance(max_memory, str) else int(max_memory)
    except (ValueError, TypeError, OverflowError):
        raise UserError(f"--max-memory {max_memory}: give a size such as 500M or 2G") \
            from None
    if limit > MAX_MEMORY:
        raise UserError(f"--max-memory {max_memory}: more than any machine has; give at most "
                        f"{size_text(MAX_MEMORY)} (a size such as 500M or 2G)")
    if limit < MIN_MEMORY:
        raise UserError(f"--max-memory {max_memory}: {size_text(limit)} is too little for a run; "
                   f"give at least {size_text(MIN_MEMORY)} (a size such as 500M or 2G)")
    return limit


class Watch:
    """What the supervisor knows of a run: its limits, the child's last progress report,
    its peak memory, and when a frame last came."""

    def __init__(self, program: Path, limit: int, timeout: float | None, stall_after: float,
                 stall_again: float, say) -> None:
        self.program, self.limit, self.timeout = program, limit, timeout
        self.stall_after, self.stall_again, self.say = stall_after, stall_again, say
        self.start = time.monotonic()
        self.peak = 0
        self.killed: tuple[str, int | None] | None = None
        self.reported = 0.0
        self.dialect: str | None = None   # known once the program was read and compiled
        self.last: dict = {}
        self.last_at = self.start
        self.frames = -1
        self.waiting = self.start         # since when no frame has come
        self.mark = (self.start, {})      # (when, progress) of the last frame or diagnosis
        self.said = False

    def progress(self, message: dict) -> None:
        if "taken" in message:          # sent as a frame is taken, before the clock moves
            message["frames"] = message["taken"]
        self.last, self.last_at = message, time.monotonic()
        if message.get("frames", 0) != self.frames:
            self.frames = message.get("frames", 0)
            self.waiting = self.last_at
            self.mark, self.said = (self.last_at, message), False

    def check_stall(self) -> None:
        """Say why no frame has come, after ``stall_after`` s and every ``stall_again``."""
        now = time.monotonic()
        if now - self.mark[0] < (self.stall_again if self.said else self.stall_after):
            return
        self.say(stall_line(self, now))
        self.mark, self.said = (now, self.last), True

    def where(self) -> str:
        """``"at 1.23 s of program time (61 frames)"``, or before the clock started."""
        if not self.last.get("started"):
            return "before the program's clock started"
        frames = self.last["frames"]
        return (f"at {self.last['clock']:.4g} s of program time ({frames} "
                f"frame{'s' * (frames != 1)})")


def stall_line(watch: Watch, now: float) -> str:
    """Why no frame has come since ``watch.mark``: the program's clock and its calls."""
    p, (then, before) = watch.last, watch.mark
    head = (f"springscene: {watch.program}: no frame for {now - watch.waiting:.0f} s of "
            "wall clock")
    line = f" (at line {p['line']} of {watch.program.name})" if p.get("line") else ""
    if now - watch.last_at > 1:          # four reports missed (one every 0.25 s)
        return (f"{head}: nothing reported for {now - watch.last_at:.0f} s: one long call "
                f"holds Python (a big numpy operation, or VTK loading){line}")
    if not p.get("started"):
        return f"{head}: the program is still setting up{line}"
    if p.get("ended"):
        return (f"{head}: the program has ended, {watch.where()}; its video is being "
                "finished")
    due = p["frames"] / p["fps"]
    calls = p["calls"] - before.get("calls", 0)
    clock = (f"at {p['clock']:.6g} s of program time; the next frame comes when it passes "
             f"{due:.6g} s")
    if calls <= 0 or not p.get("call"):
        return f"{head}: no rate() or sleep() call in {now - then:.0f} s{line}; {clock}"
    moved = p["clock"] - before.get("clock", 0.0)
    arg = f"{p['arg']:g}" if isinstance(p["arg"], float) else p["arg"]
    pace = (f", about {_duration((due - p['clock']) / moved * (now - then))} of wall clock "
            "away at this pace" if moved > 0 else ", and it does not move")
    return (f"{head}: {p['call']}({arg}) advances program time {p['span']:.3g} s a call "
            f"({calls:,} calls in {now - then:.0f} s){line}; {clock}{pace}")


def _duration(seconds: float) -> str:
    if not math.isfinite(seconds) or seconds > 3.2e9:
        return "forever"
    for unit, size in (("years", 3.15e7), ("days", 86400), ("h", 3600), ("min", 60)):
        if seconds >= size:
            return f"{seconds / size:,.3g} {unit}"
    return f"{seconds:.3g} s"


def ended_line(report: dict, watch: Watch) -> tuple[int, str]:
    """The exit status and the one line of a run that ended without its files."""
    status = report["process_status"]
    head = f"springscene: {watch.program}:"
    tail = f"{watch.where()}; nothing written (peak memory {size_text(watch.peak)})"
    if report.get("kind") == "exit":
        return report["status"], (f"{head} the program exited with status "
                                  f"{report['status']} (sys.exit) {tail}")
    if watch.killed and watch.killed[0] == "memory":
        return 128 + signal.SIGKILL, (f"{head} stopped: it used {size_text(watch.killed[1])}"
                                      f" of memory, over --max-memory "
                                      f"{size_text(watch.limit)}, {tail}")
    if watch.killed:
        return 124, f"{head} stopped by --timeout {watch.timeout:g} s (wall clock) {tail}"
    if status < 0:
        try:
            name = signal.Signals(-status).name
        except ValueError:                  # a real-time signal has no name
            name = f"signal {-status}"
        why = {"SIGSEGV": " (a crash: segmentation fault)",
               "SIGKILL": " (the kernel's out-of-memory killer sends it)"}.get(name, "")
        return 128 - status, f"{head} the program was killed by {name}{why} {tail}"
    if watch.dialect is None:           # springscene's child failed before the program ran
        return status or 1, (f"{head} the run's process ended with status {status} before "
                             f"the program started (see above); nothing written")
    return status or 1, (f"{head} the program's process ended with status {status} "
                         f"(os._exit?) before its output was finished, {tail}")
