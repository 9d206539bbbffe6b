"""The physics of the page beyond the free spring: damping, driving, resonance, Hooke's
limits, integrators, stability, and `analyze` / `sweep` against closed forms."""

from __future__ import annotations

import csv
import json
import math

import numpy as np
import pytest

from conftest import ROOT, WIKI
from springscene import build, config
from springscene.model import integrators, physics
from springscene.science import analysis, sweep, theory
from springscene.errors import UserError

DAMPED = ROOT / "configs" / "damped.toml"
DRIVEN = ROOT / "configs" / "driven.toml"
OVER = ROOT / "configs" / "overstretched.toml"
INTEGRATORS = ("euler", "euler-cromer", "verlet", "rk4")


@pytest.fixture(scope="module")
def wiki():
    return config.load(WIKI)


def with_(cfg, **sections):
    for section, values in sections.items():
        cfg = config.override(cfg, section, **values)
    return cfg


def displacement(cfg, n_steps):
    """Simulated displacement from equilibrium along the line of motion, and the closed form."""
    osc = theory.Oscillator.from_config(cfg)
    traj = physics.run(build.system(cfg), n_steps)
    x = (traj.pos - np.asarray(osc.equilibrium)) @ np.asarray(osc.axis)
    return traj, x, osc.x(traj.t), osc


# ---- integrators -------------------------------------------------------------------------

@pytest.mark.parametrize("name, order", integrators.ORDER.items())
def test_measured_global_order(wiki, name, order):
    """Position error at t = 1 s against the closed form falls as dt^order."""
    dts = np.array([0.004, 0.002, 0.001])
    errors = []
    for dt in dts:
        cfg = with_(wiki, physics=dict(integrator=name, dt=float(dt)))
        s = physics.step(build.system(cfg), int(round(1.0 / dt)))
        osc = theory.Oscillator.from_config(cfg)
        errors.append(abs((s.pos[1] - osc.equilibrium) @ np.asarray(osc.axis) - osc.x(1.0)))
    slope = np.polyfit(np.log(dts), np.log(errors), 1)[0]
    assert slope == pytest.approx(order, abs=0.15)


def test_energy_behaviour_of_each_integrator(wiki):
    """Euler's energy grows every period; Euler-Cromer's and Verlet's stay bounded; RK4's
    drifts down too slowly to see at dt = 0.01."""
    T = 2 * math.pi * math.sqrt(0.1 / 15)
    n = int(round(20 * T / 0.01))
    osc_energy = 0.5 * 15 * 0.02 ** 2
    drift = {}
    for name in INTEGRATORS:
        traj = physics.run(build.system(with_(wiki, physics=dict(integrator=name))), n)
        per = int(round(T / 0.01))
        first, last = traj.E[:per].mean(), traj.E[-per:].mean()
        drift[name] = (last - first) / osc_energy
        if name == "euler":
            peaks = [traj.E[i * per:(i + 1) * per].max() for i in range(n // per)]
            assert np.all(np.diff(peaks) > 0)          # grows, period after period
    assert drift["euler"] > 100                       # e^(pi omega dt) per period, 20 periods
    assert abs(drift["euler-cromer"]) < 0.01
    assert abs(drift["verlet"]) < 0.01
    assert abs(drift["rk4"]) < 0.01


def test_amplification_is_the_integrators_own_map():
    """The stability analysis uses the integrators' code: for Euler-Cromer without drag
    the one-step map on (x, v) is [[1 - w^2 h^2, h], [-w^2 h, 1]]."""
    w, h = 12.0, 0.01
    A = integrators.amplification("euler-cromer", w, 0.0, h)
    assert np.allclose(A, [[1 - w * w * h * h, h], [-w * w * h, 1]], rtol=0, atol=1e-15)
    for name, limit in (("euler-cromer", 2.0), ("verlet", 2.0), ("rk4", 2 * math.sqrt(2))):
        assert integrators.stable(name, w, 0.0, 0.99 * limit / w)
        assert not integrators.stable(name, w, 0.0, 1.01 * limit / w)


@pytest.mark.parametrize("args, words", [
    (("--dt", "0.2"), ["--dt", "unstable for euler-cromer", "omega*dt = 2.45", "use dt <= 0.05 s"]),
    (("--integrator", "verlet", "--dt", "0.17"), ["unstable for verlet", "use dt <="]),
    (("--integrator", "euler", "--dt", "0.05"), ["unstable for euler", "per period"]),
])
def test_unstable_step_is_refused(tmp_path, cli, args, words):
    out = tmp_path / "t.csv"
    proc = cli("simulate", WIKI, "--duration", "1", "--out", out, *args)
    assert proc.returncode == 2 and not out.exists()
    line, = proc.stderr.strip().splitlines()
    for w in words:
        assert w in line


def test_unstable_step_in_a_file_names_the_key(tmp_path, cli):
    bad = tmp_path / "bad.toml"
    bad.write_text("[physics]\ndt = 0.3\n")
    proc = cli("analyze", bad)
    assert proc.returncode == 2
    assert f"{bad}: [physics] dt: dt = 0.3 s is unstable" in proc.stderr
    bad.write_text('[physics]\ndt = 0.2\nintegrator = "rk4"\n')   # RK4 is stable there...
    assert cli("simulate", bad, "--duration", "2", "--out", tmp_path / "t.csv").returncode == 0
    proc = cli("analyze", bad, "--duration", "2")   # ...but 2.6 steps a period measure nothing
    assert proc.returncode == 2 and "gives 2.57 steps a period" in proc.stderr


# ---- damping -------------------------------------------------------------------------------

@pytest.mark.parametrize("b, regime", [(0.1, "under-damped"), (2 * math.sqrt(15 * 0.1), "critically damped"),
                                       (5.0, "over-damped")])
def test_damped_motion_matches_closed_form(wiki, b, regime):
    """x(t) = A e^(-gamma t) cos(omega_d t + phi) (and the critical / over-damped forms):
    RK4 to 5e-5 of the amplitude over 4 s; Euler-Cromer (first order: a phase error of
    about omega dt / 2) within 8 %, halving with dt."""
    errs = []
    for dt in (0.01, 0.005):
        cfg = with_(wiki, damping=dict(b=b), physics=dict(dt=dt))
        _, x, exact, osc = displacement(cfg, int(round(4 / dt)))
        assert osc.regime == regime
        errs.append(np.abs(x - exact).max() / 0.02)
    assert errs[0] < 0.08
    assert errs[1] == pytest.approx(errs[0] / 2, rel=0.2)
    _, x, exact, _ = displacement(with_(wiki, damping=dict(b=b), physics=dict(integrator="rk4")),
                                  400)
    assert np.abs(x - exact).max() < 5e-5 * 0.02


def test_damped_gamma_and_omega_d(wiki):
    osc = theory.Oscillator.from_config(with_(wiki, damping=dict(b=0.1)))
    assert osc.gamma == pytest.approx(0.5)
    assert osc.omega_d == pytest.approx(math.sqrt(150 - 0.25))
    assert osc.envelope(2.0) == pytest.approx(math.hypot(-0.02, -0.5 * 0.02 / osc.omega_d)
                                              * math.exp(-1.0))


@pytest.mark.parametrize("name", ["euler", "euler-cromer", "verlet"])
def test_drag_bookkeeping_to_round_off(name):
    """With drag alone, every joule of kinetic energy lost is in E_thermal, to round-off."""
    s = physics.System(pos=[[0, 0, 0]], p=[[0.3, -0.2, 0.1]], m=0.1, fixed=False, i=[], j=[],
                       k=[], L0=[], g=(0, 0, 0), dt=0.01, b=0.4, integrator=name)
    e0 = physics.energies(s).total
    physics.step(s, 500)
    e = physics.energies(s)
    assert e.E_thermal > 0.99 * e0
    assert e.total == pytest.approx(e0, rel=1e-13)


def test_damped_energy_bookkeeping_with_spring(wiki):
    """K + Us + Ug + E_thermal stays within Euler-Cromer's own bounded wobble (the same
    as without drag, shrinking with dt), while E_thermal takes the oscillation's energy."""
    osc_energy = 0.5 * 15 * 0.02 ** 2
    for dt in (0.01, 0.001):
        cfg = with_(wiki, damping=dict(b=0.1), physics=dict(dt=dt))
        traj = physics.run(build.system(cfg), int(round(10 / dt)))
        free = physics.run(build.system(with_(wiki, physics=dict(dt=dt))), int(round(10 / dt)))
        wobble = np.abs(traj.total - traj.total[0]).max()
        assert wobble <= 1.05 * np.abs(free.E - free.E[0]).max()
        assert wobble < 20 * dt * osc_energy
        assert traj.E_thermal[-1] == pytest.approx(osc_energy * (1 - math.exp(-10)), rel=0.01)
    assert np.all(np.diff(traj.E_thermal) >= 0)          # heat is never given back


def test_overdamped_is_stable_with_any_drag(wiki):
    """Euler-Cromer's drag acts on the mean momentum, so drag alone cannot blow up."""
    cfg = with_(wiki, damping=dict(b=200.0))             # b dt / m = 20
    traj = physics.run(build.system(cfg), 500)
    assert np.all(np.isfinite(traj.pos))
    assert abs(traj.pos[-1, 1] - theory.Oscillator.from_config(cfg).equilibrium[1]) < 0.02


# ---- driving and resonance -----------------------------------------------------------------

@pytest.mark.parametrize("kind, amplitude", [("force", 0.03), ("support", 0.002)])
def test_driven_steady_state(wiki, kind, amplitude):
    cfg = with_(wiki, damping=dict(b=0.1),
                drive=dict(type=kind, amplitude=amplitude, omega=10.0),
                ball=dict(pos=(0, -(0.1 + 0.98 / 15), 0)), physics=dict(integrator="rk4"))
    traj, x, _, osc = displacement(cfg, 2500)                      # 25 s; e^(-0.5*15) settled
    steady = x[1500:]
    F0 = theory.drive_force_amplitude(cfg)
    A = theory.steady_amplitude(10.0, osc.omega0, osc.gamma, F0, 0.1)
    assert (steady.max() - steady.min()) / 2 == pytest.approx(A, rel=0.002)


def test_sweep_is_one_batch_equal_to_single_runs(wiki):
    """Copy c of the batched sweep system moves bit for bit like a run driven at omega[c]."""
    cfg = config.load(DRIVEN)
    omega = np.array([8.0, 11.5, 12.2, 15.0])
    batch = physics.step(build.system(cfg, omega=omega), 300)
    for c, w in enumerate(omega):
        single = physics.step(build.system(with_(cfg, drive=dict(omega=float(w)))), 300)
        assert np.array_equal(batch.pos[2 * c:2 * c + 2], single.pos)
        assert np.array_equal(batch.p[2 * c:2 * c + 2], single.p)


def test_sweep_against_analytic_curve():
    cfg = config.load(DRIVEN)
    result = sweep.sweep(cfg, np.linspace(6, 18, 60), periods=100)
    err = np.abs(result.amplitude - result.theory) / result.theory
    assert err.max() < 0.015
    wp, ap = result.peak
    wt, at = result.theory_peak
    assert abs(wp - wt) < 0.25 and ap == pytest.approx(at, rel=0.02)
    assert ap > 5 * result.amplitude[0]                    # a real resonance, Q = 12


def test_sweep_cli_writes_curve(tmp_path, cli):
    out = tmp_path / "curve.csv"
    proc = cli("sweep", DRIVEN, "--omega", "10:14:5", "--periods", "60", "--out", out,
                   check=True)
    assert "peak: measured" in proc.stdout
    rows = list(csv.reader(open(out)))
    assert rows[0] == ["omega [rad/s]", "frequency [Hz]", "amplitude [m]", "theory [m]"]
    data = np.array(rows[1:], dtype=float)
    assert np.allclose(data[:, 0], [10, 11, 12, 13, 14])
    assert np.allclose(data[:, 2], data[:, 3], rtol=0.02)


# ---- Hooke's limits ----------------------------------------------------------------------

def test_stiffening_force_law():
    s = physics.System(pos=[[0, 0, 0], [0, -0.15, 0]], p=np.zeros((2, 3)), m=[1, 0.1], fixed=[True, False],
                       i=[0], j=[1], k=15.0, L0=0.1, k3=2000.0, g=(0, 0, 0), dt=0.01)
    stretch = 0.05
    assert physics.net_forces(s)[1, 1] == pytest.approx(15 * stretch + 2000 * stretch ** 3)
    assert physics.energies(s).Us == pytest.approx(0.5 * 15 * stretch ** 2
                                                   + 0.25 * 2000 * stretch ** 4)


def test_stiffening_shortens_the_period_with_amplitude(wiki):
    periods = []
    for dy in (0.005, 0.04):
        cfg = with_(wiki, spring=dict(k3=3000.0), ball=dict(pos=(0, -(0.1 + 0.98 / 15 + dy), 0)))
        traj = physics.run(build.system(cfg), 1000)
        y = traj.pos[:, 1]
        periods.append(analysis.period_from_crossings(traj.t, y - (y.max() + y.min()) / 2))
    assert periods[1] < 0.99 * periods[0]   # a stiffer spring at larger stretch


@pytest.mark.parametrize("name", ["euler-cromer", "rk4"])
def test_permanent_set_beyond_elastic_limit(name):
    cfg = with_(config.load(OVER), physics=dict(integrator=name))
    result = analysis.analyze(cfg)
    m, t = result["measured"], result["theory"]
    assert m["permanent_set"] == pytest.approx(t["permanent_set"], rel=0.01)
    assert m["permanent_set"] > 0.05
    # afterwards it oscillates about the new equilibrium, mg/k below the new L0
    assert m["equilibrium_stretch"] == pytest.approx(0.98 / 15, rel=0.001)
    assert m["amplitude"] == pytest.approx(t["amplitude"], rel=0.01)
    traj = physics.run(build.system(cfg), 1000)
    assert traj.L0[-1] == pytest.approx(0.1 + m["permanent_set"], rel=1e-9)
    assert np.all(np.diff(traj.L0) >= 0)
    # the work of the set went to heat: the total is kept within the integrator's error
    kick = 0.5 * 0.1 * 1.0 ** 2                            # the 1 m/s kick's energy, 0.05 J
    assert abs(traj.total[-1] - traj.total[0]) < 0.005 * kick   # no leak, beyond the wobble
    if name == "rk4":
        assert np.abs(traj.total - traj.total[0]).max() < 0.001 * kick
    assert traj.E_thermal[-1] > 0.5 * kick                   # most of it went into the set


def test_below_the_limit_nothing_yields(wiki):
    cfg = with_(wiki, spring=dict(yield_stretch=0.2))
    traj = physics.run(build.system(cfg), 500)
    assert np.all(traj.L0 == 0.1) and np.all(traj.E_thermal == 0)
    ref = physics.run(build.system(wiki), 500)
    assert np.array_equal(traj.pos, ref.pos)             # Hooke's law untouched below it


# ---- analyze -----------------------------------------------------------------------------

def test_analyze_wiki_against_theory(wiki):
    r = analysis.analyze(wiki)
    m, t = r["measured"], r["theory"]
    assert set(m) == set(t) == set(analysis.KEYS)
    assert m["period"] == pytest.approx(2 * math.pi * math.sqrt(0.1 / 15), rel=0.003)
    assert t["period"] == pytest.approx(2 * math.pi * math.sqrt(0.1 / 15), rel=1e-12)
    assert t["equilibrium_stretch"] == pytest.approx(0.1 * 9.8 / 15)
    assert m["equilibrium_stretch"] == pytest.approx(t["equilibrium_stretch"], rel=1e-4)
    for key in ("amplitude", "max_speed", "max_acceleration", "energy", "frequency"):
        assert m[key] == pytest.approx(t[key], rel=0.005), key
    assert t["max_speed"] == pytest.approx(0.02 * math.sqrt(150))
    assert t["energy"] == pytest.approx(0.5 * 15 * 0.02 ** 2)


def test_analyze_json_cli_damped(cli):
    proc = cli("analyze", DAMPED, "--json", check=True)
    r = json.loads(proc.stdout)
    assert set(r["measured"]) == set(analysis.KEYS + analysis.DAMPED_KEYS)
    assert r["regime"] == "under-damped"
    m, t = r["measured"], r["theory"]
    assert t["damping_rate"] == pytest.approx(0.5)
    assert m["damping_rate"] == pytest.approx(0.5, rel=0.01)
    assert m["period"] == pytest.approx(t["period"], rel=0.003)
    assert m["energy_lost"] == pytest.approx(t["energy_lost"], rel=0.01)


def test_analyze_table_cli(cli):
    proc = cli("analyze", DRIVEN, check=True)
    assert "driven" in proc.stdout and "period" in proc.stdout and "%" in proc.stdout


# ---- bad parameters ------------------------------------------------------------------------

@pytest.mark.parametrize("toml, words", [
    ("[damping]\nb = -0.1\n", "[damping] b must be >= 0"),
    ('[drive]\ntype = "support"\namplitude = 0.01\nomega = 0\n', "[drive] omega must be > 0"),
    ('[drive]\ntype = "support"\namplitude = 0.01\nomega = -3\n', "[drive] omega must be > 0"),
    ('[drive]\ntype = "support"\namplitude = 0.01\n', "[drive] omega is required"),
    ('[drive]\ntype = "shake"\n', "[drive] type must be one of"),
    ('[physics]\nintegrator = "leapfrog"\n', "[physics] integrator must be one of"),
    ("[spring]\nyield_stretch = 0\n", "[spring] yield_stretch must be > 0"),
    ("[spring]\nk3 = -5\n", "[spring] k3 must be >= 0"),
])
def test_bad_physics_keys_refused(tmp_path, cli, toml, words):
    bad = tmp_path / "bad.toml"
    bad.write_text(toml)
    proc = cli("analyze", bad)
    assert proc.returncode == 2, proc.stderr
    line, = proc.stderr.strip().splitlines()
    assert str(bad) in line and words in line


@pytest.mark.parametrize("omega, words", [
    ("6:18:0", "empty sweep"), ("6:18", "expected START:STOP:N"), ("0:18:10", "must be > 0"),
    ("18:6:10", "STOP must not be below START"), ("a:b:c", "must be numbers"),
])
def test_bad_sweeps_refused(tmp_path, cli, omega, words):
    out = tmp_path / "c.csv"
    proc = cli("sweep", DRIVEN, "--omega", omega, "--out", out)
    assert proc.returncode == 2 and not out.exists()
    line, = proc.stderr.strip().splitlines()
    assert "--omega" in line and words in line


def test_sweep_needs_drive_and_damping(tmp_path, cli):
    proc = cli("sweep", WIKI, "--omega", "6:18:10")
    assert proc.returncode == 2 and "needs a [drive] section" in proc.stderr
    with pytest.raises(UserError, match=r"\[damping\] b > 0"):
        sweep.check_sweepable(config.override(config.load(DRIVEN), "damping", b=0.0))


@pytest.mark.parametrize("config_path, duration, words", [
    (WIKI, "0.3", "--duration 0.3 s is too short to analyze: it needs at least 1.28 s"),
    (DRIVEN, "5", "--duration 5 s is too short to analyze"),
    (WIKI, "-1", "--duration must be >= 0"),
])
def test_analyze_refuses_too_short_runs(cli, config_path, duration, words):
    proc = cli("analyze", config_path, "--duration", duration)
    assert proc.returncode == 2
    line, = proc.stderr.strip().splitlines()
    assert words in line


@pytest.mark.parametrize("toml, command, words", [
    ("[spring]\nk3 = 1e9\n", "simulate", "the simulation blew up by t ="),
    ("[spring]\nyield_stretch = 0.01\n", "analyze", "[spring] yield_stretch 0.01 m is not above"),
    ('[damping]\nb = 0.1\n[drive]\ntype = "force"\namplitude = 0.01\nomega = 10\n'
     "direction = [1, 0, 0]\n", "analyze", "[drive] direction [1.0, 0.0, 0.0] is not along"),
    ('[drive]\ntype = "force"\namplitude = 0.01\nomega = 10\n', "analyze",
     "analyze needs [damping] b > 0 with a drive"),
    ('[damping]\nb = 0.1\n[drive]\ntype = "force"\namplitude = 0.01\nomega = 628\n', "analyze",
     "[drive] omega: a drive at 628 rad/s needs dt <="),
])
def test_physics_that_cannot_be_measured_is_refused(tmp_path, cli, toml, command, words):
    bad = tmp_path / "bad.toml"
    bad.write_text(toml)
    out = tmp_path / "t.csv"
    args = ("--out", out) if command == "simulate" else ()
    proc = cli(command, bad, *args)
    assert proc.returncode == 2 and not out.exists()
    line, = proc.stderr.strip().splitlines()
    assert words in line


def test_sweep_refuses_drives_faster_than_the_step(cli):
    proc = cli("sweep", DRIVEN, "--omega", "1e6:1e7:3")
    assert proc.returncode == 2
    assert "--omega: a drive at 1e+07 rad/s needs dt <=" in proc.stderr


def test_driven_analyze_measures_gamma_in_the_steady_state():
    """Long after the transient, gamma comes from the heat the drag made (b <v^2>)."""
    r = analysis.analyze(with_(config.load(DRIVEN), physics=dict(integrator="rk4")), 120.0)
    assert r["measured"]["damping_rate"] == pytest.approx(0.5, rel=1e-3)
    assert r["measured"]["energy"] == pytest.approx(r["theory"]["energy"], rel=0.005)
    assert r["measured"]["amplitude"] == pytest.approx(r["theory"]["amplitude"], rel=0.002)
