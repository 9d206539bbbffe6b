"""`make fidelity`: springscene's pictures of the fidelity scenes against real VPython's.

For each scene of benchmarks/fidelity/scenes/ (and its ids variant, idscene.py):

1. real VPython's picture: kept in tests/baselines/fidelity/ (the CI test's baselines);
   taken with benchmarks/fidelity/realvpython.py (headless Chromium, the fidelity venv's
   vpython) when missing, or for every scene with ``--update-reference``,
2. springscene's picture (``springscene.jobs.vpython``, the canvas alone),
3. the numbers (springscene.view.imagediff): silhouette IoU per object, mean CIEDE2000
   inside each object, % of the picture's pixels with CIEDE2000 > 5.

Writes docs/fidelity.md (the table), renders/fidelity/<scene>.png (real VPython | springscene
| where CIEDE2000 > 5, and the ids pictures under them) and renders/fidelity/thresholds.txt
(today's numbers as tests/vpython/test_fidelity.py's threshold table).

usage: .venv/bin/python benchmarks/fidelity/run.py [--update-reference] [--scene NAME ...]
                                                   [--python .fidelity-venv/bin/python]
"""
from __future__ import annotations

import argparse
import datetime
import json
import math
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import harness  # noqa: E402
from springscene.view import imagediff  # noqa: E402

RENDERS = harness.ROOT / "renders" / "fidelity"
DOC = harness.ROOT / "docs" / "fidelity.md"
INFO = harness.REFERENCE / "reference.json"


def take_reference(scenes: list[str], python: str) -> None:
    """Real VPython's pictures of ``scenes`` (and their ids variants) into the baselines."""
    work = RENDERS / "reference"
    if work.exists():
        shutil.rmtree(work)
    work.mkdir(parents=True)
    programs = []
    for scene in scenes:
        shutil.copy(harness.SCENES / f"{scene}.py", work / f"{scene}.py")
        prog, _ = harness.write_ids_program(scene, work)
        programs += [work / f"{scene}.py", prog]
    shots = work / "shots"
    subprocess.run([python, str(harness.HERE / "realvpython.py"), str(shots)]
                   + [str(p) for p in programs], check=True)
    harness.REFERENCE.mkdir(parents=True, exist_ok=True)
    for scene in scenes:
        for suffix in (".png", ".ids.png"):
            _save_small(shots / f"{scene}{suffix}", harness.REFERENCE / f"{scene}{suffix}")
        shutil.copy(work / f"{scene}.ids.json", harness.REFERENCE / f"{scene}.ids.json")
    meta = json.loads((shots / "realvpython.json").read_text())
    old = json.loads(INFO.read_text()) if INFO.exists() else {"pictures": {}}
    old["versions"] = meta["versions"]
    old["pictures"].update(meta["pictures"])
    old["date"] = datetime.date.today().isoformat()
    INFO.write_text(json.dumps(old, indent=1) + "\n")


def _save_small(src: Path, dst: Path) -> None:
    from PIL import Image  # noqa: PLC0415  heavy: PIL

    Image.open(src).convert("RGB").save(dst, optimize=True)


def side_by_side(m: dict, out: Path) -> None:
    """real | springscene | CIEDE2000 > 5 in red, and the ids pictures under them."""
    from PIL import Image  # noqa: PLC0415  heavy: PIL

    de = imagediff.ciede2000(m["real"], m["ours"])
    diff = (m["real"] // 3).astype(np.uint8)
    diff[de > imagediff.TARGET_OVER_DE] = (255, 0, 0)
    gap = np.full((m["real"].shape[0], 4, 3), 128, np.uint8)
    top = np.hstack([m["real"], gap, m["ours"], gap, diff])
    bottom = np.hstack([m["real_ids"], gap, m["ours_ids"], gap, np.zeros_like(diff)])
    Image.fromarray(np.vstack([top, np.full((4, top.shape[1], 3), 128, np.uint8),
                               bottom])).save(out)


def _num(x: float, digits: int = 3) -> str:
    return "–" if math.isnan(x) else f"{x:.{digits}f}"


def table_rows(m: dict) -> list[str]:
    """The scene's rows of docs/fidelity.md: one per object, then the whole picture."""
    c, scene = m["comparison"], m["scene"]
    rows = []
    for o in c.objects:
        verdict = "pass" if o.passes() else "FAIL"
        rows.append(f"| {scene} | {o.name} | {_num(o.iou)} | {_num(o.mean_de, 2)} | "
                    f"{_num(o.over_percent, 1)} | {o.pixels[0]} / {o.pixels[1]} | {verdict} |")
    whole = "whole picture" + (f" (with {harness.NO_ID[scene]}, no id)"
                               if harness.NO_ID.get(scene) else "")
    ok = c.over_percent <= imagediff.TARGET_OVER_PERCENT
    rows.append(f"| {scene} | **{whole}** | | {_num(c.mean_de, 2)} | "
                f"{_num(c.over_percent, 2)} | | {'pass' if ok else 'FAIL'} |")
    for name in m["extra"]:
        rows.append(f"| {scene} | {name}: in springscene's scene.objects, not VPython's "
                    "| | | | | FAIL |")
    return rows


def write_doc(results: list[dict]) -> None:
    info = json.loads(INFO.read_text()) if INFO.exists() else {"versions": {}}
    v = info.get("versions", {})
    glow = next(iter(info.get("pictures", {}).values()), {}).get("glowscript", "?")
    n_obj = sum(len(m["comparison"].objects) for m in results)
    n_pass = sum(o.passes() for m in results for o in m["comparison"].objects)
    lines = [
        "# Fidelity: springscene against real VPython",
        "",
        "Written by `make fidelity` (benchmarks/fidelity/run.py) on "
        f"{datetime.date.today().isoformat()}. Real VPython: vpython {v.get('vpython', '?')} "
        f"(GlowScript {glow}) in {v.get('chromium', 'Chromium')}, headless, WebGL on "
        f"SwiftShader; its pictures taken {info.get('date', '?')} "
        "(tests/baselines/fidelity/).",
        "",
        f"Targets (issue 14): each object's silhouette IoU >= {imagediff.TARGET_IOU}, mean "
        f"CIEDE2000 inside it <= {imagediff.TARGET_MEAN_DE:g}; at most "
        f"{imagediff.TARGET_OVER_PERCENT:g} % of a picture's pixels with CIEDE2000 > "
        f"{imagediff.TARGET_OVER_DE:g}. Objects meeting them: {n_pass} of {n_obj}.",
        "",
        "How: each scene is also run as an *ids* variant (benchmarks/fidelity/idscene.py: every "
        "object flat in its own palette colour on black -- a white ambient light and no "
        "lights --, labels hidden, trails cleared); "
        "its pictures give each object's silhouette in both renderers. The colour difference "
        "is taken on the normal pictures inside both silhouettes, less a pixel at the border. "
        "Labels and trails have no id: the whole-picture row measures them. The % column is "
        "of the object's pixels for an object, of the whole picture for the whole picture. "
        "Side-by-side pictures (real | springscene | dE00 > 5 in red): renders/fidelity/.",
        "",
        "Again: `make fidelity` (springscene's side; real VPython's pictures are read from "
        "tests/baselines/fidelity/), `make fidelity FIDELITY_ARGS=--update-reference` (real "
        "VPython's too, in Chromium). tests/vpython/test_fidelity.py checks the same numbers "
        "without a browser; its threshold tables are renders/fidelity/thresholds.txt.",
        "",
        "| scene | object | IoU | mean dE00 | % px dE00 > 5 | pixels (VPython / springscene) "
        "| targets |",
        "|---|---|---|---|---|---|---|",
    ]
    for m in results:
        lines += table_rows(m)
    DOC.write_text("\n".join(lines) + "\n")


def thresholds(results: list[dict], margin_iou: float = 0.01, margin_de: float = 0.3) -> str:
    """Today's numbers as test_fidelity.py's THRESHOLDS: the target where it is met, else
    the measured value with a margin."""
    out = ["THRESHOLDS = {  # (scene, object): (min IoU, max mean dE00); target "
           f"({imagediff.TARGET_IOU}, {imagediff.TARGET_MEAN_DE})"]
    for m in results:
        for o in m["comparison"].objects:
            lo = imagediff.TARGET_IOU if not o.iou < imagediff.TARGET_IOU else \
                max(0.0, math.floor((o.iou - margin_iou) * 100) / 100)
            hi = imagediff.TARGET_MEAN_DE if not o.mean_de > imagediff.TARGET_MEAN_DE else \
                math.ceil((o.mean_de + margin_de) * 10) / 10
            if (lo, hi) != (imagediff.TARGET_IOU, imagediff.TARGET_MEAN_DE):
                out.append(f"    ({m['scene']!r}, {o.name!r}): ({lo}, {hi}),")
    out += ["}", "WHOLE = {  # scene: max % of pixels with dE00 > 5; target "
            f"{imagediff.TARGET_OVER_PERCENT}"]
    for m in results:
        p = m["comparison"].over_percent
        if p > imagediff.TARGET_OVER_PERCENT:
            out.append(f"    {m['scene']!r}: {math.ceil((p + 0.5) * 10) / 10},")
    out += ["}", "EXTRA = {  # scene: springscene objects real VPython's scene.objects has not"]
    out += [f"    {m['scene']!r}: {len(m['extra'])},  # {', '.join(m['extra'])}"
            for m in results if m["extra"]]
    return "\n".join(out + ["}"]) + "\n"


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--update-reference", action="store_true",
                    help="take real VPython's pictures again, for every scene")
    ap.add_argument("--scene", action="append", help="only this scene (repeatable)")
    ap.add_argument("--python", default=str(harness.ROOT / ".fidelity-venv" / "bin" / "python"),
                    help="a Python with vpython, selenium, numpy and pillow")
    a = ap.parse_args(argv)
    scenes = a.scene or harness.scene_names()
    missing = [s for s in scenes if a.update_reference
               or not (harness.REFERENCE / f"{s}.ids.png").exists()]
    if missing:
        take_reference(missing, a.python)
    RENDERS.mkdir(parents=True, exist_ok=True)
    results = []
    for scene in scenes:
        m = harness.measure(scene, RENDERS / "springscene")
        side_by_side(m, RENDERS / f"{scene}.png")
        results.append(m)
        print(f"{scene}: whole {m['comparison'].over_percent:.2f} % over dE00 5", flush=True)
    if a.scene is None:                  # the table is of every scene
        write_doc(results)
        print(f"wrote {DOC}")
    (RENDERS / "thresholds.txt").write_text(thresholds(results))
    print(f"wrote {RENDERS}/ (thresholds.txt: test_fidelity.py's tables)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
