"""The order of a program's page: each canvas (at its first object) and each graph (at
its first point) takes the next place, once; the page is laid out in that order."""

from __future__ import annotations

import itertools

_slots = itertools.count()


def claim_slot(item) -> None:
    """Give a canvas (at its first object) or a graph (at its first point) its place on
    the page, once."""
    if getattr(item, "_page_slot", None) is None:
        item._page_slot = next(_slots)
