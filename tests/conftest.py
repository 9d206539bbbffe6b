"""Shared fixtures: the wiki config, the CLI (in a new process or in this one), backends,
baselines; and the two tiers of tests.

The tiers
---------
``make test`` runs every test. ``make test-fast`` (``pytest -m "not slow"``) leaves out the
tests marked ``slow``, and touches every layer in under a minute. The marks are put here,
at every collection (:func:`pytest_collection_modifyitems`), by four rules, each read off
the test itself or from one list in this file:

1. **Place** (:data:`SLOW_PLACES`): the reliability suite (``tests/reliability``, marked
   ``reliability`` too), the installs (``tests/test_clean_install.py``,
   ``tests/app/test_install.py``) and the README's commands run as written
   (``tests/app/test_readme.py``).
2. **A new Python started by the test**: a test whose code (its own, that of the fixtures
   it uses, and that of the functions of its module these call) names ``run_cli`` or
   ``sys.executable`` (:data:`STARTS_PYTHON`).
3. **Long runs** (:data:`LONG_TESTS`): tests that run long in this process (whole videos
   and pictures at full size, long physics), named with the seconds they took.
4. **By hand**: ``@pytest.mark.slow`` on a test whose new Python the rules above cannot
   see: one that springscene's own code starts (a supervised ``springscene vpython`` run,
   whose program runs in a child interpreter), or one started through a path (a console
   script of the venv).

The list of rule 3 is committed rather than measured at each run: timings change with the
machine and its load, and the tiers must be the same on every run and every machine. Two
checks keep the rules from rotting:

- **The guard** (:func:`_guarded_execute_child`): in a test not marked slow, starting a
  Python interpreter (``sys.executable``, any ``python*``, a ``#!...python`` script, the
  ``springscene`` command) or forking this process fails the test, saying to mark it slow
  or run it in-process. Other programs are let through: springscene's ffmpeg (the video
  tests stay in the fast tier), ``mount``. A Python started by springscene's own code (a
  supervised VPython run) is caught as well: it costs a second or two like any other.
- **Timings** (:func:`pytest_terminal_summary`): a test of the fast tier whose call took
  over :data:`FAST_LIMIT_S` is named at the end of the run (a note, not a failure: a
  loaded machine would fail sound tests); an entry of :data:`LONG_TESTS` naming no test of
  its file is an error at collection. (An entry is not checked for having become quick: in
  a whole run a test's time depends on which test made the module's shared fixtures
  first, so that check named sound entries.)
"""

from __future__ import annotations

import contextlib
import inspect
import logging
import os
import re
import shutil
import signal
import subprocess
import sys
import warnings
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
from springscene.app import cli as springscene_cli
from springscene.view import backend

ROOT = Path(__file__).resolve().parent.parent
WIKI = ROOT / "configs" / "wiki.toml"
BASELINES = Path(__file__).resolve().parent / "baselines"


def pytest_addoption(parser):
    parser.addoption("--regen-baselines", action="store_true",
                     help="write the images the tests render as the new baselines "
                     "(the same as springscene's plugin's --springscene-regen)")


@pytest.fixture
def regen(request) -> bool:
    """Whether to write baselines (--regen-baselines or --springscene-regen)."""
    return pytest_plugin.regenerating(request.config)


@pytest.fixture(scope="session")
def wiki_cfg():
    return config.load(WIKI)


def process_alive(pid: int) -> bool:
    """Running (a zombie no reaper has collected yet counts as dead)."""
    try:
        state = Path(f"/proc/{pid}/stat").read_text().rsplit(")", 1)[1].split()[0]
    except OSError:
        return False
    return state != "Z"


def run_cli(*args, check=False):
    """Run the installed ``springscene`` command (the console script beside this Python) in
    a fresh process, as a user runs it (each may pick its own backend)."""
    proc = subprocess.run([str(Path(sys.executable).parent / "springscene"), *map(str, args)],
                          cwd=ROOT, capture_output=True, text=True, timeout=600)
    if check and proc.returncode != 0:
        raise AssertionError(f"springscene {' '.join(map(str, args))} failed:\n{proc.stderr}")
    return proc


# Python's own warning filters when no -W option is given: a command run in a new process
# shows its warnings by these (pytest's, in this process, would record them instead)
PYTHON_WARNING_FILTERS = [("default", DeprecationWarning, "__main__"),
                          ("ignore", DeprecationWarning, ""),
                          ("ignore", PendingDeprecationWarning, ""),
                          ("ignore", ImportWarning, ""),
                          ("ignore", ResourceWarning, "")]
STOP_SIGNALS = (signal.SIGINT, signal.SIGTERM, signal.SIGHUP)


def default_stop_signals() -> None:
    """(A ``preexec_fn``) the stop signals at their defaults and unblocked in the child,
    whatever the tests inherited: a shell's background job ignores SIGINT, and springscene
    keeps a signal ignored when it started ignored, so a test that stops a command with
    SIGINT would wait for it to end by itself."""
    for signum in STOP_SIGNALS:
        signal.signal(signum, signal.SIG_DFL)
    signal.pthread_sigmask(signal.SIG_UNBLOCK, STOP_SIGNALS)
# the process's off-screen backend (springscene.view.backend.select): chosen once for the
# process, with backend._selected, so it stays after a command as the choice does
PROCESS_WIDE_ENV = ("VTK_DEFAULT_OPENGL_WINDOW",)


class _LastResortLogging(logging.Handler):
    """What Python does with a library's log record of WARNING or above when nothing is
    configured (``logging.lastResort``): the message alone, on the stderr of the moment."""

    def __init__(self) -> None:
        super().__init__(logging.WARNING)

    def emit(self, record: logging.LogRecord) -> None:
        sys.stderr.write(self.format(record) + "\n")


def _exit_status(code) -> int:
    """The status a process leaving with ``SystemExit(code)`` has, as Python gives it (a
    message for a code that is not a number goes to stderr)."""
    if code is None:
        return 0
    if isinstance(code, int):
        return code
    print(code, file=sys.stderr)
    return 1


@contextlib.contextmanager
def _as_a_new_process():
    """Run a command as in a process of its own, and leave this one as it was: the working
    folder ``run_cli``'s process has (the checkout), Python's default warnings shown on
    stderr, a library's log warnings on stderr; afterwards the folder, the environment (but
    :data:`PROCESS_WIDE_ENV`), the stop signals' handlers, matplotlib's settings and
    logging's switch put back, whatever the command did to them."""
    folder, environ = os.getcwd(), dict(os.environ)
    handlers = {s: signal.getsignal(s) for s in STOP_SIGNALS}
    unraisable, disabled = sys.unraisablehook, logging.root.manager.disable
    log = _LastResortLogging()
    logging.root.addHandler(log)
    try:
        with warnings.catch_warnings(record=True) as caught, matplotlib.rc_context():
            warnings.resetwarnings()
            for action, category, module in reversed(PYTHON_WARNING_FILTERS):
                warnings.filterwarnings(action, category=category, module=module)
            os.chdir(ROOT)
            yield
        for w in caught:
            sys.stderr.write(warnings.formatwarning(w.message, w.category, w.filename,
                                                    w.lineno, w.line))
    finally:
        logging.root.removeHandler(log)
        logging.disable(disabled)
        sys.unraisablehook = unraisable
        for signum, handler in handlers.items():
            if signal.getsignal(signum) is not handler:
                signal.signal(signum, handler)
        kept = {k: os.environ[k] for k in PROCESS_WIDE_ENV if k in os.environ}
        os.environ.clear()
        os.environ.update({**environ, **kept})
        os.chdir(folder)


@pytest.fixture
def cli(capfd):
    """springscene's command line run in this process: ``cli(*args, check=False)`` gives
    what :func:`run_cli` gives (a ``CompletedProcess``: ``returncode``, ``stdout``,
    ``stderr``) without starting a Python. It calls :func:`springscene.app.cli.main`, which
    maps every error to its line and status, not the command's entry
    (:func:`springscene.app.signals.main`), whose signal handlers are the process's and
    would outlive the command here. An argparse exit (a usage error, ``--version``) is the
    status the process would exit with; an exception out of ``main`` (a bug) fails the
    test. Both stdout and stderr are captured at the file descriptors (ffmpeg's and VTK's
    own lines included), so the test cannot use ``capsys`` too; what the test printed
    before a call is not part of that call's output."""

    def run(*args, check=False) -> subprocess.CompletedProcess:
        argv = [str(a) for a in args]
        capfd.readouterr()
        with _as_a_new_process():
            try:
                status = springscene_cli.main(argv)
            except SystemExit as leaving:
                status = _exit_status(leaving.code)
        out, err = capfd.readouterr()
        if check and status != 0:
            raise AssertionError(f"springscene {' '.join(argv)} failed:\n{err}")
        return subprocess.CompletedProcess(["springscene", *argv], status, out, err)

    return run


def require_backend(name: str) -> None:
    """Skip when a backend's library is absent, unless CI demands every backend."""
    if not backend.library_present(name):
        if os.environ.get("SPRINGSCENE_REQUIRE_BACKENDS"):
            pytest.fail(f"{name} is required here but its library is missing")
        pytest.skip(f"{name} library not installed")


# ---- the tiers (the module's docstring) ----------------------------------------------------

TESTS = Path(__file__).resolve().parent
RELIABILITY = TESTS / "reliability"
SLOW_PLACES = (RELIABILITY, TESTS / "test_clean_install.py", TESTS / "app" / "test_install.py",
               TESTS / "app" / "test_readme.py")
STARTS_PYTHON = {"run_cli", "executable"}           # run_cli(...), sys.executable
FAST_LIMIT_S = 1.0       # a fast test's call over this is named at the end of the run

# rule 3: tests that run long in this process, with the seconds each took (all its cases)
# in the fast tier's runs that made this list, on 2 shared cores: every test that took 0.6 s
# or more there but two pictures kept for the fast tier's image regression
# (tests/view/test_render.py)
LONG_TESTS = {
    "tests/figures/test_figures.py::test_closed_form_matches_rk4_for_damped_and_driven_configs": 2.8,
    "tests/figures/test_figures.py::test_hooke_figure": 0.6,
    "tests/figures/test_figures.py::test_integrators_energy_error": 1.1,
    "tests/figures/test_figures.py::test_integrators_figure": 0.8,
    "tests/figures/test_figures.py::test_saved_figures_are_the_same_bytes_every_time": 1.4,
    "tests/model/test_dynamics.py::test_analyze_table_cli": 0.6,
    "tests/model/test_dynamics.py::test_damped_energy_bookkeeping_with_spring": 3.3,
    "tests/model/test_dynamics.py::test_damped_motion_matches_closed_form": 1.1,
    "tests/model/test_dynamics.py::test_driven_analyze_measures_gamma_in_the_steady_state": 3.2,
    "tests/model/test_dynamics.py::test_driven_steady_state": 1.2,
    "tests/model/test_dynamics.py::test_energy_behaviour_of_each_integrator": 0.8,
    "tests/model/test_dynamics.py::test_permanent_set_beyond_elastic_limit": 1.1,
    "tests/model/test_dynamics.py::test_sweep_against_analytic_curve": 0.8,
    "tests/model/test_lattice.py::test_energy_stays_bounded_with_euler_cromer": 0.7,
    "tests/model/test_physics.py::test_energy_bounded_over_100_periods": 0.6,
    "tests/science/test_matter.py::test_cli_analyze_table": 0.7,
    "tests/science/test_matter.py::test_cli_figures": 0.9,
    "tests/science/test_matter.py::test_cli_figures_leave_nothing_on_error": 0.9,
    "tests/science/test_matter.py::test_dispersion_every_mode": 3.9,
    "tests/science/test_matter.py::test_dispersion_run_lengthened_or_refused": 1.9,
    "tests/science/test_matter.py::test_dispersion_zone_edge_is_two_omega0": 2.4,
    "tests/science/test_matter.py::test_equipartition": 0.6,
    "tests/science/test_matter.py::test_speed_of_sound": 3.5,
    "tests/science/test_matter.py::test_speed_of_sound_free_ends": 0.8,
    "tests/science/test_matter.py::test_temperature_is_half_the_start": 0.8,
    "tests/science/test_matter.py::test_youngs_modulus": 1.4,
    "tests/science/test_matter.py::test_youngs_modulus_refuses_an_unsettled_bar": 0.7,
    "tests/test_api.py::test_render_is_a_video_that_jupyter_shows": 1.0,
    "tests/test_api.py::test_the_documented_examples_run": 0.9,
    "tests/test_architecture.py::test_no_module_or_function_is_too_long": 0.8,
    "tests/test_grade.py::test_springscene_run_gives_the_recordings_run_and_nothing_runs": 2.7,
    "tests/test_readers.py::test_figures_with_a_prefix": 7.8,
    "tests/test_readers.py::test_lattice_video_has_its_clock_by_default": 1.3,
    "tests/test_video_outputs.py::test_a_full_disk_is_one_line_exit_1_and_nothing_left": 2.0,
    "tests/test_video_outputs.py::test_fps_above_the_physics_rate_warns_on_one_line": 1.3,
    "tests/test_video_outputs.py::test_quality_presets_differ_in_size": 2.9,
    "tests/test_video_outputs.py::test_render_writes_webm_and_ogg_a_wiki_takes": 1.0,
    "tests/view/test_lattice_scene.py::test_color_bar_is_drawn_with_its_title_and_scale": 0.9,
    "tests/view/test_lattice_scene.py::test_each_bond_style_renders_and_differs": 0.7,
    "tests/view/test_lattice_scene.py::test_update_rewrites_the_same_objects_in_place": 1.3,
    "tests/vpython/test_fidelity.py::test_real_vpythons_id_picture_shows_every_object": 0.7,
    "tests/vpython/test_fidelity.py::test_springscene_against_real_vpython": 6.5,
    "tests/vpython/test_interactive_page.py::test_the_atomic_solid_page_is_at_most_5_mb": 2.6,
    "tests/vpython/test_trails.py::test_thin_default_trails_against_real_vpython": 3.5,
    "tests/vpython/test_trails.py::test_thin_trails_drawn_through_real_vpythons_points": 3.8,
    "tests/vpython/test_trails.py::test_thin_trails_have_real_vpythons_points": 3.3,
    "tests/vpython/test_vpython_dialects.py::test_glowscript_spring_lab_moves_the_ball_and_plots": 1.8,
    "tests/vpython/test_vpython_dialects.py::test_vpython6_bounce_with_a_frame": 1.8,
    "tests/vpython/test_vpython_dialects.py::test_vpython6_controls_wait_for_no_one": 0.7,
    "tests/vpython/test_vpython_followers.py::test_rate_above_the_machine_runs_at_the_machines_pace": 1.1,
    "tests/vpython/test_vpython_graph.py::test_graph_strip_stacks_graphs": 2.3,
    "tests/vpython/test_vpython_helix_capsules.py::test_helix_capsules_draw_the_full_meshes": 3.1,
    "tests/vpython/test_vpython_impostors.py::test_a_negative_radius_keeps_its_mesh": 1.0,
    "tests/vpython/test_vpython_impostors.py::test_every_frame_shows_the_spheres_as_the_camera_comes_and_goes": 0.6,
    "tests/vpython/test_vpython_impostors.py::test_impostors_draw_the_full_detail_spheres": 16.0,
    "tests/vpython/test_vpython_instanced.py::test_instances_draw_the_placed_meshes_picture": 0.9,
    "tests/vpython/test_vpython_labels.py::test_labels_match_real_vpythons_picture": 2.5,
    "tests/vpython/test_vpython_lod.py::test_a_coarser_level_draws_fewer_polygons_near_the_full_picture": 1.2,
    "tests/vpython/test_vpython_lod.py::test_lattice_at_its_detail_is_within_the_image_tolerance": 2.4,
    "tests/vpython/test_vpython_lod.py::test_renderer_draws_a_lattice_of_helices_in_one_batch": 1.3,
    "tests/vpython/test_vpython_object_memory.py::test_impostors_drawn_in_chunks_give_the_same_pixels": 0.7,
    "tests/vpython/test_vpython_opacity.py::test_transparent_scene_matches_real_vpython": 1.3,
    "tests/vpython/test_vpython_polygons.py::test_the_triangles_program_and_rug_like_sheets_run": 0.9,
    "tests/vpython/test_vpython_run.py::test_a_program_that_ends_ends_the_video": 0.7,
    "tests/vpython/test_vpython_run.py::test_example_stills": 3.2,
    "tests/vpython/test_vpython_run.py::test_rate_takes_a_frame_on_every_call_whose_span_holds_a_frame_time": 0.8,
    "tests/vpython/test_vpython_run.py::test_visual_and_module_imports_and_a_second_run_reimports_local_modules": 0.8,
    "tests/vpython/test_vpython_run.py::test_waits_in_a_loop_end_with_the_video": 1.1,
    "tests/vpython/test_vpython_run.py::test_wiki_program_follows_simulate_bit_for_bit": 4.5,
    "tests/vpython/test_vpython_shaders.py::test_glowscript_lighting_rules_take": 1.0,
    "tests/vpython/test_vpython_textures.py::test_a_bump_map_bends_the_normal_along_glowscripts_bumpaxis": 1.3,
    "tests/vpython/test_vpython_textures.py::test_a_cylinders_far_half_bends_its_bumps_the_other_way": 0.8,
    "tests/vpython/test_vpython_textures.py::test_a_one_colour_texture_is_lit_as_that_colour_with_a_white_highlight": 1.0,
}


def pytest_collection_modifyitems(config, items):
    """Mark the slow tests (the module's docstring); every test in tests/reliability is
    marked ``reliability`` too: ``pytest -m reliability`` runs that suite alone (hostile
    configs, signals, misbehaving programs, full disks)."""
    _check_long_tests(items)
    for item in items:
        if RELIABILITY in Path(str(item.path)).parents:
            item.add_marker(pytest.mark.reliability)
        if _slow_by_rule(item):
            item.add_marker(pytest.mark.slow)


def _slow_by_rule(item) -> bool:
    """Rules 1 to 3 (rule 4 is the test's own mark)."""
    path = Path(str(item.path))
    return any(path == place or place in path.parents for place in SLOW_PLACES) \
        or _test_id(item) in LONG_TESTS or _starts_python(item)


def _test_id(item) -> str:
    """``tests/file.py::test_name``: the test function, all its cases."""
    name = getattr(item, "originalname", item.name)
    return f"{Path(str(item.path)).relative_to(ROOT).as_posix()}::{name}"


def _check_long_tests(items) -> None:
    """Every entry of :data:`LONG_TESTS` whose file was collected names a test there."""
    modules = {Path(str(i.path)).relative_to(ROOT).as_posix(): i.module
               for i in items if getattr(i, "module", None) is not None}
    for entry in LONG_TESTS:
        path, name = entry.split("::")
        if path in modules and not callable(getattr(modules[path], name, None)):
            raise pytest.UsageError(f"tests/conftest.py LONG_TESTS: {entry} is no test "
                                    "(renamed or removed? update the entry)")


def _starts_python(item) -> bool:
    """Rule 2: the test's code, its fixtures' and that of the functions of their modules
    they call name :data:`STARTS_PYTHON`."""
    functions = [getattr(item, "function", None)]
    info = getattr(item, "_fixtureinfo", None)
    for defs in (info.name2fixturedefs.values() if info is not None else ()):
        functions += [d.func for d in defs]
    seen: set = set()
    return any(_names_python(f, seen) for f in functions if f is not None)


def _names_python(function, seen: set) -> bool:
    function = inspect.unwrap(function)
    code = getattr(function, "__code__", None)
    if code is None or code in seen:
        return False
    seen.add(code)
    names = _code_names(code)
    if names & STARTS_PYTHON:
        return True
    module = getattr(function, "__module__", None)
    for name in names:
        called = function.__globals__.get(name)
        if inspect.isfunction(called) and called.__module__ == module \
                and _names_python(called, seen):
            return True
    return False


def _code_names(code) -> set[str]:
    """The global and attribute names a code object uses, with its nested functions'."""
    names = set(code.co_names)
    for const in code.co_consts:
        if inspect.iscode(const):
            names |= _code_names(const)
    return names


# ---- the guard: no new Python in the fast tier ------------------------------------------------

_running: list = [None]                  # the test being run (its set-up and teardown too)


@pytest.hookimpl(wrapper=True)
def pytest_runtest_protocol(item, nextitem):
    _running[0] = item
    try:
        return (yield)
    finally:
        _running[0] = None


def _fast_test():
    """The test being run, when it is in the fast tier; else None."""
    item = _running[0]
    return item if item is not None and item.get_closest_marker("slow") is None else None


def _refuse(item, what: str) -> None:
    pytest.fail(f"{item.nodeid} is in the fast tier (not marked slow) but {what}: mark it "
                "slow (the rules in tests/conftest.py) or run it in-process (the cli "
                "fixture for the command line; run_program, or jobs.vpython(..., "
                "supervised=False), for a VPython program)", pytrace=False)


_PYTHON_NAME = re.compile(r"python[0-9.]*")


def _is_python(program) -> bool:
    """A Python interpreter, a script run by one (``#!...python``), or the ``springscene``
    command (its console script)."""
    program = os.fsdecode(program)
    found = shutil.which(program) or program
    real = os.path.realpath(found)
    if _PYTHON_NAME.fullmatch(os.path.basename(real)) or os.path.basename(found) == "springscene":
        return True
    try:
        with open(real, "rb") as f:
            first = f.readline(256)
    except OSError:
        return False
    return first.startswith(b"#!") and b"python" in first


_execute_child = subprocess.Popen._execute_child
_EXECUTE_CHILD = inspect.signature(_execute_child)
_fork = os.fork


def _guarded_execute_child(self, *args, **kwargs):
    item = _fast_test()
    if item is not None:
        call = _EXECUTE_CHILD.bind(self, *args, **kwargs).arguments
        argv, program = call["args"], call["executable"]
        if isinstance(argv, (str, bytes, os.PathLike)):
            argv = [argv]
        first = program or (argv[0] if argv else "")
        if call["shell"]:
            first = os.fsdecode(argv[0]).split()[0] if argv else ""
        if first and _is_python(first):
            command = " ".join(map(os.fsdecode, argv))
            _refuse(item, f"starts a new Python ({command[:120]}{'...' * (len(command) > 120)})")
    return _execute_child(self, *args, **kwargs)


def _guarded_fork():
    item = _fast_test()
    if item is not None:
        _refuse(item, "forks the test process")
    return _fork()


def pytest_configure(config):
    if config.getoption("--regen-baselines"):
        config.option.springscene_regen = True
    subprocess.Popen._execute_child = _guarded_execute_child
    os.fork = _guarded_fork


def pytest_unconfigure(config):
    subprocess.Popen._execute_child = _execute_child
    os.fork = _fork


# ---- the timings' check ------------------------------------------------------------------------

_long_fast_tests: list = []              # (seconds, node id) of fast tests over the limit


def pytest_runtest_logreport(report):
    if report.when == "call" and report.passed and "slow" not in report.keywords \
            and report.duration > FAST_LIMIT_S:
        _long_fast_tests.append((report.duration, report.nodeid))


def pytest_terminal_summary(terminalreporter):
    if not _long_fast_tests:
        return
    terminalreporter.section("tiers: fast tests that ran long")
    for seconds, nodeid in sorted(_long_fast_tests, reverse=True):
        terminalreporter.line(f"{seconds:.1f} s  {nodeid}: in the fast tier; if it is always "
                              "this long, add it to LONG_TESTS in tests/conftest.py")


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
