"""Overlays drawn into the video around the 3D scene: a clock, a y(t) graph, energy bars."""

from __future__ import annotations

from .errors import UserError

OVERLAYS = ("time", "graph", "energy")


def parse_overlays(text: str, flag: str = "--overlay") -> tuple[str, ...]:
    """``"time,graph"`` as ("time", "graph"); unknown names are bad input."""
    names = tuple(dict.fromkeys(n.strip() for n in str(text).split(",") if n.strip()))
    unknown = [n for n in names if n not in OVERLAYS]
    if unknown:
        raise UserError(f"{flag} {text!r}: unknown overlay {unknown[0]!r} "
                        f"(use a comma list of {', '.join(OVERLAYS)})")
    return names
