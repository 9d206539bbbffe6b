"""The jobs a user runs: simulate to CSV, a still at a time, a video in real time.

Each is a plain function a notebook can call; the command-line app only parses
arguments and maps errors to exit codes.
"""

from __future__ import annotations

import csv
import time
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import config, physics
from .config import Config
from .errors import UserError
from .outputs import (VIDEO_FORMATS, VideoWriter, atomic_path, check_output, check_video_fps,
                      write_png)

CSV_HEADER = ("t", "x", "y", "z", "px", "py", "pz", "K", "Us", "Ug", "E", "E_thermal")
# a lattice: the whole crystal per step (total momentum, energies)
LATTICE_CSV_HEADER = ("t", "px", "py", "pz", "K", "Us", "E", "E_thermal")


MAX_STEPS = 10_000_000    # about 3 minutes of stepping; past it a typo, not a plan
MAX_FRAMES = 360_000      # two hours at 50 fps


def step_at(time_s: float, dt: float, flag: str = "--time") -> int:
    """Index of the step nearest ``time_s`` (>= 0, within :data:`MAX_STEPS`)."""
    time_s = config.check_flag(flag, config.non_negative, time_s)
    if time_s / dt > MAX_STEPS:
        raise UserError(f"{flag} {time_s:g} is {time_s / dt:.3g} steps of dt = {dt:g} s; "
                        f"the limit is {MAX_STEPS:,}")
    return int(round(time_s / dt))


def frame_steps(duration: float, fps: int, dt: float, speed: float = 1.0) -> np.ndarray:
    """Step index of each video frame: frame f shows the step nearest t = f speed / fps.

    ``speed`` is simulated seconds per video second (1: real time), so the video
    lasts ``duration / speed`` seconds.
    """
    step_at(duration, dt, "--duration")
    frames = duration / speed * fps
    if frames > MAX_FRAMES:
        raise UserError(f"--duration {duration:g} at --fps {fps} and speed {speed:g} is "
                        f"{frames:.3g} frames; the limit is {MAX_FRAMES:,}")
    n = int(round(frames))
    return np.rint(np.arange(n) * (speed / (fps * dt))).astype(np.int64)


# ---- simulate ---------------------------------------------------------------------------

def simulate(cfg: Config, duration: float | None = None):
    """The ball's trajectory from t = 0 to ``duration`` (default: the config's), one row per step.

    For a lattice config, the crystal's totals per step instead (:func:`lattice_totals`).
    """
    cfg = config.override(cfg, "render", duration=duration)
    n = step_at(cfg.render.duration, cfg.physics.dt, "--duration")
    if cfg.is_lattice:
        return lattice_totals(cfg.system(), n)
    return physics.run(cfg.system(), n)


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
               backend: str = "auto"):
    """The off-screen scene for a config: the page's holder, spring and ball, or a lattice."""
    if cfg.is_lattice:
        from .lattice_scene import LatticeScene

        return LatticeScene(cfg, system, antialias=antialias, backend_name=backend)
    from .scene import Scene

    return Scene(cfg, system, antialias=antialias, backend_name=backend)


# ---- still and video --------------------------------------------------------------------

def still(cfg: Config, time_s: float, out: str | Path | None = None, *,
          backend: str = "auto", antialias: bool = True) -> np.ndarray:
    """The scene at the step nearest ``time_s`` as an (h, w, 3) image; written as PNG to ``out``."""
    path = check_output(out, (".png",)) if out is not None else None
    n = step_at(time_s, cfg.physics.dt)
    system = physics.step(cfg.system(), n)
    with make_scene(cfg, system, antialias=antialias, backend=backend) as scene:
        image = scene.frame()
    if path is not None:
        write_png(path, image)
    return image


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
    from tqdm import tqdm

    from .overlay import Overlays

    system = cfg.system()
    start = time.perf_counter()
    # graph and energy panels pre-run the same (deterministic) system to fix their axes
    panels = Overlays(cfg, overlays)
    with make_scene(cfg, system, antialias=antialias, backend=backend) as scene, \
            atomic_path(path) as tmp:
        with VideoWriter(tmp, fps, panels.size) as writer:
            loop_start = time.perf_counter()
            for target in tqdm(steps, desc=path.name, unit="frame", disable=not progress,
                               leave=False):
                physics.step(system, int(target) - system.steps)
                scene.update(system)
                panels.update_scene(scene, system)
                writer.write(panels.compose(scene.frame(), system))
        end = time.perf_counter()
    return RenderStats(path, len(steps), fps, time.perf_counter() - start, end - loop_start)
