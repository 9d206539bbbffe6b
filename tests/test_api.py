"""The Python API (``import springscene``): light to import, documented with examples that
run, configs checked on every change, results that show themselves in Jupyter."""

from __future__ import annotations

import base64
import dataclasses
import doctest
import inspect
import io
import subprocess
import sys
import warnings

import numpy as np
import pytest

import springscene
from conftest import ROOT, WIKI
from springscene import api, config, jobs, results
from springscene.app.cli import main
from springscene.errors import UserError

if sys.version_info >= (3, 11):
    import tomllib
else:
    import tomli as tomllib

SMALL = {"scene": {"width": 240, "height": 160}}


@pytest.fixture(scope="module")
def wiki():
    return springscene.load_config("wiki")


def test_import_springscene_loads_no_drawing_and_not_the_api():
    code = ("import sys, springscene\n"
            "v = springscene.__version__\n"
            "print(sorted(m for m in sys.modules if m.split('.')[0] in ('vtkmodules', "
            "'pyvista', 'matplotlib', 'PIL', 'imageio', 'tqdm', 'numpy') "
            "or m == 'springscene.api'))\n")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          cwd=ROOT, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "[]"


def test_version_is_pyprojects_own():
    version = tomllib.loads((ROOT / "pyproject.toml").read_text())["project"]["version"]
    assert springscene.__version__ == version
    out = io.StringIO()
    with pytest.raises(SystemExit) as stop:
        sys.stdout, saved = out, sys.stdout
        try:
            main(["--version"])
        finally:
            sys.stdout = saved
    assert stop.value.code == 0
    assert out.getvalue().strip() == f"springscene {version}"


@pytest.mark.parametrize("module", [api, results, springscene.settings],
                         ids=lambda m: m.__name__)
def test_the_documented_examples_run(module):
    """The numpydoc Examples sections are doctests, and they pass."""
    found = doctest.testmod(module, optionflags=doctest.ELLIPSIS, verbose=False)
    assert found.failed == 0
    if module is not results:
        assert found.attempted >= 4


def test_every_public_function_is_documented_with_parameters_and_returns():
    for name in springscene.__all__:
        if name in ("__version__", "Config", "UserError"):
            continue
        doc = inspect.getdoc(getattr(api, name)) or ""     # dedented, as Python 3.13 does
        assert len(doc) > 60, name
        if callable(getattr(api, name)) and name[0].islower() and name != "starters":
            assert "\nReturns\n-------\n" in doc, name


def test_the_package_exports_the_api_and_lazily(wiki):
    for name in springscene.__all__:
        assert hasattr(springscene, name), name
    assert springscene.simulate is api.simulate and springscene.Config is config.Config
    assert "load_config" in dir(springscene)
    with pytest.raises(AttributeError, match="no attribute 'nonsense'"):
        springscene.nonsense  # noqa: B018


def test_render_and_figures_are_modules_and_the_api_functions():
    """springscene.render is the pipeline module (from springscene import render) and,
    called, api.render; likewise figures."""
    from springscene import figures, render
    assert callable(render.render_video) and callable(figures.make_figures)
    assert callable(springscene.render) and callable(springscene.figures)
    with pytest.raises(UserError, match="no such config file"):
        springscene.render("no-such.toml", "x.mp4")
    with pytest.raises(UserError, match="no such config file"):
        springscene.figures("no-such.toml", "figs")


# ---- configs: loaded, changed, checked -----------------------------------------------------

def test_load_config_by_file_starter_name_or_dict(wiki):
    from_file = springscene.load_config(WIKI)
    assert dataclasses.replace(from_file, source="x") == dataclasses.replace(wiki, source="x")
    assert wiki.source == "wiki.toml"
    assert springscene.load_config("wiki.toml") == wiki
    assert springscene.load_config("driven").driven
    assert springscene.load_config({"spring": {"k": 20}}).spring.k == 20.0
    assert springscene.load_config(wiki) is wiki
    with pytest.raises(UserError, match=r"^nope\.toml: no such config file$"):
        springscene.load_config("nope.toml")


def test_replace_gives_the_same_one_line_error_as_the_toml_file(tmp_path, cli):
    """cfg.replace(k=-1) and a TOML file with k = -1 are refused with the same words."""
    good = tmp_path / "wiki.toml"
    good.write_text(WIKI.read_text())
    bad = tmp_path / "bad" / "wiki.toml"
    bad.parent.mkdir()
    bad.write_text(WIKI.read_text().replace("k = 15.0", "k = -1"))
    with pytest.raises(UserError) as from_file:
        springscene.load_config(bad)
    cfg = dataclasses.replace(springscene.load_config(good), source=str(bad))
    with pytest.raises(UserError) as from_replace:
        cfg.replace(k=-1)
    assert str(from_replace.value) == str(from_file.value)
    assert str(from_replace.value) == f"{bad}: [spring] k must be > 0, got -1"
    # and the CLI prints the file's error as one line, exit 2
    proc = cli("simulate", bad, "--out", tmp_path / "t.csv")
    assert proc.returncode == 2
    assert proc.stderr == f"springscene: error: {from_file.value}\n"


def test_replace_checks_every_change_and_leaves_the_config_alone(wiki):
    stiff = wiki.replace(k=30, ball={"m": 0.2}, dt=0.005)
    assert (stiff.spring.k, stiff.ball.m, stiff.physics.dt) == (30.0, 0.2, 0.005)
    assert (wiki.spring.k, wiki.ball.m, wiki.physics.dt) == (15.0, 0.1, 0.01)
    assert stiff.spring.L0 == wiki.spring.L0 and stiff.source == wiki.source
    assert wiki.replace(spring={"coils": 5}).spring.coils == 5
    cases = [
        ("radius", 0.1, "'radius' is in [spring], [ball]: name the section"),
        ("stiffness", 3, "'stiffness' is not a key of any of its sections"),
        ("spring", {"stiffness": 3}, "unknown key 'stiffness' in [spring]"),
        ("spring", {"k": "soft"}, "[spring] k must be a number, got str"),
        ("lattice", {"shape": [3]}, "[lattice] does not apply to this config"),
        ("spring", 3, "[spring] must be a table"),
        ("dt", 0.3, "[physics] dt: dt = 0.3 s is unstable for euler-cromer"),
        ("b", -1, "[damping] b must be >= 0, got -1"),
        ("ball", {"pos": [0, 0, 0]}, "[ball] pos must differ from [holder] pos"),
    ]
    for key, value, message in cases:
        with pytest.raises(UserError) as err:
            wiki.replace(**{key: value})
        assert str(err.value).startswith("wiki.toml: ") and message in str(err.value), err.value
        assert "\n" not in str(err.value)


def test_replace_on_a_lattice_finds_the_lattice_sections():
    chain = springscene.load_config("chain")
    assert chain.replace(k=20).bond.k == 20.0
    assert chain.replace(m=0.2).atom.m == 0.2
    with pytest.raises(UserError, match=r"\[spring\] does not apply"):
        chain.replace(spring={"k": 3})


# ---- the jobs ------------------------------------------------------------------------------

def test_simulate_is_a_table_of_columns_with_units(wiki, tmp_path):
    run = springscene.simulate(wiki, duration=1, out=tmp_path / "t.csv")
    traj = jobs.simulate(wiki, 1)
    assert list(run) == ["t", "x", "y", "z", "px", "py", "pz", "K", "Us", "Ug", "E",
                         "E_thermal"]
    assert run.units["t"] == "s" and run.units["y"] == "m" and run.units["py"] == "kg m/s"
    assert run.units["E"] == "J"
    assert all(v.shape == (101,) for v in run.values())
    np.testing.assert_array_equal(run["y"], traj.pos[:, 1])
    np.testing.assert_array_equal(run["E"], traj.E)
    assert run.array.shape == (101, 12)
    csv_rows = np.loadtxt(tmp_path / "t.csv", delimiter=",", skiprows=1)
    np.testing.assert_allclose(csv_rows, run.array, rtol=1e-15)
    assert "101 rows" in repr(run) and "<th>y [m]</th>" in run._repr_html_()


def test_simulate_a_lattice_gives_its_totals():
    run = springscene.simulate("chain", duration=0.05)
    assert list(run) == ["t", "px", "py", "pz", "K", "Us", "E", "E_thermal"]
    np.testing.assert_array_equal(run.array, jobs.simulate(springscene.load_config("chain"),
                                                           0.05))


def test_still_is_an_image_array_that_jupyter_shows(wiki, tmp_path):
    from PIL import Image

    out = tmp_path / "s.png"
    picture = springscene.still(wiki.replace(**SMALL), time=0.25, out=out, draft=True)
    assert isinstance(picture, np.ndarray) and picture.shape == (160, 240, 3)
    assert picture.dtype == np.uint8 and picture.path == out
    shown = np.asarray(Image.open(io.BytesIO(picture._repr_png_())))
    np.testing.assert_array_equal(shown, picture)
    np.testing.assert_array_equal(np.asarray(Image.open(out)), picture)
    assert (picture[..., 0] > 200).any() and picture.std() > 10      # the red ball, a scene
    assert picture[:, :, 0]._repr_png_() is None         # a slice is numbers, not a picture
    assert type(np.asarray(picture)) is np.ndarray


def test_render_is_a_video_that_jupyter_shows(wiki, tmp_path, monkeypatch):
    out = tmp_path / "v.mp4"
    video = springscene.render(wiki.replace(**SMALL), out, duration=0.4, fps=10, draft=True,
                               progress=False)
    assert video.path == out and video.frames == 4 and video.fps == 10
    html = video._repr_html_()
    assert html.startswith("<video controls") and 'type="video/mp4"' in html
    data = html.split("base64,")[1].split('"')[0]
    assert base64.b64decode(data) == out.read_bytes()
    monkeypatch.setattr(results, "EMBED_LIMIT", 0)          # a big video is linked, not embedded
    monkeypatch.chdir(tmp_path)
    assert 'src="v.mp4"' in video._repr_html_()
    gif = springscene.render(wiki.replace(**SMALL), tmp_path / "v.gif", duration=0.2, fps=10,
                             draft=True, progress=False)
    assert gif._repr_html_().startswith('<img src="v.gif"')


def test_analyze_and_sweep(wiki):
    result = springscene.analyze(wiki, duration=3)
    assert result["measured"]["period"] == pytest.approx(result["theory"]["period"], rel=2e-3)
    assert str(result) == jobs.report(wiki, jobs.analyze(wiki, 3))
    assert '"measured"' in result.report(as_json=True)
    curve = springscene.sweep("driven", "10:14:5", periods=40)
    np.testing.assert_allclose(curve.omega, [10, 11, 12, 13, 14])
    assert curve.peak[0] == 12.0
    with pytest.raises(UserError, match="omega"):
        springscene.sweep("driven", "10:14")


@pytest.mark.slow       # run_vpython runs the program in a supervised child: a new Python
def test_run_vpython_is_a_video(tmp_path):
    program = springscene.init("bounce", tmp_path)
    video = springscene.run_vpython(program, tmp_path / "b.png", duration=0.2, draft=True,
                                    page=False)
    assert video.path.is_file() and video.frames == 1 and video.ended == "duration"
    assert video._repr_html_().startswith('<img src="data:image/png;base64,')


def test_scene_capture_outside_springscene_vpython_warns():
    from springscene.vpython.api import canvas
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        canvas().capture("snap")
    assert len(caught) == 1 and caught[0].category is UserWarning
    assert "scene.capture('snap.png') saved nothing" in str(caught[0].message)
    assert "springscene vpython" in str(caught[0].message)


# ---- starters: springscene init -----------------------------------------------------------

def test_starters_are_the_package_data():
    names = springscene.starters()
    configs = sorted(p.name for p in (ROOT / "springscene" / "configs").glob("*.toml"))
    examples = sorted(p.name for p in (ROOT / "springscene" / "examples").iterdir()
                      if p.suffix in (".py", ".ipynb"))
    assert sorted(names) == sorted(configs + examples)
    assert "api.ipynb" in names and all(names.values())


def test_init_copies_a_starter_and_never_overwrites(tmp_path, monkeypatch, capsys):
    monkeypatch.chdir(tmp_path)
    assert main(["init"]) == 0
    assert (tmp_path / "wiki.toml").read_text() == WIKI.read_text()
    assert capsys.readouterr().out == "wrote wiki.toml\n"
    (tmp_path / "wiki.toml").write_text("# mine\n")
    assert main(["init", "wiki"]) == 2
    err = capsys.readouterr().err
    assert err == ("springscene: error: wiki.toml: already exists; init never overwrites "
                   "(remove it or run init in another folder)\n")
    assert (tmp_path / "wiki.toml").read_text() == "# mine\n"
    assert main(["init", "nothing"]) == 2
    assert capsys.readouterr().err.startswith("springscene: error: init nothing: no such "
                                              "starter (choose from bar.toml, ")
    assert main(["init", "damped"]) == 0 and (tmp_path / "damped.toml").is_file()
    assert main(["init", "--list"]) == 0
    listing = capsys.readouterr().out.splitlines()
    assert any(line.startswith("wiki.toml ") and "Ball and Spring Model" in line
               for line in listing)
    assert any(line.startswith("api.ipynb ") for line in listing)
