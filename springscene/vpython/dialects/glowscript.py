"""The names a Web VPython (GlowScript) page gives a program that imports nothing.

GlowScript compiles the program to JavaScript with RapydScript and runs it with
VPython's library in scope (``lib/glow/api_misc.js``, ``lib/compiling/GScompiler.js``).
So a program uses, without importing: VPython's names (as ``from vpython import *``),
the math functions, ``random()``, ``arange``, ``clock``/``msclock``, the old names
``display``, ``gdisplay``, ``vp_graph``, and JavaScript's own (``Math.PI``,
``alert``, ``console.log``). Where JavaScript is more lenient than CPython and
programs rely on it, the names here are too:

- ``range(N/2)``, ``range(0, T, dt)``: RapydScript's range takes floats
  (``runtime.js``: ``ceil((stop - start) / step)`` values from ``start``);
- ``rate(0.5)``: a rate below 1 is a slow loop, not an error;
- ``sqrt(-1e-17)``, ``acos(1.0000000000000002)``, ``log(0)``: JavaScript's ``Math``
  gives NaN or -Infinity where Python's ``math`` raises;
- ``factorial(5.0)``: whole-number floats are accepted.

Older GlowScript gave a little more (``package/compiler.1.1.min.js``, ``glow.1.1.min.js``
in vpython/glowscript): ``version`` is the header's, ``sleep(t, wait)`` and
``rate(n, wait)`` take GlowScript 1's ``wait``, and before RapydScript-NG (GlowScript
2.3) JavaScript's ``true`` and ``false`` passed through. A VPython 7 program converted
from GlowScript (its header left as a comment) gets, from :func:`converted_names`,
the names of these it uses and never defines, which VPython 7 lacks.
"""

from __future__ import annotations

import builtins
import math
import random
import re
import time
import types
from typing import Any, Callable

from ..core import runtime, widgets
from ..core.vectors import vector

_NAN = float("nan")


def gs_range(*args):
    """RapydScript's ``range``: Python's for whole numbers, else ``start + k*step`` for
    ``k < ceil((stop - start) / step)``."""
    if all(isinstance(a, int) for a in args):
        return range(*args)
    if len(args) == 1:
        start, stop, step = 0, args[0], 1
    elif len(args) == 2:
        (start, stop), step = args, 1
    elif len(args) == 3:
        start, stop, step = args
    else:
        raise TypeError(f"range expected at most 3 arguments, got {len(args)}")
    if step == 0:
        raise ValueError("range() arg 3 must not be zero")
    count = max(0, math.ceil((stop - start) / step))
    return [start + k * step for k in range(count)]


def gs_rate(n, *wait) -> None:
    """``rate(n)`` for any ``n > 0`` (GlowScript takes ``rate(0.5)``, and GlowScript 1's
    ``rate(n, wait)``)."""
    if isinstance(n, (int, float)) and 0 < n < 1:
        if runtime.current() is not None:
            runtime.current().calls += 1
        runtime.sleep(1 / n)
        return
    runtime.rate(n)


def _lenient_math(name: str, on_error: float):
    f = getattr(math, name)

    def g(*args):
        try:
            return f(*args)
        except ValueError:      # a log of 0 is -Infinity, of a negative number NaN
            return on_error if not (name.startswith("log") and args[0] < 0) else _NAN
    g.__name__ = name
    g.__doc__ = f"math.{name}, giving {on_error} where math raises (as JavaScript's Math)."
    return g


def factorial(x) -> float:
    """``factorial`` of a whole number, given as an int or a float (GlowScript's)."""
    if x != int(x) or x < 0:
        raise ValueError(f"factorial({x}): needs a whole number 0 or more")
    return math.factorial(int(x))


def msclock() -> float:
    """Milliseconds, as GlowScript's ``msclock``."""
    return 1000 * time.perf_counter()


def print_options(**options: Any) -> None:
    """GlowScript's print area options (size, place, clear, digits): nothing to do off
    a page."""


def _math_namespace() -> types.SimpleNamespace:
    """JavaScript's ``Math``, for programs by teachers who write JavaScript habits."""
    names = {n: getattr(math, n) for n in ("sqrt", "floor", "ceil", "sin", "cos", "tan",
                                            "asin", "acos", "atan", "atan2", "exp", "log",
                                            "log10", "log2")}
    return types.SimpleNamespace(PI=math.pi, E=math.e, SQRT2=math.sqrt(2), LN2=math.log(2),
                                 LN10=math.log(10), abs=abs, max=max, min=min, pow=pow,
                                 round=round, random=random.random, **names)


def series(vp: types.ModuleType, type: str = "line", **options: Any):
    """GlowScript's old ``series(type=...)``: a gcurve ("line"), gdots ("scatter"),
    gvbars ("bar") or ghbars ("hbar")."""
    kinds = {"line": vp.gcurve, "scatter": vp.gdots, "bar": vp.gvbars, "hbar": vp.ghbars}
    if type not in kinds:
        raise ValueError(f"series type must be one of {', '.join(kinds)}, not {type!r}")
    return kinds[type](**options)


def download(filename, data) -> None:
    """GlowScript's ``download``: a file to the user's Downloads folder; there is none."""
    widgets.skipped(f"download({str(filename)!r}): no browser to save it; not written")


def alert(*args) -> None:
    """JavaScript's ``alert``: no one to show it to; noted."""
    widgets.skipped(f"alert({' '.join(map(str, args))!r}): no user, printed as a note")


def gs_sleep(dt, *wait) -> None:
    """``sleep(dt)``, and GlowScript 1's ``sleep(dt, wait)``."""
    runtime.sleep(dt)


def names(vp: types.ModuleType, version: str = "3.2") -> dict[str, Any]:
    """Every name a GlowScript program of ``version`` may use without importing."""
    found = {name: getattr(vp, name) for name in vp.__all__}
    for name, on_error in (("sqrt", _NAN), ("acos", _NAN), ("asin", _NAN), ("log", -math.inf),
                           ("log10", -math.inf), ("log2", -math.inf), ("pow", _NAN)):
        found[name] = _lenient_math(name, on_error)
    found.update(range=gs_range, rate=gs_rate, factorial=factorial, msclock=msclock,
                 print_options=print_options, display=vp.canvas, gdisplay=vp.graph,
                 vp_graph=vp.graph, Math=_math_namespace(), alert=alert,
                 console=types.SimpleNamespace(log=print), version=[version, "glowscript"],
                 series=lambda **options: series(vp, **options), wait=None,
                 download=download, sleep=gs_sleep)
    for name in ("mag", "mag2", "hat"):    # vectors.js: ``A.mag``, undefined where A has none
        found[name] = _attribute_reader(name, found[name])
    if before(version, "2.3"):       # RapydScript before -NG let JavaScript's through
        found.update(true=True, false=False)
    return found


def _attribute_reader(name: str, of_vector: Callable) -> Callable:
    """GlowScript's ``mag(A)`` (and ``mag2``, ``hat``): ``A``'s attribute of that name, so
    ``mag(ball)`` of an object is JavaScript's undefined (None), not an error, as a
    program that reads it and never uses it runs in the browser."""
    def read(A):
        if isinstance(A, vector):
            return of_vector(A)
        return getattr(A, name, None)
    read.__name__ = name
    return read


def before(version: str, than: str) -> bool:
    """Whether GlowScript ``version`` ("1.1", "3.3dev") is older than ``than``."""
    def parts(text: str) -> tuple[int, ...]:
        return tuple(int(p) for p in re.findall(r"\d+", text))
    return parts(version) < parts(than)


def converted_names(vp: types.ModuleType, unbound: set[str],
                    version: str = "3.2") -> tuple[dict[str, Any], str | None]:
    """For a VPython 7 program converted from GlowScript ``version``: GlowScript's names
    among those it reads and never binds (``unbound``) that neither ``from vpython import
    *`` nor Python gives (``display``, ``gdisplay``, ...), and ``range`` taking floats
    (noted when it does); with the note naming them (None when none is given)."""
    glow = names(vp, version)
    given = {n: glow[n] for n in sorted(unbound)
             if n in glow and n not in vp.__all__ and not hasattr(builtins, n)}
    note = (f"{', '.join(given)}: GlowScript's name{'s' * (len(given) > 1)}, given to this "
            f"program converted from GlowScript {version} (VPython 7 has none)"
            if given else None)
    if "range" in unbound:
        given["range"] = _noted_range
    return given, note


def _noted_range(*args):
    """Python's ``range``, or for floats GlowScript's, with a note that it was."""
    try:
        return range(*args)           # whole numbers, numpy's too
    except TypeError:
        pass
    widgets.skipped("range() of floats: GlowScript's range, which takes them, as in the "
                    "GlowScript program this was converted from")
    return gs_range(*args)
