"""The 3D scene, drawn as VPython draws it: holder boxes, helix springs and ball spheres.

A :class:`Scene` is built once from the settings it draws with (the canvas, the
camera, the holder, spring and ball sections of a config) and mirrors a physics
:class:`~springscene.model.physics.System`: each fixed node is a holder box, each free
node a ball, each spring a helix from its start node to its end node. Each frame,
:meth:`Scene.update` moves the balls' actors and rewrites the springs' points in
place; no mesh is rebuilt and no actor is added. The scene only reads the state.
"""

from __future__ import annotations

import math

import numpy as np

from ..model.physics import System
from ..settings import BallCfg, CameraCfg, HolderCfg, SceneCfg, SpringCfg
from . import backend, camera
from .window import Window, mesh_actor, title_actor
from .geometry import HelixFrame, HelixTube

# VPython's lights: fixed in the world, (direction towards the light, colour).
LIGHTS = (((0.22, 0.44, 0.88), 0.8), ((-0.88, -0.22, -0.44), 0.3))
AMBIENT = 0.2
SPECULAR = 0.8
SHININESS = 0.6          # VPython's default; specular exponent 100 * shininess
SPHERE_SLICES = 30
MULTI_SAMPLES = 4        # MSAA when anti-aliased
TITLE_FONT_SIZE = 12
TITLE_RGB = {"black": (0.0, 0.0, 0.0), "white": (1.0, 1.0, 1.0)}


def _material(actor, color) -> None:
    """VPython's shading, per pixel: ambient*C + sum lc*max(N.L,0)*C + 0.8*lc*max(R.V,0)^60."""
    prop = actor.GetProperty()
    prop.SetInterpolationToPhong()
    prop.SetColor(*color)
    prop.SetAmbient(AMBIENT)
    prop.SetDiffuse(1.0)
    prop.SetSpecular(SPECULAR)
    prop.SetSpecularColor(1.0, 1.0, 1.0)
    prop.SetSpecularPower(100 * SHININESS)


def grab(render_window, width: int, height: int, buffer) -> np.ndarray:
    """Render ``render_window`` and read it back as (height, width, 3) uint8, top row first.

    ``buffer`` is a ``vtkUnsignedCharArray`` reused from frame to frame.
    """
    from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: PLC0415  heavy: VTK

    render_window.Render()
    render_window.GetPixelData(0, 0, width - 1, height - 1, 0, buffer, 0)
    img = vtk_to_numpy(buffer).reshape(height, width, 3)
    return np.ascontiguousarray(img[::-1])


def apply_view(window: Window, v: camera.View) -> None:
    """Place a window's camera at a VPython :class:`~springscene.view.camera.View`."""
    cam = window.renderer.GetActiveCamera()
    cam.SetPosition(*v.position)
    cam.SetFocalPoint(*v.focal_point)
    cam.SetViewUp(*v.up)
    cam.SetViewAngle(math.degrees(v.fov))
    cam.SetClippingRange(v.near, v.far)


def title_color(background) -> str:
    """Black text on a light background, white on a dark one."""
    luminance = float(np.dot(background, (0.2126, 0.7152, 0.0722)))
    return "black" if luminance > 0.5 else "white"


def new_window(canvas: SceneCfg, antialias: bool = True) -> Window:
    """An off-screen window of the canvas's size and background, lit by VPython's :data:`LIGHTS`.

    4x multisampling when ``antialias``. The backend must have been chosen
    (:func:`springscene.view.backend.select`). Plain VTK (:mod:`springscene.view.window`):
    no ``pyvista.plotting``, no matplotlib.
    """
    return Window((canvas.width, canvas.height), canvas.background,
                  MULTI_SAMPLES if antialias else 0, LIGHTS)


def add_title(window: Window, canvas: SceneCfg) -> None:
    """The canvas's title centred along the top edge (no text when it is blank)."""
    if canvas.title.strip():
        window.add_actor(title_actor(canvas.title.strip(), TITLE_FONT_SIZE,
                                     TITLE_RGB[title_color(canvas.background)]),
                         name="title", pickable=False)


class SceneBase:
    """What every off-screen scene shares: the window, VPython's camera and autoscale,
    the read-back, the clock. A subclass draws its objects, calls :meth:`_open` first and
    :meth:`_place_camera` from its ``update``, and gives :meth:`object_bounds`."""

    canvas: SceneCfg
    camera: CameraCfg
    window: Window | None = None
    view: camera.View | None = None
    _range: float | None = None
    _pixels = None

    def _open(self, canvas: SceneCfg, camera_cfg: CameraCfg, antialias: bool,
              backend_name: str):
        """Choose the backend and make the window; returns it."""
        backend.select(backend_name)
        self.canvas, self.camera = canvas, camera_cfg
        self.window = new_window(canvas, antialias)
        self._autoscale = camera.Autoscaler()
        self.view = None
        self._range = None
        self._pixels = None
        return self.window

    def object_bounds(self, system: System) -> np.ndarray:
        """Axis-aligned bounds (n, 2, 3) of every object, for autoscale."""
        raise NotImplementedError

    def autoscale_bounds(self, system: System) -> tuple[np.ndarray, np.ndarray]:
        """What VPython's autoscale measures: the objects' bounds and the point they are
        measured from (the world axes and ``[camera] center``, as VPython)."""
        return self.object_bounds(system), np.asarray(self.camera.center, dtype=float)

    def _place_camera(self, system: System) -> None:
        c = self.camera
        w, h = self.canvas.width, self.canvas.height
        rng = c.range
        if rng is None:
            bounds, center = self.autoscale_bounds(system)
            rng = self._autoscale.update(bounds, center, c.fov, w, h)
        if self.view is not None and rng == self._range:
            return
        v = camera.view(c.center, c.forward, c.up, c.fov, rng, w, h)
        apply_view(self.window, v)
        self.view, self._range = v, rng

    def frame(self) -> np.ndarray:
        """Render and read back the frame as an (height, width, 3) uint8 array, top row first."""
        if self._pixels is None:
            from vtkmodules.vtkCommonCore import vtkUnsignedCharArray  # noqa: PLC0415  heavy: VTK

            self._pixels = vtkUnsignedCharArray()
        return grab(self.window.ren_win, self.canvas.width, self.canvas.height,
                    self._pixels)

    _clock = None            # the clock's text actor, added by the first set_clock()
    CLOCK_FONT_SIZE = 20     # px, a little smaller than the title
    CLOCK_MARGIN = 12        # px from the top and left edges

    def set_clock(self, text: str, top: int | None = None) -> None:
        """Show ``text`` (e.g. ``t = 1.23 s``) in the top-left corner from the next frame on,
        its top ``top`` px below the canvas's edge (default :attr:`CLOCK_MARGIN`).

        The text actor is added on the first call (black on a light background, white
        on a dark one, as the title); later calls only change its text.
        """
        if self._clock is None:
            from vtkmodules.vtkRenderingCore import vtkTextActor  # noqa: PLC0415  heavy: VTK

            actor = vtkTextActor()
            prop = actor.GetTextProperty()
            prop.SetFontFamilyToArial()
            prop.SetFontSize(self.CLOCK_FONT_SIZE)
            dark = title_color(self.canvas.background) == "black"
            prop.SetColor((0.0,) * 3 if dark else (1.0,) * 3)
            prop.SetJustificationToLeft()
            prop.SetVerticalJustificationToTop()
            actor.SetPosition(self.CLOCK_MARGIN, self.canvas.height
                              - (self.CLOCK_MARGIN if top is None else top))
            self.window.renderer.AddViewProp(actor)
            self._clock = actor
        self._clock.SetInput(str(text))

    def close(self) -> None:
        self.window.close()

    def __enter__(self):
        return self

    def __exit__(self, *exc) -> None:
        self.close()


class Scene(SceneBase):
    """An off-screen scene of holders, springs and balls, following a :class:`System` frame by frame.

    Parameters
    ----------
    system : System
        The state the scene starts from (its fixed nodes are holders, its free nodes balls).
    canvas, camera, holder, spring, ball : SceneCfg, CameraCfg, HolderCfg, SpringCfg, BallCfg
        What to draw with: a config's sections of those names.
    antialias : bool
        4x multisampling when True; off for draft renders.
    backend_name : str
        "auto", "egl" or "osmesa".
    """

    def __init__(self, system: System, *, canvas: SceneCfg, camera: CameraCfg,
                 holder: HolderCfg, spring: SpringCfg, ball: BallCfg, antialias: bool = True,
                 backend_name: str = "auto") -> None:
        from pyvista.core import Box, PolyData, Sphere  # noqa: PLC0415  heavy: pyvista

        win = self._open(canvas, camera, antialias, backend_name)
        self.ball_radius = ball.radius

        # holders: boxes centred on the fixed nodes
        self._holder_bounds = []
        self._holders = []          # (node, actor, rest position): driven supports move
        for node in np.flatnonzero(system.fixed):
            c = system.pos[node]
            half = np.asarray(holder.size) / 2
            box = Box(bounds=np.ravel(np.column_stack([c - half, c + half])))
            actor = win.add_actor(mesh_actor(box))
            _material(actor, holder.color)
            actor.GetProperty().SetInterpolationToFlat()      # a box has flat faces
            self._holder_bounds.append(np.stack([c - half, c + half]))
            self._holders.append((int(node), actor, c.copy()))

        # balls: one sphere mesh, moved by its actor's position
        self._balls = []
        r = ball.radius
        for node in system.free:
            sphere = Sphere(radius=r, theta_resolution=SPHERE_SLICES,
                            phi_resolution=SPHERE_SLICES)
            actor = win.add_actor(mesh_actor(sphere, smooth_shading=True))
            _material(actor, ball.color)
            self._balls.append((int(node), actor))

        # springs: tube meshes whose points are rewritten in place
        self._springs = []
        sc = spring
        for i, j in zip(system.i, system.j):
            tube = HelixTube(sc.radius, sc.thickness, sc.coils)
            frame = HelixFrame()
            pts, normals = tube.points(system.pos[i], system.pos[j] - system.pos[i],
                                       frame.set_axis(system.pos[j] - system.pos[i]))
            mesh = PolyData(pts, faces=tube.faces())
            mesh.point_data["Normals"] = normals
            mesh.GetPointData().SetActiveNormals("Normals")
            actor = win.add_actor(mesh_actor(mesh))
            _material(actor, sc.color)
            self._springs.append((int(i), int(j), tube, frame, mesh, actor))

        add_title(win, canvas)
        self.update(system)

    # -- per frame ---------------------------------------------------------------------

    def update(self, system: System) -> None:
        """Move balls and redraw springs along ``pos[j] - pos[i]`` (``spring.axis = ball.pos - holder.pos``)."""
        for node, actor in self._balls:
            actor.SetPosition(*system.pos[node])
        if system.drive is not None and system.drive.kind == "support":
            for node, actor, rest in self._holders:       # the driven holder moves
                actor.SetPosition(*(system.pos[node] - rest))
        for i, j, tube, frame, mesh, _ in self._springs:
            axis = system.pos[j] - system.pos[i]
            pts, normals = tube.points(system.pos[i], axis, frame.set_axis(axis))
            mesh.points[:] = pts
            mesh.point_data["Normals"][:] = normals
            mesh.GetPoints().Modified()
            mesh.GetPointData().GetNormals().Modified()
        self._place_camera(system)

    def object_bounds(self, system: System) -> np.ndarray:
        """Axis-aligned bounds (n, 2, 3) of every object, for autoscale."""
        r = self.ball_radius
        b = [bounds + (system.pos[node] - rest)
             for bounds, (node, _, rest) in zip(self._holder_bounds, self._holders)]
        b += [np.stack([system.pos[n] - r, system.pos[n] + r]) for n, _ in self._balls]
        for *_, mesh, _ in self._springs:
            x0, x1, y0, y1, z0, z1 = mesh.bounds
            b.append(np.array([[x0, y0, z0], [x1, y1, z1]]))
        return np.array(b)

    @property
    def ball_actors(self) -> list:
        return [actor for _, actor in self._balls]

    @property
    def spring_meshes(self) -> list:
        """The springs' tube meshes (their points are rewritten each frame)."""
        return [spring[4] for spring in self._springs]

    @property
    def spring_actors(self) -> list:
        return [spring[5] for spring in self._springs]
