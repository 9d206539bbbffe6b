"""What every VPython object checks in what a program gives it.

A vector argument is copied (so the program's own vector is never linked to the
object) and anything else is VPython's ``TypeError``; a choice among a few words
(``trail_type``) is VPython's ``ValueError`` naming them (:func:`one_of`). A name
VPython has and springscene lacks fails with an :class:`UnsupportedError` naming it
(the package's ``__getattr__``). Used by the canvas, the objects and curves, and as the
checks of their :class:`.attributes.Linked` attributes.
"""

from __future__ import annotations

from .vectors import as_vector, vector

class UnsupportedError(AttributeError):
    """A real VPython feature springscene does not reproduce."""


def _vec(value, name: str) -> vector:
    """A fresh copy of ``value`` as a vector; VPython's error if it is not one."""
    if isinstance(value, vector):
        return vector(value)
    try:
        return as_vector(value, name)
    except TypeError:
        raise TypeError(f"{name} must be a vector") from None


def one_of(*choices):
    """A check that a value is one of ``choices``, VPython's ``ValueError`` if not
    ("trail_type must be 'curve' or 'points'")."""
    def check(value, name: str):
        if value not in choices:
            raise ValueError(f"{name} must be {' or '.join(map(repr, choices))}")
        return value
    return check
