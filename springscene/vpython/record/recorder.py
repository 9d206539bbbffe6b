"""The recording of a run, written as the program runs: one JSON line a frame.

:class:`Recorder` is called at each frame the video takes (the run's
:class:`..core.runtime.Timeline`), reads every canvas, object, light and graph, and writes
what changed since the frame before (docs/recording.md). Per kind of object it keeps the
last recorded values as one row of floats an object and compares whole arrays, so a frame
of a thousand spheres costs a few array operations, not a thousand comparisons; what it
holds is that one row an object (and each curve's point count), never the frames before.
"""

from __future__ import annotations

import base64
import contextlib
import errno
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
from ...video import reason_of
from ..api.graphs import GraphSeries, graph, graphs
from ..core.canvases import canvases
from ..core.vectors import vector
from ..objects import frames
from .fields import POINT_KINDS, Schema, schema_of

__all__ = ["Recorder", "FORMAT", "VERSION", "json_value"]

FORMAT = "springscene-recording"
VERSION = 1
PRINTED_LIMIT = 1 << 20         # characters of printed text kept between two frames (and shown)
_UNSEEN = object()              # a value not read yet (the object is new to its group)


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
        # every numeric field of an object in one C-level getter: a vector's as its three
        # components ("_pos._x", ...), in the row's order
        paths = []
        for f in schema.numeric:
            paths.extend([f"{f.store}._{c}" for c in "xyz"] if f.type == "v" else [f.store])
        self._row_of = operator.attrgetter(*paths) if len(paths) > 1 else None
        self.field_starts = np.array([c.start for c in schema.columns] or [0], dtype=np.intp)
        self.visible_col = next((cols.start for f, cols in zip(schema.numeric, schema.columns)
                                 if f.name == "visible"), None)
        # a moving object's position alone, with its count of other changes (``_looks``)
        self.pos_cols = next((cols for f, cols in zip(schema.numeric, schema.columns)
                              if f.name == "pos" and f.store == "_pos"), None)
        self._pos_looks = operator.attrgetter("_pos._x", "_pos._y", "_pos._z", "_looks")

    def new_row(self) -> int:
        if self.free:
            return self.free.pop()
        if self.used == len(self.rows):
            self.rows = np.concatenate([self.rows, np.zeros_like(self.rows)])
        self.used += 1
        return self.used - 1

    def gather(self, objs: list) -> np.ndarray:
        """The numeric fields of ``objs`` as an (M, width) array, read in one pass."""
        M, width = len(objs), max(self.schema.width, 1)
        if self._row_of is not None:
            try:
                flat = itertools.chain.from_iterable(map(self._row_of, objs))
                return np.fromiter(flat, float, count=width * M).reshape(M, width)
            except (AttributeError, TypeError, ValueError):   # a kind without some field
                pass
        out = np.empty((M, width))
        for f, cols in zip(self.schema.numeric, self.schema.columns):
            for i, o in enumerate(objs):
                out[i, cols] = _one(getattr(o, f.store, None), f.type)
        return out

    def read(self, group: "_Group") -> np.ndarray:
        """The group's numeric fields now, as :meth:`gather` reads them, but read in full
        only for objects made since the last frame or whose ``_looks`` moved: of the
        others only the position is read, the rest is as last recorded (what
        :meth:`..objects.base._Base._touch` promises: any other change counts)."""
        objs = group.objs
        if not group.apart:
            return self.gather(objs)
        M = len(objs)
        now = np.fromiter(itertools.chain.from_iterable(map(self._pos_looks, objs)), float,
                          count=4 * M).reshape(M, 4)
        looks, before = now[:, 3], group.looks
        group.looks = looks
        if before is None:
            return self.gather(objs)
        cur = self.rows[group.rows]
        cur[:, self.pos_cols] = now[:, :3]
        stale = np.flatnonzero((looks != before) | group.fresh)
        if len(stale):
            cur[stale] = self.gather([objs[i] for i in stale])
        return cur


class _Group:
    """The objects of one kind on one canvas, as the last frame had them: their rows in
    the kind's table, record ids, and their non-numeric values."""

    def __init__(self, objs: list, rows: np.ndarray, rids: np.ndarray, fresh: np.ndarray,
                 table: _KindTable) -> None:
        self.objs, self.rows, self.rids, self.fresh = objs, rows, rids, fresh
        self.getters = [operator.attrgetter(f.store) for f in table.schema.other]
        self.others: list[list | None] = [None] * len(table.schema.other)
        # read position apart (:meth:`_KindTable.read`): objects that count their other
        # changes (``_looks_counted``: every solid but 3D text, whose facing turns with the
        # camera, and VPython 6's extrusion, whose arrays change in place)
        self.apart = table.pos_cols is not None and all(
            getattr(t, "_looks_counted", False) for t in set(map(type, objs)))
        self.looks: np.ndarray | None = None       # each object's ``_looks`` as last read


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


def _records(kind: str, cid: int, schema: Schema, rids: list, block: np.ndarray, objs: list,
             getters: list) -> list[dict]:
    """The "new" entries of objects just made: their ids and all their fields, from their
    rows of numbers (``block``) and their other values. A number not finite is null, and
    so is a vector with no finite component (a label's unset colour)."""
    fields = [(f.name, c.start, c.stop, f.type) for f, c in zip(schema.numeric, schema.columns)]
    finite = np.isfinite(block).all(axis=1)
    out = []
    for rid, row, ok, o in zip(rids, block.tolist(), finite.tolist(), objs):
        rec = {"id": rid, "kind": kind, "canvas": cid}
        if ok:
            for name, a, b, t in fields:
                rec[name] = row[a:b] if t == "v" else bool(row[a]) if t == "b" else row[a]
        else:
            row = [x if math.isfinite(x) else None for x in row]
            for name, a, b, t in fields:
                v = row[a:b]
                rec[name] = ((v if any(x is not None for x in v) else None) if t == "v"
                             else v[0] if t == "f" or v[0] is None else bool(v[0]))
        for f, get in zip(schema.other, getters):
            rec[f.name] = json_value(get(o))
        out.append(rec)
    return out


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
                 version: str = "", max_objects: int | None = None,
                 time_scale: float | None = None) -> None:
        self.path, self.fps = Path(path), fps
        # a recording made only for a page gives up past this many objects (``gave_up``):
        # the page would be too heavy for a browser, and its making for the run's memory
        self.max_objects, self.gave_up = max_objects, False
        try:
            raw = open(self.path, "wb")
        except OSError as exc:
            raise OutputError(reason_of(exc), self.path, exc.errno or errno.EIO) from None
        self._file = (io.TextIOWrapper(gzip.GzipFile(fileobj=raw, mode="wb", mtime=0),
                                       encoding="utf-8")
                      if self.path.suffix == ".gz" else io.TextIOWrapper(raw, encoding="utf-8"))
        self._raw = raw
        self.frames = 0
        self._ids: dict[int, tuple[int, str, int]] = {}   # id(obj) -> (record id, kind, row)
        self._objs: dict[int, Any] = {}                   # id(obj) -> obj (kept: ids unique)
        self._tables: dict[str, _KindTable] = {}
        self._layout: dict[int, tuple] = {}        # canvas id -> (object ids, groups by kind)
        self._points: dict[int, tuple[int, int, int]] = {}  # record id -> version, appended, n
        self._next = 0
        self._canvas_ids: dict[int, int] = {}
        self._canvas_state: dict[int, dict] = {}
        self._graph_ids: dict[int, int] = {}
        self._series: dict[int, tuple[int, int, int]] = {}  # id(series) -> (id, n, from)
        self._graph_next = 0                                 # graphs and series share ids
        self._printed: list[str] = []
        self._printed_size = 0
        header = {"format": FORMAT, "version": VERSION, "springscene": version,
                  "program": program, "dialect": dialect, "fps": fps}
        if time_scale is not None and time_scale != 1:
            header["time_scale"] = time_scale     # program seconds a second of playing
        self._write(header)

    # -- what the program does between frames ----------------------------------------------

    def printed(self, text: str) -> None:
        if self._printed_size < PRINTED_LIMIT:
            self._printed.append(text[:PRINTED_LIMIT - self._printed_size])
            self._printed_size += len(self._printed[-1])

    # -- a frame -------------------------------------------------------------------------

    def take(self, t: float | None = None) -> None:
        """Record the scene as it is now, as frame ``frames`` at ``t`` (default: the
        frame's time on the video's clock, ``frames / fps`` s)."""
        if self.gave_up:
            return
        if self.max_objects is not None and sum(
                len(cv._objects) for cv in canvases()) > self.max_objects:
            self.gave_up = True            # what is held goes; the file is the run's to remove
            self._tables, self._layout, self._objs, self._ids = {}, {}, {}, {}
            return
        line: dict[str, Any] = {"frame": self.frames,
                                "t": self.frames / self.fps if t is None else t}
        cvs = self._canvases()
        if cvs:
            line["canvases"] = cvs
        new, sets, deleted, pts = self._objects()
        if new:
            line["new"] = new
        if sets:
            for entry in sets.values():
                if "f8" in entry:
                    entry["f8"] = base64.b64encode(
                        np.concatenate(entry["f8"]).astype("<f8").tobytes()).decode("ascii")
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
        new: list[dict] = []
        sets: dict[str, dict] = {}
        deleted: list[int] = []
        pts = {}
        for cv in canvases():
            cid = self._canvas_ids[id(cv)]
            ids = np.fromiter(map(id, cv._objects), np.int64, count=len(cv._objects))
            layout = self._layout.get(cid)
            if layout is None or not np.array_equal(layout[0], ids):
                layout = self._layout[cid] = (ids, self._regroup(cv, cid, layout, deleted))
            framed = frames.frame.made > 0 and any(
                getattr(o, "_frame", None) is not None for o in cv._objects)
            with frames.in_world(cv._objects) if framed else contextlib.nullcontext():
                for kind, group in layout[1].items():
                    self._kind_frame(kind, group, cid, new, sets, framed)
                    if kind in POINT_KINDS:
                        for o, rid in zip(group.objs, group.rids.tolist()):
                            change = self._point_change(o, rid)
                            if change:
                                pts[str(rid)] = change
        return new, sets, deleted, pts

    def _regroup(self, cv, cid: int, layout, deleted: list) -> dict[str, _Group]:
        """The canvas's objects by kind, after objects were made or deleted: new ones get
        a record id and a row, deleted ones free theirs (and are listed in ``deleted``)."""
        by_kind: dict[str, list] = {}
        now = set()
        for o in cv._objects:
            if id(o) in now:
                continue
            now.add(id(o))
            by_kind.setdefault(o._kind, []).append(o)
        if layout is not None:
            for key in set(layout[0].tolist()) - now:
                found = self._ids.pop(key, None)
                if found is None:
                    continue
                rid, kind, row = found
                self._objs.pop(key, None)
                self._points.pop(rid, None)
                self._tables[kind].free.append(row)
                deleted.append(rid)
        groups = {}
        for kind, objs in by_kind.items():
            table = self._tables.get(kind)
            if table is None:
                table = self._tables[kind] = _KindTable(schema_of(kind))
            rows = np.empty(len(objs), dtype=np.int64)
            rids = np.empty(len(objs), dtype=np.int64)
            fresh = np.zeros(len(objs), dtype=bool)
            for i, o in enumerate(objs):
                key = id(o)
                if key not in self._ids:
                    self._objs[key] = o
                    self._ids[key] = (self._next, kind, table.new_row())
                    self._next += 1
                    fresh[i] = True
                rids[i], _, rows[i] = self._ids[key]
            group = groups[kind] = _Group(objs, rows, rids, fresh, table)
            old = (layout[1].get(kind) if layout is not None else None)
            if old is not None:      # the values of the objects that were there before
                at = {r: j for j, r in enumerate(old.rids.tolist())}
                for n, before in enumerate(old.others):
                    if before is not None:
                        group.others[n] = [before[at[r]] if r in at else _UNSEEN
                                           for r in rids.tolist()]
                if old.looks is not None and group.apart:     # new objects: read in full
                    group.looks = np.array([old.looks[at[r]] if r in at else math.nan
                                            for r in rids.tolist()])
        return groups

    def _kind_frame(self, kind: str, group: _Group, cid: int, new: list, sets: dict,
                    framed: bool = False) -> None:
        table = self._tables[kind]
        schema = table.schema
        objs, rows, rids, fresh = group.objs, group.rows, group.rids, group.fresh
        if framed:       # in world coordinates, only for this frame: all read anew
            cur, group.looks = table.gather(objs), None
        else:
            cur = table.read(group)
        if framed and table.visible_col is not None:   # VPython 6: a hidden frame hides
            hidden = np.fromiter(map(frames.hidden, objs), bool, count=len(objs))
            cur[hidden, table.visible_col] = 0.0
        born = np.flatnonzero(fresh)
        if len(born):
            new.extend(_records(kind, cid, schema, rids[born].tolist(), cur[born],
                                [objs[i] for i in born.tolist()], group.getters))
        old = ~fresh
        some_fresh = bool(fresh.any())
        if not some_fresh or old.any():
            o_rows, o_cur, o_rids = ((rows[old], cur[old], rids[old]) if some_fresh
                                     else (rows, cur, rids))
            prev = table.rows[o_rows]
            differ = o_cur != prev
            unset = np.isnan(o_cur)             # an unset value (a label's colour) stays
            if unset.any():
                differ &= ~(unset & np.isnan(prev))
            changed = differ.any(axis=0)
            if changed.any():
                # the fields that changed, then each one's rows
                for n in np.flatnonzero(np.logical_or.reduceat(changed, table.field_starts)):
                    f, cols = schema.numeric[n], schema.columns[n]
                    mask = differ[:, cols].any(axis=1)
                    vals = o_cur[mask][:, cols].ravel()
                    if f.type == "b":
                        entry = sets.setdefault(f.name, {"ids": [], "values": []})
                        entry["values"].extend(bool(x) for x in vals)
                    else:     # numbers as binary: exact, and 20x quicker to write than text
                        entry = sets.setdefault(f.name, {"ids": [], "f8": []})
                        entry["f8"].append(vals)
                    entry["ids"].extend(o_rids[mask].tolist())
        for n, (f, get) in enumerate(zip(schema.other, group.getters)):
            values = list(map(get, objs))
            before = group.others[n]
            if before is not None and values != before:
                for i, (v, b) in enumerate(zip(values, before)):
                    if not fresh[i] and (b is _UNSEEN or v != b):
                        entry = sets.setdefault(f.name, {"ids": [], "values": []})
                        entry["ids"].append(int(rids[i]))
                        entry["values"].append(json_value(v))
            group.others[n] = values
        table.rows[rows] = cur
        if fresh.any():
            group.fresh = np.zeros(len(objs), dtype=bool)

    def _point_change(self, o, rid: int) -> dict | None:
        pts = o._pts
        version, appended, n = o._edits, o._appended, len(pts)
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
        with contextlib.suppress(OSError):
            self._raw.close()

    def _close(self) -> None:
        try:
            self._file.close()       # a GzipFile leaves the file under it open
            self._raw.close()
        except OSError as exc:
            raise OutputError(reason_of(exc), self.path, exc.errno or errno.EIO) from None

    def _write(self, line: dict) -> None:
        try:
            self._file.write(json.dumps(line, separators=(",", ":"), allow_nan=False))
            self._file.write("\n")
        except OSError as exc:
            raise OutputError(reason_of(exc), self.path, exc.errno or errno.EIO) from None

    def _record_id(self, obj) -> int | None:
        """``obj``'s record id, if it is a recorded object still on its canvas."""
        found = self._ids.get(id(obj))
        return found[0] if found is not None and self._objs.get(id(obj)) is obj else None

    def names(self, namespace: dict) -> tuple[dict, dict]:
        """The program's global names that hold recorded objects (or lists of them), and
        its global numbers, booleans and vectors (the end's ``names`` and ``globals``)."""
        names: dict[str, Any] = {}
        values: dict[str, Any] = {}
        for name, v in namespace.items():
            if name.startswith("__"):
                continue
            rid = self._record_id(v)
            if rid is not None:
                names[name] = rid
            elif isinstance(v, (list, tuple)) and v and len(v) <= 100_000:
                ids = [self._record_id(x) for x in v]
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
