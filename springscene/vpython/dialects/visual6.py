"""VPython 6's ``visual`` package, on springscene's VPython 7 API, for Python 3 programs.

``from visual import *`` gave a program far more than ``from vpython import *``
(VPython 6.11, ``visual/__init__.py`` → ``visual_all.py``): ``from math import *``
then ``from numpy import *`` (numpy wins the shared names), seventeen scalar-fast
wrappers that take ``math`` for a Python ``float``/``int`` and numpy for anything
else (so ``sin(arange(0, 10, 0.1))`` works), ``random`` as the ``numpy.random``
module, ``true``/``false``, then the objects, ``display``, ``materials``, ``crayola``
and ``scene``. :func:`namespace` builds those names; :func:`modules` makes the
modules a program imports (``visual``, ``visual.graph``, ``visual.controls``,
``visual.factorial``, ``visual.filedialog``, ``vis``).

numpy 2 is not star-imported: it would bind ``max``/``min``/``abs``/``round``/``pow``
over the builtins (``max(a, b)`` then means an axis). The names numpy 1.x gave and
numpy 2 dropped (``float_``, ``Inf``, ``product``, ...) are put back.

``mag``, ``mag2``, ``norm`` and ``cross`` also take N x 3 numpy arrays, row by row, as
VPython 6's ``cvisual`` did (``src/python/wrap_vector.cpp``); ``dot`` is ``visual``'s,
numpy's for arrays. ``color`` is VPython 6's (tuples from its functions), ``text``,
``gcurve``/``gdots``/``gvbars``/``ghbars``, ``shapes`` and ``paths`` take VPython 6's
positional arguments (:mod:`.visual6_extras`).

Vectors: VPython 6 took tuples, lists and arrays wherever a vector goes and let a
vector act as a sequence; :func:`springscene.vpython.core.vectors.set_lenient` turns that
on for the run (the runner does it for VPython 6 programs).
"""

from __future__ import annotations

import functools
import math
import time
import types
from typing import Any

import numpy as np

from . import visual6_modules
from ..core import vectors as _vector_module
from ..core.vectors import as_vector, vector
from ..objects.frames import frame
from ..objects.array_surfaces import convex, faces
from . import visual6_extras as _extras
from .visual6_extras import (button, controls, crayola, ghistogram, materials, menu, slider,
                             toggle)

# numpy names that would shadow a builtin VPython 6 programs use as the builtin
_NOT_FROM_NUMPY = {"abs", "max", "min", "round", "pow", "bool", "divmod", "int", "float",
                   "complex", "object", "str", "random", "test", "show_config", "info",
                   "typing", "version", "exceptions",
                   # numpy 2's new aliases of math's names: VPython 6 (numpy 1) had math's
                   "acos", "asin", "atan", "atan2", "acosh", "asinh", "atanh", "concat",
                   "permute_dims", "vecdot", "bitwise_left_shift", "bitwise_right_shift",
                   "bitwise_invert"}
# names numpy 1.x's star import gave and numpy 2 removed
_NUMPY1 = {"float_": np.float64, "complex_": np.complex128, "round_": np.round,
           "product": np.prod, "cumproduct": np.cumprod, "alltrue": np.all,
           "sometrue": np.any, "Inf": np.inf, "Infinity": np.inf, "NaN": np.nan,
           "NINF": -np.inf, "PINF": np.inf, "infty": np.inf,
           "trapz": getattr(np, "trapezoid", None)}
# VPython 6's scalar-fast wrappers: math for an exact float/int, numpy otherwise
_WRAPPED = ("ceil", "cos", "cosh", "exp", "fabs", "floor", "fmod", "frexp", "ldexp", "log",
            "log10", "modf", "sin", "sinh", "sqrt", "tan", "tanh")
_MATH_TYPES = (float, int)


def _wrap(name: str):
    m, n = getattr(math, name), getattr(np, name)

    def f(x, *args):
        if type(x) in _MATH_TYPES and not args:
            return m(x)
        return n(x, *args) if not isinstance(x, vector) else n(np.array(x._xyz()), *args)
    f.__name__ = name
    f.__doc__ = f"VPython 6's {name}: math.{name} for a float or int, numpy.{name} otherwise."
    return f


def _vec(v) -> vector:
    return v if isinstance(v, vector) else as_vector(v, "vector")


def _table(A) -> np.ndarray | None:
    """An N x 3 numpy array as VPython 6's array functions took it (``wrap_vector.cpp``:
    ``mag_a``, ``norm_a``, ``cross_a_a`` ...), as floats; None for anything else (a
    vector, a tuple, one 3-array), which is one vector."""
    if not isinstance(A, np.ndarray) or A.ndim == 1 and A.shape[0] in (2, 3):
        return None
    if A.ndim != 2 or A.shape[1] != 3:
        raise ValueError("Array must be Nx3 in shape.")
    return np.asarray(A, dtype=float)


def _xyz(v) -> np.ndarray:
    return np.array(_vec(v)._xyz())


def mag(A):
    """A vector's magnitude; of an N x 3 array, each row's (an array of N)."""
    rows = _table(A)
    if rows is None:
        return _vec(A).mag
    return np.sqrt(np.einsum("ij,ij->i", rows, rows))


def mag2(A):
    """A vector's magnitude squared; of an N x 3 array, each row's."""
    rows = _table(A)
    if rows is None:
        return _vec(A).mag2
    return np.einsum("ij,ij->i", rows, rows)


def norm(A):
    """A unit vector; of an N x 3 array, each row made unit (a zero row stays zero)."""
    rows = _table(A)
    if rows is None:
        return _vec(A).norm()
    m = np.sqrt(np.einsum("ij,ij->i", rows, rows))[:, None]
    return np.divide(rows, m, out=np.zeros_like(rows), where=m > 0)


def dot(A, B):
    """``visual``'s ``dot`` (``visual_all.py``): a vector dot product for two vectors,
    numpy's ``dot`` when an array is in it (``dot(rows, v)``: each row's). Two N x 3
    arrays that numpy cannot multiply (N != 3) are dotted row by row, as VPython 6's
    own ``cvisual.dot`` did."""
    if isinstance(A, np.ndarray) or isinstance(B, np.ndarray):
        a = _xyz(A) if isinstance(A, vector) else np.asarray(A)
        b = _xyz(B) if isinstance(B, vector) else np.asarray(B)
        if a.ndim == 2 and a.shape == b.shape and a.shape[1] == 3 and a.shape[0] != 3:
            return np.einsum("ij,ij->i", a, b)
        return np.dot(a, b)
    if isinstance(A, vector) or isinstance(B, vector):
        return _vec(A).dot(_vec(B))
    return np.dot(A, B)


def cross(A, B):
    """A vector cross product; with an N x 3 array (and a vector or another N x 3 array
    of the same shape), each row's, an N x 3 array."""
    a, b = _table(A), _table(B)
    if a is None and b is None:
        return _vec(A).cross(_vec(B))
    if a is not None and b is not None and a.shape != b.shape:
        raise ValueError("Array shape mismatch.")
    return np.cross(_xyz(A) if a is None else a, _xyz(B) if b is None else b)


def proj(A, B) -> vector:
    return _vec(A).proj(_vec(B))


def comp(A, B) -> float:
    return _vec(A).comp(_vec(B))


def diff_angle(A, B) -> float:
    return _vec(A).diff_angle(_vec(B))


def rotate(A, angle: float = 0.0, axis=None) -> vector:
    return _vec(A).rotate(angle, None if axis is None else _vec(axis))


def hypot(x, y):
    if type(x) in _MATH_TYPES and type(y) in _MATH_TYPES:
        return math.hypot(x, y)
    return np.hypot(x, y)


def factorial(x) -> float:
    """``visual.factorial.factorial``: x! as a float."""
    if x != int(x) or x < 0:
        raise ValueError(f"factorial({x}): must be a whole number 0 or more")
    return float(math.factorial(int(x)))


def _numpy_names() -> dict[str, Any]:
    names = {n: getattr(np, n) for n in dir(np)
             if not n.startswith("_") and n not in _NOT_FROM_NUMPY}
    names = {n: v for n, v in names.items() if not isinstance(v, types.ModuleType)
             or n in ("linalg", "fft", "ma", "polynomial")}
    names.update({n: v for n, v in _NUMPY1.items() if v is not None})
    return names


def _numpy_or_builtin(numpy_f, builtin_f):
    """numpy's ``sum``/``any``/``all`` for an array or with an axis (``from visual import *``
    bound numpy's: ``sum(a, -1)``), Python's for anything else (a generator, a list, a
    dict's values), whose meaning numpy would change (``np.any(x > 0 for x in a)`` is
    always True)."""
    def f(a, *args, **kwargs):
        if isinstance(a, np.ndarray) or ((args or kwargs) and builtin_f is not sum):
            return numpy_f(a, *args, **kwargs)
        if builtin_f is sum and args and not isinstance(args[0], (int, np.integer)):
            return sum(a, *args)             # sum(vectors, vector(0, 0, 0))
        if args or kwargs:
            return numpy_f(a, *args, **kwargs)          # sum(a, -1): over an axis
        return builtin_f(a)
    f.__name__ = builtin_f.__name__
    return f


class _Random:
    """``random`` as ``from visual import *`` left it, ``numpy.random``
    (``random.uniform(a, b)``, ``random.randint``), that can also be called as
    ``random()``, as many VPython 6 programs (written against later VPythons) do."""

    def __call__(self) -> float:
        return float(np.random.random())

    def __getattr__(self, name: str):
        return getattr(np.random, name)


def _exit(*args) -> None:
    """``exit()``: the program ends (VPython 6 closed its window)."""
    raise SystemExit(0)


@functools.cache
def _positional_classes(vp: types.ModuleType) -> dict[str, type]:
    """VPython 7's classes that VPython 6 made with positional arguments, taking them
    (:func:`.visual6_extras.positional`), made once so that every module gives the same."""
    made = {"text": _extras.positional(vp.text, _extras.TEXT_ARGS)}
    for name, args in _extras.SERIES_ARGS.items():
        made[name] = _extras.positional(getattr(vp, name), args, drop=("shape",))
    return made


def namespace(vp: types.ModuleType) -> dict[str, Any]:
    """The names ``from visual import *`` binds, in VPython 6's order."""
    names: dict[str, Any] = {n: getattr(math, n) for n in dir(math) if not n.startswith("_")}
    names.update(_numpy_names())
    names.update({n: _wrap(n) for n in _WRAPPED})
    names.update(hypot=hypot, true=True, false=False)
    for n in vp.__all__:
        if n not in names or n in ("vector", "vec", "rate", "sleep", "color", "scene"):
            names[n] = getattr(vp, n)
    names.update(vector=vector, vec=vector, mag=mag, mag2=mag2, norm=norm, dot=dot,
                 cross=cross, proj=proj, comp=comp, diff_angle=diff_angle, rotate=rotate,
                 display=vp.canvas, crayola=crayola, color=crayola, materials=materials,
                 frame=frame, random=_Random(), exit=_exit, scene=vp.scene,
                 text=_positional_classes(vp)["text"], version=("6.11", "release"),
                 shapes=_extras.Outlines(vp.shapes, _extras.SHAPES_ARGS, _extras.SHAPE_NAMES),
                 paths=_extras.Outlines(vp.paths, _extras.PATHS_ARGS))
    names["sum"], names["any"], names["all"] = (_numpy_or_builtin(np.sum, sum),
                                                _numpy_or_builtin(np.any, any),
                                                _numpy_or_builtin(np.all, all))
    names.update(faces=faces, convex=convex)        # VPython 6's array surfaces
    names.update(math=math, numpy=np)      # visual's own imports, bound by its star import
    names.update(visual6_modules.names(vp, names))
    return names


def _module(name: str, names: dict[str, Any]) -> types.ModuleType:
    module = types.ModuleType(name, f"springscene's stand-in for VPython 6's {name}")
    for key, value in names.items():
        setattr(module, key, value)
    module.__all__ = list(names)
    return module


def _graph_names(vp: types.ModuleType) -> dict[str, Any]:
    """``from visual.graph import *``: everything ``from visual import *`` gives (VPython
    5's and 6.0's ``visual/graph.py`` began ``from .visual_all import *``), then the
    plotting names, numpy's basics, math's scalar ``log10``/``modf`` and the ``time``
    module, as ``graph.py``'s own imports bound them."""
    names = namespace(vp)
    names.update({n: getattr(vp, n) for n in ("vector", "label", "curve", "points",
                                              "distant_light")})
    names.update(display=vp.canvas, crayola=crayola, color=crayola, gdisplay=vp.graph,
                 ghistogram=ghistogram, time=time, log10=math.log10, modf=math.modf)
    names.update({n: c for n, c in _positional_classes(vp).items() if n != "text"})
    names.update({n: getattr(np, n) for n in ("array", "arange", "ndarray", "zeros", "sort",
                                              "searchsorted", "concatenate")})
    return names


def _controls_names(vp: types.ModuleType) -> dict[str, Any]:
    names = {n: getattr(vp, n) for n in ("box", "cylinder", "distant_light", "label",
                                         "sphere", "vector")}
    names.update(display=vp.canvas, crayola=crayola, color=crayola, mag=mag, norm=norm,
                 pi=math.pi, sin=math.sin, cos=math.cos, controls=controls, frame=frame,
                 button=button, toggle=toggle, slider=slider, menu=menu)
    return names


_STROKE_TEXT_ARGS = ("pos", "axis", "string", "justify", "height", "width", "depth", "color",
                     "up", "visible")


def _stroke_text(vp: types.ModuleType):
    """``visual.text``'s ``text(pos, axis, string, justify, height, width, depth, color,
    up, visible)``, drawn as VPython 7's 3D text."""
    def text(*args: Any, **options: Any):
        options = _extras._named("text", _STROKE_TEXT_ARGS, args, options)
        options.pop("width", None)
        string = options.pop("text", options.pop("string", ""))
        made = vp.text(text=str(string), align=options.pop("justify", "left"), **options)

        def reshape(**changes: Any) -> None:          # visual.text's way to change it
            for name, value in changes.items():
                setattr(made, name, value)
        made.reshape = reshape
        return made
    return text


def _filedialog_names() -> dict[str, Any]:
    def none(*args, **kwargs):
        return None
    return {"get_file": none, "save_file": none, "get_file_list": none}


def modules(vp: types.ModuleType) -> dict[str, types.ModuleType]:
    """The modules a VPython 6 program may import, by their ``sys.modules`` names."""
    visual = _module("visual", namespace(vp))
    parts = {"graph": _graph_names(vp), "controls": _controls_names(vp),
             "factorial": {"factorial": factorial, "combin": vp.combin},
             "filedialog": _filedialog_names(), "text": {"text": _stroke_text(vp)}}
    visual.__path__ = []              # a package: an unknown visual.x is "no module named"
    found = {"visual": visual}
    for part, names in parts.items():
        module = _module(f"visual.{part}", names)
        if part != "text":              # visual.text stays the 3D text class until imported
            setattr(visual, part, module)
        found[f"visual.{part}"] = module
    vis = _module("vis", {k: v for k, v in namespace(vp).items()
                          if k in vp.__all__ or k in ("display", "frame", "materials")})
    found["vis"] = vis
    visual6_modules.complete(found)
    return found


def is_lenient() -> bool:
    return _vector_module.is_lenient()


__all__ = ["namespace", "modules", "is_lenient"]
