"""VPython 6 names VPython 7 dropped: ``materials``, ``ghistogram`` and ``controls``.

- ``materials.*`` (``visual_common/materials.py``): a look for an object
  (``material=materials.wood``). Each is drawn with the texture VPython 7 gives the
  same look (``materials.earth`` → ``textures.earth``), or as plain colour where
  VPython 7 has none; ``emissive`` and ``unshaded`` glow (VPython 7's
  ``emissive=True``).
- ``ghistogram(bins=, accumulate=, average=, delta=, gdisplay=, color=)``
  (``visual_common/graph.py``): a histogram drawn as ``gvbars``; ``plot(data=...)``
  counts the data into the bins.
- ``controls(...)``: VPython 6's separate window of widgets. With no user its
  widgets never fire; it only holds them.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from ..core import runtime, widgets
from ..api.graphs import gvbars
from ..api.texturing import textures

# material → (texture name in VPython 7, or None; drawn emissive)
MATERIALS = {"unshaded": (None, True), "emissive": (None, True), "diffuse": (None, False),
             "plastic": (None, False), "rough": ("rough", False), "shiny": (None, False),
             "chrome": ("metal", False), "ice": (None, False), "glass": (None, False),
             "blazed": (None, False), "silver": ("metal", False), "wood": ("wood", False),
             "marble": ("stucco", False), "earth": ("earth", False),
             "BlueMarble": ("earth", False), "bricks": ("stones", False)}


class Material:
    """One of VPython 6's materials: a name, the texture that shows it, and glow."""

    def __init__(self, name: str) -> None:
        self.name = name
        self.texture, self.emissive = MATERIALS[name]
        # what ``texture=`` takes for it (VPython 7's texture of that name), or None
        self.texture_value = getattr(textures, self.texture) if self.texture else None

    def __repr__(self) -> str:
        return f"materials.{self.name}"


class _Materials:
    """``materials``: VPython 6's looks, by name."""

    def __init__(self) -> None:
        for name in MATERIALS:
            setattr(self, name, Material(name))

    def __getattr__(self, name: str) -> Material:     # texture(), loadTGA, show_mat_pos ...
        if name.startswith("__"):
            raise AttributeError(name)
        return Material("diffuse")


materials = _Materials()


class ghistogram:
    """VPython 6's histogram: counts of data in ``bins``, shown as vertical bars.

    Bin ``i`` counts data with ``bins[i] <= d < bins[i+1]``; the last bin counts
    ``d >= bins[-1]``; data below ``bins[0]`` are dropped. ``accumulate`` adds each
    plot's counts to the last ones; with ``average`` the sum is divided by the plots.
    """

    def __init__(self, bins=None, accumulate: bool = False, average: bool = False,
                 delta: float | None = None, gdisplay=None, color=None, **kwargs: Any) -> None:
        self.bins = np.asarray(bins if bins is not None else np.arange(0, 10), dtype=float)
        self.delta = float(delta if delta is not None else
                           (self.bins[1] - self.bins[0] if len(self.bins) > 1 else 1.0))
        self.accumulate, self.average = bool(accumulate), bool(average)
        self._counts = np.zeros(len(self.bins))
        self._plots = 0
        args = {"delta": 0.8 * self.delta, "graph": gdisplay or kwargs.pop("graph", None)}
        if color is not None:
            args["color"] = color
        self._bars = gvbars(**args)

    def plot(self, data=None, accumulate: bool | None = None, average: bool | None = None,
             color=None) -> None:
        acc = self.accumulate if accumulate is None else bool(accumulate)
        avg = self.average if average is None else bool(average)
        data = np.ravel(np.asarray(data if data is not None else [], dtype=float))
        index = np.searchsorted(self.bins, data, side="right") - 1
        counts = np.bincount(index[index >= 0], minlength=len(self.bins))[:len(self.bins)]
        if acc:
            self._counts = self._counts + counts
            self._plots += 1
            shown = self._counts / self._plots if avg else self._counts
        else:
            self._counts, self._plots, shown = counts.astype(float), 1, counts
        centres = self.bins + 0.5 * self.delta
        self._bars.data = [[float(x), float(y)] for x, y in zip(centres, shown)]
        if color is not None:
            self._bars.color = color


class controls:
    """VPython 6's controls window: holds its widgets, which no user ever works."""

    def __init__(self, **args: Any) -> None:
        self.__dict__.update(args)
        self.display = None

    def select(self) -> None:
        pass

    def interact(self) -> None:
        """VPython 6 handled the mouse here; with no user, one video frame passes (so a
        ``while True: c.interact()`` loop ends with the video)."""
        widgets.skipped("controls.interact(): no user; each call lets one frame pass")
        runtime.wait()


def _v6_args(args: dict[str, Any]) -> dict[str, Any]:
    """VPython 6's control keywords as VPython 7's: ``action`` is the ``bind`` (called with
    no argument, never here); its place in the controls window (``pos``, ``axis``) is
    not kept."""
    action = args.pop("action", None)
    args["bind"] = action if action is not None else (lambda *a: None)
    for name in ("pos", "axis", "controls", "display"):
        args.pop(name, None)
    return args


def button(**args: Any) -> widgets.button:
    """VPython 6's ``button(pos=, width=, height=, text=, color=, action=)``."""
    return widgets.button(**_v6_args(args))


def slider(**args: Any) -> widgets.slider:
    """VPython 6's ``slider(pos=, axis=|length=, width=, min=, max=, value=, action=)``."""
    args = _v6_args(args)
    args.setdefault("min", 0)
    args.setdefault("max", 100)
    return widgets.slider(**args)


def toggle(**args: Any) -> widgets.checkbox:
    """VPython 6's ``toggle(text0=, text1=, value=, action=)``: ``value`` stays as made."""
    args = _v6_args(args)
    args.setdefault("value", 0)
    return widgets.checkbox(**args)


def menu(**args: Any) -> widgets.menu:
    """VPython 6's ``menu(text=)``, filled by ``m.items.append(("label", function))``."""
    args = _v6_args(args)
    args.setdefault("choices", [])
    m = widgets.menu(**args)
    m.items = []
    return m
