"""A program's run (springscene.vpython.run): its process state set up in one place and put
back whole however the program ends, on_end called before anything is put back; its
options as the supervised child gets them."""

from __future__ import annotations

import json
import sys
import time
from pathlib import Path

import pytest

from springscene.errors import UserError
from springscene.vpython import api
from springscene.vpython.core import runtime
from springscene.vpython.core.canvases import canvas
from springscene.vpython.core.vectors import is_lenient
from springscene.vpython.dialects.compiling import Dialect
from springscene.vpython.geometry import lod
from springscene.vpython.run import runner, session
from springscene.vpython.run.options import RunOptions, check_lod
from springscene.vpython.run.session import ProgramSession


def _state() -> tuple:
    return (sys.argv, list(sys.path), sys.stdout, sys.modules.get("vpython"),
            sys.modules.get("visual"), runtime.current(), canvas._measurer, is_lenient(),
            hasattr(time, "clock"))


def _session(tmp_path, kind="vpython6", name="VPython 6", on_end=None):
    program = tmp_path / "prog.py"
    program.write_text("")
    timeline = runtime.Timeline(50, 10, lambda: None)
    return program, timeline, ProgramSession(program, Dialect(kind, name), timeline,
                                             capture=lambda cv, n: None,
                                             measure=lambda cv: None, stdout=sys.stderr,
                                             on_end=on_end)


def test_the_program_sees_its_own_process_and_everything_is_put_back(tmp_path):
    before = _state()
    program, timeline, s = _session(tmp_path)
    (tmp_path / "helper_mod_xyz.py").write_text("X = 1\n")
    with s:
        assert sys.argv == [str(program)] and sys.path[0] == str(tmp_path.resolve())
        assert sys.modules["vpython"] is api and sys.modules["visual"] is not None
        assert runtime.current() is timeline and canvas._measurer is not None
        assert is_lenient() and time.clock is time.perf_counter
        assert sys.stdout is sys.stderr
        import helper_mod_xyz  # noqa: F401  a module of the program's own folder
    assert _state() == before
    assert "helper_mod_xyz" not in sys.modules        # forgotten: a new run imports it afresh


def test_put_back_after_an_error_and_on_end_sees_it_first(tmp_path):
    before = _state()
    seen = []
    program, _, s = _session(tmp_path, "vpython7", "VPython 7",
                             on_end=lambda error: seen.append((error, list(sys.argv))))
    with pytest.raises(ZeroDivisionError):
        with s:
            assert not is_lenient()
            1 / 0
    assert _state() == before
    (error, argv), = seen
    assert isinstance(error, ZeroDivisionError) and argv == [str(program)]   # before put back


def test_on_end_sees_none_when_the_program_ended(tmp_path):
    seen = []
    _, _, s = _session(tmp_path, on_end=seen.append)
    with s:
        pass
    assert seen == [None]


def test_what_was_set_before_is_put_back_not_a_default(tmp_path):
    """A session inside a session (a program run from a program's run) leaves the outer
    one's clock, capture and leniency as they were."""
    _, outer_clock, outer = _session(tmp_path)
    with outer:
        capture, lenient = runtime.capturer(), is_lenient()
        (tmp_path / "inner").mkdir()
        _, _, inner = _session(tmp_path / "inner", "vpython7", "VPython 7")
        with inner:
            assert not is_lenient()
        assert runtime.current() is outer_clock and runtime.capturer() is capture
        assert is_lenient() == lenient


def test_only_the_programs_own_modules_are_forgotten(tmp_path):
    """A program's folder may hold this Python's installation or springscene itself (a
    notebook in the project's folder): those modules stay loaded."""
    folder = Path(session.__file__).resolve().parents[4]          # the checkout
    assert session._the_programs(folder / "helper.py", folder)
    assert not session._the_programs(Path(session.__file__).resolve(), folder)
    assert not session._the_programs(Path(sys.prefix).resolve() / "lib" / "x.py",
                                     Path(sys.prefix).resolve().parent)


def test_a_traceback_keeps_the_examples_frames_and_drops_springscenes():
    """An example program shipped inside the package is the user's code; a folder whose
    name only starts like the package's is not springscene."""
    package = Path(runner.__file__).resolve().parents[2]
    assert runner._ours(runner.__file__)
    assert not runner._ours(str(package / "examples" / "wiki_spring.py"))
    assert not runner._ours(str(package.parent / (package.name + "-notes") / "prog.py"))


@pytest.mark.parametrize("options", [
    RunOptions(),
    RunOptions(duration=2.5, fps=25, overlays=("graph",), canvas_only=True, lod=0.3),
    RunOptions(frames=3, antialias=False, page=False, quality="high", lod=lod.FULL),
    RunOptions(lod=lod.LevelOfDetail(helix_px=0.2, sphere_steps=(12, 6))),
])
def test_options_go_to_the_child_and_back_through_json(options):
    assert RunOptions.from_request(json.loads(json.dumps(options.to_request()))) == options


def test_a_level_of_detail_given_as_itself_is_checked():
    with pytest.raises(UserError, match="sphere_steps"):
        check_lod(lod.LevelOfDetail(sphere_steps=()))
    check_lod(lod.FULL)
