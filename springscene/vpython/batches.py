"""One VTK actor holding many VPython objects: the renderer's unit of drawing.

A :class:`Batch` is one mesh and one actor for every object of one kind and
look (opacity, shininess, emissive, and for textured objects the texture); its
points, normals, colours (and texture coordinates) are rewritten in place while
the topology stays the same. :class:`TexturedBatch` adds a picture: VTK keeps a
texture per actor, so textured objects get batches of their own, one per
texture (:mod:`springscene.vpython.draw` groups them). Textures are made into
VTK textures once per renderer (:class:`TextureCache`).

VTK multiplies a texture by the per-point RGB colours (checked: a white-to-red
quad under a green-and-yellow texture draws green and red), which is GlowScript's
rule, ``diffuse_color = vcolor * texture(texmap, mat_pos)``
(opaque_render_fragment.shader).
"""

from __future__ import annotations

import numpy as np

from ..view.scene import SPECULAR
from .placement import vtk_cells

LINE_WIDTH = 2            # px: a curve of radius 0 (VPython draws a thin line)


class Batch:
    """One actor and mesh holding every object of one kind and look."""

    empty = False        # nothing to draw (a cleared curve, a zero-length helix)

    def __init__(self, plotter, key: tuple, mode: str, texture=None) -> None:
        import pyvista as pv  # noqa: PLC0415  heavy: pyvista

        self.key, self.mode = key, mode
        self.signature = None
        self.mesh = pv.PolyData()
        self.plotter = plotter
        self.actor = None
        self.texture = texture
        self.pv = pv

    def set(self, points, normals, colors, cells, signature, style, uv=None) -> None:
        """New geometry: in place when the topology (``signature``) is unchanged."""
        self.empty = False
        if signature == self.signature and self.actor is not None:
            self._update(points, normals, colors, uv)
            return
        pv = self.pv
        if self.mode == "lines":
            mesh = pv.PolyData(points, lines=cells)
        elif self.mode == "points":
            mesh = pv.PolyData(points)
        else:
            mesh = pv.PolyData(points, faces=cells)
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
            self.actor = self.plotter.add_mesh(mesh, scalars="rgb", rgb=True,
                                               smooth_shading=False, show_scalar_bar=False,
                                               render_points_as_spheres=self.mode == "points",
                                               texture=self.texture)
            self._style(style)
        self.signature = signature

    def _update(self, points, normals, colors, uv) -> None:
        self.mesh.points[:] = points
        self.mesh.GetPoints().Modified()
        if normals is not None:
            self.mesh.point_data["Normals"][:] = normals
            self.mesh.GetPointData().GetNormals().Modified()
        self.mesh.point_data["rgb"][:] = colors
        self.mesh.GetPointData().GetArray("rgb").Modified()
        if uv is not None:
            tcoords = self.mesh.GetPointData().GetTCoords()
            self.mesh.active_texture_coordinates[:] = uv
            tcoords.Modified()

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
        if style["emissive"]:
            prop.LightingOff()
        if self.mode == "lines":
            prop.SetLineWidth(LINE_WIDTH)
            prop.LightingOff()
        if self.mode == "points":
            prop.SetPointSize(style["point_px"])
            prop.LightingOff()

    def hide(self) -> None:
        self.empty = True
        if self.actor is not None:
            self.actor.SetVisibility(False)

    def show(self) -> None:
        if self.actor is not None and not self.empty:
            self.actor.SetVisibility(True)

    def restyle(self, style: dict) -> None:
        if self.actor is not None:
            self._style(style)

    def remove(self) -> None:
        if self.actor is not None:
            self.plotter.remove_actor(self.actor)
            self.actor = None


class TexturedBatch(Batch):
    """A batch drawn with a picture; the parts a ``place`` leaves bare go to a second,
    plain actor (GlowScript draws those in the object's colour, untextured)."""

    def __init__(self, plotter, key: tuple, texture) -> None:
        super().__init__(plotter, key, "triangles", texture)
        self.bare = Batch(plotter, key, "triangles")

    def set_parts(self, points, normals, colors, uv, triangles, covered, signature,
                  style) -> None:
        """Triangles with ``covered`` True textured, the others (if any) plain."""
        if covered.any():
            new = signature != self.signature or self.actor is None
            cells = vtk_cells(triangles[covered]) if new else None
            self.set(points, normals, colors, cells, signature, style, uv)
        else:
            super().hide()
        if covered.all():
            self.bare.hide()
        else:
            new = signature != self.bare.signature or self.bare.actor is None
            cells = vtk_cells(triangles[~covered]) if new else None
            self.bare.set(points, normals, colors, cells, signature, style)

    def hide(self) -> None:
        super().hide()
        self.bare.hide()

    def show(self) -> None:
        super().show()
        self.bare.show()

    def restyle(self, style: dict) -> None:
        super().restyle(style)
        self.bare.restyle(style)

    def remove(self) -> None:
        super().remove()
        self.bare.remove()


class TextureCache:
    """VTK textures made once per renderer, keyed by their picture's source."""

    def __init__(self) -> None:
        self._textures: dict[str, object] = {}

    def get(self, source: str, image: np.ndarray):
        texture = self._textures.get(source)
        if texture is None:
            import pyvista as pv  # noqa: PLC0415  heavy: pyvista

            texture = pv.Texture(np.ascontiguousarray(image))   # row 0 at v = 1, as WebGL's flip
            texture.SetInterpolate(True)
            texture.SetMipmap(True)
            texture.SetRepeat(True)                              # WebGL's default wrap
            self._textures[source] = texture
        return texture


__all__ = ["Batch", "TexturedBatch", "TextureCache", "LINE_WIDTH"]
