"""VPython's helpers for an object's ``axis`` and ``up``: ``adjust_up``, ``adjust_axis``,
``object_rotate`` (``vpython/vector.py``).

Like VPython's, they write the components of the vectors they are given directly and
notify no one: the object that calls them knows what changed.
"""

from __future__ import annotations

from math import pi

from .vector import vector

__all__ = ["adjust_axis", "adjust_up", "object_rotate"]


def _turn(v: vector, angle: float, axis: vector) -> None:
    """Rotate ``v`` in place without notifying (VPython's ``rotate_in_place``)."""
    v._x, v._y, v._z = v._rotation(angle, axis)


def object_rotate(objaxis: vector, objup: vector, angle: float, axis: vector) -> None:
    """Turn an object's ``axis`` and ``up`` in place by ``angle`` about ``axis``."""
    _turn(objaxis, angle, axis)
    _turn(objup, angle, axis)


def adjust_up(oldaxis: vector, newaxis: vector, up: vector, save_oldaxis):
    """VPython's update of ``up`` when an object's axis changes from ``oldaxis``
    to ``newaxis``: ``up`` turns with the axis unless they are perpendicular.

    Writes ``up`` and ``oldaxis`` (set to ``newaxis``) in place, without
    notifying; returns the saved axis to restore after a zero axis, or None.
    """
    if abs(newaxis._x) + abs(newaxis._y) + abs(newaxis._z) == 0:
        if save_oldaxis is None:
            save_oldaxis = oldaxis
        return save_oldaxis
    if save_oldaxis is not None:
        oldaxis._x = save_oldaxis._x
        oldaxis._y = save_oldaxis._y
        oldaxis._z = save_oldaxis._z
        save_oldaxis = None
    if newaxis.dot(up) != 0:
        angle = oldaxis.diff_angle(newaxis)
        if angle > 1e-6:
            if abs(angle - pi) < 1e-6:
                up._x = -up._x
                up._y = -up._y
                up._z = -up._z
            else:
                _turn(up, angle, oldaxis.cross(newaxis))
    oldaxis._x = newaxis._x
    oldaxis._y = newaxis._y
    oldaxis._z = newaxis._z
    return save_oldaxis


def adjust_axis(oldup: vector, newup: vector, axis: vector, save_oldup):
    """VPython's update of ``axis`` when an object's up changes (the mirror of
    :func:`adjust_up`); writes in place without notifying."""
    if abs(newup._x) + abs(newup._y) + abs(newup._z) == 0:
        if save_oldup is None:
            save_oldup = oldup
        return save_oldup
    if save_oldup is not None:
        oldup = save_oldup      # as VPython: the saved vector stands in for oldup
        save_oldup = None
    if newup.dot(axis) != 0:
        angle = oldup.diff_angle(newup)
        if angle > 1e-6:
            if abs(angle - pi) < 1e-6:
                axis._x = -axis._x
                axis._y = -axis._y
                axis._z = -axis._z
            else:
                _turn(axis, angle, oldup.cross(newup))
    oldup._x = newup._x
    oldup._y = newup._y
    oldup._z = newup._z
    return save_oldup
