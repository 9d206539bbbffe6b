"""The terminal tables of ``analyze``: quantity, measured, theory, difference, unit.

One layout for the page's oscillator (:func:`springscene.science.analysis.table`) and
the model of matter (:func:`springscene.science.matter.table`); only the column widths
differ.
"""

from __future__ import annotations

from ..units import percent


def number(x: float | None) -> str:
    """Six significant figures, or a dash for nothing measured."""
    return "—" if x is None else f"{x:.6g}"


def header(label_width: int, measured_width: int) -> str:
    return (f"{'quantity':<{label_width}}{'measured':>{measured_width}}{'theory':>14}"
            f"{'difference':>12}  unit")


def row(label: str, measured: float | None, theory: float | None, unit: str, *,
        error: float | None = None, label_width: int, measured_width: int) -> str:
    """One line: the measured value (± its standard ``error``), theory, and their relative
    difference when theory is given and not zero."""
    diff = percent((measured - theory) / abs(theory)) if measured is not None and theory else ""
    m = number(measured) + (f" ± {error:.2g}" if error is not None else "")
    return (f"{label:<{label_width}}{m:>{measured_width}}{number(theory):>14}{diff:>12}  "
            f"{unit}")
