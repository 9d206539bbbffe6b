"""A program's process state (springscene.vpython.run.session): set up in one place, put
back whole however the program ends, and the end hooks called before anything is put back."""

from __future__ import annotations

import sys
import time

import pytest

from springscene.vpython import api
from springscene.vpython.api import runtime
from springscene.vpython.api.canvases import canvas
from springscene.vpython.api.vectors import is_lenient
from springscene.vpython.dialects.compiling import Dialect
from springscene.vpython.run import session
from springscene.vpython.run.session import ProgramSession


def _state() -> tuple:
    return (sys.argv, list(sys.path), sys.stdout, sys.modules.get("vpython"),
            sys.modules.get("visual"), runtime.current(), canvas._measurer, is_lenient(),
            hasattr(time, "clock"))


def _session(tmp_path, kind="vpython6", name="VPython 6"):
    program = tmp_path / "prog.py"
    program.write_text("")
    timeline = runtime.Timeline(50, 10, lambda: None)
    return program, timeline, ProgramSession(program, Dialect(kind, name), timeline,
                                             capture=lambda cv, n: None,
                                             measure=lambda cv: None, stdout=sys.stderr)


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


def test_put_back_after_an_error_and_the_hooks_see_it_first(tmp_path, monkeypatch):
    before = _state()
    program, _, s = _session(tmp_path, "vpython7", "VPython 7")
    seen = []
    monkeypatch.setattr(session, "program_end_hooks",
                        [lambda error: seen.append((error, list(sys.argv)))])
    with pytest.raises(ZeroDivisionError):
        with s:
            assert not is_lenient()
            1 / 0
    assert _state() == before
    (error, argv), = seen
    assert isinstance(error, ZeroDivisionError) and argv == [str(program)]   # before put back


def test_a_hook_sees_none_when_the_program_ended(tmp_path, monkeypatch):
    _, _, s = _session(tmp_path)
    seen = []
    monkeypatch.setattr(session, "program_end_hooks", [seen.append])
    with s:
        pass
    assert seen == [None]
