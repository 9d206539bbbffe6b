"""Recordings written by hand in the documented format (docs/recording.md), for the
interactive page's tests: a ball on a spring with a trail, a label, a graph and printed
text; a crystal of 64 atoms joined by 144 springs, as springscene's AtomicSolid example.
"""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np

FPS = 25
LABEL_GONE = 60          # the spring's label is deleted at this frame
DEFAULT_LIGHTS = [
    {"kind": "distant_light", "direction": [0.22, 0.44, 0.88], "color": [0.8, 0.8, 0.8]},
    {"kind": "distant_light", "direction": [-0.88, -0.22, -0.44], "color": [0.3, 0.3, 0.3]},
]


def canvas_record(cid: int = 0, *, title: str = "", caption: str = "", width: int = 640,
                  height: int = 400, center=(0.0, 0.0, 0.0), forward=(0.0, 0.0, -1.0),
                  rng: float = 1.0) -> dict:
    """A canvas's whole first record."""
    return {"id": cid, "width": width, "height": height, "background": [0.0, 0.0, 0.0],
            "foreground": [1.0, 1.0, 1.0], "ambient": [0.2, 0.2, 0.2], "title": title,
            "caption": caption, "visible": True, "fov": math.pi / 3, "userzoom": True,
            "userspin": True, "userpan": True, "center": list(center),
            "forward": list(forward), "up": [0.0, 1.0, 0.0], "range": rng,
            "autoscale": True, "lights": DEFAULT_LIGHTS}


def solid(oid: int, kind: str, pos, axis, size, color, **more) -> dict:
    """An object's whole record (the solids' attributes)."""
    return {"id": oid, "kind": kind, "canvas": 0, "visible": True, "pos": list(pos),
            "axis": list(axis), "up": [0.0, 1.0, 0.0], "size": list(size),
            "color": list(color), "opacity": 1.0, "shininess": 0.6, "emissive": False,
            "texture": None, **more}


def write(path: Path, frames: list[dict], end: dict | None = None,
          program: str = "test.py") -> Path:
    """The recording: the header, the frames (``frame`` and ``t`` filled in), the end."""
    lines = [{"format": "springscene-recording", "version": 1, "springscene": "0.1.0",
              "program": program, "dialect": "VPython 7", "fps": FPS}]
    for k, f in enumerate(frames):
        lines.append({"frame": k, "t": k / FPS, **f})
    lines.append({"end": {"t": (len(frames) - 1) / FPS, "frames": len(frames),
                          "ended": "program", "error": None, "names": {}, "globals": {},
                          **(end or {})}})
    path.write_text("".join(json.dumps(x) + "\n" for x in lines), encoding="utf-8")
    return path


def spring_position(k: int) -> list[float]:
    """The ball's position at frame k: a vertical oscillation, 1 s period."""
    return [0.0, -0.5 + 0.2 * math.cos(2 * math.pi * k / FPS), 0.0]


def spring(path: Path, seconds: float = 4.0, *, title: str = "<b>spring</b> k = 5",
           caption: str = "", label_text: str = "ball", printed: str = "") -> Path:
    """A holder, a helix, a ball with a curve trail, a label, a graph of y(t) and print."""
    n = int(round(seconds * FPS)) + 1
    frames = []
    for k in range(n):
        y = spring_position(k)
        f: dict = {}
        if k == 0:
            f["canvases"] = [canvas_record(title=title, caption=caption, rng=0.8,
                                           center=(0.0, -0.3, 0.0))]
            f["new"] = [
                solid(1, "box", (0, 0.05, 0), (0.3, 0, 0), (0.3, 0.05, 0.3), (0.5, 0.5, 0.5)),
                solid(2, "helix", (0, 0.05, 0), (0, y[1] - 0.05, 0),
                      (abs(y[1] - 0.05), 0.1, 0.1), (1, 0.7, 0.2),
                      coils=8, thickness=0.01, ccw=True),
                solid(3, "sphere", y, (0.1, 0, 0), (0.1, 0.1, 0.1), (0, 0.5, 1)),
                {"id": 4, "kind": "curve", "canvas": 0, "visible": True,
                 "origin": [0, 0, 0], "axis": [1, 0, 0], "up": [0, 1, 0],
                 "size": [1, 1, 1], "color": [1, 1, 0], "radius": 0.005, "opacity": 1.0,
                 "shininess": 0.6, "emissive": False, "retain": 20},
                {"id": 5, "kind": "label", "canvas": 0, "visible": True,
                 "pos": [0.2, 0.1, 0], "text": label_text, "xoffset": 0, "yoffset": 0,
                 "height": 15, "font": "sans", "color": None, "background": None,
                 "linecolor": None, "opacity": 0.66, "box": True, "border": 5,
                 "line": True, "linewidth": 1, "space": 0, "align": "center",
                 "pixel_pos": False},
            ]
            f["graphs"] = {"new": [
                {"id": 10, "kind": "graph", "title": "y(t)", "xtitle": "t (s)",
                 "ytitle": "y (m)", "width": 480, "height": 240, "xmin": None, "xmax": None,
                 "ymin": None, "ymax": None, "logx": False, "logy": False,
                 "background": None, "foreground": None},
                {"id": 11, "kind": "gcurve", "graph": 10, "label": "ball",
                 "color": [0, 0, 1], "width": 2, "radius": 3, "dot": False,
                 "visible": True}]}
            f["points"] = {"4": {"reset": [[*y, 1, 1, 0, 0.005]]}}
        else:
            f["set"] = {"pos": {"ids": [3], "values": y},
                        "axis": {"ids": [2], "values": [0, y[1] - 0.05, 0]},
                        "size": {"ids": [2], "values": [abs(y[1] - 0.05), 0.1, 0.1]}}
            f["points"] = {"4": {"drop": 1 if k >= 20 else 0,
                                 "append": [[*y, 1, 1, 0, 0.005]]}}
            f["canvases"] = [{"id": 0, "range": 0.8 + 0.001 * k}]
        f["graphs"] = {**f.get("graphs", {}), "data": {"11": [k / FPS, y[1]]}}
        if k == LABEL_GONE:
            f["deleted"] = [5]
        if printed and k % FPS == 0:
            f["printed"] = printed
        frames.append(f)
    return write(path, frames, program="spring.py")


def crystal_positions(k: int, n: int = 4, spacing: float = 1.0) -> np.ndarray:
    """The 64 atoms' positions at frame k: a lattice, each atom vibrating."""
    g = np.arange(n) * spacing - (n - 1) * spacing / 2
    base = np.array([(x, y, z) for x in g for y in g for z in g])
    phase = np.arange(len(base))[:, None] * np.array([0.7, 1.3, 2.1])
    return base + 0.08 * np.sin(2 * math.pi * 1.3 * k / FPS + phase)


def crystal_bonds(n: int = 4) -> list[tuple[int, int]]:
    """The 144 nearest-neighbour bonds of an n×n×n lattice."""
    idx = lambda x, y, z: (x * n + y) * n + z  # noqa: E731
    bonds = []
    for x in range(n):
        for y in range(n):
            for z in range(n):
                for dx, dy, dz in ((1, 0, 0), (0, 1, 0), (0, 0, 1)):
                    if x + dx < n and y + dy < n and z + dz < n:
                        bonds.append((idx(x, y, z), idx(x + dx, y + dy, z + dz)))
    return bonds


def crystal(path: Path, seconds: float = 10.0) -> Path:
    """64 spheres and 144 helices moving for ``seconds``: AtomicSolid's scene."""
    bonds = crystal_bonds()
    frames = []
    for k in range(int(round(seconds * FPS)) + 1):
        p = crystal_positions(k)
        a = np.array([p[j] - p[i] for i, j in bonds])
        length = np.linalg.norm(a, axis=1)
        spos = np.array([p[i] for i, _ in bonds])
        if k == 0:
            new = [solid(100 + i, "sphere", q, (0.3, 0, 0), (0.3, 0.3, 0.3), (1, 0, 0))
                   for i, q in enumerate(p)]
            new += [solid(200 + b, "helix", spos[b], a[b], (length[b], 0.16, 0.16),
                          (1, 0.7, 0.2), coils=10, thickness=0.016, ccw=True)
                    for b in range(len(bonds))]
            frames.append({"canvases": [canvas_record(rng=3.2, forward=(-0.3, -0.25, -1))],
                           "new": new})
        else:
            sids, hids = list(range(100, 164)), list(range(200, 200 + len(bonds)))
            frames.append({"set": {
                "pos": {"ids": sids + hids, "values": np.concatenate([p, spos]).ravel().tolist()},
                "axis": {"ids": hids, "values": a.ravel().tolist()},
                "size": {"ids": hids, "values": np.column_stack(
                    [length, np.full_like(length, 0.16), np.full_like(length, 0.16)]
                ).ravel().tolist()}}})
    return write(path, frames, program="AtomicSolid.py")


# AtomicSolid as a VPython program: 64 atoms and 144 springs (helices), every position,
# axis, up and size changing at every step, for the recorder itself to record
ATOMIC_SOLID = """\
from vpython import *
N, L, k, m, dt = 4, 1.0, 50.0, 1.0, 0.01
atoms = []
for x in range(N):
    for y in range(N):
        for z in range(N):
            a = sphere(pos=L*vector(x-1.5, y-1.5, z-1.5), radius=0.15, color=color.red)
            a.p = vector.random() * 0.3
            atoms.append(a)
def idx(x, y, z): return (x*N + y)*N + z
springs = []
for x in range(N):
    for y in range(N):
        for z in range(N):
            for d in ((1,0,0),(0,1,0),(0,0,1)):
                if x+d[0] < N and y+d[1] < N and z+d[2] < N:
                    i, j = idx(x,y,z), idx(x+d[0], y+d[1], z+d[2])
                    s = helix(pos=atoms[i].pos, axis=atoms[j].pos-atoms[i].pos, radius=0.08, coils=10, thickness=0.016, color=color.orange)
                    s.ends = (i, j)
                    springs.append(s)
t = 0
while t < 10:
    rate(100)
    for s in springs:
        i, j = s.ends
        F = k * (mag(s.axis) - L) * norm(s.axis)
        atoms[i].p = atoms[i].p + F*dt
        atoms[j].p = atoms[j].p - F*dt
    for a in atoms:
        a.pos = a.pos + a.p/m*dt
    for s in springs:
        i, j = s.ends
        s.pos = atoms[i].pos
        s.axis = atoms[j].pos - atoms[i].pos
    t += dt
"""
