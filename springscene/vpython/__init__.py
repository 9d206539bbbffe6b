"""springscene's ``vpython``: VPython 7's programming interface, drawn off-screen.

``springscene vpython program.py --out video.mp4`` runs an unmodified VPython
program with this package standing in for ``vpython`` (and ``visual``). The names
are VPython's: ``vector``, ``sphere``, ``box``, ``helix``, ``scene``, ``rate``,
``graph``, ``gcurve``, ``color`` and the rest; see :data:`__all__`.

Modules, each importing only those listed before it:

- :mod:`.vector` (vectors), :mod:`.vmath` (the math names VPython re-exports),
  :mod:`.runtime` (the program clock), :mod:`.widgets` (controls, with no user),
  :mod:`.checks` (vector arguments, unsupported features);
- :mod:`.canvas` (scene, camera, lights, colours);
- the 3D objects as data: :mod:`.base` (what all share), :mod:`.curves` (curve,
  points), :mod:`.objects` (``standardAttributes``, trails), :mod:`.solids` (sphere,
  box, ...), :mod:`.labels` (label);
- meshes and off-screen drawing: :mod:`.placement` (frames, placing copies),
  :mod:`.shape_sizes` (VPython's size rules), :mod:`.shapes` (the meshes of each
  kind), :mod:`.draw` (the renderer), then :mod:`.compounds` (compound, which
  takes its parts' meshes);
- graphs: :mod:`.graph` (the graphs and plotted points), :mod:`.graph_layout` (one
  graph on matplotlib axes), :mod:`.graph_images` (graphs as pictures);
- :mod:`.page` (the page VPython would show) and :mod:`.runner` (a program to a
  video).
"""

from __future__ import annotations

from . import vmath
from .canvas import canvas, color, distant_light, local_light
from .checks import UnsupportedError
from .compounds import compound
from .curves import curve, points
from .graph import gcurve, gdots, ghbars, graph, gvbars
from .graph import reset as _reset_graphs
from .graph_images import reset as _forget_graph_figures
from .labels import label
from .runtime import rate, sleep
from .solids import (arrow, box, cone, cylinder, ellipsoid, helix, pyramid, ring, simple_sphere,
                     sphere)
from .vector import (adjust_axis, adjust_up, comp, cross, diff_angle, dot, hat, mag, mag2,
                     norm, object_rotate, proj, rotate, vec, vector)
from .widgets import button, checkbox, menu, radio, slider, winput, wtext
from .widgets import reset as _reset_widgets

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
    global scene
    canvas._reset()
    _reset_graphs()
    _forget_graph_figures()
    _reset_widgets()
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
