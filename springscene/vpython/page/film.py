"""The frames of a VPython program's video: its page, or its first canvas alone.

By default a frame is the page as VPython lays it out (:mod:`.layout`): each
shown canvas with its title above and caption below, and the graphs, in the order
they appeared. With ``canvas_only`` a frame is the first canvas with objects at its
own size (what ``scene.capture`` saves), with ``--overlay graph`` the graphs under it.
A canvas resized during the run is drawn at its new size from then on.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ...outputs import VideoWriter
from ..core.canvases import canvas, canvases
from ..draw.renderer import Renderer
from ..geometry.lod import DEFAULT, LevelOfDetail
from ..api.graphs import graphs
from .graph_images import GraphStrip
from .layout import PAGE_BACKGROUND, PageLayout, fit

__all__ = ["Film", "Printed"]


class Printed:
    """What the program prints: passed on to the terminal and kept (up to ``limit``
    characters) for the page, as GlowScript shows it below the canvas; ``also(text)``, if
    given, gets each piece as it is printed."""

    def __init__(self, out, limit: int = 100_000, also=None) -> None:
        self.out, self.limit, self.also = out, limit, also
        self.parts: list[str] = []
        self.size = 0

    def write(self, text: str) -> int:
        if self.also is not None:             # the recording's own copy, frame by frame
            self.also(text)
        if self.size < self.limit:
            self.parts.append(text[: self.limit - self.size])
            self.size += len(self.parts[-1])
        return self.out.write(text)

    def __getattr__(self, name: str):
        return getattr(self.out, name)

    def text(self) -> str:
        return "".join(self.parts)


class Film:
    """Takes the frames: draws the page (or the shown canvas), feeds the writer."""

    def __init__(self, tmp: Path | None, fps: int, overlays: tuple[str, ...], backend: str,
                 antialias: bool, on_frame, canvas_only: bool = False,
                 quality: str = "medium", lod: LevelOfDetail = DEFAULT) -> None:
        self.tmp, self.fps, self.overlays = tmp, fps, overlays
        self.backend, self.antialias, self.on_frame = backend, antialias, on_frame
        self.lod = lod
        self.canvas_only, self.quality = canvas_only, quality
        self.renderers: dict[int, Renderer] = {}
        self.shown = None
        self.writer = None
        self.strip = None
        self.graph_strips: dict[int, GraphStrip] = {}
        self.layout = PageLayout()
        self.graphs_only = False            # no 3D object at all: the video is the graphs
        self.printed: Printed | None = None
        self.frames = 0
        self.size: tuple[int, int] | None = None      # a still's (width, height)
        self.notes: list[str] = []
        if overlays and not canvas_only:
            self.notes.append("--overlay graph: the page video has the graphs already "
                              "(the overlay is for --canvas-only)")

    def renderer(self, cv) -> Renderer:
        """The renderer of ``cv``, made anew when the program resized the canvas."""
        r = self.renderers.get(id(cv))
        if r is not None and (r.width, r.height) != (int(cv.width), int(cv.height)):
            r.close()
            r = None
        if r is None:
            r = self.renderers[id(cv)] = Renderer(cv, self.antialias, self.backend,
                                                           self.lod)
        return r

    def _choose_canvas(self):
        shown = [cv for cv in canvases() if cv._visible and cv._objects]
        if len(shown) > 1:
            self.notes.append(f"{len(shown)} canvases have objects; with --canvas-only the "
                              "video shows the first")
        return shown[0] if shown else canvas.get_selected()

    def picture(self) -> np.ndarray:
        """The shown canvas alone (``--canvas-only``)."""
        if self.shown is None:
            self.shown = self._choose_canvas()
        return self.renderer(self.shown).frame()

    def page(self) -> np.ndarray:
        """The page now: titles, canvases, captions and graphs in page order."""
        items = []
        for it in PageLayout.order(canvases(), graphs()):
            if isinstance(it, canvas):
                items.append((it.title, it.caption, self.renderer(it).frame()))
            else:
                items.append(("", "", self._graph_picture(it)))
        if not items:                       # nothing drawn yet: the empty scene
            cv = canvas.get_selected()
            items.append((cv.title, cv.caption, self.renderer(cv).frame()))
        return self.layout.frame(items)

    def _graph_picture(self, g) -> np.ndarray:
        """A graph at its own size; before its first point VPython shows nothing there, so
        the page keeps its place blank."""
        size = (int(g.height), int(g.width))
        if not any(s._n for s in g.series):
            block = np.empty(size + (3,), np.uint8)
            block[:] = PAGE_BACKGROUND
            return block
        strip = self.graph_strips.get(id(g))
        if strip is None or (strip.height, strip.width) != size:
            strip = self.graph_strips[id(g)] = GraphStrip([g], size[1], size[0])
        return strip.draw()

    def still(self) -> np.ndarray:
        """The picture a PNG output gets: the page, or the canvas alone."""
        return self.picture() if self.canvas_only else self.page()

    def take(self) -> None:
        image = self._canvas_frame() if self.canvas_only else self.page()
        if self.writer is None:
            self.writer = VideoWriter(self.tmp, self.fps, (image.shape[1], image.shape[0]),
                                      self.quality)
        elif image.shape[:2] != self.writer.size[::-1]:     # a canvas resized mid-run
            if not any("resized" in n for n in self.notes):
                self.notes.append(f"the canvas was resized to {image.shape[1]} x "
                                  f"{image.shape[0]} during the run; the video keeps "
                                  f"{self.writer.size[0]} x {self.writer.size[1]}")
            image = fit(image, self.writer.size)
        self.writer.write(image)
        self.frames += 1
        if self.on_frame is not None:
            self.on_frame(self.frames - 1, image)

    def _canvas_frame(self) -> np.ndarray:
        """The canvas alone, with the graphs under it for ``--overlay graph`` (or the
        graphs alone for a program that draws only graphs)."""
        image = self.picture()
        if self.writer is None:
            self.graphs_only = not any(cv._objects for cv in canvases()) and bool(graphs())
            if self.graphs_only:
                self.notes.append("the program draws only graphs: the video shows them")
            if "graph" in self.overlays or self.graphs_only:
                if graphs():
                    self.strip = GraphStrip(list(graphs()), image.shape[1])
                else:
                    self.notes.append("--overlay graph: the program had made no graph "
                                      "by its first frame")
        if self.graphs_only:
            return self.strip.draw()
        if self.strip is not None:
            return np.vstack([image, self.strip.draw()])
        return image

    def close(self, ok: bool) -> None:
        if self.writer is not None:
            self.writer.__exit__(None if ok else RuntimeError, None, None)
        for r in self.renderers.values():
            r.close()
        self.notes.extend(n for n in self.layout.notes if n not in self.notes)
