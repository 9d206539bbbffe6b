"""Shared fixtures: the wiki config, the CLI, backends, baselines."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from springscene import config
from springscene.view import backend

ROOT = Path(__file__).resolve().parent.parent
WIKI = ROOT / "configs" / "wiki.toml"
BASELINES = Path(__file__).resolve().parent / "baselines"


def pytest_addoption(parser):
    parser.addoption("--regen-baselines", action="store_true",
                     help="write the images the tests render as the new baselines")


@pytest.fixture
def regen(request) -> bool:
    return request.config.getoption("--regen-baselines")


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
