"""The cost of keeping a run as data (docs/recording.md), against the same run's video.

For each program: a drafted MP4 run (``--draft``, the page's video, no HTML page), the
same run with ``--record``, and the recording alone (``--out run.jsonl``: nothing drawn),
in this process (no supervisor), 3 s of program time at 25 frames/s. The target: the
recording adds at most 10 % to the drafted video run. Rounds are interleaved and the best
of each kept; what is quoted are ratios within one run. On a shared machine two whole runs
differ by several per cent, so the recorder's own time (its frames, its file's opening and
closing, timed inside the run with the video) is quoted too, as a share of that run.
"""

from __future__ import annotations

import sys
import tempfile
import textwrap
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from springscene.view import backend  # noqa: E402
from springscene.vpython.record.recorder import Recorder  # noqa: E402
from springscene.vpython.run.options import RunOptions  # noqa: E402
from springscene.vpython.run.runner import run_program  # noqa: E402

SECONDS, FPS, ROUNDS = 3.0, 25, 3

SPHERES = textwrap.dedent("""
    from vpython import *
    scene.width, scene.height = 640, 400
    balls = [sphere(pos=vector(i % 10, (i // 10) % 10, i // 100), radius=0.2,
                    color=vector((i % 7) / 7, 0.5, 1 - (i % 5) / 5)) for i in range(1000)]
    t = 0
    while True:
        rate(25)
        t += 0.04
        for i, b in enumerate(balls):
            b.pos.y = (i // 10) % 10 + 0.3 * sin(t + i)
""")


def _programs(tmp: Path) -> list[tuple[str, Path]]:
    spheres = tmp / "spheres.py"
    spheres.write_text(SPHERES)
    return [("wiki_spring", ROOT / "examples" / "wiki_spring.py"),
            ("lattice (64 atoms, 144 helices)", ROOT / "examples" / "lattice.py"),
            ("1,000 moving spheres", spheres)]


_OWN = [0.0]        # seconds spent inside the recorder since last reset


def _timed(method):
    def timed(*args, **kwargs):
        start = time.perf_counter()
        try:
            return method(*args, **kwargs)
        finally:
            _OWN[0] += time.perf_counter() - start
    return timed


for _name in ("__init__", "take", "close", "printed"):
    setattr(Recorder, _name, _timed(getattr(Recorder, _name)))


def _run(program: Path, out: Path, record: Path | None = None) -> float:
    _OWN[0] = 0.0
    start = time.perf_counter()
    run_program(program, out, RunOptions(duration=SECONDS, fps=FPS, antialias=False,
                                         page=False,
                                         record=str(record) if record else None))
    return time.perf_counter() - start


def main() -> None:
    backend.select("auto")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        print(f"the recording's cost: {SECONDS:g} s at {FPS} frames/s, drafted MP4 "
              f"(best of {ROUNDS}, interleaved):")
        for name, program in _programs(tmp):
            best = {"video": float("inf"), "video + recording": float("inf"),
                    "recording alone": float("inf")}
            share = float("inf")      # the recorder's own time / the run it was part of
            for _ in range(ROUNDS):
                best["video"] = min(best["video"], _run(program, tmp / "v.mp4"))
                whole = _run(program, tmp / "v.mp4", tmp / "v.jsonl")
                best["video + recording"] = min(best["video + recording"], whole)
                share = min(share, _OWN[0] / (whole - _OWN[0]))
                best["recording alone"] = min(best["recording alone"],
                                              _run(program, tmp / "r.jsonl"))
            size = (tmp / "r.jsonl").stat().st_size
            base = best["video"]
            print(f"  {name}: video {base:.2f} s; with the recording "
                  f"{best['video + recording']:.2f} s "
                  f"(+{100 * (best['video + recording'] / base - 1):.1f} %); the recording "
                  f"alone {best['recording alone']:.2f} s "
                  f"({best['recording alone'] / base:.2f}x the video), {size / 1e6:.2f} MB; "
                  f"the recorder's own time {100 * share:.1f} % of the video run")


if __name__ == "__main__":
    main()
