"""VPython's helpers for an object's ``axis`` and ``up``: ``adjust_up``, ``adjust_axis``,
``object_rotate`` (``vpython/vector.py``).

Like VPython's, they write the components of the vectors they are given directly and
notify no one: the object that calls them knows what changed.
"""

from __future__ import annotations

from math import pi

from .vectors import vector

__all__ = ["adjust_axis", "adjust_up", "object_rotate"]


def _turn(v: vector, angle: float, axis: vector) -> None:
    """Rotate ``v`` in place without notifying (VPython's ``rotate_in_place``)."""
    v._x, v._y, v._z = v._rotation(angle, axis)


def object_rotate(objaxis: vector, objup: vector, angle: float, axis: vector) -> None:
    """Turn an object's ``axis`` and ``up`` in place by ``angle`` about ``axis``."""
    _turn(objaxis, angle, axis)
    _turn(objup, angle, axis)


def _follow(old: vector, new: vector, other: vector, saved, copy_saved: bool):
    """VPython's rule behind :func:`adjust_up` and :func:`adjust_axis`: ``other`` turns as
    ``old`` turns into ``new`` unless they are square; ``old`` becomes ``new``. A zero
    ``new`` saves ``old`` instead (returned); the saved one then stands in for ``old``,
    its components copied in (``adjust_up``) or the vector itself (``adjust_axis``)."""
    if abs(new._x) + abs(new._y) + abs(new._z) == 0:
        return old if saved is None else saved
    if saved is not None:
        if copy_saved:
            old._x, old._y, old._z = saved._x, saved._y, saved._z
        else:
            old = saved
        saved = None
    if new.dot(other) != 0:
        angle = old.diff_angle(new)
        if angle > 1e-6:
            if abs(angle - pi) < 1e-6:
                other._x, other._y, other._z = -other._x, -other._y, -other._z
            else:
                _turn(other, angle, old.cross(new))
    old._x, old._y, old._z = new._x, new._y, new._z
    return saved


def adjust_up(oldaxis: vector, newaxis: vector, up: vector, save_oldaxis):
    """VPython's update of ``up`` when an object's axis changes from ``oldaxis``
    to ``newaxis``: ``up`` turns with the axis unless they are perpendicular.

    Writes ``up`` and ``oldaxis`` (set to ``newaxis``) in place, without
    notifying; returns the saved axis to restore after a zero axis, or None.
    """
    return _follow(oldaxis, newaxis, up, save_oldaxis, copy_saved=True)


def adjust_axis(oldup: vector, newup: vector, axis: vector, save_oldup):
    """VPython's update of ``axis`` when an object's up changes (the mirror of
    :func:`adjust_up`); writes in place without notifying."""
    return _follow(oldup, newup, axis, save_oldup, copy_saved=False)
