"""The page a VPython program shows, as one video frame.

VPython lays its page out from top to bottom in the order things appear (vpython/
glowscript ``lib/glow/canvas.js`` ``__activate``; ``lib/glow/graph.js``): for each canvas,
when its first object is made, its title, the canvas, then its caption; each graph when
its first point is plotted. springscene gives a graph its place when it is made and
keeps that place blank until its first point (VPython leaves no space until then), so
that a video whose first frame comes before the first plot has room for the graph. Everything is left-aligned inside the body's 8 px margin,
on vpython's page colour #f1f2f4 (``ide.css``). A canvas without objects is never
shown. :class:`PageLayout` draws that page from the canvases' pictures and the graphs'
pictures; the first frame fixes the video's size (even, for yuv420p), later frames are
padded to it, and a page that outgrows it is cut, with a note.
"""

from __future__ import annotations


import numpy as np

from ..text.html_text import render_html

__all__ = ["PAGE_BACKGROUND", "MARGIN", "PageLayout", "fit"]

PAGE_BACKGROUND = (241, 242, 244)      # vpython's ide.css: body background #f1f2f4
MARGIN = 8                             # the browser's default body margin

def fit(image: np.ndarray, size: tuple[int, int],
        background: tuple[int, int, int] = (0, 0, 0)) -> np.ndarray:
    """``image`` at the video's ``size`` (width, height): padded with ``background`` at the
    right and bottom, or cut there."""
    W, H = size
    if image.shape[:2] == (H, W):
        return image
    out = np.empty((H, W, 3), np.uint8)
    out[:] = background
    h, w = min(image.shape[0], H), min(image.shape[1], W)
    out[:h, :w] = image[:h, :w]
    return out


class PageLayout:
    """Stacks titles, canvases, captions and graphs into frames of one size."""

    def __init__(self, background: tuple[int, int, int] = PAGE_BACKGROUND) -> None:
        self.background = tuple(background)
        self.size: tuple[int, int] | None = None      # (width, height), set by the first frame
        self.notes: list[str] = []

    @staticmethod
    def order(canvases: list, graphs: list) -> list:
        """Canvases with objects and the graphs made so far, in the order they appeared."""
        shown = [c for c in canvases if c._objects and getattr(c, "_visible", True)]
        shown += [g for g in graphs if getattr(g, "_page_slot", None) is not None]
        return sorted(shown, key=lambda x: getattr(x, "_page_slot", 0) or 0)

    def blocks(self, items: list[tuple[str, str, np.ndarray]]) -> list[np.ndarray]:
        """``items``: (title html, caption html, picture) for each thing on the page, in
        order (graphs have no title or caption). Returns the blocks, top to bottom."""
        inner = max([img.shape[1] for _, _, img in items] + [1])
        if self.size is not None:
            inner = max(inner, self.size[0] - 2 * MARGIN)
        out = []
        for title, caption, img in items:
            if title:
                out.append(render_html(title, inner, background=self.background))
            out.append(img)
            if caption:
                out.append(render_html(caption, inner, background=self.background))
        return out

    def frame(self, items: list[tuple[str, str, np.ndarray]]) -> np.ndarray:
        """The page now, (height, width, 3) uint8, at the video's one size."""
        blocks = self.blocks(items)
        w = max([b.shape[1] for b in blocks] + [1]) + 2 * MARGIN
        h = sum(b.shape[0] for b in blocks) + 2 * MARGIN
        if self.size is None:
            self.size = (w + w % 2, h + h % 2)
        W, H = self.size
        if (w > W or h > H) and not self.notes:
            self.notes.append(f"the page grew to {w} x {h} px after the first frame; the "
                              f"video keeps its first size, {W} x {H}, and cuts the rest")
        page = np.empty((H, W, 3), np.uint8)
        page[:] = self.background
        y = MARGIN
        for b in blocks:
            if y >= H:
                break
            bh, bw = min(b.shape[0], H - y), min(b.shape[1], W - MARGIN)
            page[y:y + bh, MARGIN:MARGIN + bw] = b[:bh, :bw]
            y += b.shape[0]
        return page
