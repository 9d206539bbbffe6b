"""Draw VPython labels over a frame as GlowScript's 2D overlay canvas draws them.

Per label, in GlowScript's order (``label.__update``, ``lib/glow/primitives.js``): the
background rectangle (``fillRect`` in the background colour at ``opacity``), the leader
line from ``pos`` to ``pos + offset`` (when an offset is set and ``line``), the box
(``strokeRect``-like closed path, ``linewidth`` wide, when ``box``), then the text
(``fillText``, :mod:`..text.label_layout`). Colours are GlowScript's: the text in ``color``,
else white, or black when the canvas background is exactly white; lines and box in
``linecolor``, else the text colour; the fill in ``background``, else the canvas's.

Everything is composited in numpy onto the grabbed RGB frame ("source over"), with
exact area coverage for the rectangles, 4 x 4 supersampling for the leader line; glyphs
are Pillow's FreeType at 16x size averaged down, at the browser's fractional x and on
a whole-pixel baseline (as Chromium's canvas text: measured against VPython 7.6.5 this
halves the pixels off by more than a quarter). Text masks are cached by their look.
"""

from __future__ import annotations

import functools
import math
from dataclasses import dataclass

import numpy as np

from ..text import fonts, label_layout

SS = 4            # supersampling of the leader line
TEXT_SS = 16      # glyphs are drawn at 16x size and averaged down (unhinted, at 1/16 px)


@dataclass(frozen=True)
class Spec:
    """One label to draw: its geometry and GlowScript's colours (0..255 floats)."""

    geometry: label_layout.Geometry
    text_rgb: tuple
    line_rgb: tuple
    fill_rgba: tuple
    linewidth: float
    box: bool


def _html(rgb) -> tuple:
    """``color.to_html``: floor(255 * c), each channel in 0..255."""
    return tuple(float(min(255, max(0, math.floor(255 * c)))) for c in rgb)


def _rgb(c) -> tuple:
    return tuple(float(v) for v in (c.value if hasattr(c, "value") else c))


def spec(lab, view, width: int, height: int, background) -> Spec | None:
    """Where and how ``lab`` is drawn on a ``width`` x ``height`` canvas seen by ``view``
    (None when GlowScript skips it: behind the camera or beyond its far plane)."""
    xoff, yoff = float(lab._xoffset), float(lab._yoffset)
    if lab._pixel_pos:                     # pos in pixels from the bottom-left; yoffset down
        posx, posy = float(lab._pos.x), height - float(lab._pos.y)
        yoff = -yoff
    else:
        p = np.array(lab._pos.value, dtype=float)
        fwd = view.focal_point - view.position
        depth = float((p - view.position) @ (fwd / np.linalg.norm(fwd)))
        if depth < view.near or depth > view.far:
            return None
        col, row = view.project(p)
        if not (math.isfinite(col) and math.isfinite(row)):
            return None
        posx, posy = math.floor(col + 0.5), math.floor(row + 0.5)
    if not all(math.isfinite(v) for v in (posx, posy, xoff, yoff, float(lab._height))):
        return None                        # a NaN or infinite place: nowhere to draw it
    geo = label_layout.place(lab._text, lab._font, float(lab._height), lab._align,
                             (posx, posy), (xoff, yoff), float(lab._border),
                             fonts.width, float(lab._space))
    bg = tuple(background)
    default = (0.0, 0.0, 0.0) if bg == (1.0, 1.0, 1.0) else (1.0, 1.0, 1.0)
    text = lab._color if lab._color is not None else default
    line = lab._linecolor if lab._linecolor is not None else text
    fill = lab._background if lab._background is not None else bg
    return Spec(geo, _html(_rgb(text)), _html(_rgb(line)),
                (*_html(_rgb(fill)), min(1.0, max(0.0, float(lab._opacity)))),
                float(lab._linewidth), bool(lab._box))


def composite(image: np.ndarray, specs) -> np.ndarray:
    """``image`` (h, w, 3) uint8 with the labels drawn over it, in order."""
    specs = [s for s in specs if s is not None]
    if not specs:
        return image
    out = np.array(image, dtype=np.uint8, copy=True)
    for s in specs:
        _draw(out, s)
    return out


def _draw(out: np.ndarray, s: Spec) -> None:
    x, y, w, h = s.geometry.rect
    _over(out, _rect_cover(out.shape, x, y, x + w, y + h), s.fill_rgba[:3], s.fill_rgba[3])
    if s.geometry.line is not None and s.linewidth > 0:
        _over(out, _segment_cover(out.shape, *s.geometry.line, s.linewidth), s.line_rgb, 1.0)
    if s.box and s.linewidth > 0:
        _over(out, _box_cover(out.shape, x, y, w, h, s.linewidth), s.line_rgb, 1.0)
    runs = s.geometry.runs
    if runs:
        ox = math.floor(min(r.x - r.size / 2 for r in runs))
        oy = math.floor(min(r.y - r.size for r in runs))
        key = tuple((r.x - ox, r.y - oy, r.text, r.size, r.bold, r.italic) for r in runs)
        mask = _text_mask(key, s.geometry.family)
        _over(out, (oy, ox, mask), s.text_rgb, 1.0)


def _over(out: np.ndarray, cover, rgb, alpha: float) -> None:
    """Source-over of colour ``rgb`` with coverage ``cover`` = (row0, col0, mask)."""
    if cover is None:
        return
    r0, c0, mask = cover
    hgt, wid = out.shape[:2]
    r1, c1 = r0 + mask.shape[0], c0 + mask.shape[1]
    rr0, cc0, rr1, cc1 = max(r0, 0), max(c0, 0), min(r1, hgt), min(c1, wid)
    if rr0 >= rr1 or cc0 >= cc1:
        return
    a = mask[rr0 - r0:rr1 - r0, cc0 - c0:cc1 - c0, None] * alpha
    region = out[rr0:rr1, cc0:cc1].astype(np.float32)
    region += (np.asarray(rgb, dtype=np.float32) - region) * a
    out[rr0:rr1, cc0:cc1] = np.clip(np.rint(region), 0, 255).astype(np.uint8)


def _span(lo: float, hi: float) -> tuple[int, np.ndarray]:
    """Coverage of pixels [i, i+1) by the interval [lo, hi): (first pixel, fractions)."""
    i0, i1 = math.floor(lo), math.ceil(hi)
    edges = np.arange(i0, i1 + 1, dtype=np.float64)
    return i0, np.clip(np.minimum(edges[1:], hi) - np.maximum(edges[:-1], lo), 0.0, 1.0)


def _rect_cover(shape, x0: float, y0: float, x1: float, y1: float):
    """Exact area coverage of the axis-aligned rectangle [x0, x1) x [y0, y1) (the part
    on the canvas, give or take a pixel)."""
    x0, y0, x1, y1 = max(x0, -1.0), max(y0, -1.0), min(x1, shape[1] + 1.0), min(y1, shape[0] + 1.0)
    if x1 <= x0 or y1 <= y0:
        return None
    c0, cx = _span(x0, x1)
    r0, cy = _span(y0, y1)
    return r0, c0, (cy[:, None] * cx[None, :]).astype(np.float32)


def _box_cover(shape, x: float, y: float, w: float, h: float, lw: float):
    """A rectangle's outline stroked ``lw`` wide (mitred corners): outer minus inner."""
    outer = _rect_cover(shape, x - lw / 2, y - lw / 2, x + w + lw / 2, y + h + lw / 2)
    inner = _rect_cover(shape, x + lw / 2, y + lw / 2, x + w - lw / 2, y + h - lw / 2)
    if outer is None or inner is None:
        return outer
    r0, c0, mask = outer
    ir, ic, imask = inner
    mask = mask.copy()
    mask[ir - r0:ir - r0 + imask.shape[0], ic - c0:ic - c0 + imask.shape[1]] -= imask
    return r0, c0, np.clip(mask, 0.0, 1.0)


def _segment_cover(shape, x0: float, y0: float, x1: float, y1: float, lw: float):
    """A straight stroke ``lw`` wide with butt ends, 4 x 4 samples a pixel."""
    length = math.hypot(x1 - x0, y1 - y0)
    if length == 0:
        return None
    pad = lw / 2 + 1
    c0, r0 = math.floor(min(x0, x1) - pad), math.floor(min(y0, y1) - pad)
    c1, r1 = math.ceil(max(x0, x1) + pad), math.ceil(max(y0, y1) + pad)
    c0, r0, c1, r1 = max(c0, 0), max(r0, 0), min(c1, shape[1]), min(r1, shape[0])   # on canvas
    if c1 <= c0 or r1 <= r0:
        return None
    sub = (np.arange(SS) + 0.5) / SS
    xs = (np.arange(c0, c1)[:, None] + sub[None, :]).ravel()
    ys = (np.arange(r0, r1)[:, None] + sub[None, :]).ravel()
    ux, uy = (x1 - x0) / length, (y1 - y0) / length
    dx, dy = xs[None, :] - x0, ys[:, None] - y0
    along = dx * ux + dy * uy
    across = np.abs(dy * ux - dx * uy)
    inside = (along >= 0) & (along <= length) & (across <= lw / 2)
    mask = inside.reshape(r1 - r0, SS, c1 - c0, SS).mean(axis=(1, 3))
    return r0, c0, mask.astype(np.float32)


@functools.lru_cache(maxsize=512)
def _text_mask(runs: tuple, family: str) -> np.ndarray:
    """Coverage of text runs (x, y_middle, text, size, bold, italic) relative to (0, 0)."""
    from PIL import Image, ImageDraw  # noqa: PLC0415  heavy: PIL

    right = max(x + fonts.width(t, family, size, b, i) for x, _, t, size, b, i in runs)
    bottom = max(y + size for _, y, _, size, _, _ in runs)
    wid, hgt = int(math.ceil(right + max(r[3] for r in runs) / 2)) + 2, int(math.ceil(bottom)) + 2
    s = TEXT_SS
    canvas = Image.new("L", (wid * s, hgt * s), 0)
    draw = ImageDraw.Draw(canvas)
    for x, y, text, size, bold, italic in runs:
        if not text or size * s < 1:
            continue
        path = fonts.font_file(family, bold, italic)
        base = math.floor(y + fonts.middle(path) * size + 0.5)
        font = fonts.pil_font(path, size * s)
        draw.text((round(x * s), base * s), text, font=font, fill=255, anchor="ls")
    return np.asarray(canvas.reduce(s), dtype=np.float32) / 255.0     # box average
