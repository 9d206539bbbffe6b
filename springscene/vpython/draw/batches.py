"""One VTK actor holding many VPython objects: the renderer's unit of drawing.

A :class:`Batch` is one mesh and one actor for every object of one kind and
look (opacity, shininess, emissive, and for textured objects the texture); its
points, normals, colours (and texture coordinates) are rewritten in place while
the topology stays the same. :class:`TexturedBatch` adds a picture: VTK keeps a
texture per actor, so textured objects get batches of their own, one per
texture (:mod:`springscene.vpython.draw.renderer` groups them). Textures are made into
VTK textures once per renderer (:class:`TextureCache`).

VTK multiplies a texture by the per-point RGB colours (checked: a white-to-red
quad under a green-and-yellow texture draws green and red), which is GlowScript's
rule, ``diffuse_color = vcolor * texture(texmap, mat_pos)``
(opaque_render_fragment.shader); it multiplies after lighting, GlowScript before the
specular is added: :mod:`.texture_shading` makes a textured batch GlowScript's.
"""

from __future__ import annotations

import numpy as np

from ...view.scene import SPECULAR
from ...view.window import image_texture, rgb_mesh_actor
from .materials import shade_as_glowscript, shade_emissive
from ..geometry.placement import vtk_cells
from ..api import texturing
from .texture_shading import BUMP_SAMPLER, bump_frame, shade_textured



class Batch:
    """One actor and mesh holding every object of one kind and look."""

    empty = False        # nothing to draw (a cleared curve, a zero-length helix)
    own_empty = False    # its own actor draws nothing now, its parts may
    parts: tuple = ()    # batches drawn with it (a textured batch's bare part, impostors)
    opacity = 1.0        # the look's opacity
    vertex_alpha = False  # some vertex's own opacity (RGBA colours) is below 1
    lit = False          # a surface lit by the lights (shaded by GlowScript's rules)
    # what the renderer keeps to draw the batch again for another view
    objs = None          # the objects drawn
    detail_view = None   # the view their level of detail was chosen for
    drawn_detail = None  # spheres: (slices of the meshed ones, which are impostors)
    helix_arrays = None  # helices: their arrays (:func:`..geometry.helices.helix_arrays`)

    def __init__(self, window, key: tuple, texture=None) -> None:
        from pyvista.core import PolyData  # noqa: PLC0415  heavy: pyvista

        self.key = key
        self.signature = None
        self.mesh = PolyData()
        self.window = window
        self.actor = None
        self.texture = texture

    def set(self, points, normals, colors, cells, signature, style, uv=None) -> None:
        """New geometry: in place when the topology (``signature``) is unchanged."""
        self.empty = False
        alpha = colors.ndim == 2 and colors.shape[1] == 4 and bool((colors[:, 3] < 255).any())
        if alpha != self.vertex_alpha:
            self.vertex_alpha = alpha
            if self.actor is not None:
                self._shade()
        if signature == self.signature and self.actor is not None:
            self._update(points, normals, colors, uv)
            return
        from pyvista.core import PolyData  # noqa: PLC0415  heavy: pyvista

        mesh = PolyData(points, faces=cells)    # every kind is triangles
        if normals is not None:
            mesh.point_data["Normals"] = normals
            mesh.GetPointData().SetActiveNormals("Normals")
        mesh.point_data["rgb"] = colors
        if uv is not None:
            mesh.active_texture_coordinates = uv
        if self.actor is not None:           # the actor keeps its mesh; its content changes
            self.mesh.shallow_copy(mesh)
            self.mesh.GetPointData().SetActiveScalars("rgb")
        else:
            self.mesh = mesh
            self.actor = self.window.add_actor(rgb_mesh_actor(mesh, self.texture))
            self._style(style)
        self.signature = signature

    def _update(self, points, normals, colors, uv) -> None:
        self.mesh.points[:] = points
        self.mesh.GetPoints().Modified()
        if normals is not None:
            self.mesh.point_data["Normals"][:] = normals
            self.mesh.GetPointData().GetNormals().Modified()
        rgb = self.mesh.point_data["rgb"]
        if not np.array_equal(rgb, colors):      # unchanged colours are not uploaded again
            rgb[:] = colors
            self.mesh.GetPointData().GetArray("rgb").Modified()
        if uv is not None:
            tcoords = self.mesh.GetPointData().GetTCoords()
            self.mesh.active_texture_coordinates[:] = uv
            tcoords.Modified()

    def _adopt(self, mapper, style: dict) -> None:
        """The batch's actor for ``mapper`` (its points' ``rgb`` the colours, as they are),
        put in the renderer and given ``style``."""
        from vtkmodules.vtkRenderingCore import vtkActor  # noqa: PLC0415  heavy: vtk

        mapper.ScalarVisibilityOn()
        mapper.SetScalarModeToUsePointFieldData()
        mapper.SelectColorArray("rgb")
        mapper.SetColorModeToDirectScalars()
        actor = vtkActor()
        actor.SetMapper(mapper)
        self.window.add_actor(actor)      # listed in renderer.actors, as add_mesh's are
        self.actor = actor
        self._style(style)

    def _style(self, style: dict) -> None:
        prop = self.actor.GetProperty()
        prop.SetInterpolationToPhong()
        prop.SetAmbient(style["ambient"])
        prop.SetDiffuse(1.0)
        shininess = style["shininess"]
        prop.SetSpecular(SPECULAR if shininess > 0 else 0.0)
        prop.SetSpecularColor(1.0, 1.0, 1.0)
        prop.SetSpecularPower(max(100 * shininess, 1.0))
        prop.SetOpacity(style["opacity"])
        self.opacity = style["opacity"]
        self.lit = not style["emissive"]
        prop.LightingOn()                  # emissive too: VTK's unlit shader has no normals
        self._shade()
        if style["emissive"]:
            shade_emissive(self.actor)     # GlowScript's glow, dimmed towards the outline

    @property
    def translucent(self) -> bool:
        """Drawn in GlowScript's transparent layers: its opacity or a vertex's is below 1."""
        return self.opacity < 1 or self.vertex_alpha

    def _shade(self) -> None:
        if self.lit:
            shade_as_glowscript(self.actor, self.translucent)

    def hide(self) -> None:
        """Nothing drawn: its own actor and its parts."""
        self.hide_own()
        for part in self.parts:
            part.hide()

    def hide_own(self) -> None:
        """Its own actor not drawn; its parts as they are."""
        self.empty = True
        if self.actor is not None:
            self.actor.SetVisibility(False)

    def show(self) -> None:
        if self.actor is not None and not self.empty and not self.own_empty:
            self.actor.SetVisibility(True)
        for part in self.parts:
            part.show()

    def restyle(self, style: dict) -> None:
        if self.actor is not None:
            self._style(style)
        for part in self.parts:
            part.restyle(style)

    def remove(self) -> None:
        if self.actor is not None:
            self.window.remove_actor(self.actor)
            self.actor = None
        for part in self.parts:
            part.remove()


class TexturedBatch(Batch):
    """A batch drawn with a picture; the parts a ``place`` leaves bare go to a second,
    plain actor (GlowScript draws those in the object's colour, untextured)."""

    def __init__(self, window, key: tuple, texture) -> None:
        super().__init__(window, key, texture)
        self.bare = Batch(window, key)
        self.parts = (self.bare,)
        spec = key[-1]                     # the batch's TextureSpec (renderer.Renderer._key)
        bump = texturing.bump_of(spec) if isinstance(spec, texturing.TextureSpec) else None
        self.bump = None if bump is None else vtk_texture(bump)
        self.frame = None if bump is None else bump_frame(spec.flipx, spec.flipy, spec.turn)

    def _shade(self) -> None:
        if not self.lit:
            return
        if self.bump is not None and self.actor.GetProperty().GetTexture(BUMP_SAMPLER) is None:
            self.actor.GetProperty().SetTexture(BUMP_SAMPLER, self.bump)
        # the texel colours diffuse and ambient, not specular; a bump map bends the normals
        shade_textured(self.actor, self.translucent, self.frame)

    def set_parts(self, points, normals, colors, uv, triangles, covered, signature,
                  style) -> None:
        """Triangles with ``covered`` True textured, the others (if any) plain."""
        if covered.any():
            new = signature != self.signature or self.actor is None
            cells = vtk_cells(triangles[covered]) if new else None
            self.set(points, normals, colors, cells, signature, style, uv)
        else:
            self.hide_own()
        if covered.all():
            self.bare.hide()
        else:
            new = signature != self.bare.signature or self.bare.actor is None
            cells = vtk_cells(triangles[~covered]) if new else None
            self.bare.set(points, normals, colors, cells, signature, style)


class TextureCache:
    """VTK textures made once per renderer, keyed by their picture's source."""

    def __init__(self) -> None:
        self._textures: dict[str, object] = {}

    def get(self, source: str, image: np.ndarray):
        texture = self._textures.get(source)
        if texture is None:
            texture = self._textures[source] = vtk_texture(image)
        return texture


def vtk_texture(image: np.ndarray):
    """A VTK texture of an RGB picture: row 0 at v = 1 (WebGL's ``UNPACK_FLIP_Y_WEBGL``),
    repeated (WebGL's default wrap), with mipmaps (GlowScript's ``generateMipmap``)."""
    texture = image_texture(np.ascontiguousarray(image))
    texture.SetInterpolate(True)
    texture.SetMipmap(True)
    texture.SetRepeat(True)
    return texture


__all__ = ["Batch", "TexturedBatch", "TextureCache", "vtk_texture"]
