"""springscene's pytest plugin: image regression against stored baselines, and VPython
programs run as data for a test to check.

Installed with the package (the ``pytest11`` entry point ``springscene``), it gives a
test the ``vpython_run`` fixture (below) and the ``verify_image`` fixture, in the spirit
of pytest-pyvista's ``verify_image_cache``::

    def test_scene(verify_image):
        cfg = springscene.config.load("wiki.toml")
        verify_image(springscene.render.still(cfg, 0.25), "wiki_t0.25.png")

- The first run stores the picture as the baseline (with a warning saying where); later
  runs compare against it (:func:`springscene.view.compare.compare`: at most 0.05 % of
  the pixels off by more than 24/255 in a channel, mean difference at most 0.2/255;
  each limit can be given per call).
- ``pytest --springscene-regen`` writes every picture as its new baseline.
- On a difference the test fails with the measure, and the new picture and a diff image
  (the baseline pale, the pixels off in red) are written to a folder the message names:
  ``--springscene-diffs DIR``, else ``.pytest_cache/d/springscene-diffs``.

A relative baseline name is looked up in the ``springscene_baselines`` ini folder
(relative to the root folder) when it is set, else in ``baselines/`` beside the test
file. ``springscene_missing_baseline = fail`` (ini) fails on a missing baseline instead of
storing it (for CI, where a first run should not pass by storing).

VPython programs
----------------
``vpython_run(program, **options)`` runs a VPython program headless and gives its
:class:`springscene.Run` (:func:`springscene.run_vpython` with no ``out``: the objects by
the program's names with their attributes over the frames, the graphs, what it printed,
its globals)::

    def test_the_ball_falls(vpython_run):
        run = vpython_run("drop.py", duration=1)
        assert run["ball"].pos[-1, 1] < run["ball"].pos[0, 1]

- A relative program is looked up beside the test file, then in the current folder.
- A module (or class, or test) names its program once with the ``vpython_program``
  marker, ``pytestmark = pytest.mark.vpython_program("lab.py", fps=100)``; then
  ``vpython_run()`` runs that one (options given to the call add to the marker's).
- ``pytest --springscene-program submission.py`` runs that program wherever a marker
  names one: an instructor's tests, written against their own program, check a
  student's.
- ``pytest --springscene-run run.jsonl`` runs nothing: ``vpython_run()`` (naming no
  program) is the run recorded in ``run.jsonl`` (``springscene vpython --out run.jsonl``;
  docs/recording.md), as it was recorded, whatever options the marker or the call give.
  A recording that ends at the program's error is the run up to it (``run.ended`` is
  ``"error"``, ``run.error`` says what). ``--springscene-run-failed LINE`` stands for a
  program that left no recording (it raised before its first frame, or was stopped):
  ``vpython_run()`` fails the test with LINE. ``springscene grade`` grades this way.
- ``@pytest.mark.weight(2)``: the points a test is worth in ``springscene grade``
  (default 1).
- A program is run once a session for the same options (and file contents); each test
  that asks again gets the same :class:`~springscene.Run`, or the same error (a program
  that raised fails each test with its traceback).
- The run is supervised, as ``springscene vpython``'s (a child process; ``timeout`` and
  ``max_memory`` options stop a program that runs away).
"""

from __future__ import annotations

import importlib
import re
import warnings
from pathlib import Path

import numpy as np
import pytest

import springscene

from .outputs import write_png
from .view.compare import (MAX_MEAN_DIFF, PIXEL_TOLERANCE, TOLERANCE, compare, diff_image,
                           read_image)

DIFF_FOLDER = "springscene-diffs"
PROGRAM_MARKER = "vpython_program"
WEIGHT_MARKER = "weight"
_RUNS = pytest.StashKey[dict]()    # a session's VPython runs: (file, options) -> (run, error)
_configs: list = []      # the running sessions' configs, innermost last (verify() outside fixtures)


class BaselineStoredWarning(UserWarning):
    """A test stored its picture as a new baseline (none existed)."""


def pytest_addoption(parser) -> None:
    group = parser.getgroup("springscene", "springscene image regression")
    group.addoption("--springscene-regen", action="store_true", dest="springscene_regen",
                    help="write the pictures verify_image is given as the new baselines")
    group.addoption("--springscene-diffs", dest="springscene_diffs", metavar="DIR",
                    help="folder for the new picture and the diff image of a failed "
                    "comparison (default .pytest_cache/d/springscene-diffs)")
    group.addoption("--springscene-program", dest="springscene_program", metavar="PROGRAM",
                    help="run this VPython program wherever a test's vpython_program "
                    "marker names one (an instructor's tests on a student's program)")
    group.addoption("--springscene-run", dest="springscene_run", metavar="RECORDING",
                    help="run nothing: vpython_run() naming no program gives the run "
                    "recorded in RECORDING (.jsonl or .jsonl.gz, springscene vpython --out "
                    "run.jsonl)")
    group.addoption("--springscene-run-failed", dest="springscene_run_failed",
                    metavar="LINE", help="the program left no recording: vpython_run() "
                    "naming no program fails the test with LINE")
    parser.addini("springscene_baselines", "folder of the baseline pictures, relative to the "
                  "root folder (default: baselines/ beside each test file)", default="")
    parser.addini("springscene_missing_baseline", "store (default) or fail when a baseline "
                  "is missing", default="store")


def pytest_configure(config) -> None:
    _configs.append(config)
    config.stash[_RUNS] = {}
    config.addinivalue_line("markers", f"{PROGRAM_MARKER}(program, **options): the VPython "
                            "program (and springscene.run_vpython options) that vpython_run() "
                            "runs; a relative path is beside the test file")
    config.addinivalue_line("markers", f"{WEIGHT_MARKER}(points): what the test is worth "
                            "in springscene grade (default 1)")
    recording = config.getoption("springscene_run", None)
    if recording and not Path(config.invocation_params.dir, recording).is_file():
        raise pytest.UsageError(f"--springscene-run {recording}: no such recording")


def pytest_unconfigure(config) -> None:
    if config in _configs:
        _configs.remove(config)


def _current():
    return _configs[-1] if _configs else None


def diff_folder(config=None) -> Path:
    """Where failed comparisons leave their pictures."""
    config = config if config is not None else _current()
    if config is None:
        return Path(DIFF_FOLDER).resolve()
    given = config.getoption("springscene_diffs", None)
    if given:
        return Path(given).resolve()
    cache = getattr(config, "cache", None)
    if cache is not None:
        return Path(cache.mkdir(DIFF_FOLDER))
    return Path(config.rootpath) / DIFF_FOLDER


def regenerating(config=None) -> bool:
    """Whether ``--springscene-regen`` was given."""
    config = config if config is not None else _current()
    return bool(config is not None and config.getoption("springscene_regen", False))


def _as_image(image) -> np.ndarray:
    if isinstance(image, (str, Path)):
        return read_image(image)
    image = np.asarray(image)
    if image.dtype != np.uint8:
        raise TypeError(f"verify_image: a uint8 picture, not {image.dtype}")
    return image


def _flat_name(baseline: Path, root: Path | None) -> str:
    """The baseline's name for the diff folder: its path below ``root`` with ``__``."""
    try:
        rel = baseline.resolve().relative_to(root) if root is not None else Path(baseline.name)
    except ValueError:
        rel = Path(baseline.name)
    return re.sub(r"[^\w.-]", "_", "__".join(rel.with_suffix("").parts))


def verify(image, baseline: str | Path, *, regen: bool | None = None,
           missing: str = "store", tolerance: float = TOLERANCE,
           pixel_tolerance: int = PIXEL_TOLERANCE, max_mean: float = MAX_MEAN_DIFF,
           diffs: str | Path | None = None) -> None:
    """Compare ``image`` (an array or a picture file) with the picture at ``baseline``.

    Stores it there when ``regen`` (default: ``--springscene-regen``), or when there is
    none and ``missing`` is "store"; raises AssertionError, having written the picture and
    its diff image into ``diffs`` (default :func:`diff_folder`), when they differ.
    """
    __tracebackhide__ = True
    baseline = Path(baseline)
    image = _as_image(image)
    regen = regenerating() if regen is None else regen
    if regen or not baseline.exists():
        if not regen and missing != "store":
            raise AssertionError(f"no baseline {baseline}; run pytest with --springscene-regen")
        baseline.parent.mkdir(parents=True, exist_ok=True)
        write_png(baseline, image)
        if not regen:
            warnings.warn(BaselineStoredWarning(f"stored a new baseline {baseline}"),
                          stacklevel=2)
        return
    reference = read_image(baseline)
    result = compare(image, reference, tolerance=tolerance, pixel_tolerance=pixel_tolerance,
                     max_mean=max_mean)
    if result.alike:
        return
    folder = Path(diffs) if diffs is not None else diff_folder()
    folder.mkdir(parents=True, exist_ok=True)
    config = _current()
    name = _flat_name(baseline, Path(config.rootpath) if config is not None else None)
    write_png(folder / f"{name}.png", image[..., :3] if image.ndim == 3 else image)
    written = f"{folder / name}.png"
    if result.same_size:
        write_png(folder / f"{name}-diff.png", diff_image(image, reference, pixel_tolerance))
        written += f" and {name}-diff.png"
    raise AssertionError(f"{baseline.name}: {result.summary()}; the new picture: {written} "
                         f"(pytest --springscene-regen makes it the baseline)")


class ImageVerifier:
    """The ``verify_image`` fixture: ``verify_image(image, "name.png", **limits)``."""

    def __init__(self, request) -> None:
        self.config = request.config
        folder = self.config.getini("springscene_baselines")
        self.folder = (Path(self.config.rootpath) / folder if folder
                       else Path(request.path).parent / "baselines")
        self.missing = self.config.getini("springscene_missing_baseline")
        if self.missing not in ("store", "fail"):
            raise pytest.UsageError(f"springscene_missing_baseline = {self.missing!r}: "
                                    "use store or fail")

    def __call__(self, image, baseline: str | Path, **limits) -> None:
        __tracebackhide__ = True
        path = Path(baseline)
        if not path.is_absolute():
            path = self.folder / path
        verify(image, path, regen=regenerating(self.config), missing=self.missing,
               diffs=diff_folder(self.config), **limits)


@pytest.fixture
def verify_image(request) -> ImageVerifier:
    """Compare a picture with its stored baseline (stored on the first run); see
    :mod:`springscene.pytest_plugin`."""
    return ImageVerifier(request)


# ---- VPython programs as data: the vpython_run fixture ----------------------------------------

class ProgramRuns:
    """The ``vpython_run`` fixture: ``vpython_run(program=None, **options)`` is the
    program's :class:`springscene.Run` (the module's docstring)."""

    def __init__(self, request) -> None:
        self.request = request
        self.config = request.config
        self.runs: dict = self.config.stash.get(_RUNS, {})

    def __call__(self, program: str | Path | None = None, **options):
        __tracebackhide__ = True
        if "out" in options:
            raise TypeError("vpython_run: no out (it gives the run as data; "
                            "springscene.run_vpython writes videos)")
        if program is None:
            recorded = self._recorded()
            if recorded is not None:
                return recorded
            program, options = self._marked(options)
        path = self._locate(Path(program))
        key = (str(path.resolve()), *_stamp(path), repr(sorted(options.items())))
        if key not in self.runs:
            self.runs[key] = self._run(path, options)
        run, error = self.runs[key]
        if error is not None:
            raise error.with_traceback(None)
        return run

    def _recorded(self):
        """The run ``--springscene-run`` names (read once a session), or None without it;
        ``--springscene-run-failed`` fails the test with its line."""
        __tracebackhide__ = True
        failed = self.config.getoption("springscene_run_failed", None)
        if failed:
            pytest.fail(failed, pytrace=False)
        given = self.config.getoption("springscene_run", None)
        if not given:
            return None
        path = Path(self.config.invocation_params.dir, given)
        key = ("recording", str(path.resolve()))
        if key not in self.runs:
            self.runs[key] = (read_run(path), None)
        return self.runs[key][0]

    def _marked(self, options: dict) -> tuple[str | Path, dict]:
        """The program the closest ``vpython_program`` marker names (``--springscene-program``
        in its place, when given), and its options with the call's."""
        marker = self.request.node.get_closest_marker(PROGRAM_MARKER)
        if marker is None or not marker.args:
            pytest.fail(f"vpython_run() names no program and {self.request.node.nodeid} has "
                        f"no {PROGRAM_MARKER} marker: call vpython_run('lab.py') or mark the "
                        f"module, pytestmark = pytest.mark.{PROGRAM_MARKER}('lab.py')",
                        pytrace=False)
        given = self.config.getoption("springscene_program", None)
        program = Path(self.config.invocation_params.dir, given) if given else marker.args[0]
        return program, {**marker.kwargs, **options}

    def _locate(self, program: Path) -> Path:
        """A relative program beside the test file, else from the current folder."""
        if not program.is_absolute():
            beside = Path(self.request.path).parent / program
            if beside.is_file():
                return beside
        return program

    @staticmethod
    def _run(path: Path, options: dict) -> tuple:
        """(the run, None), or (None, the error) for a program that raised or ended badly."""
        try:                     # (springscene's API loads on this first use, not with pytest)
            return springscene.run_vpython(path, **options), None
        except Exception as exc:        # ProgramError (its traceback), UserError, RunEnded
            return None, exc


def read_run(recording: Path):
    """The :class:`springscene.Run` recorded in ``recording`` (springscene's API and the
    recording's reader loaded on this first use, not with pytest)."""
    reader = importlib.import_module("springscene.vpython.record.reader")
    return springscene.Run(reader.read(recording), None, recording)


def _stamp(path: Path) -> tuple:
    """The file's modification time and size (a program edited during a session runs again);
    a missing file is left for the run to name."""
    try:
        st = path.stat()
    except OSError:
        return (None, None)
    return (st.st_mtime_ns, st.st_size)


@pytest.fixture
def vpython_run(request) -> ProgramRuns:
    """Run a VPython program headless and get its :class:`springscene.Run`; see
    :mod:`springscene.pytest_plugin`."""
    return ProgramRuns(request)
