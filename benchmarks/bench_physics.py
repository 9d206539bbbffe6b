"""Physics speed (`make bench`): the resonance sweep as one batch against separate runs,
and each integrator's steps per second against Euler-Cromer's, in the same run.

- sweep: 1,000 drive frequencies (6..18 rad/s, configs/driven.toml), every one run
  for 200 periods of the slowest drive (20,944 steps of 0.01 s) as ONE system of
  1,000 holder-ball pairs (`springscene sweep`);
- separate: the same sweep done as 1,000 single runs, one frequency each, through the
  same engine. Timing all 1,000 would take minutes, so SAMPLE of them, spread over the
  band, are timed and the total is extrapolated (each single run costs the same
  number of steps of the same size, so the time per run barely varies).
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from springscene import build, config  # noqa: E402
from springscene.model import integrators, physics  # noqa: E402
from springscene.science import sweep  # noqa: E402

N_FREQ = 1000
PERIODS = 200
SAMPLE = 8


def main() -> None:
    cfg = config.load(ROOT / "configs" / "driven.toml")
    omega = np.linspace(6.0, 18.0, N_FREQ)

    batch = sweep.sweep(cfg, omega, periods=PERIODS)
    singles = []
    picks = np.linspace(0, N_FREQ - 1, SAMPLE).astype(int)
    for c in picks:   # same run length as the batch: 200 periods of the slowest drive
        one = sweep.sweep(cfg, omega[[0, c]][1:], periods=PERIODS * omega[c] / omega[0])
        assert one.steps == batch.steps
        singles.append(one.seconds)
    per_run = float(np.median(singles))
    separate = per_run * N_FREQ
    print(f"resonance sweep: {N_FREQ} frequencies x {batch.steps:,} steps "
          f"({PERIODS} periods of the slowest drive, {batch.simulated:g} s simulated each)")
    print(f"  one batch      {batch.seconds:8.2f} s")
    print(f"  separate runs  {separate:8.1f} s  (median of {SAMPLE} timed single runs, "
          f"{per_run:.3f} s each, x {N_FREQ})")
    print(f"  the batch is {separate / batch.seconds:.0f}x faster; "
          f"{N_FREQ * batch.steps / batch.seconds / 1e6:.1f} M spring updates/s")

    print("integrators on the wiki scene (20,000 steps each, best of 3):")
    wiki = config.load(ROOT / "configs" / "wiki.toml")
    rates = {}
    for name in integrators.NAMES:
        c = config.override(wiki, "physics", integrator=name)
        best = min(_time_steps(c, 20000) for _ in range(3))
        rates[name] = 20000 / best
    for name, r in rates.items():
        print(f"  {name:<13} {r:10,.0f} steps/s  {rates['euler-cromer'] / r:5.2f}x euler-cromer's cost")


def _time_steps(cfg, n: int) -> float:
    s = build.system(cfg)
    start = time.perf_counter()
    physics.step(s, n)
    return time.perf_counter() - start


if __name__ == "__main__":
    main()
