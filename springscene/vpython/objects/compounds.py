"""VPython's ``compound`` and what it shares with ``extrusion`` and ``text``: a surface made once.

A :class:`fused` object takes a surface (:class:`Surface`: triangles in world
coordinates, with per-vertex normals and colours) once, keeps it as a unit mesh
(:class:`..geometry.placement.Mesh`) about an origin, and is from then on placed like any
other object by ``pos``, ``axis``, ``up`` and ``size``; the renderer draws kind
``"compound"`` from ``_mesh`` and :meth:`fused._vertex_rgb`
(:func:`..geometry.object_meshes.object_mesh`). The vertex colours are multiplied by ``color``, as
GlowScript's shaders do.

:class:`compound` takes its parts' surfaces as the renderer would draw them;
``extrusion`` (:mod:`.extrusions`) and ``text`` (:mod:`.text3d`) build theirs.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from ..core.attributes import Linked
from ..core.checks import _vec
from ..geometry.object_meshes import object_mesh
from .standard_attributes import standard
from ..geometry.placement import Mesh
from ..core.vectors import vector


class Surface(NamedTuple):
    """Triangles in world coordinates, with unit vertex normals and RGB colours in [0, 1]."""

    points: np.ndarray     # (n, 3)
    normals: np.ndarray    # (n, 3)
    triangles: np.ndarray  # (f, 3) int
    rgb: np.ndarray        # (n, 3) float

    @staticmethod
    def join(parts: list) -> Surface:
        """One surface of several, the triangles renumbered."""
        offsets = np.cumsum([0] + [len(p.points) for p in parts])
        return Surface(np.concatenate([p.points for p in parts]),
                       np.concatenate([p.normals for p in parts]),
                       np.concatenate([p.triangles + off for p, off in zip(parts, offsets)])
                       .astype(np.int64).reshape(-1, 3),
                       np.concatenate([p.rgb for p in parts]))


def bounding_size(points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Centre and size of the bounding box; a zero side is 0.001 of the largest (GlowScript)."""
    lo, hi = points.min(axis=0), points.max(axis=0)
    size = hi - lo
    size = np.where(size == 0, 0.001 * size.max(), size)
    return (lo + hi) / 2, np.where(size == 0, 1.0, size)


class fused(standard):
    """An object drawn from a surface taken once, placed by pos, axis, up and size.

    ``_take(surface, origin, size0)`` keeps ``(points - origin) / size0`` as the unit
    mesh; ``size = size0`` then draws the surface where it was, with ``pos`` at
    ``origin``. Turning it does not resize it (``axis`` and ``size`` are independent).
    """

    _kind = "compound"
    _axis_sets_size = False
    # The shininess each vertex of the surface carries. GlowScript draws a compound with
    # ``objectShininess * shininess`` (glow.min.js ``render_vertex``: parameters.x), the
    # second being the merged mesh's per-vertex value: a ``vertex`` object's (default 0.6,
    # as extrusion and 3D text are built of vertex objects), or a part's own shininess.
    _part_shininess = 0.6

    @property
    def _drawn_shininess(self) -> float:
        """The shininess the renderer lights this object with."""
        return float(self._shininess) * float(self._part_shininess)

    def _take(self, surface: Surface, origin, size0) -> None:
        origin, size0 = np.asarray(origin, dtype=float), np.asarray(size0, dtype=float)
        unit_normals = surface.normals * size0
        length = np.linalg.norm(unit_normals, axis=1)[:, None]
        unit_normals = unit_normals / np.where(length == 0, 1.0, length)
        self._mesh = Mesh((surface.points - origin) / size0, unit_normals,
                          np.asarray(surface.triangles, dtype=np.int64).reshape(-1, 3))
        self._size0 = size0
        self._origin = vector(*origin)
        self._rgb0 = np.asarray(surface.rgb, dtype=float)

    def _start(self, args: dict, size0) -> None:
        """``standard``'s set-up, then ``size = size0`` (or the program's ``size``)."""
        args.setdefault("pos", vector(self._origin))
        size = args.pop("size", None)
        standard.__init__(self, **args)
        self._size = vector(*size0)
        self._size._on_change = self._on_size_change
        self._fit_axis()
        if size is not None:
            self.size = size

    _tinted = True     # False: the vertex colours as made, until the program sets color

    _HOOKS = {**standard._HOOKS, "_color": "_retint"}

    def _retint(self) -> None:
        self._tinted = True
        self._touch()

    color = Linked(_vec, then="_retint", live=True)

    def _tint(self) -> np.ndarray:
        return np.array(self._color._xyz()) if self._tinted else np.ones(3)

    def _vertex_rgb(self) -> np.ndarray:
        return np.clip(np.rint(self._rgb0 * self._tint() * 255), 0, 255).astype(np.uint8)

    def _clone_args(self) -> dict:
        raise NotImplementedError

    def clone(self, **args) -> compound:
        """A copy sharing the surface (VPython's clone of an extrusion is a compound too)."""
        new = object.__new__(compound)
        new.__dict__.update({k: v for k, v in self.__dict__.items() if k.startswith("_")})
        for name in ("_pos", "_axis", "_up", "_size", "_color"):
            new.__dict__[name] = vector(self.__dict__[name])
        new._trail = None
        new.__dict__.pop("_stopped_trails", None)     # the original's stopped trails
        new.__dict__.pop("_frame", None)              # the copy is in the world
        new._register({"canvas": self._canvas})
        for name, value in args.items():
            setattr(new, name, value)
        return new

    origin = Linked(readonly='The compound "origin" attribute is read-only; '
                             'change "pos" instead.')

    def world_to_compound(self, v) -> vector:
        """A world point in the surface's own coordinates (VPython's, scaled by size0/size)."""
        X, Y, Z = self._local_axes()
        d = _vec(v, "v") - self._pos
        k = self._size0 / np.array(self._size._xyz())
        return self._origin + vector(d.dot(X) * k[0], d.dot(Y) * k[1], d.dot(Z) * k[2])

    def compound_to_world(self, v) -> vector:
        X, Y, Z = self._local_axes()
        v = _vec(v, "v") - self._origin
        k = np.array(self._size._xyz()) / self._size0
        return self._pos + X * (v.x * k[0]) + Y * (v.y * k[1]) + Z * (v.z * k[2])

    def _local_axes(self) -> tuple[vector, vector, vector]:
        X = self._axis.norm()
        Z = X.cross(self._up).norm()
        return X, Z.cross(X).norm(), Z


def _parts_shininess(objs: list, counts: list) -> float:
    """The per-vertex shininess of a merged mesh, as one number: the parts' (Mesh.merge:
    ``object.shininess * mesh.shininess``, a primitive's mesh having 1, a compound's its own
    product, a triangle's its vertices'). Parts that differ: the value most vertices carry."""
    weight: dict[float, int] = {}
    for obj, n in zip(objs, counts):
        verts = getattr(obj, "_verts", None)
        value = (np.mean([v._shininess for v in verts]) if verts
                 else getattr(obj, "_drawn_shininess", obj._shininess))
        weight[float(value)] = weight.get(float(value), 0) + n
    return max(weight, key=weight.get) if weight else 0.6


class compound(fused):
    """Objects fused into one, moved and turned as one (VPython's ``compound``).

    The parts' surfaces are taken once, in the world as they stand; the parts
    disappear. ``pos`` is the centre of their bounding box (or ``origin``), and
    ``size`` scales the whole from the size the parts had.
    """

    _INELIGIBLE = ("label", "curve", "points", "helix", "light")

    def __init__(self, objList, **args) -> None:
        objs = list(objList)
        if not objs:
            raise ValueError("compound needs a list of objects")
        for obj in objs:
            if getattr(obj, "_kind", None) in self._INELIGIBLE or obj.__class__.__name__ \
                    in self._INELIGIBLE:
                raise TypeError(f"A {type(obj).__name__} object cannot be used in a compound")
        parts = [object_mesh(o, uv=True) for o in objs]     # texpos kept, as mesh.js merges
        self._part_shininess = _parts_shininess(objs, [len(p[0]) for p in parts])
        surface = Surface.join([Surface(p[0], p[1], p[2], p[3].astype(float) / 255)
                                for p in parts])
        uv = np.concatenate([p[4] for p in parts])
        lo, hi = surface.points.min(axis=0), surface.points.max(axis=0)
        origin = args.pop("origin", None)
        centre = (lo + hi) / 2 if origin is None else np.array(_vec(origin, "origin")._xyz())
        size0 = np.maximum(hi - lo, 1e-12)
        self._take(surface, centre, size0)
        self._mesh = self._mesh._replace(uv=uv)
        for obj in objs:
            obj.visible = False
        self._start(args, hi - lo)
