"""VPython's solid objects: box, pyramid, sphere, ellipsoid, cylinder, cone, arrow, helix, ring.

Each is a :class:`.standard_attributes.standard` with its own kind, default size and the
attributes VPython gives it (``radius``, ``shaftwidth``, ``coils``, ``thickness``,
...), all views of ``size`` where VPython has them so. The meshes they are drawn
with are in :mod:`..geometry.meshes`.
"""

from __future__ import annotations

from ..core.attributes import Linked
from .standard_attributes import standard
from ..core.vectors import vector


class box(standard):
    _kind = "box"
    _compact = True


class pyramid(standard):
    _kind = "pyramid"
    _compact = True


class _Round(standard):
    """Objects whose ``radius`` is half of size.y (and size.z)."""

    _compact = True

    @property
    def radius(self) -> float:
        return self._size.y / 2

    @radius.setter
    def radius(self, value) -> None:
        d = 2 * float(value)
        self.size = vector(self._size.x, d, d)


class sphere(_Round):
    _kind = "sphere"
    _default_size = (2.0, 2.0, 2.0)
    _axis_sets_size = False

    @_Round.radius.setter
    def radius(self, value) -> None:
        d = 2 * float(value)
        self.size = vector(d, d, d)


class simple_sphere(sphere):
    _kind = "sphere"


class ellipsoid(sphere):
    _kind = "sphere"     # drawn as a scaled sphere
    _default_size = (1.0, 1.0, 1.0)
    _axis_sets_size = True


class cylinder(_Round):
    _kind = "cylinder"
    _default_size = (1.0, 2.0, 2.0)


class cone(_Round):
    _kind = "cone"
    _default_size = (1.0, 2.0, 2.0)


class arrow(standard):
    """``shaftwidth``, ``headwidth``, ``headlength``: 0 means VPython's automatic value."""

    _kind = "arrow"
    _compact = True
    _default_size = (1.0, 0.2, 0.2)
    _shaftwidth = _headwidth = _headlength = 0.0
    _round = False

    shaftwidth = Linked(float, then="_touch")
    headwidth = Linked(float, then="_touch")
    headlength = Linked(float, then="_touch")
    round = Linked(bool, then="_touch")

    def _clone_args(self) -> dict:
        return {**super()._clone_args(), "shaftwidth": self._shaftwidth,
                "headwidth": self._headwidth, "headlength": self._headlength}


class helix(_Round):
    """A coil from ``pos`` along ``axis``: ``radius`` to the wire's centre line,
    ``thickness`` the wire's diameter (unset: radius/10), ``coils`` turns."""

    _kind = "helix"
    _default_size = (1.0, 2.0, 2.0)
    _coils = 5.0
    _thickness = None
    _ccw = True

    coils = Linked(float, then="_touch")
    ccw = Linked(bool, then="_touch")
    thickness = Linked(float, then="_touch", get=lambda self: (
        self._thickness if self._thickness is not None else self.radius / 10))

    def _clone_args(self) -> dict:
        return {**super()._clone_args(), "coils": self._coils, "thickness": self.thickness,
                "ccw": self._ccw}


class ring(standard):
    """A torus centred on ``pos`` whose plane is square to ``axis``: ``radius`` to the
    tube's centre, ``thickness`` the tube's radius (VPython's size = (2t, 2(R+t), 2(R+t)))."""

    _kind = "ring"
    _compact = True
    _default_size = (0.2, 2.2, 2.2)
    _axis_sets_size = False

    @property
    def thickness(self) -> float:
        return self._size.x / 2

    @thickness.setter
    def thickness(self, value) -> None:
        r = self.radius
        t = float(value)
        self._size = vector(2 * t, 2 * (r + t), 2 * (r + t))
        self._touch()

    @property
    def radius(self) -> float:
        return (self._size.y - self._size.x) / 2

    @radius.setter
    def radius(self, value) -> None:
        t = self.thickness
        r = float(value)
        self._size = vector(2 * t, 2 * (r + t), 2 * (r + t))
        self._touch()
