"""What every VPython object checks in what a program gives it.

A vector argument is copied (so the program's own vector is never linked to the
object) and anything else is VPython's ``TypeError``; a VPython feature
springscene does not reproduce (frames, materials) is refused with an
:class:`UnsupportedError` naming it. ``texture`` and ``bumpmap`` are not refused:
an object keeps them as given (as ``vpython.py`` does) and the renderer draws the
texture (:mod:`.textures`). Used by the canvas, the objects and curves.
"""

from __future__ import annotations

from .vector import as_vector, vector

# VPython attributes springscene does not draw: refused with a message naming them
UNSUPPORTED: dict[str, str] = {}


class UnsupportedError(AttributeError):
    """A real VPython feature springscene does not reproduce."""


def unsupported(what: str) -> UnsupportedError:
    return UnsupportedError(f"{what} is not supported by springscene's vpython "
                            f"(it runs without a browser)")


def _vec(value, name: str) -> vector:
    """A fresh copy of ``value`` as a vector; VPython's error if it is not one."""
    if isinstance(value, vector):
        return vector(value)
    try:
        return as_vector(value, name)
    except TypeError:
        raise TypeError(f"{name} must be a vector") from None
