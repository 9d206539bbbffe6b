"""A canvas's title and caption drawn as VPython's page draws them, for the page video.

VPython puts them in ``<div>``\\ s styled ``white-space: pre`` (vpython/glowscript,
``lib/glow/canvas.js``, ``__activate``) on a page whose font is ``Verdana, sans-serif``
at 90 % of 16 px = 14.4 px, in black on #f1f2f4 (vpython's ``ide.css``). Headless
Chromium skips Verdana (it has no metric-compatible alias here) and draws the generic
sans-serif, Liberation Sans (measured: "Spring" in bold is 46 px wide there, 45.6 in
Liberation Sans, 53.2 in DejaVu Sans). springscene draws with the Liberation Sans it
ships (:mod:`.fonts`, the labels' fonts).

This parser follows the browser's HTML (the page's divs); a label's text follows
GlowScript's own ``parse_html`` instead (:mod:`.label_layout`), so they stay two. The
HTML VPython programs put there is a small subset: ``<b>``/``<strong>``,
``<i>``/``<em>``, ``<sub>``, ``<sup>``, ``<br>`` and ``\\n`` line breaks, entities; other
tags are dropped and their text kept. Lines wrap at the page's width (a video cannot
scroll sideways as the browser does).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass
from html.parser import HTMLParser
import numpy as np

from .fonts import font_file, pil_font

__all__ = ["FONT_PX", "TEXT_COLOR", "font_path", "render_html", "parse"]

FONT_PX = 14.4                  # ide.css: body font-size 90 % of the browser's 16 px
SCRIPT_SCALE = 12.0 / 14.4      # <sub>/<sup> are font-size: smaller (measured: 12 px)
TEXT_COLOR = (0, 0, 0)
_SUP, _SUB = 0.4, 0.3           # baseline shifts of <sup> and <sub> in ems (Chromium: a 2-line
                                # title with both is 40 px high, 24 + 16)

# a line box as Chromium makes it: the font's ascent and descent, each rounded to pixels
# (OS/2 metrics over units per em: Liberation Sans 1854 and 434 of 2048; DejaVu Sans
# 1901 and 483 of 2048), so 13 + 3 = 16 px at 14.4 px, as measured in VPython's page
_METRICS = {"Liberation": (1854 / 2048, 434 / 2048), "DejaVu": (1901 / 2048, 483 / 2048)}
_BREAK_TAGS = {"br", "p", "div", "li", "tr", "h1", "h2", "h3", "h4"}


@dataclass(frozen=True)
class Run:
    """Text in one style: bold, italic, and script (1 superscript, -1 subscript)."""

    text: str
    bold: bool = False
    italic: bool = False
    script: int = 0


def font_path(bold: bool = False, italic: bool = False) -> str:
    """The TrueType file for the page's sans-serif in this style."""
    return font_file("arial", bold, italic)


def _font(bold: bool, italic: bool, px: float):
    """The labels' Pillow font (raqm kerning, as the browser lays text out)."""
    return pil_font(font_path(bold, italic), px)


class _Parser(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.lines: list[list[Run]] = [[]]
        self.bold = self.italic = 0
        self.script: list[int] = []

    def handle_starttag(self, tag: str, attrs) -> None:
        if tag in _BREAK_TAGS:
            self.lines.append([])
        self._style(tag, +1)

    def handle_startendtag(self, tag: str, attrs) -> None:
        if tag in _BREAK_TAGS:
            self.lines.append([])

    def handle_endtag(self, tag: str) -> None:
        if tag in _BREAK_TAGS - {"br"}:
            self.lines.append([])
        self._style(tag, -1)

    def _style(self, tag: str, step: int) -> None:
        if tag in ("b", "strong"):
            self.bold = max(self.bold + step, 0)
        elif tag in ("i", "em"):
            self.italic = max(self.italic + step, 0)
        elif tag in ("sub", "sup"):
            if step > 0:
                self.script.append(1 if tag == "sup" else -1)
            elif self.script:
                self.script.pop()

    def handle_data(self, data: str) -> None:
        script = self.script[-1] if self.script else 0
        for i, part in enumerate(data.split("\n")):
            if i:
                self.lines.append([])
            if part:
                self.lines[-1].append(Run(part.replace("\t", "    "), self.bold > 0,
                                          self.italic > 0, script))


def parse(markup: str) -> list[list[Run]]:
    """The lines of a title or caption, each a list of styled runs."""
    p = _Parser()
    p.feed(str(markup))
    p.close()
    lines = p.lines
    while lines and not lines[-1]:       # a trailing break adds no line in a <div>
        lines.pop()
    return lines


def _font_for(run: Run, px: float):
    return _font(run.bold, run.italic, px * (SCRIPT_SCALE if run.script else 1.0))


def _wrap(line: list[Run], width: float, px: float) -> list[list[Run]]:
    """Break one line into lines no wider than ``width`` at spaces (words kept whole)."""
    out: list[list[Run]] = [[]]
    x = 0.0
    for run in line:
        font = _font_for(run, px)
        words = run.text.split(" ")
        for j, word in enumerate(words):
            token = word + (" " if j < len(words) - 1 else "")
            w = font.getlength(token)
            if x + font.getlength(word) > width and x > 0:
                out.append([])
                x = 0.0
                token = token.lstrip(" ") if not word else token
            if token:
                out[-1].append(Run(token, run.bold, run.italic, run.script))
                x += w
    return out


def render_html(markup: str, width: int, px: float = FONT_PX,
                background: tuple[int, int, int] = (241, 242, 244),
                color: tuple[int, int, int] = TEXT_COLOR) -> np.ndarray:
    """``markup`` laid out in a block ``width`` px wide, as (height, width, 3) uint8.

    An empty title or caption gives a block 0 px high (an empty ``<div>``).
    """
    return _render(str(markup), int(width), float(px), tuple(background), tuple(color)).copy()


@functools.lru_cache(maxsize=64)
def _render(markup: str, width: int, px: float, background: tuple, color: tuple) -> np.ndarray:
    from PIL import Image, ImageDraw  # noqa: PLC0415  heavy: Pillow

    lines = [w for line in parse(markup) for w in _wrap(line, width, px)]
    a, d = _METRICS["Liberation" if "Liberation" in font_path() else "DejaVu"]
    ascent, descent = a * px, d * px
    boxes = []
    for line in lines:     # a raised or lowered script grows its line's box
        up = max([ascent] + [a * px * SCRIPT_SCALE + _SUP * px for r in line if r.script > 0])
        down = max([descent] + [d * px * SCRIPT_SCALE + _SUB * px for r in line if r.script < 0])
        boxes.append((int(round(up)), int(round(down))))
    height = sum(u + d for u, d in boxes)
    image = Image.new("RGB", (max(width, 1), height), background)
    draw = ImageDraw.Draw(image)
    y = 0
    for line, (up, down) in zip(lines, boxes):
        x = 0.0
        for run in line:
            font = _font_for(run, px)
            shift = -_SUP * px if run.script > 0 else (_SUB * px if run.script < 0 else 0.0)
            draw.text((x, y + up + shift), run.text, font=font, fill=color, anchor="ls")
            x += font.getlength(run.text)
        y += up + down
    return np.asarray(image)[:, :width]
