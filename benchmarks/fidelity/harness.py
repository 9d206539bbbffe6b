"""The fidelity scenes drawn by springscene and compared with real VPython's pictures
(shared by benchmarks/fidelity/run.py and tests/vpython/test_fidelity.py).

Real VPython's pictures are kept in tests/baselines/fidelity/: ``<scene>.png`` (the
program), ``<scene>.ids.png`` (its ids variant, :mod:`idscene`) and ``<scene>.ids.json``
(how real VPython numbered the objects).
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np

from idscene import PALETTE, ids_program
from springscene import jobs
from springscene.view import imagediff

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
SCENES = HERE / "scenes"
REFERENCE = ROOT / "tests" / "baselines" / "fidelity"

# objects a scene has no id for: measured through the whole picture only
NO_ID = {"labels": "labels", "trail": "the trail", "autoscale": "the trail",
         "points": "", "curves": ""}


def scene_names() -> list[str]:
    """The fidelity scenes, by name (benchmarks/fidelity/scenes/<name>.py)."""
    return sorted(p.stem for p in SCENES.glob("*.py"))


def write_ids_program(scene: str, folder: Path) -> tuple[Path, Path]:
    """Write the ids variant of ``scene`` into ``folder``: (program, its numbering JSON)."""
    folder.mkdir(parents=True, exist_ok=True)
    table = (folder / f"{scene}.ids.json").resolve()
    prog = folder / f"{scene}.ids.py"
    prog.write_text(ids_program((SCENES / f"{scene}.py").read_text(), str(table)))
    return prog, table


def _read_png(path: Path) -> np.ndarray:
    from PIL import Image  # noqa: PLC0415  heavy: PIL

    return np.asarray(Image.open(path).convert("RGB"))


def springscene_picture(program: Path, out: Path, supervised: bool = True) -> np.ndarray:
    """springscene's still of ``program``, the canvas alone: run in a supervised child, or
    with ``supervised=False`` in this process (the tests: no new Python a picture)."""
    jobs.vpython(program, out, page=False, canvas_only=True, supervised=supervised)
    return _read_png(out)


def object_names(table: list[dict]) -> list[str]:
    """Names for the numbered objects of an ids JSON: kind and position."""
    names = []
    for entry in sorted(table, key=lambda e: e["id"]):
        pos = ", ".join(f"{v:g}" for v in entry["pos"])
        names.append(f"{entry['kind']} ({pos})")
    return names


def reference(scene: str, folder: Path = REFERENCE):
    """Real VPython's pictures of ``scene`` and its numbering: (image, ids image, table)."""
    table = json.loads((folder / f"{scene}.ids.json").read_text())
    return (_read_png(folder / f"{scene}.png"), _read_png(folder / f"{scene}.ids.png"), table)


def measure(scene: str, work: Path, folder: Path = REFERENCE, supervised: bool = True) -> dict:
    """Draw ``scene`` and its ids variant with springscene into ``work`` and compare with
    real VPython's: a dict with the comparison, the pictures and both numberings
    (``supervised``: :func:`springscene_picture`'s)."""
    work.mkdir(parents=True, exist_ok=True)
    real, real_ids, real_table = reference(scene, folder)
    ours = springscene_picture(SCENES / f"{scene}.py", work / f"{scene}.springscene.png",
                               supervised)
    prog, table_path = write_ids_program(scene, work)
    ours_ids = springscene_picture(prog, work / f"{scene}.ids.springscene.png", supervised)
    table = json.loads(table_path.read_text()) if table_path.exists() else []
    if ours.shape != real.shape:
        raise ValueError(f"{scene}: springscene drew {ours.shape[:2]}, VPython {real.shape[:2]}")
    ids, extra = match_objects(real_table, table)
    cmp = imagediff.compare_scene(real, ours, real_ids, ours_ids, PALETTE,
                                  object_names(real_table),
                                  palette_b=[None if i is None else PALETTE[i] for i in ids])
    return {"scene": scene, "comparison": cmp, "real": real, "ours": ours,
            "real_ids": real_ids, "ours_ids": ours_ids, "extra": object_names(extra)}


def match_objects(real: list[dict], ours: list[dict], tol: float = 0.05):
    """For each object real VPython numbered, springscene's number for the same object (same
    kind, position within ``tol``) or None; and springscene's objects real VPython has not
    (a trail listed in ``scene.objects``, say)."""
    left = sorted(ours, key=lambda e: e["id"])
    found = []
    for r in sorted(real, key=lambda e: e["id"]):
        hit = next((e for e in left if e["kind"] == r["kind"] and
                    max(abs(x - y) for x, y in zip(e["pos"], r["pos"])) <= tol), None)
        found.append(None if hit is None else hit["id"] % len(PALETTE))
        if hit is not None:
            left.remove(hit)
    return found, left
