"""``springscene compare A.png B.png``: image regression from the command line.

Exit 0 when the pictures are alike within the tolerance, 1 when they differ (a line
saying by how much, and a diff image), 2 on bad input (a missing or unreadable file).
"""

from __future__ import annotations

import argparse

from ..view.compare import MAX_MEAN_DIFF, PIXEL_TOLERANCE, TOLERANCE, compare_files

EXIT_DIFFERENT = 1


def add_compare_command(sub) -> None:
    s = sub.add_parser("compare", help="compare two pictures (image regression): exit 1 and "
                       "a diff image when they differ")
    s.add_argument("image", metavar="A", help="the picture to check (PNG, JPEG, ...)")
    s.add_argument("reference", metavar="B", help="the reference picture")
    s.add_argument("--tolerance", type=float, default=TOLERANCE, metavar="T",
                   help=f"the share of pixels (0 to 1) allowed to differ by more than "
                   f"{PIXEL_TOLERANCE}/255 in a channel (default {TOLERANCE:g} = "
                   f"{100 * TOLERANCE:.2f}%%; the mean difference must also stay within "
                   f"{MAX_MEAN_DIFF:g}/255)")
    s.add_argument("--diff", metavar="DIFF.png",
                   help="where the diff image goes when they differ (default: A-diff.png "
                   "beside A): B pale grey, pixels off in red")


def run_compare(args: argparse.Namespace) -> int:
    result, diff = compare_files(args.image, args.reference, tolerance=args.tolerance,
                                 diff=args.diff)
    if result.alike:
        print(f"alike: {args.image} and {args.reference}: {result.summary()}")
        return 0
    wrote = f"; wrote {diff}" if diff is not None else "; no diff image"
    print(f"different: {args.image} and {args.reference}: {result.summary()}{wrote}")
    return EXIT_DIFFERENT
