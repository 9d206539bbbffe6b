"""The pytest plugin ``springscene grade`` runs an instructor's tests with: each test's
outcome, message, weight and run options, written as JSON for :mod:`.grading` to read.

Loaded in the grading's own pytest process (``-p springscene.batch.grade_report
--springscene-outcomes FILE``), never in this one. ``FILE`` holds::

    {"tests": [{"name": "test_period", "weight": 1.0, "options": {"fps": 100},
                "outcome": "failed", "message": "period 0.4967 s ..."}, ...],
     "errors": ["test_lab.py: SyntaxError: ..."]}

``options`` are the test's ``vpython_program`` marker's keyword arguments; ``outcome`` is
``passed``, ``failed`` or ``skipped`` (absent after ``--collect-only``); ``errors`` are
the files that could not be collected, one line each.
"""

from __future__ import annotations

import json
import os
from pathlib import Path

import pytest

MAX_LINES = 4            # of a failure's message: the assertion's own lines
MAX_CHARS = 1000


def pytest_addoption(parser) -> None:
    parser.getgroup("springscene").addoption(
        "--springscene-outcomes", dest="springscene_outcomes", metavar="FILE",
        help="write each test's outcome, message, weight and run options to FILE (JSON)")


def pytest_configure(config) -> None:
    target = config.getoption("springscene_outcomes", None)
    if target:
        config.pluginmanager.register(Outcomes(Path(target)), "springscene-outcomes")


class Outcomes:
    """The session's tests as they are collected and run, written at its end."""

    def __init__(self, target: Path) -> None:
        self.target = target
        self.tests: dict[str, dict] = {}
        self.errors: list[str] = []

    def pytest_collectreport(self, report) -> None:
        if report.failed:
            self.errors.append(f"{report.nodeid or 'the tests'}: "
                               f"{_last_error_line(report.longreprtext)}")

    def pytest_collection_finish(self, session) -> None:
        for item in session.items:
            program = item.get_closest_marker("vpython_program")
            try:
                weight = _weight(item.get_closest_marker("weight"))
            except ValueError as exc:
                self.errors.append(f"{item.nodeid}: {exc}")
                continue
            self.tests[item.nodeid] = {"name": _name(item.nodeid), "weight": weight,
                                       "options": dict(program.kwargs) if program else {}}

    @pytest.hookimpl(wrapper=True)
    def pytest_runtest_makereport(self, item, call):
        report = yield
        entry = self.tests.get(item.nodeid)
        if (call.excinfo is not None and not report.skipped and entry is not None
                and "message" not in entry):
            entry["message"] = message_of(call.excinfo.value)
        return report

    def pytest_runtest_logreport(self, report) -> None:
        entry = self.tests.get(report.nodeid)
        if entry is None:
            return
        if report.failed:
            entry["outcome"] = "failed"
        elif report.skipped and entry.get("outcome") != "failed":
            entry["outcome"] = "skipped"
            entry.setdefault("message", _skip_reason(report))
        elif report.when == "call" and "outcome" not in entry:
            entry["outcome"] = "passed"

    def pytest_sessionfinish(self, session) -> None:
        data = {"tests": list(self.tests.values()), "errors": self.errors}
        tmp = self.target.with_name(f"{self.target.name}.{os.getpid()}.tmp")
        tmp.write_text(json.dumps(data, default=repr, indent=1))
        os.replace(tmp, self.target)


def message_of(error: BaseException) -> str:
    """What a failed test says: an assertion's own message (its first lines, before
    pytest's ``assert ...`` explanation; that explanation's first line for an assertion
    without one), a ``pytest.fail`` line, or the exception's type and message."""
    text = str(error).strip()
    if isinstance(error, AssertionError):
        lines = text.splitlines()
        own = list(_until_explanation(lines))
        lines = own or lines[:1] or ["assertion failed"]
    elif isinstance(error, pytest.fail.Exception):
        lines = text.splitlines()
    else:
        last = text.splitlines()[-1] if text else ""
        # a program's traceback (springscene's ProgramError) ends in its error's line
        lines = [last if "Traceback (most recent call last)" in text
                 else f"{type(error).__name__}: {last}".rstrip(": ")]
    return _cut("\n".join(lines[:MAX_LINES]))


def _until_explanation(lines: list[str]):
    for line in lines:
        if line.startswith("assert ") or line.startswith(" +"):
            return
        yield line


def _cut(text: str) -> str:
    return text if len(text) <= MAX_CHARS else text[:MAX_CHARS - 3] + "..."


def _name(nodeid: str) -> str:
    """A test's name without its file: ``test_period``, ``TestLab::test_period[2]``."""
    return nodeid.split("::", 1)[-1]


def _weight(marker) -> float:
    """The points of ``@pytest.mark.weight(points)`` (default 1); a ValueError for a
    weight that is not a number of 0 or more."""
    if marker is None:
        return 1.0
    points = marker.args[0] if marker.args else marker.kwargs.get("points")
    if isinstance(points, bool) or not isinstance(points, (int, float)) or not points >= 0:
        raise ValueError(f"weight({points!r}): the points must be a number of 0 or more")
    return float(points)


def _skip_reason(report) -> str:
    longrepr = report.longrepr
    reason = longrepr[2] if isinstance(longrepr, tuple) and len(longrepr) == 3 else ""
    return _cut(str(reason).removeprefix("Skipped: "))


def _last_error_line(text: str) -> str:
    """The line naming a collection's error: pytest's last ``E   ...`` line, else its last."""
    lines = [line for line in text.splitlines() if line.strip()]
    errors = [line[1:].strip() for line in lines if line.startswith("E ")]
    return _cut((errors or lines or ["could not be collected"])[-1])

