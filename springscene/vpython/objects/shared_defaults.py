"""What the objects of a VPython class share until each sets its own: a few hundred
bytes an object.

A sphere made with ``pos``, ``radius`` and ``color`` stores those and nothing else of
VPython's twenty-odd attributes; the rest are its class's (``standard``'s class-level
scalars) or, for the vectors, one read-only :class:`Default` vector the whole class
points to. An object copies a default vector the first time it changes it in place
(:meth:`.standard_attributes.standard._own`), so ``ball.axis.x = 2`` changes that ball alone.

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

:func:`compact` does for the values a solid is made with what the defaults do for
VPython's: its ``axis``, ``up``, ``size`` and ``color`` become read-only vectors shared
by every object made with the same values (a thousand red spheres of one radius, one
colour and one size vector), and the components of its ``pos`` float objects shared with
equal ones (a lattice's spheres share their coordinates): about 250 bytes a sphere of a
lattice, 100 of a random cloud. Both caches are bounded (:data:`LIMIT`), emptied when full;
floats that do not repeat (a random cloud's) stop the interning for a while (:data:`PAUSE`
objects), which then only cost time.
"""

from __future__ import annotations

import struct
from math import copysign

from ..core.vectors import vector

LIMIT = 4096          # floats, and shared vectors, kept for reuse at most (then started afresh)
PAUSE = 4 * LIMIT     # objects made without interning floats after a cache full of misses
_FLOATS: dict[float, float] = {}
_hits = 0             # floats found in the cache since it was last emptied
_paused = 0           # objects still to make without interning
_SHARED: dict[bytes, "Default"] = {}
_pack = struct.Struct("<3d").pack
_COMPACTED = ("_axis", "_up", "_size", "_color")


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


def interned(x: float) -> float:
    """``x``, or an equal float object stored before (never 0.0 for -0.0)."""
    global _hits, _paused
    f = _FLOATS.get(x)
    if f is None:
        if len(_FLOATS) >= LIMIT:
            if _hits < LIMIT // 4:      # mostly misses: values that do not repeat
                _paused = PAUSE
            _hits = 0
            _FLOATS.clear()
        _FLOATS[x] = x
        return x
    if f == 0.0 and copysign(1.0, f) != copysign(1.0, x):
        return x
    _hits += 1
    return f


def shared(v: vector) -> Default:
    """A read-only vector with ``v``'s components (bit for bit), the same one for every
    equal ``v`` while it is in the cache: ``v`` itself, made read-only, if none is yet
    (``v`` must be a vector no one else holds: an object's own, never a program's)."""
    key = _pack(v._x, v._y, v._z)
    d = _SHARED.get(key)
    if d is None:
        if len(_SHARED) >= LIMIT:
            _SHARED.clear()
        if not _paused:
            v._x, v._y, v._z = interned(v._x), interned(v._y), interned(v._z)
        v.__class__ = Default
        _SHARED[key] = d = v
    return d


def compact(obj) -> None:
    """A new solid's vectors shared (:func:`shared`), its ``pos``'s components interned;
    only vectors no program holds (no ``_on_change`` hook yet). Objects copy a shared
    vector before changing it in place, as they copy a default
    (:meth:`.standard_attributes.standard._own`)."""
    global _paused
    p = obj._pos
    if _paused:
        _paused -= 1
    elif type(p) is vector and p._on_change is None:
        p._x, p._y, p._z = interned(p._x), interned(p._y), interned(p._z)
    for name in _COMPACTED:
        v = getattr(obj, name)
        if type(v) is vector and v._on_change is None:
            d = shared(v)
            if d is not v:
                object.__setattr__(obj, name, d)
