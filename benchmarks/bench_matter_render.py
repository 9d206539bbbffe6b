"""Drawing the model of matter: a 10 x 10 x 10 crystal's frames per second (`make bench`).

``configs/crystal.toml`` (1000 atoms, 2700 bonds drawn as cylinders, coloured by
speed) at 900 x 600. Each frame is what ``render_video`` does for it: step the
physics to the frame's time, update the scene, render and read back (no encoding).
Against baselines drawn in the same run, with the same lights, material, colours
and camera:

- imposters: :class:`springscene.view.lattice_scene.LatticeScene`: one point cloud of
  sphere imposters and one of stick imposters, arrays rewritten in place;
- merged mesh: one mesh of 1000 tessellated 30 x 30 spheres (the page's ball) and
  one of 2700 16-sided cylinder tubes, every vertex and normal rewritten in place
  by numpy each frame: the best a mesh-based renderer does;
- per object: the VPython way, one actor per atom (a shared 30 x 30 sphere, moved
  by its actor's position, coloured by its property) and one per bond (a shared
  unit cylinder placed by its actor's matrix): 3700 actors updated from Python.

Anti-aliased (4x MSAA) unless marked draft. Rounds are interleaved and the best of
each kept. Runs in well under a minute.
"""

from __future__ import annotations

import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))

from springscene import build, config, render  # noqa: E402
from springscene.model import physics  # noqa: E402
from springscene.view import backend, scene  # noqa: E402
from springscene.view.geometry import frames_from_up, perpendicular_ups  # noqa: E402
from springscene.view import lattice_scene as ls  # noqa: E402

ROUNDS = 3
FRAMES = {"imposters": 20, "imposters draft": 20, "merged mesh": 5,
          "merged mesh draft": 5, "per object": 3}
SPHERE_RES = scene.SPHERE_SLICES
CYLINDER_SIDES = 16


def steps_per_frame(cfg) -> int:
    return max(1, round(cfg.render.speed / (cfg.render.fps * cfg.physics.dt)))


class Baseline:
    """What the baselines share with LatticeScene: its window, camera, colours, title."""

    def __init__(self, cfg, system, antialias, color_range):
        # borrow a LatticeScene for the window, camera and colour bar; hide its objects
        self.sc = render.make_scene(cfg, system, antialias=antialias, color_range=color_range)
        self.sc.atom_actor.VisibilityOff()
        self.sc.bond_actor.VisibilityOff()
        self.window = self.sc.window
        self.cfg, self.lo, self.hi = cfg, *color_range
        self.sites, self.held = self.sc.sites, system.fixed.copy()
        self.i, self.j = system.i, system.j
        self.radii = self.sc.radii          # held atoms smaller
        self.rc = ls.CYLINDER_RADIUS * self.sc.lattice.d
        self.ups = perpendicular_ups(system.pos[self.j] - system.pos[self.i])

    def atom_rgb(self, system) -> np.ndarray:
        rgb = np.empty((len(system.pos), 3), np.uint8)
        v = ls.scalar(self.cfg.render.color_by, system, self.sites)
        idx = np.clip((v - self.lo) * ((ls.LUT_SIZE - 1) / (self.hi - self.lo)) + 0.5, 0,
                      ls.LUT_SIZE - 1).astype(np.intp)
        rgb[:] = self.sc.lut[idx]
        rgb[self.held] = np.round(np.asarray(self.sc.held_color) * 255)
        return rgb

    def bond_frames(self, system):
        start, end = system.pos[self.i], system.pos[self.j]
        axes = end - start
        return (start + end) / 2, np.linalg.norm(axes, axis=1), frames_from_up(axes, self.ups)

    def frame(self):
        return self.sc.frame()

    def close(self):
        self.sc.close()


class MergedMesh(Baseline):
    def __init__(self, cfg, system, antialias, color_range):
        super().__init__(cfg, system, antialias, color_range)
        import pyvista as pv

        from springscene.view import window

        n, s = len(system.pos), len(self.i)
        sphere = pv.Sphere(radius=1.0, theta_resolution=SPHERE_RES, phi_resolution=SPHERE_RES)
        self.unit = np.asarray(sphere.points, float)
        sph_faces = sphere.faces.reshape(-1, 4)[:, 1:]
        p = len(self.unit)
        faces = (sph_faces[None] + (np.arange(n) * p)[:, None, None]).reshape(-1, 3)
        self.atoms = pv.PolyData(np.zeros((n * p, 3), np.float32),
                                 np.hstack([np.full((len(faces), 1), 3), faces]).ravel())
        self.atoms.point_data["Normals"] = np.tile(self.unit, (n, 1)).astype(np.float32)
        self.atoms.GetPointData().SetActiveNormals("Normals")
        self.atoms.point_data["rgb"] = np.zeros((n * p, 3), np.uint8)
        self.atoms.GetPointData().SetActiveScalars("rgb")
        self.p = p
        a = window.mesh_actor(self.atoms)
        a.GetMapper().ScalarVisibilityOn()
        a.GetMapper().SetColorModeToDirectScalars()
        self.window.add_actor(a)
        scene._material(a, cfg.atom.color)
        # unit tube along x from -1/2 to 1/2, radius 1
        phi = 2 * np.pi * np.arange(CYLINDER_SIDES) / CYLINDER_SIDES
        ring = np.column_stack([np.zeros_like(phi), np.cos(phi), np.sin(phi)])
        self.tube_pts = np.concatenate([ring + [-0.5, 0, 0], ring + [0.5, 0, 0]])
        self.tube_nrm = np.concatenate([ring, ring])
        q = np.arange(CYLINDER_SIDES)
        quads = np.column_stack([q, (q + 1) % CYLINDER_SIDES,
                                 CYLINDER_SIDES + (q + 1) % CYLINDER_SIDES, CYLINDER_SIDES + q])
        m = len(self.tube_pts)
        quads = (quads[None] + (np.arange(s) * m)[:, None, None]).reshape(-1, 4)
        self.bonds = pv.PolyData(np.zeros((s * m, 3), np.float32),
                                 np.hstack([np.full((len(quads), 1), 4), quads]).ravel())
        self.bonds.point_data["Normals"] = np.zeros((s * m, 3), np.float32)
        self.bonds.GetPointData().SetActiveNormals("Normals")
        b = window.mesh_actor(self.bonds)
        self.window.add_actor(b)
        scene._material(b, cfg.bond.color)
        self.update(system)

    def update(self, system):
        pts = self.atoms.points
        pts[:] = (system.pos[:, None, :]
                  + self.radii[:, None, None] * self.unit[None]).reshape(-1, 3)
        self.atoms.point_data["rgb"][:] = np.repeat(self.atom_rgb(system), self.p, axis=0)
        mid, length, F = self.bond_frames(system)
        local = self.tube_pts[None] * np.stack([length, np.full_like(length, self.rc),
                                                np.full_like(length, self.rc)], -1)[:, None]
        FT = np.swapaxes(F, 1, 2)
        self.bonds.points[:] = (np.matmul(local, FT) + mid[:, None]).reshape(-1, 3)
        self.bonds.point_data["Normals"][:] = np.matmul(
            np.broadcast_to(self.tube_nrm, (len(mid),) + self.tube_nrm.shape), FT).reshape(-1, 3)
        for mesh in (self.atoms, self.bonds):
            mesh.GetPoints().Modified()
            mesh.GetPointData().Modified()


class PerObject(Baseline):
    def __init__(self, cfg, system, antialias, color_range):
        super().__init__(cfg, system, antialias, color_range)
        import pyvista as pv
        from vtkmodules.vtkCommonMath import vtkMatrix4x4
        from vtkmodules.vtkRenderingCore import vtkActor, vtkPolyDataMapper

        mappers = {}
        for r in np.unique(self.radii):
            mappers[r] = vtkPolyDataMapper()
            mappers[r].SetInputData(pv.Sphere(radius=r, theta_resolution=SPHERE_RES,
                                              phi_resolution=SPHERE_RES))
            mappers[r].ScalarVisibilityOff()
        cyl = pv.Cylinder(center=(0, 0, 0), direction=(1, 0, 0), radius=1.0, height=1.0,
                          resolution=CYLINDER_SIDES, capping=False).compute_normals()
        cm = vtkPolyDataMapper()
        cm.SetInputData(cyl)
        cm.ScalarVisibilityOff()
        self.atom_actors, self.bond_actors, self.mats = [], [], []
        ren = self.window.renderer
        for r in self.radii:
            a = vtkActor()
            a.SetMapper(mappers[r])
            scene._material(a, self.cfg.atom.color)
            ren.AddActor(a)
            self.atom_actors.append(a)
        for _ in range(len(self.i)):
            a = vtkActor()
            a.SetMapper(cm)
            scene._material(a, self.cfg.bond.color)
            m = vtkMatrix4x4()
            a.SetUserMatrix(m)
            ren.AddActor(a)
            self.bond_actors.append(a)
            self.mats.append(m)
        self.update(system)

    def update(self, system):
        rgb = self.atom_rgb(system) / 255.0
        for a, p, c in zip(self.atom_actors, system.pos.tolist(), rgb.tolist()):
            a.SetPosition(p)
            a.GetProperty().SetColor(c)
        mid, length, F = self.bond_frames(system)
        M = np.zeros((len(mid), 4, 4))
        M[:, :3, :3] = F * np.stack([length, np.full_like(length, self.rc),
                                     np.full_like(length, self.rc)], -1)[:, None, :]
        M[:, :3, 3] = mid
        M[:, 3, 3] = 1.0
        for m, a, row in zip(self.mats, self.bond_actors, M.reshape(len(mid), 16).tolist()):
            m.DeepCopy(row)
            a.Modified()


def run(kind: str, cfg, color_range) -> float:
    """Frames per second of ``kind``: physics step + update + render + read back."""
    antialias = not kind.endswith("draft")
    s = build.system(cfg)
    n = FRAMES[kind]
    spf = steps_per_frame(cfg)
    if kind.startswith("imposters"):
        sc = render.make_scene(cfg, s, antialias=antialias, color_range=color_range)
    elif kind.startswith("merged"):
        sc = MergedMesh(cfg, s, antialias, color_range)
    else:
        sc = PerObject(cfg, s, antialias, color_range)
    try:
        sc.frame()                       # first render: shaders compiled, buffers made
        start = time.perf_counter()
        for _ in range(n):
            physics.step(s, spf)
            sc.update(s)
            sc.frame()
        return n / (time.perf_counter() - start)
    finally:
        sc.close()


def main() -> None:
    t0 = time.perf_counter()
    backend.select("auto")
    cfg = config.load(ROOT / "configs" / "crystal.toml")
    cr = render.lattice_color_range(cfg)
    fps: dict[str, list[float]] = {k: [] for k in FRAMES}
    for _ in range(ROUNDS):
        for kind in FRAMES:
            fps[kind].append(run(kind, cfg, cr))
    best = {k: max(v) for k, v in fps.items()}
    s = build.system(cfg)
    print(f"matter render benchmark: configs/crystal.toml, {len(s.pos)} atoms, {len(s.i)} bonds "
          f"({ls.bond_style(cfg.bond.style, len(s.i))}), coloured by {cfg.render.color_by}, "
          f"{cfg.scene.width}x{cfg.scene.height}; step + update + render + read back; "
          f"best of {ROUNDS} interleaved rounds")
    print(f"{'case':<20} {'frames/s':>9} {'frames':>7}  (rounds)")
    for kind, v in best.items():
        rounds = ", ".join(f"{x:.1f}" for x in fps[kind])
        print(f"{kind:<20} {v:9.1f} {FRAMES[kind]:7d}  ({rounds})")
    print(f"imposters: {best['imposters'] / best['merged mesh']:.1f}x the merged mesh and "
          f"{best['imposters'] / best['per object']:.1f}x one actor per object anti-aliased; "
          f"draft {best['imposters draft'] / best['merged mesh draft']:.1f}x the merged mesh "
          f"(took {time.perf_counter() - t0:.0f} s)")


if __name__ == "__main__":
    main()
