"""A class at once: `springscene batch` on 40 lab programs against their single runs (issue 28).

The class is benchmarks/class_labs/make_class.py's: 40 students' programs for four labs
(spring, projectile, orbit, pendulum or ramp), most Web VPython, some VPython 7, a few
VPython 6, four with a mistake (a wrong spring constant, a NameError after a second, a
loop with no ``rate`` that times out, a list that blows the memory limit). Each is filmed
for 3 s of program time with the options a batch uses (its video, page and recording,
``--timeout`` and ``--max-memory``), and measured three ways:

- **single runs**: ``springscene vpython PROGRAM`` one after another; their wall times summed;
- **the batch**: ``springscene batch CLASS --jobs 2``, sandboxed as by default and then
  with ``--no-sandbox`` (as the single runs are); its wall time against that sum (target:
  at most 0.6x), and the peak memory of its whole process tree (sampled from /proc)
  against jobs x the largest single run's tree + 200 MB. Memory is the tree's PSS, which
  counts a page shared by several processes once: the batch's job processes and their
  programs are forks of one warm process and share its pages, which a sum of RSS would
  count once in each (that sum is printed beside it);
- **a Dask cluster** (when ``distributed`` is importable): the same batch through a
  2-worker ``distributed.LocalCluster`` (``--scheduler``): its rows must be the local
  batch's but for the times, its videos byte-identical.

Both measurements are made in the same run, so the ratio holds on a shared machine; the
load average (``uptime``) is printed with them. Each program's status and times are
listed, with the ending its student's mistake should have (MANIFEST.tsv).

    python benchmarks/bench_batch.py [--jobs 2] [--keep DIR] [--single-only]
"""

from __future__ import annotations

import argparse
import json
import os
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT / "benchmarks" / "class_labs"))

from make_class import write_class  # noqa: E402

try:
    from distributed import LocalCluster
except ImportError:                   # the Dask path is measured only where it is installed
    LocalCluster = None

SECONDS, TIMEOUT, MAX_MEMORY = 3, 120, "1G"
# each program's run, single or in the batch; --timeout is set in main
RUN_OPTIONS = ["--duration", str(SECONDS), "--max-memory", MAX_MEMORY]
SAMPLE = 0.1                # s between two samples of a process tree's memory (one takes ~6 ms)
HEADROOM = 200 * 2 ** 20    # the memory target's allowance over jobs x the largest run
STATUS = {0: "ran", 1: "error", 124: "timeout", 137: "memory"}
_REACHED = re.compile(r"([-+.\deE]+) s of program time|at t = ([-+.\deE]+) s")
_ERROR = re.compile(r"^\w+(Error|Exception|Interrupt|Exit)\b.*", re.MULTILINE)
# the time fields of a row, which differ between two runs of the same program
TIMES = {"wall_seconds", "started", "finished", "seconds", "peak_memory"}


def springscene(*args: str) -> list[str]:
    """The command line of ``springscene ARGS`` with this checkout's springscene."""
    # (not the working folder first on the path: the measured checkout is)
    return [sys.executable, "-c", "import sys; sys.path.pop(0); "
            "from springscene.app.signals import main; sys.exit(main())", *args]


CHECKOUT = [ROOT]           # the springscene measured: this checkout, or --checkout's


def environment() -> dict:
    """The measured springscene first on the path of every process started."""
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join(filter(None, [str(CHECKOUT[0]), env.get("PYTHONPATH")]))
    return env


def _children() -> dict[int, list[int]]:
    """Each process's children, from /proc/PID/stat."""
    children: dict[int, list[int]] = {}
    for entry in os.scandir("/proc"):
        if not entry.name.isdigit():
            continue
        try:
            with open(f"/proc/{entry.name}/stat") as stat:
                fields = stat.read().rsplit(")", 1)[1].split()
        except OSError:
            continue
        children.setdefault(int(fields[1]), []).append(int(entry.name))
    return children


def tree_memory(root: int) -> tuple[int, int]:
    """The resident memory of ``root`` and all its descendants, in bytes, two ways: the sum
    of their RSS, which counts a page shared by several processes (a fork's, a library's)
    once in each, and of their PSS, which shares such a page out among them (the memory
    the tree really holds)."""
    children, rss, pss, todo = _children(), 0, 0, [root]
    while todo:
        pid = todo.pop()
        todo.extend(children.get(pid, []))
        try:
            with open(f"/proc/{pid}/smaps_rollup") as rollup:
                fields = dict(line.split(":", 1) for line in rollup if ":" in line)
        except OSError:
            continue
        rss += int(fields.get("Rss", "0 kB").split()[0]) * 1024
        pss += int(fields.get("Pss", "0 kB").split()[0]) * 1024
    return rss, pss


def measured(command: list[str], log: Path) -> tuple[int, float, dict]:
    """Runs ``command`` (its output into ``log``): its exit status, wall time (s) and the
    peak memory of its process tree (bytes, sampled every :data:`SAMPLE` s: PSS, and under
    ``"rss"`` the RSS summed)."""
    start, peak = time.perf_counter(), {"pss": 0, "rss": 0}
    with open(log, "wb") as out:
        process = subprocess.Popen(command, stdout=out, stderr=subprocess.STDOUT,
                                   stdin=subprocess.DEVNULL, env=environment())
        try:
            while process.poll() is None:
                rss, pss = tree_memory(process.pid)
                peak = {"pss": max(peak["pss"], pss), "rss": max(peak["rss"], rss)}
                time.sleep(SAMPLE)
        finally:                        # (interrupted: springscene ends its own children)
            if process.poll() is None:
                process.terminate()
                process.wait()
    return process.returncode, time.perf_counter() - start, peak


def single_runs(programs: list[Path], out: Path) -> list[dict]:
    """Each program by ``springscene vpython``, one after another, as a batch runs it."""
    rows = []
    for program in programs:
        folder = out / program.stem
        folder.mkdir(parents=True, exist_ok=True)
        video = folder / f"{program.stem}.mp4"
        status, wall, peak = measured(
            springscene("vpython", str(program), "--out", str(video), "--record",
                        str(folder / f"{program.stem}.jsonl.gz"), *RUN_OPTIONS),
            folder / "log.txt")
        text = (folder / "log.txt").read_text(errors="replace")
        reached = [float(a or b) for a, b in _REACHED.findall(text)]
        error = _ERROR.search(text[text.rfind("Traceback"):]) if "Traceback" in text else None
        rows.append({"program": program.name, "status": STATUS.get(status, f"exit {status}"),
                     "program_seconds": reached[-1] if reached else None,
                     "wall": wall, "peak": peak,
                     "last_line": error[0] if error else _last_line(text)})
        print(f"  {program.name}: {rows[-1]['status']}, {wall:.1f} s, "
              f"{peak['pss'] / 2 ** 20:.0f} MiB", flush=True)
    return rows


def _last_line(text: str) -> str:
    lines = [line for line in text.strip().splitlines() if line.strip()]
    return lines[-1].strip() if lines else ""


def batch_run(folder: Path, out: Path, jobs: int, *extra: str) -> tuple[float, dict, list]:
    """``springscene batch`` on the class: its wall time, peak memory and summary rows."""
    out.mkdir(parents=True, exist_ok=True)
    status, wall, peak = measured(
        springscene("batch", str(folder), "--out-dir", str(out), "--jobs", str(jobs),
                    *RUN_OPTIONS, *extra), out.parent / f"{out.name}.log")
    if status not in (0, 1):
        log = (out.parent / f"{out.name}.log").read_text(errors="replace")
        raise SystemExit(f"springscene batch ended with status {status}: {_last_line(log)}")
    summary = json.loads((out / "summary.json").read_text())
    rows = summary["rows"] if isinstance(summary, dict) else summary
    return wall, peak, rows


def _name(row: dict) -> str:
    return Path(row.get("program", row.get("name", ""))).name


def _untimed(row: dict) -> dict:
    return {key: value for key, value in row.items() if key not in TIMES}


def cluster_compare(folder: Path, out: Path, jobs: int, local: list) -> str | None:
    """The class through a 2-worker LocalCluster, against the local batch's rows and
    videos; None when ``distributed`` is not importable."""
    if LocalCluster is None:
        return None
    # the measured springscene for the workers and for the scheduler, here, which unpickles
    # the tasks
    os.environ["PYTHONPATH"] = environment()["PYTHONPATH"]
    sys.path.insert(0, str(CHECKOUT[0]))
    with LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                      dashboard_address=None) as cluster:
        wall, _, rows = batch_run(folder, out / "cluster", jobs, "--scheduler",
                                  cluster.scheduler_address)
    local_rows = {_name(row): _untimed(row) for row in local}
    differ = [_name(row) for row in rows if _untimed(row) != local_rows.get(_name(row))]
    videos = sorted((out / "batch").rglob("*.mp4"))
    unlike = [video.name for video in videos
              if not _same_bytes(video, out / "cluster" / video.relative_to(out / "batch"))]
    return (f"the cluster's batch (a 2-worker LocalCluster): {wall:.1f} s; rows differing "
            f"but for times: {len(differ)} of {len(rows)}{_listed(differ)}; videos not "
            f"byte-identical: {len(unlike)} of {len(videos)}{_listed(unlike)}")


def _same_bytes(one: Path, other: Path) -> bool:
    return other.is_file() and one.read_bytes() == other.read_bytes()


def _listed(names: list[str]) -> str:
    return f" ({', '.join(names)})" if names else ""


def manifest(folder: Path) -> dict[str, dict]:
    lines = (folder / "MANIFEST.tsv").read_text().splitlines()
    keys = lines[0].split("\t")
    return {row["file"]: row for row in (dict(zip(keys, line.split("\t"))) for line in lines[1:])}


def report_programs(singles: list[dict], batch_rows: list, expected: dict) -> None:
    """Each program: the ending expected, the single run's and the batch's."""
    by_name = {_name(row): row for row in batch_rows}
    print(f"{'program':28} {'dialect':7} {'expected':8} {'single':8} {'reached':>8} "
          f"{'wall':>6} {'peak':>6} {'batch':8}")
    for row in singles:
        want = expected[row["program"]]
        other = by_name.get(row["program"], {})
        reached = "-" if row["program_seconds"] is None else f"{row['program_seconds']:.2f}"
        flag = "" if row["status"] == want["expected"] else "   <-- not as expected"
        print(f"{row['program']:28} {want['dialect']:7} {want['expected']:8} "
              f"{row['status']:8} {reached:>8} {row['wall']:6.1f} "
              f"{row['peak']['pss'] / 2 ** 20:6.0f} {other.get('status', '-'):8}{flag}")
        if row["status"] != "ran":
            print(f"    {row['last_line'][:150]}")


def report_batch(flags: str, wall: float, peak: dict, rows: list, singles: list[dict],
                 jobs: int) -> None:
    """A batch's wall time against the single runs' sum, and its peak memory against
    jobs x the largest single run + 200 MiB (PSS, the target's measure; RSS summed beside)."""
    total = sum(row["wall"] for row in singles)
    print(f"springscene batch {flags}: {wall:.1f} s, {wall / total:.2f}x the sum of the "
          f"single runs (target 0.6x); {uptime()}")
    own = sum(row.get("wall_seconds") or 0 for row in rows)
    print(f"  its programs' own wall times sum to {own:.1f} s, {own / total:.2f}x their "
          f"single runs (each slowed by sharing the cores); {own / wall:.2f} at once")
    ran = [row for row in singles if row["status"] == "ran"]
    for what, among in (("the largest run", singles), ("the largest that ran", ran)):
        for measure in ("pss", "rss"):
            big = max(row["peak"][measure] for row in among)
            allowed = jobs * big + HEADROOM
            print(f"  peak memory of its tree ({measure.upper()}) "
                  f"{peak[measure] / 2 ** 20:.0f} MiB against {jobs} x {what} "
                  f"({big / 2 ** 20:.0f} MiB) + 200 MiB = {allowed / 2 ** 20:.0f} MiB: "
                  f"{peak[measure] / allowed:.2f}x the target")


def uptime() -> str:
    with open("/proc/loadavg") as load:
        return "load average " + ", ".join(load.read().split()[:3])


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--timeout", type=float, default=TIMEOUT,
                        help=f"each program's --timeout, s (default {TIMEOUT}: above any "
                        "run's wall time on a loaded machine; the loop with no rate() "
                        "takes it whole)")
    parser.add_argument("--keep", type=Path, help="a folder to keep the outputs in")
    parser.add_argument("--single-only", action="store_true", help="the single runs alone")
    parser.add_argument("--checkout", type=Path, default=ROOT,
                        help="the springscene checkout to measure (default: this one)")
    args = parser.parse_args()
    CHECKOUT[0] = args.checkout.resolve()
    RUN_OPTIONS.extend(["--timeout", f"{args.timeout:g}"])
    with tempfile.TemporaryDirectory() as tmp:
        out = args.keep or Path(tmp)
        programs = write_class(out / "class")
        print(f"the class: {len(programs)} programs, {SECONDS} s of program time each, "
              f"{' '.join(RUN_OPTIONS)}; {uptime()}")
        print("single runs (springscene vpython, one after another):")
        singles = single_runs(programs, out / "single")
        total = sum(row["wall"] for row in singles)
        largest = max(singles, key=lambda row: row["peak"]["pss"])
        ran = [row for row in singles if row["status"] == "ran"]
        print(f"  the sum: {total:.1f} s; the largest run's tree "
              f"{largest['peak']['pss'] / 2 ** 20:.0f} MiB ({largest['program']}); of those "
              f"that ran, {max(row['peak']['pss'] for row in ran) / 2 ** 20:.0f} MiB; {uptime()}")
        batch_rows: list = []
        if not args.single_only:
            for name, extra in (("batch", ()), ("batch-unsandboxed", ("--no-sandbox",))):
                wall, peak, rows = batch_run(out / "class", out / name, args.jobs, *extra)
                report_batch(" ".join(("--jobs", str(args.jobs), *extra)), wall, peak, rows,
                             singles, args.jobs)
                batch_rows = batch_rows or rows
        report_programs(singles, batch_rows, manifest(out / "class"))
        if not args.single_only:
            line = cluster_compare(out / "class", out, args.jobs, batch_rows)
            print(line or "the Dask cluster: distributed is not importable here: not measured")


if __name__ == "__main__":
    main()
