"""Draw a VPython canvas off-screen, one merged mesh per kind of object.

A frame costs one geometry update per batch, not one VTK call per object: every
visible object of a kind (and opacity, shininess, emissive) is placed with one
numpy pass (:func:`springscene.vpython.geometry.placement.place`) into one mesh whose points,
normals and colours are rewritten in place. A batch none of whose objects changed
is not touched. Labels are drawn over the grabbed frame (:mod:`.label_overlay`).

Textured objects are batched per texture (VTK keeps one texture per actor) and
drawn from GlowScript's textured meshes (:mod:`..geometry.textured`, :mod:`.batches`);
triangles and quads (:mod:`..objects.polygons`) are a kind of their own, coloured,
lit and textured per vertex.

Lights, camera, autoscale and shading are those of
:class:`springscene.view.scene.Scene`, so a VPython program of the wiki scene draws
what ``springscene render`` draws. The title and caption are the page's, around the
canvas (:mod:`..page.layout`), not in it.
"""

from __future__ import annotations

import math
from collections import defaultdict

import numpy as np

from ...view import backend, camera, window
from ...view.scene import MULTI_SAMPLES, apply_view, grab
from . import autoscale, culling, helix_batches, label_overlay, materials
from ..objects import frames, polygons
from ..api import texturing
from ..geometry import meshes, object_meshes, placement, point_meshes, textured
from ..geometry.lod import DEFAULT, LevelOfDetail
from ..geometry.object_meshes import TEMPLATES, kind_mesh, rgb8, template
from .batches import Batch, TextureCache, TexturedBatch
from .impostors import PointBatch, SphereBatch
from .instanced import InstancedBatch
from .capsules import CapsuleBatch
from . import capsules, impostors
from . import surface_meshes

SCREEN_THINNED = ("lines", "tube", "points")   # drawn for the camera's view and range
INSTANCING = True     # template kinds drawn as instances of one unit mesh (:mod:`.instanced`)
IMPOSTORS = True      # small opaque spheres drawn as impostors (:mod:`.impostors`)
CAPSULES = True       # lit curves drawn as ray-cast capsules (:mod:`.capsules`)
HELIX_CAPSULES = True  # opaque lit helices drawn as their chords' capsules (:mod:`.helix_batches`)
POINT_IMPOSTORS = True   # lit points ray-cast as their 8 x 8 polyhedron, anti-aliased (:mod:`.impostors`)


_Batch = Batch       # one actor and mesh per kind and look (:mod:`.batches`)


class Renderer:
    """Off-screen drawing of one canvas; :meth:`frame` gives the picture now.

    Parameters
    ----------
    cv : canvas
        The VPython canvas to draw (its size is fixed at the first frame).
    antialias : bool
        4x multisampling when True.
    backend_name : str
        "auto", "egl" or "osmesa".
    lod : LevelOfDetail
        How finely spheres and helices are drawn for the view (:mod:`..geometry.lod`).
    """

    def __init__(self, cv, antialias: bool = True, backend_name: str = "auto",
                 lod: LevelOfDetail = DEFAULT) -> None:
        backend.select(backend_name)
        self.cv = cv
        self.width, self.height = int(cv.width), int(cv.height)
        self.antialias, self.lod = antialias, lod
        # plain VTK (no pyvista.plotting, no matplotlib); no light until scene.lights
        win = window.Window((self.width, self.height), (1.0, 1.0, 1.0), MULTI_SAMPLES)
        culling.no_frustum_culler(win.renderer)  # its bounds cost time, not pixels
        self._transparency = materials.Transparency(win, MULTI_SAMPLES if antialias else 0)
        self.window = win
        self._ambient = None
        self._batches: dict[tuple, _Batch] = {}
        self._label_specs: list = []
        self._lights_sig = None
        self._background = None
        self._textures = TextureCache()
        self.view: camera.View | None = None
        self._pixels = None

    # -- per frame -----------------------------------------------------------------------

    def frame(self) -> np.ndarray:
        """Bring the scene up to date and return it as (height, width, 3) uint8."""
        self.sync()
        if self._pixels is None:
            from vtkmodules.vtkCommonCore import vtkUnsignedCharArray  # noqa: PLC0415  heavy: vtk
            self._pixels = vtkUnsignedCharArray()
        image = grab(self.window.ren_win, self.width, self.height, self._pixels)
        return label_overlay.composite(image, self._label_specs)

    def sync(self) -> None:
        """Rewrite every batch whose objects changed, then the lights and camera
        (objects in VPython 6 frames placed in the world for the drawing)."""
        with frames.in_world(self.cv._objects):
            self._sync()

    def _sync(self) -> None:
        cv = self.cv
        groups: dict[tuple, list] = defaultdict(list)
        labels = []
        for obj in cv._objects:
            if not obj._visible or frames.hidden(obj):
                continue
            kind = obj._kind
            if kind == "label":
                labels.append(obj)
                continue
            groups[self._key(obj)].append(obj)
        for key in [k for k in self._batches if k not in groups]:   # e.g. a faded opacity
            self._batches.pop(key).remove()
        # the camera first: even the first frame's objects get their level of detail (at
        # full detail a still of 100,000 small spheres would be 96 million vertices)
        self._place_camera()
        for key, objs in groups.items():
            batch = self._batches.get(key)
            if batch is None:
                batch = self._batches[key] = self._new_batch(key, objs)
            members = np.fromiter(map(id, objs), dtype=np.int64, count=len(objs))  # 8 B each
            if batch.signature is not None \
                    and np.array_equal(getattr(batch, "members", None), members) \
                    and not any(o._dirty for o in objs):
                batch.show()
                continue
            if key[0] in SCREEN_THINNED:    # drawn once the camera is placed, for its view
                batch.objs, batch.view_key = objs, "to draw"
            else:
                self._draw(batch, key, objs)
            batch.members = members
            batch.show()
            for o in objs:
                o._dirty = False
        ambient = tuple(self.cv.ambient.value)
        if ambient != self._ambient:
            if self._ambient is not None:
                for key, batch in self._batches.items():
                    batch.restyle(self._style(key))
            self._ambient = ambient
        self._transparency.sync(self._batches.values())   # GlowScript's depth peeling
        self._sync_background()
        self._sync_lights()
        self._thin_for_this_view()
        self._detail_for_this_view()
        self._sync_labels(labels)

    def _key(self, obj) -> tuple:
        """The batch an object is drawn in: its kind and look (and texture)."""
        kind = obj._kind
        if kind in ("curve", "points"):
            return self._point_key(obj)
        if kind == "triangle":
            return ("triangle", *polygons.look(obj), self._texture_spec(obj._texture))
        key = (kind, float(obj._opacity), float(getattr(obj, "_drawn_shininess", obj._shininess)),
               bool(obj._emissive))
        spec = _texture_of(obj)
        if spec is not None and texturing.load(spec) is not None:
            return ("textured", *key, spec)
        return key

    @staticmethod
    def _texture_spec(value) -> texturing.TextureSpec | None:
        spec = texturing.spec_of(value)
        return spec if spec is not None and texturing.load(spec) is not None else None

    def _new_batch(self, key: tuple, objs=()) -> _Batch:
        spec = key[-1] if key[0] in ("textured", "triangle") else None
        if spec is None:
            if key[0] in ("tube", "lines", "points", "sphere-points") and not key[2]:
                return self._new_point_batch(key)
            if key[0] == "helix" and self._ray_cast_helices(key, objs):
                return CapsuleBatch(self.window, key)
            if not self._instanced(key):
                return _Batch(self.window, key)
            spheres = key[0] == "sphere" and IMPOSTORS and impostors.available(self.window.ren_win)
            return (SphereBatch if spheres else InstancedBatch)(self.window, key)
        texture = self._textures.get(spec.source, texturing.load(spec))
        return TexturedBatch(self.window, key, texture)

    def _new_point_batch(self, key: tuple) -> _Batch:
        """Lit curves as ray-cast capsules, lit points as spheres (the small ones
        impostors), where the GL has what their shaders need; else meshes."""
        if key[0] in ("tube", "lines"):
            ray_cast = CAPSULES and capsules.available(self.window.ren_win)
            return (CapsuleBatch if ray_cast else _Batch)(self.window, key)
        if not (IMPOSTORS and impostors.available(self.window.ren_win)):
            return _Batch(self.window, key)
        # drafted, llvmpipe draws the meshes for less (RotatingPoints' shape: 0.89x)
        ray_cast = POINT_IMPOSTORS and self.antialias and capsules.available(self.window.ren_win)
        return (PointBatch if ray_cast else SphereBatch)(self.window, key)

    def _ray_cast_helices(self, key: tuple, objs) -> bool:
        """Opaque lit helices are drawn as GlowScript draws them, a curve of chords, as
        ray-cast capsules (:func:`.helix_batches.draw_capsules`), where the GL has what
        their shader needs and the look's first helices have
        :data:`.helix_batches.MIN_CAPSULE_CHORDS` chords or more between them (fewer are a
        mesh llvmpipe sets up in a millisecond or two, and the wiki's spring keeps the
        picture of ``springscene render``); transparent and emissive ones keep meshes."""
        return HELIX_CAPSULES and key[1] >= 1 and not key[3] \
            and helix_batches.chords(objs) >= helix_batches.MIN_CAPSULE_CHORDS \
            and capsules.available(self.window.ren_win)

    @staticmethod
    def _instanced(key: tuple) -> bool:
        """Opaque lit template objects are drawn as instances (:mod:`.instanced`); the
        transparent and emissive keep placed meshes (their shader rules are written for
        VTK's plain surface shader)."""
        return INSTANCING and key[0] in TEMPLATES and key[1] >= 1 and not key[3]

    @staticmethod
    def _point_key(obj) -> tuple:
        look = (float(obj._shininess), bool(obj._emissive))
        if obj._kind == "points":
            return ("sphere-points" if obj._size_units == "world" else "points", *look)
        return ("tube" if obj._radius > 0 else "lines", *look)

    def _style(self, key: tuple) -> dict:
        ambient = float(np.mean(self.cv.ambient.value))
        style = {"ambient": ambient, "opacity": 1.0, "shininess": 0.6, "emissive": False}
        if key[0] in TEMPLATES or key[0] in ("arrow", "helix", "ring", "compound",
                                             *surface_meshes.KINDS):
            style.update(opacity=key[1], shininess=key[2], emissive=key[3])
        elif key[0] in ("tube", "sphere-points", "lines", "points", "triangle"):
            style.update(shininess=key[1], emissive=key[2])   # a triangle's opacity: RGBA
        elif key[0] == "textured":
            style.update(opacity=key[2], shininess=key[3], emissive=key[4])
        return style

    # -- geometry per kind ---------------------------------------------------------------

    def _draw(self, batch: _Batch, key: tuple, objs: list) -> None:
        kind = key[0]
        style = self._style(key)
        if kind in TEMPLATES:
            self._draw_templates(batch, key, objs, style)
        elif kind in ("lines", "points", "tube", "sphere-points"):
            self._draw_points(batch, key, objs, style)
        elif kind == "textured":
            a = textured.arrays(key[1], objs, key[-1])
            batch.set_parts(a["points"], a["normals"], a["rgb"], a["uv"], a["triangles"],
                            a["covered"], a["signature"], style)
        elif kind == "triangle":
            self._draw_polygons(batch, key, objs, style)
        elif kind in surface_meshes.KINDS:      # VPython 6's faces and convex
            self._draw_meshes(batch, key, surface_meshes.meshes(objs), style)
            surface_meshes.one_sided(batch, key)
        elif kind == "helix":             # chords as capsules, or one vectorised mesh
            draw = helix_batches.draw_capsules if isinstance(batch, CapsuleBatch) \
                else helix_batches.draw
            draw(batch, objs, self.view, style, full=self.lod.full_helices(self.antialias),
                 lod=self.lod)
            batch.objs, batch.detail_view = objs, self._view_key()
        else:
            parts = [m for m in (kind_mesh(kind, o) for o in objs) if m is not None]
            self._draw_meshes(batch, key, parts, style)

    def _draw_templates(self, batch, key, objs, style) -> None:
        if isinstance(batch, SphereBatch):
            self._draw_spheres(batch, key, objs, style)
            return
        pos, R, size, color = placement.object_frames(objs)
        slices = None
        if key[0] == "sphere":      # kept to redraw at another detail for another view
            slices, small = self._sphere_detail(pos, size)
            batch.objs, batch.drawn_detail = objs, (slices, small)
            batch.detail_view = self._view_key()
        template_ = template(key[0], slices)
        if isinstance(batch, InstancedBatch):
            batch.set_instances(template_, (key[0], slices), pos, R, size, rgb8(color), style)
        else:
            points, normals = placement.place(template_, pos, R, size)
            n = len(template_.points)
            colors = np.repeat(rgb8(color), n, axis=0)
            signature = ("tmpl", len(objs), slices)
            cells = None if signature == batch.signature else \
                placement.vtk_cells(placement.tile(template_.triangles, n, len(objs)))
            batch.set(points, normals, colors, cells, signature, style)
        if key[0] == "sphere":
            culling.cull_back_faces(batch, style, self.view, pos, size.max(axis=1) / 2)

    def _draw_spheres(self, batch, key, objs, style) -> None:
        """Spheres, the small ones impostors: only the meshed ones' turns are found."""
        pos, size, color = np.split(placement.xyz_array(objs, "_pos", "_size", "_color"), 3,
                                    axis=1)
        slices, small = self._sphere_detail(pos, size, True)
        batch.objs, batch.drawn_detail = objs, (slices, small)
        batch.detail_view = self._view_key()
        meshed = [o for o, s in zip(objs, small.tolist()) if not s]
        axis, up = np.split(placement.xyz_array(meshed, "_axis", "_up"), 2, axis=1)
        batch.set_spheres(template(key[0], slices), (key[0], slices), pos,
                          placement.frames(axis, up), size, rgb8(color), style, small)
        culling.cull_back_faces(batch, style, self.view, pos, size.max(axis=1) / 2)

    def _draw_polygons(self, batch, key, objs, style) -> None:
        """Triangles and quads: each vertex's own position, normal, colour and opacity."""
        points, normals, triangles, rgba, uv = object_meshes.polygon_arrays(objs)
        signature = ("poly", len(points), hash(triangles.tobytes()))
        if key[-1] is not None:
            batch.set_parts(points, normals, rgba, uv, triangles,
                            np.ones(len(triangles), dtype=bool), signature, style)
        else:
            cells = None if signature == batch.signature else placement.vtk_cells(triangles)
            batch.set(points, normals, rgba, cells, signature, style)

    def _sphere_detail(self, pos: np.ndarray, size: np.ndarray,
                       impostors_too: bool = False) -> tuple[int, np.ndarray]:
        """Level of detail for a batch of spheres: which are drawn as impostors (small
        and round, with ``impostors_too``), and the slices for the others' mesh, enough
        for the largest of them on screen."""
        v = self.view
        if v is None:
            return meshes.SPHERE_SLICES, np.zeros(len(pos), dtype=bool)
        fwd = v.focal_point - v.position
        fwd = fwd / np.linalg.norm(fwd)
        depth = np.maximum((pos - v.position) @ fwd, v.near)
        px_per_unit = (v.height / 2) / math.tan(v.fov / 2)
        radius_px = size.max(axis=1) / 2 / depth * px_per_unit
        small = np.zeros(len(pos), dtype=bool)
        if impostors_too:
            small = impostors.small(radius_px, self.lod.sphere_steps, self.lod.sphere_px) \
                & impostors.round_spheres(size)
        meshed = radius_px[~small]
        return self.lod.sphere_slices(float(meshed.max()) if len(meshed) else 0.0), small

    def _draw_meshes(self, batch, key, parts, style) -> None:
        if not parts:
            batch.hide()
            return
        offsets = np.cumsum([0] + [len(m[0]) for m in parts])
        points = np.concatenate([m[0] for m in parts])
        normals = np.concatenate([m[1] for m in parts])
        colors = np.concatenate([m[3] for m in parts])
        signature = tuple((len(m[0]), len(m[2])) for m in parts)
        if signature == batch.signature:
            cells = None
        else:
            cells = placement.vtk_cells(np.concatenate([m[2] + off
                                                     for m, off in zip(parts, offsets)]))
        batch.set(points, normals, colors, cells, signature, style)

    def _draw_points(self, batch, key, objs, style) -> None:
        """Points as spheres and curves as tubes (:mod:`..geometry.point_meshes`); pixel-sized points and
        thin curves sized by the range, curves thinned on screen for this view. Curves of
        a :class:`.CapsuleBatch` go as segments, points of a :class:`.SphereBatch` as
        centres and sizes (the small ones impostors), neither made into meshes."""
        if key[0] in SCREEN_THINNED:
            batch.view_key = self._view_key()
        rng, w = self.cv._range_now(), self.width
        if isinstance(batch, CapsuleBatch):
            parts = [point_meshes.polyline(key[0], o, self.view, rng, w) for o in objs]
            segs = [capsules.segments_of(*p) for p in parts if p is not None]
            if not segs:
                batch.hide()
                return
            batch.set_segments(*(np.concatenate(c) for c in zip(*segs)), style, self.view)
            return
        if isinstance(batch, SphereBatch):
            self._draw_point_spheres(batch, key, objs, style, rng, w)
            return
        parts = [point_meshes.mesh(key[0], o, self.view, rng, w) for o in objs]
        self._draw_meshes(batch, key, [m for m in parts if m is not None], style)

    def _draw_point_spheres(self, batch, key, objs, style, rng, w) -> None:
        """Points as spheres sized for this range (nothing rebuilt): with
        :data:`POINT_IMPOSTORS` (a :class:`.PointBatch`) every one ray-cast as the exact
        polyhedron of VPython's 8 x 8 point mesh (:class:`.impostors.PointImpostors`),
        else instances of that mesh."""
        arrays = [point_meshes.balls(key[0], o, rng, w) for o in objs]
        arrays = [a for a in arrays if a is not None]
        if not arrays:
            batch.hide()
            return
        pos, diam, rgb = (np.concatenate(c) for c in zip(*arrays))
        size = np.repeat(diam[:, None], 3, axis=1)
        small = np.zeros(len(pos), dtype=bool)
        if isinstance(batch, PointBatch):
            small = diam > 0                # a negative size: its mesh turned inside out
            batch.impostors.set_axes(self._view_rotation())
        R = np.broadcast_to(np.eye(3), (int((~small).sum()), 3, 3))
        batch.set_spheres(point_meshes.point_sphere(), ("points", point_meshes.POINT_SLICES),
                          pos, R, size, rgb, style, small, 1.0)
        culling.cull_back_faces(batch, style, self.view, pos, diam / 2)

    def _view_rotation(self) -> np.ndarray:
        """The camera's rotation, world to view coordinates (3 x 3), as VTK draws it."""
        m = self.window.renderer.GetActiveCamera().GetViewTransformMatrix()
        return np.array([[m.GetElement(i, j) for j in range(3)] for i in range(3)])

    def _radius_px(self, pos: np.ndarray, radius: np.ndarray) -> np.ndarray:
        """Radii in pixels on screen of spheres at ``pos``, for this view."""
        v = self.view
        fwd = v.focal_point - v.position
        fwd = fwd / np.linalg.norm(fwd)
        depth = np.maximum((pos - v.position) @ fwd, v.near)
        return radius / depth * ((v.height / 2) / math.tan(v.fov / 2))

    def _view_key(self):
        v = self.view
        return None if v is None else (tuple(v.position), tuple(v.focal_point), tuple(v.up),
                                       v.fov)

    def _thin_for_this_view(self) -> None:
        """Lines and tubes that changed, or were thinned for another camera, drawn (once)
        for this one: their points under a pixel apart on screen merged."""
        now = self._view_key()
        for key, batch in self._batches.items():
            if key[0] in SCREEN_THINNED and getattr(batch, "view_key", now) != now \
                    and batch.objs:
                self._draw(batch, key, batch.objs)

    def _detail_for_this_view(self) -> None:
        """Spheres and helices left unchanged while the camera moved (autoscale zooming in
        as a program runs, say) redrawn when their level of detail for this view differs
        from the one they were drawn at."""
        now = self._view_key()
        for key, batch in self._batches.items():
            at_a_detail = batch.drawn_detail is not None or batch.helix_arrays is not None
            if not at_a_detail or batch.detail_view == now or batch.empty:
                continue
            batch.detail_view = now
            if key[0] == "sphere":      # the objects unchanged: read again, not kept
                pos, size = np.split(placement.xyz_array(batch.objs, "_pos", "_size"), 2,
                                     axis=1)
                slices, small = self._sphere_detail(pos, size, isinstance(batch, SphereBatch))
                redraw = slices != batch.drawn_detail[0] or \
                    not np.array_equal(small, batch.drawn_detail[1])
                if not redraw:      # a camera now inside an opaque sphere sees its inside
                    culling.cull_back_faces(batch, self._style(key), self.view, pos,
                                            size.max(axis=1) / 2)
            else:
                redraw = helix_batches.detail_changed(
                    batch, self.view, self.lod.full_helices(self.antialias), self.lod)
            if redraw:
                self._draw(batch, key, batch.objs)
                batch.show()        # a part hidden at the last detail may be needed now

    # -- the rest of the picture ---------------------------------------------------------

    def _sync_background(self) -> None:
        bg = tuple(self.cv.background.value)
        if bg != self._background:
            self.window.set_background(bg)
            self._background = bg

    def _sync_lights(self) -> None:
        lights = [lt for lt in self.cv.lights if lt._visible]
        sig = tuple((type(lt).__name__, tuple(lt.color.value),
                     tuple((lt.direction if hasattr(lt, "_direction") else lt.pos).value))
                    for lt in lights)
        if sig == self._lights_sig:
            return
        self.window.remove_all_lights()
        add = self.window.renderer.AddLight
        for kind, colour, where in sig:
            if kind == "distant_light":
                add(window.scene_light(where, colour, False, focal_point=(0, 0, 0)))
            else:
                add(window.scene_light(where, colour, True, cone_angle=180))
        if not sig:        # VTK draws unlit with no light at all; VPython then shows ambient
            add(window.scene_light((0, 0, 1), (0, 0, 0), False, intensity=0.0))
        self._lights_sig = sig

    def _place_camera(self) -> None:
        cv = self.cv
        w, h = self.width, self.height
        if cv._follow is not None:
            cv._center = cv._follow.pos
        center = np.array(cv.center.value)
        if cv.autoscale:      # VPython's rule, at every render (:mod:`.autoscale`)
            autoscale.update(cv)
        rng = cv._range_now()
        v = camera.view(center, np.array(cv.forward.value), np.array(cv.up.value), cv.fov,
                        rng, w, h)
        apply_view(self.window, v)
        self.view = v

    def _sync_labels(self, labels: list) -> None:
        """GlowScript's 2D overlay: labels drawn over the grabbed frame (:mod:`.label_overlay`)."""
        bg = tuple(self.cv.background.value)
        self._label_specs = [label_overlay.spec(lab, self.view, self.width, self.height, bg)
                             for lab in labels]

    def close(self) -> None:
        self.window.close()


def _texture_of(obj) -> texturing.TextureSpec | None:
    """The texture ``obj`` is drawn with, or None (none given, none drawable, a kind without)."""
    value = getattr(obj, "texture", None)     # not obj.__dict__: that would make one
    if value is None or not textured.has_layout(obj):
        return None
    return texturing.spec_of(value)
