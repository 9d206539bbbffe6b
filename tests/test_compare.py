"""Image regression for users: ``springscene compare`` (exit 0 alike, 1 different with a
diff image, 2 bad input), the comparator's measure, and the pytest plugin's
``verify_image`` fixture run in pytest's own ``pytester``."""

from __future__ import annotations

from pathlib import Path

import imageio.v3 as iio
import numpy as np
import pytest

from conftest import run_cli
from springscene.app.cli import main
from springscene.view import compare as cmp

pytest_plugins = ["pytester"]


def picture(h=60, w=80, value=200) -> np.ndarray:
    img = np.full((h, w, 3), value, np.uint8)
    img[20:40, 30:50] = (200, 30, 30)       # a red square
    return img


@pytest.fixture
def pair(tmp_path):
    a = picture()
    b = picture()
    b[20:40, 30:50] = 200                   # the square gone from B
    b[20:40, 32:52] = (200, 30, 30)         # ... and moved 2 px right
    iio.imwrite(tmp_path / "a.png", a)
    iio.imwrite(tmp_path / "b.png", b)
    iio.imwrite(tmp_path / "a2.png", a)
    return tmp_path


# ---- the measure ----------------------------------------------------------------------

def test_measure_counts_pixels_off_by_more_than_the_allowance():
    a = picture()
    b = a.copy()
    b[0, :10] += 24                         # 10 pixels off by exactly the allowance: not counted
    r = cmp.compare(b, a)
    assert r.bad_fraction == 0 and r.alike
    assert r.mean_difference == pytest.approx(24 * 10 * 3 / a.size)
    b[1, :12] = 0                           # 12 of 4800 pixels off by 200: 0.25 %
    r = cmp.compare(b, a)
    assert r.bad_fraction == pytest.approx(12 / 4800) and not r.alike
    assert cmp.compare(b, a, tolerance=0.003, max_mean=5).alike


def test_a_thin_change_everywhere_fails_on_the_mean():
    a = picture()
    r = cmp.compare(a + 3, a)               # every pixel 3 levels brighter
    assert r.bad_fraction == 0 and r.mean_difference == pytest.approx(3) and not r.alike


def test_sizes_differ_never_alike_and_alpha_compared():
    a = picture()
    r = cmp.compare(a, a[:, :-1])
    assert not r.same_size and not r.alike and "80x60 against 79x60" in r.summary()
    rgba = np.dstack([a, np.full(a.shape[:2], 255, np.uint8)])
    assert cmp.compare(rgba, a).alike                 # opaque alpha is no difference
    rgba[:30, :, 3] = 0
    assert not cmp.compare(rgba, a).alike             # half transparent is one


def test_diff_image_marks_what_differs_in_red_on_pale_reference():
    a = picture()
    b = a.copy()
    b[5, 5] = 0
    b[6, 6] = a[6, 6] + 5                   # under the allowance
    d = cmp.diff_image(b, a)
    assert d.shape == a.shape and d.dtype == np.uint8
    assert tuple(d[5, 5]) == cmp.DIFF_RED and tuple(d[6, 6]) == cmp.DIFF_FAINT
    assert d[0, 0].min() > a[0, 0].min() and len(set(d[0, 0])) == 1      # pale grey
    assert (d[20:40, 30:50] != cmp.DIFF_RED).any(axis=2).all()            # the square: grey


# ---- the command ----------------------------------------------------------------------

def test_compare_alike_exits_0_and_writes_nothing(pair, capsys):
    assert main(["compare", str(pair / "a.png"), str(pair / "a2.png")]) == 0
    out = capsys.readouterr().out
    assert out.startswith("alike:") and "tolerance 0.0500%" in out
    assert not (pair / "a-diff.png").exists()


def test_compare_different_exits_1_with_summary_and_diff_beside_a(pair, capsys):
    assert main(["compare", str(pair / "a.png"), str(pair / "b.png")]) == 1
    out = capsys.readouterr().out.strip()
    assert len(out.splitlines()) == 1
    # 2 columns of 20 rows appear and 2 vanish: 80 of 4800 pixels
    assert out.startswith("different:") and "1.6667% of pixels off by more than 24/255" in out
    assert "tolerance 0.0500%" in out and f"wrote {pair / 'a-diff.png'}" in out
    d = iio.imread(pair / "a-diff.png")
    red = (d == cmp.DIFF_RED).all(axis=2)
    assert red.sum() == 80 and red[20:40, 30:32].all() and red[20:40, 50:52].all()


def test_compare_tolerance_and_diff_flags(pair, capsys):
    assert main(["compare", str(pair / "a.png"), str(pair / "b.png"),
                 "--tolerance", "0.02"]) == 1          # the mean still differs
    diff = pair / "out" / "d.png"
    diff.parent.mkdir()
    assert main(["compare", str(pair / "b.png"), str(pair / "a.png"), "--diff", str(diff)]) == 1
    assert diff.exists() and not (pair / "b-diff.png").exists()


def test_compare_different_sizes_exit_1_one_line(pair, capsys):
    iio.imwrite(pair / "small.png", picture(50, 80))
    assert main(["compare", str(pair / "a.png"), str(pair / "small.png")]) == 1
    out = capsys.readouterr().out
    assert "sizes differ: 80x60 against 80x50" in out and "no diff image" in out
    assert not (pair / "a-diff.png").exists()


@pytest.mark.parametrize("make, says", [
    (lambda p: None, "no such file"),
    (lambda p: p.write_text("not a png"), "not a picture Pillow can read"),
    (lambda p: p.mkdir(), "is a folder"),
])
def test_compare_bad_file_exit_2_one_line(pair, capsys, make, says):
    bad = pair / "bad.png"
    make(bad)
    assert main(["compare", str(pair / "a.png"), str(bad)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and err.startswith(f"springscene: error: {bad}: {says}")


@pytest.mark.parametrize("flags, says", [
    (["--tolerance", "2"], "--tolerance 2: a share of the pixels"),
    (["--tolerance", "nan"], "--tolerance nan"),
    (["--diff", "x.jpg"], "--diff x.jpg: unknown output format"),
])
def test_compare_bad_flags_exit_2(pair, capsys, flags, says):
    assert main(["compare", str(pair / "a.png"), str(pair / "b.png"), *flags]) == 2
    assert says in capsys.readouterr().err
    assert not (pair / "a-diff.png").exists()


def test_compare_from_the_installed_command(pair):
    proc = run_cli("compare", pair / "a.png", pair / "b.png")
    assert proc.returncode == 1 and "different:" in proc.stdout and not proc.stderr


# ---- the pytest plugin ----------------------------------------------------------------

PLUGIN_TEST = """
import numpy as np
import os

def test_picture(verify_image):
    img = np.full((40, 60, 3), 255, np.uint8)
    shift = int(os.environ.get("SHIFT", "0"))
    img[10:20, 10 + shift:20 + shift] = (0, 0, 200)
    verify_image(img, "square.png")
"""


@pytest.fixture
def plugin_project(pytester):
    pytester.makepyfile(test_pic=PLUGIN_TEST)
    return pytester


def test_plugin_first_run_stores_then_compares(plugin_project, monkeypatch):
    p = plugin_project
    result = p.runpytest("-W", "default")
    result.assert_outcomes(passed=1, warnings=1)
    result.stdout.fnmatch_lines(["*stored a new baseline*square.png*"])
    stored = p.path / "baselines" / "square.png"
    assert iio.imread(stored)[15, 15].tolist() == [0, 0, 200]
    p.runpytest().assert_outcomes(passed=1)                 # the same picture: passes
    monkeypatch.setenv("SHIFT", "1")
    result = p.runpytest()
    result.assert_outcomes(failed=1)
    folder = p.path / ".pytest_cache" / "d" / "springscene-diffs"
    result.stdout.fnmatch_lines([f"*square.png: 0.8333% of pixels off*the new picture: "
                                 f"{folder}*square.png and baselines__square-diff.png*"])
    diff = iio.imread(folder / "baselines__square-diff.png")
    assert (diff == cmp.DIFF_RED).all(axis=2).sum() == 20       # a column in, a column out
    assert iio.imread(folder / "baselines__square.png")[15, 20].tolist() == [0, 0, 200]
    assert iio.imread(stored)[15, 20].tolist() == [255, 255, 255]     # baseline untouched


def test_plugin_regen_flag_and_diff_folder(plugin_project, monkeypatch, tmp_path):
    p = plugin_project
    p.runpytest().assert_outcomes(passed=1)
    monkeypatch.setenv("SHIFT", "3")
    diffs = tmp_path / "ci-artifacts"
    p.runpytest("--springscene-diffs", str(diffs)).assert_outcomes(failed=1)
    assert (diffs / "baselines__square-diff.png").exists()
    p.runpytest("--springscene-regen").assert_outcomes(passed=1)
    assert iio.imread(p.path / "baselines" / "square.png")[15, 22].tolist() == [0, 0, 200]
    p.runpytest().assert_outcomes(passed=1)


def test_plugin_ini_folder_and_missing_fail(pytester):
    pytester.makeini("[pytest]\nspringscene_baselines = pics\n"
                     "springscene_missing_baseline = fail\n")
    pytester.makepyfile(test_pic=PLUGIN_TEST)
    result = pytester.runpytest()
    result.assert_outcomes(failed=1)
    result.stdout.fnmatch_lines(["*no baseline *pics*square.png; run pytest with "
                                 "--springscene-regen*"])
    pytester.runpytest("--springscene-regen").assert_outcomes(passed=1)
    assert (pytester.path / "pics" / "square.png").exists()
    pytester.runpytest().assert_outcomes(passed=1)


def test_compare_help_states_the_measure_and_default(capsys):
    with pytest.raises(SystemExit) as exc:
        main(["compare", "--help"])
    out = " ".join(capsys.readouterr().out.split())
    assert exc.value.code == 0 and "differ by more than 24/255" in out and "0.05%" in out


def test_the_projects_regen_baselines_flag_drives_the_plugin(pytester):
    """tests/conftest.py's --regen-baselines (make baselines) is the plugin's regen."""
    pytester.makeconftest((Path(__file__).parent / "conftest.py").read_text())
    pytester.makepyfile(test_flag="""
        from springscene import pytest_plugin

        def test_flag(regen, request):
            assert regen is pytest_plugin.regenerating(request.config) is True
    """)
    pytester.runpytest("--regen-baselines").assert_outcomes(passed=1)
    pytester.runpytest("--springscene-regen").assert_outcomes(passed=1)
    pytester.runpytest().assert_outcomes(failed=1)
