"""VPython's ``compound``: objects fused into one mesh, moved and turned as one.

The parts' surfaces are taken once, as the renderer would draw them
(:func:`.draw.object_mesh`), into a unit mesh (:class:`.shapes.Mesh`) that is then
placed like any other object by ``pos``, ``axis``, ``up`` and ``size``.
"""

from __future__ import annotations

import numpy as np

from .checks import _vec
from .draw import object_mesh
from .objects import standard
from .placement import Mesh
from .vector import vector


class compound(standard):
    """Objects fused into one, moved and turned as one (VPython's ``compound``).

    The parts' surfaces are taken once, in the world as they stand; the parts
    disappear. ``pos`` is the centre of their bounding box (or ``origin``), and
    ``size`` scales the whole from the size the parts had.
    """

    _kind = "compound"
    _axis_sets_size = False          # turning a compound does not resize it
    _INELIGIBLE = ("label", "curve", "points", "helix", "light")

    def __init__(self, objList, **args) -> None:
        objs = list(objList)
        if not objs:
            raise ValueError("compound needs a list of objects")
        for obj in objs:
            if getattr(obj, "_kind", None) in self._INELIGIBLE or obj.__class__.__name__ \
                    in self._INELIGIBLE:
                raise TypeError(f"A {type(obj).__name__} object cannot be used in a compound")
        parts = [object_mesh(o) for o in objs]
        points = np.concatenate([p[0] for p in parts])
        normals = np.concatenate([p[1] for p in parts])
        offsets = np.cumsum([0] + [len(p[0]) for p in parts])
        triangles = np.concatenate([p[2] + off for p, off in zip(parts, offsets)])
        rgb = np.concatenate([p[3] for p in parts])
        lo, hi = points.min(axis=0), points.max(axis=0)
        origin = args.pop("origin", None)
        centre = (lo + hi) / 2 if origin is None else np.array(_vec(origin, "origin")._xyz())
        size0 = np.maximum(hi - lo, 1e-12)
        unit_normals = normals * size0
        unit_normals /= np.linalg.norm(unit_normals, axis=1)[:, None]
        self._mesh = Mesh((points - centre) / size0, unit_normals, triangles)
        self._size0 = size0
        self._rgb0 = rgb.astype(float) / 255
        for obj in objs:
            obj.visible = False
        args.setdefault("pos", vector(*centre))
        size = args.pop("size", None)
        super().__init__(**args)
        self._size = vector(*(hi - lo))
        self._size._on_change = self._on_size_change
        self._fit_axis()
        if size is not None:
            self.size = size

    def _vertex_rgb(self):
        tint = np.array(self._color._xyz())
        return np.clip(np.rint(self._rgb0 * tint * 255), 0, 255).astype(np.uint8)

    def _clone_args(self) -> dict:
        raise NotImplementedError

    def clone(self, **args):
        """A copy of the compound, sharing its surface."""
        new = object.__new__(compound)
        new.__dict__.update({k: v for k, v in self.__dict__.items() if k.startswith("_")})
        for name in ("_pos", "_axis", "_up", "_size", "_color"):
            new.__dict__[name] = vector(self.__dict__[name])
        new._trail = None
        new._hook()
        new._register({"canvas": self._canvas})
        for name, value in args.items():
            setattr(new, name, value)
        return new

    def world_to_compound(self, v) -> vector:
        X, Y, Z = self._local_axes()
        d = _vec(v, "v") - self._pos
        return vector(d.dot(X), d.dot(Y), d.dot(Z))

    def compound_to_world(self, v) -> vector:
        X, Y, Z = self._local_axes()
        v = _vec(v, "v")
        return self._pos + X * v.x + Y * v.y + Z * v.z

    def _local_axes(self):
        X = self._axis.norm()
        Z = X.cross(self._up).norm()
        return X, Z.cross(X).norm(), Z
