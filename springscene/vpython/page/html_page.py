"""The web page a VPython program would have shown, written beside its video.

VPython puts, from top to bottom: the canvas's title area, the canvas, its caption
area, then the graphs. When the video is that whole page (the default, :mod:`.film`),
the page shows the video once with the widgets under it. With ``--canvas-only``
:func:`write_page` writes the page around the canvas's video as one self-contained HTML5
file: the title and caption are the program's own HTML (inserted as it is, as
VPython does; both areas keep line breaks and spaces, ``white-space: pre``, as
VPython's anchors do), the video or image stands where the canvas was, widgets are
drawn as disabled HTML controls showing their initial values (there was no user),
``wtext`` shows its text, and each graph is an ``<img>``.

Widgets go after the text of their area (``title`` or ``caption``), unless the area's
HTML holds the widget's placeholder (:func:`..core.widgets.placeholder`), which is then
replaced by it, so a widget appears where the program put it among the text.
"""

from __future__ import annotations

import html
import os
import tempfile
from pathlib import Path
from typing import Any, Iterable
from urllib.parse import quote

from .graph_layout import plain_text

__all__ = ["write_page", "widget_html"]

_MEDIA_KINDS = ("video", "image", "gif")

_STYLE = """\
body { font-family: Verdana, Arial, Helvetica, sans-serif; font-size: 15px; margin: 10px; }
.vp-title, .vp-caption { white-space: pre; }
.vp-print { border: 1px solid #ccc; padding: 4px; max-height: 300px; overflow: auto; }
.vp-canvas { display: inline-block; margin: 4px 0; }
.vp-canvas video, .vp-canvas img { display: block; }
.vp-graph { display: block; margin: 6px 0; }
input[type=range].vp-vertical { writing-mode: vertical-lr; direction: rtl; }
"""


def _attr(value: Any) -> str:
    return html.escape(str(value), quote=True)


def _css_rgb(c: Any, default: str) -> str:
    """A vector or 3-sequence in 0..1 as ``rgb(r, g, b)``; ``default`` if it is neither."""
    try:
        if all(hasattr(c, a) for a in "xyz"):
            c = (c.x, c.y, c.z)
        r, g, b = (round(255 * min(max(float(v), 0.0), 1.0)) for v in c)
    except (TypeError, ValueError):
        return default
    return f"rgb({r}, {g}, {b})"


def _number(v: Any) -> str:
    try:
        f = float(v)
    except (TypeError, ValueError):
        return _attr(v)
    return repr(int(f)) if f.is_integer() else repr(f)


def widget_html(w: Any) -> str:
    """One widget as disabled HTML showing its current value (a ``wtext`` as its text).

    Parameters
    ----------
    w : widget
        A control or wtext from :mod:`..core.widgets` (read through its ``kind`` and
        attributes).
    """
    kind = getattr(w, "kind", "")
    if kind == "wtext":
        return f'<span class="vp-wtext">{w.text}</span>'
    if kind == "button":
        style = (f"color: {_css_rgb(w.color, 'black')}; "
                 f"background-color: {_css_rgb(w.background, 'white')}; font-size: 15px")
        return (f'<button type="button" class="vp-button" disabled style="{style}">'
                f"{w.text}</button> ")
    if kind == "slider":
        vertical = bool(w.vertical)
        size = (f"height: {int(w.length)}px; width: {int(w.width) + 6}px" if vertical
                else f"width: {int(w.length)}px")
        cls = "vp-slider vp-vertical" if vertical else "vp-slider"
        return (f'<input type="range" class="{cls}" disabled min="{_number(w.min)}" '
                f'max="{_number(w.max)}" step="{_number(w.step) if w.step else "any"}" '
                f'value="{_number(w.value)}" style="{size}; margin: 0 12px">')
    if kind == "checkbox":
        checked = " checked" if w.checked else ""
        return (f'<label class="vp-checkbox"><input type="checkbox" disabled{checked}> '
                f"{w.text}</label>")
    if kind == "radio":
        checked = " checked" if w.checked else ""
        name = f' name="{_attr(w.name)}"' if w.name else ""
        return (f'<label class="vp-radio"><input type="radio" disabled{name}{checked}> '
                f"{w.text}</label>")
    if kind == "menu":
        options = "".join(
            f"<option{' selected' if c == w.selected else ''}>{c}</option>"
            for c in w.choices)
        return f'<select class="vp-menu" disabled style="font-size: 15px">{options}</select> '
    if kind == "winput":
        prompt = f'<span class="vp-prompt">{w.prompt} </span>' if w.prompt else ""
        return (f'{prompt}<input type="text" class="vp-winput" disabled '
                f'value="{_attr(w.text)}" style="width: {int(w.width)}px; '
                f'height: {int(w.height)}px">')
    return ""


def _fill(area_html: str, ws: Iterable[Any]) -> str:
    """``area_html`` with each widget at its placeholder, or after the text if none."""
    out, rest = area_html, []
    for w in ws:
        mark = f"<!--vpython-widget-{getattr(w, 'seq', '')}-->"
        if getattr(w, "seq", None) is not None and mark in out:
            out = out.replace(mark, widget_html(w), 1)
        else:
            rest.append(widget_html(w))
    return out + "".join(rest)


def _relative(ref: str, base: Path) -> str:
    """``ref`` (a file name, or a path) as a URL relative to the folder ``base``."""
    p = Path(ref)
    if p.is_absolute():
        try:
            p = Path(os.path.relpath(p, base))
        except ValueError:                       # another drive (Windows)
            p = Path(p.name)
    return quote(p.as_posix())


def write_page(path: str | Path, *, title_html: str, caption_html: str, media: str,
               media_kind: str, width: int, height: int, graph_images: list[str],
               widgets: list, printed: str = "", page_video: bool = False) -> Path:
    """Write the page VPython would show, atomically.

    Parameters
    ----------
    path : str or Path
        The HTML file to write; the media and graph images are beside it.
    title_html, caption_html : str
        The canvas's title and caption, HTML from the program (inserted as it is).
    media : str
        The video or image (a file name beside the page, or a path).
    media_kind : {"video", "image", "gif"}
        A ``<video>`` for "video", an ``<img>`` otherwise.
    width, height : int
        The canvas's size in pixels.
    graph_images : list of str
        PNGs of the graphs, in order (file names or paths).
    widgets : list
        Controls and wtexts in the order made (:func:`..core.widgets.widgets_in_order`).
    printed : str
        What the program printed: GlowScript shows it in a box below the canvas.
    page_video : bool
        The media is the whole page (titles, canvases, captions and graphs drawn in
        it): the page shows it once, with the widgets under it, and nothing twice.

    Returns
    -------
    Path
        ``path``.
    """
    path = Path(path)
    if media_kind not in _MEDIA_KINDS:
        raise ValueError(f"media_kind must be one of {', '.join(_MEDIA_KINDS)}, "
                         f"not {media_kind!r}")
    base = path.parent
    name = plain_text(title_html) or Path(media).name
    canvas = _canvas_html(media, media_kind, int(width), int(height), base)
    title_ws, caption_ws = _split_widgets(widgets, page_video)
    if page_video:           # the title, caption and graphs are in the video already
        title_html, caption_html, graph_images = "", "", []
    text = "\n".join([
        '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">',
        f"<title>{html.escape(' '.join(name.split()))}</title>",
        f"<style>\n{_STYLE}</style>\n</head>\n<body>",
        f'<div class="vp-title">{_fill(str(title_html), title_ws)}</div>',
        f'<div class="vp-canvas">{canvas}</div>',
        f'<div class="vp-caption">{_fill(str(caption_html), caption_ws)}</div>',
        '<div class="vp-graphs">',
        *_graphs_html(graph_images, base),
        "</div>",
        *([f'<pre class="vp-print">{html.escape(printed)}</pre>'] if printed else []),
        "</body>\n</html>\n",
    ])
    _write_atomic(path, text)
    return path


def _split_widgets(widgets: list, page_video: bool) -> tuple[list, list]:
    """The widgets of the title area and of the caption area (all under a page video)."""
    if page_video:
        return [], list(widgets)
    title_ws = [x for x in widgets if getattr(x, "anchor", "caption") == "title"]
    return title_ws, [x for x in widgets if getattr(x, "anchor", "caption") != "title"]


def _canvas_html(media: str, media_kind: str, w: int, h: int, base: Path) -> str:
    """The ``<video>`` (or ``<img>``) that stands where the canvas was."""
    src = _relative(media, base)
    if media_kind == "video":
        return (f'<video src="{src}" width="{w}" height="{h}" controls loop muted autoplay '
                f"playsinline></video>")
    return f'<img src="{src}" width="{w}" height="{h}" alt="{_attr(Path(media).name)}">'


def _graphs_html(graph_images: list[str], base: Path) -> list[str]:
    """One ``<img>`` a graph, with the image's size when it can be read."""
    graphs = []
    for i, img in enumerate(graph_images, 1):
        size = _image_size(base / img if not Path(img).is_absolute() else Path(img))
        dims = f' width="{size[0]}" height="{size[1]}"' if size else ""
        graphs.append(f'<img class="vp-graph" src="{_relative(img, base)}"{dims} '
                      f'alt="graph {i}">')
    return graphs


def _image_size(p: Path) -> tuple[int, int] | None:
    """(width, height) of an image file, or None if it cannot be read."""
    try:
        from PIL import Image  # noqa: PLC0415  heavy: Pillow

        with Image.open(p) as im:
            return im.size
    except Exception:       # a missing or unreadable image: the <img> goes without a size
        return None


def _write_atomic(path: Path, text: str) -> None:
    """Write ``text`` (UTF-8) to a temporary file beside ``path``, then put it in place."""
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp = tempfile.mkstemp(prefix=f".{path.name}.", suffix=".tmp", dir=path.parent)
    try:
        with os.fdopen(fd, "w", encoding="utf-8", newline="\n") as f:
            f.write(text)
            f.flush()
            os.fsync(f.fileno())
        os.chmod(tmp, 0o644)                     # mkstemp makes it private
        os.replace(tmp, path)
    except BaseException:
        try:
            os.unlink(tmp)
        except FileNotFoundError:
            pass
        raise
