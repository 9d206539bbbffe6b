"""What ``from vpython import *`` gives a program: VPython 7's names, drawn off-screen.

``springscene vpython program.py`` runs a program with this module as ``vpython``. The
names are VPython's: ``vector``, ``sphere``, ``box``, ``helix``, ``scene``, ``rate``,
``graph``, ``gcurve``, ``color`` and the rest (:data:`__all__`); one VPython has and this
module has not fails with :class:`..core.checks.UnsupportedError` naming it. :func:`reset`
forgets every canvas, graph and control and makes a fresh default ``scene``.

The objects are plain Python data; drawing them is :mod:`springscene.vpython.draw`'s job.
"""

from __future__ import annotations

from types import SimpleNamespace as _SimpleNamespace

from . import attachments, vmath
from .attachments import attach_arrow, attach_trail
from ..core.canvases import canvas, color, distant_light, local_light
from ..core.checks import UnsupportedError
from ..objects.compounds import compound
from ..objects.curves import curve, points
from ..objects.extrusions import extrusion
from .graphs import gcurve, gdots, ghbars, graph, gvbars
from .graphs import reset as _reset_graphs
from ..objects.labels import label
from ..objects.polygons import quad, triangle, vertex
from ..core.runtime import rate, sleep
from ..objects.outlines import paths, shapes
from ..objects.solids import (arrow, box, cone, cylinder, ellipsoid, helix, pyramid, ring,
                              simple_sphere, sphere)
from ..objects.text3d import text
from .texturing import bumpmaps, textures
from .texturing import reset as _reset_textures
from ..core.vectors import (comp, cross, diff_angle, dot, hat, mag, mag2, norm, proj, rotate, vec,
                            vector)
from ..core.turns import adjust_axis, adjust_up, object_rotate
from ..core.widgets import button, checkbox, menu, radio, slider, winput, wtext
from ..core.widgets import reset as _reset_widgets
from ..core.widgets import skipped as _skipped

globals().update(vmath.NAMES)

version = ("7.6.5", "springscene")


scene: canvas        # set by reset()
GSversion = ["3.2", "glowscript"]


def keysdown() -> list:
    """No keyboard here: nothing is ever down."""
    return []


def get_library(url, *args, **kwargs) -> None:
    """A JavaScript library from the web: nothing to load it into here; noted."""
    _skipped(f"get_library({url!r}): a JavaScript library; not loaded (no browser)")


def read_local_file(*args, **kwargs) -> _SimpleNamespace:
    """A file the user picks (GlowScript gives its name, text, size, type and date): no
    user here, so no file; an empty one is read (noted)."""
    _skipped("read_local_file(): no user to pick a file; read an empty file")
    return _SimpleNamespace(name="", text="", size=0, type="", date="")


def set_browser(*args, **kwargs) -> None:
    """Where VPython shows its page: springscene writes the page beside the video."""


def attach_light(obj, offset=None, **options):
    """A local light that follows ``obj`` (at ``obj.pos + offset``) at each render."""
    return attachments.attach_light(obj, local_light, offset, options.pop("color", None),
                                    **options)


def reset() -> None:
    """Forget every canvas, graph and control, and make a fresh default ``scene``."""
    global scene
    canvas._reset()
    _reset_graphs()
    _reset_widgets()
    attachments.reset()
    _reset_textures()
    scene = canvas()


_OURS = ["vector", "vec", "mag", "mag2", "norm", "hat", "dot", "cross", "proj", "comp",
         "diff_angle", "rotate", "adjust_up", "adjust_axis", "object_rotate",
         "canvas", "scene", "color", "rate", "sleep",
         "sphere", "simple_sphere", "box", "cylinder", "cone", "pyramid", "arrow", "helix",
         "ring", "ellipsoid", "curve", "points", "label", "compound", "local_light",
         "distant_light", "graph", "gcurve", "gdots", "gvbars", "ghbars",
         "button", "slider", "menu", "checkbox", "radio", "winput", "wtext",
         "vertex", "triangle", "quad", "textures", "bumpmaps", "paths", "shapes",
         "extrusion", "text", "keysdown", "attach_arrow", "attach_trail", "attach_light",
         "version", "GSversion", "get_library", "read_local_file", "set_browser"]
__all__ = list(dict.fromkeys(_OURS + list(vmath.__all__)))

reset()


def __getattr__(name: str):
    """A VPython name this package does not have fails with a message naming it."""
    if name.startswith("__"):
        raise AttributeError(name)
    raise UnsupportedError(f"vpython.{name} is not supported by springscene's vpython")
