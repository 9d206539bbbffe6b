"""A config's scene recorded as the VPython program the wiki page shows, for its page.

``springscene render configs/wiki.toml --out wiki.html`` gives the page's own scene as an
interactive VPython page: the config's system is run by springscene's physics (the
integrator, damping and drive the config asks for), and at each video frame its holder,
spring and ball are VPython's ``box``, ``helix`` and ``sphere`` (one of each per fixed
node, spring and free node), moved as the page's loop moves them
(``spring.axis = ball.pos - holder.pos``), with VPython's camera and autoscale, and
recorded (:mod:`..record.recorder`) frame by frame.
"""

from __future__ import annotations

import html
import os
import tempfile
from pathlib import Path

import numpy as np

from ... import build, config
from ...errors import UserError
from ...model.timeline import frame_steps, play
from ...settings import Config
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


def record_scene(cfg: Config, out: Path, *, duration: float | None = None,
                 fps: int | None = None, speed: float | None = None,
                 version: str = "") -> int:
    """Record ``cfg``'s scene into ``out`` (a ``.jsonl`` file); the number of frames.

    Program time is simulated time: a frame every ``speed / fps`` s, as the video's.
    """
    if cfg.is_lattice:
        raise UserError("--out .html: the interactive page is made for a ball-and-spring "
                        "config (a lattice config's scene has no VPython program yet; "
                        "render it to a video)")
    cfg = config.override(cfg, "render", duration=duration, fps=fps, speed=speed)
    r = cfg.render
    steps = frame_steps(r.duration, r.fps, cfg.physics.dt, r.speed)
    if len(steps) == 0:
        raise UserError(f"--duration {r.duration:g} at --fps {r.fps} gives no frame")
    system = build.system(cfg)
    vp.reset()
    scene = _canvas(cfg)
    holders, balls, springs = _objects(cfg, system)
    sc = cfg.spring
    rest = {n: system.pos[n].copy() for n in holders}
    recorder = Recorder(out, r.fps / r.speed, program=cfg.scene.title,
                        dialect="springscene config", version=version)
    try:
        for state in play(system, steps):
            for n, box in holders.items():
                if not np.array_equal(state.pos[n], rest[n]):       # a driven support
                    box.pos = _vec(state.pos[n])
            for n, ball in balls.items():
                ball.pos = _vec(state.pos[n])
            for i, j, spring in springs:
                spring.pos = _vec(state.pos[i])
                spring.axis = _vec(state.pos[j] - state.pos[i])
            autoscale.update(scene)
            recorder.take()
        names = {"holder": next(iter(holders.values()), None),
                 "ball": next(iter(balls.values()), None),
                 "spring": springs[0][2] if springs else None}
        held, _ = recorder.names({k: v for k, v in names.items() if v is not None})
        recorder.close({"t": float(steps[-1] * cfg.physics.dt), "frames": recorder.frames,
                        "ended": "duration", "error": None, "names": held,
                        "globals": {"k": sc.k, "L0": sc.L0, "m": cfg.ball.m,
                                    "g": [float(v) for v in cfg.physics.g],
                                    "dt": cfg.physics.dt}})
    finally:
        recorder.discard()
    return recorder.frames


def write_scene_page(cfg: Config, out: Path, *, duration: float | None = None,
                     fps: int | None = None, speed: float | None = None,
                     version: str = "") -> int:
    """The interactive page of ``cfg``'s scene at ``out``; the number of frames. The
    recording is made in a hidden file beside ``out`` and removed."""
    out = Path(out)
    stem = out.name
    while len(os.fsencode(stem)) > 200:          # room for the rest of the name
        stem = stem[:-1]
    fd, name = tempfile.mkstemp(prefix=f".{stem}.", suffix=".jsonl", dir=out.parent or ".")
    os.close(fd)
    recording = Path(name)
    try:
        frames = record_scene(cfg, recording, duration=duration, fps=fps, speed=speed,
                              version=version)
        write_interactive_page(recording, out)
    finally:
        recording.unlink(missing_ok=True)
    return frames
