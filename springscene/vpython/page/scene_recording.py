"""A config's scene recorded as the VPython program the wiki page shows, for its page.

``springscene render configs/wiki.toml --out wiki.html`` gives the page's own scene as an
interactive VPython page: the config's system is run by springscene's physics (the
integrator, damping and drive the config asks for), and at each video frame its holder,
spring and ball are VPython's ``box``, ``helix`` and ``sphere`` (one of each per fixed
node, spring and free node), moved as the page's loop moves them
(``spring.axis = ball.pos - holder.pos``), with VPython's camera and autoscale, and
recorded (:mod:`..record.recorder`) frame by frame. A lattice config's atoms are spheres
and its bonds helices, cylinders or thin curves, as its video draws them.
"""

from __future__ import annotations

import html
import os
import tempfile
from pathlib import Path

import numpy as np

from ... import build, config
from ... import render as pipeline
from ...errors import UserError
from ...outputs import hidden_name
from ...model.timeline import frame_steps, play
from ...settings import Config
from ...view import camera, lattice_scene
from .. import api as vp
from ..draw import autoscale
from ..record.recorder import Recorder
from .interactive import write_interactive_page

__all__ = ["record_scene", "write_scene_page"]


def _vec(values) -> vp.vector:
    return vp.vector(*(float(v) for v in values))


def _canvas(cfg: Config):
    """VPython's scene set up as the config's canvas and camera."""
    scene = vp.scene
    scene.width, scene.height = cfg.scene.width, cfg.scene.height
    scene.background = _vec(cfg.scene.background)
    scene.title = html.escape(cfg.scene.title)
    cam = cfg.camera
    scene.center, scene.forward, scene.up = _vec(cam.center), _vec(cam.forward), _vec(cam.up)
    scene.fov = cam.fov
    if cam.range is not None:
        scene.range = cam.range
    return scene


def _objects(cfg: Config, system) -> tuple[dict, dict, list]:
    """A box on each fixed node, a sphere on each free one, a helix on each spring."""
    holders = {int(n): vp.box(pos=_vec(system.pos[n]), size=_vec(cfg.holder.size),
                              color=_vec(cfg.holder.color))
               for n in np.flatnonzero(system.fixed)}
    balls = {int(n): vp.sphere(pos=_vec(system.pos[n]), radius=cfg.ball.radius,
                               color=_vec(cfg.ball.color))
             for n in system.free}
    sc = cfg.spring
    springs = [(int(i), int(j), vp.helix(pos=_vec(system.pos[i]),
                                         axis=_vec(system.pos[j] - system.pos[i]),
                                         radius=sc.radius, thickness=sc.thickness,
                                         coils=sc.coils, color=_vec(sc.color)))
               for i, j in zip(system.i, system.j)]
    return holders, balls, springs


def _lattice_objects(cfg: Config, system) -> tuple[list, list, str]:
    """The atoms as spheres (the held ones gray and smaller) and the bonds in the style
    ``[bond] style`` resolves to (helix, cylinder, or a thin curve), sized as springscene's
    lattice renderer sizes them."""
    d = build.lattice(cfg).d
    atom, b = cfg.atom, cfg.bond
    r = atom.radius if atom.radius is not None else lattice_scene.ATOM_RADIUS * d
    held = lattice_scene.held_color(atom.color)
    atoms = [vp.sphere(pos=_vec(p), radius=r * (lattice_scene.HELD_RADIUS if fixed else 1),
                       color=_vec(held if fixed else atom.color))
             for p, fixed in zip(system.pos, system.fixed)]
    style = lattice_scene.bond_style(b.style, len(system.i))
    bonds = []
    for i, j in zip(system.i, system.j):
        start, axis = _vec(system.pos[i]), _vec(system.pos[j] - system.pos[i])
        if style == "helix":
            bonds.append(vp.helix(
                pos=start, axis=axis, coils=b.coils, color=_vec(b.color),
                radius=b.radius if b.radius is not None else lattice_scene.HELIX_RADIUS * d,
                thickness=(b.thickness if b.thickness is not None
                           else lattice_scene.HELIX_THICKNESS * d)))
        elif style == "cylinder":
            bonds.append(vp.cylinder(
                pos=start, axis=axis, color=_vec(b.color),
                radius=b.radius if b.radius is not None else lattice_scene.CYLINDER_RADIUS * d))
        else:
            bonds.append(vp.curve(pos=[start, start + axis], color=_vec(b.color)))
    return atoms, bonds, style


class _Lattice:
    """A lattice config's atoms and bonds, moved (and coloured by ``[render] color_by``)
    frame by frame."""

    def __init__(self, cfg: Config, system) -> None:
        self.atoms, self.bonds, self.style = _lattice_objects(cfg, system)
        self.i, self.j = system.i.copy(), system.j.copy()
        self.cfg = cfg
        self.autoscaler = camera.Autoscaler() if cfg.camera.range is None else None
        self.radii = np.array([a.radius for a in self.atoms])
        first = self.bonds[0] if self.bonds else None
        self.extent = (0.0 if first is None or self.style == "line" else
                       first.radius + (first.thickness / 2 if self.style == "helix" else 0.0))
        self.kind = cfg.render.color_by
        if self.kind != "none":
            self.low, self.high = pipeline.lattice_color_range(cfg, system)
            self.lut = lattice_scene.colormap_table() / 255.0
            self.sites = build.lattice(cfg).sites()
            self.free = np.flatnonzero(~system.fixed)

    def update(self, state) -> None:
        for atom, p in zip(self.atoms, state.pos):
            atom.pos = _vec(p)
        for bond, i, j in zip(self.bonds, self.i, self.j):
            start, axis = _vec(state.pos[i]), _vec(state.pos[j] - state.pos[i])
            if self.style == "line":
                bond.modify(0, pos=start)
                bond.modify(1, pos=start + axis)
            else:
                bond.pos, bond.axis = start, axis
        if self.kind != "none":
            v = lattice_scene.scalar(self.kind, state, self.sites)[self.free]
            n = len(self.lut) - 1
            idx = np.clip((v - self.low) * (n / (self.high - self.low)) + 0.5, 0, n)
            for atom, k in zip((self.atoms[a] for a in self.free), idx.astype(np.intp)):
                atom.color = _vec(self.lut[k])

    def names(self) -> dict:
        return {"atoms": self.atoms, "bonds": self.bonds}

    def place_camera(self, scene, state) -> None:
        """The range the lattice's video has: VPython's autoscale measured in the camera's
        own axes (:meth:`springscene.view.lattice_scene.LatticeScene.autoscale_bounds`),
        which keeps an oblique crystal's near corner in the picture."""
        if self.autoscaler is None:
            return
        c, canvas = self.cfg.camera, self.cfg.scene
        fwd = np.asarray(c.forward, float) / np.linalg.norm(c.forward)
        right = np.cross(fwd, c.up)
        right /= np.linalg.norm(right)
        rot = np.stack([right, np.cross(right, fwd), -fwd])
        pos = (state.pos - np.asarray(c.center, float)) @ rot.T
        r = self.radii[:, None]
        start, end = pos[self.i], pos[self.j]
        e = self.extent
        bounds = np.concatenate([np.stack([pos - r, pos + r], axis=1),
                                 np.stack([np.minimum(start, end) - e,
                                           np.maximum(start, end) + e], axis=1)])
        scene.range = self.autoscaler.update(bounds, np.zeros(3), c.fov, canvas.width,
                                             canvas.height)


class _Oscillator:
    """The page's holder, spring and ball (one of each per fixed node, spring and free
    node), moved as the page's loop moves them."""

    def __init__(self, cfg: Config, system) -> None:
        self.holders, self.balls, self.springs = _objects(cfg, system)
        self.rest = {n: system.pos[n].copy() for n in self.holders}

    def update(self, state) -> None:
        for n, box in self.holders.items():
            if not np.array_equal(state.pos[n], self.rest[n]):       # a driven support
                box.pos = _vec(state.pos[n])
        for n, ball in self.balls.items():
            ball.pos = _vec(state.pos[n])
        for i, j, spring in self.springs:
            spring.pos = _vec(state.pos[i])
            spring.axis = _vec(state.pos[j] - state.pos[i])

    def names(self) -> dict:
        found = {"holder": next(iter(self.holders.values()), None),
                 "ball": next(iter(self.balls.values()), None),
                 "spring": self.springs[0][2] if self.springs else None}
        return {k: v for k, v in found.items() if v is not None}


def record_scene(cfg: Config, out: Path, *, duration: float | None = None,
                 fps: int | None = None, speed: float | None = None,
                 version: str = "") -> int:
    """Record ``cfg``'s scene into ``out`` (a ``.jsonl`` file); the number of frames.

    Program time is simulated time: a frame every ``speed / fps`` s, as the video's, and
    the page plays ``speed`` simulated seconds a second (a chain of atoms: picoseconds).
    """
    cfg = config.override(cfg, "render", duration=duration, fps=fps, speed=speed)
    r = cfg.render
    steps = frame_steps(r.duration, r.fps, cfg.physics.dt, r.speed)
    if len(steps) == 0:
        raise UserError(f"--duration {r.duration:g} at --fps {r.fps} gives no frame")
    system = build.system(cfg)
    vp.reset()
    scene = _canvas(cfg)
    objects = _Lattice(cfg, system) if cfg.is_lattice else _Oscillator(cfg, system)
    recorder = Recorder(out, r.fps / r.speed, program=cfg.scene.title,
                        dialect="springscene config", version=version, time_scale=r.speed)
    try:
        for state in play(system, steps):
            objects.update(state)
            if cfg.is_lattice:
                objects.place_camera(scene, state)
            else:
                autoscale.update(scene)
            recorder.take()
        held, _ = recorder.names(objects.names())
        physics = ({"k": cfg.spring.k, "L0": cfg.spring.L0, "m": cfg.ball.m,
                    "g": [float(v) for v in cfg.physics.g]} if not cfg.is_lattice
                   else {"k": cfg.bond.k})
        recorder.close({"t": float(steps[-1] * cfg.physics.dt), "frames": recorder.frames,
                        "ended": "duration", "error": None, "names": held,
                        "globals": {**physics, "dt": cfg.physics.dt}})
    finally:
        recorder.discard()
    return recorder.frames


def write_scene_page(cfg: Config, out: Path, *, duration: float | None = None,
                     fps: int | None = None, speed: float | None = None,
                     version: str = "") -> int:
    """The interactive page of ``cfg``'s scene at ``out``; the number of frames. The
    recording is made in a hidden file beside ``out`` and removed."""
    out = Path(out)
    fd, name = tempfile.mkstemp(prefix=f"{hidden_name(out)}.", suffix=".jsonl",
                                dir=out.parent or ".")
    os.close(fd)
    recording = Path(name)
    try:
        frames = record_scene(cfg, recording, duration=duration, fps=fps, speed=speed,
                              version=version)
        write_interactive_page(recording, out)
    finally:
        recording.unlink(missing_ok=True)
    return frames
