"""springscene's ``vpython``: VPython 7's programming interface, drawn off-screen.

``springscene vpython program.py --out video.mp4`` runs an unmodified VPython
program with this package standing in for ``vpython`` (and ``visual``). The names
are VPython's: ``vector``, ``sphere``, ``box``, ``helix``, ``scene``, ``rate``,
``graph``, ``gcurve``, ``color`` and the rest; see :data:`__all__`.

Modules: :mod:`.vector` (vectors), :mod:`.vmath` (the math names VPython
re-exports), :mod:`.objects` and :mod:`.curves` (the 3D objects as data),
:mod:`.canvas` (scene, camera, colours), :mod:`.graph` (graphs), :mod:`.widgets`
(controls, with no user), :mod:`.runtime` (the program clock), :mod:`.shapes`
and :mod:`.draw` (meshes and off-screen drawing), :mod:`.runner` (a program to a
video) and :mod:`.page` (the page VPython would show).
"""

from __future__ import annotations

from . import vmath
from .canvas import canvas, color
from .curves import curve, points
from .graph import gcurve, gdots, ghbars, graph, gvbars
from .objects import (UnsupportedError, arrow, box, compound, cone, cylinder, distant_light,
                      ellipsoid, helix, label, local_light, pyramid, ring, simple_sphere, sphere)
from .runtime import rate, sleep
from .vector import (adjust_axis, adjust_up, comp, cross, diff_angle, dot, hat, mag, mag2,
                     norm, object_rotate, proj, rotate, vec, vector)
from .widgets import button, checkbox, menu, radio, slider, winput, wtext

globals().update(vmath.NAMES)

version = ("7.6.5", "springscene")
textures = None        # replaced below: using one is an UnsupportedError


class _Refused:
    """A VPython name springscene has on purpose but does not do (textures, bump maps)."""

    def __init__(self, name: str) -> None:
        self._name = name

    def __getattr__(self, attr: str):
        raise UnsupportedError(f"{self._name}.{attr} is not supported by springscene's vpython "
                               "(no textures off-screen)")


textures = _Refused("textures")
bumpmaps = _Refused("bumpmaps")
paths = _Refused("paths")


def _refuse(name: str):
    def refused(*args, **kwargs):
        raise UnsupportedError(f"{name} is not supported by springscene's vpython")
    refused.__name__ = name
    return refused


# VPython 7 objects springscene does not draw: named, so a program fails saying which
REFUSED = ("triangle", "quad", "vertex", "extrusion", "text", "attach_arrow", "attach_trail")
for _name in REFUSED:
    globals()[_name] = _refuse(_name)
scene: canvas        # set by reset()


def keysdown() -> list:
    """No keyboard here: nothing is ever down."""
    return []


def get_library(*args, **kwargs) -> None:
    raise UnsupportedError("get_library is not supported by springscene's vpython")


def reset() -> None:
    """Forget every canvas, graph and control, and make a fresh default ``scene``."""
    from .graph import reset as reset_graphs
    from .widgets import reset as reset_widgets

    global scene
    canvas._reset()
    reset_graphs()
    reset_widgets()
    scene = canvas()


_OURS = ["vector", "vec", "mag", "mag2", "norm", "hat", "dot", "cross", "proj", "comp",
         "diff_angle", "rotate", "adjust_up", "adjust_axis", "object_rotate",
         "canvas", "scene", "color", "rate", "sleep",
         "sphere", "simple_sphere", "box", "cylinder", "cone", "pyramid", "arrow", "helix",
         "ring", "ellipsoid", "curve", "points", "label", "compound", "local_light",
         "distant_light", "graph", "gcurve", "gdots", "gvbars", "ghbars",
         "button", "slider", "menu", "checkbox", "radio", "winput", "wtext",
         "textures", "bumpmaps", "paths", "keysdown", "version", "get_library", *REFUSED]
__all__ = list(dict.fromkeys(_OURS + list(vmath.__all__)))

reset()


def __getattr__(name: str):
    """A VPython name this package does not have fails with a message naming it."""
    if name.startswith("__"):
        raise AttributeError(name)
    raise UnsupportedError(f"vpython.{name} is not supported by springscene's vpython")
