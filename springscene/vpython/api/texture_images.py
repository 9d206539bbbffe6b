"""The pictures behind VPython's built-in ``textures`` and ``bumpmaps``: VPython's own.

VPython 7.6.5 ships its texture and bump-map photographs in its wheel
(``vpython/vpython_data/<name>_texture.jpg``, ``<name>_bumpmap.jpg``, MIT
licence); springscene ships the same files, unchanged, in
``springscene/vpython/data/vpython_textures/`` (see ``data/README.md``), so a
``texture=textures.wood`` draws the picture VPython draws.

Every image is ``(height, width, 3)`` uint8 with row 0 at the top of the
picture (a grey file, ``rough_texture.jpg``, is repeated into RGB as WebGL's
``RGB`` upload does); the renderer puts the top at texture v = 1 as WebGL's
``UNPACK_FLIP_Y_WEBGL`` does (GlowScript ``WebGLRenderer.js``
``handleLoadedTexture``). ``earth`` is equirectangular, longitude -180 at the
left edge and north at the top.

A program may also make a picture from numbers (VPython 6's ``materials.texture(data=
...)``): :func:`keep_picture` keeps it for the run under a source name beginning
``array:``, which the renderer reads as it reads a file (:func:`kept_picture`).
"""

from __future__ import annotations

import functools
import hashlib
from importlib import resources

import numpy as np

FOLDER = "vpython_textures"       # in springscene/vpython/data
NAMES = ("earth", "flower", "granite", "gravel", "metal", "rock", "rough", "rug", "stones",
         "stucco", "wood", "wood_old")
BUMP_NAMES = ("gravel", "rock", "stones", "stucco", "wood_old")


def _data_image(filename: str) -> np.ndarray:
    import imageio.v3 as iio  # noqa: PLC0415  heavy: imageio

    data = resources.files("springscene.vpython").joinpath("data", FOLDER, filename).read_bytes()
    image = np.asarray(iio.imread(data, extension=".jpg"))
    if image.ndim == 2:
        image = np.repeat(image[..., None], 3, axis=2)
    image = np.ascontiguousarray(image[..., :3])
    image.setflags(write=False)
    return image


@functools.cache
def builtin_image(name: str) -> np.ndarray:
    """The picture of built-in texture ``name`` (``(h, w, 3)`` uint8, read-only), read once."""
    if name not in NAMES:
        raise KeyError(f"no built-in texture {name!r}")
    return _data_image(f"{name}_texture.jpg")


@functools.cache
def bump_image(name: str) -> np.ndarray:
    """The picture of built-in bump map ``name``: a normal map, (x, y, z) in [-1, 1] stored
    as RGB (GlowScript's fragment shaders read ``2.0*texture(bumpmap, mat_pos).xyz - 1.0``)."""
    if name not in BUMP_NAMES:
        raise KeyError(f"no built-in bump map {name!r}")
    return _data_image(f"{name}_bumpmap.jpg")


ARRAY_PREFIX = "array:"
_kept: dict[str, np.ndarray] = {}


def keep_picture(image: np.ndarray) -> str:
    """Keep a program's picture (``(h, w, 3)`` uint8, top row first) for the run; the
    source name it is drawn by (the same picture, the same name)."""
    image = np.array(image, dtype=np.uint8, order="C")      # a copy: the program's own
    digest = hashlib.sha1(image.tobytes() + str(image.shape).encode()).hexdigest()[:16]
    name = f"{ARRAY_PREFIX}{image.shape[1]}x{image.shape[0]}:{digest}"
    if name not in _kept:
        image.setflags(write=False)
        _kept[name] = image
    return name


def is_kept(source: str) -> bool:
    return source in _kept


def kept_picture(source: str) -> np.ndarray:
    """The picture kept under ``source`` by :func:`keep_picture`."""
    return _kept[source]


def forget_pictures() -> None:
    """Forget the pictures a program made (a new run starts without them)."""
    _kept.clear()


__all__ = ["builtin_image", "bump_image", "NAMES", "BUMP_NAMES", "ARRAY_PREFIX",
           "keep_picture", "is_kept", "kept_picture", "forget_pictures"]
