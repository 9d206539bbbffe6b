"""What a user does after ``pip install .``, from a folder of their own: ``springscene
init``, ``still``, ``render --out x.webm``, ``figures --prefix``, ``compare``, and the
example notebook (executed by nbclient on an ipykernel).

The commands are the ``springscene`` script of the Python running the tests: the
editable install of ``make test``, or, in ``.ci/run``'s legs on Python 3.10 and the
newest Python, a real (non-editable) install in a fresh venv; there
``SPRINGSCENE_INSTALLED=1`` also requires the package to come from site-packages.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

import springscene
from conftest import ROOT

BIN = Path(sys.executable).parent


def _env() -> dict[str, str]:
    return {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH",)}


def springscene_cli(cwd: Path, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([str(BIN / "springscene"), *args], cwd=cwd, env=_env(),
                          capture_output=True, text=True, timeout=600)


@pytest.fixture(scope="module")
def home(tmp_path_factory) -> Path:
    """A user's folder, outside the checkout."""
    folder = tmp_path_factory.mktemp("user")
    assert not folder.resolve().is_relative_to(ROOT)
    return folder


def test_the_package_is_the_installed_one(home):
    proc = subprocess.run([sys.executable, "-c", "import springscene; print(springscene.__file__)"
                           "; print(springscene.__version__)"], cwd=home, env=_env(),
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    where, version = proc.stdout.split()
    assert version == springscene.__version__
    if os.environ.get("SPRINGSCENE_INSTALLED"):
        assert "site-packages" in where and not where.startswith(str(ROOT)), where
    proc = springscene_cli(home, "--version")
    assert proc.returncode == 0 and proc.stdout == f"springscene {version}\n"


def test_init_still_render_webm_figures_compare(home):
    proc = springscene_cli(home, "init")
    assert proc.returncode == 0, proc.stderr
    assert (home / "wiki.toml").read_text() == (ROOT / "configs" / "wiki.toml").read_text()
    proc = springscene_cli(home, "init")
    assert proc.returncode == 2 and proc.stderr.count("\n") == 1
    assert "wiki.toml: already exists" in proc.stderr

    proc = springscene_cli(home, "still", "wiki.toml", "--time", "0.25", "--draft", "--out",
                           "a.png")
    assert proc.returncode == 0, proc.stderr
    proc = springscene_cli(home, "still", "wiki.toml", "--time", "0.25", "--draft", "--out",
                           "b.png")
    assert proc.returncode == 0, proc.stderr
    proc = springscene_cli(home, "compare", "a.png", "b.png")
    assert proc.returncode == 0, proc.stdout + proc.stderr
    proc = springscene_cli(home, "still", "wiki.toml", "--time", "0.1", "--draft", "--out",
                           "c.png")
    assert springscene_cli(home, "compare", "c.png", "a.png").returncode == 1

    proc = springscene_cli(home, "render", "wiki.toml", "--duration", "0.4", "--fps", "10",
                           "--draft", "--out", "x.webm")
    assert proc.returncode == 0, proc.stderr
    import imageio_ffmpeg
    reader = imageio_ffmpeg.read_frames(str(home / "x.webm"))
    meta = next(reader)
    assert meta["codec"] == "vp9" and meta["size"] == (900, 600)
    assert sum(1 for _ in reader) == 4

    proc = springscene_cli(home, "figures", "wiki.toml", "--draft", "--prefix", "BallSpring_",
                           "--out", "figs")
    assert proc.returncode == 0, proc.stderr
    names = {p.name for p in (home / "figs").iterdir()}
    assert {"BallSpring_scene.png", "BallSpring_hooke.png"} <= names
    assert all(name.startswith("BallSpring_") for name in names)
    gallery = [name for name in names if name.endswith("figures.wiki")]
    assert len(gallery) == 1
    assert "BallSpring_scene.png" in (home / "figs" / gallery[0]).read_text()


def _run_example_notebook(home, name: str) -> list:
    """``springscene init NAME`` in the user's folder, every cell run there by a kernel;
    the cells' outputs, none of them an error."""
    import nbclient
    import nbformat

    proc = springscene_cli(home, "init", name)
    assert proc.returncode == 0, proc.stderr
    nb = nbformat.read(home / name, as_version=4)
    nbclient.NotebookClient(nb, timeout=600, kernel_name="python3",
                            resources={"metadata": {"path": str(home)}}).execute()
    outputs = [o for cell in nb.cells if cell.cell_type == "code" for o in cell.outputs]
    assert not [o for o in outputs if o.output_type == "error"]
    return outputs


def test_the_example_notebook_runs(home):
    """springscene init api.ipynb, then every cell run by a kernel in the user's folder:
    no errors, a still shown as a PNG and the video as an HTML5 <video>."""
    outputs = _run_example_notebook(home, "api.ipynb")
    kinds = [key for o in outputs for key in o.get("data", {})]
    assert "image/png" in kinds
    videos = [o.data["text/html"] for o in outputs if "<video" in o.get("data", {})
              .get("text/html", "")]
    assert len(videos) == 1 and "data:video/mp4;base64," in videos[0]
    assert (home / "spring.mp4").stat().st_size > 10_000
    printed = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    assert "wiki.toml: [spring] k must be > 0, got -1" in printed


# ---- the Makefile's .venv: made afresh when another Python made it --------------------------

def _make(*args: str) -> subprocess.CompletedProcess:
    if not shutil.which("make"):
        pytest.skip("no make here")
    return subprocess.run(["make", "-C", str(ROOT), *args], capture_output=True, text=True,
                          timeout=120)


def _other_python(than: str) -> str | None:
    """An interpreter whose base install differs from ``than``'s, if the machine has one."""
    who = "import sys; print(sys.base_prefix)"
    mine = subprocess.run([than, "-c", who], capture_output=True, text=True).stdout
    for candidate in sorted(Path("/root/.pyenv/versions").glob("3.1*/bin/python3")) + \
            [Path(p) for p in ("/usr/bin/python3", "/usr/local/bin/python3") if Path(p).exists()]:
        proc = subprocess.run([str(candidate), "-c", who], capture_output=True, text=True)
        if proc.returncode == 0 and proc.stdout != mine:
            return str(candidate)
    return None


def _venv_check_line(python: str) -> str:
    """The recipe line of `make setup` comparing the .venv's Python with $(PYTHON)."""
    proc = _make("-n", "-B", "setup", f"PYTHON={python}")   # -B: as if out of date
    assert proc.returncode == 0, proc.stderr
    lines = [line for line in proc.stdout.splitlines() if "!=" in line and ".venv" in line]
    assert len(lines) == 1, proc.stdout
    return lines[0]


def test_make_keeps_a_venv_made_by_the_same_python_and_remakes_another():
    """`make setup` compares the .venv's Python (base install and version) with $(PYTHON):
    the same one keeps the .venv, another one has it removed and made afresh."""
    venv_python = ROOT / ".venv" / "bin" / "python"
    if not venv_python.exists():
        pytest.skip("no .venv (made by make)")
    check = re.compile(r'\[ "([^"]*)" != "([^"]*)" \]')
    want, have = check.search(_venv_check_line(str(venv_python))).groups()
    assert want == have and len(have.split()) == 4      # base_prefix major minor micro
    other = _other_python(str(venv_python))
    if other is None:
        pytest.skip("no second Python on this machine")
    want, have2 = check.search(_venv_check_line(other)).groups()
    assert have2 == have and want != have
    who = "import sys; print(sys.base_prefix, *sys.version_info[:3])"
    assert want == subprocess.run([other, "-c", who], capture_output=True, text=True
                                  ).stdout.strip()


def test_make_refuses_a_python_older_than_3_10_and_keeps_the_venv():
    old = next((str(p) for p in sorted(Path("/root/.pyenv/versions").glob("3.[6-9]*/bin/python3"))),
               None)
    if old is None or not (ROOT / ".venv").exists():
        pytest.skip("no Python older than 3.10 here, or no .venv")
    proc = _make(str(Path(".venv") / ".installed"), f"PYTHON={old}")
    assert proc.returncode != 0
    assert "springscene needs Python 3.10 or newer" in proc.stdout
    assert (ROOT / ".venv" / "bin" / "python").exists()


def test_the_vpython_notebook_runs(home):
    """springscene init vpython.ipynb, then every cell run by a kernel: the %%vpython cells
    show the interactive page (GlowScript's library inline in an iframe) or, with --video,
    the video; the testing API measures the wiki spring's period."""
    outputs = _run_example_notebook(home, "vpython.ipynb")
    shown = [o.data["text/html"] for o in outputs if "text/html" in o.get("data", {})]
    pages = [h for h in shown if h.startswith("<iframe srcdoc=") and "glow.min.js" in h]
    videos = [h for h in shown if "<video" in h and "data:video/mp4;base64," in h]
    assert len(pages) == 3 and len(videos) == 1
    printed = "".join(o.get("text", "") for o in outputs if o.output_type == "stream")
    measured, expected = (float(x) for x in re.findall(r"([\d.]+) s", printed)[:2])
    assert abs(measured / expected - 1) < 0.02, printed
