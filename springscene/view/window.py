"""The off-screen render window, on plain VTK, and the actors the scenes put in it.

The meshes are pyvista's core (``pyvista.core``: ``PolyData``, ``Sphere``, ``Box``); the
window is not ``pv.Plotter``, because ``pyvista.plotting`` imports matplotlib's pyplot,
which no scene without a graph needs. A :class:`Window` is one off-screen render window
and renderer of a size, a background, multisampling and scene lights. The actors are the
ones ``pv.Plotter`` made, with the same property values (pyvista 0.46), so the pictures
are pyvista's: :func:`mesh_actor` and :func:`title_actor` (``add_mesh``, and
``add_text(position="upper_edge")``: colours rounded to 1/255, a ``vtkDataSetMapper``
with scalars off, point normals computed for smooth shading, a ``vtkCornerAnnotation``
scaled by half the font size); for the VPython renderer :func:`rgb_mesh_actor`
(``add_mesh`` of a mesh coloured by its points' ``rgb``, a texture or none),
:func:`image_texture` (``pv.Texture``) and :func:`scene_light` (``pv.Light``).

The backend must have been chosen (:func:`springscene.view.backend.select`) before a
window is made.
"""

from __future__ import annotations

import functools

import numpy as np

UPPER_EDGE = 7        # vtkCornerAnnotation's text positions: 7 is the top edge's middle


def pyvista_color(color) -> tuple[float, float, float]:
    """A colour as pyvista hands it to VTK: each channel rounded to a multiple of 1/255."""
    return tuple(round(255 * float(c)) / 255 for c in color)


@functools.cache
def _renderer_class():
    """``vtkOpenGLRenderer`` with ``actors``: its actors by name, as pyvista's renderer."""
    from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLRenderer  # noqa: PLC0415  heavy: VTK

    class Renderer(vtkOpenGLRenderer):
        """A renderer that keeps its actors by name (``actors``)."""

        def __init__(self) -> None:
            super().__init__()
            self._named = {}

        @property
        def actors(self) -> dict:
            """The actors added through :meth:`Window.add_actor`, by name."""
            return dict(self._named)

    return Renderer


class Window:
    """An off-screen render window with one renderer.

    Parameters
    ----------
    size : (width, height)
        In pixels.
    background : (r, g, b)
        In 0..1 (rounded to 1/255, as pyvista's ``set_background``).
    multisamples : int
        MSAA samples; 0 for none.
    lights : sequence of ((x, y, z), intensity)
        Directional scene lights, each shining from ``(x, y, z)`` towards the origin
        in gray ``intensity`` (rounded to 1/255, as ``pv.Light``'s colour).
    """

    def __init__(self, size: tuple[int, int], background, multisamples: int = 0,
                 lights=()) -> None:
        # the OpenGL classes and the FreeType text renderer register VTK's factories
        import vtkmodules.vtkRenderingFreeType  # noqa: F401, PLC0415  heavy: VTK
        import vtkmodules.vtkRenderingOpenGL2  # noqa: F401, PLC0415  heavy: VTK
        from vtkmodules.vtkRenderingCore import vtkRenderWindow  # noqa: PLC0415  heavy: VTK

        self.ren_win = vtkRenderWindow()       # the class VTK_DEFAULT_OPENGL_WINDOW names
        self.ren_win.SetOffScreenRendering(True)
        self.ren_win.SetSize(int(size[0]), int(size[1]))
        self.ren_win.SetMultiSamples(int(multisamples))
        self.ren_win.SetAlphaBitPlanes(True)
        self.renderer = _renderer_class()()
        self.renderer.SetAutomaticLightCreation(False)
        self.renderer.SetBackground(*pyvista_color(background))
        self.ren_win.AddRenderer(self.renderer)
        for direction, intensity in lights:
            self.add_light(direction, intensity)

    @property
    def window_size(self) -> tuple[int, int]:
        return tuple(self.ren_win.GetSize())

    def add_light(self, direction, intensity: float):
        """A directional scene light from ``direction`` towards the origin; returns it."""
        from vtkmodules.vtkRenderingCore import vtkLight  # noqa: PLC0415  heavy: VTK

        light = vtkLight()
        light.SetLightTypeToSceneLight()
        light.SetPosition(*direction)
        light.SetFocalPoint(0.0, 0.0, 0.0)
        gray = pyvista_color((intensity,) * 3)
        light.SetAmbientColor(*gray)
        light.SetDiffuseColor(*gray)
        light.SetSpecularColor(*gray)
        light.SetPositional(False)
        self.renderer.AddLight(light)
        return light

    def set_background(self, color) -> None:
        """The background, rounded to 1/255 (``pv.Plotter.set_background``)."""
        self.renderer.SetBackground(*pyvista_color(color))

    def remove_all_lights(self) -> None:
        self.renderer.RemoveAllLights()

    def add_actor(self, actor, name: str | None = None, pickable: bool = True):
        """Add a prop (a 3D actor or a 2D text); ``name`` replaces an actor of that name."""
        name = name or f"{type(actor).__name__}({actor.__this__})"
        if name in self.renderer._named:
            self.remove_actor(self.renderer._named[name])
        actor.SetPickable(pickable)
        self.renderer.AddViewProp(actor)
        self.renderer._named[name] = actor
        return actor

    def remove_actor(self, actor, render: bool = False) -> bool:
        """Remove an actor (or the actor of that name); True when there was one.
        ``render`` is pv.Plotter's argument, accepted and ignored (nothing renders here
        until the next frame)."""
        named = self.renderer._named
        if isinstance(actor, str):
            actor = named.get(actor)
        names = [k for k, v in named.items() if v is actor]
        for k in names:
            del named[k]
        if actor is None or not self.renderer.HasViewProp(actor):
            return bool(names)
        self.renderer.RemoveViewProp(actor)
        return True

    def render(self) -> None:
        self.ren_win.Render()

    def close(self) -> None:
        """Release the window's OpenGL context and its actors."""
        if self.ren_win is None:
            return
        self.renderer.RemoveAllViewProps()
        self.renderer.RemoveAllLights()
        self.renderer._named.clear()
        self.ren_win.Finalize()
        self.ren_win.RemoveRenderer(self.renderer)
        self.ren_win = None


def mesh_actor(mesh, smooth_shading: bool = False):
    """An actor for a pyvista ``PolyData`` as ``pv.Plotter.add_mesh(mesh,
    smooth_shading=...)`` made it (no colour: the caller sets the material).

    Smooth shading computes point normals into ``mesh`` in place when it has none, as
    ``add_mesh`` does: pyvista's ``compute_normals(cell_normals=False, inplace=True)``.
    """
    from vtkmodules.vtkRenderingCore import vtkActor, vtkDataSetMapper  # noqa: PLC0415  heavy: VTK

    if smooth_shading and mesh.point_data.active_normals is None:
        mesh.compute_normals(cell_normals=False, inplace=True)
    mapper = vtkDataSetMapper()
    mapper.SetInputData(mesh)
    mapper.SetInterpolateScalarsBeforeMapping(True)
    mapper.ScalarVisibilityOff()
    actor = vtkActor()
    actor.SetMapper(mapper)
    prop = actor.GetProperty()
    prop.SetPointSize(5.0)           # pyvista's theme; nothing here draws points
    prop.SetEdgeColor(0.0, 0.0, 0.0)
    return actor


def scene_light(position, color, positional: bool, focal_point=None, cone_angle=None,
                intensity=None):
    """A scene light as ``pv.Light(position=..., focal_point=..., color=...,
    light_type="scene light")`` made it, then ``positional``, ``cone_angle`` and
    ``intensity`` set: ambient, diffuse and specular colour rounded to 1/255, VTK's
    defaults for the rest (attenuation, exponent)."""
    from vtkmodules.vtkRenderingCore import vtkLight  # noqa: PLC0415  heavy: VTK

    light = vtkLight()
    light.SetPosition(*(float(v) for v in position))
    if focal_point is not None:
        light.SetFocalPoint(*(float(v) for v in focal_point))
    rgb = pyvista_color(color)
    light.SetAmbientColor(*rgb)
    light.SetDiffuseColor(*rgb)
    light.SetSpecularColor(*rgb)
    light.SetLightTypeToSceneLight()
    light.SetPositional(bool(positional))
    if cone_angle is not None:
        light.SetConeAngle(float(cone_angle))
    if intensity is not None:
        light.SetIntensity(float(intensity))
    return light


def rgb_mesh_actor(mesh, texture=None):
    """An actor for a polydata coloured by its points' ``rgb`` array, as
    ``pv.Plotter.add_mesh(mesh, scalars="rgb", rgb=True, smooth_shading=False,
    show_scalar_bar=False, texture=texture)`` made it (the mesh not copied): point
    scalars shown as they are (direct colour mode), interpolated before mapping, an
    identity user matrix, and pyvista's property (flat, white under a texture, else
    its default colour)."""
    from vtkmodules.vtkCommonMath import vtkMatrix4x4  # noqa: PLC0415  heavy: VTK

    actor = mesh_actor(mesh)
    mesh.GetPointData().SetActiveScalars("rgb")
    mapper = actor.GetMapper()
    mapper.SetArrayName("rgb")
    mapper.SetScalarModeToUsePointData()
    mapper.SetColorModeToDirectScalars()
    mapper.ScalarVisibilityOn()
    actor.SetUserMatrix(vtkMatrix4x4())
    if texture is not None:
        actor.SetTexture(texture)
    prop = actor.GetProperty()
    prop.SetColor(*((1.0, 1.0, 1.0) if texture is not None else PYVISTA_MESH_COLOR))
    prop.SetInterpolationToFlat()
    prop.SetSpecularPower(100.0)
    return actor


PYVISTA_MESH_COLOR = pyvista_color((173 / 255, 216 / 255, 230 / 255))   # pyvista's "lightblue"


def image_texture(image: np.ndarray):
    """A ``vtkTexture`` of an (h, w[, c]) picture as ``pv.Texture(image)`` made it: an
    image of w x h points, row 0 of the picture at the top (the last image row), the
    point array ``Image`` of the picture's dtype."""
    from vtkmodules.util.numpy_support import numpy_to_vtk  # noqa: PLC0415  heavy: VTK
    from vtkmodules.vtkCommonDataModel import vtkImageData  # noqa: PLC0415  heavy: VTK
    from vtkmodules.vtkRenderingCore import vtkTexture  # noqa: PLC0415  heavy: VTK

    image = np.asarray(image)
    components = 1 if image.ndim == 2 else image.shape[2]
    grid = vtkImageData()
    grid.SetDimensions(image.shape[1], image.shape[0], 1)
    pixels = numpy_to_vtk(np.ascontiguousarray(image[::-1].reshape(-1, components)), deep=True)
    pixels.SetName("Image")
    grid.GetPointData().SetScalars(pixels)
    texture = vtkTexture()
    texture.SetInputDataObject(grid)
    texture.Update()
    return texture


def title_actor(text: str, font_size: int, color):
    """A title along the top edge's middle, as ``pv.Plotter.add_text(text,
    position="upper_edge", font_size=font_size, color=color)`` drew it: a
    ``vtkCornerAnnotation`` whose font scales with the window, Arial, no shadow."""
    from vtkmodules.vtkRenderingAnnotation import vtkCornerAnnotation  # noqa: PLC0415  heavy: VTK

    actor = vtkCornerAnnotation()
    actor.SetText(UPPER_EDGE, text)
    actor.SetLinearFontScaleFactor(font_size // 2)
    prop = actor.GetTextProperty()
    prop.SetColor(*pyvista_color(color))
    prop.SetFontFamilyToArial()
    prop.SetOrientation(0.0)
    prop.SetShadow(False)
    return actor
