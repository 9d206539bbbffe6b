"""A recording read back as numpy arrays over its frames (docs/recording.md).

:func:`read` gives a :class:`Recording`: its ``times``, its objects by id, kind and the
program's own variable names (``rec["ball"]``), each object's attributes as arrays over
the frames (``rec["ball"].pos`` is ``(frames, 3)``, NaN where the object did not exist
yet or any more), the state at a time (``rec.at(t)``), what was printed, the graphs'
points, the program's last global numbers and vectors, and the program's error when the
run ended in one (``rec.error``: its type, message, program time, line and traceback).

An attribute's array over all objects is made the first time any object's is asked for
(frames x objects x its width), by carrying each frame's changes forward.
"""

from __future__ import annotations

import base64
import bisect
import gzip
import json
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any, Iterator

import numpy as np

from ...errors import UserError
from .recorder import FORMAT, VERSION

__all__ = ["read", "lines", "numbers", "Recording", "Track", "Series", "Snapshot"]


def lines(path: Path) -> Iterator[dict]:
    """Each JSON line of a recording (header, frames, end; ``.gz`` through gzip): a line
    that is not JSON is a :class:`UserError` naming it, except the last one cut short (a
    run killed mid-line), where the lines before it are the recording."""
    opener = gzip.open if path.name.endswith(".gz") else open
    try:
        with opener(path, "rt", encoding="utf-8") as fh:
            for number, line in enumerate(fh, 1):
                if not line.strip():
                    continue
                try:
                    yield json.loads(line)
                except json.JSONDecodeError:
                    if line.endswith("\n"):
                        raise UserError(f"{path}, line {number}: not a JSON line") from None
                    return          # the last line cut short: a run that was killed
    except (OSError, EOFError) as exc:
        raise UserError(f"{path}: cannot read the recording "
                        f"({getattr(exc, 'strerror', None) or exc})") from None


def numbers(change: dict) -> np.ndarray:
    """A ``set`` entry's values as floats: ``f8`` (base64 of little-endian float64s) or a
    JSON list (booleans; null as NaN)."""
    if "f8" in change:
        return np.frombuffer(base64.b64decode(change["f8"]), dtype="<f8").astype(float)
    return np.array([np.nan if v is None else v for v in change["values"]], dtype=float)


@dataclass
class Series:
    """One graph series: its kind, label, colour, graph, and its points."""

    id: int
    kind: str
    label: str
    color: tuple
    graph: dict
    chunks: list = field(default_factory=list, repr=False)    # (frame, reset, flat xy)
    frames_seen: int = 0

    def points(self, frame: int | None = None) -> np.ndarray:
        """The (n, 2) points the graph showed at ``frame`` (default: the end)."""
        out = np.empty((0, 2))
        for f, reset, flat in self.chunks:
            if frame is not None and f > frame:
                break
            xy = np.asarray(flat, dtype=float).reshape(-1, 2)
            out = xy if reset else np.concatenate([out, xy])
        return out

    @property
    def data(self) -> np.ndarray:
        return self.points()


class Track:
    """One object over the run: ``kind``, ``id``, ``name`` and each recorded attribute as
    an array over the frames (``track.pos``: (frames, 3); a scalar's: (frames,))."""

    def __init__(self, recording: "Recording", record: dict, frame: int) -> None:
        self._rec = recording
        self.id: int = record["id"]
        self.kind: str = record["kind"]
        self.canvas: int = record.get("canvas", 0)
        self.born: int = frame
        self.deleted: int | None = None
        self.names: list[str] = []
        self.first = {k: v for k, v in record.items() if k not in ("id", "kind", "canvas")}
        self._points: list = []              # (frame, change) of a curve's point list

    @property
    def name(self) -> str | None:
        return self.names[0] if self.names else None

    def __repr__(self) -> str:
        return f"<{self.kind} {self.name or self.id}, frames {self.born}..>"

    def __getattr__(self, attribute: str) -> np.ndarray:
        if attribute.startswith("_") or attribute not in self.first:
            raise AttributeError(f"{self.kind} {self.name or self.id}: no recorded attribute "
                                 f"{attribute!r} (recorded: {', '.join(sorted(self.first))})")
        return self._rec._column(attribute)[:, self._rec._slot[self.id]]

    def attributes(self) -> list[str]:
        return sorted(self.first)

    def value(self, attribute: str, frame: int) -> Any:
        """The attribute at ``frame`` as the program had it (a list for a vector)."""
        v = getattr(self, attribute)[frame]
        return v.tolist() if isinstance(v, np.ndarray) else v

    def points(self, frame: int | None = None) -> np.ndarray:
        """A curve's or points object's (n, 3) point positions at ``frame`` (default: the
        end), in its own coordinates."""
        pts: list = []
        for f, change in self._points:
            if frame is not None and f > frame:
                break
            if "reset" in change:
                pts = list(change["reset"])
            pts = pts[change.get("drop", 0):]
            pts.extend(change.get("append", ()))
        return np.array([p[:3] for p in pts], dtype=float).reshape(-1, 3)


class Snapshot:
    """Every object at one frame: ``snap["ball"].pos``, ``snap.objects``."""

    def __init__(self, recording: "Recording", frame: int) -> None:
        self.recording, self.frame = recording, frame
        self.t = float(recording.times[frame])

    @property
    def objects(self) -> list["_State"]:
        return [_State(tr, self.frame) for tr in self.recording.objects
                if tr.born <= self.frame and (tr.deleted is None or tr.deleted > self.frame)]

    def __getitem__(self, name: str):
        found = self.recording[name]
        if isinstance(found, list):
            return [_State(tr, self.frame) for tr in found]
        return _State(found, self.frame)

    def __repr__(self) -> str:
        return f"<frame {self.frame} at t = {self.t:g} s, {len(self.objects)} objects>"


class _State:
    def __init__(self, track: Track, frame: int) -> None:
        self._track, self._frame = track, frame
        self.kind, self.id, self.name = track.kind, track.id, track.name

    def __getattr__(self, attribute: str):
        if attribute.startswith("_"):
            raise AttributeError(attribute)
        v = getattr(self._track, attribute)[self._frame]
        return v if isinstance(v, np.ndarray) else (v.item() if hasattr(v, "item") else v)

    def __repr__(self) -> str:
        return f"<{self.kind} {self.name or self.id} at frame {self._frame}>"


class Recording:
    """A recording read whole; see the module's docstring."""

    def __init__(self, path: Path) -> None:
        self.path = Path(path)
        lines_ = lines(self.path)
        header = next(lines_, None)
        if not isinstance(header, dict) or header.get("format") != FORMAT:
            raise UserError(f"{self.path}: not a springscene recording")
        if header.get("version", 0) > VERSION:
            raise UserError(f"{self.path}: a recording of version {header['version']}; this "
                            f"springscene reads version {VERSION} (upgrade springscene)")
        self.header = header
        self.fps: int = header["fps"]
        self.program: str = header.get("program", "")
        self.dialect: str = header.get("dialect", "")
        self.objects: list[Track] = []
        self._by_id: dict[int, Track] = {}
        self._slot: dict[int, int] = {}
        self._sets: list[tuple[int, dict]] = []      # (frame, "set")
        self._times: list[float] = []
        self._printed: list[tuple[int, str]] = []
        self.canvases: list[dict] = []              # each canvas's attributes at the end
        self._canvas_changes: list[tuple[int, dict]] = []
        self.series: list[Series] = []
        self.graphs: list[dict] = []
        self.end: dict | None = None
        self._columns: dict[str, np.ndarray] = {}
        for line in lines_:
            if "end" in line:
                self.end = line["end"]
                if self.end.get("printed"):           # printed after the last frame
                    self._printed.append((len(self._times), self.end["printed"]))
                break
            self._frame(line)
        self.times = np.asarray(self._times, dtype=float)
        self.names: dict[str, Any] = {}
        for name, held in (self.end or {}).get("names", {}).items():
            if isinstance(held, list):
                self.names[name] = [self._by_id[i] for i in held if i in self._by_id]
            elif held in self._by_id:
                self.names[name] = self._by_id[held]
                self._by_id[held].names.append(name)
        self.globals: dict[str, Any] = {
            k: (np.asarray(v, dtype=float) if isinstance(v, list) else v)
            for k, v in (self.end or {}).get("globals", {}).items()}
        # the program's own error the run ended at: type, message, t, line, traceback
        self.error: dict | None = (self.end or {}).get("error")

    def _frame(self, line: dict) -> None:
        f = line["frame"]
        self._times.append(line["t"])
        for cv in line.get("canvases", ()):
            cid = cv["id"]
            while len(self.canvases) <= cid:
                self.canvases.append({})
            self.canvases[cid].update({k: v for k, v in cv.items() if k != "id"})
            self._canvas_changes.append((f, cv))
        for record in line.get("new", ()):
            tr = Track(self, record, f)
            self._slot[tr.id] = len(self.objects)
            self.objects.append(tr)
            self._by_id[tr.id] = tr
        if "set" in line:
            self._sets.append((f, line["set"]))
        for rid, change in line.get("points", {}).items():
            self._by_id[int(rid)]._points.append((f, change))
        for rid in line.get("deleted", ()):
            self._by_id[rid].deleted = f
        g = line.get("graphs")
        if g:
            for item in g.get("new", ()):
                if item["kind"] == "graph":
                    self.graphs.append(item)
                else:
                    graph = next((x for x in self.graphs if x["id"] == item["graph"]), {})
                    self.series.append(Series(item["id"], item["kind"], item.get("label", ""),
                                              tuple(item.get("color") or (0, 0, 0)), graph))
            by_id = {s.id: s for s in self.series}
            for sid, flat in g.get("reset", {}).items():
                by_id[int(sid)].chunks.append((f, True, flat))
            for sid, flat in g.get("data", {}).items():
                by_id[int(sid)].chunks.append((f, False, flat))
        if "printed" in line:
            self._printed.append((f, line["printed"]))

    # -- what a test reads ------------------------------------------------------------------

    @property
    def frames(self) -> int:
        return len(self._times)

    @property
    def printed(self) -> str:
        """Everything the program printed (after the last frame too, if it ended)."""
        return "".join(text for _, text in self._printed)

    def __getitem__(self, key) -> Any:
        """An object by the program's variable name (a list of them for a list), or by id."""
        if isinstance(key, str):
            try:
                return self.names[key]
            except KeyError:
                raise KeyError(f"{self.program}: no global variable {key!r} holds a recorded "
                               f"object (names: {', '.join(sorted(self.names)) or 'none'})"
                               ) from None
        return self._by_id[key]

    def __contains__(self, key) -> bool:
        return key in self.names if isinstance(key, str) else key in self._by_id

    def of_kind(self, kind: str) -> list[Track]:
        return [tr for tr in self.objects if tr.kind == kind]

    def frame_at(self, t: float) -> int:
        """The frame shown at program time ``t``: the last one taken at or before it."""
        i = bisect.bisect_right(self._times, t + 1e-9) - 1
        if i < 0:
            raise ValueError(f"t = {t:g} s is before the first frame ({self._times[0]:g} s)")
        return i

    def at(self, t: float) -> Snapshot:
        return Snapshot(self, self.frame_at(t))

    def _column(self, attribute: str) -> np.ndarray:
        """(frames, objects[, width]) of one attribute, NaN where an object is not there."""
        col = self._columns.get(attribute)
        if col is not None:
            return col
        n, F = len(self.objects), self.frames
        sample = self._sample(attribute)
        if sample is None or isinstance(sample, str):     # text, or never set: as objects
            return self._object_column(attribute)
        width = len(sample) if isinstance(sample, list) else 1
        cur = np.full((n, width), np.nan)
        out = np.full((F, n, width), np.nan)
        born = self._born()
        gone: dict[int, list[Track]] = {}
        for tr in self.objects:
            if tr.deleted is not None:
                gone.setdefault(tr.deleted, []).append(tr)
        sets = iter(self._sets)
        pending = next(sets, None)
        for f in range(F):
            for tr in born.get(f, ()):
                v = tr.first.get(attribute)
                cur[self._slot[tr.id]] = np.nan if v is None else v
            while pending is not None and pending[0] == f:
                change = pending[1].get(attribute)
                if change is not None:
                    slots = [self._slot[i] for i in change["ids"]]
                    vals = numbers(change)
                    cur[slots] = vals.reshape(len(slots), width)
                pending = next(sets, None)
            for tr in gone.get(f, ()):
                cur[self._slot[tr.id]] = np.nan
            out[f] = cur
        col = out[:, :, 0] if width == 1 else out
        self._columns[attribute] = col
        return col

    def _born(self) -> dict[int, list[Track]]:
        """The objects by the frame they were made in."""
        born: dict[int, list[Track]] = {}
        for tr in self.objects:
            born.setdefault(tr.born, []).append(tr)
        return born

    def _sample(self, attribute: str) -> Any:
        """A value the attribute had somewhere in the run (None: never any)."""
        for tr in self.objects:
            if tr.first.get(attribute) is not None:
                return tr.first[attribute]
        for _, sets in self._sets:
            change = sets.get(attribute)
            if change is not None:
                values = numbers(change).tolist() if "f8" in change else change["values"]
                width = len(values) // max(len(change["ids"]), 1)
                found = next((v for v in values if v is not None), None)
                if found is not None:
                    return [found] * width if width > 1 else found
        return None

    def _object_column(self, attribute: str) -> np.ndarray:
        """A text attribute (label text, a texture's name) over the frames, as objects."""
        n, F = len(self.objects), self.frames
        out = np.empty((F, n), dtype=object)
        cur: list = [None] * n
        changes: dict[int, dict] = {f: s.get(attribute) for f, s in self._sets
                                    if attribute in s}
        born = self._born()
        for f in range(F):
            for tr in born.get(f, ()):
                cur[self._slot[tr.id]] = tr.first.get(attribute)
            change = changes.get(f)
            if change is not None:
                for i, v in zip(change["ids"], change["values"]):
                    cur[self._slot[i]] = v
            out[f] = cur
        self._columns[attribute] = out
        return out


def read(path) -> Recording:
    """The recording in ``path`` (``.jsonl`` or ``.jsonl.gz``)."""
    return Recording(Path(path))
