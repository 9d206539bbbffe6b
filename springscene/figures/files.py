"""Writing figures: the output folder, PNG and SVG without dates, palette PNGs, text.

Every file is written atomically (:func:`springscene.outputs.atomic_path`), so a run
that fails leaves no half-written figure; the same figure gives the same bytes.
"""

from __future__ import annotations

import contextlib
import os
import shutil
import tempfile
from pathlib import Path
from typing import Iterator

import numpy as np

from ..errors import OutputError, UserError
from ..outputs import atomic_path, check_writable_folder
from ..video import WRITE_ERRNOS, reason_of
from ..view.plotstyle import DPI, PNG_METADATA, SVG_METADATA, figure_image, style

PNG_COLORS = 128


def save_figure(fig, out_dir: Path, stem: str, formats: tuple[str, ...] = ("png", "svg")
                ) -> list[Path]:
    """Write ``stem.png`` and ``stem.svg`` atomically, without dates (same bytes every run)."""
    paths = []
    with style():
        for fmt in formats:
            path = out_dir / f"{stem}.{fmt}"
            metadata = PNG_METADATA if fmt == "png" else SVG_METADATA
            with named(path), atomic_path(path) as tmp:
                fig.savefig(tmp, format=fmt, dpi=DPI, metadata=metadata)
            paths.append(path)
    return paths


def prepare_out_dir(out: str | Path) -> Path:
    """The output folder, created if missing; bad input is a :class:`UserError` naming --out."""
    if not str(out).strip():
        raise UserError("--out is empty: give a folder for the figures")
    out = Path(out)
    if out.exists() and not out.is_dir():
        raise UserError(f"--out {out}: is a file, not a folder")
    try:
        out.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        if exc.errno in WRITE_ERRNOS:       # a read-only file system, a full disk: exit 1
            raise OutputError(reason_of(exc), out, exc.errno) from None
        raise UserError(f"--out {out}: cannot create the folder ({exc.strerror})") from None
    check_writable_folder(out, out)
    return out


STAGING_PREFIX = ".springscene-figures."   # the private folder a set is built in


@contextlib.contextmanager
def figure_set(out: str | Path) -> Iterator[Path]:
    """A private folder inside ``out`` to build a figure set in; when the block ends the new
    set replaces the old one whole (each file moved over its namesake), or, if anything
    fails or a signal stops the run, nothing in ``out`` changes.

    Files in ``out`` that are not in the new set are kept. A folder this call created is
    removed again on failure; the private folder never outlives the block. An ``OSError``
    names the file in ``out`` (never the private folder).
    """
    created = not Path(out).exists()
    target = prepare_out_dir(out)
    try:
        staging = Path(tempfile.mkdtemp(prefix=STAGING_PREFIX, dir=target))
    except OSError as exc:
        _remove_if_empty(target, created)
        raise OSError(exc.errno, exc.strerror, str(target)) from None
    names: list[str] = []
    try:
        yield staging
        names = sorted(p.name for p in staging.iterdir())
        _swap_in(staging, target, names)
    except BaseException as exc:
        if any((staging / name).exists() for name in names):   # stopped half way: undo
            _put_back(staging, target, names)
        _remove_tree(staging)
        _remove_if_empty(target, created)
        if isinstance(exc, OSError) and isinstance(exc.filename, (str, bytes, os.PathLike)):
            raise _named(exc, staging, target) from None
        raise
    _remove_tree(staging)


def _swap_in(staging: Path, target: Path, names: list[str]) -> None:
    """Move each new file over its namesake in ``target``; the old file waits in
    ``staging/.old`` until the whole set is in (:func:`_put_back` undoes a partial swap)."""
    old = staging / ".old"
    old.mkdir()
    for name in names:
        if (target / name).exists():
            os.replace(target / name, old / name)
        os.replace(staging / name, target / name)


def _put_back(staging: Path, target: Path, names: list[str]) -> None:
    """Undo :func:`_swap_in` from what the folders hold, wherever it stopped."""
    old = staging / ".old"
    for name in names:
        if (old / name).exists():
            os.replace(old / name, target / name)
        elif not (staging / name).exists():         # moved in, and no old file was there
            (target / name).unlink(missing_ok=True)


def _remove_tree(path: Path) -> None:
    try:
        shutil.rmtree(path, ignore_errors=True)
    finally:            # a stop signal cut the first removal short: the second finishes
        shutil.rmtree(path, ignore_errors=True)


def _remove_if_empty(folder: Path, created: bool) -> None:
    if created:
        with contextlib.suppress(OSError):
            folder.rmdir()


@contextlib.contextmanager
def named(path: Path) -> Iterator[None]:
    """An ``OSError`` that names no file (a write that ran out of space) names ``path``."""
    try:
        yield
    except OSError as exc:
        if exc.filename is not None:
            raise
        raise OSError(exc.errno, exc.strerror, str(path)) from exc


def _named(exc: OSError, staging: Path, target: Path) -> OSError:
    """``exc`` naming the file in ``target`` instead of its copy in ``staging``."""
    name = Path(os.fsdecode(exc.filename))
    if name.parent != staging:
        return exc
    if isinstance(exc, OutputError):
        return exc.at(target / name.name)
    return OSError(exc.errno, exc.strerror, str(target / name.name))


def save_png(fig, path: Path, colors: int = PNG_COLORS) -> Path:
    """Write the figure as a palette PNG of ``colors`` colours (a few tens of kB), atomically,
    without dates: the same figure gives the same bytes."""
    from PIL import Image  # noqa: PLC0415  heavy: Pillow, only when writing a palette PNG

    image = Image.fromarray(figure_image(fig)).quantize(colors, method=Image.Quantize.FASTOCTREE,
                                                         dither=Image.Dither.NONE)
    palette = np.array(image.getpalette()[:3 * colors], dtype=np.int16).reshape(-1, 3)
    palette[(palette >= 246).all(axis=1)] = 255       # the quantizer greys the white a little
    image.putpalette(palette.astype(np.uint8).ravel().tolist())
    with named(path), atomic_path(path) as tmp:
        image.save(tmp, format="PNG", optimize=True)
    return path


def write_text(path: Path, text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` atomically."""
    with named(path), atomic_path(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return path
