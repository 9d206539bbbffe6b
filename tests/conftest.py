"""Shared fixtures: the wiki config, the CLI, backends, baselines."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

if sys.version_info < (3, 11):    # the tests read TOML with tomllib; tomli is the same parser
    import tomli
    sys.modules.setdefault("tomllib", tomli)

from springscene import config, pytest_plugin  # noqa: E402
from springscene.view import backend

ROOT = Path(__file__).resolve().parent.parent
WIKI = ROOT / "configs" / "wiki.toml"
BASELINES = Path(__file__).resolve().parent / "baselines"


def pytest_addoption(parser):
    parser.addoption("--regen-baselines", action="store_true",
                     help="write the images the tests render as the new baselines "
                     "(the same as springscene's plugin's --springscene-regen)")


def pytest_configure(config):
    if config.getoption("--regen-baselines"):
        config.option.springscene_regen = True


@pytest.fixture
def regen(request) -> bool:
    """Whether to write baselines (--regen-baselines or --springscene-regen)."""
    return pytest_plugin.regenerating(request.config)


@pytest.fixture(scope="session")
def wiki_cfg():
    return config.load(WIKI)


def run_cli(*args, check=False):
    """Run the real console entry point in a fresh process (each may pick its own backend)."""
    proc = subprocess.run([sys.executable, "-m", "app", *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, timeout=600)
    if check and proc.returncode != 0:
        raise AssertionError(f"springscene {' '.join(map(str, args))} failed:\n{proc.stderr}")
    return proc


def require_backend(name: str) -> None:
    """Skip when a backend's library is absent, unless CI demands every backend."""
    if not backend.library_present(name):
        if os.environ.get("SPRINGSCENE_REQUIRE_BACKENDS"):
            pytest.fail(f"{name} is required here but its library is missing")
        pytest.skip(f"{name} library not installed")
