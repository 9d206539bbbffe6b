"""Physics against the wiki's loop, bit for bit, and against closed forms."""

import math

import numpy as np
import pytest

from springscene import build, config
from springscene.model import physics
from wikiloop import wiki_loop

CFG = config.load("configs/wiki.toml")
K, M, L0, G, DT = 15.0, 0.10, 0.10, 9.8, 0.01


def test_config_values_are_the_pages():
    s = build.system(CFG)
    assert (s.k[0], s.L0[0], s.m[1], s.dt) == (15.0, 0.10, 0.10, 0.01)
    assert tuple(s.g) == (0.0, -9.8, 0.0)
    # starts at rest 0.02 m below equilibrium
    assert s.pos[1, 1] == pytest.approx(-(L0 + M * G / K + 0.02), abs=1e-15)
    assert np.all(s.p == 0)


def test_first_step_by_hand():
    s = build.system(CFG)
    y0 = s.pos[1, 1]
    physics.step(s)
    Fs_y = -K * (abs(y0) - L0) * (y0 / abs(y0))    # spring pulls up
    Fnet_y = Fs_y + M * -G
    p1 = Fnet_y * DT
    assert Fnet_y == pytest.approx(0.3, abs=1e-12)  # k * 0.02 m below equilibrium
    assert s.p[1, 1] == p1
    assert s.pos[1, 1] == y0 + (p1 / M) * DT
    assert s.pos[0].tolist() == [0, 0, 0] and s.p[0].tolist() == [0, 0, 0]  # holder fixed


@pytest.mark.parametrize("start, p0", [
    ((0, -0.18533333333333335, 0), (0, 0, 0)),
    ((0.03, -0.12, 0.01), (0.002, 0.01, -0.001)),   # a swinging, compressed start
])
def test_bit_identical_to_wiki_loop(start, p0):
    ref = wiki_loop(2000, start, p0)
    cfg = config.override(CFG, "ball", pos=start, p=p0)
    s = build.system(cfg)
    got = np.empty_like(ref)
    for n in range(len(ref)):
        physics.step(s)
        got[n, :3], got[n, 3:] = s.pos[1], s.p[1]
    assert np.array_equal(got, ref)   # exact, not approximate


def crossings(t, y, level):
    """Interpolated times of upward crossings of ``level``."""
    d = y - level
    idx = np.flatnonzero((d[:-1] < 0) & (d[1:] >= 0))
    return t[idx] - d[idx] * (t[idx + 1] - t[idx]) / (d[idx + 1] - d[idx])


def test_period_matches_closed_form():
    traj = physics.run(build.system(CFG), 2000)            # 20 s, about 39 periods
    eq = -(L0 + M * G / K)
    tc = crossings(traj.t, traj.pos[:, 1], eq)
    period = (tc[-1] - tc[0]) / (len(tc) - 1)
    assert period == pytest.approx(2 * math.pi * math.sqrt(M / K), rel=0.002)


def test_equilibrium_stretch_is_mg_over_k():
    eq = -(L0 + M * G / K)
    s = build.system(config.override(CFG, "ball", pos=(0, eq, 0)))
    physics.step(s, 1000)
    assert s.pos[1, 1] == pytest.approx(eq, abs=1e-12)
    # and an oscillation is centred on it
    traj = physics.run(build.system(CFG), 1000)
    assert traj.pos[:, 1].mean() == pytest.approx(eq, abs=2e-4)
    assert (-traj.pos[:, 1] - L0).mean() == pytest.approx(0.0653, abs=5e-4)


def test_energy_bounded_over_100_periods():
    T = 2 * math.pi * math.sqrt(M / K)
    per = int(round(T / DT))
    traj = physics.run(build.system(CFG), 100 * per)
    E = traj.E
    osc = 0.5 * K * 0.02 ** 2                             # energy of the oscillation
    first, last = E[:per], E[-per:]
    assert np.ptp(E) < 0.2 * osc                         # Euler-Cromer's wobble stays small
    assert abs(last.mean() - first.mean()) < 0.01 * osc  # and does not drift


def test_energy_terms():
    s = build.system(CFG)
    e = physics.energies(s)
    y = s.pos[1, 1]
    assert e.K == 0
    assert e.Us == pytest.approx(0.5 * K * (abs(y) - L0) ** 2, rel=1e-14)
    assert e.Ug == pytest.approx(M * G * y, rel=1e-14)
    s.p[1] = (0.0, 0.05, 0.0)
    assert physics.energies(s).K == pytest.approx(0.05 ** 2 / (2 * M))


def test_many_nodes_one_engine_conserves_momentum():
    """A free chain (no anchors, no gravity) keeps its total momentum to round-off."""
    rng = np.random.default_rng(1)
    n = 12
    pos = np.c_[np.arange(n) * 0.1, np.zeros(n), np.zeros(n)] + rng.normal(0, 0.01, (n, 3))
    s = physics.System(pos=pos, p=rng.normal(0, 0.01, (n, 3)), m=0.1, fixed=False,
                       i=np.arange(n - 1), j=np.arange(1, n), k=15.0, L0=0.1,
                       g=(0, 0, 0), dt=0.001)
    p0 = s.p.sum(axis=0)
    physics.step(s, 2000)
    assert np.allclose(s.p.sum(axis=0), p0, atol=1e-14)
