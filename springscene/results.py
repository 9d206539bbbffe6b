"""What the API's jobs return, made to show themselves in Jupyter.

:class:`Table` (a run as columns with units), :class:`Still` (a picture, shown as a
PNG), :class:`Video` (a video file, shown as an HTML5 video), :class:`Analysis` (measured
beside theory, shown as the table ``springscene analyze`` prints), :class:`Run` (a VPython
program's run as data, from its recording: what a test of the program reads).
"""

from __future__ import annotations

import base64
import html
import io
import os
from pathlib import Path
from typing import Any

import numpy as np

from . import jobs
from .settings import Config
from .vpython.page import glow_library, interactive
from .vpython.page.replay_data import replay_data
from .vpython.record import trace
from .vpython.record.reader import Recording, Series, Snapshot

EMBED_LIMIT = 25 * 2 ** 20      # a video up to this size is embedded in the notebook itself
MIME = {".mp4": "video/mp4", ".webm": "video/webm", ".ogv": "video/ogg", ".ogg": "video/ogg",
        ".gif": "image/gif", ".png": "image/png"}

UNITS = {"t": "s", "x": "m", "y": "m", "z": "m", "px": "kg m/s", "py": "kg m/s",
         "pz": "kg m/s", "K": "J", "Us": "J", "Ug": "J", "E": "J", "E_thermal": "J"}
LATTICE_COLUMNS = ("t", "px", "py", "pz", "K", "Us", "E", "E_thermal")


class Table(dict):
    """A run as columns: name -> 1-D array, one row per step; ``units`` name -> SI unit.

    A dict, so ``pandas.DataFrame(table)`` is a data frame; ``table.array`` is the
    (rows, columns) array; ``table.run`` what :func:`springscene.jobs.simulate` returned
    (a :class:`~springscene.model.physics.Trajectory`, or a lattice's totals).
    """

    def __init__(self, columns: dict[str, np.ndarray], run: Any = None) -> None:
        super().__init__(columns)
        self.units = {name: UNITS[name] for name in columns}
        self.run = run

    @property
    def array(self) -> np.ndarray:
        return np.column_stack(list(self.values()))

    def __repr__(self) -> str:
        rows = len(next(iter(self.values()))) if self else 0
        cols = ", ".join(f"{k} [{u}]" for k, u in self.units.items())
        return f"<Table: {rows} rows of {cols}>"

    def _repr_html_(self) -> str:
        head = "".join(f"<th>{html.escape(k)} [{html.escape(u)}]</th>"
                       for k, u in self.units.items())
        n = len(self["t"])
        shown = list(range(min(n, 5))) + ([n - 1] if n > 5 else [])
        body = "".join("<tr>" + "".join(f"<td>{self[k][r]:.6g}</td>" for k in self) + "</tr>"
                       + ("<tr><td>…</td></tr>" if i == 4 and n > 6 else "")
                       for i, r in enumerate(shown))
        return f"<table><tr>{head}</tr>{body}</table><p>{n} rows</p>"


def table(run) -> Table:
    """A :func:`springscene.jobs.simulate` result as a :class:`Table`."""
    if isinstance(run, np.ndarray):
        if run.shape[1] != len(LATTICE_COLUMNS):
            raise AssertionError(f"a lattice run has {run.shape[1]} columns")
        return Table({name: run[:, i] for i, name in enumerate(LATTICE_COLUMNS)}, run)
    cols = {"t": run.t, "x": run.pos[:, 0], "y": run.pos[:, 1], "z": run.pos[:, 2],
            "px": run.p[:, 0], "py": run.p[:, 1], "pz": run.p[:, 2], "K": run.K,
            "Us": run.Us, "Ug": run.Ug, "E": run.E, "E_thermal": run.E_thermal}
    return Table(cols, run)


def _png_bytes(image: np.ndarray) -> bytes:
    from PIL import Image  # noqa: PLC0415  heavy: Pillow, only to show a picture
    buf = io.BytesIO()
    Image.fromarray(np.ascontiguousarray(image)).save(buf, format="PNG")
    return buf.getvalue()


class Still(np.ndarray):
    """A picture: an (h, w, 3) uint8 array that Jupyter shows as a PNG; ``path`` its file."""

    path: Path | None

    def __new__(cls, image: np.ndarray, path: Path | None = None) -> Still:
        obj = np.asarray(image).view(cls)
        obj.path = Path(path) if path is not None else None
        return obj

    def __array_finalize__(self, obj) -> None:
        self.path = getattr(obj, "path", None)

    def _repr_png_(self) -> bytes | None:
        if self.ndim != 3 or self.shape[2] not in (3, 4) or self.dtype != np.uint8:
            return None             # a slice or a computed array: shown as numbers
        return _png_bytes(self.view(np.ndarray))


class Video:
    """A video (or GIF, or the PNG of a VPython program) written to ``path``; Jupyter shows it.

    ``frames``, ``fps`` and ``seconds`` (wall time); ``run``, a VPython program's
    :class:`Run` when its recording was kept (``run_vpython(..., record=...)``), else
    None; ``result`` is the job's own record
    (:class:`~springscene.render.RenderStats` or
    :class:`~springscene.vpython.run.runner.ProgramResult`), whose other fields read through.
    Up to :data:`EMBED_LIMIT` bytes the file is embedded in the notebook, above it linked
    by its path relative to the notebook's folder.
    """

    def __init__(self, result: Any, run: Run | None = None) -> None:
        self.result = result
        self.path = Path(result.path)
        self.run = run            # a VPython run kept with record=: its Run; else None

    def __getattr__(self, name: str) -> Any:
        if name in ("result", "run"):
            raise AttributeError(name)
        return getattr(self.result, name)

    def __repr__(self) -> str:
        return f"<Video {self.path}: {self.result.frames} frames at {self.result.fps} fps>"

    def _src(self) -> str:
        mime = MIME.get(self.path.suffix.lower(), "application/octet-stream")
        if self.path.stat().st_size <= EMBED_LIMIT:
            data = base64.b64encode(self.path.read_bytes()).decode("ascii")
            return f"data:{mime};base64,{data}"
        return html.escape(os.path.relpath(self.path))

    def _interactive_page(self) -> str | None:
        """The run's interactive page, if it has one: the output itself (``.html``) or the
        page beside its video or still (not the picture page made without GlowScript)."""
        page = self.path if self.path.suffix.lower() == ".html" else getattr(
            self.result, "page", None)
        if page is None or not Path(page).is_file():
            return None
        text = Path(page).read_text(encoding="utf-8")
        return text if "glow.min.js" in text else None

    def _repr_html_(self) -> str:
        page = self._interactive_page()       # a run made without its page: the video
        if page is not None:
            size = getattr(self.result, "size", None)
            return page_frame(page, (size[1] if size else 600) + 160)
        if self.path.suffix.lower() in (".gif", ".png"):
            return f'<img src="{self._src()}" alt="{html.escape(self.path.name)}"/>'
        mime = MIME.get(self.path.suffix.lower(), "")
        return (f'<video controls loop muted playsinline><source src="{self._src()}" '
                f'type="{mime}">{html.escape(self.path.name)}</video>')


def page_frame(page: str, height: int) -> str:
    """A whole HTML page shown inline in a notebook: an iframe holding it (``srcdoc``), its
    scripts run in the frame's own sandbox, away from the notebook's page (Jupyter,
    JupyterLab and Colab alike; no extension, no server)."""
    return (f'<iframe srcdoc="{html.escape(page, quote=True)}" '
            f'style="width: 100%; height: {int(height)}px; border: 0; resize: vertical" '
            'sandbox="allow-scripts allow-popups"></iframe>')


class Analysis(dict):
    """:func:`analyze`'s result (a dict: ``measured``, ``theory``, ...); shown as a table."""

    def __init__(self, cfg: Config, result: dict) -> None:
        super().__init__(result)
        self.cfg = cfg

    def report(self, as_json: bool = False) -> str:
        """The table ``springscene analyze`` prints, or its ``--json``."""
        return jobs.report(self.cfg, dict(self), as_json=as_json)

    def __str__(self) -> str:
        return self.report()

    def _repr_pretty_(self, printer, cycle: bool) -> None:
        printer.text(self.report())


# ---- a VPython program's run, as data -----------------------------------------------------

class Objects(list):
    """The run's objects (each a :class:`~springscene.vpython.record.reader.Track`), in the
    order the program made them; :meth:`of_kind` picks one kind."""

    def of_kind(self, kind: str) -> Objects:
        """The objects of one kind (``"sphere"``, ``"helix"``, ``"label"``, ...)."""
        return Objects(o for o in self if o.kind == kind)


class Graph:
    """One of the program's graphs: ``title``, ``xtitle``, ``ytitle`` (the program's
    text, HTML as VPython takes it) and its ``series`` (each a
    :class:`~springscene.vpython.record.reader.Series`: ``kind``, ``label``, ``color``
    and ``points()``, the (n, 2) points at the run's end). ``graph["K"]`` is the series
    labelled ``K``; ``graph[0]`` the first series."""

    def __init__(self, record: dict, series: list[Series]) -> None:
        self.id: int = record["id"]
        self.title: str = record.get("title") or ""
        self.xtitle: str = record.get("xtitle") or ""
        self.ytitle: str = record.get("ytitle") or ""
        self.record = record                 # every key the recording holds (bounds, size)
        self.series = series

    def __getitem__(self, key: str | int) -> Series:
        if isinstance(key, int):
            return self.series[key]
        for s in self.series:
            if s.label == key:
                return s
        labels = ", ".join(repr(s.label) for s in self.series) or "none"
        raise KeyError(f"graph {self.title or self.id!r}: no series labelled {key!r} "
                       f"(labels: {labels})")

    def __len__(self) -> int:
        return len(self.series)

    def __iter__(self):
        return iter(self.series)

    def __repr__(self) -> str:
        labels = ", ".join(f"{s.kind} {s.label!r}" for s in self.series)
        return f"<Graph {self.title or self.id!r}: {labels or 'no series'}>"


class Run:
    """A VPython program's run as data: what :func:`springscene.run_vpython` gives.

    Built on the run's recording (docs/recording.md; ``springscene.vpython.record.reader``),
    it holds every object the program drew at every frame of the video (frames at
    ``t = frame / fps`` of program time, the clock of ``rate``), its graphs, what it
    printed and its global numbers at the end.

    Attributes
    ----------
    objects : Objects
        Every object, in the order made; ``run.objects.of_kind("sphere")``.
    names : dict
        The program's global variable names that held an object (or a list of them) at
        its end; ``run["ball"]`` is one, as a
        :class:`~springscene.vpython.record.reader.Track` whose recorded attributes are
        numpy arrays over the frames: ``run["ball"].pos`` is (frames, 3), as are
        ``.axis``, ``.size`` (a sphere's is its diameter three times), ``.color``;
        ``.opacity``, ``.visible``, ... are (frames,): NaN before the object was made and
        after it was deleted. ``.attributes()`` lists what was recorded of it.
    times : numpy.ndarray
        Each frame's program time, s.
    printed : str
        What the program printed.
    graphs : list of Graph
        Each graph with its title, axis titles and series (``graph["K"].points()``).
    series : list of Series
        Every series of every graph.
    globals : dict
        The program's global numbers (``int``, ``float``), booleans and vectors (numpy
        arrays) at its end: ``run.globals["k"]``.
    canvases : list of dict
        Each canvas's attributes at the end (title, caption, camera, ...).
    ended : str
        ``"program"`` (it ended), ``"duration"`` or ``"frames"`` (the run's limit), or
        ``"error"`` (it raised: the run up to its error).
    error : dict or None
        The program's own error, when the run ended in one: ``type`` (``"IndexError"``),
        ``message``, ``t`` (the program time it was raised at, the last frame's),
        ``line`` (the program's line) and ``traceback``. :func:`springscene.run_vpython`
        raises the program's error; the run up to it is the error's ``run``.
    recording : Path or None
        The recording's file, when it was kept (``record=``, or an ``out`` ending
        ``.jsonl``).
    result : ProgramResult
        The run's own record (``seconds`` of wall clock, ``dialect``, ``notes``, ...).

    Notes
    -----
    VPython's attributes carry no units. A wiki page's programs are in SI, so springscene
    reads them so: positions and sizes in metres, times in seconds (``run.trace`` labels
    its columns ``t [s]``, ``pos.x [m]``, ...; see
    :mod:`springscene.vpython.record.trace`).
    """

    def __init__(self, recording: Recording, result: Any = None,
                 kept: str | Path | None = None, source: str | Path | None = None) -> None:
        self._recording = recording
        # the recording's file, for the page (kept, or a scratch copy the caller owns)
        self._source = Path(source) if source is not None else (
            Path(kept) if kept is not None else None)
        self.result = result
        self.recording = Path(kept) if kept is not None else None
        self.objects = Objects(recording.objects)
        self.names: dict[str, Any] = recording.names
        self.times: np.ndarray = recording.times
        self.fps: int = recording.fps
        self.program: str = recording.program
        self.dialect: str = recording.dialect
        self.globals: dict[str, Any] = recording.globals
        self.canvases: list[dict] = recording.canvases
        self.series: list[Series] = recording.series
        self.graphs = [Graph(g, [s for s in recording.series if s.graph.get("id") == g["id"]])
                       for g in recording.graphs]
        end = recording.end or {}
        self.ended: str = end.get("ended") or getattr(result, "ended", None) or "cut short"
        self.error: dict | None = recording.error

    @property
    def frames(self) -> int:
        return len(self.times)

    @property
    def printed(self) -> str:
        return self._recording.printed

    def __getitem__(self, key: str | int) -> Any:
        """An object by the program's variable name (a list of them for a list), or by the
        recording's id; a name the program does not have is a KeyError naming those it has."""
        return self._recording[key]

    def __contains__(self, key: str | int) -> bool:
        return key in self._recording

    def of_kind(self, kind: str) -> Objects:
        """The objects of one kind: ``run.of_kind("sphere")``."""
        return self.objects.of_kind(kind)

    def frame_at(self, t: float) -> int:
        """The frame shown at program time ``t``: the last one taken at or before it."""
        return self._recording.frame_at(t)

    def at(self, t: float) -> Snapshot:
        """Every object as it was at program time ``t`` (the frame shown then):
        ``run.at(1.5)["ball"].pos`` is a (3,) array."""
        return self._recording.at(t)

    def trace(self, name: str, out: str | Path | None = None) -> dict[str, np.ndarray]:
        """The object the program calls ``name`` (``"ball"``, ``"atoms[3]"``) over the
        frames, as columns with units (``"t [s]"``, ``"pos.x [m]"``, ...; what
        ``springscene vpython --trace`` writes); also written as CSV to ``out`` if given.
        ``pandas.DataFrame(run.trace("ball"))`` is a data frame."""
        table = trace.columns(self._recording, trace.find(self._recording, name, "trace"))
        if out is not None:
            trace.write(out, table, "trace")
        return table

    def __repr__(self) -> str:
        named = ", ".join(self.names) or "none named"
        span = f"{self.times[0]:g} to {self.times[-1]:g} s" if self.frames else "no frames"
        graphs = f"{len(self.graphs)} graph{'s' * (len(self.graphs) != 1)}"
        ended = (f"the program's {self.error['type']}" if self.error is not None
                 else self.ended)
        return (f"<Run {self.program}: {self.frames} frames at {self.fps} fps, {span}, ended "
                f"by {ended}; {len(self.objects)} object{'s' * (len(self.objects) != 1)} "
                f"({named}); {graphs}>")

    def page_html(self) -> str:
        """The run's interactive page (GlowScript replaying it), as one HTML document."""
        if self._source is None or not self._source.exists():
            raise ValueError(f"{self.program}: the run's recording is gone; keep it with "
                             "record= to show its page")
        return interactive.page_html(replay_data(self._source), glow_library.library())

    def _repr_html_(self) -> str:
        """In Jupyter, JupyterLab and Colab: the interactive page, inline."""
        try:
            page = self.page_html()
        except (ValueError, OSError) as exc:        # no recording, or no GlowScript
            return f"<pre>{html.escape(repr(self))}\n({html.escape(str(exc))})</pre>"
        return page_frame(page, self._page_height())

    def _page_height(self) -> int:
        shown = [c for c in self.canvases if c.get("visible", True)]
        return (60 + sum(int(c.get("height", 400)) + 80 for c in shown)
                + sum(int(g.record.get("height", 400)) + 20 for g in self.graphs) + 60)
