"""Numbers as people read them: SI prefixes and signed percentages, in one place.

Used by the tables (:mod:`springscene.science`), the figures, the colour bar and the
video clock, so that a picometre or a relative error reads the same everywhere.
"""

from __future__ import annotations

# (size, prefix) from kilo down to zepto
PREFIXES = ((1e3, "k"), (1.0, ""), (1e-3, "m"), (1e-6, "µ"), (1e-9, "n"), (1e-12, "p"),
            (1e-15, "f"), (1e-18, "a"), (1e-21, "z"))
MINUS = "−"       # U+2212, the typographic minus of figures


def prefixes(largest: str = "k", smallest: str = "z") -> tuple[tuple[float, str], ...]:
    """The (size, prefix) pairs from ``largest`` down to ``smallest`` ("" is the unit)."""
    names = [p for _, p in PREFIXES]
    return PREFIXES[names.index(largest):names.index(smallest) + 1]


def si_prefix(value: float, *, largest: str = "k", smallest: str = "z",
              tolerance: float = 0.0) -> tuple[float, str]:
    """(size, prefix) that shows ``value`` as 1 to 999 of the prefixed unit: the largest
    prefix, from ``largest`` down to ``smallest``, whose size |value| reaches (within a
    relative ``tolerance``); the smallest when none does."""
    value = abs(value)
    table = prefixes(largest, smallest)
    for size, prefix in table:
        if value >= size * (1 - tolerance):
            return size, prefix
    return table[-1]


def percent(fraction: float, digits: int = 3, minus: str = "-") -> str:
    """``fraction`` as a signed percentage, e.g. ``+0.063 %``; ``minus`` is the sign
    below zero (:data:`MINUS` in figures)."""
    return f"{100 * fraction:+.{digits}f} %".replace("-", minus)
