"""One object of a recording over time, as columns with units and as CSV (``--trace``).

``springscene vpython prog.py --out run.mp4 --trace ball`` writes ``run-ball.csv`` beside
the video: a row a frame, the frame's program time ``t [s]`` and each numeric attribute
the recording holds of the object the program calls ``ball`` (docs/recording.md), a
vector split into three columns (``pos.x [m]``, ``pos.y [m]``, ``pos.z [m]``), a colour
into ``color.r``, ``color.g``, ``color.b``. One of a list is named by its index:
``--trace atoms[0]`` writes ``run-atoms-0.csv``.

Units: VPython's attributes carry none. A wiki page's programs are written in SI, so the
columns are labelled by that convention, as ``springscene simulate``'s CSV is (``name
[unit]``): lengths in metres (``pos``, ``axis``, ``size``, ``origin``, ``radius``,
``thickness``, an arrow's ``shaftwidth``, ``headwidth`` and ``headlength``), time in
seconds; a label's offsets, height, border, line width and space in pixels (``[px]``,
as VPython draws them), as a ``points`` object's radius unless its ``size_units`` is
``"world"``, and a label's ``pos`` when ``pixel_pos`` is set. Directions (``up``),
colours, ``opacity``, ``shininess`` and counts (``coils``) have no unit; a flag
(``visible``, ``emissive``, ``box``, ...) is written 1 or 0, as is any whole number
(``0``, ``15``). A cell is empty where the
object did not exist yet or any more, or the attribute had no value (a label's colour
left to the canvas's). Text (a label's ``text``, a ``texture``'s name) is left out, as
are a curve's points (not one value a frame).

Numbers are written as Python's ``repr`` of the float: the value the program had.
"""

from __future__ import annotations

import csv
import re
from pathlib import Path

import numpy as np

from ...errors import UserError
from ...outputs import atomic_path, check_output
from .reader import Recording, Track

__all__ = ["columns", "find", "check_name", "trace_path", "write", "write_traces"]

LENGTHS = frozenset({"pos", "axis", "size", "origin", "radius", "thickness", "shaftwidth",
                     "headwidth", "headlength"})
LABEL_PIXELS = frozenset({"xoffset", "yoffset", "height", "border", "linewidth", "space"})
COLOURS = frozenset({"color", "background", "linecolor"})
_NAME = re.compile(r"([A-Za-z_]\w*)(?:\[(\d+)\])?")


def check_name(name: str, flag: str = "--trace") -> str:
    """``name`` if it can name a program's object (``ball``, ``atoms[3]``); else a one-line
    :class:`UserError` (checked before a run, so a typo costs no run)."""
    if not _NAME.fullmatch(name.strip()):
        raise UserError(f"{flag} {name!r}: not a variable name (the program's name for an "
                        "object, such as ball, or atoms[0] for the first of a list)")
    return name.strip()


def find(recording: Recording, name: str, flag: str = "--trace") -> Track:
    """The object the program calls ``name`` (``atoms[3]``: one of a list) at its end; a
    name it does not have is a one-line :class:`UserError` listing the names it has."""
    variable, index = _NAME.fullmatch(check_name(name, flag)).groups()
    if variable not in recording.names:
        known = ", ".join(_shown(n, held) for n, held in sorted(recording.names.items()))
        raise UserError(f"{flag} {name}: {recording.program or 'the program'} has no global "
                        f"variable {variable!r} holding an object (its names: "
                        f"{known or 'none'})")
    held = recording.names[variable]
    if isinstance(held, list):
        if index is None or int(index) >= len(held):
            raise UserError(f"{flag} {name}: {variable} holds {len(held)} objects; name one "
                            f"of them, {variable}[0] to {variable}[{len(held) - 1}]")
        return held[int(index)]
    if index is not None:
        raise UserError(f"{flag} {name}: {variable} is one object ({held.kind}), not a list; "
                        f"trace it as {variable}")
    return held


def _shown(name: str, held) -> str:
    return f"{name}[0..{len(held) - 1}]" if isinstance(held, list) else name


def trace_path(out: str | Path, name: str) -> Path:
    """Where ``--trace name`` writes beside ``out``: ``run.mp4`` -> ``run-ball.csv``,
    ``atoms[3]`` -> ``run-atoms-3.csv``."""
    out = Path(out)
    stem = out.name[:-len(".jsonl.gz")] if out.name.endswith(".jsonl.gz") else out.stem
    variable, index = _NAME.fullmatch(name).groups()
    return out.with_name(f"{stem}-{variable}{'' if index is None else '-' + index}.csv")


def _unit(track: Track, attribute: str) -> str:
    """The unit an attribute is labelled with (the module's docstring); "" for none."""
    if track.kind == "label" and attribute in LABEL_PIXELS:
        return "px"
    if track.kind == "label" and attribute == "pos" and track.first.get("pixel_pos"):
        return "px"
    if track.kind == "points" and attribute == "radius" \
            and track.first.get("size_units", "pixels") != "world":
        return "px"
    return "m" if attribute in LENGTHS else ""


def _parts(attribute: str, width: int) -> list[str]:
    if width == 1:
        return [attribute]
    letters = "rgb" if attribute in COLOURS else "xyz"
    names = letters if width == 3 else [str(i) for i in range(width)]
    return [f"{attribute}.{part}" for part in names]


def columns(recording: Recording, track: Track) -> dict[str, np.ndarray]:
    """``track``'s numeric attributes over the frames: ``"t [s]"``, then a column each
    (``"pos.x [m]"``, ``"color.r"``, ``"visible"``), in the order the recording lists
    them; NaN where there is no value, a flag as 1.0 or 0.0 (the module's docstring)."""
    out = {"t [s]": np.asarray(recording.times, dtype=float)}
    for attribute in track.first:
        values = getattr(track, attribute)
        if values.dtype == object or np.isnan(values).all():    # text, or never a value
            continue
        values = values.reshape(len(values), -1)
        unit = _unit(track, attribute)
        for i, part in enumerate(_parts(attribute, values.shape[1])):
            out[f"{part} [{unit}]" if unit else part] = values[:, i]
    return out


def _cell(value: float) -> str:
    """A number as written: empty for NaN, a whole number without ".0" (a flag's 1 or 0, a
    count), any other as ``repr`` (the float exactly)."""
    if np.isnan(value):
        return ""
    if value.is_integer() and abs(value) < 1e15:
        return str(int(value))
    return repr(float(value))


def write(path: str | Path, table: dict[str, np.ndarray], flag: str = "--trace") -> Path:
    """``table`` (:func:`columns`) as CSV at ``path``, written whole or not at all."""
    path = check_output(path, (".csv",), flag)
    rows = np.column_stack(list(table.values()))
    with atomic_path(path) as tmp, open(tmp, "w", newline="", encoding="utf-8") as fh:
        w = csv.writer(fh)
        w.writerow(table)
        w.writerows([_cell(v) for v in row] for row in rows.tolist())
    return path


def write_traces(recording: Recording, traces: list[tuple[str, Path]],
                 flag: str = "--trace") -> list[Path]:
    """Each ``(name, path)`` of ``traces`` written (:func:`write`); every name is found
    first, so a name the program does not have writes none of them."""
    found = [(find(recording, name, flag), path) for name, path in traces]
    return [write(path, columns(recording, track), flag) for track, path in found]
