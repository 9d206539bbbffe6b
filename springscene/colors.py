"""VPython's colour names and values (``vpython.color``), and parsing of colour settings."""

from __future__ import annotations

import re

NAMED = {
    "red": (1.0, 0.0, 0.0),
    "green": (0.0, 1.0, 0.0),
    "blue": (0.0, 0.0, 1.0),
    "yellow": (1.0, 1.0, 0.0),
    "cyan": (0.0, 1.0, 1.0),
    "magenta": (1.0, 0.0, 1.0),
    "orange": (1.0, 0.6, 0.0),
    "purple": (0.4, 0.2, 0.6),
    "white": (1.0, 1.0, 1.0),
    "black": (0.0, 0.0, 0.0),
    # VPython has gray(g) as a function; plain "gray" is gray(0.5).
    "gray": (0.5, 0.5, 0.5),
    "grey": (0.5, 0.5, 0.5),
}

_GRAY = re.compile(r"^gr[ae]y\(\s*([0-9]*\.?[0-9]+)\s*\)$")

Color = tuple[float, float, float]


def parse_color(value: object) -> Color:
    """Return an RGB triple in [0, 1] from a name, ``"gray(g)"`` or ``[r, g, b]``.

    Raises ``ValueError`` with a short reason otherwise.
    """
    if isinstance(value, str):
        name = value.strip().lower()
        if name in NAMED:
            return NAMED[name]
        m = _GRAY.match(name)
        if m and 0.0 <= float(m.group(1)) <= 1.0:
            g = float(m.group(1))
            return (g, g, g)
        raise ValueError(f"unknown colour {value!r} (use a VPython name such as "
                         f"{', '.join(sorted(NAMED))}, gray(0.7), or [r, g, b])")
    if (isinstance(value, list) and len(value) == 3
            and all(isinstance(c, (int, float)) and not isinstance(c, bool) for c in value)
            and all(0.0 <= c <= 1.0 for c in value)):
        return (float(value[0]), float(value[1]), float(value[2]))
    raise ValueError("must be a colour name or [r, g, b] with each in 0..1")
