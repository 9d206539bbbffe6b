"""The interactive page: a recorded run replayed by GlowScript's own library, in one file.

:func:`write_interactive_page` turns a recording (docs/recording.md) into one
self-contained HTML file that works from the disk (``file://``) with no network and no
server: the program's page, titles, canvases, captions, graphs, printed text and widgets
(disabled: there is no program to answer them), every canvas drawn by GlowScript's
``glow.min.js`` (VPython 7.6.5's, :mod:`.glow_library`) as VPython draws it, with its
mouse controls (turn, zoom, pan), and a player: play and pause, a slider that shows any
frame, the speed, and "Follow the program's camera" after the user moved it.

What is in the file, in order: the player's CSS; jQuery, jQuery UI and glow.min.js as
VPython's page loads them, glow.min.js under its MIT licence notice; the data
(:mod:`.replay_data`) as JSON in a ``<script type="application/json">`` element; the
player (``vpython/data/plot.js`` and ``player.js``).

What the program wrote reaches the page safely: the data is JSON with ``<``, ``>``, ``&``
and the line separators written as ``\\uXXXX`` escapes, so no string in it (printed text,
a label, a title) can close the script element or open a comment; titles and captions are
kept as formatting only (:mod:`.safe_html`); printed text, label text, graph titles and
an error's traceback are shown as text (``textContent``, GlowScript's 2D canvas, the
graph's canvas), never parsed as HTML.
"""

from __future__ import annotations

import html
import json
import math
import os
import re
from importlib import resources
from pathlib import Path
from types import SimpleNamespace
from typing import Any, Iterable
from urllib.parse import quote

from ... import outputs
from ...errors import OutputError
from .glow_library import VERSION, GlowLibrary, library
from .graph_layout import plain_text
from .html_page import widget_html
from .replay_data import replay_data
from .safe_html import sanitize

__all__ = ["write_interactive_page", "page_html"]

_DATA = "vpython/data"
_JSON_ESCAPES = {"<": "\\u003c", ">": "\\u003e", "&": "\\u0026",
                 "\u2028": "\\u2028", "\u2029": "\\u2029"}
_UNSAFE_IN_SCRIPT = re.compile(r"</script|<!--", re.IGNORECASE)
_WIDGET_TEXTS = ("text", "prompt", "name")


def write_interactive_page(recording: str | Path, out: str | Path, *,
                           video: str | Path | None = None,
                           widgets: Iterable[Any] = (), at_end: bool = False) -> Path:
    """Write the interactive page of a recorded run, atomically.

    Parameters
    ----------
    recording : str or Path
        The run's recording (JSON Lines, ``.gz`` too; a recording cut short is read to
        its last whole frame).
    out : str or Path
        The HTML file to write.
    video : str or Path, optional
        The run's video, linked from the page (by a path relative to ``out``).
    widgets : iterable, optional
        The program's controls and wtexts in the order made
        (:func:`..core.widgets.widgets_in_order`, or dicts of the same attributes), shown
        disabled in the canvas's title or caption area as VPython places them.
    at_end : bool
        Open at the last frame, paused (a still's page: its picture, then the run).

    Returns
    -------
    Path
        ``out``.

    Raises
    ------
    OutputError
        GlowScript's library cannot be had (no network and no cache: the message says
        what to do), or the file cannot be written.
    """
    out = Path(out)
    try:
        lib = library()
    except OutputError as e:
        raise e.at(out) from None
    text = page_html({**replay_data(recording), "at_end": at_end}, lib,
                     video=_relative(video, out.parent), widgets=_widget_areas(widgets))
    with outputs.atomic_path(out) as tmp:
        tmp.write_text(text, encoding="utf-8", newline="\n")
    return out


def page_html(data: dict, lib: GlowLibrary, *, video: str | None = None,
              widgets: dict | None = None) -> str:
    """The page's HTML for ``data`` (:func:`.replay_data.replay_data`)."""
    data = {**data, "widgets": widgets or {"title": [], "caption": []}}
    title = _page_title(data)
    licence = lib.license_text.strip()
    copyright_line = next((ln for ln in licence.splitlines() if "Copyright" in ln), "")
    parts = [
        '<!DOCTYPE html>\n<html lang="en">\n<head>\n<meta charset="utf-8">',
        f"<title>{html.escape(title)}</title>",
        f"<style>\n{_asset('player.css')}</style>\n</head>\n<body>",
        '<div id="vp-player"></div>',
        '<div id="vp-page"></div>',
        '<p id="vp-left-out" class="vp-note"></p>',
        *([f'<p class="vp-note">The {_media_word(video)} of this run: '
           f'<a href="{html.escape(video)}">'
           f"{html.escape(Path(video).name)}</a></p>"] if video else []),
        f'<p class="vp-licence">Drawn by GlowScript, the library of VPython {VERSION} '
        f"(glow.min.js, inlined below under the MIT licence: {html.escape(copyright_line)})"
        f", with jQuery and jQuery UI (MIT).</p>",
        _script(lib.jquery_js),
        _script(lib.jquery_ui_js),
        _script(f"/* GlowScript, VPython {VERSION}'s vpython_libraries/glow.min.js.\n"
                f"{_comment_safe(licence)}\n*/\n{lib.glow_js}"),
        '<script type="application/json" id="springscene-recording">'
        f"{_json_for_script(data)}</script>",
        _script(_asset("plot.js") + "\n" + _asset("player.js")),
        "</body>\n</html>\n",
    ]
    return "\n".join(parts)


def _media_word(name: str) -> str:
    """What the run's file linked from the page is: its picture (a still) or its video."""
    return "picture" if Path(name).suffix.lower() == ".png" else "video"


def _asset(name: str) -> str:
    return resources.files("springscene").joinpath(f"{_DATA}/{name}").read_text("utf-8")


def _script(code: str) -> str:
    """``code`` as an inline script; code that could end the element is refused."""
    if _UNSAFE_IN_SCRIPT.search(code):
        raise ValueError("script text holds '</script' or '<!--'")
    return f"<script>\n{code}\n</script>"


def _comment_safe(text: str) -> str:
    return text.replace("*/", "* /")


def _json_for_script(data: Any) -> str:
    """``data`` as JSON that cannot end a script element, whatever its strings hold."""
    try:
        text = json.dumps(data, ensure_ascii=False, separators=(",", ":"), allow_nan=False)
    except ValueError:                   # a NaN or an infinity: null, as the recording has
        text = json.dumps(_finite(data), ensure_ascii=False, separators=(",", ":"))
    return re.sub("[<>&\u2028\u2029]", lambda m: _JSON_ESCAPES[m.group()], text)


def _finite(v: Any) -> Any:
    if isinstance(v, float):
        return v if math.isfinite(v) else None
    if isinstance(v, dict):
        return {k: _finite(x) for k, x in v.items()}
    if isinstance(v, list):
        return [_finite(x) for x in v]
    return v


def _page_title(data: dict) -> str:
    """The first canvas's title as text, else the program's name."""
    for c in data.get("canvases", ()):
        for _, value in c["t"].get("title", ()):
            text = " ".join(plain_text(value or "").split())
            if text:
                return text
    program = (data.get("header") or {}).get("program")
    return f"{Path(program).name} (VPython)" if program else "VPython"


def _relative(ref: str | Path | None, base: Path) -> str | None:
    """``ref`` as a URL relative to the folder ``base`` (None stays None)."""
    if ref is None:
        return None
    p = Path(ref)
    if p.is_absolute() or base != Path("."):
        try:
            p = Path(os.path.relpath(p.resolve(), base.resolve()))
        except ValueError:                       # another drive (Windows)
            p = Path(p.name)
    return quote(p.as_posix())


def _widget_areas(widgets: Iterable[Any]) -> dict[str, list]:
    """Each widget as disabled HTML with its place: {"title": [[seq, html]], "caption": …}."""
    areas: dict[str, list] = {"title": [], "caption": []}
    for w in widgets:
        safe = _safe_widget(w)
        area = "title" if getattr(safe, "anchor", "caption") == "title" else "caption"
        areas[area].append([getattr(safe, "seq", None), widget_html(safe)])
    return areas


def _safe_widget(w: Any) -> SimpleNamespace:
    """A copy of a widget (or a dict of its attributes) whose texts are formatting only."""
    attrs = dict(w) if isinstance(w, dict) else _attributes(w)
    for a in _WIDGET_TEXTS:
        if isinstance(attrs.get(a), str):
            attrs[a] = sanitize(attrs[a])
    if isinstance(attrs.get("choices"), (list, tuple)):
        attrs["choices"] = [sanitize(str(c)) for c in attrs["choices"]]
        if attrs.get("selected") is not None:
            attrs["selected"] = sanitize(str(attrs["selected"]))
    return SimpleNamespace(**attrs)


def _attributes(w: Any) -> dict[str, Any]:
    """A widget's readable attributes that are not methods."""
    out = {}
    for a in dir(w):
        if a.startswith("__"):
            continue
        try:
            v = getattr(w, a)
        except Exception:        # a property this kind of widget refuses: not shown
            continue
        if not callable(v):
            out[a] = v
    return out
