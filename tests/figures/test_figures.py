"""The wiki figures: each plot against a committed baseline, their physics, the whole
`figures` command end to end (once, --draft), and bad --out input.

Baselines are the plots as :func:`springscene.figures.figure_image` draws them, compared
with ``imagecompare.check`` (a pixel counts as off when a channel differs by more than
24/255; at most 0.05 % of pixels may be off and the mean difference at most 0.2).
matplotlib is pinned and its style fixed, so the same data draw the same pixels; a
moved line, a changed label or a changed colour fails. Regenerate with
``pytest tests/test_figures.py --regen-baselines``.
"""

from __future__ import annotations

import xml.etree.ElementTree as ET
from fractions import Fraction

import imageio.v3 as iio
import numpy as np
import pytest

from conftest import BASELINES, ROOT, WIKI, run_cli
from imagecompare import check
from springscene import config, render
from springscene.figures import gallery, media, notation, oscillator, plots
from springscene.figures.files import save_figure
from springscene.science import sweep, theory
from springscene.view.plotstyle import figure_image

FIGS = BASELINES / "figures"


@pytest.fixture(scope="module")
def traj(wiki_cfg):
    return render.simulate(wiki_cfg)


@pytest.fixture(scope="module")
def runs(wiki_cfg):
    return oscillator.integrator_runs(wiki_cfg)


@pytest.fixture(scope="module")
def damped(wiki_cfg):
    dcfg, demo = oscillator.demo_damped(wiki_cfg)
    return dcfg, demo, render.simulate(dcfg)


@pytest.fixture(scope="module")
def resonance(wiki_cfg):
    rcfg, added = oscillator.demo_driven(wiki_cfg)
    return rcfg, added, sweep.sweep(rcfg, oscillator.sweep_omegas(rcfg, 60), periods=30)


@pytest.fixture(scope="module")
def hooke():
    hcfg = oscillator.hooke_config(config.load(WIKI))
    return hcfg, render.simulate(hcfg)


# ---- each figure against its baseline ----------------------------------------------------

def test_position_figure(wiki_cfg, traj, regen):
    fig = plots.position_figure(wiki_cfg, traj, measured_period=0.5127)
    img = figure_image(fig)
    assert img.shape == (560, 800, 3)
    check(img, FIGS / "position.png", regen)


def test_energy_figure(wiki_cfg, traj, regen):
    img = figure_image(plots.energy_figure(wiki_cfg, traj))
    assert img.shape == (600, 800, 3)
    check(img, FIGS / "energy.png", regen)


def test_phase_figure(wiki_cfg, traj, damped, regen):
    dcfg, _, dtraj = damped
    img = figure_image(plots.phase_figure(wiki_cfg, traj, damped=(dcfg, dtraj)))
    check(img, FIGS / "phase.png", regen)


def test_damped_figure(damped, regen):
    dcfg, demo, dtraj = damped
    img = figure_image(plots.damped_figure(dcfg, dtraj, demo=demo, measured_rate=0.5))
    check(img, FIGS / "damped.png", regen)


def test_resonance_figure(resonance, regen):
    _, added, res = resonance
    img = figure_image(plots.resonance_figure(res, demo="demo " + " and ".join(added)))
    check(img, FIGS / "resonance.png", regen)


def test_integrators_figure(wiki_cfg, runs, regen):
    img = figure_image(plots.integrators_figure(wiki_cfg, runs))
    check(img, FIGS / "integrators.png", regen)


def test_hooke_figure(hooke, regen):
    hcfg, htraj = hooke
    img = figure_image(plots.hooke_figure(hcfg, htraj))
    assert img.shape == (780, 800, 3)
    check(img, FIGS / "hooke.png", regen)


def test_baseline_tolerance_catches_data_off_by_two_percent(resonance):
    """The stated tolerance is tight enough for plots: 2 % more amplitude fails it.
    (One changed digit in a title is below it: captions' numbers are tested as text.)"""
    import copy

    from imagecompare import MAX_BAD_FRACTION, MAX_MEAN_DIFF, compare

    _, added, res = resonance
    off = copy.copy(res)
    off.amplitude = res.amplitude * 1.02
    img = figure_image(plots.resonance_figure(off, demo="demo " + " and ".join(added)))
    bad, mean = compare(img, iio.imread(FIGS / "resonance.png")[..., :3])
    assert bad > MAX_BAD_FRACTION or mean > MAX_MEAN_DIFF


def test_filmstrip_figure_lays_tiles_side_by_side():
    tile = np.full((300, 110, 3), 255, np.uint8)
    tile[200:240, 35:75] = (255, 0, 0)                         # a "ball" below the line
    strip = media.Filmstrip([tile] * 6, [0.0, 0.09, 0.17, 0.26, 0.34, 0.43], 0.513, 150,
                            [media._fraction_label(Fraction(c, 6)) for c in range(6)])
    img = figure_image(media.filmstrip_figure(strip, gap=8))
    assert img.shape == (300 + 8 + 64, 6 * 110 + 7 * 8, 3)
    body = img[64:]
    assert (body[220, 8 + 55] == (255, 0, 0)).all()           # tiles at their own pixels
    assert (body[220, 8 + 118 + 55] == (255, 0, 0)).all()
    line = body[150, 8:118]
    assert (line == 120).all(axis=1).sum() > 40                 # the dashed equilibrium line
    assert strip.labels == ["0", "T/6", "T/3", "T/2", "2T/3", "5T/6"]


# ---- determinism --------------------------------------------------------------------------

def test_saved_figures_are_the_same_bytes_every_time(tmp_path, wiki_cfg, traj):
    first = save_figure(plots.energy_figure(wiki_cfg, traj), tmp_path, "a")
    second = save_figure(plots.energy_figure(wiki_cfg, traj), tmp_path, "b")
    for p, q in zip(first, second):
        assert p.read_bytes() == q.read_bytes(), p.name
    svg = first[1].read_text()
    assert "<dc:date>" not in svg and "Matplotlib v" not in svg
    # the PNG is exactly what figure_image (the baselines) sees
    png = iio.imread(first[0])[..., :3]
    assert np.array_equal(png, figure_image(plots.energy_figure(wiki_cfg, traj)))


def test_style_ignores_the_users_matplotlibrc(wiki_cfg, traj):
    import matplotlib

    base = figure_image(plots.phase_figure(wiki_cfg, traj))
    with matplotlib.rc_context({"font.size": 30, "axes.facecolor": "black", "lines.linewidth": 9}):
        again = figure_image(plots.phase_figure(wiki_cfg, traj))
    assert np.array_equal(base, again)


# ---- the physics in the figures -----------------------------------------------------------

def test_position_residual_small_against_amplitude(wiki_cfg, traj):
    A = theory.Oscillator.from_config(wiki_cfg).amplitude
    resid = np.abs(oscillator.position_residual(wiki_cfg, traj))
    T = oscillator.period_of(wiki_cfg)
    first = resid[traj.t <= T].max()
    assert first < 0.08 * A                  # Euler-Cromer's half-step phase offset
    assert resid.max() < 0.15 * A            # plus a drift of 0.06 % a period, over 10 s
    assert resid[traj.t > traj.t[-1] - T].max() > first     # the drift grows
    # with RK4 the simulation is the closed form to 10 micrometres (0.05 % of A)
    rk4 = config.override(wiki_cfg, "physics", integrator="rk4")
    assert np.abs(oscillator.position_residual(rk4, render.simulate(rk4))).max() < 5e-4 * A


@pytest.mark.parametrize("name", ["driven.toml", "damped.toml"])
def test_closed_form_matches_rk4_for_damped_and_driven_configs(name):
    cfg = config.override(config.load(ROOT / "configs" / name), "physics", integrator="rk4",
                          dt=0.001)
    traj = render.simulate(cfg, 5.0)
    y, v = oscillator.along(cfg, traj)
    osc = theory.Oscillator.from_config(cfg)
    x, vx = oscillator.closed_form(cfg, traj.t)
    scale = max(np.abs(x).max(), 1e-3)
    assert np.abs(y - np.dot(osc.equilibrium, osc.axis) - x).max() < 1e-5 * scale
    assert np.abs(v - vx).max() < 1e-5 * scale * osc.omega0


def test_resonance_peak_near_omega0(resonance):
    _, added, res = resonance
    assert added == ["damping", "drive"]
    wp, ap = res.peak
    wr, ar = res.theory_peak
    spacing = res.omega[1] - res.omega[0]
    assert abs(wp - wr) <= spacing and abs(wp - res.omega0) <= 2 * spacing
    assert ap == pytest.approx(ar, rel=0.03)
    assert np.median(np.abs(res.amplitude - res.theory) / res.theory) < 0.02


def test_integrators_energy_error(wiki_cfg, runs):
    scale = oscillator.oscillation_energy(wiki_cfg)
    T = oscillator.period_of(wiki_cfg)
    peaks = {n: oscillator.per_period_max(r.t, oscillator.energy_error(r, scale), T)[1]
             for n, r in runs.items()}
    euler = peaks["euler"]
    assert np.all(np.diff(euler) > 0) and euler[-1] > 1e3 * euler[0]     # grows every period
    ec = peaks["euler-cromer"]
    assert ec.max() < 0.1 and ec[-1] < 1.05 * ec[0]                       # bounded
    assert peaks["verlet"].max() < ec.max() / 10
    assert peaks["rk4"].max() < peaks["verlet"].max() / 10


def test_damped_demo_decays_at_gamma(wiki_cfg, damped):
    dcfg, demo, dtraj = damped
    assert demo and dcfg.damping.b == oscillator.DEMO_B and not dcfg.driven
    from springscene.science.analysis import peak_decay_rate

    osc = theory.Oscillator.from_config(dcfg)
    y, _ = oscillator.along(dcfg, dtraj)
    rate = peak_decay_rate(dtraj.t, y - np.dot(osc.equilibrium, osc.axis))
    assert rate == pytest.approx(osc.gamma, rel=0.01)
    # the envelope really bounds the motion (to the integrator's error)
    assert np.all(np.abs(y - np.dot(osc.equilibrium, osc.axis)) <= osc.envelope(dtraj.t) * 1.03)


def test_a_config_with_its_own_damping_and_drive_is_used_as_is():
    driven = config.load(ROOT / "configs" / "driven.toml")
    cfg, added = oscillator.demo_driven(driven)
    assert added == [] and cfg == driven
    dcfg, demo = oscillator.demo_damped(driven)
    assert not demo and not dcfg.driven and dcfg.damping.b == driven.damping.b


def test_hooke_permanent_set(hooke, wiki_cfg):
    hcfg, htraj = hooke
    assert hcfg.source.endswith("overstretched.toml")
    assert htraj.L0[-1] > htraj.L0[0] + 0.01                    # a permanent set
    y, _ = oscillator.along(hcfg, htraj)
    osc = theory.Oscillator.from_config(hcfg)
    y_after = -(htraj.L0[-1] + osc.equilibrium_stretch)
    assert abs(y[htraj.t > htraj.t[-1] - 1].mean() - y_after) < 0.003
    # a user's own elastic limit is used instead
    own = config.override(wiki_cfg, "spring", yield_stretch=0.09)
    assert oscillator.hooke_config(own) is own


def test_gallery_snippet():
    text = gallery.gallery([("a.png", "first | caption"), ("b.gif", "second")], ["a.svg"])
    lines = text.splitlines()
    assert lines[2].startswith("<gallery") and lines[-1] == "</gallery>"
    assert "File:a.png|first / caption" in lines      # a pipe would end the caption
    assert "a.svg" in text


def test_error_format():
    assert notation._fmt_err(6.8e5) == "6.8×10⁵"
    assert notation._fmt_err(3.7e-3) == "3.7×10⁻³"
    assert notation._fmt_err(0.065) == "0.065"


# ---- the command end to end ---------------------------------------------------------------

PLOTS = ("position", "energy", "phase", "damped", "resonance", "integrators", "hooke")
SIZES = {"scene.png": (600, 900), "position.png": (560, 800), "energy.png": (600, 800),
         "phase.png": (560, 800), "damped.png": (500, 800), "resonance.png": (500, 800),
         "integrators.png": (520, 800), "hooke.png": (780, 800)}


def test_figures_command_end_to_end(tmp_path):
    out = tmp_path / "new" / "wiki"                  # created, parents too
    proc = run_cli("figures", WIKI, "--out", out, "--draft", check=True)
    listed = [line.removeprefix("wrote ") for line in proc.stdout.splitlines()]
    names = sorted(p.split("/")[-1] for p in listed)
    expected = sorted(["scene.png", "filmstrip.png", "oscillation.gif", "figures.wiki"]
                      + [f"{p}.{ext}" for p in PLOTS for ext in ("png", "svg")])
    assert names == expected
    assert sorted(p.name for p in out.iterdir()) == expected        # no temporary files left
    for name, (h, w) in SIZES.items():
        assert iio.imread(out / name).shape[:2] == (h, w), name
    strip = iio.imread(out / "filmstrip.png")
    assert strip.shape[1] <= 800 and strip.shape[0] > 300
    for p in PLOTS:
        root = ET.parse(out / f"{p}.svg").getroot()
        assert root.tag.endswith("svg") and root.get("width") == "576pt"   # 800 px at 100 dpi
    gif = out / "oscillation.gif"
    assert gif.stat().st_size < media.GIF_MAX_BYTES
    frames = iio.imread(gif, index=None)
    meta = iio.immeta(gif, index=0)
    assert frames.shape[1:] == (300, 450, 3) and len(frames) >= 20
    assert meta.get("loop") == 0 and meta["duration"] == 40
    wiki = (out / "figures.wiki").read_text()
    entries = dict(line.removeprefix("File:").split("|", 1) for line in wiki.splitlines()
                   if line.startswith("File:"))
    on_disk = {n for n in expected if n.endswith((".png", ".gif"))}
    assert set(entries) == on_disk
    for name, caption in entries.items():
        assert len(caption) > 60, name
    assert "k = 15 N/m" in entries["position.png"] and "dt = 0.01 s" in entries["position.png"]
    assert "Euler-Cromer" in entries["position.png"] and "0.51302 s" in entries["position.png"]
    assert "demo damping b = 0.1 kg/s" in entries["damped.png"]
    assert "demo damping b = 0.1 kg/s and a driven support" in entries["resonance.png"]
    for p in PLOTS:
        assert f"{p}.svg" in wiki


@pytest.mark.parametrize("make_bad", ["file", "under_a_file"])
def test_bad_out_is_one_line_exit_2(tmp_path, cli, make_bad):
    afile = tmp_path / "figures.txt"
    afile.write_text("not a folder")
    out = afile if make_bad == "file" else afile / "sub"
    proc = cli("figures", WIKI, "--out", out)
    assert proc.returncode == 2
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and "--out" in lines[0] and "Traceback" not in proc.stderr
    assert afile.read_text() == "not a folder"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["figures.txt"]
