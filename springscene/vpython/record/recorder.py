"""The recording of a run, written as the program runs: one JSON line a frame.

:class:`Recorder` is called at each frame the video takes (the run's
:class:`..core.runtime.Timeline`), reads every canvas, object, light and graph, and writes
what changed since the frame before (docs/recording.md). Per kind of object it keeps the
last recorded values as one row of floats an object and compares whole arrays, so a frame
of a thousand spheres costs a few array operations, not a thousand comparisons; what it
holds is that one row an object (and each curve's point count), never the frames before.
"""

from __future__ import annotations

import contextlib
import gzip
import io
import itertools
import json
import math
import operator
from pathlib import Path
from typing import Any

import numpy as np

from ...errors import OutputError
from ..api.graphs import GraphSeries, graph, graphs
from ..core.canvases import canvases
from ..core.vectors import vector
from .fields import POINT_KINDS, Schema, schema_of

__all__ = ["Recorder", "FORMAT", "VERSION", "json_value"]

FORMAT = "springscene-recording"
VERSION = 1
_PRINTED_LIMIT = 1 << 20        # characters of printed text kept between two frames


def json_value(v: Any) -> Any:
    """A program's value as JSON: vectors as [x, y, z], numbers as they are; None for
    what has no JSON form."""
    if v is None or isinstance(v, (bool, str)):
        return v
    if isinstance(v, vector):
        return list(v._xyz())
    if isinstance(v, (int, float, np.integer, np.floating)):
        f = float(v)
        if isinstance(v, (int, np.integer)) and not isinstance(v, bool):
            return int(v)
        return f if math.isfinite(f) else None
    if isinstance(v, dict):           # a texture given as a dictionary: its file
        return json_value(v.get("file"))
    if isinstance(v, (tuple, list)) and len(v) == 3:
        try:
            return [float(c) for c in v]
        except (TypeError, ValueError):
            return None
    return str(v)


def _floats(values: np.ndarray) -> list:
    """A float array as JSON numbers (non-finite ones as null)."""
    out = values.tolist()
    if not np.isfinite(values).all():
        out = [x if math.isfinite(x) else None for x in out]
    return out


class _KindTable:
    """The last recorded values of every object of one kind: a row of floats each."""

    def __init__(self, schema: Schema) -> None:
        self.schema = schema
        self.rows = np.zeros((16, max(schema.width, 1)))
        self.free: list[int] = []
        self.used = 0
        self.other: dict[int, tuple] = {}        # row -> the non-numeric values

    def new_row(self) -> int:
        if self.free:
            return self.free.pop()
        if self.used == len(self.rows):
            self.rows = np.concatenate([self.rows, np.zeros_like(self.rows)])
        self.used += 1
        return self.used - 1

    def gather(self, objs: list) -> np.ndarray:
        """The numeric fields of ``objs`` as an (M, width) array."""
        M, schema = len(objs), self.schema
        out = np.empty((M, max(schema.width, 1)))
        for f, cols in zip(schema.numeric, schema.columns):
            get = operator.attrgetter(f.store)
            try:
                if f.type == "v":
                    flat = itertools.chain.from_iterable(get(o)._xyz() for o in objs)
                    out[:, cols] = np.fromiter(flat, float, count=3 * M).reshape(M, 3)
                else:
                    out[:, cols.start] = np.fromiter(map(get, objs), float, count=M)
            except (AttributeError, TypeError, ValueError):   # a kind without the field
                for i, o in enumerate(objs):
                    out[i, cols] = _one(getattr(o, f.store, None), f.type)
        return out

    def others(self, obj) -> tuple:
        return tuple(json_value(getattr(obj, f.store, None)) for f in self.schema.other)


def _one(v: Any, kind: str):
    if v is None:
        return math.nan
    if kind == "v":
        try:
            return v._xyz()
        except AttributeError:
            return math.nan
    try:
        return float(v)
    except (TypeError, ValueError):
        return math.nan


def _point(p: dict) -> list:
    """A curve's point: [x, y, z], then its own colour and radius where it has them."""
    out = list(p["pos"]._xyz())
    color, radius = p.get("color"), p.get("radius")
    if color is not None or radius is not None:
        out.append(list(color._xyz()) if color is not None else None)
    if radius is not None:
        out.append(float(radius))
    return out


class Recorder:
    """Writes a run's recording to ``path`` (gzip-compressed when it ends in ``.gz``).

    Call :meth:`take` at each frame, :meth:`printed` with what the program prints, and
    :meth:`close` at the end (with the end's facts).
    """

    def __init__(self, path: Path, fps: int, program: str = "", dialect: str = "",
                 version: str = "") -> None:
        self.path, self.fps = Path(path), fps
        try:
            raw = open(self.path, "wb")
        except OSError as exc:
            raise OutputError(f"{self.path}: cannot write the recording "
                              f"({exc.strerror or exc})") from None
        self._file = (io.TextIOWrapper(gzip.GzipFile(fileobj=raw, mode="wb", mtime=0),
                                       encoding="utf-8")
                      if self.path.suffix == ".gz" else io.TextIOWrapper(raw, encoding="utf-8"))
        self._raw = raw
        self.frames = 0
        self._ids: dict[int, tuple[int, str, int]] = {}   # id(obj) -> (record id, kind, row)
        self._objs: dict[int, Any] = {}                   # id(obj) -> obj (kept: ids unique)
        self._tables: dict[str, _KindTable] = {}
        self._points: dict[int, tuple[int, int, int]] = {}  # record id -> version, appended, n
        self._next = 0
        self._canvas_ids: dict[int, int] = {}
        self._canvas_state: dict[int, dict] = {}
        self._graph_ids: dict[int, int] = {}
        self._series: dict[int, tuple[int, int, int]] = {}  # id(series) -> (id, n, from)
        self._graph_next = 0                                 # graphs and series share ids
        self._printed: list[str] = []
        self._printed_size = 0
        self.record_ids: dict[int, int] = {}      # id(obj) -> record id, for the end's names
        self._write({"format": FORMAT, "version": VERSION, "springscene": version,
                     "program": program, "dialect": dialect, "fps": fps})

    # -- what the program does between frames ----------------------------------------------

    def printed(self, text: str) -> None:
        if self._printed_size < _PRINTED_LIMIT:
            self._printed.append(text[:_PRINTED_LIMIT - self._printed_size])
            self._printed_size += len(self._printed[-1])

    # -- a frame -------------------------------------------------------------------------

    def take(self) -> None:
        """Record the scene as it is now, as frame ``frames`` at ``frames / fps`` s."""
        line: dict[str, Any] = {"frame": self.frames, "t": self.frames / self.fps}
        cvs = self._canvases()
        if cvs:
            line["canvases"] = cvs
        new, sets, deleted, pts = self._objects()
        if new:
            line["new"] = new
        if sets:
            line["set"] = sets
        if pts:
            line["points"] = pts
        if deleted:
            line["deleted"] = deleted
        g = self._graphs()
        if g:
            line["graphs"] = g
        if self._printed:
            line["printed"] = "".join(self._printed)
            self._printed, self._printed_size = [], 0
        self._write(line)
        self.frames += 1

    def _canvases(self) -> list[dict]:
        out = []
        for cv in canvases():
            cid = self._canvas_ids.setdefault(id(cv), len(self._canvas_ids))
            now = {"width": int(cv.width), "height": int(cv.height),
                   "background": json_value(cv._background),
                   "foreground": json_value(cv._foreground),
                   "ambient": json_value(cv._ambient), "title": cv._title,
                   "caption": cv._caption, "visible": bool(cv._visible),
                   "fov": float(cv.fov), "userzoom": bool(cv.userzoom),
                   "userspin": bool(cv.userspin), "userpan": bool(cv.userpan),
                   "center": json_value(cv._center), "forward": json_value(cv._forward),
                   "up": json_value(cv._up), "range": float(cv._range_now()),
                   "autoscale": bool(cv._autoscale),
                   "lights": [_light(lt) for lt in cv.lights if lt._visible]}
            before = self._canvas_state.get(cid)
            changed = {k: v for k, v in now.items() if before is None or before.get(k) != v}
            if changed:
                out.append({"id": cid, **changed})
            self._canvas_state[cid] = now
        return out

    def _objects(self) -> tuple[list, dict, list, dict]:
        by_kind: dict[str, list] = {}
        seen = set()
        for cv in canvases():
            for o in cv._objects:
                key = id(o)
                if key in seen:
                    continue
                seen.add(key)
                kind = o._kind
                by_kind.setdefault(kind, []).append(o)
                if key not in self._ids:
                    self._objs[key] = o
                    self._ids[key] = (self._next, kind, -1)
                    self.record_ids[key] = self._next
                    self._next += 1
        new: list[dict] = []
        sets: dict[str, dict] = {}
        for kind, objs in by_kind.items():
            self._kind_frame(kind, objs, new, sets)
        deleted = []
        for key in [k for k in self._ids if k not in seen]:
            rid, kind, row = self._ids.pop(key)
            self._objs.pop(key, None)
            self._points.pop(rid, None)
            table = self._tables[kind]
            table.free.append(row)
            table.other.pop(row, None)
            deleted.append(rid)
        pts = {}
        for kind in POINT_KINDS:
            for o in by_kind.get(kind, ()):
                change = self._point_change(o)
                if change:
                    pts[str(self._ids[id(o)][0])] = change
        return new, sets, deleted, pts

    def _kind_frame(self, kind: str, objs: list, new: list, sets: dict) -> None:
        table = self._tables.get(kind)
        if table is None:
            table = self._tables[kind] = _KindTable(schema_of(kind))
        schema = table.schema
        cur = table.gather(objs)
        rows = np.empty(len(objs), dtype=np.int64)
        rids = np.empty(len(objs), dtype=np.int64)
        fresh = []
        for i, o in enumerate(objs):
            rid, _, row = self._ids[id(o)]
            if row < 0:
                row = table.new_row()
                self._ids[id(o)] = (rid, kind, row)
                fresh.append(i)
            rows[i], rids[i] = row, rid
        old = np.ones(len(objs), dtype=bool)
        old[fresh] = False
        for i in fresh:
            o = objs[i]
            rec = {"id": int(rids[i]), "kind": kind,
                   "canvas": self._canvas_ids[id(o._canvas)]}
            for f, cols in zip(schema.numeric, schema.columns):
                v = cur[i, cols]
                rec[f.name] = (_floats(v) if f.type == "v" else
                               (bool(v[0]) if f.type == "b" and math.isfinite(v[0])
                                else _floats(v)[0]))
            others = table.others(o)
            for f, v in zip(schema.other, others):
                rec[f.name] = v
            table.other[int(rows[i])] = others
            new.append(rec)
        if old.any():
            o_rows, o_cur = rows[old], cur[old]
            prev = table.rows[o_rows]
            differ = (o_cur != prev) & ~(np.isnan(o_cur) & np.isnan(prev))
            if differ.any():
                o_rids = rids[old]
                for f, cols in zip(schema.numeric, schema.columns):
                    mask = differ[:, cols].any(axis=1)
                    if not mask.any():
                        continue
                    entry = sets.setdefault(f.name, {"ids": [], "values": []})
                    entry["ids"].extend(o_rids[mask].tolist())
                    vals = o_cur[mask][:, cols].ravel()
                    entry["values"].extend([bool(x) for x in vals] if f.type == "b"
                                           else _floats(vals))
            if schema.other:
                for i in np.flatnonzero(old):
                    o, row = objs[i], int(rows[i])
                    others = table.others(o)
                    before = table.other.get(row)
                    if others != before:
                        for f, v, b in zip(schema.other, others, before or (None,) * len(others)):
                            if v != b or before is None:
                                entry = sets.setdefault(f.name, {"ids": [], "values": []})
                                entry["ids"].append(int(rids[i]))
                                entry["values"].append(v)
                        table.other[row] = others
        table.rows[rows] = cur

    def _point_change(self, o) -> dict | None:
        rid = self._ids[id(o)][0]
        pts = o._pts
        version, appended, n = o._version, o._appended, len(pts)
        before = self._points.get(rid)
        self._points[rid] = (version, appended, n)
        if before is None or before[0] != version:
            return {"reset": [_point(p) for p in pts]} if (pts or before is not None) else None
        added = appended - before[1]
        if added == 0 and n == before[2]:
            return None
        if added > n or before[2] + added - n < 0:      # more appended than kept: all anew
            return {"reset": [_point(p) for p in pts]}
        change: dict[str, Any] = {}
        dropped = before[2] + added - n
        if dropped:
            change["drop"] = dropped
        if added:
            change["append"] = [_point(p) for p in pts[n - added:]]
        return change

    def _graphs(self) -> dict:
        new, data, reset = [], {}, {}
        for g in graphs():
            if id(g) not in self._graph_ids:
                gid = self._graph_ids[id(g)] = self._graph_next
                self._graph_next += 1
                new.append(_graph_record(g, gid))
            for s in g.series:
                key = id(s)
                if key not in self._series:
                    sid = self._graph_next
                    self._graph_next += 1
                    self._series[key] = (sid, 0, 0)
                    new.append(_series_record(s, sid, self._graph_ids[id(g)]))
                sid, n, start = self._series[key]
                if s._shown_from != start or s._n < n:
                    reset[str(sid)] = _floats(s._buf[s._shown_from:s._n].ravel())
                elif s._n > n:
                    data[str(sid)] = _floats(s._buf[n:s._n].ravel())
                self._series[key] = (sid, s._n, s._shown_from)
        out: dict[str, Any] = {}
        if new:
            out["new"] = new
        if data:
            out["data"] = data
        if reset:
            out["reset"] = reset
        return out

    # -- the end -------------------------------------------------------------------------

    def close(self, end: dict) -> None:
        """Write the end line (docs/recording.md) and close the file; what the program
        printed after the last frame (its result, printed once the loop is done) goes in
        the end line's ``printed``."""
        if self._printed:
            end = {**end, "printed": "".join(self._printed)}
            self._printed, self._printed_size = [], 0
        self._write({"end": end})
        self._close()

    def discard(self) -> None:
        """Close the file if :meth:`close` was not reached (a run that ended in an error;
        the run's output handling removes the file)."""
        if not self._file.closed:
            with contextlib.suppress(OSError):
                self._file.close()

    def _close(self) -> None:
        try:
            self._file.close()
        except OSError as exc:
            raise OutputError(f"{self.path}: cannot write the recording "
                              f"({exc.strerror or exc})") from None

    def _write(self, line: dict) -> None:
        try:
            self._file.write(json.dumps(line, separators=(",", ":"), allow_nan=False))
            self._file.write("\n")
        except OSError as exc:
            raise OutputError(f"{self.path}: cannot write the recording "
                              f"({exc.strerror or exc})") from None

    def names(self, namespace: dict) -> tuple[dict, dict]:
        """The program's global names that hold recorded objects (or lists of them), and
        its global numbers, booleans and vectors (the end's ``names`` and ``globals``)."""
        names: dict[str, Any] = {}
        values: dict[str, Any] = {}
        for name, v in namespace.items():
            if name.startswith("__"):
                continue
            rid = self.record_ids.get(id(v))
            if rid is not None and self._objs.get(id(v)) is v:
                names[name] = rid
            elif isinstance(v, (list, tuple)) and v and len(v) <= 100_000:
                ids = [self.record_ids.get(id(x)) for x in v]
                if all(i is not None for i in ids):
                    names[name] = ids
            elif isinstance(v, (bool, int, float, vector, np.floating, np.integer)):
                value = json_value(v)
                if value is not None:
                    values[name] = value
        return names, values


def _light(lt) -> dict:
    if hasattr(lt, "_direction"):
        return {"kind": "distant_light", "direction": json_value(lt._direction),
                "color": json_value(lt._color)}
    return {"kind": "local_light", "pos": json_value(lt._pos), "color": json_value(lt._color)}


def _graph_record(g: graph, gid: int) -> dict:
    return {"id": gid, "kind": "graph", "title": g.title, "xtitle": g.xtitle,
            "ytitle": g.ytitle, "width": g.width, "height": g.height,
            "xmin": json_value(g.xmin), "xmax": json_value(g.xmax),
            "ymin": json_value(g.ymin), "ymax": json_value(g.ymax), "logx": g.logx,
            "logy": g.logy, "background": json_value(g.background),
            "foreground": json_value(g.foreground)}


_SERIES_KIND = {"gcurve": "gcurve", "gdots": "gdots", "gvbars": "gvbars", "ghbars": "ghbars"}


def _series_record(s: GraphSeries, sid: int, gid: int) -> dict:
    return {"id": sid, "kind": _SERIES_KIND.get(type(s).__name__, "gcurve"), "graph": gid,
            "label": s.label, "color": json_value(s._color), "width": s.width,
            "radius": s.radius, "dot": s.dot, "markers": s.markers,
            "visible": s._visible}
