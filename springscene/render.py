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


MAX_STEPS = 10_000_000    # about 3 minutes of stepping; past it a typo, not a plan
MAX_FRAMES = 360_000      # two hours at 50 fps


def step_at(time_s: float, dt: float, flag: str = "--time") -> int:
    """Index of the step nearest ``time_s`` (>= 0, within :data:`MAX_STEPS`)."""
    time_s = config.check_flag(flag, config.non_negative, time_s)
    if time_s / dt > MAX_STEPS:
        raise UserError(f"{flag} {time_s:g} is {time_s / dt:.3g} steps of dt = {dt:g} s; "
                        f"the limit is {MAX_STEPS:,}")
    return int(round(time_s / dt))


def frame_steps(duration: float, fps: int, dt: float) -> np.ndarray:
    """Step index of each video frame: frame f shows the step nearest t = f/fps (real time)."""
    step_at(duration, dt, "--duration")
    if duration * fps > MAX_FRAMES:
        raise UserError(f"--duration {duration:g} at --fps {fps} is {duration * fps:.3g} frames; "
                        f"the limit is {MAX_FRAMES:,}")
    n = int(round(duration * fps))
    return np.rint(np.arange(n) / (fps * dt)).astype(np.int64)


# ---- simulate ---------------------------------------------------------------------------

def simulate(cfg: Config, duration: float | None = None) -> physics.Trajectory:
    """The ball's trajectory from t = 0 to ``duration`` (default: the config's), one row per step."""
    cfg = config.override(cfg, "render", duration=duration)
    return physics.run(cfg.system(), step_at(cfg.render.duration, cfg.physics.dt, "--duration"))


def write_csv(traj: physics.Trajectory, out: str | Path) -> Path:
    """Write ``t,x,y,z,px,py,pz,K,Us,Ug,E,E_thermal`` rows, full float precision.

    E = K + Us + Ug; E_thermal is the energy drag and permanent set have taken.
    """
    out = check_output(out, (".csv",))
    table = np.column_stack([traj.t, traj.pos, traj.p, traj.K, traj.Us, traj.Ug, traj.E,
                             traj.E_thermal])
    with atomic_path(out) as tmp, open(tmp, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(CSV_HEADER)
        w.writerows(table.tolist())
    return out


# ---- still and video --------------------------------------------------------------------

def still(cfg: Config, time_s: float, out: str | Path | None = None, *,
          backend: str = "auto", antialias: bool = True) -> np.ndarray:
    """The scene at the step nearest ``time_s`` as an (h, w, 3) image; written as PNG to ``out``."""
    path = check_output(out, (".png",)) if out is not None else None
    n = step_at(time_s, cfg.physics.dt)
    system = physics.step(cfg.system(), n)
    from .scene import Scene

    with Scene(cfg, system, antialias=antialias, backend_name=backend) as scene:
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
                 fps: int | None = None, backend: str = "auto", antialias: bool = True,
                 overlays: tuple[str, ...] = (), progress: bool = False) -> RenderStats:
    """Render the oscillation in real time (one video second per simulated second) to MP4 or GIF.

    ``overlays`` (names from :data:`springscene.overlay.OVERLAYS`) add a clock in the
    scene, a y(t) graph below it and energy bars beside it; the scene keeps its size
    and the video grows around it (:class:`springscene.overlay.Overlays`).
    """
    path = check_output(out, VIDEO_FORMATS)
    cfg = config.override(cfg, "render", duration=duration, fps=fps)
    duration, fps = cfg.render.duration, cfg.render.fps
    steps = frame_steps(duration, fps, cfg.physics.dt)
    if len(steps) == 0:
        raise UserError(f"--duration {duration:g} at --fps {fps} gives no frame")
    check_video_fps(path, fps)
    from tqdm import tqdm

    from .overlay import Overlays
    from .scene import Scene

    system = cfg.system()
    start = time.perf_counter()
    # graph and energy panels pre-run the same (deterministic) system to fix their axes
    panels = Overlays(cfg, overlays)
    with Scene(cfg, system, antialias=antialias, backend_name=backend) as scene, \
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
