"""Image regression: two pictures compared within a stated tolerance, and a diff image.

The measure is the share of pixels that differ by more than :data:`PIXEL_TOLERANCE`
levels (of 255) in any channel: two pictures are alike when that share is at most the
tolerance (:data:`TOLERANCE`, 0.05 % of the pixels by default) and, as a guard against a
change spread thinly over the whole picture (a colour shifted by a few levels
everywhere), their mean absolute difference is at most :data:`MAX_MEAN_DIFF` levels.
The per-pixel allowance absorbs the rasteriser's anti-aliasing noise between Mesa's
EGL and OSMesa drivers; a ball moved by one pixel or a changed colour fails. Pictures
of different sizes are never alike.

The diff image (:func:`diff_image`) is the reference dimmed to a pale grey, with the
pixels off by more than the allowance in red and those off by less in pale orange.

Used by ``springscene compare A.png B.png`` and by the pytest plugin
(:mod:`springscene.pytest_plugin`, the ``verify_image`` fixture).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

import numpy as np

from ..errors import UserError
from ..outputs import check_output, write_png

PIXEL_TOLERANCE = 24        # levels of 255 a channel may differ without the pixel counting
TOLERANCE = 0.0005          # the share of pixels allowed to count as different
MAX_MEAN_DIFF = 0.2         # levels of 255: the mean absolute difference allowed

DIFF_RED = (220, 0, 0)
DIFF_FAINT = (255, 190, 140)


@dataclass(frozen=True)
class Comparison:
    """What :func:`compare` measured, and the limits it was measured against."""

    size: tuple[int, int]            # (width, height) of the first picture
    other_size: tuple[int, int]      # of the second
    bad_fraction: float              # share of pixels off by more than pixel_tolerance
    mean_difference: float           # mean absolute difference, levels of 255
    tolerance: float = TOLERANCE
    pixel_tolerance: int = PIXEL_TOLERANCE
    max_mean: float = MAX_MEAN_DIFF

    @property
    def same_size(self) -> bool:
        return self.size == self.other_size

    @property
    def alike(self) -> bool:
        return (self.same_size and self.bad_fraction <= self.tolerance
                and self.mean_difference <= self.max_mean)

    def summary(self) -> str:
        """The measure, its value and the tolerance, on one line."""
        if not self.same_size:
            return ("sizes differ: {}x{} against {}x{}".format(*self.size, *self.other_size))
        return (f"{self.bad_fraction:.4%} of pixels off by more than {self.pixel_tolerance}/255 "
                f"in a channel (tolerance {self.tolerance:.4%}), mean difference "
                f"{self.mean_difference:.3f}/255 (tolerance {self.max_mean:g})")


def _size(image: np.ndarray) -> tuple[int, int]:
    return int(image.shape[1]), int(image.shape[0])


def _channels(a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Both as (h, w, c) with the same channels: RGB, or RGBA when either has alpha."""
    def expand(x: np.ndarray, c: int) -> np.ndarray:
        if x.ndim == 2:
            x = np.repeat(x[..., None], 3, axis=2)
        if x.shape[2] < c:
            x = np.concatenate([x, np.full(x.shape[:2] + (c - x.shape[2],), 255, x.dtype)], 2)
        return x[..., :c]
    c = 4 if any(x.ndim == 3 and x.shape[2] == 4 for x in (a, b)) else 3
    return expand(a, c), expand(b, c)


def compare(image: np.ndarray, reference: np.ndarray, *, tolerance: float = TOLERANCE,
            pixel_tolerance: int = PIXEL_TOLERANCE,
            max_mean: float = MAX_MEAN_DIFF) -> Comparison:
    """Compare two uint8 pictures ((h, w), (h, w, 3) or (h, w, 4)).

    Examples
    --------
    >>> import numpy as np
    >>> a = np.zeros((10, 10, 3), np.uint8)
    >>> compare(a, a).alike
    True
    >>> b = a.copy(); b[0, 0] = 255
    >>> c = compare(b, a); c.alike, c.bad_fraction
    (False, 0.01)
    """
    if not (0 <= tolerance <= 1):
        raise UserError(f"--tolerance {tolerance:g}: a share of the pixels, from 0 to 1")
    limits = dict(tolerance=tolerance, pixel_tolerance=pixel_tolerance, max_mean=max_mean)
    if _size(image) != _size(reference):
        return Comparison(_size(image), _size(reference), 1.0, float("inf"), **limits)
    a, b = _channels(image, reference)
    diff = np.abs(a.astype(np.int16) - b.astype(np.int16))
    return Comparison(_size(image), _size(reference),
                      float((diff.max(axis=2) > pixel_tolerance).mean()), float(diff.mean()),
                      **limits)


def diff_image(image: np.ndarray, reference: np.ndarray,
               pixel_tolerance: int = PIXEL_TOLERANCE) -> np.ndarray:
    """(h, w, 3) uint8: ``reference`` as a pale grey, pixels off by more than
    ``pixel_tolerance`` in red, those off by less (but off) in pale orange."""
    a, b = _channels(image, reference)
    off = np.abs(a.astype(np.int16) - b.astype(np.int16)).max(axis=2)
    grey = b[..., :3].astype(np.float32) @ np.array([0.299, 0.587, 0.114], np.float32)
    pale = np.rint(255 - 0.35 * (255 - grey)).astype(np.uint8)
    out = np.repeat(pale[..., None], 3, axis=2)
    out[off > 0] = DIFF_FAINT
    out[off > pixel_tolerance] = DIFF_RED
    return out


def read_image(path: str | Path, what: str = "") -> np.ndarray:
    """A picture file as a uint8 array (h, w, 3) or (h, w, 4); the first frame of an
    animation. A missing or unreadable file is bad input, named in one line."""
    from PIL import Image, UnidentifiedImageError  # noqa: PLC0415  heavy: PIL

    path = Path(path)
    where = f"{what} {path}".strip()
    if path.is_dir():
        raise UserError(f"{where}: is a folder, not a picture")
    if not path.is_file():
        raise UserError(f"{where}: no such file")
    try:
        with Image.open(path) as im:
            im.seek(0)
            if im.mode.startswith("I;16") or im.mode == "I":
                return (np.asarray(im, np.uint32) >> 8).astype(np.uint8)
            return np.asarray(im.convert("RGBA" if "A" in im.getbands() or "transparency"
                                         in im.info else "RGB"))
    except (UnidentifiedImageError, OSError, ValueError, SyntaxError,
            Image.DecompressionBombError, MemoryError) as exc:
        raise UserError(f"{where}: not a picture Pillow can read "
                        f"({type(exc).__name__}: {str(exc)[:80]})") from None


def default_diff_path(image: str | Path) -> Path:
    """``A.png`` -> ``A-diff.png`` beside it."""
    image = Path(image)
    return image.with_name(f"{image.stem}-diff.png")


def compare_files(image: str | Path, reference: str | Path, *, tolerance: float = TOLERANCE,
                  diff: str | Path | None = None) -> tuple[Comparison, Path | None]:
    """Compare two picture files; on a difference (same size) write the diff image to
    ``diff`` (default: :func:`default_diff_path` of ``image``, skipped when that folder is
    not writable) and return its path too."""
    a, b = read_image(image), read_image(reference)
    diff_path = check_output(diff, (".png",), "--diff") if diff is not None else None
    result = compare(a, b, tolerance=tolerance)
    if result.alike or not result.same_size:
        return result, None
    if diff_path is None:
        try:
            diff_path = check_output(default_diff_path(image), (".png",), "--diff")
        except UserError:
            return result, None
    write_png(diff_path, diff_image(a, b))
    return result, diff_path
