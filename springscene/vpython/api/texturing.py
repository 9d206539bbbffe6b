"""VPython's ``textures`` and ``bumpmaps``, and what a ``texture=`` value means here.

The names are VPython 7's (``vpython/vpython.py`` ``class textures``, ``class
bumpmaps``; GlowScript ``lib/glow/primitives.js`` ``var textures``): each is
the string VPython uses, ``textures.wood == ":wood_texture.jpg"``, so a program
that compares, stores or prints them sees what it would in VPython.

A ``texture`` is, as in primitives.js (``texture: set``):

- a string: a built-in (``textures.earth``), one of GlowScript's own texture
  URLs (``https://s3.amazonaws.com/glowscript/textures/flower_texture.jpg``,
  drawn with the built-in of that name: there is no network here), a local
  image file (relative to the current directory, or the running program's
  folder), or any other URL, which is drawn untextured with one note naming it;
- a dict ``{'file': ..., 'bumpmap': ..., 'place': ..., 'flipx': ..., 'flipy':
  ..., 'turn': ...}``: ``place`` is 'left', 'right', 'sides', 'ends', 'all' or
  a list of them (default all), ``turn`` quarter turns (rounded, modulo 4).

:func:`spec_of` turns the value into a hashable :class:`TextureSpec` (the
renderer batches objects by it); :func:`image_of` gives its picture. Bump maps
(``{'file': ..., 'bumpmap': bumpmaps.stones}``) perturb the lit normals as
GlowScript's fragment shaders do (:mod:`..draw.texture_shading`).
"""

from __future__ import annotations

import functools
import os
import re
import sys
from pathlib import Path

import numpy as np

from ..geometry.textured import TextureSpec, transform_uv
from . import texture_images
from ..core import widgets

# GlowScript's places to find its own texture files (primitives.js setup_texture)
GLOWSCRIPT_PREFIXES = (":", "https://s3.amazonaws.com/glowscript/textures/",
                       "http://s3.amazonaws.com/glowscript/textures/",
                       "/nbextensions/vpython_data/")
_BUILTIN_FILE = re.compile(r"^([a-z_]+)_texture\.jpg$")
_BUMP_FILE = re.compile(r"^([a-z_]+)_bumpmap\.jpg$")


class textures:
    """VPython's built-in textures (``texture=textures.wood``)."""

    flower = ":flower_texture.jpg"
    granite = ":granite_texture.jpg"
    gravel = ":gravel_texture.jpg"
    earth = ":earth_texture.jpg"
    metal = ":metal_texture.jpg"
    rock = ":rock_texture.jpg"
    rough = ":rough_texture.jpg"
    rug = ":rug_texture.jpg"
    stones = ":stones_texture.jpg"
    stucco = ":stucco_texture.jpg"
    wood = ":wood_texture.jpg"
    wood_old = ":wood_old_texture.jpg"


class bumpmaps:
    """VPython's built-in bump maps (``texture={'file': ..., 'bumpmap': bumpmaps.rock}``)."""

    gravel = ":gravel_bumpmap.jpg"
    rock = ":rock_bumpmap.jpg"
    stones = ":stones_bumpmap.jpg"
    stucco = ":stucco_bumpmap.jpg"
    wood_old = ":wood_old_bumpmap.jpg"


def builtin_name(name: str) -> str | None:
    """The built-in texture a GlowScript texture name or URL stands for, else None."""
    for prefix in GLOWSCRIPT_PREFIXES:
        if name.startswith(prefix):
            m = _BUILTIN_FILE.match(name[len(prefix):])
            if m and m.group(1) in texture_images.NAMES:
                return m.group(1)
    return None


def _note(message: str) -> None:
    """One note for the run (the renderer asks again each frame)."""
    if message not in widgets.notes():
        widgets.skipped(message)


def _program_folder() -> str:
    """The running program's folder (its run sets ``sys.argv[0]`` to the program: :mod:`..run.session`)."""
    return _folder_of(sys.argv[0] if sys.argv else "")


@functools.lru_cache(maxsize=16)
def _folder_of(arg: str) -> str:
    return str(Path(arg).resolve().parent) if arg.endswith(".py") else ""


def _source(name: str) -> tuple[str | None, str]:
    """(``builtin:<name>`` or an image file's absolute path, or None; why not)."""
    return _resolve(name, os.getcwd(), _program_folder())


@functools.lru_cache(maxsize=256)
def _resolve(name: str, cwd: str, folder: str) -> tuple[str | None, str]:
    if name.startswith(texture_images.ARRAY_PREFIX):
        if texture_images.is_kept(name):
            return name, ""
        return None, f"texture {name!r}: no such picture made in this run; drawn without it"
    builtin = builtin_name(name)
    if builtin is not None:
        return "builtin:" + builtin, ""
    if re.match(r"^[a-z][a-z0-9+.-]*://", name, flags=re.I) or name.startswith("data:"):
        return None, f"texture {name!r}: not fetched (no network here); drawn without it"
    if any(name.startswith(p) for p in GLOWSCRIPT_PREFIXES) and _BUMP_FILE.match(
            name.rsplit("/", 1)[-1].lstrip(":")):
        return None, f"texture {name!r} is a bump map; drawn without it"
    path = Path(name)
    candidates = [path if path.is_absolute() else Path(cwd) / path]
    if folder and not path.is_absolute():
        candidates.append(Path(folder) / path)
    for candidate in candidates:
        if candidate.is_file():
            return str(candidate.resolve()), ""
    return None, f"texture {name!r}: no such image file; drawn without it"


def bump_name(name: str) -> str | None:
    """The built-in bump map a GlowScript bump-map name or URL stands for, else None."""
    for prefix in GLOWSCRIPT_PREFIXES:
        if name.startswith(prefix):
            m = _BUMP_FILE.match(name[len(prefix):])
            if m and m.group(1) in texture_images.BUMP_NAMES:
                return m.group(1)
    return None


def _bump_source(value) -> str:
    """A ``bumpmap``'s source (``builtin:<name>`` or a file), "" (with a note) if none."""
    if value is None:
        return ""
    if not isinstance(value, str):
        _note(f"bumpmap {value!r}: not a file name; drawn without bumps")
        return ""
    builtin = bump_name(value)
    if builtin is not None:
        return "builtin:" + builtin
    source, why = _source(value)
    if source is None or source.startswith("builtin:"):
        _note(why.replace("texture", "bumpmap", 1) if why else
              f"bumpmap {value!r} is a texture, not a bump map; drawn without bumps")
        return ""
    return source


def _source_or_note(name: str) -> str | None:
    source, why = _source(name)
    if source is None:
        _note(why)
    return source


def _places(place) -> tuple[bool, bool, bool]:
    """(left, right, sides) from VPython's ``place`` (primitives.js ``texture: set``)."""
    if place is None:
        return True, True, True
    if isinstance(place, str):
        place = [place]
    left = right = sides = False
    for p in place:
        if p == "left":
            left = True
        elif p == "right":
            right = True
        elif p == "sides":
            sides = True
        elif p == "ends":
            left = right = True
        elif p == "all":
            left = right = sides = True
    return left, right, sides


def _from_dict(value: dict) -> TextureSpec | None:
    file = value.get("file")
    if not isinstance(file, str):
        _note("texture: a texture dict needs a 'file' (a name or path); drawn without it")
        return None
    source = _source_or_note(file)
    if source is None:
        return None
    left, right, sides = _places(value.get("place"))
    turns = int(round(float(value.get("turn", 0) or 0))) % 4
    return TextureSpec(source, left, right, sides, bool(value.get("flipx", False)),
                       bool(value.get("flipy", False)), turns,
                       _bump_source(value.get("bumpmap")))


def spec_of(value) -> TextureSpec | None:
    """The texture a ``texture=`` value asks for, or None to draw without one.

    Never raises: a value that cannot be drawn is noted once and ignored.
    """
    if value is None:
        return None
    if isinstance(value, str):
        source = _source_or_note(value)
        return TextureSpec(source) if source is not None else None
    if isinstance(value, dict):
        return _from_dict(value)
    _note(f"texture {value!r}: not a file name or a dict; drawn without it")
    return None


def image_of(source: str) -> np.ndarray:
    """The picture of a :class:`TextureSpec` source: ``(h, w, 3)`` uint8, top row first."""
    if source.startswith("builtin:"):
        return texture_images.builtin_image(source[len("builtin:"):])
    if source.startswith(texture_images.ARRAY_PREFIX):
        return texture_images.kept_picture(source)
    return _read(source, os.stat(source).st_mtime_ns)


@functools.lru_cache(maxsize=64)
def _read(source: str, mtime: int) -> np.ndarray:
    """An image file as RGB uint8 (read again when the file changes)."""
    import imageio.v3 as iio  # noqa: PLC0415  heavy: imageio

    image = np.asarray(iio.imread(source))
    if image.ndim == 3 and image.shape[0] in (1, 3, 4) and image.shape[-1] not in (3, 4):
        image = image[0]                           # first frame of an animation
    if image.ndim == 2:
        image = np.repeat(image[..., None], 3, axis=2)
    if image.dtype != np.uint8:
        image = np.clip(image.astype(float) / max(float(image.max()), 1.0) * 255, 0, 255)
        image = image.astype(np.uint8)
    image = np.ascontiguousarray(image[..., :3])
    image.setflags(write=False)
    return image


def bump_of(spec: TextureSpec) -> np.ndarray | None:
    """The bump map of ``spec`` (RGB uint8, a normal map), or None (none, or unreadable)."""
    if not spec.bump:
        return None
    try:
        if spec.bump.startswith("builtin:"):
            return texture_images.bump_image(spec.bump[len("builtin:"):])
        return _read(spec.bump, os.stat(spec.bump).st_mtime_ns)
    except (OSError, ValueError, RuntimeError) as exc:
        _note(f"bumpmap {os.path.basename(spec.bump)!r} could not be read ({exc}); "
              "drawn without bumps")
        return None


def load(spec: TextureSpec) -> np.ndarray | None:
    """The picture for ``spec``; None (with a note) when the file cannot be read."""
    try:
        return image_of(spec.source)
    except (OSError, ValueError, RuntimeError) as exc:
        _note(f"texture {os.path.basename(spec.source)!r} could not be read ({exc}); "
              "drawn without it")
        return None


def reset() -> None:
    """Forget resolved names (a new program may have its own files) and the pictures a
    program made."""
    _resolve.cache_clear()
    _read.cache_clear()
    texture_images.forget_pictures()


__all__ = ["textures", "bumpmaps", "TextureSpec", "spec_of", "image_of", "load", "bump_of",
           "transform_uv", "builtin_name", "reset"]
