"""The last of VPython 6's ``visual``: names laid over :func:`.visual6.namespace`, and
the modules that gave all of ``visual``.

:func:`names` gives, over what ``from visual import *`` already binds:

- ``Polygon``, ``shapes`` whose figures are Polygons, ``paths`` whose figures have a
  ``pos``, and ``extrusion(pos=path, shape=...)`` (:mod:`.visual6_shapes`);
- ``materials`` that also makes a look from numbers, ``materials.texture(data=,
  mapping=, interpolate=, channels=)``, and reads and writes targa files
  (``loadTGA``, ``saveTGA``) (:class:`PictureMaterials`);
- ``scene.info()``: VPython 6's report of the renderer (a ``display`` a program makes
  itself has none: ``display`` stays VPython 7's ``canvas``);
- ``text`` whose ``frame`` is the text's own frame (VPython 6 built its 3D text in a
  frame of its own: ``t.frame.pos`` moves the text).

:func:`complete` fills ``visual.controls`` and ``visual.text`` with everything ``visual``
gives (VPython 6's ``controls.py`` and ``text.py`` began ``from visual import *``).
"""

from __future__ import annotations

import inspect
import sys
import types
from pathlib import Path
from typing import Any

import numpy as np

from ..api import texture_images
from ..core import widgets
from ...errors import UserError
from ...view.info import info as render_info
from .visual6_shapes import PathFigures, Polygon, PolygonShapes, extrusion

# -- materials.texture(data=...) -----------------------------------------------------------------

# VPython 6's mappings (vis/materials.py ``texture``) as the places GlowScript textures:
# the whole object (its colour multiplying the picture), or one face (``sign``: the +x
# face, drawn as the picture is, the rest in the object's colour)
MAPPING_PLACES = {"rectangular": "all", "spherical": "all", "cubic": "all", "cylinder": "all",
                  "hollow_box": "all", "sign": "right", "front": "right", "right": "right",
                  "back": "left", "left": "left", "top": "sides", "bottom": "sides"}
_CHANNELS = {1: ("luminance",), 2: ("luminance", "opacity"), 3: ("red", "green", "blue"),
             4: ("red", "green", "blue", "opacity")}
SHARP_SIZE = 256        # a picture drawn without interpolation is enlarged to about this


def picture(data, channels=None) -> np.ndarray:
    """VPython 6's texture data as a picture: ``(h, w, 3)`` uint8, the first row at the top.

    Numbers not already bytes are in [0, 1] (VPython 6's ``convert_data``: 255 x data);
    1 value per pixel is luminance (or opacity, with ``channels=["opacity"]``), 2
    luminance and opacity, 3 RGB, 4 RGB and opacity. Opacity is not drawn.
    """
    a = np.asarray(data)
    if a.dtype != np.uint8:
        a = np.clip(np.rint(255 * a.astype(float)), 0, 255).astype(np.uint8)
    if a.ndim == 2:
        a = a[..., None]
    if a.ndim != 3 or a.shape[2] not in _CHANNELS:
        raise ValueError(f"Must have 1, 3, or 4 values per pixel, not {a.shape[-1]}.")
    channels = tuple(channels) if channels is not None else _CHANNELS[a.shape[2]]
    if len(channels) != a.shape[2]:
        raise ValueError("Channel combination does not match number of values per pixel "
                         "in data.")
    if "opacity" in channels:
        _note("materials.texture: the opacity in the data is not drawn (textures here are "
              "opaque)")
    if "red" in channels:
        return a[..., :3]
    if channels == ("opacity",):
        return np.full(a.shape[:2] + (3,), 255, np.uint8)
    return np.repeat(a[..., :1], 3, axis=2)


def _sharp(image: np.ndarray) -> np.ndarray:
    """The picture enlarged pixel by pixel, so that the renderer's smoothing between
    texels no longer shows (VPython 6's ``interpolate=False``)."""
    k = max(1, SHARP_SIZE // max(image.shape[:2]))
    return np.repeat(np.repeat(image, k, axis=0), k, axis=1) if k > 1 else image


def _note(message: str) -> None:
    if message not in widgets.notes():
        widgets.skipped(message)


class PictureMaterial:
    """A look made from a picture (``materials.texture(data=...)``): what an object's
    ``material=`` takes (``texture_value`` is the ``texture=`` it is drawn with)."""

    emissive = False

    def __init__(self, source: str, mapping: str, name: str) -> None:
        self.name, self.mapping = name, mapping
        self.texture_value = {"file": source, "place": MAPPING_PLACES[mapping]}

    def __repr__(self) -> str:
        return f"<materials.texture {self.name!r}, mapping {self.mapping!r}>"


class raw_texture:
    """VPython 6's ``materials.raw_texture(data=, ...)``: a texture for a shader; kept, not
    drawn (springscene runs no shaders)."""

    def __init__(self, **kwargs: Any) -> None:
        self.__dict__.update(kwargs)


def _targa_path(fileid) -> Path:
    name = str(fileid) if str(fileid).endswith(".tga") else f"{fileid}.tga"
    path = Path(name)
    if not path.is_absolute() and not path.exists() and sys.argv and sys.argv[0]:
        beside = Path(sys.argv[0]).resolve().parent / path      # the program's folder
        if beside.exists():
            return beside
    return path


class PictureMaterials:
    """``materials`` as VPython 6 gave it: the named looks (those of ``materials``
    given), and ``texture``, ``raw_texture``, ``loadTGA`` and ``saveTGA``."""

    def __init__(self, named: Any) -> None:
        self._named = named

    def __getattr__(self, name: str):
        if name.startswith("__"):
            raise AttributeError(name)
        return getattr(self._named, name)

    raw_texture = raw_texture

    @staticmethod
    def texture(data=None, channels=None, mapping: str = "rectangular", mipmap: bool = True,
                interpolate: bool = True, name: str = "texture") -> PictureMaterial:
        """A look showing ``data`` (see :func:`picture`), placed as ``mapping`` places it."""
        if data is None:
            raise TypeError("materials.texture() needs data")
        if mapping not in MAPPING_PLACES:
            raise ValueError(f"Unknown mapping type: {mapping}")
        image = picture(data, channels)
        if not interpolate:
            image = _sharp(image)
        return PictureMaterial(texture_images.keep_picture(image), mapping, name)

    @staticmethod
    def loadTGA(fileid) -> np.ndarray:
        """A targa file's pixels, ``(h, w, bytes)`` uint8, the top row first (``.tga`` may
        be left off the name)."""
        from PIL import Image  # noqa: PLC0415  heavy: Pillow

        with Image.open(_targa_path(fileid) if isinstance(fileid, (str, Path)) else fileid) as im:
            a = np.asarray(im)
        return a if a.ndim == 3 else a[..., None]

    @staticmethod
    def saveTGA(fileid, data) -> None:
        """``data`` (as :meth:`texture` takes it) written as a targa file."""
        from PIL import Image  # noqa: PLC0415  heavy: Pillow

        a = np.asarray(data)
        if a.dtype != np.uint8:
            a = np.clip(np.rint(255 * a.astype(float)), 0, 255).astype(np.uint8)
        a = a[..., 0] if a.ndim == 3 and a.shape[2] == 1 else a
        name = str(fileid) if str(fileid).endswith(".tga") else f"{fileid}.tga"
        Image.fromarray(a).save(name, format="TGA")


# -- display.info() ------------------------------------------------------------------------------

def renderer_info() -> str:
    """VPython 6's ``display.info()``: the OpenGL renderer the pictures are drawn with."""
    for backend in ("auto", "egl", "osmesa"):
        try:
            found = render_info(backend)
        except (UserError, RuntimeError, OSError):
            continue
        return ("OpenGL renderer active.\n"
                f"  Vendor: {found['GL vendor']}\n"
                f"  Version: {found['GL version']}\n"
                f"  Renderer: {found['GL renderer']}\n"
                f"  Extensions: (drawn off-screen by VTK {found['vtk']}, "
                f"{found['backend']})\n")
    return "Renderer inactive.\n"


# -- the 3D text's own frame ---------------------------------------------------------------------

class TextFrame:
    """The frame VPython 6's 3D text was built in, as a program sees it: its ``pos``,
    ``axis``, ``up`` and ``visible`` are the text's, ``rotate`` turns the text, and
    ``frame`` is the frame the text is in (None: the world)."""

    def __init__(self, text: Any) -> None:
        object.__setattr__(self, "_text", text)

    _SHARED = ("pos", "axis", "up", "visible", "x", "y", "z")

    def __getattr__(self, name: str):
        if name in self._SHARED:
            return getattr(self._text, name)
        if name == "frame":
            return self._text._frame
        if name == "objects":
            return [self._text]
        raise AttributeError(f"a text's frame has no attribute {name!r}")

    def __setattr__(self, name: str, value) -> None:
        if name in self._SHARED:
            setattr(self._text, name, value)
        elif name == "frame":
            self._text.frame = value
        else:
            raise AttributeError(f"a text's frame has no attribute {name!r} to set")

    def rotate(self, angle=None, axis=None, origin=None) -> None:
        self._text.rotate(angle=angle, axis=axis, origin=origin)


def framed_text(base: type) -> type:
    """``base`` (the 3D text class) whose ``frame`` reads as its :class:`TextFrame`."""
    placed = inspect.getattr_static(base, "frame")

    def get(self) -> TextFrame:
        return TextFrame(self)

    def put(self, parent) -> None:
        placed.__set__(self, parent)
    return type("text", (base,), {"frame": property(get, put), "__doc__": base.__doc__,
                                  "__module__": __name__})


# -- the names and the modules -------------------------------------------------------------------

def names(vp: types.ModuleType, given: dict[str, Any]) -> dict[str, Any]:
    """The names laid over ``given`` (what ``from visual import *`` binds so far)."""
    scene = given.get("scene", vp.scene)
    if scene is not None:
        scene.info = renderer_info
    return {"Polygon": Polygon, "shapes": PolygonShapes(given.get("shapes", vp.shapes)),
            "paths": PathFigures(given.get("paths", vp.paths)), "extrusion": extrusion, "materials": PictureMaterials(given["materials"]),
            "text": framed_text(given.get("text", vp.text))}


def complete(found: dict[str, types.ModuleType]) -> None:
    """``visual.controls`` and ``visual.text`` given everything ``visual`` gives besides
    their own names."""
    visual = found["visual"]
    everything = {name: getattr(visual, name) for name in visual.__all__}
    for module_name in ("visual.controls", "visual.text"):
        module = found.get(module_name)
        if module is None:
            continue
        for key, value in everything.items():
            if not hasattr(module, key):
                setattr(module, key, value)
        module.__all__ = list(dict.fromkeys([*module.__all__, *everything]))


__all__ = ["names", "complete", "picture", "PictureMaterials", "PictureMaterial",
           "TextFrame", "framed_text", "renderer_info", "MAPPING_PLACES"]
