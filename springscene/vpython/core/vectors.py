"""VPython's ``vector`` and its free functions, for headless VPython programs.

A drop-in for ``vpython.vector`` (VPython 7.6.5: ``vpython/vector.py`` and its
compiled twin ``vpython/cyvector.pyx``). Arithmetic is the same float64
operation, in the same order, as VPython's, so a physics loop written with
these vectors gives bit for bit the numbers it gives under VPython (and the
numbers of :mod:`springscene.model.physics`)::

    mag(v)  = sqrt(x**2 + y**2 + z**2)
    norm(v) = <x/m, y/m, z/m>, or <0, 0, 0> when m == 0
    a + b   = <a.x + b.x, ...>;   v * s = s * v = <x*s, y*s, z*s>

What matches VPython (checked against its sources):

- ``vector(x, y, z)`` or ``vector(v)`` (a copy); anything else is a
  ``TypeError('A vector needs 3 components.')``; ``vec`` is an alias.
- ``+``/``-`` only between vectors, ``*`` with a number on either side, ``/``
  by a number; anything else is Python's own ``TypeError`` ("unsupported
  operand type(s) ..."), as in VPython. There is no ``+=`` in place: ``a += b``
  binds a new vector to ``a``.
- ``==`` is exact; a vector never equals a non-vector; vectors are unhashable,
  not iterable, have no ``len`` and no ``abs`` (VPython defines none of them).
- ``str(v)`` is ``<x, y, z>`` and ``repr(v)`` is ``vector(x, y, z)``, each
  component formatted ``.6g``.

Additions for springscene (VPython programs cannot tell):

- ``v[i]`` and ``v[i] = value`` for i in 0..2; VPython 6's leniency
  (:func:`set_lenient`: tuples as vectors, ``len``, iteration, ``abs``) for its programs;
- ``_on_change``: called after every in-place change (setters, item assignment,
  ``rotate_in_place``), so an object learns of ``ball.pos.x = 3``; operators return
  new vectors with none (``+v`` too, which in VPython returns ``v`` itself);
- ``_xyz()``; ``_x_set``/``_y_set``/``_z_set`` (no notifying); :func:`as_vector`.

VPython's helpers that turn an object's axis and up (``adjust_up``, ``adjust_axis``,
``object_rotate``) are in :mod:`.turns`.
"""

from __future__ import annotations

import math

import numbers
from math import acos, cos, pi, sin, sqrt
from operator import index as _index
from random import random as _random

from .attributes import Linked

__all__ = ['comp', 'cross', 'diff_angle', 'dot', 'hat', 'mag', 'mag2', 'norm', 'proj',
           'rotate', 'vec', 'vector']

_Real = numbers.Real
_new = object.__new__


_lenient = False     # VPython 6's vectors, for its programs only (:func:`set_lenient`)


def set_lenient(flag: bool) -> None:
    """VPython 6's vectors: ``vector()``, ``vector(x, y)``, sequences as vectors, ``len``."""
    global _lenient
    _lenient = bool(flag)


def is_lenient() -> bool:           # while a VPython 6 program runs
    return _lenient


def _ieee_divided(v: "vector", zero: float) -> "vector":
    """``v / 0`` as VPython 6's C++ divided: each component inf (its sign times the
    zero's), or nan for a zero component; the program draws on with what it has."""
    sign = math.copysign(1.0, zero)
    return vector(*(math.copysign(math.inf, c * sign) if c else math.nan
                    for c in v._xyz()))


def _is_triple(value) -> bool:      # a 2- or 3-sequence of numbers (tuple, list, array)
    if isinstance(value, (str, bytes, vector)):
        return False
    try:
        n = len(value)
    except TypeError:
        return False
    return n in (2, 3) and all(isinstance(c, _Real) for c in value)


def _lenient_components(args: tuple) -> tuple[float, float, float]:   # (), (x, y), (seq,)
    if len(args) == 1:
        if not _is_triple(args[0]) and hasattr(args[0], "__iter__") and \
                not isinstance(args[0], (str, bytes)):
            args = (tuple(args[0]),)        # Python 2's map() was a list: vector(map(...))
        if not _is_triple(args[0]):
            raise TypeError('A vector needs 3 components.')
        args = tuple(args[0])
    values = [float(c) for c in args] + [0.0] * (3 - len(args))
    return values[0], values[1], values[2]


def _is_rows(value) -> bool:       # VPython 6: an N x 3 numpy array, a vector each row
    shape = getattr(value, "shape", None)
    return shape is not None and len(shape) == 2 and shape[1] == 3


def _scalar(other):
    """``other`` as a float if it is a real number (numpy scalars too), else None."""
    if isinstance(other, _Real) and not isinstance(other, vector):
        return float(other)
    return None


class vector:
    """A 3-vector of floats with VPython's semantics.

    Parameters
    ----------
    *args
        ``x, y, z`` (anything ``float`` accepts), or one vector to copy.
    """

    __slots__ = ('_x', '_y', '_z', '_on_change')

    __hash__ = None     # VPython's vectors are mutable and unhashable
    __array_ufunc__ = None   # numpy leaves ``np.float64(2) * v`` to the vector

    def __iter__(self):      # not iterable, as in VPython 7; a sequence in VPython 6
        if not _lenient:
            raise TypeError("'vector' object is not iterable")
        return iter((self._x, self._y, self._z))

    def __bool__(self) -> bool:         # always true, as in VPython (not "len() > 0")
        return True

    def __len__(self) -> int:
        if not _lenient:
            raise TypeError("object of type 'vector' has no len()")
        return 3

    def __abs__(self) -> float:
        if not _lenient:
            raise TypeError("bad operand type for abs(): 'vector'")
        return self.mag

    def astuple(self) -> tuple[float, float, float]:      # VPython 6's
        return (self._x, self._y, self._z)

    def __init__(self, *args) -> None:
        if len(args) == 3:
            self._x = float(args[0])
            self._y = float(args[1])
            self._z = float(args[2])
        elif len(args) == 1 and isinstance(args[0], vector):
            other = args[0]
            self._x = other._x
            self._y = other._y
            self._z = other._z
        elif _lenient and len(args) in (0, 1, 2):
            self._x, self._y, self._z = _lenient_components(args)
        else:
            raise TypeError('A vector needs 3 components.')
        self._on_change = None

    @staticmethod
    def random() -> vector:
        """A vector with each component uniform in [-1, 1] (``random.random``)."""
        return vector(-1.0 + 2.0 * _random(), -1.0 + 2.0 * _random(),
                      -1.0 + 2.0 * _random())

    # -- components -------------------------------------------------------

    x = Linked(float, notify=True)
    y = Linked(float, notify=True)
    z = Linked(float, notify=True)

    def _x_set(self, value: float) -> None:
        """Set ``x`` without calling ``_on_change``."""
        self._x = float(value)

    def _y_set(self, value: float) -> None:
        """Set ``y`` without calling ``_on_change``."""
        self._y = float(value)

    def _z_set(self, value: float) -> None:
        """Set ``z`` without calling ``_on_change``."""
        self._z = float(value)

    def _xyz(self) -> tuple[float, float, float]:
        """The components as a tuple ``(x, y, z)``."""
        return (self._x, self._y, self._z)

    @property
    def value(self) -> list[float]:
        """The components as a list ``[x, y, z]``; settable from a vector or 3 numbers."""
        return [self._x, self._y, self._z]

    @value.setter
    def value(self, other) -> None:
        other = as_vector(other, 'value')
        self._x = other._x
        self._y = other._y
        self._z = other._z
        if self._on_change is not None:
            self._on_change()

    def __getitem__(self, index: int) -> float:
        i = _index(index)
        if i < 0:
            i += 3
        if i == 0:
            return self._x
        if i == 1:
            return self._y
        if i == 2:
            return self._z
        raise IndexError('vector index out of range')

    def __setitem__(self, index: int, value) -> None:
        i = _index(index)
        if i < 0:
            i += 3
        if i == 0:
            self._x = float(value)
        elif i == 1:
            self._y = float(value)
        elif i == 2:
            self._z = float(value)
        else:
            raise IndexError('vector assignment index out of range')
        if self._on_change is not None:
            self._on_change()

    # -- text, copies -----------------------------------------------------

    def __str__(self) -> str:
        return '<{:.6g}, {:.6g}, {:.6g}>'.format(self._x, self._y, self._z)

    def __repr__(self) -> str:
        return 'vector({:.6g}, {:.6g}, {:.6g})'.format(self._x, self._y, self._z)

    def __copy__(self) -> vector:
        return vector(self)

    def __deepcopy__(self, memo) -> vector:
        return vector(self)

    def __reduce__(self):
        return (vector, (self._x, self._y, self._z))

    # -- arithmetic (hot path: no validation beyond VPython's) -------------
    def __neg__(self) -> vector:
        v = _new(vector)
        v._x = -self._x
        v._y = -self._y
        v._z = -self._z
        v._on_change = None
        return v

    def __pos__(self) -> vector:
        return vector(self)

    def __add__(self, other):
        if isinstance(other, vector):
            v = _new(vector)
            v._x = self._x + other._x
            v._y = self._y + other._y
            v._z = self._z + other._z
            v._on_change = None
            return v
        if _lenient and _is_triple(other):
            return self.__add__(vector(*_lenient_components((other,))))
        if _lenient and _is_rows(other):
            return other + (self._x, self._y, self._z)
        return NotImplemented

    def __sub__(self, other):
        if isinstance(other, vector):
            v = _new(vector)
            v._x = self._x - other._x
            v._y = self._y - other._y
            v._z = self._z - other._z
            v._on_change = None
            return v
        if _lenient and _is_triple(other):
            return self.__sub__(vector(*_lenient_components((other,))))
        if _lenient and _is_rows(other):
            return (self._x, self._y, self._z) - other
        return NotImplemented

    def __radd__(self, other):          # VPython 6: (1, 2, 3) + v
        if _lenient and _is_triple(other):
            return vector(*_lenient_components((other,))).__add__(self)
        if _lenient and _is_rows(other):
            return other + (self._x, self._y, self._z)
        return NotImplemented

    def __rsub__(self, other):
        if _lenient and _is_triple(other):
            return vector(*_lenient_components((other,))).__sub__(self)
        if _lenient and _is_rows(other):
            return other - (self._x, self._y, self._z)
        return NotImplemented

    def __mul__(self, other):
        cls = other.__class__
        if cls is not float and cls is not int:
            other = _scalar(other)
            if other is None:
                return NotImplemented
        v = _new(vector)
        v._x = self._x * other
        v._y = self._y * other
        v._z = self._z * other
        v._on_change = None
        return v

    __rmul__ = __mul__

    def __truediv__(self, other):
        cls = other.__class__
        if cls is not float and cls is not int:
            other = _scalar(other)
            if other is None:
                return NotImplemented
        v = _new(vector)
        if other == 0 and _lenient:     # VPython 6's C++ vector: IEEE's inf and nan
            return _ieee_divided(self, other)
        v._x = self._x / other
        v._y = self._y / other
        v._z = self._z / other
        v._on_change = None
        return v

    def __eq__(self, other) -> bool:
        if isinstance(other, vector):
            return self._x == other._x and self._y == other._y and self._z == other._z
        if _lenient and _is_triple(other):
            return self.__eq__(vector(*_lenient_components((other,))))
        return False

    def __ne__(self, other) -> bool:
        if isinstance(other, vector):
            return not (self._x == other._x and self._y == other._y and self._z == other._z)
        if _lenient and _is_triple(other):
            return not self.__eq__(other)
        return True

    def equals(self, other: vector) -> bool:
        """True if every component of ``other`` equals this one's exactly."""
        return self._x == other._x and self._y == other._y and self._z == other._z

    # -- magnitude and direction ------------------------------------------

    @property
    def mag(self) -> float:
        """``sqrt(x**2 + y**2 + z**2)``; setting it rescales, keeping the direction."""
        return sqrt(self._x**2 + self._y**2 + self._z**2)

    @mag.setter
    def mag(self, value) -> None:
        value = float(value)
        h = self.hat
        self._x = value * h._x
        self._y = value * h._y
        self._z = value * h._z
        if self._on_change is not None:
            self._on_change()

    @property
    def mag2(self) -> float:
        """``x**2 + y**2 + z**2``; setting it rescales, keeping the direction."""
        return self._x**2 + self._y**2 + self._z**2

    @mag2.setter
    def mag2(self, value) -> None:
        m = sqrt(value)
        h = self.hat
        self._x = m * h._x
        self._y = m * h._y
        self._z = m * h._z
        if self._on_change is not None:
            self._on_change()

    @property
    def hat(self) -> vector:
        """The unit vector ``self / mag`` (zero vector if ``mag`` is 0); setting it
        turns this vector to the new direction, keeping its magnitude."""
        m = sqrt(self._x**2 + self._y**2 + self._z**2)
        v = _new(vector)
        if m > 0.0:
            v._x = self._x / m
            v._y = self._y / m
            v._z = self._z / m
        else:
            v._x = v._y = v._z = 0.0
        v._on_change = None
        return v

    @hat.setter
    def hat(self, value) -> None:
        m = self.mag
        h = as_vector(value, 'hat').hat
        self._x = m * h._x
        self._y = m * h._y
        self._z = m * h._z
        if self._on_change is not None:
            self._on_change()

    def norm(self) -> vector:
        """The unit vector (same as ``hat``); zero vector for a zero vector."""
        return self.hat

    # -- products and angles ----------------------------------------------

    def dot(self, other: vector) -> float:
        """The scalar product."""
        return self._x * other._x + self._y * other._y + self._z * other._z

    def cross(self, other: vector) -> vector:
        """The vector product ``self x other``."""
        v = _new(vector)
        v._x = self._y * other._z - self._z * other._y
        v._y = self._z * other._x - self._x * other._z
        v._z = self._x * other._y - self._y * other._x
        v._on_change = None
        return v

    def proj(self, other: vector) -> vector:
        """The projection of this vector on the direction of ``other``."""
        u = other.hat
        return self.dot(u) * u

    def comp(self, other: vector) -> float:
        """The scalar component of this vector along ``other``."""
        return self.dot(other.hat)

    def diff_angle(self, other: vector) -> float:
        """The angle between the two vectors in [0, pi], clamped against round-off."""
        a = self.hat.dot(other.hat)
        if a > 1:
            return 0.0
        if a < -1:
            return pi
        return acos(a)

    def _rotation(self, angle, axis):
        """VPython's rotation matrix (Rodrigues) about ``axis`` (None: z), applied to self."""
        if axis is None:
            x, y, z = 0.0, 0.0, 1.0
        elif isinstance(axis, vector):
            u = axis.hat
            x, y, z = u._x, u._y, u._z
        else:
            raise TypeError('the rotation axis must be a vector')
        c = cos(angle)
        s = sin(angle)
        t = 1.0 - c
        sx, sy, sz = self._x, self._y, self._z
        return ((t*x*x + c)*sx + (t*x*y - z*s)*sy + (t*x*z + y*s)*sz,
                (t*x*y + z*s)*sx + (t*y*y + c)*sy + (t*y*z - x*s)*sz,
                (t*x*z - y*s)*sx + (t*y*z + x*s)*sy + (t*z*z + c)*sz)

    def rotate(self, angle: float = 0.0, axis: vector | None = None) -> vector:
        """This vector turned by ``angle`` (rad) about ``axis`` (default z), right-handed."""
        return vector(*self._rotation(angle, axis))

    def rotate_in_place(self, angle: float = 0.0, axis: vector | None = None) -> None:
        """Turn this vector by ``angle`` about ``axis`` (default z)."""
        self._x, self._y, self._z = self._rotation(angle, axis)
        if self._on_change is not None:
            self._on_change()


vec = vector


def as_vector(value, name: str) -> vector:
    """``value`` as a vector: a vector itself, or a new one from 3 real numbers.

    Raises ``TypeError("<name> must be a vector")`` for anything else.
    """
    if isinstance(value, vector):
        return value
    if not isinstance(value, (str, bytes)):
        try:
            n = len(value)
        except TypeError:
            n = -1
        if n == 3:
            x, y, z = value[0], value[1], value[2]
            if isinstance(x, _Real) and isinstance(y, _Real) and isinstance(z, _Real):
                return vector(x, y, z)
        if _lenient and _is_triple(value):
            return vector(*_lenient_components((value,)))
    raise TypeError(f'{name} must be a vector')


# -- VPython's free functions ---------------------------------------------

def mag(A: vector) -> float:
    """``A.mag``."""
    return A.mag


def mag2(A: vector) -> float:
    """``A.mag2``."""
    return A.mag2


def norm(A: vector) -> vector:
    """``A.hat``: the unit vector, or the zero vector."""
    return A.hat


def hat(A: vector) -> vector:
    """``A.hat``."""
    return A.hat


def dot(A: vector, B: vector) -> float:
    """``A.dot(B)``."""
    return A.dot(B)


def cross(A: vector, B: vector) -> vector:
    """``A.cross(B)``."""
    return A.cross(B)


def proj(A: vector, B: vector) -> vector:
    """``A.proj(B)``."""
    return A.proj(B)


def comp(A: vector, B: vector) -> float:
    """``A.comp(B)``."""
    return A.comp(B)


def diff_angle(A: vector, B: vector) -> float:
    """``A.diff_angle(B)``."""
    return A.diff_angle(B)


def rotate(A: vector, angle: float = 0.0, axis: vector | None = None) -> vector:
    """``A.rotate(angle, axis)``."""
    return A.rotate(angle, axis)
