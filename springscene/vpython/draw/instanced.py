"""Copies of one template (spheres, boxes, cylinders, cones, pyramids) drawn by instancing.

A batch of template objects holds one small unit mesh (a sphere of so many slices, a
box...) and, per object, only where it is and how it is turned, sized and coloured:
VTK's glyph mapper (``vtkGlyph3DMapper``, OpenGL instancing) draws the template once
per object with that object's matrix ``T(pos) R S(size)``, which is
:func:`springscene.vpython.geometry.placement.place`'s ``pos + R @ (p * size)``, the normals by
the inverse transpose (GlowScript's ``rot * (normal / size)``).

Per object that is a position, a quaternion, a size and a colour (about 100 bytes, and
VTK's matrices for the instances about as much again) where a placed mesh held every
vertex twice (about 12 KB for a 10-slice sphere, 90 KB at 30 slices, and the index
buffer besides): a still of 100,000 small spheres needs a few hundred MB, not 18 GB.
The pictures are the placed meshes' (the same triangles, placed on the GPU).
"""

from __future__ import annotations

import numpy as np

from .batches import Batch


def quaternions(R: np.ndarray) -> np.ndarray:
    """(w, x, y, z) unit quaternions of rotation matrices ``R`` (M, 3, 3), columns the
    local x, y, z axes in the world (Shepperd's method: the largest of the four
    candidates is divided by, so no cancellation)."""
    R = np.asarray(R, dtype=float).reshape(-1, 3, 3)
    m00, m11, m22 = R[:, 0, 0], R[:, 1, 1], R[:, 2, 2]
    trace = m00 + m11 + m22
    q = np.empty((len(R), 4))
    cand = np.stack([trace, m00, m11, m22], axis=1)
    pick = np.argmax(cand, axis=1)
    for case in range(4):
        sel = pick == case
        if not sel.any():
            continue
        r = R[sel]
        if case == 0:
            s = 2.0 * np.sqrt(1.0 + trace[sel])
            q[sel] = np.stack([0.25 * s, (r[:, 2, 1] - r[:, 1, 2]) / s,
                               (r[:, 0, 2] - r[:, 2, 0]) / s, (r[:, 1, 0] - r[:, 0, 1]) / s], 1)
        elif case == 1:
            s = 2.0 * np.sqrt(1.0 + r[:, 0, 0] - r[:, 1, 1] - r[:, 2, 2])
            q[sel] = np.stack([(r[:, 2, 1] - r[:, 1, 2]) / s, 0.25 * s,
                               (r[:, 0, 1] + r[:, 1, 0]) / s, (r[:, 0, 2] + r[:, 2, 0]) / s], 1)
        elif case == 2:
            s = 2.0 * np.sqrt(1.0 + r[:, 1, 1] - r[:, 0, 0] - r[:, 2, 2])
            q[sel] = np.stack([(r[:, 0, 2] - r[:, 2, 0]) / s, (r[:, 0, 1] + r[:, 1, 0]) / s,
                               0.25 * s, (r[:, 1, 2] + r[:, 2, 1]) / s], 1)
        else:
            s = 2.0 * np.sqrt(1.0 + r[:, 2, 2] - r[:, 0, 0] - r[:, 1, 1])
            q[sel] = np.stack([(r[:, 1, 0] - r[:, 0, 1]) / s, (r[:, 0, 2] + r[:, 2, 0]) / s,
                               (r[:, 1, 2] + r[:, 2, 1]) / s, 0.25 * s], 1)
    return q / np.linalg.norm(q, axis=1, keepdims=True)


def _source(template):
    """The unit template as VTK polydata with its normals."""
    from pyvista.core import PolyData  # noqa: PLC0415  heavy: pyvista

    mesh = PolyData.from_regular_faces(np.asarray(template.points, dtype=float),
                                       np.asarray(template.triangles), deep=True)
    mesh.point_data["Normals"] = np.asarray(template.normals, dtype=float)
    mesh.GetPointData().SetActiveNormals("Normals")
    return mesh


class InstancedBatch(Batch):
    """Every object of one template kind and look, drawn as instances of the template."""

    def __init__(self, window, key: tuple) -> None:
        super().__init__(window, key)
        self.template_key = None
        self.instances = 0

    def set_instances(self, template, template_key, pos, R, size, rgb, style) -> None:
        """The objects now: ``pos`` (M, 3), frames ``R`` (M, 3, 3), ``size`` (M, 3),
        ``rgb`` (M, 3) uint8; ``template`` (a :class:`~..geometry.placement.Mesh`) replaced when
        ``template_key`` changes (a sphere's level of detail)."""
        self.empty = False
        pos = np.asarray(pos, dtype=float).reshape(-1, 3)
        if self.actor is None or len(pos) != self.instances:
            self._new_input(pos, R, size, rgb)
        else:
            self._update_input(pos, R, size, rgb)
        if self.actor is None:
            self._new_actor(_source(template), style)
        elif template_key != self.template_key:
            self.actor.GetMapper().SetSourceData(_source(template))
        self.template_key = template_key
        self.signature = ("instances", template_key)

    def _update_input(self, pos, R, size, rgb) -> None:
        pd = self.mesh
        pd.points[:] = pos
        pd.GetPoints().Modified()
        for name, values in (("orient", quaternions(R)), ("scale", size), ("rgb", rgb)):
            arr = pd.point_data[name]
            if not np.array_equal(arr, values):      # unchanged: not uploaded again
                arr[:] = values
                pd.GetPointData().GetArray(name).Modified()
        pd.Modified()

    def _new_input(self, pos, R, size, rgb) -> None:
        from pyvista.core import PolyData  # noqa: PLC0415  heavy: pyvista

        pd = PolyData(pos.copy())
        pd.point_data["orient"] = quaternions(R)
        pd.point_data["scale"] = np.asarray(size, dtype=float).reshape(-1, 3).copy()
        pd.point_data["rgb"] = np.asarray(rgb, dtype=np.uint8).reshape(-1, 3).copy()
        self.instances = len(pos)
        if self.actor is None:
            self.mesh = pd
        else:                        # the mapper keeps its input; its content changes
            self.mesh.shallow_copy(pd)

    def _new_actor(self, source, style) -> None:
        from vtkmodules.vtkRenderingCore import vtkGlyph3DMapper  # noqa: PLC0415  heavy: vtk

        m = vtkGlyph3DMapper()
        m.SetInputData(self.mesh)
        m.SetSourceData(source)
        m.SetScaleArray("scale")
        m.SetScaleModeToScaleByVectorComponents()
        m.SetScaleFactor(1.0)
        m.SetOrientationArray("orient")
        m.SetOrientationModeToQuaternion()
        self._adopt(m, style)
