"""A batch's rows as ``index.html``, ``summary.csv`` and ``summary.json``.

``index.html`` is one static page, opened from disk, to look through a class: a card a
program with its thumbnail (linking its interactive page, or its video), how its run
ended (the program's error with its first line, the timeout, the memory), the program
time it reached, the wall time, and its grade with each test's pass or fail and message.
``summary.csv`` and ``summary.json`` hold the same rows. All three are written atomically
(:func:`springscene.outputs.atomic_path`), after each program, for what is done.
"""

from __future__ import annotations

import csv
import html
import io
import json
from pathlib import Path
from urllib.parse import quote

from ..outputs import atomic_path

COLUMNS = ("name", "program", "status", "detail", "program_seconds", "frames", "wall_seconds",
           "peak_memory", "dialect", "score", "max_score", "grade_error")
STATUS_COLOURS = {"ran": "#2e7d32", "error": "#c62828", "exit": "#c62828",
                  "timeout": "#ef6c00", "memory": "#ef6c00", "crashed": "#6a1b9a", "sandbox": "#ad1457",
                  "refused": "#455a64", "failed": "#455a64"}


def write_index(out_dir: Path, rows: list[dict], total: int) -> None:
    """The three files for ``rows`` (the programs done of ``total``)."""
    _write(out_dir / "summary.json", json.dumps(
        {"programs": total, "done": len(rows),
         "settings": rows[0].get("settings") if rows else None,
         "rows": [{k: v for k, v in row.items() if k != "settings"} for row in rows]},
        indent=1) + "\n")
    _write(out_dir / "summary.csv", summary_csv(rows))
    _write(out_dir / "index.html", index_html(rows, total))


def _write(path: Path, text: str) -> None:
    with atomic_path(path) as tmp:
        tmp.write_text(text, encoding="utf-8")


def test_names(rows: list[dict]) -> list[str]:
    """Every test's name, in the order the rows first give them."""
    names: dict[str, None] = {}
    for row in rows:
        for test in row.get("tests") or ():
            names.setdefault(test["name"], None)
    return list(names)


def summary_csv(rows: list[dict]) -> str:
    """A row a program: :data:`COLUMNS`, then a column a test (``pass``, or ``fail:``
    and its message)."""
    tests = test_names(rows)
    buffer = io.StringIO()
    writer = csv.writer(buffer, lineterminator="\n")
    writer.writerow([*COLUMNS, *(f"test {name}" for name in tests)])
    for row in rows:
        outcomes = {t["name"]: t for t in row.get("tests") or ()}
        writer.writerow([_cell(row.get(column)) for column in COLUMNS]
                        + [_outcome(outcomes.get(name)) for name in tests])
    return buffer.getvalue()


def _cell(value) -> str:
    return "" if value is None else str(value)


def _outcome(test: dict | None) -> str:
    if test is None:
        return ""
    return "pass" if test["passed"] else f"fail: {test.get('message') or ''}".strip()


_STYLE = """
body{font:14px system-ui,sans-serif;margin:1.5em;background:#fafafa;color:#212121}
h1{font-size:1.4em;margin:0 0 .3em}
.counts span{margin-right:1em}
.cards{display:grid;grid-template-columns:repeat(auto-fill,minmax(250px,1fr));gap:14px;
margin-top:1em}
.card{background:#fff;border:1px solid #ddd;border-radius:6px;padding:8px;overflow:hidden}
.card img{width:100%;height:180px;object-fit:contain;display:block;background:#eee;
border-radius:3px}
.none{height:180px;background:#eee;display:flex;align-items:center;justify-content:center;
color:#777;border-radius:3px}
.name{font-weight:600;margin:.4em 0 .2em;word-break:break-all}
.status{color:#fff;border-radius:3px;padding:0 .4em;font-size:.85em}
.detail{font-family:monospace;font-size:.85em;margin:.3em 0;word-break:break-word}
.numbers,.links{color:#555;font-size:.85em;margin:.2em 0}
.grade{margin-top:.3em;font-size:.85em}.pass{color:#2e7d32}.fail{color:#c62828}
ul{margin:.2em 0;padding-left:0;list-style:none}
"""


def index_html(rows: list[dict], total: int) -> str:
    """The page: a header with the counts, then a card a program."""
    counts: dict[str, int] = {}
    for row in rows:
        counts[row["status"]] = counts.get(row["status"], 0) + 1
    shown = "".join(f"<span>{_badge(status)} {n}</span>" for status, n in sorted(counts.items()))
    cards = "\n".join(_card(row) for row in rows)
    return (f"<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\">\n"
            f"<title>springscene batch: {len(rows)} of {total} programs</title>\n"
            f"<style>{_STYLE}</style></head><body>\n"
            f"<h1>{len(rows)} of {total} programs</h1>\n<div class=\"counts\">{shown}"
            f"<span><a href=\"summary.csv\">summary.csv</a> · "
            f"<a href=\"summary.json\">summary.json</a></span></div>\n"
            f"<div class=\"cards\">\n{cards}\n</div></body></html>\n")


def _badge(status: str) -> str:
    colour = STATUS_COLOURS.get(status, "#455a64")
    return f"<span class=\"status\" style=\"background:{colour}\">{html.escape(status)}</span>"


def _link(row: dict, kind: str) -> str | None:
    name = (row.get("files") or {}).get(kind)
    return None if name is None else quote(f"{row['name']}/{name}")


def _card(row: dict) -> str:
    """One program: thumbnail, name and status, what its run reached, its grade."""
    page, video, thumb = _link(row, "page"), _link(row, "video"), _link(row, "thumbnail")
    target = page or video
    picture = (f"<img src=\"{thumb}\" alt=\"{html.escape(row['name'])}\" loading=\"lazy\">"
               if thumb else "<div class=\"none\">no video</div>")
    if target:
        picture = f"<a href=\"{target}\">{picture}</a>"
    links = " · ".join(f"<a href=\"{url}\">{label}</a>" for label, url in (
        ("page", page), ("video", video), ("log", _link(row, "log"))) if url)
    detail = f"<div class=\"detail\">{html.escape(row['detail'])}</div>" \
        if row.get("detail") else ""
    return (f"<div class=\"card\" id=\"{html.escape(row['name'])}\">{picture}\n"
            f"<div class=\"name\">{html.escape(row['name'])} {_badge(row['status'])}</div>"
            f"{detail}<div class=\"numbers\">{_numbers(row)}</div>"
            f"<div class=\"links\">{links}</div>{_grade(row)}</div>")


def _numbers(row: dict) -> str:
    parts = []
    if row.get("program_seconds") is not None:
        parts.append(f"program time {row['program_seconds']:.2f} s")
    if row.get("wall_seconds") is not None:
        parts.append(f"wall {row['wall_seconds']:.1f} s")
    if row.get("frames"):
        parts.append(f"{row['frames']} frames")
    return " · ".join(parts)


def _grade(row: dict) -> str:
    """The score and each test's outcome (nothing without tests)."""
    if row.get("max_score") is None and not row.get("tests") and not row.get("grade_error"):
        return ""
    score = (f"<b>{row['score']:g} / {row['max_score']:g}</b>"
             if row.get("max_score") is not None and row.get("score") is not None else "")
    error = (f" <span class=\"fail\">{html.escape(row['grade_error'])}</span>"
             if row.get("grade_error") else "")
    items = "".join(
        f"<li class=\"{'pass' if t['passed'] else 'fail'}\">{'✓' if t['passed'] else '✗'} "
        f"{html.escape(t['name'])}"
        + (f": {html.escape(t['message'])}" if t.get("message") and not t["passed"] else "")
        + "</li>" for t in row.get("tests") or ())
    return f"<div class=\"grade\">grade {score}{error}<ul>{items}</ul></div>"
