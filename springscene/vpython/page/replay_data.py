"""A recording (docs/recording.md) as the interactive page's data: timelines to seek in.

The recording says, frame by frame, what changed. The page must show any frame at once,
backwards too, so :func:`replay_data` turns it around: one **timeline** per (object,
attribute), the frames where the value changed and the values, which the player
(``vpython/data/player.js``) searches with a binary search; curves' and points' points and
graphs' series as **segments** (a ``reset`` starts one; appends add to its end, ``drop``
removes from its front) with, at each frame they changed, which segment and which slice of
it is shown.

Compactness: every number of a numeric timeline (a vector or a number at every value) is
a float32, each value XORed with the one before it in its timeline (bit for bit, so a
value that changed little is mostly zero bits); the frames of a timeline that changed at
every frame from its first are that first frame alone, others' frames int32s. Each kind
goes into the page as one buffer: its bytes shuffled (all first bytes, then all second
bytes, …), compressed with zlib, in base64; the page inflates it with the browser's
``DecompressionStream``. float32 keeps 7 significant digits, what WebGL draws with.
Canvases (the camera), strings, booleans and values that may be null are JSON, the
program's own numbers as Python wrote them.
"""

from __future__ import annotations

import base64
import math
import zlib
from dataclasses import dataclass, field
from importlib import resources
from pathlib import Path
from typing import Any

import numpy as np

from ..record.reader import lines, numbers
from ..record.recorder import PRINTED_LIMIT as _PRINTED_LIMIT
from .graph_layout import plain_text
from .safe_html import sanitize

__all__ = ["replay_data", "DRAWN_KINDS"]

# kinds the player draws with GlowScript's own constructor
DRAWN_KINDS = frozenset("box sphere simple_sphere ellipsoid cylinder cone pyramid arrow helix "
                        "ring curve points label".split())
_POINT_WIDTH = 7                      # x, y, z, r, g, b, radius
_SERIES_WIDTH = 2                     # x, y
_TEXTURES = "vpython/data/vpython_textures"


@dataclass
class _Buffers:
    """The page's numbers: float32s and int32s, each packed as in the module docstring."""

    floats: list = field(default_factory=list)
    ints: list = field(default_factory=list)
    n_floats: int = 0
    n_ints: int = 0

    def add_floats(self, values, rows_of: int = 0) -> int:
        """Append floats; with ``rows_of`` = n each row of n is XORed with the row before
        (as uint32s), so a value that changes little becomes mostly zero bits."""
        with np.errstate(over="ignore"):        # past float32's 3.4e38: infinite, as drawn
            at, a = self.n_floats, np.asarray(values, dtype="<f4")
        if rows_of and a.size > rows_of:
            u = a.view("<u4").reshape(-1, rows_of)
            u[1:] ^= u[:-1].copy()
        self.floats.append(a)
        self.n_floats += a.size
        return at

    def add_ints(self, values) -> int:
        at, a = self.n_ints, np.asarray(values, dtype="<i4")
        self.ints.append(a)
        self.n_ints += a.size
        return at

    def encoded(self) -> dict[str, str]:
        return {"f32": _packed(self.floats, "<f4"), "i32": _packed(self.ints, "<i4")}


ZLIB_LEVEL = 6     # zlib's default: level 9 took 10 s, not 0.9 s, on a run's 7 MB of
                   # trail points and made them 0.6 % smaller


def _packed(chunks: list, dtype: str) -> str:
    """Arrays of 4-byte numbers as base64 of the zlib stream of their bytes shuffled: the
    first bytes of every number, then the second bytes, … (alike bytes side by side)."""
    a = np.concatenate(chunks).astype(dtype) if chunks else np.zeros(0, dtype)
    shuffled = a.view(np.uint8).reshape(-1, 4).T.tobytes()
    return base64.b64encode(zlib.compress(shuffled, ZLIB_LEVEL)).decode("ascii")


@dataclass
class _Segments:
    """A list of points (curve, points, a graph's series) over time, as segments."""

    width: int
    segments: list[list[np.ndarray]] = field(default_factory=list)   # (n, width) blocks
    sizes: list[int] = field(default_factory=list)                   # points a segment
    states: list[tuple[int, int, int, int]] = field(default_factory=list)  # frame, seg, a, b

    def change(self, frame: int, reset=None, drop: int = 0, append=()) -> None:
        seg, start, end = (self.states[-1][1:] if self.states else (-1, 0, 0))
        if reset is not None or seg < 0:
            self.segments.append([])
            self.sizes.append(0)
            seg, start, end = len(self.segments) - 1, 0, 0
            append = list(reset or ()) + list(append)
        start = min(start + max(int(drop), 0), end)
        rows = _rows(append, self.width)
        if len(rows):
            self.segments[seg].append(rows)
            self.sizes[seg] += len(rows)
        end = self.sizes[seg]
        state = (frame, seg, start, end)
        if self.states and self.states[-1][0] == frame:
            self.states[-1] = state
        else:
            self.states.append(state)

    def encoded(self, buf: _Buffers) -> list[Any]:
        offsets = [buf.add_floats(np.concatenate(s).ravel() if s else ()) for s in self.segments]
        flat = [v for s in self.states for v in s]
        return [offsets, buf.add_ints(flat), len(self.states)]


def _rows(points, width: int) -> np.ndarray:
    """The points as :func:`_row` gives them, (n, width): at once for the usual all-number
    points of one length (a trail's ``[x, y, z]``), else point by point."""
    points = list(points)
    if not points:
        return np.zeros((0, width))
    a = None
    if all(type(p) is list and len(p) == len(points[0]) for p in points) \
            and not any(v is True or v is False for p in points for v in p):   # not numbers
        try:
            a = np.array(points)
        except (TypeError, ValueError):
            a = None
    if a is None or a.ndim != 2 or a.dtype.kind not in "if" or not 2 <= a.shape[1] <= width \
            or (width == _POINT_WIDTH and a.shape[1] != 3):
        return np.array([_row(p, width) for p in points], dtype=float).reshape(-1, width)
    rows = np.zeros((len(a), width))
    rows[:, :a.shape[1]] = a
    if width == _POINT_WIDTH:
        rows[:, 3:6] = -1.0                   # no colour of its own
    return rows


def _row(p, width: int) -> list[float]:
    """A point as ``width`` floats. A curve's point is ``[x, y, z]``, then its own colour
    (a list, or null) and radius where it has them, or ``[x, y, z, r, g, b, radius]``;
    as floats ``[x, y, z, r, g, b, radius]`` with r = -1 for no colour of its own and 0
    for no radius of its own (the object's, then). A series' point is ``[x, y]``."""
    p = list(p)
    if width == _POINT_WIDTH:
        color = p[3] if len(p) > 3 and (p[3] is None or isinstance(p[3], list)) else None
        if len(p) > 3 and (p[3] is None or isinstance(p[3], list)):
            p = p[:3] + (list(color) if color else [-1.0, -1.0, -1.0]) + p[4:5]
        elif len(p) == 3:
            p = p + [-1.0, -1.0, -1.0]
    row = [float(v) if _is_number(v) else 0.0 for v in p[:width]]
    return row + [0.0] * (width - len(row))


@dataclass
class _Object:
    id: int
    kind: str
    canvas: int
    born: int
    died: int | None = None
    attrs: dict[str, list[tuple[int, Any]]] = field(default_factory=dict)
    points: _Segments | None = None

    def set(self, frame: int, name: str, value: Any) -> None:
        timeline = self.attrs.setdefault(name, [])
        if timeline and timeline[-1][0] == frame:
            timeline[-1] = (frame, value)
        elif not timeline or timeline[-1][1] != value:
            timeline.append((frame, value))

    def encoded(self, buf: _Buffers) -> dict[str, Any]:
        numeric, other = {}, {}
        for name, timeline in self.attrs.items():
            dim = _numeric_dim([v for _, v in timeline])
            if dim:
                numeric[name] = _numeric_timeline(timeline, dim, buf)
            else:
                other[name] = [[f, v] for f, v in timeline]
        out = {"id": self.id, "kind": self.kind, "canvas": self.canvas, "born": self.born,
               "died": self.died, "n": numeric, "j": other}
        if self.points is not None:
            out["p"] = self.points.encoded(buf)
        return out


def _is_number(v: Any) -> bool:
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _numeric_dim(values: list) -> int:
    """3 if every value is a vector, 1 if every one is a number, else 0 (kept as JSON)."""
    if all(_is_number(v) for v in values):
        return 1
    if all(isinstance(v, list) and len(v) == 3 and all(map(_is_number, v)) for v in values):
        return 3
    return 0


def _numeric_timeline(timeline, dim: int, buf: _Buffers) -> list[int]:
    """[dim, float offset, count, dense, first frame or int offset] (module docstring)."""
    frames = [f for f, _ in timeline]
    flat = [float(x) for _, v in timeline for x in ([v] if dim == 1 else v)]
    at = buf.add_floats(flat, rows_of=dim)
    if frames == list(range(frames[0], frames[0] + len(frames))):
        return [dim, at, len(frames), 1, frames[0]]
    return [dim, at, len(frames), 0, buf.add_ints(frames)]


@dataclass
class _Replay:
    """The recording read through once, gathered per object, canvas and graph."""

    header: dict = field(default_factory=dict)
    times: list[float] = field(default_factory=list)
    objects: dict[int, _Object] = field(default_factory=dict)
    canvases: dict[int, dict[str, list]] = field(default_factory=dict)
    graphs: list[dict] = field(default_factory=list)
    series: dict[int, dict] = field(default_factory=dict)
    series_points: dict[int, _Segments] = field(default_factory=dict)
    printed: list[str] = field(default_factory=list)
    printed_at: list[list[int]] = field(default_factory=list)
    printed_len: int = 0
    printed_units: int = 0
    end: dict | None = None

    def frame(self, rec: dict) -> None:
        k = len(self.times)
        self.times.append(float(rec.get("t", k / max(self.header.get("fps", 25), 1))))
        for c in rec.get("canvases") or ():
            self._canvas(k, c)
        for o in rec.get("new") or ():
            self._new(k, o)
        for name, change in (rec.get("set") or {}).items():
            self._set(k, name, change)
        for oid, change in (rec.get("points") or {}).items():
            obj = self.objects.get(int(oid))
            if obj is not None:
                obj.points = obj.points or _Segments(_POINT_WIDTH)
                obj.points.change(k, change.get("reset"), change.get("drop", 0),
                                  change.get("append") or ())
        for oid in rec.get("deleted") or ():
            if int(oid) in self.objects:
                self.objects[int(oid)].died = k
        self._graphs(k, rec.get("graphs") or {})
        self._printed(k, rec.get("printed") or "")

    def _canvas(self, k: int, c: dict) -> None:
        timelines = self.canvases.setdefault(int(c["id"]), {})
        for name, value in c.items():
            if name == "id":
                continue
            if name in ("title", "caption") and value is not None:
                value = sanitize(value)
            timeline = timelines.setdefault(name, [])
            if timeline and timeline[-1][0] == k:
                timeline[-1] = [k, value]
            elif not timeline or timeline[-1][1] != value:
                timeline.append([k, value])

    def _new(self, k: int, o: dict) -> None:
        obj = _Object(int(o["id"]), str(o.get("kind", "")), int(o.get("canvas", 0)), k)
        self.objects[obj.id] = obj
        for name, value in o.items():
            if name in ("id", "kind", "canvas"):
                continue
            if name == "points" and obj.kind in ("curve", "points"):
                obj.points = _Segments(_POINT_WIDTH)
                obj.points.change(k, reset=value or [])
            else:
                obj.set(k, name, value)

    def _set(self, k: int, name: str, change: dict) -> None:
        ids = change.get("ids") or []
        if "f8" in change:           # numbers: exact float64s, NaN for an unset value
            values = [None if math.isnan(v) else v for v in numbers(change).tolist()]
        else:                        # booleans and text
            values = change.get("values") or []
        dim = 3 if ids and len(values) == 3 * len(ids) else 1
        for i, oid in enumerate(ids):
            obj = self.objects.get(int(oid))
            if obj is not None:
                value = values[3 * i:3 * i + 3] if dim == 3 else values[i]
                if dim == 3 and value == [None, None, None]:
                    value = None            # unset again (a label's colour: the canvas's)
                obj.set(k, name, value)

    def _graphs(self, k: int, g: dict) -> None:
        for item in g.get("new") or ():
            if item.get("kind") == "graph":
                self.graphs.append({key: _graph_value(key, v) for key, v in item.items()})
            else:
                self.series[int(item["id"])] = {key: _graph_value(key, v)
                                                for key, v in item.items()}
        for sid, flat in (g.get("reset") or {}).items():
            self._series(int(sid)).change(k, reset=_pairs(flat))
        for sid, flat in (g.get("data") or {}).items():
            self._series(int(sid)).change(k, append=_pairs(flat))

    def _series(self, sid: int) -> _Segments:
        return self.series_points.setdefault(sid, _Segments(_SERIES_WIDTH))

    def _printed(self, k: int, text: str) -> None:
        if not text or self.printed_len >= _PRINTED_LIMIT:
            return
        text = text[:_PRINTED_LIMIT - self.printed_len]
        self.printed.append(text)
        self.printed_len += len(text)
        # where the text shown at frame k ends, in JavaScript's units (UTF-16: an emoji is 2)
        self.printed_units += len(text.encode("utf-16-le")) // 2
        self.printed_at.append([k, self.printed_units])


def _graph_value(key: str, value: Any) -> Any:
    """A graph's or series' value, titles and labels as plain text (no markup)."""
    if key in ("title", "xtitle", "ytitle", "label") and isinstance(value, str):
        return _plain(value)
    return value


def _plain(markup: str) -> str:
    """The text of ``markup``: what could run dropped with its contents, then the tags,
    entities read (shown as text, never HTML)."""
    return plain_text(sanitize(markup))


def _pairs(flat) -> list[list[float]]:
    flat = list(flat or ())
    return [flat[i:i + 2] for i in range(0, len(flat) - 1, 2)]


def _texture_urls(objects: dict[int, _Object]) -> dict[str, str]:
    """VPython's own textures that objects use, as data: URLs (no file beside the page)."""
    urls = {}
    folder = resources.files("springscene").joinpath(_TEXTURES)
    for obj in objects.values():
        for _, name in obj.attrs.get("texture", ()):
            if isinstance(name, str) and name not in urls:
                # GlowScript's ":earth_texture.jpg" (textures.earth), or the name "earth"
                file = name[1:] if name.startswith(":") else f"{name}_texture.jpg"
                f = folder.joinpath(file)
                if "/" not in file and f.is_file():
                    urls[name] = ("data:image/jpeg;base64,"
                                  + base64.b64encode(f.read_bytes()).decode("ascii"))
    return urls


def replay_data(path: str | Path) -> dict[str, Any]:
    """The page's data for the recording at ``path`` (module docstring), as JSON values."""
    replay = _Replay()
    for rec in lines(Path(path)):
        if "format" in rec:
            replay.header = rec
        elif "end" in rec:
            replay.end = rec["end"]
        elif "frame" in rec:
            replay.frame(rec)
    if replay.end and replay.end.get("printed") and replay.times:
        replay._printed(len(replay.times) - 1, str(replay.end["printed"]))   # after the last frame
    buf = _Buffers()
    objects = [o.encoded(buf) for o in sorted(replay.objects.values(), key=lambda o: o.id)]
    series = [{**s, "p": replay._series(sid).encoded(buf)}
              for sid, s in sorted(replay.series.items())]
    left_out: dict[str, int] = {}
    for o in replay.objects.values():
        if o.kind not in DRAWN_KINDS:
            left_out[o.kind] = left_out.get(o.kind, 0) + 1
    return {
        "header": {k: replay.header.get(k) for k in ("program", "dialect", "fps",
                                                     "springscene", "version", "time_scale")},
        "times": replay.times, "end": _end(replay.end),
        "canvases": [{"id": cid, "t": tl} for cid, tl in sorted(replay.canvases.items())],
        "objects": objects, "graphs": replay.graphs, "series": series,
        "printed": "".join(replay.printed), "printed_at": replay.printed_at,
        "textures": _texture_urls(replay.objects), "left_out": left_out,
        **buf.encoded(),
    }


def _end(end: dict | None) -> dict | None:
    """The end line's summary (its names and globals are for readers, not the page)."""
    if end is None:
        return None
    return {**{k: end.get(k) for k in ("t", "frames", "ended")},
            "error": _error_text(end.get("error"))}


def _error_text(error: Any) -> str | None:
    """The program's error as the page shows it under the canvas (as text): its traceback,
    as Python prints it, and the program time the replay ends at."""
    if not isinstance(error, dict):
        return None if error is None else str(error)
    told = error.get("traceback") or f"{error.get('type', 'Error')}: {error.get('message', '')}"
    t = error.get("t")
    return told if not isinstance(t, (int, float)) else (
        f"{told}\n\n(the program stopped here, at t = {t:.2f} s)")
