"""VPython's gear outlines: ``shapes.gear`` (an involute spur gear) and ``shapes.rackgear``.

The tooth profiles are those of VPython 7's ``vpython/shapespaths.py``
(``ToothOutline``, ``RackOutline``, after Stefano Selleri's "Blender Mechanical
Gears"): a tooth's bottom land, fillet, flank, involute, bevel and top land, mirrored,
then repeated round the gear (or along the rack). Points closer than 0.1 % of the
radius to the one before are dropped, as VPython does for its triangulator.
Used by :mod:`.outlines`.
"""

from __future__ import annotations

import math

import numpy as np


def _radii(radius: float, addendum: float, dedendum: float, fradius: float, bevel: float,
           phi: float) -> dict:
    return {"bottom": radius - dedendum - fradius, "ded": radius - dedendum,
            "base": radius * math.cos(phi * math.pi / 180), "bevel": radius + addendum - bevel,
            "add": radius + addendum}


def _involute_angle(u: float) -> float:
    return math.atan((math.sin(u) - u * math.cos(u)) / (math.cos(u) + u * math.sin(u)))


def _arc(cx: float, cy: float, r: float, start: float, stop: float, n: int,
         first: int = 1) -> list:
    """``n`` points of a circle of radius r about (cx, cy), from step ``first`` to ``stop``."""
    th = start + (stop - start) * np.arange(first, first + n) / n
    return list(zip(cx + r * np.cos(th), cy + r * np.sin(th)))


def tooth_outline(n: int = 30, res: int = 1, phi: float = 20, radius: float = 50,
                  addendum: float = 0.4, dedendum: float = 0.5, fradius: float = 0.1,
                  bevel: float = 0.05) -> np.ndarray:
    """One tooth of an involute gear centred on +x, as VPython's ``ToothOutline``."""
    R = _radii(radius, addendum, dedendum, fradius, bevel, phi)
    pitch = n / (2 * radius)
    thickness, circular = 1.5708 / pitch, math.pi / pitch
    u1 = math.sqrt((1 - math.cos(phi * math.pi / 180)) / math.cos(phi * math.pi / 180))
    u2 = math.sqrt(R["bevel"] ** 2 / R["ded"] ** 2 - 1)
    a3 = _involute_angle(u1) + thickness / (radius * 2)
    a0 = circular / (radius * 2)
    a1 = a3 + fradius / R["ded"]
    a2 = a3
    a4 = a3 - _involute_angle(u2) - bevel / R["add"]
    N = int(res)
    th = (a1 - a0) * np.arange(2 * N) / (2 * N - 1) + a0
    pts = list(zip(R["bottom"] * np.cos(th), R["bottom"] * np.sin(th)))
    pts += _arc(R["ded"] * math.cos(a1), R["ded"] * math.sin(a1), fradius,
                math.pi + a1, math.pi + a1 + math.pi / 2 + a2 - a1, N)
    r = (R["base"] - R["ded"]) * np.arange(1, N + 1) / N + R["ded"]
    pts += list(zip(r * math.cos(a2), r * math.sin(a2)))
    r = (R["bevel"] - R["base"]) * np.arange(1, 3 * N + 1) / (3 * N) + R["base"]
    u = np.sqrt(r * r / R["base"] ** 2 - 1)
    xp = R["base"] * (np.cos(u) + u * np.sin(u))
    yp = -R["base"] * (np.sin(u) - u * np.cos(u))
    pts += list(zip(xp * math.cos(a2) - yp * math.sin(a2), xp * math.sin(a2) + yp * math.cos(a2)))
    pts += _tooth_tip(pts[-1], -float(u[-1]) + a3 + math.pi / 2, a4, bevel, N)
    return _mirrored(np.array(pts))


def _tooth_tip(p0, auxth: float, a4: float, bevel: float, N: int) -> list:
    """The bevel from the involute's end, then the top land to the tooth's centre line."""
    ra = bevel / (1 - math.cos(auxth - a4)) if bevel else 0.0
    pts = _arc(p0[0] - ra * math.cos(auxth), p0[1] - ra * math.sin(auxth), ra, auxth, a4, N)
    p0 = pts[-1]
    a4 = math.atan(p0[1] / p0[0])
    return pts + _arc(0.0, 0.0, math.hypot(p0[0], p0[1]), a4, 0.0, N)


def _mirrored(pts: np.ndarray) -> np.ndarray:
    """The half tooth followed by its mirror image in the x axis, back to front."""
    back = pts[-2::-1] * [1, -1]
    return np.vstack([pts, back])


def _distinct(g: np.ndarray, tol: float) -> np.ndarray:
    """Drop points within ``tol`` of the one kept before, and a-b-a spikes; then close."""
    keep = [g[0]]
    for p in g[1:]:
        if np.abs(p - keep[-1]).max() < tol:
            continue
        if len(keep) >= 2 and np.abs(p - keep[-2]).max() < tol:
            keep.pop()
            continue
        keep.append(p)
    out = np.array(keep)
    return out if np.array_equal(out[0], out[-1]) else np.vstack([out, out[:1]])


def gear(pos=(0, 0), n: int = 20, radius: float = 1, phi: float = 20, addendum=None,
         dedendum=None, fradius=None, rotate: float = 0.0, scale: float = 1.0,
         res: int = 1) -> np.ndarray:
    """VPython's ``shapes.gear``: ``n`` teeth round a circle of ``radius``, closed."""
    addendum = 0.08 * radius if addendum is None else addendum
    dedendum = 0.1 * radius if dedendum is None else dedendum
    fradius = 0.02 * radius if fradius is None else fradius
    tooth = tooth_outline(n, res, phi, radius, addendum, dedendum, fradius, bevel=0)
    turns = -2 * math.pi * np.arange(n) / n
    c, s = np.cos(turns)[:, None], np.sin(turns)[:, None]
    g = np.stack([tooth[:, 0] * c - tooth[:, 1] * s + pos[0],
                  tooth[:, 0] * s + tooth[:, 1] * c + pos[1]], axis=-1).reshape(-1, 2)
    g = g * scale
    if rotate:
        cr, sr = math.cos(rotate), math.sin(rotate)
        d = g - np.asarray(pos, dtype=float)
        g = np.column_stack([cr * d[:, 0] - sr * d[:, 1], sr * d[:, 0] + cr * d[:, 1]]) + pos
    return _distinct(g, 0.001 * radius)


def rack_outline(n: int = 30, res: int = 1, phi: float = 20, radius: float = 5,
                 addendum: float = 0.4, dedendum: float = 0.5, fradius: float = 0.1,
                 bevel: float = 0.05) -> np.ndarray:
    """One tooth of a straight rack along y, as VPython's ``RackOutline``."""
    pa = phi * math.pi / 180
    pitch = n / (2 * radius)
    half = 1.5708 / pitch / 2
    x_ded, x_add = -dedendum, addendum
    y1 = half + (-x_ded + fradius * math.sin(pa)) * math.tan(pa) + fradius * math.cos(pa)
    y4 = half - (x_add - bevel) * math.tan(pa) - math.cos(pa) / (1 - math.sin(pa)) * bevel
    N = int(res)
    y0 = math.pi / pitch / 2
    ys = (y1 - y0) * np.arange(1 if fradius else 0, 2 * N) / (2 * N - 1) + y0
    pts = [(x_ded - fradius, y) for y in ys]
    pts += _arc(x_ded, y1, fradius, math.pi, math.pi + math.pi / 2 - pa, N)
    xd = x_ded - fradius * math.sin(pa)
    x = (x_add - bevel - xd) * np.arange(1, 4 * N + 1) / (4 * N) + xd
    pts += list(zip(x, half - math.tan(pa) * x))
    ra = bevel / (1 - math.sin(pa))
    pts += _arc(x_add - ra, y4, ra, math.pi / 2 - pa, 0.0, N)
    pts += [(x_add, -y4 * k / N + y4) for k in range(1, N + 1)]
    return _mirrored(np.array(pts))


def rackgear(pos=(0, 0), n: int = 30, radius: float = 5.0, phi: float = 20.0,
             addendum: float = 0.4, dedendum: float = 0.5, fradius: float = 0.1,
             rotate: float = 0.0, scale: float = 1.0, length: float = 10 * math.pi,
             res: int = 1, bevel: float = 0.05, depth: float = 1.1) -> np.ndarray:
    """VPython's ``shapes.rackgear``: teeth along y for ``length``, a back ``depth`` deep."""
    tooth = rack_outline(n, res, phi, radius, addendum, dedendum, fradius, bevel)
    pitch = tooth[0, 1] - tooth[-1, 1]
    count = int(math.floor(length / pitch))
    g = np.vstack([tooth + [0, -i * pitch] for i in range(count)]) + np.asarray(pos, float)
    g = np.vstack([g, [g[-1, 0] - depth, g[-1, 1]], [g[0, 0] - depth, g[0, 1]]])
    g = g + (np.asarray(pos, float) - (g.min(axis=0) + g.max(axis=0)) / 2)
    g = g * scale
    if rotate:
        cr, sr = math.cos(rotate), math.sin(rotate)
        d = g - np.asarray(pos, dtype=float)
        g = np.column_stack([cr * d[:, 0] - sr * d[:, 1], sr * d[:, 0] + cr * d[:, 1]]) + pos
    return _distinct(g, 1e-9 * max(radius, 1.0))
