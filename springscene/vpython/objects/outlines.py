"""VPython's ``shapes`` and ``paths`` libraries: 2D outlines to extrude, 3D paths to extrude along.

``shapes.circle(radius=2)`` is a list of ``[x, y]`` points in the xy plane, the
last equal to the first; a shape with ``thickness`` (a frame) is ``[outer, inner]``.
``paths.circle(radius=2)`` is the same figure as a list of :class:`..core.vectors.vector` in the
xz plane (``[x, y]`` goes to ``vector(x, 0, -y)``, then turned so that y becomes
``up``, then moved by ``pos``). Both are plain lists a program may edit.

The figures, their defaults and the order of their options (``pos`` is added
first, then ``rotate`` turns about ``pos``, then ``scale``/``xscale``/``yscale``
scale about the origin, then ``roundness`` rounds the corners, ``invert`` making
them chamfers) are those of VPython 7's ``vpython/shapespaths.py`` and GlowScript's
``lib/glow/shapespaths.js``. Where the two differ, or where both drop a requested
option by mistake, the documented behaviour is kept: ``scale`` applies to every
figure (the Python port drops it for ngons, stars, arcs and lines), ``pentagon``
points up (the documentation's picture and GlowScript), a frame is moved and
scaled once, and ``ellipse`` takes ``thickness``. Gears are in :mod:`.gears`.
"""

from __future__ import annotations

import math

import numpy as np

from . import gears
from ..core.vectors import vector

NP_DEFAULT = 64        # points in a full circle, ellipse or arc (VPython's npdefault)
ROUND_SEGMENTS = 16    # points inside each rounded corner


# -- what every figure shares ---------------------------------------------------------------

def _xy(pos) -> np.ndarray:
    return np.array([float(pos[0]), float(pos[1])])


def closed(cp: np.ndarray) -> np.ndarray:
    """The outline with its first point repeated at the end, as VPython's shapes are."""
    cp = np.asarray(cp, dtype=float)
    return cp if len(cp) and np.array_equal(cp[0], cp[-1]) else np.vstack([cp, cp[:1]])


def rotated(cp: np.ndarray, about, angle: float) -> np.ndarray:
    """Points turned by ``angle`` counter-clockwise about the point ``about``."""
    c, s = math.cos(angle), math.sin(angle)
    d = np.asarray(cp, dtype=float) - _xy(about)
    return np.column_stack([c * d[:, 0] - s * d[:, 1], s * d[:, 0] + c * d[:, 1]]) + _xy(about)


def _scales(scale: float, xscale: float, yscale: float) -> tuple[float, float]:
    return (scale, scale) if scale != 1 else (xscale, yscale)


def roundc(cp: np.ndarray, roundness: float = 0.1, invert: bool = False,
           nseg: int = ROUND_SEGMENTS) -> np.ndarray:
    """Corners replaced by arcs of radius ``roundness`` x the shortest side (``invert``: inward).

    VPython's ``roundc``: the outline is made counter-clockwise; each corner
    becomes ``nseg`` points on the arc tangent to both sides.
    """
    p = np.asarray(cp, dtype=float)[:-1]
    edges = np.roll(p, -1, axis=0) - p
    if np.sum(edges[:, 0] * np.roll(edges, -1, axis=0)[:, 1]
              - edges[:, 1] * np.roll(edges, -1, axis=0)[:, 0]) < 0:
        p = p[::-1]
        edges = np.roll(p, -1, axis=0) - p
    r = roundness * float(np.min(np.linalg.norm(edges, axis=1)))
    out = []
    for i in range(len(p)):
        out.extend(_round_corner(p[(i + 1) % len(p)], edges[i], edges[(i + 1) % len(p)],
                                 r, invert, nseg))
    out = np.array(out)
    return np.vstack([out[-1:], out])          # starts where the last bend ends: closed


def _round_corner(corner, v1, v2, r, invert, nseg) -> list:
    """The points of one rounded corner: end of the side, the arc, start of the next side."""
    u1, u2 = v1 / np.linalg.norm(v1), v2 / np.linalg.norm(v2)
    turn = u1[0] * u2[1] - u1[1] * u2[0]
    theta = math.acos(max(-1.0, min(1.0, float(u1 @ u2))))
    if theta < 1e-9:
        return [corner]
    d = r * math.tan(theta / 2)
    p1, p2 = corner - u1 * d, corner + u2 * d
    inward = np.array([-u1[1], u1[0]]) * math.copysign(1.0, turn)
    centre = p1 + r * inward
    step = math.copysign(theta / (nseg + 1), turn)
    if invert:
        mid = (p1 + p2) / 2
        centre, step = 2 * mid - centre, -step
    a = step * np.arange(1, nseg + 1)
    d = p1 - centre
    arc = centre + np.column_stack([np.cos(a) * d[0] - np.sin(a) * d[1],
                                    np.sin(a) * d[0] + np.cos(a) * d[1]])
    return [p1, *arc, p2]


def _finish(cp, pos, rotate=0.0, scale=1.0, xscale=1.0, yscale=1.0, roundness=0.0,
            invert=False) -> np.ndarray:
    """VPython's tail of every figure: turn about ``pos``, scale about the origin, round."""
    if rotate:
        cp = rotated(cp, pos, rotate)
    xs, ys = _scales(scale, xscale, yscale)
    if xs != 1 or ys != 1:
        cp = np.asarray(cp) * [xs, ys]
    if roundness > 0:
        cp = roundc(cp, roundness, invert)
    return np.asarray(cp, dtype=float)


def _out(*contours) -> list:
    """Plain nested lists: one outline, or ``[outer, inner]`` for a frame."""
    if len(contours) == 1:
        return contours[0].tolist()
    return [c.tolist() for c in contours]


# -- the shapes ---------------------------------------------------------------------------

def _rect_points(pos, width, height) -> np.ndarray:
    w2, h2 = width / 2, height / 2
    return np.array([[w2, -h2], [w2, h2], [-w2, h2], [-w2, -h2], [w2, -h2]]) + _xy(pos)


def _trapezoid_points(pos, width, height, top) -> np.ndarray:
    w2, h2, t2 = width / 2, height / 2, top / 2
    return np.array([[w2, -h2], [t2, h2], [-t2, h2], [-w2, -h2], [w2, -h2]]) + _xy(pos)


def _ngon_points(pos, np_, length) -> np.ndarray:
    radius = length / 2 / math.sin(math.pi / np_)
    a = 2 * math.pi * np.arange(np_) / np_
    return closed(np.column_stack([radius * np.cos(a), radius * np.sin(a)]) + _xy(pos))


def _star_points(pos, n, radius, iradius) -> np.ndarray:
    theta = math.pi / n * np.arange(2 * n)
    r = np.where(np.arange(2 * n) % 2 == 0, radius, iradius)
    return closed(np.column_stack([-r * np.sin(theta), r * np.cos(theta)]) + _xy(pos))


def _arc_points(pos, radius, angle1, angle2, np_) -> np.ndarray:
    nseg = int(math.floor(abs(angle2 - angle1) / (2 * math.pi / np_))) + 1
    a = angle1 + (angle2 - angle1) / nseg * np.arange(nseg + 1)
    return np.column_stack([radius * np.cos(a), radius * np.sin(a)]) + _xy(pos)


def _circle_points(pos, radius, np_, angle1, angle2, corner=None) -> np.ndarray:
    """VPython's circle: ``np`` points round a full circle; a part of one starts at its corner."""
    whole = angle1 == 0 and angle2 == 2 * math.pi
    nseg = int(math.floor(abs((angle2 - angle1) / (2 * math.pi / np_) + 0.5)))
    seg = (angle2 - angle1) / nseg
    a = angle1 + seg * np.arange(nseg if whole else nseg + 1)
    cp = np.column_stack([radius * np.cos(a), radius * np.sin(a)]) + _xy(pos)
    if not whole:
        cp = np.vstack([_xy(pos if corner is None else corner), cp])
    return closed(cp)


class ShapeLibrary:
    """VPython's ``shapes``: closed 2D outlines, lists of ``[x, y]``."""

    def rectangle(self, pos=(0, 0), width=1, height=None, rotate=0.0, thickness=0,
                  roundness=0.0, invert=False, scale=1.0, xscale=1.0, yscale=1.0) -> list:
        height = width if height is None else height
        outer = _rect_points(pos, width, height)
        finish = dict(rotate=rotate, scale=scale, xscale=xscale, yscale=yscale,
                      roundness=roundness, invert=invert)
        if not thickness:
            return _out(_finish(outer, pos, **finish))
        t = min(height, width) * thickness * 2
        inner = _rect_points(pos, width - t, height - t)
        return _out(_finish(outer, pos, **finish), _finish(inner, pos, **finish))

    def cross(self, pos=(0, 0), width=1, rotate=0.0, thickness=0.2, roundness=0.0,
              invert=False, scale=1.0, xscale=1.0, yscale=1.0) -> list:
        w2, t2 = width / 2, thickness / 2
        cp = np.array([[w2, -t2], [w2, t2], [t2, t2], [t2, w2], [-t2, w2], [-t2, t2],
                       [-w2, t2], [-w2, -t2], [-t2, -t2], [-t2, -w2], [t2, -w2], [t2, -t2],
                       [w2, -t2]]) + _xy(pos)
        return _out(_finish(cp, pos, rotate, scale, xscale, yscale, roundness, invert))

    def trapezoid(self, pos=(0, 0), width=2, height=1, top=None, rotate=0.0, thickness=0,
                  roundness=0.0, invert=False, scale=1.0, xscale=1.0, yscale=1.0) -> list:
        top = width / 2 if top is None else top
        finish = dict(rotate=rotate, scale=scale, xscale=xscale, yscale=yscale,
                      roundness=roundness, invert=invert)
        outer = _trapezoid_points(pos, width, height, top)
        if not thickness:
            return _out(_finish(outer, pos, **finish))
        t = min(height, top) * thickness * 2
        angle = math.atan((width - top) / 2 / height)
        db = t / math.cos(angle)
        inner = _trapezoid_points(pos, width - db - t * math.tan(angle), height - t,
                                  top - (db - t * math.tan(angle)))
        return _out(_finish(outer, pos, **finish), _finish(inner, pos, **finish))

    def circle(self, pos=(0, 0), radius=0.5, np=NP_DEFAULT, rotate=0.0, thickness=0,
               angle1=0.0, angle2=2 * math.pi, scale=1.0, xscale=1.0, yscale=1.0,
               iradius=None) -> list:
        outer = _circle_points(pos, radius, np, angle1, angle2)
        if not thickness and iradius is None:
            return _out(_finish(outer, pos, rotate, scale, xscale, yscale))
        inner = self._inner_circle(pos, radius, np, angle1, angle2,
                                   radius - radius * thickness if iradius is None else iradius)
        return _out(_finish(outer, pos, rotate, scale, xscale, yscale),
                    _finish(inner, pos, rotate, scale, xscale, yscale))

    @staticmethod
    def _inner_circle(pos, radius, np_, angle1, angle2, iradius) -> np.ndarray:
        """VPython's ``circframe`` hole: a smaller circle, or a part one moved to keep the width."""
        if angle1 == 0 and angle2 == 2 * math.pi:
            return _circle_points(pos, iradius, np_, angle1, angle2)
        t = radius - iradius
        mid = (angle1 + angle2) / 2
        offset = t / math.sin((angle2 - angle1) / 2)
        corner = _xy(pos) + offset * np.array([math.cos(mid), math.sin(mid)])
        da = math.asin(t / iradius)
        return _circle_points(pos, iradius, np_, angle1 + da, angle2 - da, corner)

    def ellipse(self, pos=(0, 0), width=1, height=None, np=NP_DEFAULT, rotate=0.0,
                thickness=0, angle1=0.0, angle2=2 * math.pi, scale=1.0, xscale=1.0,
                yscale=1.0) -> list:
        height = 0.5 * width if height is None else height
        if scale != 1:
            xscale = yscale = scale
        return self.circle(pos=pos, radius=width, np=np, rotate=rotate, thickness=thickness,
                           angle1=angle1, angle2=angle2, xscale=xscale,
                           yscale=yscale * height / width)

    def arc(self, pos=(0, 0), radius=0.5, np=NP_DEFAULT, rotate=0.0, thickness=None,
            angle1=0.0, angle2=2 * math.pi, scale=1.0, xscale=1.0, yscale=1.0, path=False) -> list:
        thickness = 0.01 * radius if thickness is None else thickness
        cp = _arc_points(pos, radius, angle1, angle2, np)
        if not path:
            inner = _arc_points(pos, radius - thickness, angle1, angle2, np)
            cp = closed(_stack(cp, inner[::-1]))
        return _out(_finish(cp, pos, rotate, scale, xscale, yscale))

    def line(self, pos=(0, 0), np=2, rotate=0.0, thickness=None, start=(0, 0), end=(0, 1),
             scale=1.0, xscale=1.0, yscale=1.0) -> list:
        cp = _line_points(pos, start, end, np, thickness)
        return _out(_finish(cp, pos, rotate, scale, xscale, yscale))

    def ngon(self, pos=(0, 0), length=1, rotate=0.0, thickness=0, np=3, roundness=0.0,
             invert=False, scale=1.0, xscale=1.0, yscale=1.0, radius=None) -> list:
        if np < 3:
            raise AttributeError("number of sides can not be less than 3")
        if radius is not None:
            length = 2 * radius * math.sin(math.pi / np)
        finish = dict(rotate=rotate, scale=scale, xscale=xscale, yscale=yscale,
                      roundness=roundness, invert=invert)
        outer = _ngon_points(pos, np, length)
        if not thickness:
            return _out(_finish(outer, pos, **finish))
        t = length * (0.1 if thickness is None else thickness)
        inner = _ngon_points(pos, np, length - 2 * t / math.tan(math.pi * (0.5 - 1 / np)))
        return _out(_finish(outer, pos, **finish), _finish(inner, pos, **finish))

    def triangle(self, rotate=0.0, **args) -> list:
        return self.ngon(np=3, rotate=rotate - math.pi / 6, **args)

    def pentagon(self, rotate=0.0, **args) -> list:
        return self.ngon(np=5, rotate=rotate + math.pi / 10, **args)

    def hexagon(self, rotate=0.0, **args) -> list:
        return self.ngon(np=6, rotate=rotate, **args)

    def octagon(self, rotate=0.0, **args) -> list:
        return self.ngon(np=8, rotate=rotate + math.pi / 8, **args)

    def star(self, pos=(0, 0), rotate=0.0, thickness=0, radius=1, n=5, iradius=None,
             roundness=0.0, invert=False, scale=1.0, xscale=1.0, yscale=1.0) -> list:
        iradius = 0.5 * radius if iradius is None else iradius
        finish = dict(rotate=rotate, scale=scale, xscale=xscale, yscale=yscale,
                      roundness=roundness, invert=invert)
        outer = _star_points(pos, n, radius, iradius)
        if not thickness:
            return _out(_finish(outer, pos, **finish))
        t = 0.2 * radius if thickness is None else thickness * 2 * iradius
        inner = _star_points(pos, n, radius - t, (radius - t) * iradius / radius)
        return _out(_finish(outer, pos, **finish), _finish(inner, pos, **finish))

    def points(self, pos=(), rotate=0.0, path=False, roundness=0.0, invert=False, scale=1.0,
               xscale=1.0, yscale=1.0) -> list:
        cp = np.array([[float(p[0]), float(p[1])] for p in pos])
        if not path:
            cp = closed(cp)
        return _out(_finish(cp, (0, 0), rotate, scale, xscale, yscale, roundness, invert))

    pointlist = points

    def gear(self, pos=(0, 0), n=20, radius=1, phi=20, addendum=None, dedendum=None,
             fradius=None, rotate=0.0, scale=1.0, res=1, bevel=0) -> list:
        return gears.gear(pos, n, radius, phi, addendum, dedendum, fradius, rotate, scale,
                            res).tolist()

    def rackgear(self, pos=(0, 0), n=30, radius=5.0, phi=20.0, addendum=0.4, dedendum=0.5,
                 fradius=0.1, rotate=0.0, scale=1.0, length=10 * math.pi, res=1, bevel=0.05,
                 depth=0.4 + 0.6 + 0.1) -> list:
        return gears.rackgear(pos, n, radius, phi, addendum, dedendum, fradius, rotate,
                                scale, length, res, bevel, depth).tolist()


def _stack(*parts) -> np.ndarray:
    return np.vstack(parts)


def _line_points(pos, start, end, n: int, thickness) -> np.ndarray:
    """VPython's line shape: ``n`` points from start to end, back along a parallel line."""
    v = _xy(end) - _xy(start)
    length = float(np.linalg.norm(v))
    thickness = 0.01 * length if thickness is None else thickness
    side = np.array([v[1], -v[0]]) / length * thickness
    cp = _xy(start) + _xy(pos) + v * (np.arange(n) / math.floor(n - 1))[:, None]
    return closed(np.vstack([cp, (cp + side)[::-1]]))


# -- the paths ----------------------------------------------------------------------------

_UP0 = vector(0, 1, 0)


def convert(pos=(0, 0, 0), up=(0, 1, 0), points=(), closed_=True) -> list[vector]:
    """2D points as 3D path points: ``[x, y]`` to ``pos + turn(vector(x, 0, -y))``.

    The turn takes (0, 1, 0) to ``up`` (VPython's ``convert``); a closed figure
    ends where it starts.
    """
    pos, up = vector(*_triple(pos)), vector(*_triple(up)).norm()
    angle = math.acos(max(-1.0, min(1.0, up.dot(_UP0))))
    axis = _UP0.cross(up)
    if angle > 0 and axis.mag2 == 0:
        axis = vector(1, 0, 0)                  # up = (0, -1, 0): a half turn about x
    pts = []
    for p in points:
        v = vector(float(p[0]), 0, -float(p[1]))
        pts.append(pos + (v.rotate(angle=angle, axis=axis) if angle > 0 else v))
    if closed_ and pts and not pts[-1].equals(pts[0]):
        pts.append(vector(pts[0]))
    return pts


def _triple(v) -> tuple[float, float, float]:
    return (float(v[0]), float(v[1]), float(v[2])) if not isinstance(v, vector) else v._xyz()


def _no_thickness(thickness, what: str) -> None:
    if thickness is not None:
        raise AttributeError(f"Thickness is not allowed in a {what} path")


class PathLibrary:
    """VPython's ``paths``: the shapes' figures as lists of vectors in the xz plane."""

    def rectangle(self, pos=(0, 0, 0), width=6, height=None, rotate=0.0, thickness=None,
                  roundness=0.0, invert=False, scale=1.0, xscale=1.0, yscale=1.0,
                  up=(0, 1, 0)) -> list[vector]:
        _no_thickness(thickness, "rectangular")
        c = shapes.rectangle(width=width, height=height, rotate=rotate, roundness=roundness,
                             invert=invert, scale=scale, xscale=xscale, yscale=yscale)
        return convert(pos, up, c)

    def cross(self, pos=(0, 0, 0), width=5, thickness=2, rotate=0.0, roundness=0.0,
              invert=False, scale=1.0, xscale=1.0, yscale=1.0,
                  up=(0, 1, 0)) -> list[vector]:
        c = shapes.cross(width=width, rotate=rotate, thickness=thickness, roundness=roundness,
                         invert=invert, scale=scale, xscale=xscale, yscale=yscale)
        return convert(pos, up, c)

    def trapezoid(self, pos=(0, 0, 0), width=6, height=3, top=None, rotate=0.0,
                  thickness=None, roundness=0.0, invert=False, scale=1.0, xscale=1.0,
                  yscale=1.0,
                  up=(0, 1, 0)) -> list[vector]:
        _no_thickness(thickness, "trapezoidal")
        c = shapes.trapezoid(width=width, height=height, top=top, rotate=rotate,
                             roundness=roundness, invert=invert, scale=scale, xscale=xscale,
                             yscale=yscale)
        return convert(pos, up, c)

    def circle(self, pos=(0, 0, 0), radius=3, np=32, thickness=None, scale=1.0, xscale=1.0,
               yscale=1.0,
                  up=(0, 1, 0)) -> list[vector]:
        _no_thickness(thickness, "circular")
        c = shapes.circle(radius=radius, np=np, scale=scale, xscale=xscale, yscale=yscale)
        return convert(pos, up, c)

    def line(self, start=(0, 0, 0), end=(0, 0, -1), np=2) -> list[vector]:
        if np < 2:
            raise AttributeError("The minimum value of np is 2 (one segment)")
        start, end = vector(*_triple(start)), vector(*_triple(end))
        step = (end - start) / (np - 1)
        return [start + i * step for i in range(np)]

    def arc(self, pos=(0, 0, 0), radius=3, np=32, rotate=0.0, angle1=0.0, angle2=math.pi,
            thickness=None, scale=1.0, xscale=1.0, yscale=1.0,
                  up=(0, 1, 0)) -> list[vector]:
        _no_thickness(thickness, "circular")
        c = shapes.arc(radius=radius, angle1=angle1, angle2=angle2, rotate=rotate, np=np,
                       scale=scale, xscale=xscale, yscale=yscale, path=True)
        return convert(pos, up, c, closed_=False)

    def ellipse(self, pos=(0, 0, 0), width=6, height=None, np=32, thickness=None, scale=1.0,
                xscale=1.0, yscale=1.0,
                  up=(0, 1, 0)) -> list[vector]:
        _no_thickness(thickness, "elliptical")
        c = shapes.ellipse(width=width, height=height, np=np, scale=scale, xscale=xscale,
                           yscale=yscale)
        return convert(pos, up, c)

    def ngon(self, pos=(0, 0, 0), np=3, length=6, radius=None, rotate=0.0, thickness=None,
             roundness=0.0, invert=False, scale=1.0, xscale=1.0, yscale=1.0,
                  up=(0, 1, 0)) -> list[vector]:
        _no_thickness(thickness, "ngon")
        c = shapes.ngon(np=np, length=length, radius=radius, rotate=rotate,
                        roundness=roundness, invert=invert, scale=scale, xscale=xscale,
                        yscale=yscale)
        return convert(pos, up, c)

    def _polygon(self, figure, what: str, pos, length, rotate, thickness, roundness, invert,
                 scale, xscale, yscale, up) -> list[vector]:
        _no_thickness(thickness, what)
        c = figure(length=length, rotate=rotate, roundness=roundness, invert=invert,
                   scale=scale, xscale=xscale, yscale=yscale)
        return convert(pos, up, c)

    def triangle(self, pos=(0, 0, 0), length=6, rotate=0.0, thickness=None, roundness=0.0,
                 invert=False, scale=1.0, xscale=1.0, yscale=1.0,
                  up=(0, 1, 0)) -> list[vector]:
        return self._polygon(shapes.triangle, "triangular", pos, length, rotate, thickness,
                             roundness, invert, scale, xscale, yscale, up)

    def pentagon(self, pos=(0, 0, 0), length=6, rotate=0.0, thickness=None, roundness=0.0,
                 invert=False, scale=1.0, xscale=1.0, yscale=1.0,
                  up=(0, 1, 0)) -> list[vector]:
        return self._polygon(shapes.pentagon, "pentagonal", pos, length, rotate, thickness,
                             roundness, invert, scale, xscale, yscale, up)

    def hexagon(self, pos=(0, 0, 0), length=6, rotate=0.0, thickness=None, roundness=0.0,
                invert=False, scale=1.0, xscale=1.0, yscale=1.0,
                  up=(0, 1, 0)) -> list[vector]:
        return self._polygon(shapes.hexagon, "hexagonal", pos, length, rotate, thickness,
                             roundness, invert, scale, xscale, yscale, up)

    def octagon(self, pos=(0, 0, 0), length=6, rotate=0.0, thickness=None, roundness=0.0,
                invert=False, scale=1.0, xscale=1.0, yscale=1.0,
                  up=(0, 1, 0)) -> list[vector]:
        return self._polygon(shapes.octagon, "octagonal", pos, length, rotate, thickness,
                             roundness, invert, scale, xscale, yscale, up)

    def star(self, pos=(0, 0, 0), radius=3, n=5, iradius=None, rotate=0.0, thickness=None,
             roundness=0.0, invert=False, scale=1.0, xscale=1.0, yscale=1.0,
                  up=(0, 1, 0)) -> list[vector]:
        _no_thickness(thickness, "star")
        c = shapes.star(n=n, radius=radius, iradius=iradius, rotate=rotate,
                        roundness=roundness, invert=invert, scale=scale, xscale=xscale,
                        yscale=yscale)
        return convert(pos, up, c)

    def pointlist(self, pos=(), rotate=0.0, thickness=None, roundness=0.0, invert=False,
                  scale=1.0, xscale=1.0, yscale=1.0,
                  up=(0, 1, 0)) -> list[vector]:
        _no_thickness(thickness, "pointlist")
        pts = [[float(p[0]), float(p[1])] for p in pos]
        was_closed = bool(pts) and pts[-1] == pts[0]
        c = shapes.points(pos=pts, rotate=rotate, roundness=roundness, invert=invert,
                          scale=scale, xscale=xscale, yscale=yscale, path=not was_closed)
        return convert((0, 0, 0), up, c, closed_=was_closed)


shapes = ShapeLibrary()
paths = PathLibrary()

__all__ = ["shapes", "paths", "ShapeLibrary", "PathLibrary", "convert", "roundc", "rotated",
           "closed"]
