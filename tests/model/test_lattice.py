"""Chains and crystals in the shared engine: configs, building, the grid stencil, conservation."""

from __future__ import annotations

import math
import tracemalloc

import numpy as np
import pytest

from conftest import ROOT
from springscene import build, config, render
from springscene.model import lattice, physics
from springscene.model.constants import BOLTZMANN
from springscene.errors import UserError

CONFIGS = ROOT / "configs"


def crystal_cfg(shape=(5, 5, 5), fixed="outer", **sections):
    data = {"lattice": {"shape": list(shape), "spacing": 1.0, "fixed": fixed},
            "bond": {"k": 1.0}, "atom": {"m": 1.0}, "physics": {"dt": 0.05}}
    for name, table in sections.items():
        data.setdefault(name, {}).update(table)
    return config.from_dict(data, source="<test>")


def generic_copy(s: physics.System) -> physics.System:
    """The same system without ``grid``: the gather-and-bincount path."""
    return physics.System(pos=s.pos, p=s.p, m=s.m, fixed=s.fixed, i=s.i, j=s.j, k=s.k, L0=s.L0,
                          g=s.g, dt=s.dt, b=s.b, k3=s.k3, yield_stretch=s.yield_stretch,
                          F_ext=s.F_ext, integrator=s.integrator)


# ---- materials ------------------------------------------------------------------------------

@pytest.mark.parametrize("name, m, d, v", [
    ("chain-aluminum", 0.027 / 6.02214076e23, 2.551e-10, 4819.5),
    ("chain-lead", 0.207 / 6.02214076e23, 3.112e-10, 1187.1),
])
def test_material_numbers(name, m, d, v):
    lat = build.lattice(config.load(CONFIGS / f"{name}.toml"))
    assert lat.m == pytest.approx(m, rel=1e-12)
    assert lat.d == pytest.approx(d, rel=1e-3)
    assert lat.d ** 3 * {"chain-aluminum": 2700.0, "chain-lead": 11400.0}[name] == \
        pytest.approx(lat.m, rel=1e-12)                   # one atom per cube of side d
    assert lat.sound_speed == pytest.approx(v, rel=1e-4)
    assert lat.youngs_modulus == pytest.approx(lat.k / lat.d)


@pytest.mark.parametrize("name", ["chain", "chain-aluminum", "chain-lead", "crystal", "bar"])
def test_configs_build(name):
    cfg = config.load(CONFIGS / f"{name}.toml")
    s = build.system(cfg)
    lat = build.lattice(cfg)
    assert s.grid == lat.shape and s.n_nodes == lat.n_atoms
    nx, ny, nz = lat.shape
    assert len(s.i) == (nx - 1) * ny * nz + nx * (ny - 1) * nz + nx * ny * (nz - 1)
    L = s.pos[s.j] - s.pos[s.i]
    np.testing.assert_allclose(np.linalg.norm(L, axis=1), lat.d, rtol=1e-12)   # relaxed bonds
    assert not s.g.any()                                  # no gravity unless [physics] g is given
    np.testing.assert_allclose(s.pos.mean(axis=0), 0.0, atol=1e-12 * lat.d * nx)


def test_fixed_modes():
    count = lambda shape, mode: int(lattice.fixed_mask(shape, mode).sum())
    assert count((10, 10, 10), "outer") == 1000 - 8 ** 3
    assert count((10, 10, 10), "ends") == 200
    assert count((20, 3, 3), "start") == 9
    assert count((7, 1, 1), "ends") == 2 and count((7, 1, 1), "outer") == 2
    assert count((7, 1, 1), "none") == 0
    held = lattice.fixed_mask((20, 3, 3), "start").reshape(20, 3, 3)
    assert held[0].all() and not held[1:].any()


def test_kick_goes_to_the_first_free_layer():
    cfg = crystal_cfg((6, 4, 4), "outer", start={"kick": [2.0, 0.0, 0.0]})
    s = build.system(cfg)
    moving = np.flatnonzero(np.abs(s.p).sum(axis=1) > 0)
    idx = np.indices((6, 4, 4)).reshape(3, -1)
    assert set(idx[0, moving]) == {1}                       # the first x layer that is free
    assert len(moving) == 2 * 2                              # its inner 2 x 2 atoms
    np.testing.assert_array_equal(s.p[moving], [[2.0, 0.0, 0.0]] * 4)


def test_thermal_start():
    T = 1e22       # K, for unit masses: p ~ 0.4
    held = build.system(crystal_cfg(start={"temperature": T, "seed": 3}))
    free = held.free
    K = np.sum(held.p[free] ** 2) / 2
    assert K == pytest.approx(1.5 * len(free) * BOLTZMANN * T, rel=1e-12)
    assert not held.p[held.fixed].any()
    loose = build.system(crystal_cfg(fixed="none", start={"temperature": T, "seed": 3}))
    np.testing.assert_allclose(loose.p.sum(axis=0), 0.0, atol=1e-13)     # no drift
    K = np.sum(loose.p ** 2) / 2
    assert K == pytest.approx(1.5 * (loose.n_nodes - 1) * BOLTZMANN * T, rel=1e-12)
    again = build.system(crystal_cfg(start={"temperature": T, "seed": 3}))
    other = build.system(crystal_cfg(start={"temperature": T, "seed": 4}))
    np.testing.assert_array_equal(held.p, again.p)
    assert not np.array_equal(held.p, other.p)


def test_pull_is_on_the_last_face():
    cfg = config.load(CONFIGS / "bar.toml")
    s = build.system(cfg)
    face = lattice.last_layer(s.grid)
    assert s.F_ext[:, 0].sum() == pytest.approx(cfg.pull.force, rel=1e-12)
    np.testing.assert_array_equal(np.flatnonzero(s.F_ext[:, 0]), face)
    F = physics.forces(s, s.pos, 0.0)
    assert F[face, 0].sum() == pytest.approx(cfg.pull.force, rel=1e-12)   # bonds relaxed at t=0


# ---- the grid stencil against the generic path --------------------------------------------

@pytest.mark.parametrize("shape", [(9, 1, 1), (4, 5, 1), (5, 4, 6)])
@pytest.mark.parametrize("integrator", ["euler-cromer", "rk4"])
def test_grid_stencil_matches_bincount(shape, integrator):
    cfg = crystal_cfg(shape, "none", start={"temperature": 3e21, "seed": 1},
                      physics={"integrator": integrator, "dt": 0.02})
    grid = build.system(cfg)
    plain = generic_copy(grid)
    assert plain.grid is None
    np.testing.assert_allclose(physics.forces(grid, grid.pos, 0.0),
                               physics.forces(plain, plain.pos, 0.0), atol=1e-15)
    physics.step(grid, 300)
    physics.step(plain, 300)
    np.testing.assert_allclose(grid.pos, plain.pos, rtol=0, atol=1e-12)
    np.testing.assert_allclose(grid.p, plain.p, rtol=0, atol=1e-12)


def test_grid_stencil_with_per_bond_values_stiffening_and_yield():
    s = build.system(crystal_cfg((4, 3, 3), "start", start={"temperature": 3e22, "seed": 2}))
    rng = np.random.default_rng(0)
    s.k[:] = rng.uniform(0.5, 2.0, len(s.k))
    s.L0[:] = rng.uniform(0.9, 1.1, len(s.L0))
    s.k3[:] = 0.3
    s.yield_stretch[:] = 0.2
    plain = generic_copy(s)
    assert s.is_plastic and s.stiffens
    physics.step(s, 200)
    physics.step(plain, 200)
    np.testing.assert_allclose(s.pos, plain.pos, rtol=0, atol=1e-12)
    np.testing.assert_allclose(s.L0, plain.L0, rtol=0, atol=1e-12)
    assert not np.array_equal(s.L0, generic_copy(build.system(crystal_cfg((4, 3, 3), "start"))).L0)


def test_grid_must_match_the_springs():
    s = build.system(crystal_cfg((3, 3, 1), "none"))
    with pytest.raises(ValueError, match="grid"):
        physics.System(pos=s.pos, p=s.p, m=s.m, fixed=s.fixed, i=s.j, j=s.i, k=s.k, L0=s.L0,
                       g=s.g, dt=s.dt, grid=s.grid)


# ---- conservation ------------------------------------------------------------------------------

def test_momentum_is_conserved_in_a_free_crystal():
    s = build.system(crystal_cfg((6, 5, 4), "none", start={"temperature": 1e22, "seed": 5},
                    physics={"dt": 0.05}))
    s.p[0] += [0.3, -0.2, 0.1]                  # a moving crystal, not only a still one
    P0 = s.p.sum(axis=0).copy()
    scale = np.abs(s.p).sum()
    for _ in range(20):
        physics.step(s, 100)
        np.testing.assert_allclose(s.p.sum(axis=0), P0, rtol=0, atol=1e-13 * scale)
    assert np.abs(s.pos.mean(axis=0) - P0 / s.n_nodes * s.t).max() < 1e-10   # centre of mass


def test_energy_stays_bounded_with_euler_cromer():
    s = build.system(crystal_cfg((6, 6, 6), "outer", start={"temperature": 1e21, "seed": 2},
                    physics={"dt": 0.1}))
    E0 = physics.energies(s).E
    E = []
    for _ in range(400):
        physics.step(s, 10)
        E.append(physics.energies(s).E)
    E = np.array(E)
    assert np.abs(E - E0).max() < 0.06 * E0   # EC: off by O(omega dt), bounded, no drift...
    q = len(E) // 4
    assert abs(E[-q:].mean() - E[:q].mean()) < 0.002 * E0
    euler = build.system(crystal_cfg((6, 6, 6), "outer", start={"temperature": 1e21, "seed": 2},
                        physics={"dt": 0.1}))
    euler.integrator = "euler"          # (a config refuses this step for Euler)
    physics.step(euler, 200)
    assert physics.energies(euler).E > 1.5 * E0         # ...where plain Euler's energy grows


def test_no_allocation_growth_per_step():
    s = build.system(crystal_cfg((12, 12, 12), "outer", start={"temperature": 1e21, "seed": 2}))
    tracemalloc.start()
    try:
        physics.step(s, 20)
        before = tracemalloc.get_traced_memory()[0]
        physics.step(s, 300)
        after = tracemalloc.get_traced_memory()[0]
    finally:
        tracemalloc.stop()
    assert after - before < 4096


# ---- the video clock and simulate -----------------------------------------------------------

def test_frame_steps_follow_the_speed():
    steps = render.frame_steps(6e-12, 50, 2e-15, speed=1e-12)
    assert len(steps) == 300                             # a 6 s video
    np.testing.assert_array_equal(steps[:3], [0, 10, 20])
    assert steps[-1] == round(299 * 1e-12 / 50 / 2e-15)


def test_simulate_lattice_csv(tmp_path, cli):
    out = tmp_path / "chain.csv"
    proc = cli("simulate", CONFIGS / "chain.toml", "--duration", "1", "--out", out)
    assert proc.returncode == 0, proc.stderr
    rows = np.loadtxt(out, delimiter=",", skiprows=1)
    assert out.read_text().splitlines()[0] == ",".join(render.LATTICE_CSV_HEADER)
    assert len(rows) == 101
    assert rows[0, 1] == pytest.approx(0.10 * 0.5)       # the kick: m v along x
    E = rows[:, 6]
    assert np.abs(E - E[0]).max() < 0.1 * E[0]       # Euler-Cromer at omega_max dt = 0.24


# ---- bad input --------------------------------------------------------------------------------

LATTICE_BAD = [
    ({"ball": {"m": 1.0}}, "[ball] does not apply to a [lattice] config"),
    ({"lattice": {"spacing": None}}, "[lattice] needs exactly one of spacing"),
    ({"atom": {"molar_mass": 0.027}}, "[atom] needs exactly one of m"),
    ({"lattice": {"shape": [3, 3]}}, "[lattice] shape must be [N]"),
    ({"lattice": {"shape": [0]}}, "[lattice] shape must be > 0"),
    ({"lattice": {"shape": [1]}}, "[lattice] shape must have at least two atoms"),
    ({"lattice": {"fixed": "sides"}}, "[lattice] fixed must be one of"),
    ({"pull": {"force": 1.0}}, "[pull] force needs [lattice] fixed = \"start\""),
    ({"lattice": {"shape": [2]}}, "holds every atom"),
    ({"physics": {"dt": 1.5}}, "[physics] dt: dt = 1.5 s is unstable"),
    ({"render": {"speed": 0}}, "[render] speed must be > 0"),
    ({"bond": {"style": "zigzag"}}, "[bond] style must be one of"),
    ({"bond": {"coils": 1e7}}, "[bond] coils must be at most 50"),
    ({"camera": {"forward": [0, 1, 0], "up": [0, 2, 0]}}, "[camera] up must not be parallel"),
    ({"start": {"temperature": 10.0}}, "[start] takes a kick or a temperature, not both"),
    ({"atom": {"m": 1e-300}}, "[atom] m must be between 1e-30 and 1e6 kg, got 1e-300"),
]


@pytest.mark.parametrize("change, message", LATTICE_BAD)
def test_bad_lattice_config(change, message):
    data = {"lattice": {"shape": [6], "spacing": 1.0, "fixed": "ends"},
            "bond": {"k": 1.0}, "atom": {"m": 1.0}, "start": {"kick": [0.1, 0, 0]},
            "physics": {"dt": 0.05}}
    for section, table in change.items():
        data.setdefault(section, {}).update(table)
        data[section] = {k: v for k, v in data[section].items() if v is not None}
    with pytest.raises(UserError) as err:
        config.from_dict(data, source="x.toml")
    assert message in str(err.value) and "\n" not in str(err.value)
    assert str(err.value).startswith("x.toml")


def test_lattice_sections_need_a_lattice():
    with pytest.raises(UserError, match=r"\[atom\] needs a \[lattice\] section"):
        config.from_dict({"atom": {"m": 1.0}}, source="x.toml")
    with pytest.raises(UserError, match="color_by"):
        config.from_dict({"render": {"color_by": "speed"}}, source="x.toml")


def test_bad_speed_flag(tmp_path, cli):
    out = tmp_path / "v.mp4"
    proc = cli("render", CONFIGS / "chain.toml", "--speed", "-1", "--out", out)
    assert proc.returncode == 2
    assert proc.stderr.strip().count("\n") == 0 and "--speed must be > 0" in proc.stderr
    assert not out.exists()


def test_uniform_mass_check():
    assert math.isclose(lattice.spacing_from_density(2.7e-3, 2700.0), 1e-2, rel_tol=1e-12)
