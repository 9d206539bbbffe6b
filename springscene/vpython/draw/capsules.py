"""Curves drawn as ray-cast capsules: a quad per segment, the true tube found per pixel.

GlowScript draws every segment of a curve (and so of a trail, and a helix's chords) as
one instance of mesh.js ``makeCurveSegment``: a 16-sided open tube from the segment's
first point to its second, of each end's radius (a tapered segment is a cone), with a
hemisphere of the second point's radius on its far end (the joint to the next segment;
the curve's first end stays open), its colour blended from the first point's to the
second's along the segment and the hemisphere the second's (curve_render_vertex.shader,
``vcolor = start_color*(1-w) + end_color*w``). Drawn as triangles
(:func:`..geometry.meshes.tube`) that is about 130 vertices a segment: a curve of
15,000 segments is about a million triangles rebuilt and set up every frame it moves.

Here a segment is one quad facing the camera, made in the vertex shader from the
segment's ends and radii: on the plane of the capsule's nearest point (no farther than the
capsule anywhere: the shader says so, ``depth_greater``, ARB_conservative_depth), along
the segment as seen and across it, exactly as far as its two end spheres reach on screen
(the capsule lies in their hull), so no corners are computed in numpy. The fragment
shader casts the pixel's ray at the true shape: the cone between the two points (its
near or, looking into the open first end, its far side) and the hemisphere on the second
point; it discards a miss and writes the hit's depth (so it meets meshes and other capsules as a mesh would), the normal the
mesh's would have there (the cone's, as :func:`..geometry.meshes.tube`'s sides) and
the blended colour; VTK's light code then shades it by GlowScript's rules
(:func:`~.materials.shade_as_glowscript`). Anti-aliased, each of the pixel's samples
casts its own ray and the covered ones go to ``gl_SampleMask``, shading once a pixel
as MSAA shades a mesh (as :mod:`.impostors` does for spheres).

A helix's chords (:func:`.helix_batches.draw_capsules`) are segments joined smoothly:
each end but the wire's two is marked a joint (a negative radius), and given the wire's
tangent there (``bends``). The quad then stops a little past a joint (the next chord's
quad draws the tube beyond it: AtomicSolid's chords, shorter than the wire is thick,
overlapped about four deep), a chord's joint on its first end holds the sphere the
previous chord ends in (so a ray into the open end finds that, not the inside), and the
wire is shaded round its tangent blended along the chord, as the helix mesh's normals
are (GlowScript's straight segments show a faint facet a chord; the mesh does not).

The segment's points, radii, colours and tangents reach the shader as vertex attributes
of the quad's corners (``MapDataArrayToVertexAttribute``), written on its 4 corners in
place; the corners themselves are fixed codes. Needs the extensions of
:data:`.impostors.EXTENSIONS` and ARB_conservative_depth (:func:`available`); opaque,
lit curves only (curves have no opacity here; an emissive curve keeps its mesh). A
capsule reaching behind the near plane is drawn from a quad on the near plane.
"""

from __future__ import annotations

import functools

import math

import numpy as np

from .batches import Batch
from . import impostors
from .impostors import DECLARE
from .materials import shade_as_glowscript
from ..geometry.meshes import CURVE_SIDES

# VPython's tube is 16-sided with its vertices on the circle: seen from the side it is as
# wide as the circle at a vertex and cos(pi/16) of it between; a capsule of the radius of
# the 16-gon's mean width, (16/pi) sin(pi/16) r = 0.9936 r, covers the pixels it covers
MEAN_WIDTH = CURVE_SIDES / math.pi * math.sin(math.pi / CURVE_SIDES)

# past a smooth joint, a quad goes this share of its end sphere's reach, and twice the sine
# of the turn on screen besides (:func:`capReach`): the outer side of the joint is then
# covered, the next segment's quad drawing the rest of the tube there
JOINT_MARGIN = 0.2

_VS_DECLARE = ("//VTK::Normal::Dec", """//VTK::Normal::Dec
#define JOINT_MARGIN JOINT_MARGIN_VALUE
in vec4 capStart;
in vec4 capEnd;
in vec3 capStartColor;
in vec3 capEndColor;
in vec3 capStartBend;
in vec3 capEndBend;
uniform int cameraParallel;
flat out vec4 capStartVC;
flat out vec4 capEndVC;
flat out vec3 capStartRGB;
flat out vec3 capEndRGB;
flat out vec3 capStartT;
flat out vec3 capEndT;
flat out float capJoinA;
flat out vec4 capDepthZ;
flat out vec4 capDepthW;

// where the sphere (c, r) is seen along the screen direction d: the least and greatest
// x / -z (perspective) or x (parallel) of its points, x along d; the tangent rays' angles
// kept short of the eye's plane
vec2 capSpan(vec3 c, float r, vec2 d) {
  float x0 = dot(c.xy, d);
  if (cameraParallel != 0) { return vec2(x0 - r, x0 + r); }
  float alpha = atan(x0, -c.z);
  float beta = asin(clamp(r / max(length(vec2(x0, c.z)), 1e-30), 0.0, 1.0));
  return tan(clamp(vec2(alpha - beta, alpha + beta), -1.55, 1.55));
}

// how far, as a share of its sphere's reach, the quad goes past an end at ``t`` (screen)
// where the wire goes on along ``bend`` (view coordinates) into the next segment: far
// enough to cover the outer side of the joint, where the two segments' sides part by
// twice the angle between this one (``u`` on screen) and the wire's tangent there
float capReach(vec2 t, vec3 bend, vec2 u) {
  vec2 onScreen = cameraParallel != 0 ? bend.xy : bend.xy + t*bend.z;
  float turn = abs(u.x*onScreen.y - u.y*onScreen.x) / max(length(onScreen), 1e-30);
  return min(1.0, JOINT_MARGIN + 2.0*turn);
}
""")
# the segment's ends in view coordinates; the rows of the view-to-device matrix that give
# a point's depth (the points go to the GPU as they are: no shift and scale, see below)
_VS_IMPL = ("//VTK::Normal::Impl", """//VTK::Normal::Impl
  capStartVC = vec4((MCVCMatrix * vec4(capStart.xyz, 1.0)).xyz, abs(capStart.w));
  capEndVC = vec4((MCVCMatrix * vec4(capEnd.xyz, 1.0)).xyz, abs(capEnd.w));
  capStartRGB = capStartColor;
  capEndRGB = capEndColor;
  capStartT = (MCVCMatrix * vec4(capStartBend, 0.0)).xyz;
  capEndT = (MCVCMatrix * vec4(capEndBend, 0.0)).xyz;
  capJoinA = capStart.w < 0.0 ? 1.0 : 0.0;
  mat3 capTurn = transpose(mat3(MCVCMatrix));     // the view is a turn and a shift
  mat4 capVCDC = MCDCMatrix * mat4(vec4(capTurn[0], 0.0), vec4(capTurn[1], 0.0),
                                   vec4(capTurn[2], 0.0), vec4(-(capTurn * MCVCMatrix[3].xyz), 1.0));
  capDepthZ = vec4(capVCDC[0][2], capVCDC[1][2], capVCDC[2][2], capVCDC[3][2]);
  capDepthW = vec4(capVCDC[0][3], capVCDC[1][3], capVCDC[2][3], capVCDC[3][3]);
""")
# the quad (its corner ``vertexMC.xy`` in {0, 1}^2) facing the camera on the plane of the
# capsule's nearest point (no nearer than the near plane): along the segment as seen and
# across it, as far as the two end spheres reach on screen (the capsule is in their hull);
# an end given a negative radius is a smooth joint (a helix's): the next segment's quad
# draws the tube past it, so this one goes only as far past it as the joint needs
# (:func:`capReach`)
_VS_QUAD = ("//VTK::PositionVC::Impl", """//VTK::PositionVC::Impl
  {
    vec3 qa = capStartVC.xyz, qb = capEndVC.xyz;
    float qra = capStartVC.w, qrb = capEndVC.w;
    float zNear = capVCDC[3][2] / (capVCDC[2][2] - 1.0);     // the near plane's -z
    float qz = cameraParallel != 0 ? max(qa.z + qra, qb.z + qrb)
                                   : min(max(qa.z + qra, qb.z + qrb), -1.0001*zNear);
    vec2 ta = cameraParallel != 0 ? qa.xy : qa.xy / max(-qa.z, 1e-30);
    vec2 tb = cameraParallel != 0 ? qb.xy : qb.xy / max(-qb.z, 1e-30);
    vec2 u = tb - ta;
    float ul = length(u);
    u = ul > 1e-12 ? u / ul : vec2(1.0, 0.0);
    vec2 v = vec2(-u.y, u.x);
    vec2 sua = capSpan(qa, qra, u), sub = capSpan(qb, qrb, u);
    vec2 sva = capSpan(qa, qra, v), svb = capSpan(qb, qrb, v);
    float ka = capStart.w < 0.0 ? capReach(ta, capStartT, u) : 1.0;
    float kb = capEnd.w < 0.0 ? capReach(tb, capEndT, u) : 1.0;
    float ua = dot(ta, u), ub = dot(tb, u);
    vec2 su = vec2(min(mix(ua, sua.x, ka), mix(ub, sub.x, kb)),
                   max(mix(ua, sua.y, ka), mix(ub, sub.y, kb)))
              + vec2(-1e-3, 1e-3)*(sua.y - sua.x);
    vec2 sv = vec2(min(sva.x, svb.x), max(sva.y, svb.y)) + vec2(-1e-3, 1e-3)*(sva.y - sva.x);
    vec2 t = u*mix(su.x, su.y, vertexMC.x) + v*mix(sv.x, sv.y, vertexMC.y);
    vertexVCVSOutput = vec4(cameraParallel != 0 ? t : -qz*t, qz, 1.0);
    gl_Position = capVCDC * vertexVCVSOutput;
  }
""")

# the ray through a point of the quad (view coordinates) and its nearest hit on the capsule:
# hit.x the ray's parameter (or -1.0 for none), hit.y how far along the segment (0..1, 1 on
# the hemisphere, -1 on a joint's sphere on the first end); the ray starts before the
# whole capsule when the camera is parallel
_FS_DECLARE = ("//VTK::Normal::Dec", """//VTK::Normal::Dec
flat in vec4 capStartVC;
flat in vec4 capEndVC;
flat in vec3 capStartRGB;
flat in vec3 capEndRGB;
flat in vec3 capStartT;
flat in vec3 capEndT;
flat in float capJoinA;
flat in vec4 capDepthZ;
flat in vec4 capDepthW;
layout(depth_greater) out float gl_FragDepth;

void capRay(vec3 onQuad, out vec3 origin, out vec3 dir) {
  if (cameraParallel != 0) {
    dir = vec3(0.0, 0.0, -1.0);
    float reach = length(capEndVC.xyz - capStartVC.xyz) + 2.0*max(capStartVC.w, capEndVC.w);
    origin = onQuad + vec3(0.0, 0.0, 2.0*reach);
  } else {
    dir = normalize(onQuad);
    origin = vec3(0.0);
  }
}

// the ray's nearest hit before ``best`` on the half of the sphere (c, r) towards ``side``
float capSphere(vec3 origin, vec3 dir, vec3 c, float r, vec3 side, float best) {
  vec3 rel = origin - c;
  float hb = dot(rel, dir);
  float hdisc = hb*hb - dot(rel, rel) + r*r;
  if (hdisc >= 0.0) {
    float root = sqrt(hdisc);
    for (int i = 0; i < 2; ++i) {
      float t = -hb + (i == 0 ? -root : root);
      if (t > 0.0 && t < best && dot(rel + t*dir, side) >= 0.0) { return t; }
    }
  }
  return best;
}

vec2 capHit(vec3 origin, vec3 dir) {
  vec3 axis = capEndVC.xyz - capStartVC.xyz;
  float len = length(axis);
  vec3 w = axis / max(len, 1e-30);
  float ra = capStartVC.w, rb = capEndVC.w;
  float k = (rb - ra) / max(len, 1e-30);
  float best = 1e30, along = 0.0;
  // the cone: |perp(p - a)| = ra + k (p - a).w, for 0 <= (p - a).w <= len
  vec3 co = origin - capStartVC.xyz;
  float s0 = dot(co, w), dw = dot(dir, w);
  vec3 cp = co - s0*w, dp = dir - dw*w;
  float r0 = ra + k*s0;
  float qa = dot(dp, dp) - k*k*dw*dw;
  float qb = dot(cp, dp) - k*dw*r0;
  float qc = dot(cp, cp) - r0*r0;
  float disc = qb*qb - qa*qc;
  if (len > 0.0 && disc >= 0.0 && abs(qa) > 1e-30) {
    float root = sqrt(disc);
    for (int i = 0; i < 2; ++i) {
      float t = (-qb + (i == 0 ? -root : root)) / qa;
      float s = s0 + t*dw;
      if (t > 0.0 && t < best && s >= 0.0 && s <= len && r0 + k*(s - s0) >= 0.0) {
        best = t; along = s / len; }
    }
  }
  // the hemisphere on the second point, on its far side; a smooth joint's on the first
  // (the previous segment's, there anyway: the ray into the open end finds it, not the
  // inside of this one)
  float t = capSphere(origin, dir, capEndVC.xyz, rb, len > 0.0 ? w : vec3(0.0), best);
  if (t < best) { best = t; along = 1.0; }
  if (capJoinA > 0.5) {
    t = capSphere(origin, dir, capStartVC.xyz, ra, -w, best);
    if (t < best) { best = t; along = -1.0; }
  }
  return vec2(best < 1e30 ? best : -1.0, along);
}

""")

# after ``vec4 vertexVC = vertexVCVSOutput;``: cast the rays (each sample's, anti-aliased),
# shade at the pixel centre's hit or, where that misses, the first covered sample's
_FS_DEPTH = ("//VTK::Depth::Impl", """
  vec3 capOrigin, capDir;
  capRay(vertexVCVSOutput.xyz, capOrigin, capDir);
  vec2 capAt = capHit(capOrigin, capDir);
  int coverage = capAt.x >= 0.0 ? -1 : 0;
  if (gl_NumSamples > 1) {
    coverage = 0;
    for (int i = 0; i < gl_NumSamples; ++i) {
      vec3 sOrigin, sDir;
      capRay(interpolateAtSample(vertexVCVSOutput, i).xyz, sOrigin, sDir);
      vec2 sAt = capHit(sOrigin, sDir);
      if (sAt.x >= 0.0) {
        coverage |= (1 << i);
        if (capAt.x < 0.0) { capAt = sAt; capOrigin = sOrigin; capDir = sDir; }
      }
    }
  }
  if (coverage == 0) { discard; }
  gl_SampleMask[0] = coverage;
  vec3 capPoint = capOrigin + capAt.x*capDir;
  vertexVC = vec4(capPoint, 1.0);
  float capZ = dot(capDepthZ, vertexVC), capW = dot(capDepthW, vertexVC);
  gl_FragDepth = clamp(0.5*(capZ/capW) + 0.5, 0.0, 1.0);
  vec3 capAxis = capEndVC.xyz - capStartVC.xyz;
  float capLen = length(capAxis);
  vec3 capW3 = capAxis / max(capLen, 1e-30);
  vec3 capNormal;
  float capAlong = clamp(capAt.y, 0.0, 1.0);
  if (dot(capStartT, capStartT) > 0.0) {     // a smooth wire: the tube round its tangent
    vec3 bent = normalize(mix(capStartT, capEndT, capAlong));
    vec3 across = capPoint - mix(capStartVC.xyz, capEndVC.xyz, capAlong);
    capNormal = normalize(across - dot(across, bent)*bent);
  } else if (capAt.y >= 1.0) {
    capNormal = normalize(capPoint - capEndVC.xyz);
  } else if (capAt.y < 0.0) {
    capNormal = normalize(capPoint - capStartVC.xyz);
  } else {
    vec3 rel = capPoint - capStartVC.xyz;
    vec3 radial = normalize(rel - dot(rel, capW3)*capW3);
    capNormal = normalize(radial - (capEndVC.w - capStartVC.w)/capLen*capW3);
  }
  vec3 capRGB = mix(capStartRGB, capEndRGB, capAlong);
""")
# the hit's normal and colour for VTK's light code
_FS_SURFACE = ("//VTK::Normal::Impl", """//VTK::Normal::Impl
  normalVCVSOutput = capNormal;
  ambientColor = ambientIntensity * capRGB;
  diffuseColor = diffuseIntensity * capRGB;
""")
FS_RULES = (_FS_DECLARE, _FS_DEPTH, _FS_SURFACE)
_VS_DECLARE = (_VS_DECLARE[0], _VS_DECLARE[1].replace("JOINT_MARGIN_VALUE", f"{JOINT_MARGIN:.3f}"))
VS_RULES = (_VS_DECLARE, _VS_IMPL)
VS_FIRST_RULES = (_VS_QUAD,)

ATTRIBUTES = ("capStart", "capEnd", "capStartColor", "capEndColor", "capStartBend", "capEndBend")
EXTENSION = "GL_ARB_conservative_depth"

_available: list[bool] = []    # one answer a process, as impostors.available


def available(render_window) -> bool:
    """The window's OpenGL has what the capsules' shader needs: the impostors' extensions
    (:func:`.impostors.available`) and :data:`EXTENSION`."""
    if not _available:
        render_window.Initialize()     # (the impostors may have asked another window first)
        _available.append(impostors.available(render_window)
                          and EXTENSION in render_window.ReportCapabilities())
    return _available[0]


# a segment's quad: corners (along, across) in {0, 1}^2, as the vertex shader reads them
_QUAD = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], dtype=np.float32)
_QUAD_TRIANGLES = np.array([[0, 1, 2], [0, 2, 3]])


@functools.cache
def _cells(segments: int) -> np.ndarray:
    """VTK's cell array (3, i, j, k per triangle) of ``segments`` quads."""
    tri = (_QUAD_TRIANGLES[None] + 4 * np.arange(segments)[:, None, None]).reshape(-1, 3)
    cells = np.empty((len(tri), 4), dtype=np.int64)
    cells[:, 0] = 3
    cells[:, 1:] = tri
    cells.flags.writeable = False
    return cells.ravel()


class CapsuleBatch(Batch):
    """Curves of one look drawn as ray-cast capsules, one quad a segment.

    Room is kept for 1/8 more segments than drawn: a curve whose count changes a little
    (a turning curve thinned for each view, a growing trail) keeps its mesh and cells,
    its spare quads of no size; half as many or more than the room, a new mesh. The
    mesh's points are the quads' corners as codes (:data:`_QUAD`), never rewritten: a
    frame rewrites the segments' ends and radii (and colours, when they change) in place."""

    segments = 0          # the quads the mesh has room for
    drawn = 0             # the segments drawn in them now
    bent = False          # the wire's own tangents given (``bends``): a smooth tube
    helix_chords = None   # helices: chords a coil drawn, by shape (:mod:`.helix_batches`)
    colours: tuple = ()   # the segments' end colours drawn (uint8), to skip rewriting them

    def set_segments(self, a, b, ra, rb, rgb_a, rgb_b, style: dict, view=None,
                     bends=None) -> None:
        """The segments now: from ``a`` to ``b`` (S, 3), radii ``ra``, ``rb`` (S,), colours
        ``rgb_a``, ``rgb_b`` (S, 3) uint8 at each end (drawn at :data:`MEAN_WIDTH` times
        the radii); ``view`` is not needed (the quads face the camera in the shader).
        ``bends``: the wire's tangents (S, 3) at each end, for a wire shaded as a smooth
        tube (a helix, as its mesh is); None, each segment's tube shaded straight, as
        GlowScript shades a curve's segments."""
        n = len(a)
        if not n:
            self.hide()
            return
        self.empty = False
        room = self.segments if self.segments // 2 <= n <= self.segments else n + n // 8
        if self.actor is None or room != self.segments:
            self._new_mesh(room, style)
        ends = {"capStart": (a, ra), "capEnd": (b, rb)}
        for name, (p, r) in ends.items():
            arr = self._quads(name)
            arr[:n, :, :3] = np.asarray(p, dtype=np.float32)[:, None, :]
            arr[:n, :, 3] = (np.asarray(r, dtype=np.float32) * np.float32(MEAN_WIDTH))[:, None]
            arr[n:self.drawn] = 0
            self.mesh.GetPointData().GetArray(name).Modified()
        rgb_a, rgb_b = np.asarray(rgb_a), np.asarray(rgb_b)
        if self.drawn != n or not all(map(np.array_equal, self.colours, (rgb_a, rgb_b))):
            for name, rgb in (("capStartColor", rgb_a), ("capEndColor", rgb_b)):
                arr = self._quads(name)
                arr[:n] = (rgb.astype(np.float32) / np.float32(255))[:, None, :]
                arr[n:self.drawn] = 0
                self.mesh.GetPointData().GetArray(name).Modified()
            self.colours = (rgb_a.copy(), rgb_b.copy())
        if bends is not None or self.bent:
            for name, t in zip(("capStartBend", "capEndBend"), bends or (0.0, 0.0)):
                arr = self._quads(name)
                arr[:n] = np.asarray(t, dtype=np.float32)[:, None, :] if bends else 0.0
                arr[n:self.drawn] = 0
                self.mesh.GetPointData().GetArray(name).Modified()
            self.bent = bends is not None
        self.drawn = n
        self.mesh.Modified()

    def _quads(self, name: str) -> np.ndarray:
        """The point array ``name`` as (segments, 4 corners, components), in place (a
        plain numpy view: pyvista's own ``__setitem__`` costs a millisecond a write)."""
        return np.asarray(self.mesh.point_data[name]).reshape(self.segments, 4, -1)

    def _new_mesh(self, room: int, style: dict) -> None:
        from pyvista.core import PolyData  # noqa: PLC0415  heavy: pyvista

        mesh = PolyData(np.tile(_QUAD, (room, 1)), faces=_cells(room))
        for name, width in zip(ATTRIBUTES, (4, 4, 3, 3, 3, 3)):
            mesh.point_data[name] = np.zeros((room * 4, width), dtype=np.float32)
        mesh.point_data["rgb"] = np.zeros((room * 4, 3), dtype=np.uint8)
        normals = np.zeros((room * 4, 3), dtype=np.float32)   # VTK's lit shader path; the
        normals[:, 2] = 1.0                                   # hit's normal replaces these
        mesh.point_data["Normals"] = normals
        mesh.GetPointData().SetActiveNormals("Normals")
        self.segments, self.drawn, self.colours = room, 0, ()
        self.signature = ("capsules", room)
        if self.actor is None:
            self.mesh = mesh
            self._new_actor(style)
        else:
            self.mesh.shallow_copy(mesh)

    def _new_actor(self, style: dict) -> None:
        from vtkmodules.vtkRenderingOpenGL2 import vtkOpenGLPolyDataMapper  # noqa: PLC0415  heavy: vtk

        m = vtkOpenGLPolyDataMapper()
        m.SetInputData(self.mesh)
        m.SetVBOShiftScaleMethod(0)        # the corners as given: the attributes are not shifted
        for name in ATTRIBUTES:
            m.MapDataArrayToVertexAttribute(name, name, 0, -1)
        self._adopt(m, style)

    def _shade(self) -> None:
        shade_as_glowscript(self.actor, False)
        shader = self.actor.GetShaderProperty()
        shader.ClearAllVertexShaderReplacements()
        for original, replacement in VS_FIRST_RULES:
            shader.AddVertexShaderReplacement(original, True, replacement, False)
        for original, replacement in VS_RULES:
            shader.AddVertexShaderReplacement(original, False, replacement, False)
        shader.AddFragmentShaderReplacement(
            *DECLARE[:1], True, DECLARE[1] + f"#extension {EXTENSION} : require\n", False)
        for original, replacement in FS_RULES:
            shader.AddFragmentShaderReplacement(original, False, replacement, False)


def segments_of(pos: np.ndarray, rgb: np.ndarray, radii: np.ndarray):
    """One polyline's segments: (a, b, ra, rb, rgb_a, rgb_b)."""
    return pos[:-1], pos[1:], radii[:-1], radii[1:], rgb[:-1], rgb[1:]


__all__ = ["CapsuleBatch", "available", "segments_of", "FS_RULES", "VS_RULES",
           "MEAN_WIDTH", "EXTENSION"]
