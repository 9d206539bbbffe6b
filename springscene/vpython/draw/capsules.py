"""Curves drawn as ray-cast capsules: a box per segment, the true tube found per pixel.

GlowScript draws every segment of a curve (and so of a trail, and a helix's chords) as
one instance of mesh.js ``makeCurveSegment``: a 16-sided open tube from the segment's
first point to its second, of each end's radius (a tapered segment is a cone), with a
hemisphere of the second point's radius on its far end (the joint to the next segment;
the curve's first end stays open), its colour blended from the first point's to the
second's along the segment and the hemisphere the second's (curve_render_vertex.shader,
``vcolor = start_color*(1-w) + end_color*w``). Drawn as triangles
(:func:`..geometry.meshes.tube`) that is about 130 vertices a segment: a curve of
15,000 segments is about a million triangles rebuilt and set up every frame it moves.

Here a segment is a box around that capsule (8 corners; its back faces culled, so each
pixel runs once, on a near face no farther than the capsule: the shader says so,
``depth_greater``, ARB_conservative_depth, and the segments are drawn nearest first, so
the depth test turns hidden pixels away before their rays are cast), and the fragment
shader casts the pixel's ray at the true shape:
the cone between the two points (its near or, looking into the open first end, its
far side) and the hemisphere on the second point; it discards a miss and writes the
hit's depth (so it meets meshes and other capsules as a mesh would), the normal the
mesh's would have there (the cone's, as :func:`..geometry.meshes.tube`'s sides) and
the blended colour; VTK's light code then shades it by GlowScript's rules
(:func:`~.materials.shade_as_glowscript`). Anti-aliased, each of the pixel's samples
casts its own ray and the covered ones go to ``gl_SampleMask``, shading once a pixel
as MSAA shades a mesh (as :mod:`.impostors` does for spheres).

The segment's points, radii and colours reach the shader as vertex attributes of the
box's corners (``MapDataArrayToVertexAttribute``), repeated on its 8 corners; a curve
that turns rewrites these arrays in place and nothing else. Needs the extensions of
:data:`.impostors.EXTENSIONS` and ARB_conservative_depth (:func:`available`); opaque,
lit curves only (curves have no opacity here; an emissive curve keeps its mesh). A
camera inside a segment's box sees none of that segment (its near faces are behind it).
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

# a segment's box: corners (along, side, up) in {0, 1}^3 and its 12 triangles wound
# outwards (counter-clockwise seen from outside), so that culling the back faces leaves
# the 3 or so near faces, a pixel each
_CORNERS = np.array([[i, j, k] for i in (0, 1) for j in (0, 1) for k in (0, 1)], dtype=float)
_BOX_TRIANGLES = np.array([
    [0, 1, 3], [0, 3, 2],      # along = 0
    [4, 6, 7], [4, 7, 5],      # along = 1
    [0, 4, 5], [0, 5, 1],      # side = 0
    [2, 3, 7], [2, 7, 6],      # side = 1
    [0, 2, 6], [0, 6, 4],      # up = 0
    [1, 5, 7], [1, 7, 3],      # up = 1
])

_VS_DECLARE = ("//VTK::Normal::Dec", """//VTK::Normal::Dec
in vec4 capStart;
in vec4 capEnd;
in vec3 capStartColor;
in vec3 capEndColor;
flat out vec4 capStartVC;
flat out vec4 capEndVC;
flat out vec3 capStartRGB;
flat out vec3 capEndRGB;
flat out vec4 capDepthZ;
flat out vec4 capDepthW;
""")
# the segment's ends in view coordinates; the rows of the view-to-device matrix that give
# a point's depth (the points go to the GPU as they are: no shift and scale, see below)
_VS_IMPL = ("//VTK::Normal::Impl", """//VTK::Normal::Impl
  capStartVC = vec4((MCVCMatrix * vec4(capStart.xyz, 1.0)).xyz, capStart.w);
  capEndVC = vec4((MCVCMatrix * vec4(capEnd.xyz, 1.0)).xyz, capEnd.w);
  capStartRGB = capStartColor;
  capEndRGB = capEndColor;
  mat4 capVCDC = MCDCMatrix * inverse(MCVCMatrix);
  capDepthZ = vec4(capVCDC[0][2], capVCDC[1][2], capVCDC[2][2], capVCDC[3][2]);
  capDepthW = vec4(capVCDC[0][3], capVCDC[1][3], capVCDC[2][3], capVCDC[3][3]);
""")

# the ray through a point of the box (view coordinates) and its nearest hit on the capsule:
# hit.x the ray's parameter (or -1.0 for none), hit.y how far along the segment (0..1, 1 on
# the hemisphere); the ray starts before the whole box when the camera is parallel
_FS_DECLARE = ("//VTK::Normal::Dec", """//VTK::Normal::Dec
flat in vec4 capStartVC;
flat in vec4 capEndVC;
flat in vec3 capStartRGB;
flat in vec3 capEndRGB;
flat in vec4 capDepthZ;
flat in vec4 capDepthW;
layout(depth_greater) out float gl_FragDepth;

void capRay(vec3 onBox, out vec3 origin, out vec3 dir) {
  if (cameraParallel != 0) {
    dir = vec3(0.0, 0.0, -1.0);
    float reach = length(capEndVC.xyz - capStartVC.xyz) + 2.0*max(capStartVC.w, capEndVC.w);
    origin = onBox + vec3(0.0, 0.0, 2.0*reach);
  } else {
    dir = normalize(onBox);
    origin = vec3(0.0);
  }
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
  // the hemisphere on the second point, on its far side
  vec3 cb = origin - capEndVC.xyz;
  float hb = dot(cb, dir);
  float hc = dot(cb, cb) - rb*rb;
  float hdisc = hb*hb - hc;
  if (hdisc >= 0.0) {
    float root = sqrt(hdisc);
    for (int i = 0; i < 2; ++i) {
      float t = -hb + (i == 0 ? -root : root);
      if (t > 0.0 && t < best && (len == 0.0 || dot(cb + t*dir, w) >= 0.0)) {
        best = t; along = 1.0; }
    }
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
  if (capAt.y >= 1.0) {
    capNormal = normalize(capPoint - capEndVC.xyz);
  } else {
    vec3 rel = capPoint - capStartVC.xyz;
    vec3 radial = normalize(rel - dot(rel, capW3)*capW3);
    capNormal = normalize(radial - (capEndVC.w - capStartVC.w)/capLen*capW3);
  }
  vec3 capRGB = mix(capStartRGB, capEndRGB, capAt.y);
""")
# the hit's normal and colour for VTK's light code
_FS_SURFACE = ("//VTK::Normal::Impl", """//VTK::Normal::Impl
  normalVCVSOutput = capNormal;
  ambientColor = ambientIntensity * capRGB;
  diffuseColor = diffuseIntensity * capRGB;
""")
FS_RULES = (_FS_DECLARE, _FS_DEPTH, _FS_SURFACE)
VS_RULES = (_VS_DECLARE, _VS_IMPL)

ATTRIBUTES = ("capStart", "capEnd", "capStartColor", "capEndColor")
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


@functools.cache
def _cells(segments: int) -> np.ndarray:
    """VTK's cell array (3, i, j, k per triangle) of ``segments`` boxes."""
    tri = (_BOX_TRIANGLES[None] + 8 * np.arange(segments)[:, None, None]).reshape(-1, 3)
    cells = np.empty((len(tri), 4), dtype=np.int64)
    cells[:, 0] = 3
    cells[:, 1:] = tri
    cells.flags.writeable = False
    return cells.ravel()


def boxes(a: np.ndarray, b: np.ndarray, ra: np.ndarray, rb: np.ndarray) -> np.ndarray:
    """The 8 corners (S * 8, 3) of a box around each segment's capsule: from ``a`` (less
    its radius, for a cone widening backwards) to ``b`` plus its hemisphere, as wide as
    the wider end (a margin of 1 % besides)."""
    axis = b - a
    length = np.linalg.norm(axis, axis=1)
    x = np.where(length[:, None] > 0, axis / np.where(length > 0, length, 1)[:, None],
                 [1.0, 0.0, 0.0])
    helper = np.where(np.abs(x[:, :1]) < 0.9, [[1.0, 0.0, 0.0]], [[0.0, 1.0, 0.0]])
    y = np.cross(x, helper)
    y /= np.linalg.norm(y, axis=1, keepdims=True)
    z = np.cross(x, y)
    r = np.maximum(ra, rb)[:, None] * 1.01
    start = a - x * r
    span = (length[:, None] + 2 * r)
    corners = (start[:, None, :]
               + _CORNERS[None, :, 0:1] * (span * x)[:, None, :]
               + (2 * _CORNERS[None, :, 1:2] - 1) * (r * y)[:, None, :]
               + (2 * _CORNERS[None, :, 2:3] - 1) * (r * z)[:, None, :])
    return corners.reshape(-1, 3)


class CapsuleBatch(Batch):
    """Curves of one look drawn as ray-cast capsules, one box a segment.

    Room is kept for 1/8 more segments than drawn: a curve whose count changes a little
    (a turning curve thinned for each view, a growing trail) keeps its mesh and cells,
    its spare boxes shrunk to a point; half as many or more than the room, a new mesh."""

    segments = 0          # the boxes the mesh has room for

    def set_segments(self, a, b, ra, rb, rgb_a, rgb_b, style: dict, view=None) -> None:
        """The segments now: from ``a`` to ``b`` (S, 3), radii ``ra``, ``rb`` (S,), colours
        ``rgb_a``, ``rgb_b`` (S, 3) uint8 at each end (drawn at :data:`MEAN_WIDTH` times
        the radii), nearest ``view``'s camera first (the depth test then spares the
        hidden ones their rays)."""
        a, b = np.asarray(a, dtype=float), np.asarray(b, dtype=float)
        if view is not None and len(a) > 1:
            forward = np.asarray(view.focal_point) - np.asarray(view.position)
            order = np.argsort((a + b) @ forward, kind="stable")
            a, b, ra, rb, rgb_a, rgb_b = (np.asarray(x)[order]
                                          for x in (a, b, ra, rb, rgb_a, rgb_b))
        ra = np.asarray(ra, dtype=float) * MEAN_WIDTH
        rb = np.asarray(rb, dtype=float) * MEAN_WIDTH
        if not len(a):
            self.hide()
            return
        self.empty = False
        n = len(a)
        room = self.segments if self.segments // 2 <= n <= self.segments else n + n // 8
        corners = np.zeros((room * 8, 3))       # the boxes past ``n``: points, drawing nothing
        corners[:n * 8] = boxes(a, b, ra, rb)
        attrs = {"capStart": np.column_stack([a, ra]), "capEnd": np.column_stack([b, rb]),
                 "capStartColor": np.asarray(rgb_a) / 255, "capEndColor": np.asarray(rgb_b) / 255}
        for name, values in attrs.items():
            padded = np.zeros((room * 8, values.shape[1]), dtype=np.float32)
            padded[:n * 8] = np.repeat(values, 8, axis=0)
            attrs[name] = padded
        if self.actor is not None and room == self.segments:
            self.mesh.points[:] = corners
            self.mesh.GetPoints().Modified()
            for name, values in attrs.items():
                arr = self.mesh.point_data[name]
                if not np.array_equal(arr, values):
                    arr[:] = values
                    self.mesh.GetPointData().GetArray(name).Modified()
            self.mesh.Modified()
            return
        from pyvista.core import PolyData  # noqa: PLC0415  heavy: pyvista

        mesh = PolyData(corners, faces=_cells(room))
        for name, values in attrs.items():
            mesh.point_data[name] = values
        mesh.point_data["rgb"] = np.zeros((len(corners), 3), dtype=np.uint8)
        normals = np.zeros((len(corners), 3))     # VTK's lit shader path; the hit's own
        normals[:, 2] = 1.0                       # normal replaces these per pixel
        mesh.point_data["Normals"] = normals
        mesh.GetPointData().SetActiveNormals("Normals")
        self.segments = room
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
        self.actor.GetProperty().BackfaceCullingOn()

    def _shade(self) -> None:
        shade_as_glowscript(self.actor, False)
        shader = self.actor.GetShaderProperty()
        shader.ClearAllVertexShaderReplacements()
        for original, replacement in VS_RULES:
            shader.AddVertexShaderReplacement(original, False, replacement, False)
        shader.AddFragmentShaderReplacement(
            *DECLARE[:1], True, DECLARE[1] + f"#extension {EXTENSION} : require\n", False)
        for original, replacement in FS_RULES:
            shader.AddFragmentShaderReplacement(original, False, replacement, False)


def segments_of(pos: np.ndarray, rgb: np.ndarray, radii: np.ndarray):
    """One polyline's segments: (a, b, ra, rb, rgb_a, rgb_b)."""
    return pos[:-1], pos[1:], radii[:-1], radii[1:], rgb[:-1], rgb[1:]


__all__ = ["CapsuleBatch", "available", "boxes", "segments_of", "FS_RULES", "VS_RULES",
           "MEAN_WIDTH", "EXTENSION"]
