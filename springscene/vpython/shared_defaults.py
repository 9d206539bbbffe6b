"""What the objects of a VPython class share until each sets its own (issue 16: memory).

A sphere made with ``pos``, ``radius`` and ``color`` stores those and nothing else of
VPython's twenty-odd attributes; the rest are its class's (``standard``'s class-level
scalars) or, for the vectors, one read-only :class:`Default` vector the whole class
points to. An object copies a default vector the first time it changes it in place
(:meth:`.objects.standard._own`), so ``ball.axis.x = 2`` changes that ball alone.

The default vectors are stored *on each object* (one pointer), not at class level:
CPython 3.11 does not specialise an attribute read when the class holds an object of a
Python class under the same name, and the renderer reads ``_pos``, ``_axis``, ``_up``,
``_size`` and ``_color`` of every object every frame.

:func:`seed_keys` puts those names first in the class's key table. CPython keeps one
table of attribute names a class; each new object gets a value array as long as the
table plus a spare that shrinks to one slot as objects are made, and an object that
needs a name the table lacks when it is full gets a whole dictionary (~600 B more).
Seeded, objects made later with more attributes than the first ones (``sphere()`` then
a thousand spheres with pos and colour) still fit in the shared table.
"""

from __future__ import annotations

from .vector import vector


class Default(vector):
    """A default vector every object of a class points to until it sets its own. Never
    changed: a write (an object that forgot to copy it first) is an error, not a change
    to every object at once."""

    __slots__ = ()

    def __setattr__(self, name: str, value) -> None:
        raise AttributeError("a shared default vector cannot be changed")


def default(x: float, y: float, z: float) -> Default:
    """A read-only default vector ``<x, y, z>``."""
    v = object.__new__(Default)
    for name, value in (("_x", float(x)), ("_y", float(y)), ("_z", float(z)),
                        ("_on_change", None)):
        object.__setattr__(v, name, value)
    return v


def _is_property(cls, name: str) -> bool:
    """A data descriptor on the class (3D text's ``_axis``): not an entry of the table."""
    return hasattr(getattr(cls, name, None), "__set__")


def stored(cls, values: dict) -> tuple:
    """``(name, default)`` pairs each object of ``cls`` stores at its start: ``values``
    without the names the class serves itself (properties)."""
    return tuple((name, v) for name, v in values.items() if not _is_property(cls, name))


def seed_keys(cls, names) -> None:
    """Put ``names`` first in ``cls``'s key table, before any object of it is made (a
    throw-away object given them; a class with a ``__del__`` of its own or inherited, a
    program's, is left as it is, so its probe runs none of its code)."""
    if getattr(cls, "__del__", None) is not None:
        return
    probe = object.__new__(cls)
    for name in names:
        if not _is_property(cls, name):
            object.__setattr__(probe, name, None)
