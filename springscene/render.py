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
import warnings
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from . import build, config, progress
from .progress import tqdm_class
from .errors import UserError
from .model import physics
from .model.timeline import frame_steps, play, step_at
from .science import theory
from .outputs import (VIDEO_FORMATS, VideoWriter, atomic_path, check_output, check_video_fps,
                      write_png)
from .video import DEFAULT_QUALITY, check_quality
from .settings import Config
from .view.lattice_scene import COLOR_QUANTILE, LatticeScene, color_scale
from .view.overlay import Overlays
from .view.scene import Scene

# each column "name [unit]", SI (the sweep's CSV and the lattice's totals alike)
CSV_HEADER = ("t [s]", "x [m]", "y [m]", "z [m]", "px [kg m/s]", "py [kg m/s]", "pz [kg m/s]",
              "K [J]", "Us [J]", "Ug [J]", "E [J]", "E_thermal [J]")
# a lattice: the whole crystal per step (total momentum, energies)
LATTICE_CSV_HEADER = ("t [s]", "px [kg m/s]", "py [kg m/s]", "pz [kg m/s]", "K [J]", "Us [J]",
                      "E [J]", "E_thermal [J]")


# ---- simulate ---------------------------------------------------------------------------

def simulate(cfg: Config, duration: float | None = None):
    """The ball's trajectory from t = 0 to ``duration`` (default: the config's), one row per step.

    For a lattice config, the crystal's totals per step instead (:func:`lattice_totals`).
    """
    cfg = config.override(cfg, "render", duration=duration)
    n = step_at(cfg.render.duration, cfg.physics.dt, "--duration")
    if cfg.is_lattice:
        return lattice_totals(build.system(cfg), n)
    with progress.steps(n, "simulating") as advance:
        return physics.run(build.system(cfg), n, progress=advance)


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
    """Write ``t [s],x [m],y [m],z [m],px [kg m/s],...,K [J],Us [J],Ug [J],E [J],E_thermal [J]``
    rows (:data:`CSV_HEADER`), full float precision.

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

def step_to(system: physics.System, n: int) -> physics.System:
    """``system`` stepped ``n`` times, with progress when that is long (:mod:`.progress`)."""
    with progress.steps(n, "stepping") as advance:
        if advance is None:
            return physics.step(system, n)
        for chunk in np.diff(np.append(np.arange(0, n, 50_000), n)):
            physics.step(system, int(chunk))
            advance(int(chunk))
    return system


def still(cfg: Config, time_s: float, out: str | Path | None = None, *,
          backend: str = "auto", antialias: bool = True) -> np.ndarray:
    """The scene at the step nearest ``time_s`` as an (h, w, 3) image; written as PNG to ``out``."""
    path = check_output(out, (".png",)) if out is not None else None
    n = step_at(time_s, cfg.physics.dt)
    system = step_to(build.system(cfg), n)
    with make_scene(cfg, system, antialias=antialias, backend=backend) as scene:
        image = scene.frame()
    if path is not None:
        write_png(path, image)
    return image


LATTICE_OVERLAYS = ("time",)    # a lattice's video: a clock (1 video second may be 1 ps)


def make_overlays(cfg: Config, overlays: tuple[str, ...] | None = ()) -> Overlays:
    """The overlays of a render of ``cfg`` (None: the default, :data:`LATTICE_OVERLAYS`
    for a lattice, none for the ball); the graph and the energy bars are handed a pre-run
    of the same (deterministic) system to the video's end, which fixes their axes, and the
    bars the potential energy at rest at equilibrium (their zero of U)."""
    if overlays is None:
        overlays = LATTICE_OVERLAYS if cfg.is_lattice else ()
    trajectory = u_rest = None
    if "graph" in overlays or "energy" in overlays:
        if cfg.is_lattice:
            raise UserError("--overlay: graph and energy follow the page's single ball; "
                            "a [lattice] config takes only time")
        trajectory = physics.run(build.system(cfg), step_at(cfg.render.duration, cfg.physics.dt,
                                                            "--duration"))
        u_rest = theory.rest_potential(cfg, float(trajectory.L0[-1]))
    return Overlays(cfg.scene, overlays, trajectory, duration=cfg.render.duration,
                    speed=cfg.render.speed, u_rest=u_rest)


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


def repeated_frames(steps: np.ndarray, fps: int, dt: float, speed: float) -> str | None:
    """What to say when frames repeat: ``fps`` above the physics' steps per video second."""
    repeats = int(np.count_nonzero(np.diff(steps) == 0))
    if not repeats:
        return None
    rate = speed / dt
    return (f"--fps {fps} is above the physics' {rate:g} steps per video second "
            f"(dt = {dt:g} s at speed {speed:g}): {repeats} of {len(steps)} frames repeat "
            f"the one before; use --fps {max(1, int(rate))} or less, or a smaller --dt")


def render_video(cfg: Config, out: str | Path, *, duration: float | None = None,
                 fps: int | None = None, speed: float | None = None, backend: str = "auto",
                 antialias: bool = True, overlays: tuple[str, ...] | None = None,
                 progress: bool = False, quality: str = DEFAULT_QUALITY,
                 on_warning=None) -> RenderStats:
    """Render the motion to MP4, WebM, Ogg or GIF, ``speed`` simulated seconds per video
    second, at ``quality`` low, medium or high (:data:`springscene.video.ENCODINGS`).

    The default speed is the config's ``[render] speed``: 1 (real time) for the
    page's ball, far less for atoms (10^-12 s of a chain of atoms is a few seconds).

    ``overlays`` (names from :data:`springscene.view.overlay.OVERLAYS`) add a clock in the
    scene, a y(t) graph below it and energy bars beside it; the scene keeps its size
    and the video grows around it (:class:`springscene.view.overlay.Overlays`).

    When ``fps`` asks for more frames than the physics has steps, frames repeat: said
    through ``on_warning(message)``, or else as a Python warning.
    """
    path = check_output(out, VIDEO_FORMATS)
    check_quality(quality)
    cfg = config.override(cfg, "render", duration=duration, fps=fps, speed=speed)
    duration, fps = cfg.render.duration, cfg.render.fps
    steps = frame_steps(duration, fps, cfg.physics.dt, cfg.render.speed)
    if len(steps) == 0:
        raise UserError(f"--duration {duration:g} at --fps {fps} and --speed "
                        f"{cfg.render.speed:g} gives no frame (a video of "
                        f"{duration / cfg.render.speed:.3g} s)")
    check_video_fps(path, fps)
    note = repeated_frames(steps, fps, cfg.physics.dt, cfg.render.speed)
    if note:
        (on_warning or warnings.warn)(note)
    system = build.system(cfg)
    start = time.perf_counter()
    panels = make_overlays(cfg, overlays)
    # the scene closed before the video is put in place: its rename is the last act (a
    # signal during the scene's teardown, after the rename, reported a whole video stopped)
    with atomic_path(path) as tmp, \
            make_scene(cfg, system, antialias=antialias, backend=backend) as scene:
        with VideoWriter(tmp, fps, panels.size, quality) as writer:
            loop_start = time.perf_counter()
            bar = tqdm_class()(steps, desc=path.name, unit="frame", disable=not progress,
                               leave=False)
            for system in play(system, bar):
                scene.update(system)
                panels.update_scene(scene, system)
                writer.write(panels.compose(scene.frame(), system))
        end = time.perf_counter()
    return RenderStats(path, len(steps), fps, time.perf_counter() - start, end - loop_start)
