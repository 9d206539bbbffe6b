"""A normal (non-editable) install works from anywhere: package data comes with the
package, and nothing is read from the checkout. The install is real: a fresh venv and
``pip install`` of a copy of the project, as a user does it."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from conftest import ROOT

SKIP = shutil.ignore_patterns(".venv", ".git", "renders", "build", "dist", "*.egg-info",
                              "__pycache__", ".pytest_cache", "tests", "benchmarks")


@pytest.fixture(scope="module")
def installed(tmp_path_factory) -> Path:
    """The bin folder of a fresh venv with springscene installed from a copy of the project."""
    base = tmp_path_factory.mktemp("install")
    source = base / "source"
    shutil.copytree(ROOT, source, symlinks=True, ignore=SKIP)
    venv = base / "venv"
    subprocess.run([sys.executable, "-m", "venv", str(venv)], check=True, timeout=300)
    proc = subprocess.run([str(venv / "bin" / "python"), "-m", "pip", "install", "--quiet",
                           str(source)], capture_output=True, text=True, timeout=1200)
    assert proc.returncode == 0, proc.stderr[-3000:]
    shutil.rmtree(source)           # nothing may be read from the source tree afterwards
    return venv / "bin"


def _run(bin_dir: Path, cwd: Path, *args: str) -> subprocess.CompletedProcess:
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "VIRTUAL_ENV")}
    return subprocess.run([str(bin_dir / args[0]), *args[1:]], cwd=cwd, env=env,
                          capture_output=True, text=True, timeout=600)


def test_installed_package_is_not_the_checkout(installed, tmp_path):
    proc = _run(installed, tmp_path, "python", "-c",
                "import springscene, sys; print(springscene.__file__)\n"
                "import importlib.util; print(importlib.util.find_spec('app'))")
    assert proc.returncode == 0, proc.stderr
    where, app = proc.stdout.split()
    assert "site-packages" in where and not where.startswith(str(ROOT))
    assert app == "None"           # the CLI lives in springscene.app, no top-level `app`


def test_still_and_figures_run_from_another_folder(installed, tmp_path):
    shutil.copy(ROOT / "configs" / "wiki.toml", tmp_path / "my.toml")
    proc = _run(installed, tmp_path, "springscene", "still", "my.toml", "--out", "still.png")
    assert proc.returncode == 0, proc.stderr
    assert (tmp_path / "still.png").stat().st_size > 10_000
    # the Hooke's-law figure reads overstretched.toml, the package's own data
    proc = _run(installed, tmp_path, "springscene", "figures", "my.toml", "--out", "figs",
                "--draft")
    assert proc.returncode == 0, proc.stderr
    names = {p.name for p in (tmp_path / "figs").iterdir()}
    assert {"hooke.png", "scene.png", "figures.wiki", "oscillation.gif"} <= names


def test_vpython_textures_come_with_the_package(installed, tmp_path):
    """The Earth map is package data: a GlowScript program textured with it runs from
    another folder and shows oceans."""
    (tmp_path / "earth.py").write_text("Web VPython 3.2\n"
                                       "sphere(texture=textures.earth)\n")
    proc = _run(installed, tmp_path, "springscene", "vpython", "earth.py", "--out", "e.png")
    assert proc.returncode == 0, proc.stderr
    import imageio.v3 as iio

    img = iio.imread(tmp_path / "e.png").astype(int)
    assert ((img[..., 2] > img[..., 0] + 40) & (img[..., 2] > 80)).sum() > 2000
