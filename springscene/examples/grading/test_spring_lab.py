"""An instructor's tests of the spring lab, run on the student's program with pytest.

    pytest examples/grading/test_spring_lab.py          # on spring_lab.py, the marker's
    pytest examples/grading/test_spring_lab.py --springscene-program spring_lab_wrong.py

springscene's pytest plugin (installed with springscene) runs the program once, headless
and with nothing drawn, and gives each test its run: the block's position at each of
100 frames a program second, the program's own globals (m, k, L0), what it printed and
the points of its graphs. The checks are the lab sheet's:

- the period of the motion is within 2 % of 2 pi sqrt(m/k), for the m and k the program
  declares;
- K + Us, computed from the motion, stays within 1 % of its mean;
- the program prints its period, within 2 % of the motion's;
- it plots K, Us and K + Us, and its own K + Us curve is flat within 1 %.

``springscene grade submission.py --tests test_spring_lab.py --results results.json``
grades a submission with these tests (the period worth 2 points, ``pytest.mark.weight``)
and writes Gradescope's results.json; README.md says how.
"""

import math
import re

import numpy as np
import pytest

pytestmark = pytest.mark.vpython_program("spring_lab.py", fps=100, timeout=120)

PERIOD_TOLERANCE = 0.02
ENERGY_TOLERANCE = 0.01


@pytest.fixture
def run(vpython_run):
    """The program's run (made once a session): a springscene.Run."""
    return vpython_run()


def stretch(run) -> np.ndarray:
    """The spring's stretch at each frame, |ball - wall| - L0 (m)."""
    length = np.linalg.norm(run["ball"].pos - run["wall"].pos, axis=1)
    return length - run.globals["L0"]


def measured_period(run) -> float:
    """The mean time between the block's passes through equilibrium going right (the
    stretch passing 0 upwards), each pass placed between its two frames (s)."""
    t, x = run.times, stretch(run)
    i = np.nonzero((x[:-1] < 0) & (x[1:] >= 0))[0]
    assert len(i) >= 3, f"the block should oscillate: it passed equilibrium {len(i)} times"
    passes = t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])
    return float(np.diff(passes).mean())


@pytest.mark.weight(2)                # the lab's main result: 2 points, the others 1
def test_period_is_two_pi_root_m_over_k(run):
    m, k = run.globals["m"], run.globals["k"]
    expected = 2 * math.pi * math.sqrt(m / k)
    measured = measured_period(run)
    off = measured / expected - 1
    assert abs(off) <= PERIOD_TOLERANCE, (
        f"period {measured:.4f} s measured from the block's motion, expected 2 pi sqrt(m/k) "
        f"= {expected:.4f} s (m = {m} kg, k = {k} N/m): off by {off:+.1%}, more than "
        f"{PERIOD_TOLERANCE:.0%}")


def test_energy_is_conserved(run):
    m, k = run.globals["m"], run.globals["k"]
    v = np.gradient(run["ball"].pos, run.times, axis=0)        # m/s, central differences
    K = 0.5 * m * (v ** 2).sum(axis=1)
    Us = 0.5 * k * stretch(run) ** 2
    E = (K + Us)[1:-1]                        # the ends' one-sided differences left out
    spread = (E.max() - E.min()) / E.mean()
    assert spread <= ENERGY_TOLERANCE, (
        f"K + Us from the motion (k = {k} N/m) runs from {E.min():.4f} J to {E.max():.4f} J: "
        f"{spread:.1%} of its mean, more than {ENERGY_TOLERANCE:.0%}")


def test_prints_its_period(run):
    found = re.search(r"period\D*?(\d+(?:\.\d+)?(?:[eE][-+]?\d+)?)", run.printed)
    assert found, f"the program should print its period; it printed {run.printed!r}"
    printed, measured = float(found.group(1)), measured_period(run)
    assert printed == pytest.approx(measured, rel=PERIOD_TOLERANCE), (
        f"the program printed a period of {printed} s; its block's motion has {measured:.4f} s")


def test_plots_its_energy_and_the_total_is_flat(run):
    labels = [s.label.replace(" ", "") for s in run.series]
    assert {"K", "Us", "K+Us"} <= set(labels), (
        f"the program should plot K, Us and K + Us with gcurve; its curves: {labels}")
    total = run.series[labels.index("K+Us")].points()[:, 1]
    spread = (total.max() - total.min()) / total.mean()
    assert spread <= ENERGY_TOLERANCE, (
        f"the program's own K + Us curve runs from {total.min():.4f} J to "
        f"{total.max():.4f} J: {spread:.1%} of its mean, more than {ENERGY_TOLERANCE:.0%}")
