"""Where VPython puts a label's box, leader line and text: pure geometry, no drawing.

These are GlowScript 3.2's rules (as bundled with vpython 7.6.5), restated:

- ``parse_html`` in ``lib/glow/api_misc.js`` splits the text into lines (``\\n``, ``<br>``)
  and styled parts (``<b>``/``<strong>``, ``<i>``/``<em>``, ``<sup>``, ``<sub>``); a part's
  width is the browser's ``measureText``.
- ``label.__update`` in ``lib/glow/primitives.js`` places the block: line pitch
  ``1.3 * height``, block height ``height + (nlines - 1) * 1.3 * height``, the first line's
  middle ``0.4 * height`` below the block's top, the box ``border`` px outside the block;
  with an ``xoffset``/``yoffset`` the box sits beyond the leader line's end
  (``pos + offset``) on the side the larger offset points to.
- ``display_2D`` in ``lib/glow/api_misc.js`` draws each part with ``fillText`` at
  ``textBaseline = 'middle'``, each line aligned by its own width.

Coordinates are canvas pixels, x to the right and y down from the top-left corner.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

PITCH = 1.3        # line spacing, in label heights (label.__update: dh = 1.3*height)
UPPER = 0.4        # from a line's middle to the block's top, in heights (upperchar)
SCRIPT_SIZE = 0.8  # <sup>/<sub> font size, in heights (parse_html: add_part)
SCRIPT_SHIFT = 0.3  # <sup>/<sub> shift up/down per part, in heights
FONT_NAMES = {"sans": "Arial", "serif": "Georgia"}   # label.__update's font mapping


@dataclass(frozen=True)
class Run:
    """One ``fillText``: ``text`` at (x, y), y the middle of the em box (textBaseline middle)."""

    x: float
    y: float
    text: str
    size: float
    bold: bool
    italic: bool


@dataclass(frozen=True)
class Geometry:
    """A label as GlowScript draws it: fill/box rectangle, leader line, text runs."""

    rect: tuple[float, float, float, float]      # x, y, width, height of the fill and box
    line: tuple[float, float, float, float] | None   # x0, y0, x1, y1 of the leader line
    runs: tuple[Run, ...]
    family: str                                  # the CSS font family fillText gets


Measure = Callable[[str, str, float, bool, bool], float]   # (text, family, size, b, i) -> px


def parse(text: str, family: str, size: float, measure: Measure):
    """``parse_html``: lines as (width, [(x, y, text, size, bold, italic), ...]) and the widest.

    Its quirks are kept: a ``<sup>``/``<sub>`` shift adds up part after part until the
    closing tag; the text after the last tag is measured and drawn in the plain font; an
    unknown tag is kept as text (``</u>`` as ``<u>``); ``<`` with no ``>`` after it is text.
    """
    if family == "Verdana":
        size *= 13 / 15
    st = {"bold": False, "italic": False, "sup": False, "sub": False, "x": 0.0, "y": 0.0,
          "part": "", "line": []}
    lines = []

    def add_part() -> None:
        fs = size
        if st["sup"] or st["sub"]:
            fs = SCRIPT_SIZE * size
            st["y"] += -SCRIPT_SHIFT * size if st["sup"] else SCRIPT_SHIFT * size
        part = st["part"]
        st["line"].append((st["x"], st["y"], part, fs, st["bold"], st["italic"]))
        st["x"] += measure(part, family, fs, st["bold"], st["italic"])
        st["part"] = ""

    def end_line() -> None:
        if st["part"]:
            add_part()
        lines.append((st["x"], st["line"]))
        st.update(line=[], x=0.0, y=0.0)

    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if c == "\n":
            end_line()
        elif c != "<" or ">" not in text[i + 1:]:
            st["part"] += c
        else:
            i = _tag(text, i, st, add_part, end_line)
        i += 1
    last = st["part"]
    if last:
        st["line"].append((st["x"], st["y"], last, size, False, False))
    lines.append((st["x"] + (measure(last, family, size, False, False) if last else 0.0),
                  st["line"]))
    return lines, max(w for w, _ in lines), size


def _tag(text: str, i: int, st: dict, add_part, end_line) -> int:
    """The tag starting at ``text[i] == '<'``: apply it; the index of its last character."""
    i += 1
    cmd, end = text[i], False
    if cmd == "/":
        cmd, end = "", True
    i += 1
    while i < len(text):
        if text[i] == "<":      # the first '<' did not open a tag
            st["part"] += "<" + cmd
            add_part()
            return i - 1
        if text[i] == ">":
            break
        cmd += text[i]
        i += 1
    if cmd in ("br", "br/"):
        end_line()
        return i
    if cmd in ("b", "strong", "i", "em", "sup", "sub") and st["part"]:
        add_part()
    if cmd in ("b", "strong"):
        st["bold"] = not end
    elif cmd in ("i", "em"):
        st["italic"] = not end
    elif cmd in ("sup", "sub"):
        st[cmd] = not end
        if end:
            st["y"] = 0.0
    else:
        st["part"] += "<" + cmd + ">"
    return i


def place(text: str, font: str, height: float, align: str, pos: tuple[float, float],
          offset: tuple[float, float], border: float, measure: Measure,
          space: float = 0.0) -> Geometry:
    """``label.__update``: the label whose ``pos`` is at canvas pixel ``pos`` (y down).

    ``offset`` is (xoffset, yoffset) with yoffset up, as the program gives it (for a
    ``pixel_pos`` label GlowScript negates yoffset first: the caller does that).
    """
    family = FONT_NAMES.get(font, font)
    align = align if align in ("left", "right") else "center"
    lines, width, fontsize = parse(text, family, height, measure)
    dh = PITCH * height
    block = height + (len(lines) - 1) * dh
    upper = UPPER * height
    posx, posy = pos
    xoff, yoff = offset
    if xoff or yoff:
        if abs(yoff) > abs(xoff):
            xbase = posx + xoff - width / 2
            ybase = posy - yoff - block - border + upper if yoff > 0 \
                else posy - yoff + border + upper
        else:
            ybase = posy - yoff - block / 2 + upper
            xbase = posx + xoff + border if xoff > 0 else posx + xoff - width - border
    else:
        ybase = posy
        xbase = posx - {"center": width / 2, "right": width, "left": 0.0}[align]
    rect = (xbase - border, ybase - upper - border, width + 2 * border, block + 2 * border)
    line = None
    if xoff or yoff:       # from pos, or ``space`` px along the line when space > 0
        start = space / math.hypot(xoff, yoff) if space > 0 else 0.0
        line = (posx + xoff * start, posy - yoff * start, posx + xoff, posy - yoff)
    x0 = xbase + {"center": width / 2, "right": width, "left": 0.0}[align]
    runs = []
    for k, (lw, parts) in enumerate(lines):
        shift = {"center": lw / 2, "right": lw, "left": 0.0}[align]
        for x, y, part, fs, bold, italic in parts:
            runs.append(Run(x0 + x - shift, ybase + k * PITCH * fontsize + y, part, fs,
                            bold, italic))
    return Geometry(rect, line, tuple(runs), family)
