"""springscene: headless ball-and-spring scenes like VPython's, rendered off-screen.

The Python API (:mod:`springscene.api`), loaded on first use so that
``import springscene`` stays light (no VTK, no pyvista)::

    import springscene
    cfg = springscene.load_config("wiki")          # a file, a starter's name, or a dict
    run = springscene.simulate(cfg.replace(k=20), duration=2)
    picture = springscene.still(cfg, time=0.25)
    video = springscene.render(cfg, "spring.mp4", duration=1)
    lab = springscene.run_vpython("lab.py")       # a VPython program's run, as data: a Run
"""

from __future__ import annotations

import importlib
import re
import types
from pathlib import Path

_API = ("load_config", "starters", "init", "simulate", "still", "render", "analyze", "sweep",
        "figures", "run_vpython", "Table", "Still", "Video", "Analysis", "Run", "Config",
        "UserError")

__all__ = ["__version__", *_API]
_MODULE_FUNCTIONS = ("render", "figures")     # submodules that are API functions too


def _version() -> str:
    """The installed distribution's version: pyproject.toml's, the one source of truth
    (read from pyproject.toml itself in a checkout that was never installed)."""
    import importlib.metadata as metadata  # noqa: PLC0415  heavy: 50 ms before the signal handlers

    try:
        return metadata.version("springscene")
    except metadata.PackageNotFoundError:
        pyproject = Path(__file__).resolve().parent.parent / "pyproject.toml"
        found = re.search(r'^version\s*=\s*"([^"]+)"', pyproject.read_text(), re.M) \
            if pyproject.is_file() else None
        return found.group(1) if found else "0+unknown"




class _ModuleAndFunction(types.ModuleType):
    """``springscene.render`` is the render pipeline (``springscene/render.py``: ``from
    springscene import render`` gives the module) and, called, :func:`springscene.api.render`;
    ``springscene.figures`` likewise the figures package and :func:`springscene.api.figures`."""

    def __call__(self, *args, **kwargs):
        api = importlib.import_module("springscene.api")
        return getattr(api, self.__name__.rpartition(".")[2])(*args, **kwargs)


def _callable(name: str) -> types.ModuleType:
    """The submodule ``springscene.<name>`` (imported if need be), callable as the API's
    function of that name."""
    module = importlib.import_module(f"{__name__}.{name}")
    module.__class__ = _ModuleAndFunction
    return module


def __getattr__(name: str):
    if name == "__version__":     # read on first use: the start of a command stays short
        globals()["__version__"] = version = _version()   # (its signal handlers go first)
        return version
    if name in _MODULE_FUNCTIONS:          # also how `from . import render` first loads it
        return _callable(name)
    if name in _API:
        api = importlib.import_module("springscene.api")   # on first use: numpy, the jobs
        return getattr(api, name)
    raise AttributeError(f"module 'springscene' has no attribute {name!r}")


def load_ipython_extension(ipython) -> None:
    """``%load_ext springscene``: the ``%%vpython`` cell magic (:mod:`springscene.notebook`)."""
    importlib.import_module("springscene.notebook").load_ipython_extension(ipython)


def __dir__() -> list[str]:
    return sorted(set(globals()) | set(_API) | {"__version__"})
