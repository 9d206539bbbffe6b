"""The wiki page's figure set in one go: :func:`make_figures` runs the config (and its demo
damping, drive and overstretched spring), draws each figure (:mod:`.plots`,
:mod:`.media`), saves it (:mod:`.files`) and writes its caption (:mod:`.gallery`) into
``figures.wiki``.

The steps run in the order of the list in :func:`_make_figures`, one function per file;
the runs that several figures share are made once, between the steps.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import NamedTuple

from .. import render
from ..model import physics
from ..science import sweep, theory
from ..settings import Config
from ..view import backend as backends
from .files import prepare_out_dir, save_figure, write_text
from .gallery import (GALLERY_ORDER, check_prefix, damped_caption, energy_caption,
                      filmstrip_caption, gallery, gif_caption, hooke_caption, integrators_caption, phase_caption,
                      position_caption, resonance_caption, scene_caption)
from .media import filmstrip_figure, filmstrip_frames, make_gif
from .oscillator import (SWEEP_PERIODS, analyze, demo_damped, demo_driven, hooke_config,
                         integrator_runs, run_duration, sweep_omegas)
from .plots import (damped_figure, energy_figure, hooke_figure, integrators_figure,
                    phase_figure, position_figure, resonance_figure)


def make_figures(cfg: Config, out_dir: str | Path, *, backend: str = "auto",
                 antialias: bool = True, prefix: str = "") -> list[Path]:
    """Write every figure, the GIF and ``figures.wiki`` into ``out_dir``; return their paths.

    ``prefix`` goes before every file name (``BallSpring_scene.png``, ...,
    ``BallSpring_figures.wiki``) and the names in the gallery snippet, so that the set
    does not clash with other files on a shared wiki.
    """
    prefix = check_prefix(prefix)
    out = prepare_out_dir(out_dir)
    backends.select(backend)
    before = set(out.iterdir())
    try:
        return _make_figures(_Page(cfg, out, backend, antialias, prefix))
    except BaseException:
        for path in set(out.iterdir()) - before:     # no half set of figures left behind
            if path.is_file():
                path.unlink()
        raise


@dataclass
class _Page:
    """What the steps share: the config, where and how to draw, and what is written so
    far (the files in order, and a caption per file shown in the gallery)."""
    cfg: Config
    out: Path
    backend: str
    antialias: bool
    prefix: str = ""
    written: list[Path] = field(default_factory=list)
    captions: list[tuple[str, str]] = field(default_factory=list)

    def path(self, name: str) -> Path:
        """Where the file ``name`` (``scene.png``) goes: in the folder, with the prefix."""
        return self.out / f"{self.prefix}{name}"

    def save(self, fig, stem: str, caption: str, **kw) -> None:
        """Save a matplotlib figure as ``stem.png`` and ``stem.svg`` (or ``formats=``), and
        caption ``stem.png``."""
        self.written += save_figure(fig, self.out, self.prefix + stem, **kw)
        self.captions.append((f"{stem}.png", caption))


def _make_figures(page: _Page) -> list[Path]:
    cfg = page.cfg
    _scene(page)
    duration = run_duration(cfg)
    traj = render.simulate(cfg, duration)
    result = analyze(cfg, duration)
    _position(page, traj, result)
    _energy(page, traj, result)
    damped = _damped_run(cfg)
    _phase(page, traj, damped)
    _damped(page, damped)
    _resonance(page)
    _integrators(page, duration)
    _hooke(page)
    _filmstrip(page)
    _gif(page)
    _gallery(page)
    return page.written


# ---- the steps, one per file --------------------------------------------------------------

def _scene(page: _Page) -> None:
    """1. the scene"""
    path = page.path("scene.png")
    render.still(page.cfg, 0.0, path, backend=page.backend, antialias=page.antialias)
    page.written.append(path)
    page.captions.append(("scene.png", scene_caption(page.cfg)))


def _position(page: _Page, traj: physics.Trajectory, result: dict) -> None:
    """2. position against the closed form"""
    fig = position_figure(page.cfg, traj, measured_period=result["measured"]["period"])
    page.save(fig, "position", position_caption(page.cfg, traj, result))


def _energy(page: _Page, traj: physics.Trajectory, result: dict) -> None:
    """3. energy"""
    page.save(energy_figure(page.cfg, traj), "energy", energy_caption(page.cfg, traj, result))


class _DampedRun(NamedTuple):
    """The config with damping (its own or the demo's) and its run, for the phase portrait
    and the damped figure."""
    cfg: Config
    demo: bool          # whether the damping is the demo's
    duration: float     # five decay times at least
    traj: physics.Trajectory


def _damped_run(cfg: Config) -> _DampedRun:
    dcfg, demo_b = demo_damped(cfg)
    dosc = theory.Oscillator.from_config(dcfg)
    d_duration = run_duration(dcfg, 5 / dosc.decay_rate)
    return _DampedRun(dcfg, demo_b, d_duration, render.simulate(dcfg, d_duration))


def _phase(page: _Page, traj: physics.Trajectory, damped: _DampedRun) -> None:
    """4. phase portrait (with the damped run's spiral beside an undamped ellipse)"""
    cfg = page.cfg
    dcfg, demo_b, _, dtraj = damped
    spiral = cfg.damping.b == 0 and not cfg.driven
    fig = phase_figure(cfg, traj, damped=(dcfg, dtraj) if spiral else None)
    page.save(fig, "phase", phase_caption(cfg, traj, dcfg if spiral else None, demo_b))


def _damped(page: _Page, damped: _DampedRun) -> None:
    """5. damped envelope"""
    dcfg, demo_b, d_duration, dtraj = damped
    d_result = analyze(dcfg, d_duration)
    rate = d_result["measured"].get("damping_rate")
    fig = damped_figure(dcfg, dtraj, demo=demo_b, measured_rate=rate)
    page.save(fig, "damped", damped_caption(dcfg, demo_b, d_result))


def _resonance(page: _Page) -> None:
    """6. resonance"""
    rcfg, added = demo_driven(page.cfg)
    omegas = sweep_omegas(rcfg)
    res = sweep.sweep(rcfg, omegas, periods=SWEEP_PERIODS)
    demo = ("demo " + " and ".join(added)) if added else ""
    fig = resonance_figure(res, demo=demo)
    page.save(fig, "resonance", resonance_caption(rcfg, added, omegas, res))


def _integrators(page: _Page, duration: float) -> None:
    """7. integrators"""
    runs = integrator_runs(page.cfg, duration)
    fig = integrators_figure(page.cfg, runs)
    page.save(fig, "integrators", integrators_caption(page.cfg, runs, duration))


def _hooke(page: _Page) -> None:
    """8. the limits of Hooke's law"""
    hcfg = hooke_config(page.cfg)
    htraj = render.simulate(hcfg, run_duration(hcfg))
    page.save(hooke_figure(hcfg, htraj), "hooke", hooke_caption(page.cfg, hcfg, htraj))


def _filmstrip(page: _Page) -> None:
    """9. film strip"""
    strip = filmstrip_frames(page.cfg, backend=page.backend, antialias=page.antialias)
    page.save(filmstrip_figure(strip), "filmstrip", filmstrip_caption(page.cfg, strip),
              formats=("png",))


def _gif(page: _Page) -> None:
    """10. GIF"""
    gif = page.path("oscillation.gif")
    stats, attempt = make_gif(page.cfg, gif, backend=page.backend, antialias=page.antialias)
    page.written.append(gif)
    page.captions.append(("oscillation.gif", gif_caption(page.cfg, gif, stats, attempt)))


def _gallery(page: _Page) -> None:
    """11. the gallery snippet"""
    by_name = dict(page.captions)
    vector = sorted(p.name for p in page.written if p.suffix == ".svg")
    entries = [(page.prefix + n, by_name[n]) for n in GALLERY_ORDER]
    page.written.append(write_text(page.path("figures.wiki"), gallery(entries, vector)))
