"""A program that raises after animating: its video, still, page and recording up to the error.

tests/vpython_programs/vp7_data_runs_out_error.py moves a cart at 1 m/s with rate(25)
and runs past the end of its 49 readings: an IndexError at t = 2 s of program time, 50
steps in. Its video (25 frames a second) must end at the error: 51 frames, the last at
t = 2 s, the cart where the program left it, measured in the picture against where the
earlier frames put it; the recording's last frame is at t = 2 s with the error in its end
line, the page shows the error, the command exits 1 with the one line after the
traceback. A program that raises before its first frame writes nothing.
"""

from __future__ import annotations

import os
import textwrap

import imageio.v3 as iio
import numpy as np
import pytest

import springscene
from conftest import ROOT, run_cli
from springscene.errors import ProgramError
from springscene.results import Run
from springscene.video import count_frames
from springscene.vpython.page.replay_data import replay_data
from springscene.vpython.record.reader import read
from springscene.vpython.run.options import RunOptions
from springscene.vpython.run.runner import ProgramExit, ProgramRaised, run_program

PROGRAM = ROOT / "tests" / "vpython_programs" / "vp7_data_runs_out_error.py"
FPS = 25
T = 2.0                 # s of program time: the IndexError, at the 50th rate(25) step
FRAMES = 51             # frames 0 ... 50 at t = k / 25: the last is the scene at T
ERROR_LINE = 23         # the program's line that raises
SAID = "springscene: the {} ends at the program's error, at t = 2.00 s (frame 50)"


def cart_column(image: np.ndarray) -> float:
    """The column of the red cart's centre in a frame (its red pixels' mean)."""
    r, g, b = (image[..., i].astype(int) for i in range(3))
    ys, xs = np.nonzero((r > 120) & (g < 80) & (b < 80))
    assert len(xs) > 100, "no cart in the picture"
    return float(xs.mean())


def column_at(frames: np.ndarray, t: float) -> float:
    """Where the cart is drawn at program time ``t``, from frames 0 and 25 (t = 0 and
    1 s): it moves at a steady speed across a fixed view."""
    c0, c1 = cart_column(frames[0]), cart_column(frames[FPS])
    return c0 + (c1 - c0) * t


def check_ends_at_the_error(frames: np.ndarray) -> None:
    """The video's last frame shows the cart at T, not a frame earlier (nor later)."""
    assert len(frames) == FRAMES
    step = (column_at(frames, 1.0) - column_at(frames, 0.0)) / FPS     # pixels a frame
    assert step > 3
    last = cart_column(frames[-1])
    assert abs(last - column_at(frames, T)) < step / 2, (last, column_at(frames, T), step)
    assert abs(cart_column(frames[-2]) - column_at(frames, T - 1 / FPS)) < step / 2


def check_recording(recording) -> None:
    """The recording ends at the error: its last frame at T, the cart at the model's
    x(T), the error in the end line."""
    assert len(recording.times) == FRAMES
    assert recording.times[-1] == T and recording.times[-2] == pytest.approx(T - 1 / FPS)
    assert recording["cart"].pos[-1, 0] == pytest.approx(-1.5 + T)
    assert recording.end["ended"] == "error" and recording.end["t"] == T
    error = recording.error
    assert (error["type"], error["message"]) == ("IndexError", "list index out of range")
    assert error["t"] == T and error["line"] == ERROR_LINE
    assert error["traceback"].endswith("IndexError: list index out of range")
    assert f'"{PROGRAM}", line {ERROR_LINE}' in error["traceback"]


def test_the_video_ends_at_the_programs_error(tmp_path):
    out = tmp_path / "run.mp4"
    with pytest.raises(ProgramRaised) as raised:
        run_program(PROGRAM, out, RunOptions(fps=FPS, antialias=False,
                                             record=str(tmp_path / "run.jsonl")))
    result = raised.value.result
    assert (result.frames, result.ended, result.program_seconds) == (FRAMES, "error", T)
    assert result.error["type"] == "IndexError" and result.page == tmp_path / "run.html"
    told = str(raised.value).splitlines()
    assert told[-2:] == ["IndexError: list index out of range", SAID.format("video")]
    assert told[0] == "Traceback (most recent call last):"
    assert count_frames(out) == FRAMES
    check_ends_at_the_error(iio.imread(out, index=None))
    recording = read(tmp_path / "run.jsonl")
    check_recording(recording)
    run = Run(recording)
    assert run.error == recording.error and run.ended == "error"
    assert "ended by the program's IndexError" in repr(run)
    # the page beside the video: the replay up to the error, the error shown under it
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.html", "run.jsonl", "run.mp4"]
    page = replay_data(tmp_path / "run.jsonl")
    assert page["times"][-1] == T and page["end"]["ended"] == "error"
    assert page["end"]["error"].startswith("Traceback (most recent call last):")
    assert page["end"]["error"].endswith(
        "IndexError: list index out of range\n\n(the program stopped here, at t = 2.00 s)")
    assert "list index out of range" in (tmp_path / "run.html").read_text()


def test_a_gif_ends_at_the_error_and_the_api_raises_with_the_video(tmp_path):
    out = tmp_path / "run.gif"
    with pytest.raises(ProgramError) as raised:
        springscene.run_vpython(PROGRAM, out, fps=FPS, draft=True, page=False,
                                supervised=False)
    error = raised.value
    assert error.video is not None and error.video.path == out and error.run is None
    assert error.error["type"] == "IndexError" and error.error["t"] == T
    assert str(error).endswith(SAID.format("video"))
    assert os.listdir(tmp_path) == ["run.gif"]
    check_ends_at_the_error(iio.imread(out, index=None))


def test_a_png_is_the_scene_at_the_error(tmp_path):
    video, still = tmp_path / "run.gif", tmp_path / "run.png"
    for out in (video, still):
        with pytest.raises(ProgramRaised) as raised:
            run_program(PROGRAM, out, RunOptions(fps=FPS, antialias=False, page=False))
    assert str(raised.value).endswith("springscene: the picture is the scene at the "
                                      "program's error, at t = 2.00 s")
    frames = iio.imread(video, index=None)
    picture = iio.imread(still)[..., :3]
    assert picture.shape == frames[-1].shape
    assert abs(cart_column(picture) - column_at(frames, T)) < 1.0
    assert abs(cart_column(picture) - cart_column(frames[-1])) < 1.0


def test_the_runs_recording_ends_at_the_error_and_the_api_gives_it(tmp_path):
    with pytest.raises(ProgramRaised) as raised:
        run_program(PROGRAM, tmp_path / "run.jsonl", RunOptions(fps=FPS))
    assert str(raised.value).endswith(SAID.format("recording"))
    check_recording(read(tmp_path / "run.jsonl"))
    # the testing API: the program's error, with the run up to it
    with pytest.raises(ProgramError) as raised:
        springscene.run_vpython(PROGRAM, fps=FPS, supervised=False)
    run = raised.value.run
    assert isinstance(run, Run) and run.ended == "error" and run.frames == FRAMES
    assert run.error == raised.value.error and run.error["t"] == T
    assert run["cart"].pos[-1, 0] == pytest.approx(-1.5 + T)
    assert run.times[-1] == T and run.at(T)["reading"].pos[0] == pytest.approx(
        -1.5 + 1.0 * 49 / FPS + 0.01)        # the last reading there was, measured[48]


def test_an_html_output_is_the_page_up_to_the_error(tmp_path):
    with pytest.raises(ProgramRaised) as raised:
        run_program(PROGRAM, tmp_path / "run.html", RunOptions(fps=FPS))
    assert str(raised.value).endswith(SAID.format("page"))
    assert os.listdir(tmp_path) == ["run.html"]
    assert "list index out of range" in (tmp_path / "run.html").read_text()


def write(tmp_path, source: str, name: str = "prog.py"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(source))
    return path


@pytest.mark.parametrize("out", ["x.mp4", "x.png", "x.jsonl"])
def test_an_error_before_the_first_frame_writes_nothing(tmp_path, out):
    prog = write(tmp_path, """
        from vpython import *
        readings = []
        cart = sphere()
        cart.pos.x = readings[0]
        while True:
            rate(25)
    """)
    with pytest.raises(ProgramRaised) as raised:
        run_program(prog, tmp_path / out, RunOptions(fps=FPS, record=None if out.endswith(
            ".jsonl") else str(tmp_path / "r.jsonl")))
    assert raised.value.result is None and raised.value.error["t"] == 0
    assert str(raised.value).endswith("IndexError: list index out of range")
    assert os.listdir(tmp_path) == ["prog.py"]


def test_sys_exit_after_frames_writes_nothing_as_before(tmp_path):
    prog = write(tmp_path, """
        import sys
        from vpython import *
        cart = sphere()
        for i in range(10):
            rate(25)
        sys.exit(3)
    """)
    with pytest.raises(ProgramExit):
        run_program(prog, tmp_path / "x.mp4", RunOptions(fps=FPS, page=False))
    assert os.listdir(tmp_path) == ["prog.py"]


def test_the_command_writes_the_files_up_to_the_error_and_says_where(tmp_path):
    """Supervised: the child hands the files back, the one line follows the traceback."""
    out = tmp_path / "out"
    out.mkdir()
    proc = run_cli("vpython", PROGRAM, "--fps", FPS, "--draft", "--out", out / "run.mp4",
                   "--record", out / "run.jsonl")
    assert proc.returncode == 1, proc.stderr
    said = proc.stderr.splitlines()
    assert said[0] == f"springscene: {PROGRAM}: written for VPython 7"
    assert said[1] == "Traceback (most recent call last):"
    assert said[-2:] == ["IndexError: list index out of range", SAID.format("video")]
    assert sum("ends at the program's error" in line for line in said) == 1
    assert proc.stdout == ""
    assert sorted(os.listdir(out)) == ["run.html", "run.jsonl", "run.mp4"]   # nothing hidden
    assert count_frames(out / "run.mp4") == FRAMES
    check_ends_at_the_error(iio.imread(out / "run.mp4", index=None))
    check_recording(read(out / "run.jsonl"))
    # the API's supervised run to a recording alone: the run up to the error comes back
    with pytest.raises(ProgramError) as raised:
        springscene.run_vpython(PROGRAM, fps=FPS)
    assert str(raised.value).endswith(SAID.format("recording"))
    run = raised.value.run
    assert run.frames == FRAMES and run.times[-1] == T and run.ended == "error"
    assert run.error == read(out / "run.jsonl").error


def test_the_recorded_line_is_the_programs_though_a_library_raised(tmp_path):
    """An error raised inside a library the program called (json here) is recorded at the
    program's line that called it, not at the library's."""
    prog = write(tmp_path, """
        import json
        from vpython import *
        b = sphere()
        rate(50)
        settings = json.loads("{not json")
    """)
    with pytest.raises(ProgramRaised):
        run_program(prog, tmp_path / "run.jsonl", RunOptions(fps=FPS))
    error = read(tmp_path / "run.jsonl").error
    assert error["type"] == "JSONDecodeError" and error["line"] == 6
