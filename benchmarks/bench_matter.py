"""The model of matter's physics speed and memory (`make bench`), against baselines in the same run.

A 30 x 30 x 30 simple cubic crystal of aluminium atoms (27,000 atoms, 78,300 bonds,
outer layer held, 300 K), stepped by Euler-Cromer:

- grid: springscene's engine (``System.grid`` set: the bond forces by slicing the
  grid, a stencil);
- bincount: the same engine and the same system without ``grid``: the plain numpy
  step, gathering the bond ends by index and scattering the forces with
  ``np.bincount`` (what the page's single spring and the resonance sweep use);
- per-object: the page's loop written per bond in Python, the way a VPython program
  writes a crystal (``examples/lattice.py``): ``L = b.pos - a.pos;
  F = -k*(mag(L)-L0)*norm(L); b.p = b.p + F*dt; a.p = a.p - F*dt``, then
  ``a.pos = a.pos + (a.p/m)*dt`` for each free atom. Twice: with the atoms as
  VPython ``sphere`` objects (springscene.vpython, nothing drawn), and, the
  fastest a per-object loop gets, as plain slotted objects holding VPython
  vectors. It is timed on a 10 x 10 x 10 crystal and given as bonds per second.

Memory: the peak of Python's traced allocations (numpy's arrays included) while
stepping, the process's peak resident size, and the traced allocations after 20
steps against after 520 (no growth per step).

Rounds are interleaved and the best of each is kept.
"""

from __future__ import annotations

import resource
import sys
import time
import tracemalloc
from pathlib import Path


ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from springscene import build, config  # noqa: E402
from springscene.model import physics  # noqa: E402

N = 30
STEPS = 40
ROUNDS = 3


def crystal(n: int) -> config.Config:
    return config.from_dict({
        "lattice": {"shape": [n, n, n], "density": 2700.0, "fixed": "outer"},
        "bond": {"k": 16.0}, "atom": {"molar_mass": 0.027},
        "start": {"temperature": 300.0, "seed": 1}, "physics": {"dt": 2e-15},
    }, source=f"<{n}^3 aluminium crystal>")


def without_grid(s: physics.System) -> physics.System:
    return physics.System(pos=s.pos, p=s.p, m=s.m, fixed=s.fixed, i=s.i, j=s.j, k=s.k,
                          L0=s.L0, g=s.g, dt=s.dt)


def rate(s: physics.System, steps: int) -> float:
    """Bond updates per second over ``steps`` steps."""
    physics.step(s, 2)                   # warm caches
    start = time.perf_counter()
    physics.step(s, steps)
    return len(s.i) * steps / (time.perf_counter() - start)


def per_object_rate(n: int, spheres: bool) -> float:
    """Bond updates per second of the page's loop written per object (examples/lattice.py)."""
    from springscene.vpython import api as vp
    from springscene.vpython.core.vectors import mag, norm, vector

    s = build.system(crystal(n))

    class Atom:
        __slots__ = ("pos", "p", "fixed")

    atoms = []
    for r, q, held in zip(s.pos, s.p, s.fixed):
        a = vp.sphere(pos=vector(*r), radius=0.25 * float(s.L0[0])) if spheres else Atom()
        a.pos, a.p, a.fixed = vector(*r), vector(*q), bool(held)
        atoms.append(a)
    bonds = [(atoms[i], atoms[j]) for i, j in zip(s.i, s.j)]
    k, d, m, dt = float(s.k[0]), float(s.L0[0]), float(s.m[0]), s.dt
    start = time.perf_counter()
    for a, b in bonds:
        L = b.pos - a.pos
        F = -k * (mag(L) - d) * norm(L)
        b.p = b.p + F * dt
        a.p = a.p - F * dt
    for a in atoms:
        if not a.fixed:
            a.pos = a.pos + (a.p / m) * dt
        else:
            a.p = vector(0, 0, 0)
    seconds = time.perf_counter() - start
    if spheres:
        vp.reset()
    return len(bonds) / seconds


def memory(cfg: config.Config) -> tuple[float, float, float]:
    """Traced peak from building the system to step 520 (MB), growth from step 20 to 520
    (bytes), and the process's peak RSS (MB)."""
    tracemalloc.start()
    s = build.system(cfg)
    physics.step(s, 20)
    before = tracemalloc.get_traced_memory()[0]
    physics.step(s, 500)
    after, peak = tracemalloc.get_traced_memory()
    tracemalloc.stop()
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024
    return peak / 1e6, after - before, rss


def main() -> None:
    cfg = crystal(N)
    grid_sys = build.system(cfg)
    plain_sys = without_grid(build.system(cfg))
    print(f"{N}^3 crystal: {grid_sys.n_nodes:,} atoms, {len(grid_sys.i):,} bonds, "
          f"Euler-Cromer, {STEPS} steps per round, best of {ROUNDS}")
    grid, plain = [], []
    for _ in range(ROUNDS):
        grid.append(rate(grid_sys, STEPS))
        plain.append(rate(plain_sys, STEPS))
    g, p = max(grid), max(plain)
    plain_obj = max(per_object_rate(10, spheres=False) for _ in range(2))
    spheres = max(per_object_rate(10, spheres=True) for _ in range(2))
    print(f"  grid (springscene)   {g / 1e6:7.1f} M bond updates/s")
    print(f"  bincount (plain)     {p / 1e6:7.1f} M bond updates/s   grid is {g / p:.2f}x")
    print(f"  per-object, spheres  {spheres / 1e6:7.3f} M bond updates/s   grid is "
          f"{g / spheres:,.0f}x   (10^3 crystal of VPython spheres)")
    print(f"  per-object, plain    {plain_obj / 1e6:7.3f} M bond updates/s   grid is "
          f"{g / plain_obj:,.0f}x   (10^3 crystal, slotted objects of VPython vectors)")
    peak, growth, rss = memory(cfg)
    state = sum(a.nbytes for a in (grid_sys.pos, grid_sys.p, grid_sys.m, grid_sys.i,
                                   grid_sys.j, grid_sys.k, grid_sys.L0))
    print(f"memory, {N}^3 crystal: state {state / 1e6:.1f} MB; traced peak, building and stepping, "
          f"{peak:.1f} MB; growth from step 20 to 520: {growth:+,} bytes; "
          f"peak RSS of this process {rss:.0f} MB")


if __name__ == "__main__":
    main()
