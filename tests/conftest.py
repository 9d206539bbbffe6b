"""Shared fixtures: the wiki config, the CLI, backends, baselines."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

# matplotlib's font cache for this venv alone: ~/.cache/matplotlib is shared by every venv
# of a user, and one made by another venv's matplotlib (the CI legs') lists other font
# files, so the figures' text came out in other glyphs (tests/baselines/figures/)
os.environ.setdefault("MPLCONFIGDIR", str(Path(sys.prefix) / "mplconfig"))
import matplotlib.font_manager  # noqa: E402,F401  the cache built here, once, not in a
                                # command under test (its "building the font cache" line)

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
    """Run the installed ``springscene`` command (the console script beside this Python) in
    a fresh process, as a user runs it (each may pick its own backend)."""
    proc = subprocess.run([str(Path(sys.executable).parent / "springscene"), *map(str, args)],
                          cwd=ROOT, capture_output=True, text=True, timeout=600)
    if check and proc.returncode != 0:
        raise AssertionError(f"springscene {' '.join(map(str, args))} failed:\n{proc.stderr}")
    return proc


def require_backend(name: str) -> None:
    """Skip when a backend's library is absent, unless CI demands every backend."""
    if not backend.library_present(name):
        if os.environ.get("SPRINGSCENE_REQUIRE_BACKENDS"):
            pytest.fail(f"{name} is required here but its library is missing")
        pytest.skip(f"{name} library not installed")


# ---- the reliability suite (tests/reliability) -------------------------------------------

RELIABILITY = Path(__file__).resolve().parent / "reliability"


def pytest_collection_modifyitems(config, items):
    """Every test in tests/reliability is marked ``reliability``: ``pytest -m reliability``
    runs that suite alone (hostile configs, signals, misbehaving programs, full disks),
    ``-m "not reliability"`` leaves it out."""
    for item in items:
        if RELIABILITY in Path(str(item.fspath)).parents:
            item.add_marker(pytest.mark.reliability)


def small_disk(tmp_path: Path, size: str):
    """A tmpfs of ``size`` (``16k``) under ``tmp_path``, as a generator for a fixture: a
    mount needs root, so the test is skipped where it cannot be made; unmounted after."""
    mount = tmp_path / f"disk-{size}"
    mount.mkdir()
    proc = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(mount)],
                          capture_output=True, text=True)
    if proc.returncode != 0:
        pytest.skip(f"cannot mount a small tmpfs here: {proc.stderr.strip()}")
    try:
        yield mount
    finally:
        subprocess.run(["umount", "-l", str(mount)], check=False)


@pytest.fixture
def tiny_disk(tmp_path):
    """A 16 kB tmpfs: room for no command's output."""
    yield from small_disk(tmp_path, "16k")
