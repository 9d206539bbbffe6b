"""``springscene grade submission.py --tests grading.py --results results.json``: one
student's program run as data and graded by the instructor's pytest tests
(:mod:`springscene.batch.grading`), with Gradescope's ``results.json``.

Exit 0 once graded, whatever the score (a program that raised, ran out of time or
memory is graded too: the tests that need its run fail with the reason); 2 for bad
input (a missing file, a bad flag, tests that cannot be collected, no sandbox to be had),
one line naming it.
"""

from __future__ import annotations

import argparse

from ..batch import grading
from ..outputs import check_output


def add_grade_command(sub) -> None:
    s = sub.add_parser("grade", help="run one VPython program as data and grade it with "
                       "pytest tests: a table, and Gradescope's results.json")
    s.add_argument("program", help="the student's VPython program")
    s.add_argument("--tests", required=True, metavar="TESTS.py",
                   help="the instructor's pytest file: tests of the run (vpython_run, the "
                   "run fixture), @pytest.mark.weight(points) for a test worth more than 1")
    s.add_argument("--results", metavar="RESULTS.json",
                   help="write the grades there in Gradescope's autograder format")
    s.add_argument("--no-sandbox", action="store_true",
                   help="run the program without the sandbox (it could read and write "
                   "anything this user can)")
    s.add_argument("--timeout", type=float, metavar="S",
                   help="stop the program after S seconds of wall clock (default: the "
                   "tests' vpython_program marker's, else none)")
    s.add_argument("--max-memory", metavar="SIZE",
                   help="stop the program when it uses more memory, e.g. 500M (default: "
                   "the marker's, else half the machine's)")
    s.add_argument("--duration", type=float, metavar="S",
                   help="program seconds to run (default: the marker's, else 10 or its end)")
    s.add_argument("--fps", type=int, help="frames a program second kept in the run "
                   "(default: the marker's, else 50)")


def run_grade(args: argparse.Namespace) -> int:
    if args.results is not None:
        check_output(args.results, (".json",), "--results")     # before the run, not after
    grades = grading.grade_program(args.program, args.tests, sandbox=not args.no_sandbox,
                                   timeout=args.timeout, max_memory=args.max_memory,
                                   duration=args.duration, fps=args.fps)
    if grades.output:
        print(grades.output.splitlines()[0])        # how the run ended
    print(grading.table(grades))
    if args.results is not None:
        print(f"wrote {grading.write_results(grades, args.results)}")
    return 0
