"""For readers of the videos, tables and files: energy bars about equilibrium (the K <-> U
exchange shows), a clock in the lattice videos by default (in ps), units in the CSV
headers and the JSON, and figure names with a prefix for a shared wiki."""

from __future__ import annotations

import csv
import json
import re

import imageio.v3 as iio
import numpy as np
import pytest

from conftest import ROOT, WIKI
from springscene import build, config, jobs, render
from springscene.app.cli import main
from springscene.figures.gallery import check_prefix, gallery
from springscene.errors import UserError
from springscene.model import physics
from springscene.science import theory
from springscene.view.overlay import EnergyPanel, clock_text, clock_top, parse_overlays

CHAIN_AL = ROOT / "configs" / "chain-aluminum.toml"
COLUMN = re.compile(r"^\w+ \[[^\]]*\]$")          # "name [unit]"


@pytest.fixture(scope="module")
def wiki():
    return config.load(WIKI)


# ---- energy bars about equilibrium -------------------------------------------------------

def test_rest_potential_is_the_energy_at_rest_at_equilibrium(wiki):
    k, m, g, L0 = wiki.spring.k, wiki.ball.m, 9.8, wiki.spring.L0
    stretch = m * g / k
    y = -(L0 + stretch)                          # below the holder, Ug = m g y from it
    assert theory.rest_potential(wiki) == pytest.approx(0.5 * k * stretch ** 2 + m * g * y,
                                                        rel=1e-12)


def test_energy_bars_show_the_exchange(wiki):
    """The page's run: K and U trade 0 <-> 1/2 k A^2 = 3 mJ and fill the axis, the total
    stays at 3 mJ; the axis is in mJ (the old bars, Us and Ug apart, were 25 mJ tall)."""
    cfg = config.override(wiki, "render", duration=1.0)
    ov = render.make_overlays(cfg, ("energy",))
    bars = ov.energy
    assert bars.scale == 1e-3 and bars.ax.get_title() == "energy (mJ)"
    lo, hi = bars.ax.get_ylim()
    assert 3.0 < hi < 3.6 and -0.5 < lo <= 0               # 3 mJ fills the axis
    traj = physics.run(build.system(cfg), 100)
    K, U, thermal, total = (np.asarray(v) for v in bars.values(traj))
    half_kA2 = 0.5 * wiki.spring.k * 0.02 ** 2
    assert U.max() == pytest.approx(half_kA2, rel=0.02) and U.min() < 0.02 * half_kA2
    assert K.max() == pytest.approx(half_kA2, rel=0.03) and K.min() < 0.02 * half_kA2
    assert np.all(thermal == 0)
    # flat but for Euler-Cromer's own energy wobble (about omega dt = 12 % at dt = 0.01 s),
    # which bars about equilibrium show as it is
    assert np.ptp(total) < 0.15 * half_kA2 and total.mean() == pytest.approx(half_kA2, rel=0.03)
    assert [t.get_text() for t in bars.ax.get_xticklabels()] == ["K", "U", "thermal", "total"]


def test_energy_bars_zero_defaults_to_the_lowest_potential_of_the_run(wiki):
    traj = physics.run(build.system(wiki), 100)
    panel = EnergyPanel(400, traj)
    assert panel.u_rest == pytest.approx(float(np.min(traj.Us + traj.Ug)))
    assert panel.u_rest == pytest.approx(theory.rest_potential(wiki), abs=2e-4)


# ---- the clock ---------------------------------------------------------------------------

def test_overlays_default_a_clock_for_lattices_only(wiki):
    chain = config.load(CHAIN_AL)
    assert render.make_overlays(chain, None).names == ("time",)
    assert render.make_overlays(chain, ()).names == ()
    assert render.make_overlays(wiki, None).names == ()
    assert parse_overlays(None) is None and parse_overlays("none") == ()
    assert parse_overlays(" None ") == () and parse_overlays("time") == ("time",)


def test_clock_unit_follows_the_video_span():
    assert clock_text(1e-13, 1e-12, 6e-12) == "t = 0.10 ps"        # chain-aluminum
    assert clock_text(4e-14, 2e-13, 2e-12) == "t = 0.04 ps"        # crystal: ps, not fs
    assert clock_text(1.234, 1.0, 10.0) == "t = 1.23 s"            # the page's ball
    assert clock_text(2e-14, 2e-13, 4e-14) == "t = 20.00 fs"       # a 40 fs video


def test_clock_goes_under_a_title_that_reaches_its_corner():
    img = np.zeros((100, 300, 3), np.uint8)
    assert clock_top(img, (0, 0, 0), margin=12, width=120, height=20) == 12
    img[2:30, 200:290] = 255                     # a short title, away from the corner
    assert clock_top(img, (0, 0, 0), margin=12, width=120, height=20) == 12
    img[2:30, 60:290] = 255                      # a long one, into the corner
    assert clock_top(img, (0, 0, 0), margin=12, width=120, height=20) == 30 + 6


def test_lattice_video_has_its_clock_by_default(tmp_path):
    """chain-aluminum: the clock (ps) is drawn under its long title; --overlay none: no clock."""
    out, plain = tmp_path / "chain.mp4", tmp_path / "plain.mp4"
    for path, extra in ((out, ()), (plain, ("--overlay", "none"))):
        assert main(["render", str(CHAIN_AL), "--duration", "1e-13", "--fps", "20", "--draft",
                     "--quiet", "--out", str(path), *extra]) == 0
    a, b = iio.imread(out)[-1], iio.imread(plain)[-1]
    assert a.shape == b.shape == (600, 900, 3)
    corner = (slice(40, 70), slice(0, 140))       # under the title, at the left edge
    dark = (np.asarray(a[corner], int).max(axis=2) < 100).sum()
    assert dark > 80 and (np.asarray(b[corner], int).max(axis=2) < 100).sum() == 0
    diff = np.abs(a.astype(int) - b.astype(int)).max(axis=2)
    diff[corner] = 0
    assert (diff > 40).mean() < 0.001             # the clock is the only difference


# ---- units in the CSV headers and the JSON -----------------------------------------------

def test_csv_headers_carry_units(tmp_path, wiki):
    out = tmp_path / "t.csv"
    jobs.simulate(wiki, 0.1, out)
    header = next(csv.reader(open(out)))
    assert header == list(render.CSV_HEADER) and all(COLUMN.match(h) for h in header)
    assert header[:2] == ["t [s]", "x [m]"] and "px [kg m/s]" in header and "K [J]" in header
    chain = tmp_path / "chain.csv"
    jobs.simulate(config.load(ROOT / "configs" / "chain.toml"), 0.05, chain)
    header = next(csv.reader(open(chain)))
    assert header[0] == "t [s]" and all(COLUMN.match(h) for h in header)
    data = np.loadtxt(chain, delimiter=",", skiprows=1)
    assert data.shape == (6, len(header))


def test_sweep_csv_header_carries_units(tmp_path):
    out = tmp_path / "curve.csv"
    assert main(["sweep", str(ROOT / "configs" / "driven.toml"), "--omega", "11:13:3",
                 "--periods", "40", "--out", str(out)]) == 0
    header = next(csv.reader(open(out)))
    assert header == ["omega [rad/s]", "frequency [Hz]", "amplitude [m]", "theory [m]"]


def test_analyze_json_carries_units(cli):
    ball = json.loads(cli("analyze", ROOT / "configs" / "damped.toml", "--json",
                          check=True).stdout)
    assert set(ball["unit"]) == set(ball["measured"]) == set(ball["theory"])
    assert ball["unit"]["period"] == "s" and ball["unit"]["damping_rate"] == "1/s"
    assert ball["unit"]["max_acceleration"] == "m/s^2" and ball["unit"]["energy_lost"] == "J"
    assert ball["dt_unit"] == ball["duration_unit"] == "s"
    chain = json.loads(cli("analyze", ROOT / "configs" / "chain.toml", "--json",
                           check=True).stdout)
    assert chain["dt_unit"] == "s" and chain["lattice"]["k_unit"] == "N/m"
    assert chain["speed_of_sound"]["unit"] == "m/s"
    assert chain["dispersion"]["lowest"]["unit"] == "rad/s"


# ---- figure names with a prefix ----------------------------------------------------------

def test_prefix_check():
    assert check_prefix("BallSpring_") == "BallSpring_" and check_prefix("") == ""
    assert check_prefix("Spring-(v2).") == "Spring-(v2)."
    for bad in ("a/b", "x|y", ".hidden", "a b", "[[x]]", "x" * 101):
        with pytest.raises(UserError, match="--prefix"):
            check_prefix(bad)


def test_gallery_names_are_the_files():
    text = gallery([("P_scene.png", "the | scene")], ["P_energy.svg"])
    assert "File:P_scene.png|the / scene" in text and "P_energy.svg" in text


def test_figures_with_a_prefix(tmp_path, wiki):
    """Every file of the set, and every name in its gallery, carries the prefix."""
    out = tmp_path / "figs"
    written = jobs.figures(wiki, out, antialias=False, prefix="BallSpring_")
    names = sorted(p.name for p in out.iterdir())
    assert names == sorted(p.name for p in written) and len(names) == 18
    assert all(n.startswith("BallSpring_") for n in names)
    assert "BallSpring_figures.wiki" in names and "BallSpring_scene.png" in names
    wiki_text = (out / "BallSpring_figures.wiki").read_text()
    files = re.findall(r"^File:([^|]+)\|", wiki_text, re.M)
    assert len(files) == 10 and all(f.startswith("BallSpring_") and f in names for f in files)
    svgs = re.search(r"Vector \(SVG\) versions of the plots: (.*) -->", wiki_text).group(1)
    assert all(n.startswith("BallSpring_") for n in svgs.split(", "))


def test_bad_prefix_is_one_line_and_leaves_nothing(tmp_path, capsys):
    out = tmp_path / "figs"
    assert main(["figures", str(WIKI), "--prefix", "x/y", "--out", str(out)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--prefix 'x/y'" in err and not out.exists()
