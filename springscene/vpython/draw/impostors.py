"""Small spheres drawn as impostors: one point each, the true sphere found per pixel.

A sphere a few pixels across drawn as a mesh costs its triangles whatever its size on
screen: llvmpipe's set-up and binning run per triangle (about 36 ns each, single
threaded) and, anti-aliased, hold about 60 bytes per triangle until the frame is done.
VTK's ``vtkOpenGLSphereMapper`` draws a sphere from its centre and radius alone: a
geometry shader turns each point into one triangle facing the camera, and the fragment
shader casts the pixel's ray at the sphere, discards a miss, and writes the hit's depth
and normal, which VTK's own light code then shades (so GlowScript's rules,
:func:`~.materials.shade_as_glowscript`, apply as to a mesh).

Two things make it VPython's sphere:

* **Only small spheres**: those the level of detail (:meth:`..geometry.lod.LevelOfDetail.sphere_slices`)
  would draw with 16 slices or fewer (:data:`MAX_SLICES`), about 5.2 px of radius and
  less, at the radius whose circle has the area of VPython's 30-slice outline
  (:data:`EQUAL_AREA`). Against VPython's full mesh, % of pixels off by more than 24/255
  on three clouds of 1,000-3,000 spheres 1-5 px across: drafted 0.041, 0.027 and 0.004
  (the project's image tolerance is 0.05 %; the cut-down meshes drawn before: 0.03-0.50),
  anti-aliased 0.097, 0.136 and 0.122 (meshes: 0.16-0.94; the rest is the highlight of
  a sphere one or two pixels across, at a pixel or the next). Between
  5.2 and 11.7 px the exact circle strays from the 30-slice outline by 0.03-0.06 px and
  anti-aliased puts up to 0.15 % of pixels off (the lattice example: 0.055 %), so there
  the mesh is kept, cut down to 20 or 24 slices, and over 11.7 px VPython's 30.
* **Anti-aliased like a mesh** (:data:`COVERAGE_RULES`): VTK's shader discards whole
  pixels, which leaves a jagged outline under MSAA. The fragment shader here tests the
  ray of each of the pixel's samples (``interpolateAtSample``, ARB_gpu_shader5) and writes
  the covered ones to ``gl_SampleMask`` (ARB_sample_shading), shading once per pixel as
  MSAA shades a mesh (a pixel whose centre misses takes the outline's normal). Shaded
  per sample instead (the first try), the highlights of small spheres came out averaged,
  unlike a mesh's: 0.19-0.79 % of pixels off where the mask put 0.15-0.22 % (both
  measured before the equal-area radius).

Mesa's llvmpipe has both extensions (GL 4.5); a context without them keeps meshes
(:func:`available`). Opaque, lit, non-emissive spheres of equal size along their three
axes only (an ellipsoid, a transparent or glowing sphere keeps its mesh).

VPython's ``points`` are not spheres but GlowScript's coarse ``simple_sphere``, an 8 x 8
UV sphere that keeps the world's axes (:func:`..geometry.point_meshes.point_sphere`): a
true circle, at any radius, is 0.9-2 % of a point's pixels off its outline, which
changes with the view. :class:`PointImpostors` ray-casts that polyhedron itself, at every
size: one square a point on the near side of the sphere around it (so every hit is
behind it: ``depth_greater``, and the points go nearest first), the fragment shader
finding the pixel's ray's least gauge (:data:`_POINT_DECLARE`), the hit where the gauge
reaches 1, and the mesh's own normal there (its direction from the centre). Drafted
they draw the meshes' pictures (0.007-0.009 % of pixels off by more than 24/255);
anti-aliased, a pixel's samples are tested against the outline's reach along the
pixel's ray (0.11-0.13 %). Against real VPython (the fidelity scene ``points``)
silhouette IoU 0.991-0.996. They need ARB_conservative_depth besides
(:func:`.capsules.available`, asked by the renderer), which uses them anti-aliased only:
drafted, llvmpipe draws the meshes for less (0.89x the processor time).
"""

from __future__ import annotations

import math
import weakref

import numpy as np

from .batches import Batch
from .instanced import InstancedBatch
from .materials import shade_as_glowscript
from ..geometry.meshes import SPHERE_SLICES

# VPython's sphere is a mesh of 30 slices with its vertices on the sphere: its outline is
# about a 30-gon inscribed in the circle, 0.73 % smaller in area. An impostor of the radius
# of equal area (0.9963 r) covers the pixels the mesh covers (a sphere 8 px in radius,
# anti-aliased: coverage 201.0 px for the mesh, 202.5 for the true radius, 201.0 for this)
EQUAL_AREA = math.sqrt(SPHERE_SLICES / (2 * math.pi) * math.sin(2 * math.pi / SPHERE_SLICES))
MAX_SLICES = 16        # spheres drawn with this many slices or fewer become impostors
# spheres an impostor actor draws: llvmpipe keeps every triangle of a frame binned (about
# 300 bytes each) until it rasterises them; a chunk after the first finishes the drawing
# before it (``WaitForCompletion``), so a frame of 100,000 impostors holds 8,192 of them,
# not 30 MB (the same pixels: opaque spheres, the same order, the depth test decides)
CHUNK = 8192
EXTENSIONS = ("GL_ARB_gpu_shader5", "GL_ARB_sample_shading")
# the extensions declared in a shader (the capsules' too)
DECLARE = ("//VTK::System::Dec",
           "//VTK::System::Dec\n" + "".join(f"#extension {e} : require\n" for e in EXTENSIONS))
# one sample's ray (sampleDir from samplePos, in the sphere's unit frame), cast again
# from its own position on the impostor's triangle as VTK casts the pixel's
_SAMPLE_RAY = (
    'vec3 sampleVC = interpolateAtSample(vertexVCVSOutput, i).xyz;',
    'vec3 sampleDir = normalize(sampleVC);',
    'vec3 samplePos = vec3(0.0);',
    'if (cameraParallel != 0) {',
    '  sampleDir = vec3(0.0, 0.0, -1.0);',
    '  samplePos = sampleVC + vec3(0.0, 0.0, 3.0*radiusVCVSOutput); }',
    'else if (length(sampleVC) > radiusVCVSOutput*3.0) {',
    '  samplePos = sampleVC - sampleDir*3.0*radiusVCVSOutput; }',
    'samplePos = (samplePos - centerVCVSOutput)/radiusVCVSOutput;',
)


def _sample_ray(indent: str) -> str:
    """:data:`_SAMPLE_RAY` as GLSL lines at ``indent``."""
    return "".join(f"{indent}{line}\n" for line in _SAMPLE_RAY)


# in vtkOpenGLSphereMapper's fragment shader (VTK 9.5), after the pixel's ray is cast:
# b and d are the quadratic's terms for the pixel's centre; the samples' rays are cast
# again from their own positions on the impostor's triangle
_COVERAGE = ("  if (d < 0.0) { discard; }", """
  int coverage = 0;
  for (int i = 0; i < gl_NumSamples; ++i) {
""" + _sample_ray("    ") + """    float sb = 2.0*dot(samplePos, sampleDir);
    if (sb*sb - 4.0*(dot(samplePos, samplePos) - 1.0) >= 0.0) { coverage |= (1 << i); }
  }
  if (coverage == 0) { discard; }
  gl_SampleMask[0] = coverage;
  d = max(d, 0.0);
""")
COVERAGE_RULES = (_COVERAGE,)

# VPython's point (GlowScript's ``simple_sphere``, mesh.js ``makeSphere(0.5, 8)``) is a
# convex polyhedron: 8 bands of latitude between its poles on y, 8 sectors of longitude
# from the x and z axes and their diagonals, its vertices on the circumscribed sphere.
# Folded into one sector (|x|, |z|, ordered) a point's distance along the sector's middle,
# divided by cos(pi/8), and its |y| meet the faces of that sector as the edges of a
# regular 16-gon of unit circumradius whose vertices are at the poles: the gauge (1 on
# the surface, less inside) is the largest of four dot products. A ray hits the
# polyhedron where the least gauge along it is at most 1 (the gauge is convex along a
# line: its point nearest the centre first, else halved by the slope's sign); the hit is
# where the gauge first reaches 1 (Newton's steps from the circumscribed sphere), and its
# normal is the hit's direction from the centre, which is the mesh's: its vertex normals
# are its vertices' directions, interpolated linearly on a flat face.
_POINT_DECLARE = r"""
// the gauge at p and its rate along dir
vec2 pointGauge(vec3 p, vec3 dir) {
  vec3 f = vec3(dot(p, pointAxisX), dot(p, pointAxisZ), dot(p, pointAxisY));
  vec3 df = vec3(dot(dir, pointAxisX), dot(dir, pointAxisZ), dot(dir, pointAxisY))*sign(f);
  f = abs(f);
  vec2 hi = f.x >= f.y ? vec2(f.x, df.x) : vec2(f.y, df.y);
  vec2 lo = f.x >= f.y ? vec2(f.y, df.y) : vec2(f.x, df.x);
  vec2 rho = hi + lo*0.41421356;
  const vec4 S = vec4(0.19509032, 0.55557023, 0.83146961, 0.98078528);
  vec4 e = rho.x*S + f.z*S.wzyx;
  vec4 de = rho.y*S + df.z*S.wzyx;
  vec2 g = e.x >= e.y ? vec2(e.x, de.x) : vec2(e.y, de.y);
  vec2 h = e.z >= e.w ? vec2(e.z, de.z) : vec2(e.w, de.w);
  return (g.x >= h.x ? g : h)*1.01959115;
}
// the ray o + t dir (o and t in radii from the centre): (t, gauge) of its point of least
// gauge, found by cutting planes (the gauge is convex and piecewise linear along the ray:
// the tangents at the two ends of a bracket meet below its least value), or, with
// ``inside``, of a point of it inside (gauge 0: in the inscribed sphere, of radius
// 0.9087) or gauge 2 if it misses the circumscribed sphere (without, such a ray is
// brought inside it, scaled about the centre, and its gauge and t scaled back)
vec2 pointNearest(vec3 o, vec3 dir, bool inside) {
  float tm = -dot(o, dir);
  vec3 q = o + tm*dir;
  float qq = dot(q, q);
  float scale = 1.0;
  if (qq >= 1.0) {
    if (inside) { return vec2(tm, 2.0); }
    scale = 0.99*inversesqrt(qq);
    o *= scale;
    tm *= scale;
    q *= scale;
    qq = 0.9801;
  }
  if (inside && qq <= 0.8256) { return vec2(tm, 0.0); }
  vec2 here = pointGauge(q, dir);
  float chord = sqrt(1.0 - qq);
  vec3 lo = vec3(tm - chord, pointGauge(o + (tm - chord)*dir, dir));
  vec3 hi = vec3(tm + chord, pointGauge(o + (tm + chord)*dir, dir));
  vec2 best = vec2(tm, here.x);
  for (int k = 0; k < 4; ++k) {
    if (here.y > 0.0) { hi = vec3(tm, here); } else { lo = vec3(tm, here); }
    float slopes = lo.z - hi.z;
    if (slopes >= 0.0 || (inside && best.y <= 1.0)) { break; }
    tm = (hi.y - lo.y + lo.z*lo.x - hi.z*hi.x)/slopes;
    float floor = lo.y + lo.z*(tm - lo.x);
    if (floor > 1.0 && inside) { break; }              // the least gauge is above 1
    here = pointGauge(o + tm*dir, dir);
    if (here.x < best.y) { best = vec2(tm, here.x); }
    if (best.y - floor < 1e-4) { break; }              // the least gauge found
  }
  return best/scale;
}
// where the ray o + t dir, of least gauge ``near`` (pointNearest's), enters the
// polyhedron: one Newton's step from the circumscribed sphere onto the plane of the face
// there (the gauge is convex and piecewise linear along the ray), exact but where the
// entry is on the next face; where the ray misses, its point of least gauge brought
// onto the surface along its direction from the centre
vec3 pointHit(vec3 o, vec3 dir, vec2 near) {
  if (near.y > 1.0) { return (o + near.x*dir)/near.y; }
  float tc = -dot(o, dir);
  vec3 q = o + tc*dir;
  float t = tc - sqrt(max(1.0 - dot(q, q), 0.0));
  vec2 g = pointGauge(o + t*dir, dir);
  if (g.x > 1.0 && g.y < 0.0) { t -= (g.x - 1.0)/g.y; }
  return o + t*dir;
}
"""
# the pixel's samples tested against the polyhedron (as :data:`COVERAGE_RULES` against
# the sphere), and its hit's depth and normal in place of the sphere's
_POINT_COVERAGE = ("  if (d < 0.0) { discard; }", """
  vec2 pointCentre = pointNearest(EyePos, EyeDir, gl_NumSamples == 1);
  int coverage = pointCentre.y <= 1.0 ? 1 : 0;
  if (gl_NumSamples > 1) {
    // the outline's reach in the direction of the pixel's ray from the centre: a
    // sample's ray passing the centre nearer than that is covered
    vec3 qc = EyePos - dot(EyePos, EyeDir)*EyeDir;
    float reach = dot(qc, qc) < 1e-6 ? 1.0 : length(qc)/pointCentre.y;
    coverage = 0;
    for (int i = 0; i < gl_NumSamples; ++i) {
""" + _sample_ray("      ") + """      vec3 qs = samplePos - dot(samplePos, sampleDir)*sampleDir;
      if (dot(qs, qs) <= reach*reach) { coverage |= (1 << i); }
    }
  }
  if (coverage == 0) { discard; }
  gl_SampleMask[0] = coverage;
""")
_POINT_SURFACE = ("""  float t = (-b - invertedDepth*sqrt(d))*0.5;
  normalVCVSOutput = normalize(EyePos + t*EyeDir);
  vertexVC.xyz = normalVCVSOutput*radiusVCVSOutput + centerVCVSOutput;""", """
  vec3 hitP = pointHit(EyePos, EyeDir, pointCentre);
  normalVCVSOutput = normalize(hitP);
  vertexVC.xyz = hitP*radiusVCVSOutput + centerVCVSOutput;""")
POINT_RULES = (_POINT_COVERAGE, _POINT_SURFACE)
# the triangle each point is drawn on moved from the centre to the sphere's near side, so
# every hit lies behind it (``depth_greater``, ARB_conservative_depth) and the depth test
# turns away a hidden point's pixels before their rays are cast (the points drawn
# nearest first)
_POINT_NEAR_SIDE = (
    ("  centerVCGSOutput = gl_in[0].gl_Position.xyz/gl_in[0].gl_Position.w;", False, """
  centerVCGSOutput = gl_in[0].gl_Position.xyz/gl_in[0].gl_Position.w;
  vec3 toEye = vec3(0.0, 0.0, 1.0);
  if (cameraParallel == 0) { toEye = normalize(-gl_in[0].gl_Position.xyz); }
  vec4 nearSide = gl_in[0].gl_Position + vec4(toEye*radiusVCGSOutput, 0.0);"""),
    ("vertexVCGSOutput = gl_in[0].gl_Position + offset.x", True,
     "vertexVCGSOutput = nearSide + offset.x"),
    # a square of the radius's half-width (2 triangles) rather than VTK's one triangle:
    # 4 r^2 of pixels a point rather than 5.2 r^2
    ("layout(triangle_strip, max_vertices = 3) out;", False,
     "layout(triangle_strip, max_vertices = 4) out;"),
    ("offset = vec4(-1.73205*radiusVCGSOutput, -radiusVCGSOutput, 0.0, 0.0);", False,
     "offset = vec4(-radiusVCGSOutput, -radiusVCGSOutput, 0.0, 0.0);"),
    ("offset = vec4(1.73205*radiusVCGSOutput, -radiusVCGSOutput, 0.0, 0.0);", False,
     "offset = vec4(radiusVCGSOutput, -radiusVCGSOutput, 0.0, 0.0);"),
    ("offset = vec4(0.0, 2.0*radiusVCGSOutput, 0.0, 0.0);", False,
     "offset = vec4(-radiusVCGSOutput, radiusVCGSOutput, 0.0, 0.0);"),
    ("  EndPrimitive();", False, """
  offset = vec4(radiusVCGSOutput, radiusVCGSOutput, 0.0, 0.0);
  vertexVCGSOutput = nearSide + offset.x*base1 + offset.y*base2;
  gl_Position = VCDCMatrix * vertexVCGSOutput;
  EmitVertex();
  EndPrimitive();"""))
_POINT_DEPTH = ("#extension GL_ARB_conservative_depth : require\n",
                "layout(depth_greater) out float gl_FragDepth;\n")
POINT_AXES = ("pointAxisX", "pointAxisY", "pointAxisZ")


_available: list[bool] = []    # one answer a process: it renders with one backend


def available(render_window) -> bool:
    """The OpenGL of the window (and of the process's others: one backend a process,
    :func:`springscene.view.backend.select`) has what the impostors' shader needs; asked
    once, the window's context made now if it is not yet."""
    if not _available:
        render_window.Initialize()
        report = render_window.ReportCapabilities()
        _available.append(all(e in report for e in EXTENSIONS))
    return _available[0]


def small(radius_px: np.ndarray, steps: tuple[int, ...], tolerance: float) -> np.ndarray:
    """Which spheres of ``radius_px`` pixels the level of detail (``steps``, most
    first, and the sagitta ``tolerance``) would draw with :data:`MAX_SLICES` slices or
    fewer; none when it keeps one detail (:data:`..geometry.lod.FULL`), and none of a
    negative radius (drawn as its mesh, scaled by its negative size)."""
    radius_px = np.asarray(radius_px)
    if len(steps) < 2:
        return np.zeros(np.shape(radius_px), dtype=bool)
    return (radius_px > 0) & (radius_px * (1 - math.cos(math.pi / MAX_SLICES)) <= tolerance)


def round_spheres(size: np.ndarray) -> np.ndarray:
    """Spheres whose three diameters are equal (an impostor is round)."""
    size = np.asarray(size, dtype=float).reshape(-1, 3)
    return (size[:, 0] == size[:, 1]) & (size[:, 1] == size[:, 2])


def _finisher(window):
    """An observer that finishes ``window``'s drawing so far; it holds the window weakly (a
    strong hold would make a cycle through VTK, window to mapper to observer, that Python's
    collector cannot see: a renderer dropped unclosed would never be freed)."""
    ref = weakref.ref(window)

    def finish(*_) -> None:
        w = ref()
        if w is not None:
            w.WaitForCompletion()
    return finish


class SphereImpostors(Batch):
    """Spheres of one look drawn by ``vtkOpenGLSphereMapper``: a point, a radius and a
    colour each, :data:`CHUNK` spheres an actor (the first chunk this batch's own, the
    others its :attr:`parts`)."""

    def __init__(self, window, key: tuple, flush: bool = False) -> None:
        super().__init__(window, key)
        self.flush = flush              # finish the drawing so far before this chunk's
        self.chunks: list[SphereImpostors] = []

    def set_spheres(self, pos: np.ndarray, radius: np.ndarray, rgb: np.ndarray,
                    style: dict, area: float = EQUAL_AREA) -> None:
        """The spheres now: centres ``pos`` (M, 3), ``radius`` (M,), ``rgb`` (M, 3) uint8
        (drawn at ``area`` times the radius: that of the circle of their mesh's outline's
        area, :data:`EQUAL_AREA` for VPython's sphere), in chunks of :data:`CHUNK`."""
        radius = np.asarray(radius) * area
        starts = range(CHUNK, len(pos), CHUNK)
        while len(self.chunks) < len(starts):
            self.chunks.append(type(self)(self.window, self.key, flush=True))
        self._set_chunk(pos[:CHUNK], radius[:CHUNK], rgb[:CHUNK], style)
        for chunk, s in zip(self.chunks, starts):
            chunk._set_chunk(pos[s:s + CHUNK], radius[s:s + CHUNK], rgb[s:s + CHUNK], style)
        for chunk in self.chunks[len(starts):]:
            chunk.hide()
        self.parts = tuple(self.chunks)

    def _set_chunk(self, pos, radius, rgb, style: dict) -> None:
        self.empty = False
        pos = np.asarray(pos, dtype=float).reshape(-1, 3)
        radius = np.asarray(radius).astype(np.float32)  # read as float
        rgb = np.asarray(rgb, dtype=np.uint8).reshape(-1, 3)
        if self.actor is not None and len(pos) == self.mesh.n_points:
            self.mesh.points[:] = pos
            self.mesh.GetPoints().Modified()
            for name, values in (("radius", radius), ("rgb", rgb)):
                arr = self.mesh.point_data[name]
                if not np.array_equal(arr, values):
                    arr[:] = values
                    self.mesh.GetPointData().GetArray(name).Modified()
            self.mesh.Modified()
            return
        from pyvista.core import PolyData  # noqa: PLC0415  heavy: pyvista

        mesh = PolyData(pos.copy())
        mesh.point_data["radius"] = radius.copy()
        mesh.point_data["rgb"] = rgb.copy()
        if self.actor is None:
            self.mesh = mesh
            self._new_actor(style)
        else:
            self.mesh.shallow_copy(mesh)

    def _new_actor(self, style: dict) -> None:
        from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLSphereMapper  # noqa: PLC0415  heavy: vtk

        m = vtkOpenGLSphereMapper()
        m.SetInputData(self.mesh)
        m.SetScaleArray("radius")
        if self.flush:                  # the chunks before drawn (rasterised) first
            m.AddObserver("StartEvent", _finisher(self.window.ren_win))
        self._adopt(m, style)

    def _shade(self) -> None:
        shade_as_glowscript(self.actor, False)
        shader = self.actor.GetShaderProperty()
        shader.AddFragmentShaderReplacement(*DECLARE[:1], True, DECLARE[1], False)
        for original, replacement in COVERAGE_RULES:
            shader.AddFragmentShaderReplacement(original, False, replacement, False)


class PointImpostors(SphereImpostors):
    """VPython's points (:data:`POINT_RULES`): the true 8 x 8 polyhedron of their mesh
    ray-cast in the sphere that circumscribes it; :meth:`set_axes` gives the world's axes
    as the camera sees them (the polyhedron keeps the world's orientation)."""

    axes = np.eye(3)                    # the world's x, y, z (columns) in view coordinates

    def set_axes(self, view_rotation: np.ndarray) -> None:
        """The camera's rotation, world to view (3 x 3): the polyhedron's axes for it."""
        for part in (self, *self.chunks):
            part.axes = np.asarray(view_rotation, dtype=float)
            if part.actor is not None:
                part._set_axes()

    def set_spheres(self, pos, radius, rgb, style: dict, area: float = 1.0) -> None:
        """As :meth:`SphereImpostors.set_spheres` (``area`` 1: the polyhedron is in the
        sphere), nearest the camera of :meth:`set_axes` first."""
        order = np.argsort(-(np.asarray(pos) @ self.axes[2]), kind="stable")
        pos, radius, rgb = (np.asarray(x)[order] for x in (pos, radius, rgb))
        super().set_spheres(pos, radius, rgb, style, area)
        self.set_axes(self.axes)

    def _set_axes(self) -> None:
        uniforms = self.actor.GetShaderProperty().GetFragmentCustomUniforms()
        for name, column in zip(POINT_AXES, self.axes.T):
            uniforms.SetUniform3f(name, [float(v) for v in column])

    def _shade(self) -> None:
        shade_as_glowscript(self.actor, False)
        shader = self.actor.GetShaderProperty()
        shader.AddFragmentShaderReplacement(*DECLARE[:1], True,
                                            DECLARE[1] + _POINT_DEPTH[0], False)
        # after the uniforms' declarations (VTK's, of :attr:`axes`), before main
        shader.AddFragmentShaderReplacement(
            "//VTK::Output::Dec", True, "//VTK::Output::Dec\n" + _POINT_DEPTH[1]
            + _POINT_DECLARE, False)
        for original, every, replacement in _POINT_NEAR_SIDE:
            shader.AddGeometryShaderReplacement(original, False, replacement, every)
        for original, replacement in POINT_RULES:
            shader.AddFragmentShaderReplacement(original, False, replacement, False)
        self._set_axes()


class SphereBatch(InstancedBatch):
    """Opaque spheres of one look: the small ones impostors (:attr:`impostors`), the
    others instances of VPython's 30-slice mesh."""

    impostor_class = SphereImpostors

    def __init__(self, window, key: tuple) -> None:
        super().__init__(window, key)
        self.impostors = self.impostor_class(window, key)
        self.parts = (self.impostors,)

    @property
    def no_meshes(self) -> bool:
        """Every sphere is an impostor now: the instances' actor draws nothing."""
        return self.own_empty

    def set_spheres(self, template, template_key, pos, R, size, rgb, style,
                    small: np.ndarray, area: float = EQUAL_AREA) -> None:
        """As :meth:`set_instances`, the spheres where ``small`` drawn as impostors (``R``:
        the frames of the others only; ``area``: as :meth:`SphereImpostors.set_spheres`)."""
        big = ~small
        self.own_empty = not big.any()
        if self.own_empty:
            self.empty = False
            if self.actor is not None:
                self.actor.SetVisibility(False)
        else:
            self.set_instances(template, template_key, pos[big], R, size[big], rgb[big],
                               style)
        if small.any():
            self.impostors.set_spheres(pos[small], size[small, 0] / 2, rgb[small], style,
                                       area)
        else:
            self.impostors.hide()
        self.signature = ("spheres", template_key, int(small.sum()))


class PointBatch(SphereBatch):
    """VPython's points of one look, every one ray-cast (:class:`PointImpostors`)."""

    impostor_class = PointImpostors


__all__ = ["PointBatch", "PointImpostors", "SphereBatch", "SphereImpostors", "available", "small", "round_spheres",
           "COVERAGE_RULES", "POINT_RULES", "CHUNK", "EQUAL_AREA", "EXTENSIONS", "MAX_SLICES"]
