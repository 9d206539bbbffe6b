"""How the wiki figures and their captions write numbers: an error in two figures with
powers of ten as superscripts, and a number with a real minus sign."""

from __future__ import annotations

import math

from ..units import MINUS

_SUPERSCRIPT = str.maketrans("-0123456789", "⁻⁰¹²³⁴⁵⁶⁷⁸⁹")


def _fmt_err(x: float) -> str:
    """0.065, 3.7×10⁻³, 6.8×10⁵: two figures, powers of ten as superscripts."""
    if not math.isfinite(x) or x == 0 or 0.01 <= abs(x) < 100:
        return f"{x:.2g}"
    e = math.floor(math.log10(abs(x)))
    mant = x / 10 ** e
    if round(mant, 1) >= 10:
        mant, e = mant / 10, e + 1
    return f"{mant:.2g}×10{str(e).translate(_SUPERSCRIPT)}"


def _signed(x: float, fmt: str = ".3f") -> str:
    """A number with a real minus sign."""
    return format(x, fmt).replace("-", MINUS)
