"""One VPython object of any kind as a world-space triangle mesh, with numpy alone.

:func:`object_mesh` gives the points, normals, triangles and RGB of one object (with its
texture coordinates when asked): what a ``compound`` keeps of its parts, and what the
renderer draws for the kinds it does not batch as instances. :func:`template` is the unit
mesh of a kind drawn scaled by its size (sphere, box, cylinder, cone, pyramid), made once;
:func:`polygon_arrays` the meshes of triangles and quads. Objects are read through their
attributes (``_kind``, ``_pos``, ...), never imported.
"""

from __future__ import annotations

import numpy as np

from . import helices, meshes, placement, point_meshes, textured

# kinds drawn from one template scaled by size (a cylinder's, cone's and pyramid's
# template starts at its pos, a sphere's and box's is centred on it)
TEMPLATES = {"sphere": meshes.sphere, "box": meshes.box, "cylinder": meshes.cylinder,
             "cone": meshes.cone, "pyramid": meshes.pyramid}


def rgb8(colors: np.ndarray) -> np.ndarray:
    """Colours 0..1 as uint8 RGB, rounded as GlowScript's 8-bit colours are."""
    return np.clip(np.rint(np.asarray(colors) * 255), 0, 255).astype(np.uint8)


_TEMPLATES: dict = {}


def template(kind: str, slices: int | None = None) -> placement.Mesh:
    """The unit mesh of a template kind (a sphere of ``slices``), made once."""
    key = (kind, slices)
    if key not in _TEMPLATES:
        _TEMPLATES[key] = meshes.sphere(slices) if slices else TEMPLATES[kind]()
    return _TEMPLATES[key]


def object_mesh(obj, uv: bool = False):
    """World points, normals, triangles and RGB (uint8) of one object, any kind.

    With ``uv``, a fifth array: each point's texture coordinates, from GlowScript's
    textured layouts (zeros for kinds GlowScript does not texture), for a compound
    that keeps its parts' texpos as GlowScript's does (mesh.js ``merge``).
    """
    if uv:
        return _uv_mesh(obj)
    kind = obj._kind
    if kind in TEMPLATES:
        t = template(kind)
        pos, R, size, color = placement.object_frames([obj])
        points, normals = placement.place(t, pos, R, size)
        return points, normals, t.triangles, np.repeat(rgb8(color), len(points), axis=0)
    if kind == "curve":
        kind = "tube" if obj._radius > 0 else kind
    if kind == "points" and obj._size_units == "world":
        kind = "sphere-points"
    return kind_mesh(kind, obj)


def _uv_mesh(obj):
    if obj._kind == "triangle":
        points, normals, triangles, rgba, uv = polygon_arrays([obj])
        return points, normals, triangles, rgba[:, :3], uv
    if textured.has_layout(obj):
        a = textured.arrays(obj._kind, [obj], textured.TextureSpec("", sides=True))
        rgb = np.repeat(rgb8([obj._color._xyz()]), len(a["points"]), axis=0)
        return a["points"], a["normals"], a["triangles"], rgb, a["uv"]
    points, normals, triangles, rgb = object_mesh(obj)
    return points, normals, triangles, rgb, np.zeros((len(points), 2))


def kind_mesh(kind: str, obj):
    """World points, normals, triangles and RGB of one object drawn from its own mesh."""
    if kind == "helix":
        return _helix(obj)
    if kind == "triangle":
        points, normals, triangles, rgba, _ = polygon_arrays([obj])
        return points, normals, triangles, rgba[:, :3]
    if kind in ("arrow", "ring", "compound"):
        pos = np.array([obj._pos._xyz()])
        R = placement.frames(np.array([obj._axis._xyz()]), np.array([obj._up._xyz()]))
    if kind == "arrow":
        dims = meshes.arrow_dims(obj._size.x, obj._shaftwidth, obj._headwidth,
                                 obj._headlength)
        mesh = meshes.arrow(obj._size.x, *dims)
        scale = np.ones((1, 3))
    elif kind == "ring":
        mesh = meshes.ring(obj.radius, obj.thickness)
        scale = np.ones((1, 3))
    elif kind == "compound":
        mesh = obj._mesh                  # unit-sized at construction: scale by size
        scale = np.array([obj._size._xyz()])
        points, normals = placement.place(mesh, pos, R, scale)
        return points, normals, mesh.triangles, obj._vertex_rgb()
    elif kind == "tube":
        return _tube(obj)
    elif kind == "sphere-points":
        p, col, rad = obj._arrays()
        if not len(p):
            return None
        t = template("sphere")
        n = len(t.points)
        eye = np.broadcast_to(np.eye(3), (len(p), 3, 3))
        points, normals = placement.place(t, p, eye, np.repeat(2 * rad[:, None], 3, axis=1))
        tris = placement.tile(t.triangles, n, len(p))
        return points, normals, tris, np.repeat(rgb8(col), n, axis=0)
    else:
        raise ValueError(kind)
    points, normals = placement.place(mesh, pos, R, scale)
    return points, normals, mesh.triangles, np.repeat(rgb8([obj._color._xyz()]),
                                                      len(points), axis=0)

def _helix(obj):
    """One helix at VPython's full detail (:mod:`.helices`)."""
    m = helices.mesh([obj])
    return None if m is None else m[:4]


def _tube(obj, view=None):
    """A curve of radius > 0 as a tube (:func:`.point_meshes.mesh`)."""
    return point_meshes.mesh("tube", obj, view, 0.0, 1)


_QUAD = np.array([[0, 1, 2], [0, 2, 3]])


def polygon_arrays(objs) -> tuple[np.ndarray, ...]:
    """Points, normals, triangles, RGBA (uint8), texture coordinates of triangles and quads.

    Each object has its own copies of its vertices (3 or 4 points). A
    triangle's winding is made to agree with its vertices' normals, so that a
    renderer lighting back faces from behind (VTK's two-sided lighting) lights
    it from the side its normals point to, as GlowScript does.
    """
    verts = [v for o in objs for v in o._verts]
    counts = np.array([len(o._verts) for o in objs])
    pos = np.array([v._pos._xyz() for v in verts], dtype=float)
    normal = np.array([v._normal._xyz() for v in verts], dtype=float)
    color = np.array([(*v._color._xyz(), v._opacity) for v in verts], dtype=float)
    uv = np.array([v._texpos._xyz()[:2] for v in verts], dtype=float)
    starts = np.concatenate([[0], np.cumsum(counts)[:-1]])
    tris = [starts[counts == 3, None] + _QUAD[0]]
    fours = starts[counts == 4]
    if len(fours):
        tris.append((fours[:, None, None] + _QUAD[None]).reshape(-1, 3))
    triangles = np.concatenate(tris).astype(np.int64)
    p = pos[triangles]
    face = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    backwards = np.einsum("ij,ij->i", face, normal[triangles].sum(axis=1)) < 0
    triangles[backwards] = triangles[backwards][:, [0, 2, 1]]
    rgba = np.clip(np.rint(color * 255), 0, 255).astype(np.uint8)
    return pos, _unit(normal), triangles, rgba, uv


def _unit(v: np.ndarray) -> np.ndarray:
    n = np.linalg.norm(v, axis=1, keepdims=True)
    return v / np.where(n == 0, 1.0, n)
