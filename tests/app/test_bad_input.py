"""Bad input: one line naming the file, key or flag; exit 2; no traceback; no output file.

The command line runs in this process (the ``cli`` fixture); a few cases run it as the
real command too, in a new process (``run_cli``), to show the two say the same."""

from __future__ import annotations

import pytest

from conftest import ROOT, WIKI, run_cli

EXAMPLES = ROOT / "examples"

GOOD = WIKI.read_text()


def variant(tmp_path, old, new):
    assert old in GOOD
    p = tmp_path / "bad.toml"
    p.write_text(GOOD.replace(old, new))
    return p


BAD_CONFIGS = [
    # (replace this, with this, the message must contain)
    ("k = 15.0", "k = 15.0\nstiffness = 3", "unknown key 'stiffness' in [spring]"),
    ("[render]", "[renderer]", "unknown section [renderer]"),
    ("m = 0.10", 'm = "heavy"', "[ball] m must be a number"),
    ("m = 0.10", "m = -0.1", "[ball] m must be > 0"),
    ("k = 15.0", "k = 0", "[spring] k must be > 0"),
    ("L0 = 0.10", "L0 = -1", "[spring] L0 must be > 0"),
    ("dt = 0.01", "dt = 0", "[physics] dt must be > 0"),
    ("dt = 0.01", "dt = nan", "[physics] dt must be finite"),
    ("g = [0, -9.8, 0]", "g = [0, inf, 0]", "[physics] g must be finite"),
    ("g = [0, -9.8, 0]", "g = [0, -9.8]", "[physics] g must be a list of three numbers"),
    ("fps = 50", "fps = 0", "[render] fps must be > 0"),
    ("fps = 50", "fps = 2.5", "[render] fps must be a whole number"),
    ("duration = 10.0", "duration = -1.0", "[render] duration must be >= 0"),
    ('color = "red"', 'color = "octarine"', "[ball] color unknown colour"),
    ("width = 900", "width = true", "[scene] width must be a whole number"),
    ("k = 15.0", "k = 15.0 15", "invalid TOML"),
    ("k = 15.0", "k = 1e308", "[spring] k must be between 1e-9 and 1e12 N/m, got 1e308"),
    ("dt = 0.01", "dt = 1e300", "use dt <= 0.05 s"),
    ("width = 900", "width = 40000", "[scene] width must be at most 8192 pixels"),
    ("thickness = 0.003", "thickness = -0.003", "[spring] thickness must be >= 0"),
]


@pytest.mark.parametrize("old, new, message", BAD_CONFIGS)
def test_bad_config(tmp_path, cli, old, new, message):
    cfg = variant(tmp_path, old, new)
    out = tmp_path / "t.csv"
    proc = cli("simulate", cfg, "--out", out)
    assert proc.returncode == 2
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1, proc.stderr
    assert "Traceback" not in proc.stderr
    assert str(cfg) in lines[0] and message in lines[0], lines[0]
    assert not out.exists()


@pytest.mark.parametrize("args, message", [
    (["simulate", "missing.toml", "--out", "{tmp}/t.csv"], "missing.toml: no such config file"),
    (["still", WIKI, "--time", "-1", "--out", "{tmp}/a.png"], "--time must be >= 0, got -1"),
    (["still", WIKI, "--time", "nan", "--out", "{tmp}/a.png"], "--time must be finite, got nan"),
    (["simulate", WIKI, "--duration", "-2", "--out", "{tmp}/t.csv"], "--duration must be >= 0, got -2"),
    (["render", WIKI, "--fps", "0", "--out", "{tmp}/v.mp4"], "--fps must be > 0"),
    (["render", WIKI, "--out", "{tmp}/v.avi"], "unknown output format '.avi'"),
    (["still", WIKI, "--out", "{tmp}/a.jpg"], "unknown output format '.jpg'"),
    (["still", WIKI, "--out", "{tmp}/no/such/dir/a.png"], "does not exist"),
    (["render", WIKI, "--backend", "vulkan", "--out", "{tmp}/v.mp4"], "--backend"),
    (["render", WIKI, "--fps", "ten", "--out", "{tmp}/v.mp4"], "--fps"),
    (["frobnicate"], "invalid choice"),
    (["simulate", WIKI, "--duration", "1e307", "--out", "{tmp}/t.csv"], "--duration 1e+307 is"),
    (["render", WIKI, "--duration", "1e12", "--out", "{tmp}/v.mp4"], "the limit is"),
    (["still", WIKI, "--time", "1e9", "--out", "{tmp}/a.png"], "--time 1e+09 is 1e+11 steps"),
    (["render", WIKI, "--fps", "60", "--out", "{tmp}/v.gif"], "--fps 60: a GIF plays at most 50"),
    (["simulate", WIKI, "--dt", "1e308", "--out", "{tmp}/t.csv"], "use dt <= 0.05 s"),
    (["simulate", WIKI, "--out", "{tmp}/" + "b" * 250 + ".csv"], "the limit is 241"),
    (["vpython", EXAMPLES / "projectile.py", "--duration", "1e308", "--out", "{tmp}/v.mp4"],
     "the limit is 360,000"),
    (["vpython", EXAMPLES / "projectile.py", "--fps", "10" * 10, "--out", "{tmp}/v.mp4"],
     "the limit is 1000 frames per program second"),
])
def test_bad_flags(tmp_path, cli, args, message):
    args = [str(a).replace("{tmp}", str(tmp_path)) for a in args]
    proc = cli(*args)
    assert proc.returncode == 2, proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and message in lines[0], proc.stderr
    assert "Traceback" not in proc.stderr
    assert list(tmp_path.iterdir()) == []


def test_unwritable_output(tmp_path, cli):
    import os

    if os.geteuid() == 0:   # root may write to a 0555 folder; /proc refuses everyone
        target = "/proc/springscene-test.csv"
    else:
        ro = tmp_path / "ro"
        ro.mkdir()
        ro.chmod(0o555)
        target = ro / "t.csv"
    proc = cli("simulate", WIKI, "--out", target)
    assert proc.returncode == 2, proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and str(target) in lines[0], proc.stderr
    assert "Traceback" not in proc.stderr


@pytest.mark.parametrize("command, name, extra", [
    ("simulate", "run.csv", ()),
    ("still", "run.png", ("--time", "0")),
    ("render", "run.mp4", ("--duration", "0.1")),
    ("sweep", "run.csv", ("--omega", "10:12:3")),
    ("vpython", "prog.png", ()),
])
def test_out_naming_the_input_is_refused(tmp_path, cli, command, name, extra):
    """A config or program saved under the output's extension must not be overwritten:
    one line, exit 2, the file untouched (also through a link)."""
    source = tmp_path / name
    text = ("from vpython import *\nsphere()\n" if command == "vpython" else GOOD)
    source.write_text(text)
    link = tmp_path / ("link" + source.suffix)
    link.symlink_to(source)
    for out in (source, link):
        proc = cli(command, source, "--out", out, *extra)
        assert proc.returncode == 2, proc.stderr
        lines = proc.stderr.strip().splitlines()
        assert len(lines) == 1 and "is the input" in lines[0] and "Traceback" not in proc.stderr
        assert source.read_text() == text


def test_a_newline_in_a_section_name_stays_one_line(tmp_path, cli):
    bad = tmp_path / "bad.toml"
    bad.write_text(GOOD + '\n["a\\nb\\u0007c"]\nx = 1\n')
    proc = cli("simulate", bad, "--out", tmp_path / "x.csv")
    assert proc.returncode == 2
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and "unknown section [a\\nb\\x07c]" in lines[0], proc.stderr
    assert not (tmp_path / "x.csv").exists()


def test_deeply_nested_values_are_one_line(tmp_path, cli):
    value = "1"
    for _ in range(3000):
        value = "{a = " + value + "}"
    bad = tmp_path / "deep.toml"
    bad.write_text(GOOD + "\n[extra]\nx = " + value + "\n")
    proc = cli("simulate", bad, "--out", tmp_path / "x.csv")
    assert proc.returncode == 2 and "Traceback" not in proc.stderr
    lines = proc.stderr.strip().splitlines()
    assert len(lines) == 1 and "nested too deeply" in lines[0], proc.stderr


def test_osmesa_missing_is_one_line(monkeypatch):
    """A backend whose library is absent is refused before VTK can crash."""
    from springscene.view import backend
    from springscene.errors import UserError

    monkeypatch.setattr(backend, "library_present", lambda name: False)
    monkeypatch.setattr(backend, "_selected", None)
    with pytest.raises(UserError, match=r"--backend osmesa: libOSMesa.so.8 not found; install Debian's libosmesa6"):
        backend.select("osmesa")


@pytest.mark.parametrize("args, message", [
    (["render", "CONFIG", "--fps", "abc"],
     "springscene: error: render: argument --fps: invalid int value: 'abc'"),
    (["still"], "springscene: error: still: the following arguments are required: config, --out"),
    (["bogus"], "springscene: error: argument command: invalid choice: 'bogus'"),
])
def test_a_usage_error_starts_springscene_as_every_message_does(cli, args, message):
    """argparse's own errors too (they said ``springscene render: error: ...``)."""
    proc = cli(*[str(WIKI) if a == "CONFIG" else a for a in args])
    assert proc.returncode == 2
    (line,) = proc.stderr.splitlines()
    assert line.startswith(message), line


@pytest.mark.parametrize("case", ["bad config", "bad flag", "usage error"])
def test_the_real_command_says_the_same_in_a_new_process(tmp_path, cli, case):
    """The real command, started as a user starts it: its one line, its status, no
    traceback, nothing written; and the same bytes as the command run in this process."""
    if case == "bad config":
        args = ["simulate", variant(tmp_path, "k = 15.0", "k = 0"), "--out", tmp_path / "t.csv"]
        message = "bad.toml: [spring] k must be > 0"
    elif case == "bad flag":
        args = ["still", WIKI, "--time", "-1", "--out", tmp_path / "a.png"]
        message = "--time must be >= 0, got -1"
    else:
        args = ["render", WIKI, "--fps", "abc"]
        message = "springscene: error: render: argument --fps: invalid int value: 'abc'"
    before = sorted(tmp_path.iterdir())
    real = run_cli(*args)
    assert real.returncode == 2, real.stderr
    (line,) = real.stderr.splitlines()
    assert line.startswith("springscene: error: ") and message in line, line
    assert real.stdout == "" and sorted(tmp_path.iterdir()) == before
    here = cli(*args)
    assert (here.returncode, here.stdout, here.stderr) == (2, real.stdout, real.stderr)


def test_a_config_saved_with_a_byte_order_mark_reads_as_without(tmp_path):
    """Some editors start UTF-8 with a BOM; tomllib refused it as 'Invalid statement'."""
    import dataclasses

    from springscene import config

    bom = tmp_path / "bom.toml"
    bom.write_bytes(b"\xef\xbb\xbf" + WIKI.read_bytes())
    read, wiki = config.load(bom), config.load(WIKI)
    assert read.source == str(bom)
    assert dataclasses.replace(read, source=wiki.source) == wiki
