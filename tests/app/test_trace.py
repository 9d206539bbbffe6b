"""``springscene vpython --trace NAME``: a named object's attributes over time as CSV beside
the output; bad names are one line, exit 2, and leave no CSV and no hidden folder."""

from __future__ import annotations

import csv
import textwrap

import numpy as np
import pytest

from springscene.vpython.record.reader import read

LINE = """
    from vpython import *
    ball = sphere(pos=vector(1, 0, 0.5), radius=0.1)
    rods = [box(), box()]
    n = 0
    while True:
        rate(100)
        n += 1
        t = n / 100
        ball.pos = vector(1 + 2 * t, -3 * t, 0.5)
"""


def program(tmp_path):
    path = tmp_path / "prog.py"
    path.write_text(textwrap.dedent(LINE))
    return path


def names(folder) -> list[str]:
    return sorted(p.name for p in folder.iterdir())


@pytest.mark.parametrize("args, message", [
    (["--trace", "a b"], "springscene: error: --trace 'a b': not a variable name (the "
                         "program's name for an object, such as ball, or atoms[0] for the "
                         "first of a list)"),
    (["--trace", "ball.pos"], "--trace 'ball.pos': not a variable name"),
    (["--trace", "ball", "--out", "nowhere/v.jsonl"], "--out {}/nowhere/v.jsonl: folder"),
])
def test_a_bad_trace_is_refused_before_the_run(tmp_path, cli, args, message):
    if "--out" not in args:
        args = args + ["--out", "v.jsonl"]
    args = [str(tmp_path / a) if a.endswith(".jsonl") else a for a in args]
    proc = cli("vpython", program(tmp_path), *args)
    assert proc.returncode == 2 and proc.stderr.count("\n") == 1, proc.stderr
    assert message.format(tmp_path) in proc.stderr and proc.stdout == ""
    assert names(tmp_path) == ["prog.py"]


@pytest.mark.slow         # springscene vpython's supervised run: a child Python
def test_trace_writes_the_numbers_of_the_run_beside_the_video(tmp_path, cli):
    proc = cli("vpython", program(tmp_path), "--out", tmp_path / "v.png", "--duration", "1",
               "--fps", "20", "--draft", "--no-page", "--trace", "ball", "--trace", "rods[1]")
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.splitlines()[1:] == [f"wrote {tmp_path / 'v-ball.csv'}",
                                            f"wrote {tmp_path / 'v-rods-1.csv'}"]
    assert names(tmp_path) == ["prog.py", "v-ball.csv", "v-rods-1.csv", "v.png"]  # no recording
    with open(tmp_path / "v-ball.csv", newline="") as fh:
        rows = list(csv.reader(fh))
    assert rows[0][:4] == ["t [s]", "pos.x [m]", "pos.y [m]", "pos.z [m]"]
    t, x, y = (np.array([float(r[i]) for r in rows[1:]]) for i in range(3))
    assert np.array_equal(t, np.arange(20) / 20)
    assert np.array_equal(x, 1 + 2 * t) and np.array_equal(y, -3 * t)    # the line, exactly
    assert rows[1][rows[0].index("size.x [m]")] == "0.2" and rows[1][3] == "0.5"


@pytest.mark.slow         # springscene vpython's supervised run: a child Python
def test_a_name_the_program_lacks_is_one_line_exit_2_after_the_run(tmp_path, cli):
    proc = cli("vpython", program(tmp_path), "--out", tmp_path / "r.jsonl", "--duration",
               "0.2", "--trace", "ball", "--trace", "bal")
    assert proc.returncode == 2, proc.stderr
    assert proc.stderr.splitlines()[-1] == (            # (after the dialect's line)
        "springscene: error: --trace bal: prog.py has no global variable 'bal' holding an "
        "object (its names: ball, rods[0..1])")
    assert proc.stdout.startswith(f"wrote {tmp_path / 'r.jsonl'}: 10 frames")
    assert names(tmp_path) == ["prog.py", "r.jsonl"]      # the run's output, whole; no CSV
    assert read(tmp_path / "r.jsonl").frames == 10       # 0.2 s at 50 frames a second


@pytest.mark.slow         # springscene vpython's supervised run: a child Python
def test_trace_with_record_keeps_the_recording_it_read(tmp_path, cli):
    proc = cli("vpython", program(tmp_path), "--out", tmp_path / "v.png", "--duration", "0.5",
               "--draft", "--no-page", "--record", tmp_path / "v.jsonl.gz", "--trace", "ball",
               "--quiet")
    assert proc.returncode == 0 and proc.stdout == "", proc.stderr
    assert names(tmp_path) == ["prog.py", "v-ball.csv", "v.jsonl.gz", "v.png"]
    rec = read(tmp_path / "v.jsonl.gz")
    with open(tmp_path / "v-ball.csv", newline="") as fh:
        rows = list(csv.reader(fh))
    assert np.array_equal([[float(v) for v in r[1:4]] for r in rows[1:]], rec["ball"].pos)
