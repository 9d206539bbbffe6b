"""springscene's Python API: what ``import springscene`` gives a script or a notebook.

The command line calls the same jobs (:mod:`springscene.jobs`); these functions take
friendlier arguments (a config by file or starter name, ``draft=True``) and return
results that show themselves in Jupyter: a still as an image, a video as an HTML5
video, a simulation as a table of columns with units.

Examples
--------
>>> import springscene
>>> cfg = springscene.load_config("wiki")           # a starter config, by name
>>> cfg.spring.k, cfg.ball.m
(15.0, 0.1)
>>> run = springscene.simulate(cfg, duration=1)
>>> len(run["t"]), run.units["y"]
(101, 'm')
>>> stiffer = cfg.replace(k=60)                     # checked like the TOML file
>>> round(springscene.analyze(stiffer)["measured"]["period"], 3)   # 2 pi sqrt(m/k)
0.256
"""

from __future__ import annotations

import gzip
import json
import os
import shutil
import sys
import tempfile
import weakref
from collections.abc import Mapping
from dataclasses import replace as _replace
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

from . import _callable, config, jobs
from .errors import OutputError, UserError
from .outputs import atomic_path
from .video import WRITE_ERRNOS, reason_of
from .results import Analysis, Run, Still, Table, Video, table
from .science.sweep import SweepResult, parse_omega
from .settings import Config
from .view.overlay import parse_overlays
from .vpython.record.reader import read as read_recording
from .vpython.run.options import check_record
from .vpython.run.runner import ProgramRaised

__all__ = ["load_config", "starters", "init", "simulate", "still", "render", "analyze", "sweep",
           "figures", "run_vpython", "Table", "Still", "Video", "Analysis", "Run", "Config",
           "UserError"]

STARTER_FOLDERS = ("configs", "examples")       # package data: springscene/configs, /examples
STARTER_SUFFIXES = (".toml", ".py", ".ipynb")


# ---- configs and starters ---------------------------------------------------------------

def _starter_files() -> dict[str, Any]:
    """Every starter shipped with the package: file name -> importlib.resources path."""
    found = {}
    for folder in STARTER_FOLDERS:
        for entry in sorted(resources.files("springscene").joinpath(folder).iterdir(),
                            key=lambda e: e.name):
            if entry.name.endswith(STARTER_SUFFIXES) and not entry.name.startswith((".", "_")):
                found.setdefault(entry.name, entry)
    return found


def _starter(name: str):
    """The starter called ``name`` (``wiki`` or ``wiki.toml``), or None."""
    files = _starter_files()
    if name in files:
        return files[name]
    for suffix in STARTER_SUFFIXES:
        if name + suffix in files:
            return files[name + suffix]
    return None


def _summary(entry) -> str:
    """A starter's first line of description: its leading comment or docstring."""
    text = entry.read_text(encoding="utf-8")
    if entry.name.endswith(".ipynb"):       # its first markdown cell's heading
        cells = json.loads(text).get("cells", [])
        first = next((c for c in cells if c.get("cell_type") == "markdown"), None)
        heading = "".join(first["source"]).splitlines()[0] if first else ""
        return "a Jupyter notebook: " + heading.lstrip("#").strip()
    for line in text.splitlines():
        line = line.strip().lstrip("#").strip().strip('"').strip()
        if line and not line.startswith(("!", "from ", "import ")):
            return line
    return ""


def starters() -> dict[str, str]:
    """The starter configs and example programs shipped with springscene.

    Returns
    -------
    dict
        File name -> its first line of description, configs first (``.toml``), then
        the example VPython programs (``.py``) and notebook (``.ipynb``).

    Examples
    --------
    >>> import springscene
    >>> names = springscene.starters()
    >>> "wiki.toml" in names, "wiki_spring.py" in names
    (True, True)
    >>> names["wiki.toml"]
    'The scene of the wiki page "Ball and Spring Model" (SI units).'
    """
    return {name: _summary(entry) for name, entry in _starter_files().items()}


def init(name: str = "wiki.toml", folder: str | Path = ".") -> Path:
    """Copy a starter config (or example program) into ``folder``; never overwrite.

    Parameters
    ----------
    name : str
        A name from :func:`starters`, with or without its suffix (``"damped"``).
    folder : str or Path
        Where to put it (the current folder by default); it must exist.

    Returns
    -------
    Path
        The new file.

    Raises
    ------
    UserError
        No such starter, no such folder, or the file is already there.

    Examples
    --------
    >>> import springscene, tempfile
    >>> folder = tempfile.mkdtemp()
    >>> springscene.init("damped", folder).name
    'damped.toml'
    >>> springscene.init("damped", folder)          # doctest: +ELLIPSIS
    Traceback (most recent call last):
    springscene.errors.UserError: .../damped.toml: already exists; init never overwrites ...
    """
    entry = _starter(str(name))
    if entry is None:
        raise UserError(f"init {name}: no such starter (choose from "
                        f"{', '.join(_starter_files())})")
    folder = Path(folder)
    if not folder.is_dir():
        raise UserError(f"init: {folder}: no such folder")
    target = folder / entry.name
    try:
        _write_new(target, entry.read_bytes())
    except FileExistsError:
        raise UserError(f"{target}: already exists; init never overwrites (remove it or "
                        "run init in another folder)") from None
    except OSError as exc:
        if exc.errno in WRITE_ERRNOS:             # no space, read-only: exit 1, as any write
            raise OutputError(reason_of(exc), target, exc.errno) from None
        raise UserError(f"{target}: cannot write ({exc.strerror})") from None
    return target


def _write_new(target: Path, data: bytes) -> None:
    """``data`` as a new file (never over one), on the disk; removed again if the write
    fails or is interrupted, so a full disk leaves no empty file."""
    with open(target, "xb") as fh:
        try:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        except BaseException:
            target.unlink(missing_ok=True)
            raise


def load_config(source: str | Path | Mapping[str, Any] | Config) -> Config:
    """Read and check a config: a TOML file, a starter's name, or a dict of sections.

    Parameters
    ----------
    source : str, Path, dict or Config
        A TOML file (``"configs/wiki.toml"``); else the name of a starter config
        (``"wiki"``, ``"damped.toml"``: :func:`starters`); or the TOML's content as a
        dict of sections (``{"spring": {"k": 20}}``, the rest the page's defaults).

    Returns
    -------
    Config
        Frozen and checked. Change it with :meth:`Config.replace`, which checks again.

    Raises
    ------
    UserError
        A one-line message naming the file (or starter), the section and the key.

    Examples
    --------
    >>> import springscene
    >>> springscene.load_config("damped").damping.b
    0.1
    >>> springscene.load_config({"spring": {"k": 20}}).spring.k
    20.0
    >>> springscene.load_config({"spring": {"k": 0}})
    Traceback (most recent call last):
    springscene.errors.UserError: <dict>: [spring] k must be > 0, got 0
    """
    if isinstance(source, Config):
        return source
    if isinstance(source, Mapping):
        return config.from_dict(dict(source), source="<dict>")
    path = Path(source)
    entry = None if path.is_file() else _starter(str(source))
    if entry is None or not entry.name.endswith(".toml"):
        return config.load(path)
    with resources.as_file(entry) as real:
        try:
            cfg = config.load(real)
        except UserError as exc:
            raise UserError(str(exc).replace(str(real), entry.name)) from None
    return _replace(cfg, source=entry.name)


def _config(cfg) -> Config:
    return cfg if isinstance(cfg, Config) else load_config(cfg)


# ---- the jobs -----------------------------------------------------------------------------

def simulate(cfg: Config | str, duration: float | None = None, out: str | Path | None = None
             ) -> Table:
    """Run the physics from t = 0 to ``duration``: one row per step, as columns.

    Parameters
    ----------
    cfg : Config or str
        A config (:func:`load_config`), or what :func:`load_config` takes.
    duration : float, optional
        Simulated seconds (default: the config's ``[render] duration``).
    out : str or Path, optional
        Also write the table as CSV there (what ``springscene simulate`` writes).

    Returns
    -------
    Table
        The ball's ``t, x, y, z, px, py, pz, K, Us, Ug, E, E_thermal`` (a lattice:
        ``t, px, py, pz, K, Us, E, E_thermal``, totals), SI units in ``.units``;
        ``pandas.DataFrame(table)`` makes a data frame.

    Examples
    --------
    >>> import springscene
    >>> run = springscene.simulate("wiki", duration=2)
    >>> float(run["t"][-1]), round(float(run["y"].min()), 4), run.units["y"]
    (2.0, -0.1854, 'm')
    """
    cfg = _config(cfg)
    return table(jobs.simulate(cfg, duration, out))


def still(cfg: Config | str, time: float = 0.0, out: str | Path | None = None, *,
          draft: bool = False, backend: str = "auto") -> Still:
    """The scene at the step nearest ``time`` (s), as an image; a PNG too if ``out``.

    Parameters
    ----------
    cfg : Config or str
        A config, or what :func:`load_config` takes.
    time : float
        Simulated seconds.
    out : str or Path, optional
        A ``.png`` to write.
    draft : bool
        No anti-aliasing (faster).
    backend : {"auto", "egl", "osmesa"}
        The off-screen OpenGL (auto: EGL when present).

    Returns
    -------
    Still
        An (height, width, 3) uint8 array that Jupyter shows as a picture.

    Examples
    --------
    >>> import springscene
    >>> cfg = springscene.load_config("wiki").replace(scene={"width": 240, "height": 160})
    >>> picture = springscene.still(cfg, time=0.25, draft=True)
    >>> picture.shape, picture.dtype.name
    ((160, 240, 3), 'uint8')
    """
    cfg = _config(cfg)
    image = jobs.still(cfg, time, out, backend=backend, antialias=not draft)
    return Still(image, path=out)


def _in_notebook() -> bool:
    return "ipykernel" in sys.modules


def render(cfg: Config | str, out: str | Path, *, duration: float | None = None,
           fps: int | None = None, speed: float | None = None,
           overlays: str | tuple[str, ...] | None = None, draft: bool = False,
           backend: str = "auto",
           progress: bool | None = None, **options: Any) -> Video:
    """Render the motion to a video file (the suffix of ``out`` chooses the format).

    Parameters
    ----------
    cfg : Config or str
        A config, or what :func:`load_config` takes.
    out : str or Path
        The video: ``.mp4`` or ``.gif`` (and what else ``springscene render`` takes).
    duration, fps, speed : optional
        Simulated seconds, frames per second, simulated seconds per video second
        (defaults: the config's ``[render]``).
    overlays : str or tuple of str, optional
        ``"time,graph,energy"`` or any subset: a clock, a y(t) graph, energy bars;
        ``"none"`` for none. Default: the command line's (a lattice gets its clock).
    draft : bool
        No anti-aliasing (faster).
    backend : {"auto", "egl", "osmesa"}
        The off-screen OpenGL.
    progress : bool, optional
        A progress bar (tqdm's: a widget in Jupyter); default on in a
        notebook or on a terminal.
    **options
        Any other option of :func:`springscene.render.render_video`.

    Returns
    -------
    Video
        The file, frame count and timing; Jupyter shows the video.

    Examples
    --------
    >>> import springscene, tempfile, os
    >>> out = os.path.join(tempfile.mkdtemp(), "spring.mp4")
    >>> cfg = springscene.load_config("wiki").replace(scene={"width": 240, "height": 160})
    >>> video = springscene.render(cfg, out, duration=0.5, fps=10, draft=True, progress=False)
    >>> video.frames, video.path.suffix, os.path.getsize(out) > 0
    (5, '.mp4', True)
    """
    cfg = _config(cfg)
    if isinstance(overlays, str):
        overlays = parse_overlays(overlays)
    if progress is None:
        progress = _in_notebook() or sys.stderr.isatty()
    stats = jobs.render(cfg, out, duration=duration, fps=fps, speed=speed, backend=backend,
                        antialias=not draft,
                        overlays=None if overlays is None else tuple(overlays),
                        progress=progress, **options)
    return Video(stats)


def analyze(cfg: Config | str, duration: float | None = None) -> Analysis:
    """Measure the run beside theory: period, amplitude, energy, ... (a lattice: its own).

    Parameters
    ----------
    cfg : Config or str
        A config, or what :func:`load_config` takes.
    duration : float, optional
        Simulated seconds (default: the config's).

    Returns
    -------
    Analysis
        A dict: ``measured`` and ``theory`` (SI), ``regime``, ``integrator``, ``dt``,
        ``duration``; ``.report()`` is the table ``springscene analyze`` prints.

    Examples
    --------
    >>> import springscene
    >>> result = springscene.analyze("wiki")
    >>> round(result["theory"]["period"], 5), round(result["measured"]["period"], 5)
    (0.51302, 0.5127)
    """
    cfg = _config(cfg)
    return Analysis(cfg, jobs.analyze(cfg, duration))


def sweep(cfg: Config | str, omega: str | np.ndarray, *, periods: float = 200,
          out: str | Path | None = None) -> SweepResult:
    """Steady-state amplitude against drive frequency, all frequencies in one batch.

    Parameters
    ----------
    cfg : Config or str
        A driven config (``"driven"``), or what :func:`load_config` takes.
    omega : str or array
        Drive frequencies in rad/s, or ``"START:STOP:N"``.
    periods : float
        Drive periods of the slowest frequency to run.
    out : str or Path, optional
        A ``.csv`` for the curve.

    Returns
    -------
    SweepResult
        ``omega``, ``amplitude`` (measured), ``theory``, ``peak``, ...

    Examples
    --------
    >>> import springscene
    >>> curve = springscene.sweep("driven", "10:14:5", periods=60)
    >>> len(curve.amplitude), round(curve.peak[0], 1)
    (5, 12.0)
    """
    cfg = _config(cfg)
    if isinstance(omega, str):
        omega = parse_omega(omega, "omega")
    return jobs.sweep(cfg, np.asarray(omega, dtype=float), periods=periods, out=out)


def figures(cfg: Config | str, out: str | Path, *, prefix: str = "", draft: bool = False,
            backend: str = "auto") -> list[Path]:
    """The config's figure set (the wiki page's, or a lattice's) into the folder ``out``.

    Parameters
    ----------
    cfg : Config or str
        A config, or what :func:`load_config` takes.
    out : str or Path
        The folder (made if missing).
    prefix : str
        Put before every file name and the names in ``figures.wiki``
        (``"BallSpring_"``: no clash on a shared wiki).
    draft : bool
        No anti-aliasing in the scene pictures.
    backend : {"auto", "egl", "osmesa"}
        The off-screen OpenGL.

    Returns
    -------
    list of Path
        The files written.
    """
    cfg = _config(cfg)
    return jobs.figures(cfg, out, backend=backend, antialias=not draft, prefix=prefix)


def run_vpython(program: str | Path, out: str | Path | None = None, *,
                duration: float | None = None, frames: int | None = None, fps: int = 50,
                draft: bool = False, backend: str = "auto", record: str | Path | None = None,
                **options: Any) -> Run | Video:
    """Run a VPython program headless: as data to test it, or to a video of its page.

    Parameters
    ----------
    program : str or Path
        A VPython 7, VPython 6 or Web VPython program.
    out : str or Path, optional
        None: nothing drawn, the run as a :class:`Run`. ``.mp4``, ``.gif``, ... or
        ``.png``: a video or still of the page, a :class:`Video`. ``.jsonl``: the
        recording alone, kept there, as a :class:`Run`.
    duration, frames, fps : optional
        Program seconds or frames to run (default 10 s or its end); frames a second.
    draft, backend, record : optional
        No anti-aliasing; the off-screen OpenGL (``"auto"``, ``"egl"``, ``"osmesa"``); a
        ``.jsonl[.gz]`` file to keep the recording in (docs/recording.md; ``Video.run``).
    **options
        Any other field of :class:`springscene.vpython.run.options.RunOptions`
        (``canvas_only``, ``page``, ``overlays``, ``quality``, ``lod``); ``timeout``,
        ``max_memory``, ``sandbox`` (a ``Sandbox``) or ``supervised=False``.

    Returns
    -------
    Run or Video
        A :class:`Run`: objects by the program's names, their attributes over the frames,
        graphs, printed text, globals. A :class:`Video`: the file, its frames, ``images``.

    Raises
    ------
    ProgramError
        The program raised: its own traceback (a test fails with it). After its first
        frame, ``error.error`` holds its type, message and time ``t``, ``error.run`` the
        :class:`Run` up to it (None for a video without ``record=``), ``error.video`` the
        :class:`Video` up to it: credit for the part that ran.

    Examples
    --------
    >>> import springscene, tempfile
    >>> program = springscene.init("projectile", tempfile.mkdtemp())
    >>> run = springscene.run_vpython(program, duration=0.5, fps=10)
    >>> run.frames, run.times[:3].tolist(), run["ball"].kind
    (5, [0.0, 0.1, 0.2], 'sphere')
    >>> run["ball"].pos.shape, run.globals["g"]
    ((5, 3), array([ 0. , -9.8,  0. ]))
    """
    run_options = dict(duration=duration, frames=frames, fps=fps, backend=backend,
                       antialias=not draft, **options)
    if out is None:
        return _as_data(program, record, run_options)
    try:
        result = jobs.vpython(program, out, record=None if record is None else str(record),
                              **run_options)
    except ProgramRaised as exc:        # the files up to the error: its run and video
        exc.run, exc.video = _output_run(exc.result) if exc.result else (None, None)
        raise
    run, video = _output_run(result)
    return run if video is None else video


def _output_run(result) -> tuple[Run | None, Video | None]:
    """A run to ``out``: its Run (the recording, ``.jsonl`` or ``record=``'s) and, for a
    video or still, its Video."""
    if result.path.suffix.lower() == ".jsonl":       # the recording alone, kept as ``out``
        return Run(read_recording(result.path), result, result.path), None
    kept = result.recording                          # (record=: the video's Run too)
    run = None if kept is None else Run(read_recording(kept), result, kept)
    return run, Video(result, run)


def _as_data(program, record, run_options: dict) -> Run:
    """The program run to a recording alone in a temporary folder, read back (and kept in
    ``record``, when given); a program's error after its first frame carries that run."""
    check_record(record)
    folder = Path(tempfile.mkdtemp(prefix="springscene-run-"))
    scratch = folder / "run.jsonl"
    try:
        result = jobs.vpython(program, scratch, **run_options)
    except ProgramRaised as exc:
        if exc.result is None:
            shutil.rmtree(folder, ignore_errors=True)
        else:
            exc.run = _scratch_run(folder, scratch, record, exc.result)
        raise
    except BaseException:
        shutil.rmtree(folder, ignore_errors=True)
        raise
    return _scratch_run(folder, scratch, record, result)


def _scratch_run(folder: Path, scratch: Path, record, result) -> Run:
    """The Run of the recording ``scratch`` (kept in ``record`` too, when given); the
    temporary ``folder`` goes with it."""
    try:
        recording = read_recording(scratch)
        if record is not None:
            _keep(scratch, Path(record))
    except BaseException:
        shutil.rmtree(folder, ignore_errors=True)
        raise
    run = Run(recording, result, record, source=scratch)
    weakref.finalize(run, shutil.rmtree, folder, True)   # the scratch copy, for its page
    return run


def _keep(recording: Path, target: Path) -> None:
    """A recording copied to ``target`` whole (gzip-compressed for a ``.gz`` name)."""
    with atomic_path(target) as tmp, open(recording, "rb") as src:
        opener = gzip.open if target.name.lower().endswith(".gz") else open
        with opener(tmp, "wb") as dst:
            shutil.copyfileobj(src, dst)


# ---- springscene.render and springscene.figures: modules, and the API's functions -------

for _name in ("render", "figures"):       # loaded by the jobs; made callable (springscene/__init__)
    _callable(_name)
