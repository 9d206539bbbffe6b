"""VPython in a notebook (springscene.notebook): ``%load_ext springscene`` and the
``%%vpython`` cell magic, run in IPython's own shell in this process; what the results
show inline (the interactive page in a sandboxed iframe, or the video)."""

from __future__ import annotations

import html
import re

import pytest

from springscene import notebook
from springscene.errors import UserError
from springscene.results import page_frame


@pytest.fixture
def shell():
    """A real IPython shell with the extension loaded as ``%load_ext springscene`` does."""
    from IPython.testing.globalipapp import get_ipython

    ip = get_ipython()
    ip.run_line_magic("load_ext", "springscene")
    return ip


def test_a_cell_that_names_no_vpython_gets_vpython_7s_names():
    assert notebook.cell_program("ball = sphere()\n") == "from vpython import *\nball = sphere()\n"
    for named in ("from vpython import *\nsphere()\n", "from visual import *\nsphere()\n",
                  "GlowScript 3.2 VPython\nsphere()\n", "\nWeb VPython 3.2\nsphere()\n",
                  "import vpython as vp\nvp.sphere()\n"):
        assert notebook.cell_program(named) == named


def test_the_extension_registers_the_cell_magic(shell):
    assert "vpython" in shell.magics_manager.magics["cell"]


@pytest.mark.parametrize("line, message", [
    ("--fps ten", "%%vpython: argument --fps: invalid int value: 'ten'"),
    ("--duration 1 --frames 3", "not allowed with argument"),
    ("--colour red", "unrecognized arguments: --colour red"),
    ('--out "unclosed', "%%vpython: No closing quotation"),
])
def test_bad_magic_flags_are_one_line(line, message):
    with pytest.raises(UserError, match=re.escape(message)):
        notebook.vpython_cell(line, "sphere()\n")


def test_a_page_shows_inline_in_a_sandboxed_frame():
    page = '<!DOCTYPE html><script>var s = "</script>" + "&amp;";</script>'
    frame = page_frame(page, 700)
    assert frame.startswith('<iframe srcdoc="') and 'sandbox="allow-scripts' in frame
    assert "height: 700px" in frame
    srcdoc = re.match(r'<iframe srcdoc="([^"]*)"', frame).group(1)
    assert html.unescape(srcdoc) == page           # the page whole, quoted for the attribute


@pytest.mark.slow      # a supervised run: its program runs in a child Python
def test_a_cell_runs_headless_and_shows_its_page(shell, capsys):
    run = shell.run_cell_magic("vpython", "--duration 1 --fps 10", (
        "ball = sphere()\n"
        "while True:\n"
        "    rate(10)\n"
        "    ball.pos.x += 0.1\n"))
    assert run.frames == 10 and run["ball"].pos[-1, 0] == pytest.approx(0.9)   # frame 9
    shown = run._repr_html_()
    assert shown.startswith("<iframe srcdoc=") and "glow.min.js" in shown
    video = shell.run_cell_magic("vpython", "--video --frames 3 --fps 10 --draft",
                                 "sphere()\n")
    assert "<video" in video._repr_html_() and video.frames == 1     # no rate(): its end
    # the program's own error: its traceback, no IPython traceback of springscene's
    assert shell.run_cell_magic("vpython", "--frames 2", "sphere()\n1 / 0\n") is None
    err = capsys.readouterr().err
    assert "ZeroDivisionError: division by zero" in err and "springscene/" not in err
