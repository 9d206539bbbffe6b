"""The fonts a browser draws VPython's labels with, their widths and their 'middle'.

GlowScript asks the canvas for ``Arial`` (font 'sans'), ``Georgia`` ('serif') or the name
given ('monospace', ...). Chromium on Linux takes what fontconfig offers only when it is a
metric-compatible alias, so (measured against VPython 7.6.5 in headless Chromium):
Arial is Liberation Sans; Georgia, which has no such alias, falls back to the browser's
standard font, Times New Roman, i.e. Liberation Serif; 'monospace' is DejaVu Sans Mono.
Liberation Sans and Serif ship in ``springscene/vpython/data`` (SIL OFL, with their
licence); DejaVu comes with matplotlib.

Widths are unhinted advances with kerning (HarfBuzz through Pillow's raqm layout when
present), as the browser's ``measureText``. ``textBaseline = 'middle'`` puts the middle of
the em box, split by the font's typographic ascender and descender, at y.
"""

from __future__ import annotations

import functools
import importlib.util
import struct
from pathlib import Path

DATA = Path(__file__).resolve().parents[1] / "data"
SYSTEM = (Path("/usr/share/fonts/truetype/liberation2"), Path("/usr/share/fonts/truetype/liberation"))
STYLES = {(False, False): "Regular", (True, False): "Bold", (False, True): "Italic",
          (True, True): "BoldItalic"}
DEJAVU_STYLES = {(False, False): "", (True, False): "-Bold", (False, True): "-Oblique",
                 (True, True): "-BoldOblique"}
SANS = ("arial", "helvetica", "liberation sans", "arimo")
MONO = ("monospace", "courier", "courier new", "liberation mono", "dejavu sans mono")
DEJAVU_SANS = ("sans-serif", "dejavu sans", "verdana")


def _mpl_fonts() -> Path | None:
    spec = importlib.util.find_spec("matplotlib")
    if spec is None or not spec.submodule_search_locations:
        return None
    return Path(list(spec.submodule_search_locations)[0]) / "mpl-data" / "fonts" / "ttf"


@functools.lru_cache(maxsize=64)
def font_file(family: str, bold: bool = False, italic: bool = False) -> str:
    """The TrueType file the browser draws CSS font ``family`` with."""
    name = family.strip().strip("'\"").lower()
    mpl = _mpl_fonts()
    if name in MONO or name in DEJAVU_SANS:
        stem = "DejaVuSansMono" if name in MONO else "DejaVuSans"
        suffix = DEJAVU_STYLES[(bold, italic)]
        if mpl is not None and (mpl / f"{stem}{suffix}.ttf").exists():
            return str(mpl / f"{stem}{suffix}.ttf")
    kind = "Sans" if name in SANS else "Serif"
    filename = f"Liberation{kind}-{STYLES[(bold, italic)]}.ttf"
    for folder in (DATA, *SYSTEM):
        if (folder / filename).exists():
            return str(folder / filename)
    fallback = "DejaVuSans" if kind == "Sans" else "DejaVuSerif"
    style = DEJAVU_STYLES[(bold, italic)]
    if kind == "Serif":
        style = style.replace("Oblique", "Italic")
    return str(mpl / f"{fallback}{style}.ttf") if mpl is not None else filename


@functools.lru_cache(maxsize=256)
def pil_font(path: str, size: float):
    """A Pillow FreeType font (raqm layout when Pillow has it: kerning as the browser)."""
    from PIL import ImageFont, features  # noqa: PLC0415  heavy: PIL

    layout = ImageFont.Layout.RAQM if features.check("raqm") else ImageFont.Layout.BASIC
    return ImageFont.truetype(path, size, layout_engine=layout)


MEASURE_SIZE = 64.0   # widths are measured at this size and scaled (linear, unhinted)


@functools.lru_cache(maxsize=4096)
def width(text: str, family: str, size: float, bold: bool = False, italic: bool = False) -> float:
    """``measureText(text).width`` for ``bold/italic size px family``."""
    if not text:
        return 0.0
    font = pil_font(font_file(family, bold, italic), MEASURE_SIZE)
    return float(font.getlength(text)) * size / MEASURE_SIZE


@functools.lru_cache(maxsize=64)
def middle(path: str) -> float:
    """From textBaseline 'middle' down to the alphabetic baseline, in font sizes:
    the middle of the em box split by the typographic ascender and descender
    (OS/2 sTypoAscender/sTypoDescender; hhea's when those are unset)."""
    data = Path(path).read_bytes()
    tables = {data[12 + 16 * k:16 + 16 * k]: struct.unpack(">I", data[20 + 16 * k:24 + 16 * k])[0]
              for k in range(struct.unpack(">H", data[4:6])[0])}
    asc = desc = 0.0
    if b"OS/2" in tables:
        asc, desc = struct.unpack(">hh", data[tables[b"OS/2"] + 68:tables[b"OS/2"] + 72])
    if asc <= 0 and b"hhea" in tables:
        asc, desc = struct.unpack(">hh", data[tables[b"hhea"] + 4:tables[b"hhea"] + 8])
    asc, desc = float(asc), abs(float(desc))
    return (asc - desc) / (2 * (asc + desc)) if asc + desc > 0 else 0.0
