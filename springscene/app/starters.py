"""``springscene init``: copy a starter config or example program into the current folder,
and ``--version``. The work is :func:`springscene.api.init`'s and :func:`~springscene.api.starters`'."""

from __future__ import annotations

import argparse

from .. import __version__, api


def version() -> str:
    """What ``springscene --version`` prints."""
    return f"springscene {__version__}"


def add_init_command(sub) -> None:
    s = sub.add_parser("init", help="copy a starter config (wiki.toml by default) or an "
                       "example program into the current folder")
    s.add_argument("name", nargs="?", default="wiki.toml",
                   help="a starter: see --list (default wiki.toml)")
    s.add_argument("--list", action="store_true", help="list the starters and what they are")


def run_init(args: argparse.Namespace) -> int:
    if args.list:
        names = api.starters()
        width = max(len(name) for name in names)
        for name, summary in names.items():
            print(f"{name:<{width}}  {summary}")
        return 0
    path = api.init(args.name)
    print(f"wrote {path}")
    return 0
