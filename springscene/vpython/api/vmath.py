"""The plain names ``from vpython import *`` gives a program: math, random, clock.

Besides its classes, VPython 7.6.5 puts these in a program's namespace:

- from ``vpython/__init__.py`` ("import for backwards compatibility"), last, so
  they win over anything imported before them:
  ``from math import *`` (every public name of the running Python's ``math``:
  ``pi``, ``e``, ``tau``, ``inf``, ``nan``, ``sqrt``, ``sin`` ... ``factorial``,
  ``pow``, ``fabs``, ``degrees``, ``radians``, ``floor``, ``ceil``, ...),
  ``from numpy import arange`` and ``from random import random`` (only the
  function ``random()``: no ``randint``, ``uniform`` or ``seed``);
- from ``vpython/vpython.py``'s ``__all__``: ``clock`` (``time.perf_counter``),
  ``combin(x, y)`` (binomial coefficient, as a float) and ``sign(x)``.

``NAMES`` maps each of these names to its object (``NAMES['pi'] is math.pi``);
``from springscene.vpython.api.vmath import *`` binds the same names.

Not here, though VPython exports them too: the vector names (``vector``,
``vec``, ``mag``, ``norm`` ...: :mod:`springscene.vpython.core.vectors`), ``rate`` and
``sleep``, the canvas, object, graph and widget names, ``shapes``/``paths`` and
their helpers (``vpython/shapespaths.py``), and the version lists ``version``
and ``GSversion``.
"""

from __future__ import annotations

import math
import time
from math import *  # noqa: F401,F403  (VPython's own ``from math import *``)
from random import random

from numpy import arange

# ``from math import *`` takes every public name (math has no __all__).
MATH_NAMES: list[str] = [n for n in dir(math) if not n.startswith('_')]

#: ``time.perf_counter`` (vpython.py: "vpython provides clock in its namespace").
clock = time.perf_counter


def sign(x) -> int:
    """1 if ``x > 0``, -1 if ``x < 0``, else 0 (vpython.py, for Web VPython)."""
    if x > 0:
        return 1
    if x < 0:
        return -1
    return 0


def combin(x, y) -> float:
    """The number of ways to choose ``y`` of ``x``, ``x! / (y! (x-y)!)``, as a float.

    VPython's own algorithm, so round-off matches; a ``ValueError`` if ``x`` is
    not a whole number.
    """
    z = x - y
    num = 1.0
    if y > z:
        y, z = z, y
    nn = z + 1
    ny = 1
    while nn <= x:
        num = num * nn / ny
        nn += 1
        ny += 1
    if nn != x + 1:
        raise ValueError('Illegal arguments (%d, %d) for combin function' % (x, y))
    return num


__all__ = MATH_NAMES + ['arange', 'random', 'clock', 'combin', 'sign']

NAMES: dict[str, object] = {name: globals()[name] for name in __all__}
