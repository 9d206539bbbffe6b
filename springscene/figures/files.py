"""Writing figures: the output folder, PNG and SVG without dates, palette PNGs, text.

Every file is written atomically (:func:`springscene.outputs.atomic_path`), so a run
that fails leaves no half-written figure; the same figure gives the same bytes.
"""

from __future__ import annotations

import os
from pathlib import Path

import numpy as np

from ..errors import UserError
from ..outputs import atomic_path
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
            with atomic_path(path) as tmp:
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
        raise UserError(f"--out {out}: cannot create the folder ({exc.strerror})") from None
    if not os.access(out, os.W_OK | os.X_OK):
        raise UserError(f"--out {out}: folder is not writable")
    return out


def save_png(fig, path: Path, colors: int = PNG_COLORS) -> Path:
    """Write the figure as a palette PNG of ``colors`` colours (a few tens of kB), atomically,
    without dates: the same figure gives the same bytes."""
    from PIL import Image  # noqa: PLC0415  heavy: Pillow, only when writing a palette PNG

    image = Image.fromarray(figure_image(fig)).quantize(colors, method=Image.Quantize.FASTOCTREE,
                                                         dither=Image.Dither.NONE)
    palette = np.array(image.getpalette()[:3 * colors], dtype=np.int16).reshape(-1, 3)
    palette[(palette >= 246).all(axis=1)] = 255       # the quantizer greys the white a little
    image.putpalette(palette.astype(np.uint8).ravel().tolist())
    with atomic_path(path) as tmp:
        image.save(tmp, format="PNG", optimize=True)
    return path


def write_text(path: Path, text: str) -> Path:
    """Write ``text`` (UTF-8) to ``path`` atomically."""
    with atomic_path(path) as tmp:
        tmp.write_text(text, encoding="utf-8")
    return path
