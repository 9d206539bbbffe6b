"""Huge runs: known before they start, refused above the step limit with the flag that
allows them (--max-steps), shown with a progress bar and the time left when long, and
frames that repeat said so."""

from __future__ import annotations

import io
import textwrap

import pytest

from conftest import WIKI, default_stop_signals, run_cli
from springscene import config, progress, render
from springscene.errors import UserError
from springscene.model import timeline


def test_a_run_over_the_step_limit_is_refused_before_it_starts_naming_the_flag(tmp_path):
    proc = run_cli("simulate", WIKI, "--dt", "1e-8", "--out", tmp_path / "t.csv")
    assert proc.returncode == 2
    assert proc.stderr.splitlines() == [
        "springscene: error: --duration 10 is 1e+09 steps of dt = 1e-08 s; the limit is "
        "10,000,000 steps (--max-steps N allows more)"]
    assert list(tmp_path.iterdir()) == []


def test_max_steps_moves_the_limit_both_ways(tmp_path):
    proc = run_cli("still", WIKI, "--time", "0.5", "--max-steps", "40", "--draft",
                   "--out", tmp_path / "s.png")
    assert proc.returncode == 2 and "the limit is 40 steps" in proc.stderr
    cfg = config.override(config.load(WIKI), "physics", dt=1e-6)
    with pytest.raises(UserError, match="limit is 10,000,000"):
        render.simulate(cfg, duration=20)
    with timeline.step_limit(30_000_000):
        assert timeline.step_at(20, 1e-6, "--duration") == 20_000_000
    assert timeline.current_limit() == timeline.MAX_STEPS      # restored after the block


@pytest.mark.parametrize("bad", [0, -5, 2.5, True])
def test_a_bad_max_steps_is_one_line(bad):
    with pytest.raises(UserError, match="--max-steps must be a whole number >= 1"):
        with timeline.step_limit(bad):
            pass


def test_a_long_run_shows_progress_with_the_time_left_on_a_terminal(monkeypatch):
    """Over LONG_RUN steps on a terminal: a bar with its rate and the time left;
    otherwise (short, or stderr not a terminal) nothing."""
    err = io.StringIO()
    err.isatty = lambda: True
    monkeypatch.setattr("sys.stderr", err)
    with progress.steps(progress.LONG_RUN - 1, "simulating") as advance:
        assert advance is None
    with progress.steps(progress.LONG_RUN, "simulating") as advance:
        for _ in range(20):
            advance(progress.LONG_RUN // 20)
    shown = err.getvalue()
    assert "simulating" in shown and "steps" in shown and "<" in shown   # elapsed<left
    err.isatty = lambda: False
    with progress.steps(10 * progress.LONG_RUN, "simulating") as advance:
        assert advance is None


def test_simulate_reports_progress_through_the_run(monkeypatch):
    """physics.run calls the callback every 10,000 steps; simulate passes it on."""
    calls = []
    monkeypatch.setattr(progress, "LONG_RUN", 1)
    monkeypatch.setattr("sys.stderr.isatty", lambda: True, raising=False)
    import contextlib

    @contextlib.contextmanager
    def record(total, what):
        calls.append(("total", total))
        yield lambda n: calls.append(n)

    monkeypatch.setattr(progress, "steps", record)
    render.simulate(config.load(WIKI), duration=300)        # 30,000 steps
    assert calls == [("total", 30_000), 10_000, 10_000, 10_000]


def test_frames_that_repeat_are_noted(tmp_path):
    prog = tmp_path / "slow.py"
    prog.write_text(textwrap.dedent("""\
        from vpython import *
        b = sphere()
        for i in range(20):
            rate(20)
            b.pos.x += 0.05
    """))
    proc = run_cli("vpython", prog, "--draft", "--no-page", "--out", tmp_path / "s.mp4")
    assert proc.returncode == 0, proc.stderr
    assert ("springscene: note: 28 of 50 frames repeat the one before: the program's "
            "rate(20) moves it 20 times a program second, and --fps is 50 (a lower --fps "
            "gives each frame its own picture)") in proc.stderr.splitlines()
    proc = run_cli("vpython", prog, "--draft", "--no-page", "--fps", "20",
                   "--out", tmp_path / "t.mp4")
    assert proc.returncode == 0 and "frames repeat" not in proc.stderr


def test_a_long_still_on_an_unsized_terminal_shows_its_bar(tmp_path):
    """A real pseudo-terminal no one gave a size (0 x 0, as a harness or a container makes
    one): tqdm would hide its bar below a screen of no rows; it is drawn 80 x 24."""
    import os
    import pty
    import select
    import signal
    import subprocess
    import sys
    import time
    from pathlib import Path

    primary, secondary = pty.openpty()
    command = Path(sys.executable).parent / "springscene"
    proc = subprocess.Popen([str(command), "still", str(WIKI), "--dt", "1e-6",
                             "--time", "9.9", "--out", str(tmp_path / "s.png")],
                            cwd=Path(__file__).resolve().parents[2], stdin=secondary,
                            stdout=secondary, stderr=secondary,
                            preexec_fn=default_stop_signals)
    os.close(secondary)
    shown, start = b"", time.monotonic()
    try:
        while b"steps/s" not in shown and time.monotonic() - start < 60:
            if select.select([primary], [], [], 0.5)[0]:
                shown += os.read(primary, 4096)
    finally:
        proc.send_signal(signal.SIGINT)
        proc.wait(timeout=60)
        os.close(primary)
    text = shown.decode(errors="replace")
    assert "stepping:" in text and "/9.90M [" in text and "steps/s" in text, text[-400:]
    assert list(tmp_path.iterdir()) == []
