"""The ball-and-spring model of matter drawn: atoms as sphere imposters, bonds as one object.

A :class:`LatticeScene` is :class:`~springscene.view.scene.Scene`'s counterpart for a
lattice config (:mod:`springscene.model.lattice`): the same off-screen window, VPython
lights and material, camera and autoscale, title, clock and read-back
(:class:`~springscene.view.scene.SceneBase`), but thousands of objects instead of three,
so each kind is one VTK object whose arrays are rewritten in place every frame:

- the atoms: one point cloud drawn by ``vtkOpenGLSphereMapper`` (each point a
  ray-cast sphere in the fragment shader: no mesh, exact silhouettes), coloured per
  atom: ``[atom] color``, or through a colour map when ``[render] color_by`` is set;
  the held atoms gray and smaller (a crystal held at its outer layer shows its inside);
- the bonds, by ``[bond] style``: ``helix``, every spring's helix tube in one mesh
  (:class:`~springscene.view.geometry.HelixBatch`); ``cylinder``, one stick imposter per
  bond (``vtkOpenGLStickMapper``); ``line``, line cells on the atoms' own points;
  ``auto``, helices up to :data:`springscene.model.lattice.HELIX_MAX_BONDS` bonds and
  cylinders beyond.

With ``color_by`` = ``displacement`` (|pos - site|) or ``speed`` (|p|/m) a colour bar
is drawn into the frame. Its range is fixed for the whole video (:func:`springscene.render.lattice_color_range`
runs a copy of the system over the video's frames first), so a colour means the
same value in every frame.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Iterable

import numpy as np

from ..colors import Color
from ..errors import UserError
from ..model.lattice import Lattice
from ..model.physics import System
from ..settings import AtomCfg, BondCfg, CameraCfg, SceneCfg
from ..units import si_prefix
from .geometry import HelixBatch, frames_from_up, perpendicular_ups
from .scene import SceneBase, _material, add_title, title_color

HELIX_MAX_BONDS = 300     # style "auto": helices up to this many bonds, cylinders beyond
# sizes as fractions of the lattice spacing d, when the config leaves them out
ATOM_RADIUS = 0.25
HELIX_RADIUS = 0.15
HELIX_THICKNESS = 0.03
CYLINDER_RADIUS = 0.05
# A lattice's helices are as coarse as the picture allows: polygons whose chords stray
# at most this far (px) from the true circles, at the nearest atom's depth, within
# these limits (the page's single spring has 60 chords a coil and 16 sides).
SAGITTA_PX = 0.25
HELIX_CHORDS = (12, 60)      # per coil
HELIX_SIDES = (6, 16)
LINE_WIDTH = 3.0             # px

HELD_COLOR = (0.5, 0.5, 0.5)     # the page's holder gray: atoms that are clamped
HELD_RADIUS = 0.6                # of an atom's radius
COLORMAP = "viridis"             # perceptually uniform, readable on white and in gray
LUT_SIZE = 256
COLOR_QUANTILE = 0.999           # the colour scale's top: this quantile over the video

# the colour bar, drawn with matplotlib and blended into the frame
BAR_DPI = 100
BAR_FONT_SIZE = 11               # pt at BAR_DPI, as the overlay panels
BAR_MARGIN = 16                  # px from the frame's edge
BAR_VERTICAL = (120, 330)        # px (width, height) at the right
BAR_HORIZONTAL = (400, 66)       # px at the bottom
BAR_MIN_VERTICAL = 140           # px: the shortest vertical bar (title and ends included)
BAR_MIN_HORIZONTAL = 200         # px: the narrowest horizontal one

_QUANTITY = {"displacement": ("displacement", "m"), "speed": ("speed", "m/s")}


def bond_style(style: str, n_bonds: int) -> str:
    """``[bond] style``, with ``auto`` resolved by the number of bonds."""
    if style == "auto":
        return "helix" if n_bonds <= HELIX_MAX_BONDS else "cylinder"
    return style


def scalar(kind: str, system: System, sites: np.ndarray) -> np.ndarray:
    """The coloured quantity per atom (N,), SI: ``displacement`` |pos - site| (m) or
    ``speed`` |p|/m (m/s)."""
    if kind == "displacement":
        return np.linalg.norm(system.pos - sites, axis=1)
    if kind == "speed":
        return np.linalg.norm(system.p, axis=1) / system.m
    raise ValueError(f"unknown colour quantity {kind!r}")


def nice_ceil(x: float) -> float:
    """The smallest of 1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 8 times a power of ten that is >= x > 0."""
    e = math.floor(math.log10(x))
    for m in (1.0, 1.2, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0):
        v = m * 10.0 ** e
        if v >= x * (1 - 1e-12):
            return v
    return 10.0 ** (e + 1)


def color_scale(kind: str, states: Iterable[System], n_values: int, lat: Lattice,
                later: System | None = None, quantile: float = COLOR_QUANTILE
                ) -> tuple[float, float]:
    """The fixed (low, high) of colouring by ``kind`` (SI) for a whole video.

    ``states`` are the system at each of the video's frames (``n_values`` values of the
    free atoms in all): the top is their ``quantile``, rounded up to a round number
    (:func:`nice_ceil`); the rare faster (or farther) atoms beyond it take the top
    colour, and a thermal crystal's bulk is not squeezed into the bottom of the scale
    by a few outliers. ``later``, a state after the video's last frame (a still), raises
    the top if the same quantile of its own values is higher. Nothing moving gives 1 %
    of d (or of the speed of sound), so that the scale is never empty.
    """
    if kind == "none":
        raise ValueError('the config colours by nothing ([render] color_by = "none")')
    sites = lat.sites()
    hi = streamed_quantile((scalar(kind, s, sites)[~s.fixed] for s in states), n_values,
                           quantile)
    if later is not None and (~later.fixed).any():
        hi = max(hi, float(np.quantile(scalar(kind, later, sites)[~later.fixed], quantile)))
    if not hi > 0:
        hi = 0.01 * (lat.d if kind == "displacement" else lat.sound_speed)
    if not math.isfinite(hi):       # the config's checks keep this from happening
        raise UserError(f"the atoms' {kind} is no longer finite ({hi}): the lattice's numbers "
                        "are beyond double precision")
    return 0.0, nice_ceil(hi)


def streamed_quantile(chunks, total: int, q: float) -> float:
    """``np.quantile`` (linear) of ``total`` values that arrive in ``chunks``, keeping only
    the largest few in memory (a million atoms over hundreds of frames would not fit);
    0 for no values."""
    if total <= 0:
        return 0.0
    pos = q * (total - 1)
    first = math.floor(pos)              # the quantile lies between sorted[first] and next
    keep = total - first
    top = np.zeros(0)
    for chunk in chunks:
        top = np.concatenate([top, np.asarray(chunk, float).ravel()])
        if len(top) > 2 * keep:
            top = np.partition(top, len(top) - keep)[len(top) - keep:]
    top = np.sort(top)[-keep:]
    if keep == 1:
        return float(top[0])
    return float(top[0] + (pos - first) * (top[1] - top[0]))


def display_unit(kind: str, high: float) -> tuple[str, float]:
    """The unit to label ``kind`` values up to ``high`` (SI) with, and its size in SI:
    the SI prefix that puts ``high`` between 1 and 1000 (e.g. ``("pm", 1e-12)``)."""
    scale, prefix = si_prefix(high, largest="k", smallest="f", tolerance=1e-9)
    return prefix + _QUANTITY[kind][1], scale


def colormap_table(name: str = COLORMAP, n: int = LUT_SIZE) -> np.ndarray:
    """The colour map as an (n, 3) uint8 table, the same colours the bar shows."""
    import matplotlib  # noqa: PLC0415  heavy: matplotlib

    cmap = matplotlib.colormaps[name].resampled(n)
    return np.round(cmap(np.arange(n))[:, :3] * 255).astype(np.uint8)


def polygon_sides(radius_px: float, limits: tuple[int, int]) -> int:
    """Sides of a polygon for a circle of ``radius_px`` whose chords stray at most
    :data:`SAGITTA_PX` from it, within ``limits``."""
    lo, hi = limits
    if radius_px <= SAGITTA_PX:
        return lo
    n = math.ceil(math.pi / math.acos(1 - SAGITTA_PX / radius_px))
    return int(min(max(n, lo), hi))


def held_color(atom_color: Color) -> Color:
    """Gray for the held atoms, one that differs from the atoms' own colour."""
    for g in (HELD_COLOR[0], 0.25, 0.8):
        if max(abs(c - g) for c in atom_color) > 0.2:
            return (g, g, g)
    return HELD_COLOR


def _to_uint8(color: Color) -> np.ndarray:
    return np.round(np.asarray(color, float) * 255).astype(np.uint8)


@dataclass
class ColorBar:
    """A colour bar as an RGBA image blended into each frame at (``x``, ``y``), its top left."""

    rgba: np.ndarray          # (h, w, 4) uint8, straight alpha
    x: int
    y: int
    title: str
    vertical: bool

    def __post_init__(self) -> None:
        a = self.rgba[..., 3:].astype(np.float32) / 255.0
        self._over = self.rgba[..., :3].astype(np.float32) * a + 0.5
        self._keep = 1.0 - a

    @property
    def box(self) -> tuple[slice, slice]:
        """Rows and columns of the frame the bar covers."""
        h, w = self.rgba.shape[:2]
        return slice(self.y, self.y + h), slice(self.x, self.x + w)

    def draw_into(self, image: np.ndarray) -> None:
        rows, cols = self.box
        region = image[rows, cols]
        h, w = region.shape[:2]          # clipped by the frame's edge
        region[...] = (region * self._keep[:h, :w] + self._over[:h, :w]).astype(np.uint8)

    @classmethod
    def render(cls, vmax: float, title: str, vertical: bool, text_color: str,
               size: tuple[int, int], x: int = 0, y: int = 0) -> "ColorBar":
        """Draw a bar from 0 to ``vmax`` (in the unit of ``title``) with matplotlib."""
        from matplotlib import colors  # noqa: PLC0415  heavy: matplotlib
        from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: PLC0415  heavy: matplotlib
        from matplotlib.cm import ScalarMappable  # noqa: PLC0415  heavy: matplotlib
        from matplotlib.figure import Figure  # noqa: PLC0415  heavy: matplotlib

        w, h = size
        fig = Figure(figsize=(w / BAR_DPI, h / BAR_DPI), dpi=BAR_DPI)
        fig.patch.set_alpha(0.0)
        canvas = FigureCanvasAgg(fig)
        import matplotlib  # noqa: PLC0415  heavy: matplotlib

        cmap = matplotlib.colormaps[COLORMAP].resampled(LUT_SIZE)
        mappable = ScalarMappable(norm=colors.Normalize(0.0, vmax), cmap=cmap)
        fs = BAR_FONT_SIZE
        if vertical:       # title in two lines on top, the bar below, labels to its right
            bar_w, top, bottom, left = 18, 48, 10, 16
            cax = fig.add_axes([left / w, bottom / h, bar_w / w, (h - top - bottom) / h])
            quantity, _, unit = title.partition(" ")
            fig.text(0.5, 1 - 4 / h, f"{quantity}\n{unit}", ha="center", va="top",
                     fontsize=fs, color=text_color, linespacing=1.2)
        else:              # title on top, the bar, labels below
            bar_h, top, side = 14, 24, 22
            cax = fig.add_axes([side / w, (h - top - bar_h) / h, (w - 2 * side) / w, bar_h / h])
            fig.text(0.5, 1 - 3 / h, title, ha="center", va="top", fontsize=fs,
                     color=text_color)
        # the top colour stands for the top value and above (the range's quantile)
        bar = fig.colorbar(mappable, cax=cax, orientation="vertical" if vertical else "horizontal",
                           extend="max", extendfrac=0.04)
        bar.outline.set_edgecolor(text_color)
        bar.ax.tick_params(labelsize=fs, colors=text_color, length=4)
        canvas.draw()
        rgba = np.array(canvas.buffer_rgba(), dtype=np.uint8)
        return cls(rgba, int(x), int(y), title, vertical)


class LatticeScene(SceneBase):
    """An off-screen scene of a lattice config's atoms and bonds, following a :class:`System`.

    Parameters
    ----------
    system : System
        The state the scene starts from (:func:`springscene.model.lattice.build`'s).
    lattice : Lattice
        The lattice's numbers (its spacing sizes the atoms and bonds; its sites are the
        displacements' zero).
    canvas, camera, atom, bond : SceneCfg, CameraCfg, AtomCfg, BondCfg
        What to draw with: a lattice config's sections of those names.
    color_by : str
        ``[render] color_by``: "none", "displacement" or "speed".
    color_range : (low, high) or None
        The fixed range (SI) of ``color_by`` (:func:`color_scale`); needed unless
        ``color_by`` is "none".
    antialias : bool
        4x multisampling when True; off for draft renders.
    backend_name : str
        "auto", "egl" or "osmesa".
    """

    def __init__(self, system: System, *, lattice: Lattice, canvas: SceneCfg,
                 camera: CameraCfg, atom: AtomCfg, bond: BondCfg, color_by: str = "none",
                 color_range: tuple[float, float] | None = None, antialias: bool = True,
                 backend_name: str = "auto") -> None:
        if color_by != "none" and color_range is None:
            raise ValueError(f"colouring by {color_by} needs a color_range (color_scale)")
        win = self._open(canvas, camera, antialias, backend_name)

        lat = lattice
        self.lattice = lat
        d = lat.d
        self.sites = lat.sites()
        self.held = system.fixed.copy()
        self._free_mask = ~self.held
        self._i, self._j = system.i.copy(), system.j.copy()
        self.atom_radius = atom.radius if atom.radius is not None else ATOM_RADIUS * d

        # the colours: per atom, fixed or through the colour map
        self.color_by = color_by
        self.color_range: tuple[float, float] | None = None
        self.unit: tuple[str, float] | None = None
        self.lut = colormap_table() if color_by != "none" else None   # matplotlib only then
        self.held_color = held_color(atom.color)
        if self.color_by != "none":
            lo, hi = (float(v) for v in color_range)
            if not hi > lo:
                raise ValueError(f"color_range must have low < high, got {color_range}")
            self.color_range = (lo, hi)
            self.unit = display_unit(self.color_by, hi)

        self._make_atoms(system, atom.color)
        self._make_bonds(system, bond, d)
        add_title(win, canvas)
        self.update(system)
        self.color_bar = self._make_color_bar() if self.color_by != "none" else None

    def _make_atoms(self, system: System, color: Color) -> None:
        """The atoms: one point cloud, each point a sphere imposter."""
        from pyvista.core import PolyData  # noqa: PLC0415  heavy: pyvista
        from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: PLC0415  heavy: VTK
        from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLSphereMapper  # noqa: PLC0415  heavy: VTK

        self.atoms = PolyData(np.asarray(system.pos, np.float32))
        rgb = np.empty((len(system.pos), 3), np.uint8)
        rgb[:] = _to_uint8(color)
        rgb[self.held] = _to_uint8(self.held_color)
        self.atoms.point_data["rgb"] = rgb
        self.atoms.GetPointData().SetActiveScalars("rgb")
        self._atom_xyz = vtk_to_numpy(self.atoms.GetPoints().GetData())
        self._atom_rgb = vtk_to_numpy(self.atoms.GetPointData().GetArray("rgb"))
        # held atoms smaller: the gray shell of a crystal held at its outer layer lets the
        # coloured atoms inside be seen
        self.radii = np.where(self.held, HELD_RADIUS * self.atom_radius, self.atom_radius)
        self.atoms.point_data["radius"] = self.radii.astype(np.float32)
        mapper = vtkOpenGLSphereMapper()
        mapper.SetInputData(self.atoms)
        mapper.SetScaleArray("radius")
        mapper.SetColorModeToDirectScalars()
        mapper.ScalarVisibilityOn()
        self.atom_actor = self._add_actor(mapper, color, "atoms")

    def _make_bonds(self, system: System, b: BondCfg, d: float) -> None:
        """The bonds: one object, in the style ``[bond] style`` resolves to."""
        self.bond_style = bond_style(b.style, len(self._i))
        if self.bond_style == "helix":
            radius = b.radius if b.radius is not None else HELIX_RADIUS * d
            thickness = b.thickness if b.thickness is not None else HELIX_THICKNESS * d
            wire = thickness / 2 if thickness > 0 else radius / 20     # as HelixTube
            self._bond_extent = radius + wire
        elif self.bond_style == "cylinder":
            radius = b.radius if b.radius is not None else CYLINDER_RADIUS * d
            self._bond_extent = radius
        else:
            radius, self._bond_extent = 0.0, 0.0
        self._place_camera(system)      # the first view sizes the helices' polygons
        getattr(self, f"_make_{self.bond_style}")(b, radius, system)

    def _add_actor(self, mapper, color, name: str):
        from vtkmodules.vtkRenderingCore import vtkActor  # noqa: PLC0415  heavy: VTK

        actor = vtkActor()
        actor.SetMapper(mapper)
        _material(actor, color)
        self.window.add_actor(actor, name=name, pickable=False)
        return actor

    # -- the bonds, by style -----------------------------------------------------------

    def _make_helix(self, b, radius: float, system: System) -> None:
        from pyvista.core import PolyData  # noqa: PLC0415  heavy: pyvista
        from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: PLC0415  heavy: VTK
        from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLPolyDataMapper  # noqa: PLC0415  heavy: VTK

        wire = self._bond_extent - radius
        ppm = self._pixels_per_metre(system)
        self.helix = HelixBatch(len(self._i), radius, 2 * wire, b.coils,
                                chords_per_coil=polygon_sides(radius * ppm, HELIX_CHORDS),
                                sides=polygon_sides(wire * ppm, HELIX_SIDES))
        axes = system.pos[self._j] - system.pos[self._i]
        self._ups = perpendicular_ups(axes)
        pts, normals = self.helix.points(system.pos[self._i], axes,
                                         frames_from_up(axes, self._ups))
        mesh = PolyData(pts.astype(np.float32), faces=self.helix.faces())
        mesh.point_data["Normals"] = normals.astype(np.float32)
        mesh.GetPointData().SetActiveNormals("Normals")
        self.bonds = mesh
        self._bond_xyz = vtk_to_numpy(mesh.GetPoints().GetData())
        self._bond_normals = vtk_to_numpy(mesh.GetPointData().GetNormals())
        mapper = vtkOpenGLPolyDataMapper()
        mapper.SetInputData(mesh)
        mapper.ScalarVisibilityOff()
        self.bond_actor = self._add_actor(mapper, b.color, "bonds")

    def _make_cylinder(self, b, radius: float, system: System) -> None:
        from pyvista.core import PolyData  # noqa: PLC0415  heavy: pyvista
        from vtkmodules.util.numpy_support import vtk_to_numpy  # noqa: PLC0415  heavy: VTK
        from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLStickMapper  # noqa: PLC0415  heavy: VTK

        n = len(self._i)
        sticks = PolyData(np.zeros((n, 3), np.float32))
        scale = np.full((n, 3), radius, np.float32)
        sticks.point_data["orientation"] = np.zeros((n, 3), np.float32)
        sticks.point_data["scale"] = scale
        # the stick mapper needs colour scalars (it crashes without them)
        sticks.point_data["rgb"] = np.tile(_to_uint8(b.color), (n, 1))
        sticks.GetPointData().SetActiveScalars("rgb")
        self.bonds = sticks
        self._bond_xyz = vtk_to_numpy(sticks.GetPoints().GetData())
        self._stick_dir = vtk_to_numpy(sticks.GetPointData().GetArray("orientation"))
        self._stick_scale = vtk_to_numpy(sticks.GetPointData().GetArray("scale"))
        mapper = vtkOpenGLStickMapper()
        mapper.SetInputData(sticks)
        mapper.SetOrientationArray("orientation")
        mapper.SetScaleArray("scale")
        mapper.SetColorModeToDirectScalars()
        mapper.ScalarVisibilityOn()
        self.bond_actor = self._add_actor(mapper, b.color, "bonds")

    def _make_line(self, b, radius: float, system: System) -> None:
        from pyvista.core import PolyData  # noqa: PLC0415  heavy: pyvista
        from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLPolyDataMapper  # noqa: PLC0415  heavy: VTK

        lines = PolyData()
        lines.SetPoints(self.atoms.GetPoints())          # the atoms' own points: no update
        lines.lines = np.column_stack([np.full(len(self._i), 2), self._i, self._j]).ravel()
        self.bonds = lines
        mapper = vtkOpenGLPolyDataMapper()
        mapper.SetInputData(lines)
        mapper.ScalarVisibilityOff()
        self.bond_actor = self._add_actor(mapper, b.color, "bonds")
        prop = self.bond_actor.GetProperty()
        prop.SetLineWidth(LINE_WIDTH)
        prop.SetRenderLinesAsTubes(True)                 # shaded as thin tubes

    # -- per frame ---------------------------------------------------------------------

    def update(self, system: System) -> None:
        """Rewrite the atoms' points (and colours) and the bonds' arrays in place for ``system``."""
        pos = system.pos
        self._atom_xyz[:] = pos
        self.atoms.GetPoints().Modified()
        if self.color_by != "none":
            free = self._free_mask
            lo, hi = self.color_range
            v = scalar(self.color_by, system, self.sites)[free]
            idx = np.clip((v - lo) * ((LUT_SIZE - 1) / (hi - lo)) + 0.5, 0, LUT_SIZE - 1)
            self._atom_rgb[free] = self.lut[idx.astype(np.intp)]
            self.atoms.GetPointData().GetScalars().Modified()
        start, end = pos[self._i], pos[self._j]
        axes = end - start
        if self.bond_style == "helix":
            self.helix.points(start, axes, frames_from_up(axes, self._ups),
                              out_points=self._bond_xyz, out_normals=self._bond_normals)
            self.bonds.GetPoints().Modified()
            self.bonds.GetPointData().GetNormals().Modified()
        elif self.bond_style == "cylinder":
            length = np.linalg.norm(axes, axis=1)
            self._bond_xyz[:] = (start + end) * 0.5
            self._stick_dir[:] = axes / length[:, None]
            self._stick_scale[:, 0] = length
            self.bonds.GetPoints().Modified()
            self.bonds.GetPointData().GetArray("orientation").Modified()
            self.bonds.GetPointData().GetArray("scale").Modified()
        self._place_camera(system)

    def object_bounds(self, system: System) -> np.ndarray:
        """Axis-aligned bounds (n, 2, 3) of every atom and bond, for autoscale."""
        pos, r = system.pos, self.radii[:, None]
        atoms = np.stack([pos - r, pos + r], axis=1)
        start, end = pos[self._i], pos[self._j]
        e = self._bond_extent
        bonds = np.stack([np.minimum(start, end) - e, np.maximum(start, end) + e], axis=1)
        return np.concatenate([atoms, bonds])

    def autoscale_bounds(self, system: System) -> tuple[np.ndarray, np.ndarray]:
        """VPython's autoscale measured in the camera's own axes (right, up, towards the
        camera) instead of the world's: the same numbers for the default camera (forward
        -z, up +y), and for an oblique ``[camera] forward`` a range that keeps every atom
        in the picture (VPython's world-axis extents clip a crystal's near corner)."""
        c = self.camera
        fwd = np.asarray(c.forward, float)
        fwd = fwd / np.linalg.norm(fwd)
        right = np.cross(fwd, c.up)
        right /= np.linalg.norm(right)
        rot = np.stack([right, np.cross(right, fwd), -fwd])        # rows: camera axes
        pos = (system.pos - np.asarray(c.center, float)) @ rot.T
        r = self.radii[:, None]
        atoms = np.stack([pos - r, pos + r], axis=1)
        start, end = pos[self._i], pos[self._j]
        e = self._bond_extent      # a bond lies within its segment's box widened by e
        bonds = np.stack([np.minimum(start, end) - e, np.maximum(start, end) + e], axis=1)
        return np.concatenate([atoms, bonds]), np.zeros(3)

    def frame(self) -> np.ndarray:
        """Render and read back the frame (h, w, 3) uint8, the colour bar drawn in."""
        image = super().frame()
        if self.color_bar is not None:
            self.color_bar.draw_into(image)
        return image

    # -- the colour bar ----------------------------------------------------------------

    @property
    def color_title(self) -> str:
        """The colour bar's title, e.g. ``displacement (pm)``."""
        return f"{_QUANTITY[self.color_by][0]} ({self.unit[0]})"

    def _make_color_bar(self) -> ColorBar | None:
        """The bar at the right when the atoms leave room there, else at the bottom;
        none on a canvas too small to hold one legibly."""
        w, h = self.canvas.width, self.canvas.height
        px = self.view.project(np.concatenate([self.sites, self._atom_xyz]))
        r_px = self._radius_px()
        right_free = w - (float(px[:, 0].max()) + r_px)
        bottom_free = h - (float(px[:, 1].max()) + r_px)
        (vw, vh), (hw, hh) = BAR_VERTICAL, BAR_HORIZONTAL
        vh = min(vh, int(0.7 * h))
        hw = min(hw, int(0.6 * w))
        fits_vertical = vh >= BAR_MIN_VERTICAL and w >= vw + BAR_MARGIN
        fits_horizontal = hw >= BAR_MIN_HORIZONTAL and h >= hh + BAR_MARGIN
        if not (fits_vertical or fits_horizontal):
            return None
        vertical = fits_vertical and (right_free >= vw + BAR_MARGIN
                                      or bottom_free < hh + BAR_MARGIN or not fits_horizontal)
        if vertical:
            size = (vw, vh)
            # centred in the room at the right, at least a margin from the edge
            x = min(w - vw - BAR_MARGIN, int(w - (right_free + vw) / 2))
            y = (h - vh) // 2
        else:
            size = (hw, hh)
            x, y = (w - hw) // 2, h - hh - max(BAR_MARGIN // 2, int((bottom_free - hh) / 2))
        vmax = self.color_range[1] / self.unit[1]
        return ColorBar.render(vmax, self.color_title, vertical,
                               title_color(self.canvas.background), size,
                               max(x, 0), max(y, 0))

    def _pixels_per_metre(self, system: System) -> float:
        """Pixels per metre at the nearest atom's depth in the current view."""
        v = self.view
        fwd = v.focal_point - v.position
        fwd = fwd / np.linalg.norm(fwd)
        depth = max(float(((system.pos - v.position) @ fwd).min()), v.near)
        return v.height / (2 * depth * math.tan(v.fov / 2))

    def _radius_px(self) -> float:
        """An atom's radius in pixels at the centre's depth."""
        v = self.view
        dist = float(np.linalg.norm(v.focal_point - v.position))
        return self.atom_radius / (2 * dist * math.tan(v.fov / 2)) * v.height
