"""Textured VPython objects as arrays: each object's mesh with texture coordinates.

An object is textured when it has a ``texture`` the renderer can draw
(the renderer's ``_texture_of``): sphere (and ellipsoid), box, cylinder, cone, pyramid and
ring, as GlowScript's object shaders texture them, and a compound whose mesh
kept its parts' texture coordinates (``_mesh.uv``, from
``object_meshes.object_mesh(part, uv=True)``); an arrow (GlowScript's arrow parts take no
texture), helix or curve with a ``texture`` is drawn without it. The meshes are GlowScript's
textured layouts (:data:`.meshes.TEXTURED`, ``meshes.ring(uv=True)``), placed
like the untextured ones (:func:`.placement.place`).

GlowScript's rules (render_vertex.shader, ring_render_vertex.shader):

- a vertex is textured when its place (:func:`.meshes.texture_parts`) is one
  the texture's ``place`` names; the others draw plain, in the object's colour;
- ``flipx``, ``flipy`` and ``turn`` change the texture coordinates
  (:func:`transform_uv`);
- the picture is multiplied by the object's colour when it covers the whole
  object; when it covers only some parts it is drawn as it is (colour white
  there) and the rest in the object's colour.
"""

from __future__ import annotations

from typing import NamedTuple

import numpy as np

from . import meshes, placement


class TextureSpec(NamedTuple):
    """What the renderer needs of a texture: which picture, where, and turned how.

    ``source`` is ``"builtin:<name>"`` or an absolute file path. ``left``,
    ``right`` and ``sides`` are GlowScript's places (a template vertex is
    *left* where its normal is exactly -x, *right* where it is +x, else a
    *side*; render_vertex.shader). ``turn`` is 0..3 quarter turns.
    """

    source: str
    left: bool = True
    right: bool = True
    sides: bool = True
    flipx: bool = False
    flipy: bool = False
    turn: int = 0
    bump: str = ""          # the bump map's ``builtin:<name>`` or file path; "" for none

    @property
    def covers_all(self) -> bool:
        return self.left and self.right and self.sides


def transform_uv(uv: np.ndarray, spec: TextureSpec) -> np.ndarray:
    """Texture coordinates flipped and turned as GlowScript's vertex shaders do.

    render_vertex.shader: ``flipx`` u -> 1 - u, ``flipy`` v -> 1 - v, then
    ``turn`` 1: (v, 1 - u), 2: (1 - u, 1 - v), 3: (1 - v, u).
    """
    u, v = uv[:, 0].copy(), uv[:, 1].copy()
    if spec.flipx:
        u = 1 - u
    if spec.flipy:
        v = 1 - v
    if spec.turn == 1:
        u, v = v, 1 - u
    elif spec.turn == 2:
        u, v = 1 - u, 1 - v
    elif spec.turn == 3:
        u, v = 1 - v, u
    return np.column_stack([u, v])


TEXTURABLE = frozenset({"sphere", "box", "cylinder", "cone", "pyramid", "ring"})


def has_layout(obj) -> bool:
    """Whether ``obj`` has texture coordinates: a kind GlowScript textures, or a compound
    whose mesh kept its parts' (``_mesh.uv``)."""
    if obj._kind == "compound":
        return getattr(obj._mesh, "uv", None) is not None
    return obj._kind in TEXTURABLE


def _rgb(colors: np.ndarray) -> np.ndarray:
    return np.clip(np.rint(np.asarray(colors) * 255), 0, 255).astype(np.uint8)


def _template(kind: str, obj=None) -> placement.Mesh:
    if kind == "ring":
        return meshes.ring(obj.radius, obj.thickness, uv=True)
    return meshes.TEXTURED[kind]()


def arrays(kind: str, objs: list, spec: TextureSpec) -> dict:
    """Everything a textured batch draws, for objects of one kind sharing ``spec``.

    Keys: ``points``, ``normals``, ``triangles``, ``rgb`` (uint8), ``uv``,
    ``covered`` (per triangle: textured) and ``signature`` (the topology).
    """
    if kind in ("ring", "compound"):
        parts = [_own_mesh(obj) for obj in objs]
        part_meshes = [p[0] for p in parts]
        points = np.concatenate([p[1] for p in parts])
        normals = np.concatenate([p[2] for p in parts])
        colors = np.concatenate([_colours(o, len(m.points)) for o, m in zip(objs, part_meshes)])
        offsets = np.cumsum([0] + [len(m.points) for m in part_meshes])
        triangles = np.concatenate([m.triangles + off for m, off in zip(part_meshes, offsets)])
        template_uv = np.concatenate([m.uv for m in part_meshes])
        vertex_parts = np.concatenate([meshes.texture_parts(m, kind) for m in part_meshes])
        signature = (kind, tuple(len(m.points) for m in part_meshes))
    else:
        t = _template(kind)
        pos, R, size, color = placement.object_frames(objs)
        points, normals = placement.place(t, pos, R, size)
        M, n = len(objs), len(t.points)
        colors = np.repeat(color, n, axis=0)
        triangles = placement.tile(t.triangles, n, M)
        template_uv = np.tile(t.uv, (M, 1))
        vertex_parts = np.tile(meshes.texture_parts(t, kind), M)
        signature = (kind, M)
    textured = _textured_vertices(vertex_parts, spec)
    if not spec.covers_all:
        colors = np.where(textured[:, None], 1.0, colors)
    return {"points": points, "normals": normals, "triangles": triangles, "rgb": _rgb(colors),
            "uv": transform_uv(template_uv, spec),
            "covered": textured[triangles].all(axis=1),
            "signature": signature}


def _own_mesh(obj):
    """A ring's (made in local lengths) or a compound's (unit-sized, scaled by size) mesh, placed."""
    if obj._kind == "compound":
        mesh, scale = obj._mesh, np.array([obj._size._xyz()])
    else:
        mesh, scale = _template("ring", obj), np.ones((1, 3))
    pos = np.array([obj._pos._xyz()])
    R = placement.frames(np.array([obj._axis._xyz()]), np.array([obj._up._xyz()]))
    points, normals = placement.place(mesh, pos, R, scale)
    return mesh, points, normals


def _colours(obj, n: int) -> np.ndarray:
    """Each point's colour in [0, 1]: a compound's own (its parts' times its colour)."""
    if obj._kind == "compound":
        return obj._vertex_rgb() / 255.0
    return np.repeat([obj._color._xyz()], n, axis=0)


def _textured_vertices(parts: np.ndarray, spec: TextureSpec) -> np.ndarray:
    on = np.array([spec.sides, spec.left, spec.right])      # indexed by SIDES, LEFT, RIGHT
    return on[parts]


__all__ = ["TextureSpec", "transform_uv", "TEXTURABLE", "has_layout", "arrays"]
