"""What the API's jobs return, made to show themselves in Jupyter.

:class:`Table` (a run as columns with units), :class:`Still` (a picture, shown as a
PNG), :class:`Video` (a video file, shown as an HTML5 video), :class:`Analysis` (measured
beside theory, shown as the table ``springscene analyze`` prints).
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

    ``frames``, ``fps`` and ``seconds`` (wall time); ``result`` is the job's own record
    (:class:`~springscene.render.RenderStats` or
    :class:`~springscene.vpython.run.runner.ProgramResult`), whose other fields read through.
    Up to :data:`EMBED_LIMIT` bytes the file is embedded in the notebook, above it linked
    by its path relative to the notebook's folder.
    """

    def __init__(self, result: Any) -> None:
        self.result = result
        self.path = Path(result.path)

    def __getattr__(self, name: str) -> Any:
        if name == "result":
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

    def _repr_html_(self) -> str:
        if self.path.suffix.lower() in (".gif", ".png"):
            return f'<img src="{self._src()}" alt="{html.escape(self.path.name)}"/>'
        mime = MIME.get(self.path.suffix.lower(), "")
        return (f'<video controls loop muted playsinline><source src="{self._src()}" '
                f'type="{mime}">{html.escape(self.path.name)}</video>')


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
