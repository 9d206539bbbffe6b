"""Every number of a config is checked for a physically and numerically sensible range:
huge or tiny finite values (1e308, 1e-300) are refused with exit 2 and one line naming
the file and the key, before anything is drawn or stepped; never a blank picture, a
numpy error, a message blaming another key, or a CSV of nan. Every shipped config stays
valid (the page's metre-scale scenes and the matter configs at 1e-10 m alike)."""

from __future__ import annotations

import math
import re
import tempfile
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

try:
    import tomllib
except ModuleNotFoundError:                     # Python 3.10
    import tomli as tomllib

from conftest import ROOT, WIKI
from springscene import build, config, ranges, render
from springscene.errors import UserError
from springscene.model import physics
from springscene.view import camera

CONFIGS = ROOT / "springscene" / "configs"
CRYSTAL = CONFIGS / "crystal.toml"
SHIPPED = sorted(CONFIGS.glob("*.toml")) + sorted((ROOT / "configs").glob("*.toml"))


def variant(tmp_path: Path, base: Path, section: str, key: str, value: str) -> Path:
    """``base`` with ``[section] key = value`` (replaced, or added to the section)."""
    text = base.read_text()
    head = f"[{section}]"
    body = re.search(rf"(?ms)^\[{section}\]\n(.*?)(?=^\[|\Z)", text)
    line = re.compile(rf"(?m)^{key}\s*=.*$")
    if body and line.search(body.group(1)):
        new_body = line.sub(f"{key} = {value}", body.group(1), count=1)
        text = text[:body.start(1)] + new_body + text[body.end(1):]
    elif body:
        text = text.replace(head + "\n", f"{head}\n{key} = {value}\n", 1)
    else:
        text += f"\n{head}\n{key} = {value}\n"
    folder = Path(tempfile.mkdtemp(dir=tmp_path))
    path = folder / "c.toml"
    path.write_text(text)
    return path


def refused(cli, args: list, path: Path, *words: str) -> str:
    """Run the CLI in-process (the ``cli`` fixture): exit 2, one line naming ``path`` and
    ``words``, and the config's folder holds nothing new."""
    proc = cli(*args)
    err = proc.stderr
    assert proc.returncode == 2, err
    assert len(err.splitlines()) == 1 and err.startswith("springscene: error: "), err
    assert "Traceback" not in err
    for word in (str(path), *words):
        assert word in err, err
    assert [p.name for p in path.parent.iterdir()] == [path.name]
    return err


# ---- the hostile campaign's cases: each refused, naming its key --------------------------

BLANK_PICTURES = [     # exit 0 with a blank or garbage picture before
    ("spring", "radius", "1e308"), ("spring", "radius", "1e6"),
    ("spring", "thickness", "1e308"), ("spring", "thickness", "1e20"),
    ("camera", "range", "1e-300"), ("camera", "range", "1e308"),
    ("ball", "pos", "[0, -1e308, 0]"), ("ball", "pos", "[1e308, 0, 0]"),
    ("camera", "center", "[-1, 1e20, 2]"), ("camera", "center", "[1e308, 0.1, 1e308]"),
    ("camera", "up", "[1e6, 1e20, 1e308]"),     # nearly +z: parallel to forward -z
]


@pytest.mark.parametrize("section, key, value", BLANK_PICTURES)
def test_a_value_that_would_draw_a_blank_picture_is_refused(tmp_path, cli, section, key,
                                                            value):
    path = variant(tmp_path, WIKI, section, key, value)
    refused(cli, ["still", path, "--draft", "--out", path.parent / "o.png"], path,
            f"[{section}] {key}")


def test_a_video_of_a_huge_spring_is_refused_before_a_frame(tmp_path, cli):
    path = variant(tmp_path, WIKI, "spring", "radius", "1e308")
    err = refused(cli, ["render", path, "--duration", "0.2", "--draft", "--quiet", "--out",
                           path.parent / "o.mp4"], path, "[spring] radius")
    assert "between" in err and " m " in err


MISATTRIBUTED = [      # blamed yield_stretch (never set) or "use a smaller --dt" before
    ("ball", "m", "1e308", "simulate"), ("physics", "g", "[0, -1e308, 0]", "simulate"),
    ("ball", "m", "1e308", "still"), ("physics", "g", "[0, -1e308, 0]", "still"),
    ("ball", "pos", "[1e308, 0, 0]", "simulate"), ("spring", "L0", "1e308", "simulate"),
    ("spring", "k", "1e308", "simulate"), ("spring", "k3", "1e308", "simulate"),
    ("ball", "p", "[1e308, 0, 0]", "simulate"), ("damping", "b", "1e308", "simulate"),
    ("physics", "dt", "1e-300", "simulate"),
]


@pytest.mark.parametrize("section, key, value, command", MISATTRIBUTED)
def test_a_huge_physical_value_is_blamed_on_its_own_key(tmp_path, cli, section, key, value,
                                                        command):
    path = variant(tmp_path, WIKI, section, key, value)
    out = path.parent / ("o.csv" if command == "simulate" else "o.png")
    err = refused(cli, [command, path, "--out", out], path, f"[{section}] {key}")
    assert "yield_stretch" not in err and "blew up" not in err


@pytest.mark.parametrize("key, value", [("amplitude", "1e308"), ("omega", "1e308")])
def test_a_huge_drive_is_blamed_on_its_key(tmp_path, cli, key, value):
    path = variant(tmp_path, ROOT / "configs" / "driven.toml", "drive", key, value)
    refused(cli, ["simulate", path, "--out", path.parent / "o.csv"], path, f"[drive] {key}")


@pytest.mark.parametrize("command, out", [("still", "o.png"), ("render", "o.mp4"),
                                          ("simulate", "o.csv")])
def test_a_crystal_of_absurd_molar_mass_is_refused(tmp_path, cli, command, out):
    """Was: a NaN traceback from the colour bar (still, render), nan columns (simulate)."""
    path = variant(tmp_path, CRYSTAL, "atom", "molar_mass", "1e308")
    extra = ["--draft", "--duration", "2e-14"] if command == "render" else []
    refused(cli, [command, path, *extra, "--out", path.parent / out], path,
            "[atom] molar_mass", "kg/mol")


@pytest.mark.parametrize("section, key, value", [
    ("lattice", "density", "1e308"), ("bond", "k", "1e308"), ("start", "temperature", "1e308"),
    ("start", "temperature", "1e8"), ("atom", "radius", "1e308"), ("bond", "radius", "1e-300"),
    ("camera", "range", "1e308"),
])
def test_a_crystal_key_out_of_range_is_named(tmp_path, cli, section, key, value):
    path = variant(tmp_path, CRYSTAL, section, key, value)
    refused(cli, ["simulate", path, "--out", path.parent / "o.csv"], path,
            f"[{section}] {key}")


def test_a_speed_that_leaves_no_frame_is_named(tmp_path, cli):
    out = tmp_path / "o.mp4"
    proc = cli("render", WIKI, "--speed", "1e308", "--duration", "0.5", "--draft", "--quiet",
               "--out", out)
    err = proc.stderr
    assert proc.returncode == 2 and len(err.splitlines()) == 1, err
    assert "--speed 1e+308" in err and "no frame" in err
    assert list(tmp_path.iterdir()) == []


def test_a_huge_but_finite_up_is_only_a_direction(tmp_path, cli):
    """`up` = [1e308, 1e308, 0] is the direction [1, 1, 0]: no error, the same picture."""
    cfg = config.load(variant(tmp_path, WIKI, "camera", "up", "[1e308, 1e308, 0]"))
    x, y, z = cfg.camera.up
    assert x == y > 0 and z == 0 and math.isfinite(x * x + y * y)
    pictures = []
    for up in ("[1e308, 1e308, 0]", "[1, 1, 0]"):
        path = variant(tmp_path, WIKI, "camera", "up", up)
        out = path.parent / "o.png"
        proc = cli("still", path, "--draft", "--out", out)
        assert proc.returncode == 0, proc.stderr
        pictures.append(out.read_bytes())
    assert pictures[0] == pictures[1]


# ---- the last line of defence: energies that are no longer finite ------------------------

def test_a_run_whose_energies_overflow_is_an_error_not_a_nan_csv():
    """Built past the config's checks (the API's System): the totals refuse, one line."""
    system = physics.System(pos=[[0, 0, 0], [0, -1, 0]], p=[[0, 0, 0], [1e200, 0, 0]],
                            m=[1.0, 1e-200], fixed=[True, False], i=[0], j=[1], k=1.0, L0=1.0,
                            g=[0, 0, 0], dt=1e-3)
    with pytest.raises(UserError) as err:
        render.lattice_totals(system, 3)
    assert "no longer finite" in str(err.value) and "\n" not in str(err.value)


# ---- every shipped config stays valid ----------------------------------------------------

@pytest.mark.parametrize("path", SHIPPED, ids=lambda p: f"{p.parent.name}/{p.name}")
def test_every_shipped_config_is_within_its_ranges(path):
    cfg = config.load(path)
    ranges.check(cfg, lambda key: key)          # the same checks again, explicitly
    system = build.system(cfg)
    physics.step(system, 3)
    assert np.isfinite(system.pos).all() and np.isfinite(system.p).all()
    assert math.isfinite(physics.energies(system).total)


# ---- generated: huge and tiny finite values for every numeric key ------------------------

BALL_KEYS = {"camera": {"center": 3, "forward": 3, "up": 3, "fov": 1, "range": 1},
             "physics": {"dt": 1, "g": 3}, "damping": {"b": 1},
             "drive": {"amplitude": 1, "omega": 1, "direction": 3},
             "holder": {"pos": 3, "size": 3},
             "spring": {"k": 1, "L0": 1, "radius": 1, "thickness": 1, "k3": 1,
                        "yield_stretch": 1},
             "ball": {"m": 1, "radius": 1, "pos": 3, "p": 3}}
LATTICE_KEYS = {"camera": BALL_KEYS["camera"], "physics": BALL_KEYS["physics"],
                "damping": {"b": 1}, "lattice": {"spacing": 1, "density": 1},
                "bond": {"k": 1, "radius": 1, "thickness": 1},
                "atom": {"m": 1, "molar_mass": 1, "radius": 1},
                "start": {"kick": 3, "temperature": 1}, "pull": {"force": 1}}
EITHER = {("lattice", "spacing"): "density", ("lattice", "density"): "spacing",
          ("atom", "m"): "molar_mass", ("atom", "molar_mass"): "m"}
BASES = {name: tomllib.loads((CONFIGS / f"{name}.toml").read_text())
         for name in ("wiki", "driven", "chain", "bar")}

extreme = st.one_of(
    st.sampled_from([1e308, -1e308, 1e-308, -1e-308, 5e-324, 1e300, 1e-300, 1e20, -1e20,
                     1e-20, 1e6, 1e-6, 0.0, 1.0, -1.0]),
    st.floats(allow_nan=False, allow_infinity=False),
    st.floats(min_value=-1e3, max_value=1e3, allow_nan=False))


@st.composite
def extreme_configs(draw) -> dict:
    name = draw(st.sampled_from(sorted(BASES)))
    doc = {section: dict(table) for section, table in BASES[name].items()}
    keys = LATTICE_KEYS if "lattice" in doc else BALL_KEYS
    for _ in range(draw(st.integers(1, 3))):
        section = draw(st.sampled_from(sorted(keys)))
        key = draw(st.sampled_from(sorted(keys[section])))
        n = keys[section][key]
        value = draw(extreme) if n == 1 else draw(st.lists(extreme, min_size=3, max_size=3))
        table = doc.setdefault(section, {})
        table[key] = value
        table.pop(EITHER.get((section, key)), None)
    return doc


def _finite_view(cfg) -> None:
    """The camera the scene would get: placed from finite numbers."""
    lo, hi = ranges.scene_box(cfg)
    assert np.isfinite(lo).all() and np.isfinite(hi).all()
    c, s = cfg.camera, cfg.scene
    rng = c.range if c.range is not None else camera.autoscale_range(
        np.array([[lo, hi]]), c.center, c.fov, s.width, s.height)
    v = camera.view(c.center, c.forward, c.up, c.fov, rng, s.width, s.height)
    assert np.isfinite(v.position).all() and 0 < v.near < v.far < math.inf
    assert np.isfinite(v.project(np.array([lo, hi]))).all()


@settings(max_examples=400, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(doc=extreme_configs())
def test_huge_and_tiny_values_are_refused_in_one_line_or_run_finite(doc):
    """Either the config is refused (one line, naming the source), or its system steps,
    its energies and its camera are finite: never a numpy error, never a nan."""
    try:
        cfg = config.from_dict(doc, source="gen.toml")
    except UserError as exc:
        message = str(exc)
        assert message.startswith("gen.toml") and "\n" not in message, message
        assert "nan" not in message.split("got")[0], message
        return
    system = build.system(cfg)
    try:
        physics.step(system, 3)
    except UserError as exc:         # a non-linear spring may still run away: one line
        assert "\n" not in str(exc)
        return
    assert np.isfinite(system.pos).all() and np.isfinite(system.p).all()
    assert math.isfinite(physics.energies(system).total)
    _finite_view(cfg)


def test_a_soft_spring_sagging_tens_of_its_length_is_a_config_not_an_error(tmp_path):
    """k = 2 N/m under 0.5 kg: mg/k = 2.45 m, 24.5 L0 (a slinky-like spring an instructor
    may well set); it runs and its ball is drawn where the sag puts it."""
    soft = tmp_path / "soft.toml"
    soft.write_text(WIKI.read_text().replace("k = 15.0", "k = 2.0").replace("m = 0.10", "m = 0.5"))
    cfg = config.load(soft)
    assert ranges.reach(cfg) > 20 * cfg.spring.L0
    image = render.still(cfg, 0.8, tmp_path / "soft.png", antialias=False)
    red = (image[..., 0] > 150) & (image[..., 1] < 80) & (image[..., 2] < 80)
    assert red.sum() > 10                                  # the ball, not a blank picture


def test_a_camera_set_on_a_soft_springs_motion_is_accepted(tmp_path):
    """k = 0.5 N/m: the ball sags 1.96 m; a camera centred 2 m down with range 2.5 m frames
    the motion (it was refused against the scene at the start: at most 1.58 m)."""
    text = WIKI.read_text().replace("k = 15.0", "k = 0.5")
    text = text.replace("center = [0, -0.10, 0]", "center = [0, -2, 0]\nrange = 2.5")
    soft = tmp_path / "soft.toml"
    soft.write_text(text)
    cfg = config.load(soft)
    assert (cfg.camera.center, cfg.camera.range) == ((0.0, -2.0, 0.0), 2.5)
