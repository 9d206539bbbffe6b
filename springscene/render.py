"""The render pipeline: a config run through its physics and drawn, to CSV, PNG or video.

The path of a video: :func:`render_video` checks the output and the timing
(:func:`springscene.model.timeline.frame_steps`), builds the system
(:func:`springscene.build.system`), plays it frame by frame
(:func:`springscene.model.timeline.play`), hands each state to the scene
(:meth:`springscene.view.scene.Scene.update`, :meth:`~springscene.view.scene.SceneBase.frame`)
and the overlays, and writes the frames (:class:`springscene.outputs.VideoWriter`).
The scene only draws what it is handed; nothing here draws.
"""

from __future__ import annotations

import csv
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from tqdm import tqdm

from . import build, config
from .errors import UserError
from .model import physics
from .model.timeline import frame_steps, play, step_at
from .outputs import (VIDEO_FORMATS, VideoWriter, atomic_path, check_output, check_video_fps,
                      write_png)
from .settings import Config
from .view.lattice_scene import COLOR_QUANTILE, LatticeScene, color_scale
from .view.overlay import Overlays
from .view.scene import Scene

CSV_HEADER = ("t", "x", "y", "z", "px", "py", "pz", "K", "Us", "Ug", "E", "E_thermal")
# a lattice: the whole crystal per step (total momentum, energies)
LATTICE_CSV_HEADER = ("t", "px", "py", "pz", "K", "Us", "E", "E_thermal")


# ---- simulate ---------------------------------------------------------------------------

def simulate(cfg: Config, duration: float | None = None):
    """The ball's trajectory from t = 0 to ``duration`` (default: the config's), one row per step.

    For a lattice config, the crystal's totals per step instead (:func:`lattice_totals`).
    """
    cfg = config.override(cfg, "render", duration=duration)
    n = step_at(cfg.render.duration, cfg.physics.dt, "--duration")
    if cfg.is_lattice:
        return lattice_totals(build.system(cfg), n)
    return physics.run(build.system(cfg), n)


def lattice_totals(system: physics.System, n_steps: int) -> np.ndarray:
    """Rows of t, total momentum (3), K, Us, E = K + Us + Ug, E_thermal at t = 0 and after each step."""
    rows = np.empty((n_steps + 1, len(LATTICE_CSV_HEADER)))
    for r in range(n_steps + 1):
        if r:
            physics.step(system)
        e = physics.energies(system)
        rows[r] = (system.t, *system.p.sum(axis=0), e.K, e.Us, e.E, e.E_thermal)
    return rows


def write_csv(traj, out: str | Path) -> Path:
    """Write ``t,x,y,z,px,py,pz,K,Us,Ug,E,E_thermal`` rows, full float precision.

    E = K + Us + Ug; E_thermal is the energy drag and permanent set have taken. A
    lattice's totals (an array from :func:`lattice_totals`) are written with
    :data:`LATTICE_CSV_HEADER`.
    """
    out = check_output(out, (".csv",))
    if isinstance(traj, np.ndarray):
        header, table = LATTICE_CSV_HEADER, traj
    else:
        header = CSV_HEADER
        table = np.column_stack([traj.t, traj.pos, traj.p, traj.K, traj.Us, traj.Ug, traj.E,
                                 traj.E_thermal])
    with atomic_path(out) as tmp, open(tmp, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(header)
        w.writerows(table.tolist())
    return out


def make_scene(cfg: Config, system: physics.System, antialias: bool = True,
               backend: str = "auto", color_range: tuple[float, float] | None = None):
    """The off-screen scene for a config: the page's holder, spring and ball, or a lattice.

    The scene is handed the config's sections it draws with, never the whole config. A
    lattice coloured by ``[render] color_by`` gets ``color_range``, or else the video's
    (:func:`lattice_color_range`, ``system`` counted when later than the video's end).
    """
    if not cfg.is_lattice:
        return Scene(system, canvas=cfg.scene, camera=cfg.camera, holder=cfg.holder,
                     spring=cfg.spring, ball=cfg.ball, antialias=antialias, backend_name=backend)
    if cfg.render.color_by != "none" and color_range is None:
        color_range = lattice_color_range(cfg, system)
    return LatticeScene(system, lattice=build.lattice(cfg), canvas=cfg.scene, camera=cfg.camera,
                        atom=cfg.atom, bond=cfg.bond, color_by=cfg.render.color_by,
                        color_range=color_range, antialias=antialias, backend_name=backend)


def lattice_color_range(cfg: Config, system: physics.System | None = None,
                        quantile: float = COLOR_QUANTILE) -> tuple[float, float]:
    """The fixed colour range of a lattice config's ``[render] color_by`` for its whole video.

    A fresh copy of the config's system is played over the video's frames
    (``[render]`` duration, fps, speed) and :func:`springscene.view.lattice_scene.color_scale`
    takes the range from them; a still's ``system`` later than the video's last frame is
    counted too.
    """
    r = cfg.render
    steps = frame_steps(r.duration, r.fps, cfg.physics.dt, r.speed)
    played = build.system(cfg)
    n_values = len(steps) * int((~played.fixed).sum())
    last = int(steps[-1]) if len(steps) else -1
    later = system if system is not None and system.steps > last else None
    return color_scale(r.color_by, play(played, steps), n_values, build.lattice(cfg), later,
                       quantile)


# ---- still and video --------------------------------------------------------------------

def still(cfg: Config, time_s: float, out: str | Path | None = None, *,
          backend: str = "auto", antialias: bool = True) -> np.ndarray:
    """The scene at the step nearest ``time_s`` as an (h, w, 3) image; written as PNG to ``out``."""
    path = check_output(out, (".png",)) if out is not None else None
    n = step_at(time_s, cfg.physics.dt)
    system = physics.step(build.system(cfg), n)
    with make_scene(cfg, system, antialias=antialias, backend=backend) as scene:
        image = scene.frame()
    if path is not None:
        write_png(path, image)
    return image


def make_overlays(cfg: Config, overlays: tuple[str, ...] = ()) -> Overlays:
    """The overlays of a render of ``cfg``; the graph and the energy bars are handed a
    pre-run of the same (deterministic) system to the video's end, which fixes their axes."""
    trajectory = None
    if "graph" in overlays or "energy" in overlays:
        if cfg.is_lattice:
            raise UserError("--overlay: graph and energy follow the page's single ball; "
                            "a [lattice] config takes only time")
        trajectory = physics.run(build.system(cfg), step_at(cfg.render.duration, cfg.physics.dt,
                                                            "--duration"))
    return Overlays(cfg.scene, overlays, trajectory, duration=cfg.render.duration,
                    speed=cfg.render.speed)


@dataclass
class RenderStats:
    path: Path
    frames: int
    fps: int
    seconds: float       # wall time, set-up included
    loop_seconds: float  # the frame loop and the encoder's flush, set-up excluded

    @property
    def frames_per_second(self) -> float:
        return self.frames / self.seconds if self.seconds else float("inf")


def render_video(cfg: Config, out: str | Path, *, duration: float | None = None,
                 fps: int | None = None, speed: float | None = None, backend: str = "auto",
                 antialias: bool = True, overlays: tuple[str, ...] = (),
                 progress: bool = False) -> RenderStats:
    """Render the motion to MP4 or GIF, ``speed`` simulated seconds per video second.

    The default speed is the config's ``[render] speed``: 1 (real time) for the
    page's ball, far less for atoms (10^-12 s of a chain of atoms is a few seconds).

    ``overlays`` (names from :data:`springscene.overlay.OVERLAYS`) add a clock in the
    scene, a y(t) graph below it and energy bars beside it; the scene keeps its size
    and the video grows around it (:class:`springscene.overlay.Overlays`).
    """
    path = check_output(out, VIDEO_FORMATS)
    cfg = config.override(cfg, "render", duration=duration, fps=fps, speed=speed)
    duration, fps = cfg.render.duration, cfg.render.fps
    steps = frame_steps(duration, fps, cfg.physics.dt, cfg.render.speed)
    if len(steps) == 0:
        raise UserError(f"--duration {duration:g} at --fps {fps} gives no frame")
    check_video_fps(path, fps)
    system = build.system(cfg)
    start = time.perf_counter()
    panels = make_overlays(cfg, overlays)
    with make_scene(cfg, system, antialias=antialias, backend=backend) as scene, \
            atomic_path(path) as tmp:
        with VideoWriter(tmp, fps, panels.size) as writer:
            loop_start = time.perf_counter()
            for system in play(system, tqdm(steps, desc=path.name, unit="frame",
                                            disable=not progress, leave=False)):
                scene.update(system)
                panels.update_scene(scene, system)
                writer.write(panels.compose(scene.frame(), system))
        end = time.perf_counter()
    return RenderStats(path, len(steps), fps, time.perf_counter() - start, end - loop_start)
