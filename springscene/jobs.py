"""The jobs a user runs, as library calls: the command line and a notebook call the same.

Each takes a checked :class:`~springscene.settings.Config` (:func:`springscene.config.load`)
and chooses, where a lattice of atoms and the page's single ball differ, the right
science and drawing:

- :func:`simulate`: the run as numbers (a trajectory, or a lattice's totals), and CSV;
- :func:`still`, :func:`render`: a picture and a video (:mod:`springscene.render`);
- :func:`analyze` and :func:`report`: what the run measures beside theory;
- :func:`sweep`: a resonance curve;
- :func:`figures`: the wiki page's figure set, or a lattice's;
- :func:`vpython`: a VPython program run headless.
"""

from __future__ import annotations

import json
import time
from typing import Callable
from pathlib import Path

import numpy as np

from . import render as pipeline
from .figures import make_figures as oscillator_figures
from .figures.files import figure_set
from .figures.gallery import check_prefix
from .figures.matter import make_figures as matter_figures
from .model import physics
from .outputs import check_output
from .science import analysis, matter
from .science import sweep as sweeps
from .errors import UserError
from .settings import Config
from .vpython.page.scene_recording import write_scene_page
from .vpython.run.options import RunOptions
from .vpython.run.runner import ProgramResult, run_program
from .vpython.run.supervise import run_supervised

RenderStats = pipeline.RenderStats


def simulate(cfg: Config, duration: float | None = None, out: str | Path | None = None
             ) -> physics.Trajectory | np.ndarray:
    """The run from t = 0 to ``duration`` (default: the config's), one row per step,
    written as CSV to ``out`` when given: the ball's trajectory, or a lattice's totals."""
    path = check_output(out, (".csv",)) if out is not None else None
    result = pipeline.simulate(cfg, duration)
    if path is not None:
        pipeline.write_csv(result, path)
    return result


def still(cfg: Config, time_s: float = 0.0, out: str | Path | None = None, *,
          backend: str = "auto", antialias: bool = True) -> np.ndarray:
    """The scene at the step nearest ``time_s`` as an (h, w, 3) image, and PNG at ``out``."""
    return pipeline.still(cfg, time_s, out, backend=backend, antialias=antialias)


def render(cfg: Config, out: str | Path, **options) -> pipeline.RenderStats:
    """The motion as MP4, WebM, Ogg or GIF (options: :func:`springscene.render.render_video`'s),
    or as ``.html``: the interactive VPython page of the scene (its holder, spring and ball
    as VPython's box, helix and sphere, drawn by GlowScript; options ``duration``, ``fps``
    and ``speed``, the others being the video's)."""
    if str(out).lower().endswith(".html"):
        path = check_output(out, (".html",))
        start = time.perf_counter()
        frames = write_scene_page(cfg, path, duration=options.get("duration"),
                                  fps=options.get("fps"), speed=options.get("speed"))
        seconds = time.perf_counter() - start
        fps = options.get("fps") or cfg.render.fps
        return pipeline.RenderStats(path, frames, fps, seconds, seconds)
    return pipeline.render_video(cfg, out, **options)


def analyze(cfg: Config, duration: float | None = None) -> dict:
    """Measured and theoretical quantities of the run (SI), the lattice's or the ball's."""
    if cfg.is_lattice:
        return matter.analyze(cfg, duration)
    return analysis.analyze(cfg, duration)


def report(cfg: Config, result: dict, as_json: bool = False) -> str:
    """:func:`analyze`'s result as a table, or as JSON."""
    if cfg.is_lattice:
        return json.dumps(result, indent=2) if as_json else matter.table(result)
    if as_json:
        keys = ("measured", "theory", "unit", "regime", "integrator", "dt", "dt_unit",
                "duration", "duration_unit")
        return json.dumps({key: result[key] for key in keys}, indent=2)
    return analysis.table(result)


def sweep(cfg: Config, omega: np.ndarray, *, periods: float = 200,
          out: str | Path | None = None) -> sweeps.SweepResult:
    """Steady-state amplitude against drive frequency; CSV at ``out`` when given."""
    path = check_output(out, (".csv",)) if out is not None else None
    result = sweeps.sweep(cfg, omega, periods=periods)
    if path is not None:
        sweeps.write_csv(result, path)
    return result


def figures(cfg: Config, out: str | Path, *, backend: str = "auto",
            antialias: bool = True, prefix: str = "") -> list[Path]:
    """The figure set of the config into the folder ``out``: the wiki page's, or a lattice's.

    The set is built in a private folder and replaces the old set whole at the end
    (:func:`springscene.figures.files.figure_set`): a run that fails or is interrupted
    leaves ``out`` as it was. ``prefix`` goes before every file name (and the names in
    ``figures.wiki``)."""
    check_prefix(prefix)
    with figure_set(out) as staging:
        if cfg.is_lattice:
            written = matter_figures(cfg, staging, prefix=prefix)
        else:
            written = oscillator_figures(cfg, staging, backend=backend, antialias=antialias,
                                         prefix=prefix)
    return [staging.parent / path.name for path in written]


def vpython(program: str | Path, out: str | Path, *, supervised: bool = True,
            timeout: float | None = None, max_memory: int | str | None = None,
            on_frame: Callable | None = None, on_dialect: Callable | None = None,
            sandbox=None, **options) -> ProgramResult:
    """Run a VPython program headless to a video or still; ``options`` are the fields of
    :class:`springscene.vpython.run.options.RunOptions`. Supervised (the default), it runs
    in a child process that cannot leave anything behind, with ``timeout`` and
    ``max_memory`` (:func:`springscene.vpython.run.supervise.run_supervised`), in
    ``sandbox`` (a :class:`springscene.vpython.run.sandbox.Sandbox`) if given; otherwise
    in this process (``on_frame`` needs that)."""
    if "overlays" in options:
        options["overlays"] = tuple(options["overlays"])
    run_options = RunOptions(**options)
    if supervised and on_frame is None:
        return run_supervised(program, out, run_options, timeout=timeout,
                              max_memory=max_memory, on_dialect=on_dialect, sandbox=sandbox)
    unsupervised = [name for name, value in (("timeout", timeout), ("max_memory", max_memory),
                                             ("sandbox", sandbox)) if value is not None]
    if unsupervised:
        raise UserError(f"{', '.join(unsupervised)}: only a supervised run has them "
                        "(not with on_frame or supervised=False)")
    return run_program(program, out, run_options, on_frame=on_frame, on_dialect=on_dialect)
