"""VPython's size rules: default sizes, what ``pos`` is, and how radius and size are linked.

From ``vpython/vpython.py`` (VPython 7): default sizes (box, pyramid, ellipsoid
(1,1,1); sphere (2,2,2); cylinder, cone, helix (1,2,2); arrow (1,0.2,0.2); ring
(0.2,2.2,2.2)); ``radius = size.y/2``; ring ``thickness = size.x/2`` and
``radius = (size.y - size.x)/2``; setting ``axis`` sets ``size.x = |axis|``
except for sphere and ring; setting ``size`` rescales ``axis`` except for ring.
Each rule as a function of arrays, the reference the objects (:mod:`.objects`,
:mod:`.solids`) are tested against.
"""

from __future__ import annotations

import numpy as np

DEFAULT_SIZE = {         # vpython.py: args['_default_size'] of each class
    "box": (1.0, 1.0, 1.0),
    "pyramid": (1.0, 1.0, 1.0),
    "ellipsoid": (1.0, 1.0, 1.0),
    "sphere": (2.0, 2.0, 2.0),
    "cylinder": (1.0, 2.0, 2.0),
    "cone": (1.0, 2.0, 2.0),
    "helix": (1.0, 2.0, 2.0),
    "arrow": (1.0, 0.2, 0.2),
    "ring": (0.2, 2.2, 2.2),
}
CENTRED = frozenset({"sphere", "ellipsoid", "box", "ring"})   # pos is the centre
SIZE_INDEX = {"length": 0, "height": 1, "width": 2}           # box.length = size.x, ...
_RADIUS_ALL = frozenset({"sphere", "ellipsoid"})              # radius sets (d, d, d)
_RADIUS_YZ = frozenset({"cylinder", "cone", "helix"})         # radius sets (x, d, d)


def default_size(kind: str) -> np.ndarray:
    """VPython's default ``size`` of an object of this kind (a new array)."""
    return np.array(DEFAULT_SIZE[kind], dtype=float)


def is_centred(kind: str) -> bool:
    """True when ``pos`` is the object's centre, False when it is one end."""
    return kind in CENTRED


def axis_sets_length(kind: str) -> bool:
    """Whether setting ``axis`` sets ``size.x = |axis|`` (vpython.py: not for sphere, ring)."""
    return kind not in ("sphere", "ring")


def size_sets_axis(kind: str) -> bool:
    """Whether setting ``size`` rescales ``axis`` to ``size.x`` (vpython.py: not for ring)."""
    return kind != "ring"


def radius_from_size(kind: str, size) -> float:
    """``radius`` as VPython reads it from ``size``.

    ``size.y / 2`` for sphere, ellipsoid, cylinder, cone and helix; for a ring
    the radius of the tube's centre line, ``(size.y - size.x) / 2``.
    """
    s = np.asarray(size, dtype=float)
    if kind == "ring":
        return float((s[1] - s[0]) / 2)
    if kind in _RADIUS_ALL or kind in _RADIUS_YZ:
        return float(s[1] / 2)
    raise AttributeError(f"a {kind} has no radius")


def size_for_radius(kind: str, size, radius: float) -> np.ndarray:
    """The ``size`` after setting ``radius`` (vpython.py's radius setters)."""
    s = np.array(size, dtype=float)
    d = 2.0 * radius
    if kind in _RADIUS_ALL:
        s[:] = d
    elif kind in _RADIUS_YZ:
        s[1] = s[2] = d
    elif kind == "ring":
        s[1] = s[2] = 2.0 * (radius + s[0] / 2)
    else:
        raise AttributeError(f"a {kind} has no radius")
    return s


def ring_thickness_from_size(size) -> float:
    """A ring's ``thickness``: the *radius* of its cross section, ``size.x / 2``."""
    return float(np.asarray(size, dtype=float)[0] / 2)


def size_for_ring_thickness(size, thickness: float) -> np.ndarray:
    """A ring's ``size`` after setting ``thickness``, keeping its radius (vpython.py)."""
    s = np.array(size, dtype=float)
    radius = (s[1] - s[0]) / 2
    s[0] = 2.0 * thickness
    s[1] = s[2] = 2.0 * (radius + thickness)
    return s


def ring_size(radius: float, thickness: float) -> np.ndarray:
    """``size`` of a ring of centre-line ``radius`` and cross-section radius ``thickness``."""
    return np.array([2 * thickness, 2 * (radius + thickness), 2 * (radius + thickness)])


def helix_wire_radius(size, thickness: float = 0.0) -> float:
    """Radius of a helix's wire: ``thickness / 2``, or ``size.y / 40`` when unset (primitives.js)."""
    return thickness / 2 if thickness else float(np.asarray(size, dtype=float)[1] / 40)



__all__ = [
    "default_size", "is_centred", "axis_sets_length", "size_sets_axis", "radius_from_size",
    "size_for_radius", "ring_thickness_from_size", "size_for_ring_thickness", "ring_size",
    "helix_wire_radius", "DEFAULT_SIZE", "SIZE_INDEX",
]
