#!/usr/bin/env python3
"""Run every corpus program through `springscene vpython` and measure what works.

Usage (needs imageio + numpy, e.g. springscene's own venv):
    /work/main/.venv/bin/python /work/corpus/run_all.py [--only SUBSTR] [--skip-py2] [--workers 2]

For each program listed in SOURCES.tsv:
    springscene vpython PROG --duration 3 --fps 25 --out /tmp/corpus_out/<name>.mp4
run with cwd = a scratch copy folder (/tmp/corpus_scratch/<name>/, holding the program and
whatever deps/<name>/ provides), stdin closed, a 120 s timeout.  Records exit status, the
last stderr line, wall time and whether the video is non-blank (some sampled frame has
pixel std >= 1).  Writes results.tsv and prints a summary.
"""
import argparse
import collections
import concurrent.futures as cf
import csv
import os
import re
import shutil
import signal
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
SPRINGSCENE = "/work/main/.venv/bin/springscene"
OUT = "/tmp/corpus_out"
SCRATCH = "/tmp/corpus_scratch"
TIMEOUT = 120
GS_AS_VP7 = False   # --glowscript-as-vp7 experiment
SRC = ""   # --src: a frozen copy of springscene's source tree to import instead of /work/main


def frames_blank(path, samples=6):
    """Return (blank: bool|None, nframes, note). None if the video cannot be read."""
    try:
        import imageio.v2 as iio
        import numpy as np
    except Exception as e:  # pragma: no cover
        return None, 0, f"no imageio: {e}"
    try:
        r = iio.get_reader(path, format="ffmpeg")
        n = r.count_frames()
        if n <= 0:
            return None, 0, "0 frames"
        idx = sorted(set(int(i) for i in np.linspace(0, n - 1, min(samples, n))))
        stds = []
        for i in idx:
            fr = r.get_data(i)
            stds.append(float(np.asarray(fr, dtype=np.float32).std()))
        r.close()
        return all(s < 1.0 for s in stds), n, "std=" + ",".join(f"{s:.1f}" for s in stds)
    except Exception as e:
        return None, 0, f"unreadable: {type(e).__name__}: {e}"


def last_error_line(stderr):
    lines = [l.rstrip() for l in stderr.splitlines() if l.strip()]
    # prefer the last "SomethingError: ..." style line
    for pat in (r"^\s*[A-Za-z_][\w.]*(Error|Exception|Exit|Interrupt)\b", r"^\s*springscene[^:]*: error"):
        for l in reversed(lines):
            if re.match(pat, l):
                return re.sub(r"^\s*(?:[a-z_]\w*\.)+(?=[A-Z]\w*(Error|Exception))", "", l).strip()
    return lines[-1].strip() if lines else ""


def run_one(row):
    rel = row["file"]
    name = os.path.splitext(os.path.basename(rel))[0]
    scratch = os.path.join(SCRATCH, name)
    shutil.rmtree(scratch, ignore_errors=True)
    os.makedirs(scratch)
    prog = os.path.join(scratch, os.path.basename(rel))
    shutil.copyfile(os.path.join(HERE, rel), prog)
    if GS_AS_VP7 and row["dialect"] == "glowscript":
        # experiment only: replace the GlowScript/Web VPython header line by an import
        with open(prog, encoding="utf-8", errors="surrogateescape") as f:
            lines = f.read().split("\n")
        for i, l in enumerate(lines):
            if re.match(r"^\s*#?\s*(GlowScript\s+[\d.]+\s+VPython|Web\s+VPython\s+[\d.]+)", l, re.I):
                lines[i] = "from vpython import *"
                break
        with open(prog, "w", encoding="utf-8", errors="surrogateescape") as f:
            f.write("\n".join(lines))
    deps = os.path.join(HERE, "deps", name)
    if os.path.isdir(deps):
        shutil.copytree(deps, scratch, dirs_exist_ok=True)
    out = os.path.join(OUT, name + ".mp4")
    if os.path.exists(out):
        os.remove(out)
    cmd = [SPRINGSCENE, "vpython", prog, "--duration", "3", "--fps", "25", "--out", out]
    t0 = time.time()
    env = dict(os.environ)
    if SRC:
        env["PYTHONPATH"] = SRC + (os.pathsep + env["PYTHONPATH"] if env.get("PYTHONPATH") else "")
    p = subprocess.Popen(cmd, cwd=scratch, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, errors="replace", start_new_session=True)
    timed_out = False
    try:
        so, se = p.communicate(timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        timed_out = True
        try:
            os.killpg(p.pid, signal.SIGKILL)   # only the group we started
        except ProcessLookupError:
            pass
        so, se = p.communicate()
    wall = time.time() - t0
    with open(os.path.join(scratch, "stderr.txt"), "w") as f:
        f.write(se or "")
    with open(os.path.join(scratch, "stdout.txt"), "w") as f:
        f.write(so or "")
    rc = "timeout" if timed_out else p.returncode
    blank, nframes, note = (None, 0, "")
    if os.path.exists(out) and os.path.getsize(out) > 0:
        blank, nframes, note = frames_blank(out)
    err = last_error_line(se or "")
    if timed_out:
        status = "timeout"
    elif rc != 0:
        status = "error"
    elif not os.path.exists(out):
        status = "no-output"
    elif blank is None:
        status = "unreadable"
    elif blank:
        status = "blank"
    else:
        status = "ok"
    return dict(file=rel, dialect=row["dialect"], status=status, exit=rc, frames=nframes,
                wall=f"{wall:.1f}", blank="" if blank is None else ("yes" if blank else "no"),
                frame_note=note, last_stderr=err[:400])


def springscene_state():
    if SRC:
        return f"frozen source tree {SRC}"
    try:
        g = ["git", "-C", "/work/main"]
        head = subprocess.run(g + ["rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
        dirty = subprocess.run(g + ["status", "--porcelain", "--untracked-files=no"], capture_output=True,
                               text=True).stdout.strip()
        return f"/work/main HEAD {head}" + (f" + uncommitted edits in {len(dirty.splitlines())} files" if dirty else "")
    except Exception as e:
        return f"unknown ({e})"


def cause(r):
    """Group a failure into a cause key."""
    st = r["status"]
    if st == "timeout":
        return "timeout (>120 s)"
    if st == "blank":
        return "blank video (every sampled frame one flat colour)"
    if st in ("no-output", "unreadable"):
        return st
    e = r["last_stderr"]
    m = re.match(r"^NameError: name '([^']+)'", e)
    if m:
        return f"NameError: name '{m.group(1)}'"
    m = re.match(r"^AttributeError: (.*?has no attribute '[^']+')", e)
    if m:
        return "AttributeError: " + m.group(1)
    m = re.match(r"^AttributeError: (.*)", e)
    if m:
        return "AttributeError: " + " ".join(m.group(1).split()[:8])
    m = re.match(r"^(ModuleNotFoundError|ImportError): (.*)", e)
    if m:
        return f"{m.group(1)}: {m.group(2)[:80]}"
    m = re.match(r"^(SyntaxError|IndentationError|TabError): (.*)", e)
    if m:
        msg = re.sub(r"\(.*line \d+\)", "", m.group(2)).strip()
        msg = re.sub(r"'[^']*'", "'…'", msg) if "Missing parentheses" not in msg else msg.split(".")[0]
        return f"{m.group(1)}: {msg[:70]}"
    m = re.match(r"^([\w.]*(Error|Exception)): (.*)", e)
    if m:
        msg = re.sub(r"-?\d+(\.\d+)?(e-?\d+)?", "N", m.group(3))
        return f"{m.group(1)}: " + " ".join(msg.split()[:10])[:110]
    return " ".join(e.split()[:10])[:110] or f"exit {r['exit']} (no stderr)"


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--only", default="")
    ap.add_argument("--skip-py2", action="store_true")
    ap.add_argument("--workers", type=int, default=2)
    ap.add_argument("--src", default="", help="import springscene from this source tree (PYTHONPATH), "
                    "e.g. a `git archive` of one commit, so the run is not disturbed by edits in /work/main")
    ap.add_argument("--out-name", default="results.tsv")
    ap.add_argument("--glowscript-as-vp7", action="store_true",
                    help="experiment: swap the GlowScript header line for `from vpython import *` first")
    ap.add_argument("--summary-only", action="store_true", help="re-print the summary of results.tsv")
    a = ap.parse_args()
    global SRC, GS_AS_VP7
    GS_AS_VP7 = a.glowscript_as_vp7
    SRC = os.path.abspath(a.src) if a.src else ""
    res_path = os.path.join(HERE, a.out_name)
    if not a.summary_only:
        meta = springscene_state()
        print("springscene:", meta, flush=True)
        if not os.path.exists(SPRINGSCENE):
            sys.exit(f"{SPRINGSCENE} not found")
        os.makedirs(OUT, exist_ok=True)
        os.makedirs(SCRATCH, exist_ok=True)
        rows = list(csv.DictReader(open(os.path.join(HERE, "SOURCES.tsv")), delimiter="\t"))
        rows = [r for r in rows if a.only in r["file"] and not (a.skip_py2 and r["dialect"] == "py2")]
        results = []
        with cf.ThreadPoolExecutor(max_workers=min(2, a.workers)) as ex:
            futs = {ex.submit(run_one, r): r for r in rows}
            for i, f in enumerate(cf.as_completed(futs), 1):
                r = f.result()
                results.append(r)
                print(f"[{i}/{len(rows)}] {r['status']:9s} {r['wall']:>6s}s {r['file']}  {r['last_stderr'][:100]}",
                      flush=True)
        results.sort(key=lambda r: r["file"])
        with open(res_path.replace(".tsv", ".meta.txt"), "w") as f:
            f.write(f"springscene at start: {meta}\nspringscene at end:   {springscene_state()}\n"
                    f"command: {SPRINGSCENE} vpython PROG --duration 3 --fps 25 --out {OUT}/<name>.mp4 "
                    f"(cwd scratch copy, stdin closed, timeout {TIMEOUT}s, PYTHONPATH={SRC or '-'})\n")
        cols = ["file", "dialect", "status", "cause", "exit", "wall", "frames", "blank", "frame_note", "last_stderr"]
        with open(res_path, "w", newline="") as f:
            w = csv.DictWriter(f, fieldnames=cols, delimiter="\t", lineterminator="\n", extrasaction="ignore")
            w.writeheader()
            for r in results:
                r["cause"] = "" if r["status"] == "ok" else cause(r)
                w.writerow(r)
    summary(res_path)


def summary(res_path):
    rs = list(csv.DictReader(open(res_path), delimiter="\t"))
    for r in rs:
        r["cause"] = "" if r["status"] == "ok" else cause(r)
    print("\n== pass rate per dialect (pass = exit 0 + non-blank video) ==")
    tot = collections.Counter(); ok = collections.Counter()
    for r in rs:
        tot[r["dialect"]] += 1
        ok[r["dialect"]] += r["status"] == "ok"
    for d in ("glowscript", "vp6", "vp7", "py2"):
        if tot[d]:
            tag = "  (excluded from total)" if d == "py2" else ""
            print(f"  {d:11s} {ok[d]:4d}/{tot[d]:<4d} {100*ok[d]/tot[d]:5.1f}%{tag}")
    n = sum(tot[d] for d in tot if d != "py2"); k = sum(ok[d] for d in ok if d != "py2")
    if n:
        print(f"  {'TOTAL':11s} {k:4d}/{n:<4d} {100*k/n:5.1f}%")
    fails = [r for r in rs if r["status"] != "ok" and r["dialect"] != "py2"]
    print(f"\n== failure causes (excluding py2), {len(fails)} failures ==")
    hist = collections.defaultdict(list)
    for r in fails:
        hist[r["cause"]].append(r["file"])
    for c, fs in sorted(hist.items(), key=lambda kv: (-len(kv[1]), kv[0])):
        ds = collections.Counter(f.split("/")[0] for f in fs)
        print(f"  {len(fs):3d}  {c}   [{', '.join(f'{d}:{v}' for d, v in sorted(ds.items()))}]  e.g. "
              + ", ".join(os.path.basename(f) for f in fs[:2]))
    names = collections.Counter(); attrs = collections.Counter()
    for r in fails:
        m = re.match(r"^NameError: name '([^']+)'", r["last_stderr"])
        if m: names[m.group(1)] += 1
        m = re.search(r"has no attribute '([^']+)'", r["last_stderr"])
        if m and r["last_stderr"].startswith("AttributeError"): attrs[m.group(1)] += 1
    if names:
        print("\n== NameError names ==\n  " + ", ".join(f"{k} ({v})" for k, v in names.most_common()))
    if attrs:
        print("\n== AttributeError attributes ==\n  " + ", ".join(f"{k} ({v})" for k, v in attrs.most_common()))


if __name__ == "__main__":
    main()
