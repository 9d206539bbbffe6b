"""Every command against what a hostile user (or an unlucky one) does: generated bad
configs, a full disk, and stop signals at random moments. Whatever happens: the right
exit status, one line on stderr (no traceback), and nothing left beside the output."""

from __future__ import annotations

import json
import math
import os
import random
import signal
import subprocess
import sys
import tempfile
import textwrap
import time
from pathlib import Path

import pytest

try:
    import tomllib
except ModuleNotFoundError:                     # Python 3.10
    import tomli as tomllib

from hypothesis import HealthCheck, event, given, settings
from hypothesis import strategies as st

from conftest import ROOT, WIKI, small_disk
from springscene.app import cli

CHAIN = ROOT / "configs" / "chain.toml"
BASES = {name: tomllib.loads(path.read_text()) for name, path in
         (("wiki", WIKI), ("chain", CHAIN))}
EXAMPLES = int(os.environ.get("SPRINGSCENE_HOSTILE_EXAMPLES", "120"))
SPRINGSCENE = str(Path(sys.executable).parent / "springscene")   # the installed command
INFO_LINE = "written for VPython"      # the one line `vpython` prints before it runs


# ---- generated bad configs ------------------------------------------------------------

def toml_value(v) -> str:
    """``v`` written as a TOML value (enough for the generated configs)."""
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, int):
        return str(v)
    if isinstance(v, float):
        return "nan" if math.isnan(v) else ("inf" if v > 0 else "-inf") if math.isinf(v) \
            else repr(v)
    if isinstance(v, str):
        return json.dumps(v)          # a TOML basic string: JSON's escapes are TOML's
    if isinstance(v, list):
        return "[" + ", ".join(toml_value(x) for x in v) + "]"
    return "{" + ", ".join(f"{json.dumps(k)} = {toml_value(x)}" for k, x in v.items()) + "}"


def toml_text(doc: dict) -> str:
    lines = []
    for section, table in doc.items():
        lines.append(f"[{json.dumps(section)}]")
        lines += [f"{json.dumps(k)} = {toml_value(v)}" for k, v in table.items()]
    return "\n".join(lines) + "\n"


scalars = st.one_of(
    st.floats(allow_nan=True, allow_infinity=True), st.integers(-10**30, 10**30),
    st.sampled_from([0, -1, 1e308, -1e308, 1e-308, 5e-324, 2**63, 1e20]),
    st.text(max_size=40), st.text(min_size=300, max_size=2000), st.booleans())
values = st.recursive(scalars, lambda inner: st.one_of(
    st.lists(inner, max_size=4), st.dictionaries(st.text(max_size=6), inner, max_size=3)),
    max_leaves=8)


@st.composite
def hostile_configs(draw) -> tuple[str, dict]:
    """A starting config (the page's ball or a chain of atoms) with one to three of its
    keys given hostile values, or an unknown key or section (names with control
    characters included)."""
    name = draw(st.sampled_from(sorted(BASES)))
    doc = json.loads(json.dumps(BASES[name]))          # a deep copy
    for _ in range(draw(st.integers(1, 3))):
        if draw(st.integers(0, 5)) == 0:
            section = draw(st.sampled_from(sorted(doc)) | st.text(min_size=1, max_size=8))
            doc.setdefault(section, {})[draw(st.text(min_size=1, max_size=8))] = draw(values)
        else:
            section = draw(st.sampled_from(sorted(doc)))
            if doc[section]:
                doc[section][draw(st.sampled_from(sorted(doc[section])))] = draw(values)
    return name, doc


@settings(max_examples=EXAMPLES, deadline=None,
          suppress_health_check=[HealthCheck.function_scoped_fixture, HealthCheck.too_slow])
@given(case=hostile_configs())
def test_generated_bad_configs_are_one_line_exit_2_and_write_nothing(case, tmp_path, capsys):
    """Each generated config through `simulate` (every config is checked in full when it
    is loaded, whatever the command): either it is a fine config and the CSV is written,
    or exit 2, one line naming what is wrong, and nothing written. Never a traceback."""
    _, doc = case
    folder = Path(tempfile.mkdtemp(dir=tmp_path))
    path = folder / "hostile.toml"
    path.write_text(toml_text(doc))
    out = folder / "out.csv"
    capsys.readouterr()
    status = cli.main(["simulate", str(path), "--duration", "0.05", "--out", str(out)])
    err = capsys.readouterr().err
    event(f"exit {status}")               # --hypothesis-show-statistics counts them
    assert "Traceback" not in err
    assert status in (0, 2), err
    if status == 2:
        assert len(err.splitlines()) == 1 and err.startswith("springscene: error: "), err
        assert sorted(p.name for p in folder.iterdir()) == ["hostile.toml"]
    else:
        assert out.is_file() and err == ""


# ---- a full disk, every command -------------------------------------------------------

PROGRAM = textwrap.dedent("""\
    from vpython import *
    ball = sphere(color=color.red)
    for i in range(200):
        rate(50)
        ball.pos.x = 0.01 * i
""")


def _commands(disk: Path, program: Path) -> dict[str, list]:
    return {
        "simulate": ["simulate", WIKI, "--out", disk / "t.csv"],
        "sweep": ["sweep", ROOT / "configs" / "driven.toml", "--omega", "10:14:600",
                  "--periods", "20", "--out", disk / "c.csv"],
        "still": ["still", WIKI, "--draft", "--out", disk / "s.png"],
        "render-mp4": ["render", WIKI, "--duration", "1", "--draft", "--quiet", "--out",
                       disk / "v.mp4"],
        "render-gif": ["render", WIKI, "--duration", "1", "--draft", "--quiet", "--out",
                       disk / "v.gif"],
        "render-webm": ["render", WIKI, "--duration", "1", "--draft", "--quiet", "--out",
                        disk / "v.webm"],
        "figures": ["figures", WIKI, "--draft", "--out", disk / "figs"],
        "vpython": ["vpython", program, "--draft", "--duration", "1", "--out",
                    disk / "p.mp4"],
    }


@pytest.mark.parametrize("command", ["simulate", "sweep", "still", "render-mp4", "render-gif",
                                     "render-webm", "figures", "vpython"])
def test_every_command_on_a_full_disk_is_one_line_exit_1_and_leaves_nothing(
        command, tiny_disk, tmp_path):
    program = tmp_path / "prog.py"
    program.write_text(PROGRAM)
    args = _commands(tiny_disk, program)[command]
    proc = subprocess.run([SPRINGSCENE, *map(str, args)], cwd=ROOT,
                          capture_output=True, text=True, timeout=300)
    lines = [line for line in proc.stderr.splitlines() if INFO_LINE not in line]
    assert proc.returncode == 1, proc.stderr
    assert len(lines) == 1 and lines[0].startswith("springscene: no space left on device "
                                                   f"writing {tiny_disk}/"), proc.stderr
    assert list(tiny_disk.iterdir()) == []               # no file, no folder, no temporary


@pytest.fixture
def full_to_the_brim(tmp_path):
    """A 64 kB tmpfs filled to its last byte: even a small PNG's first block fails."""
    for disk in small_disk(tmp_path, "64k"):
        fd = os.open(disk / "filler", os.O_WRONLY | os.O_CREAT)
        try:
            while os.write(fd, b"\0" * 512):
                pass
        except OSError:
            pass
        finally:
            os.close(fd)
        yield disk


@pytest.mark.parametrize("command", ["still", "figures", "vpython-png", "init"])
def test_a_disk_with_no_byte_free_is_one_line_exit_1_and_leaves_nothing(
        command, full_to_the_brim, tmp_path):
    """The encoder's own file handle failing again when collected (imageio's
    ``PluginV3.__del__``: nine lines more) and ``init``'s empty file (exit 2) are gone."""
    disk = full_to_the_brim
    program = tmp_path / "prog.py"
    program.write_text(PROGRAM)
    args, cwd, name = {
        "still": (["still", WIKI, "--draft", "--out", disk / "s.png"], ROOT, disk / "s.png"),
        "figures": (["figures", WIKI, "--draft", "--out", disk / "figs"], ROOT,
                    disk / "figs" / "scene.png"),
        "vpython-png": (["vpython", program, "--draft", "--out", disk / "p.png"], ROOT,
                        disk / "p.png"),
        "init": (["init", "wiki.toml"], disk, "wiki.toml"),
    }[command]
    proc = subprocess.run([SPRINGSCENE, *map(str, args)], cwd=cwd,
                          capture_output=True, text=True, timeout=300)
    lines = [line for line in proc.stderr.splitlines() if INFO_LINE not in line]
    assert (proc.returncode, lines) == (1, [f"springscene: no space left on device writing "
                                            f"{name}"]), proc.stderr
    assert [p.name for p in disk.iterdir()] == ["filler"]


# ---- stop signals at random moments ---------------------------------------------------

SIGNALS = {"SIGINT": 130, "SIGTERM": 143, "SIGHUP": 129}
# hundredths of a second; from 0.1 s: in the interpreter's own first ~25 ms no code of
# springscene's runs yet, and a signal meets Python's defaults
# (tests/reliability/test_command.py: a signal at any moment of start-up)
MOMENTS = random.Random(16).sample(range(10, 250), 9)


@pytest.mark.parametrize("command, sig, moment", [
    (command, sig, MOMENTS[3 * i + j] / 100)
    for i, command in enumerate(("render", "figures", "vpython"))
    for j, sig in enumerate(SIGNALS)])
def test_a_stop_signal_at_a_random_moment_leaves_nothing(command, sig, moment, tmp_path):
    """`render`, `figures` (over an existing set) and `vpython`, each sent SIGINT, SIGTERM
    and SIGHUP at moments drawn once (seeded) from 0.1 to 2.5 s: the signal's status (or
    0 when the run was already done), one line, and in the output folder only what a
    finished run leaves (for figures: the old set, untouched)."""
    program = tmp_path / "prog.py"
    program.write_text(PROGRAM)
    out = tmp_path / "out"
    out.mkdir()
    args = {"render": ["render", WIKI, "--duration", "2", "--draft", "--quiet", "--out",
                       out / "v.mp4"],
            "figures": ["figures", WIKI, "--draft", "--out", out],
            "vpython": ["vpython", program, "--draft", "--duration", "2", "--out",
                        out / "p.mp4"]}[command]
    old = {}
    if command == "figures":
        (out / "scene.png").write_bytes(b"the old set")
        (out / "figures.wiki").write_text("the old gallery")
        old = {p.name: p.read_bytes() for p in out.iterdir()}
    proc = subprocess.Popen([SPRINGSCENE, *map(str, args)], cwd=ROOT,
                            stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, text=True)
    time.sleep(moment)
    proc.send_signal(getattr(signal, sig))
    _, err = proc.communicate(timeout=300)
    lines = [line for line in err.splitlines() if INFO_LINE not in line]
    assert "Traceback" not in err and "Fatal" not in err, err
    if proc.returncode == 0:                                # finished before the signal
        return
    assert proc.returncode == SIGNALS[sig], err
    assert lines == [f"springscene: interrupted ({sig})"], err
    left = {p.name: (p.read_bytes() if p.is_file() else None) for p in out.iterdir()}
    assert left == old, sorted(left)                        # nothing new, nothing hidden


# ---- inputs never overwritten, messages bounded ----------------------------------------

def test_an_output_over_a_file_the_program_read_is_refused_and_the_file_kept(tmp_path):
    """The supervised run knows the files in the output's folder the program opened to
    read; it writes no output over one of them (exit 2, one line, nothing moved)."""
    data = tmp_path / "data.png"
    data.write_bytes(b"the user's data")
    prog = tmp_path / "reads.py"
    prog.write_text("from vpython import *\n"
                    "with open('data.png', 'rb') as f:\n    n = len(f.read())\n"
                    "sphere(radius=n / 10)\n")
    proc = subprocess.run([sys.executable, "-m", "springscene.app", "vpython", str(prog),
                           "--no-page", "--draft", "--out", str(data)], cwd=tmp_path,
                          capture_output=True, text=True, timeout=300)
    lines = [line for line in proc.stderr.splitlines() if INFO_LINE not in line]
    assert proc.returncode == 2
    assert lines == [f"springscene: error: --out {data}: the program read data.png; "
                     "writing there would overwrite it (choose another name)"]
    assert data.read_bytes() == b"the user's data"
    assert sorted(p.name for p in tmp_path.iterdir()) == ["data.png", "reads.py"]


def test_a_huge_name_in_a_message_is_cut_to_keep_the_line_readable(tmp_path, capsys):
    bad = tmp_path / "long.toml"
    bad.write_text(WIKI.read_text().replace("[scene]", f'[scene]\n"{"k" * 100_000}" = 1', 1))
    assert cli.main(["simulate", str(bad), "--out", str(tmp_path / "t.csv")]) == 2
    err = capsys.readouterr().err
    assert len(err.splitlines()) == 1 and len(err) < cli.MAX_LINE + 200
    assert "characters left out" in err


@pytest.mark.parametrize("looped", ["config", "out", "program"])
def test_a_loop_of_symbolic_links_is_one_line_exit_2(tmp_path, capsys, looped):
    """``ln -s b a; ln -s a b``: named, never ``RuntimeError: Symlink loop`` (a traceback)."""
    (tmp_path / "a").symlink_to(tmp_path / "b")
    (tmp_path / "b").symlink_to(tmp_path / "a")
    program = tmp_path / "p.py"
    program.write_text(PROGRAM)
    loop, out = str(tmp_path / "a"), str(tmp_path / "o.png")
    args = {"config": ["still", loop, "--out", out],
            "out": ["still", str(WIKI), "--out", loop],
            "program": ["vpython", loop, "--out", out]}[looped]
    assert cli.main(args) == 2
    flag = "--out " if looped == "out" else ""
    assert capsys.readouterr().err.splitlines() == [
        f"springscene: error: {flag}{loop}: cannot follow its symbolic links (a loop)"]
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a", "b", "p.py"]


@pytest.mark.parametrize("where", ["new folder", "the folder itself"])
def test_figures_on_a_read_only_file_system_is_a_failed_write_exit_1(tmp_path, where):
    """As the README says of every write on a read-only folder (it was exit 2, bad input)."""
    for disk in small_disk(tmp_path, "64k"):
        remount = subprocess.run(["mount", "-o", "remount,ro", str(disk)], capture_output=True)
        if remount.returncode != 0:
            pytest.skip("cannot remount the tmpfs read-only here")
        out = disk / "figs" if where == "new folder" else disk
        proc = subprocess.run([SPRINGSCENE, "figures", str(WIKI), "--draft",
                               "--out", str(out)], cwd=ROOT, capture_output=True, text=True,
                              timeout=300)
        assert (proc.returncode, proc.stderr.splitlines()) == (
            1, [f"springscene: read-only file system writing {out}"])
