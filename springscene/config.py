"""Scene configs: TOML files read into checked dataclasses (:mod:`springscene.settings`).

Every key is checked: an unknown section or key, a wrong type, a non-finite
number or a value out of range raises :class:`~springscene.errors.UserError`
with a one-line message naming the file and the key.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import replace
from pathlib import Path
from typing import Any, Callable

import numpy as np

from . import build
from .colors import parse_color
from .errors import UserError
from .model import integrators, physics
from .model.lattice import first_free_layer, fixed_mask
from .settings import (BOND_STYLES, COLOR_BY, FIXED_MODES, AtomCfg, BallCfg, BondCfg,  # noqa: F401
                       CameraCfg, Config, DampingCfg, DriveCfg, HolderCfg, LatticeCfg, PhysicsCfg,
                       PullCfg, RenderCfg, SceneCfg, SpringCfg, StartCfg, Vec)

# ---- checking -------------------------------------------------------------------------

def _number(v: Any) -> float:
    if isinstance(v, bool) or not isinstance(v, (int, float)):
        raise ValueError(f"must be a number, got {type(v).__name__}")
    if not math.isfinite(v):
        raise ValueError(f"must be finite, got {v}")
    return float(v)


def _positive(v: Any) -> float:
    x = _number(v)
    if x <= 0:
        raise ValueError(f"must be > 0, got {x:g}")
    return x


def _non_negative(v: Any) -> float:
    x = _number(v)
    if x < 0:
        raise ValueError(f"must be >= 0, got {x:g}")
    return x


def _positive_int(v: Any) -> int:
    if isinstance(v, bool) or not isinstance(v, int):
        raise ValueError(f"must be a whole number, got {type(v).__name__}")
    if v <= 0:
        raise ValueError(f"must be > 0, got {v}")
    return v


MAX_CANVAS = 8192   # OpenGL renderbuffers are limited; larger canvases come out black


def _canvas(v: Any) -> int:
    n = _positive_int(v)
    if n > MAX_CANVAS:
        raise ValueError(f"must be at most {MAX_CANVAS} pixels, got {n}")
    return n


def _vec(v: Any) -> Vec:
    if not isinstance(v, (list, tuple)) or len(v) != 3:
        raise ValueError("must be a list of three numbers [x, y, z]")
    x, y, z = (_number(c) for c in v)
    return (x, y, z)


def _positive_vec(v: Any) -> Vec:
    x, y, z = _vec(v)
    if min(x, y, z) <= 0:
        raise ValueError("must have three positive numbers")
    return (x, y, z)


def _nonzero_vec(v: Any) -> Vec:
    x, y, z = _vec(v)
    if x == y == z == 0:
        raise ValueError("must not be the zero vector")
    return (x, y, z)


def _text(v: Any) -> str:
    if not isinstance(v, str):
        raise ValueError(f"must be a string, got {type(v).__name__}")
    return v


def _choice(*options: str) -> Callable[[Any], str]:
    def check(v: Any) -> str:
        s = _text(v)
        if s not in options:
            raise ValueError(f"must be one of {', '.join(repr(o) for o in options)}, got {s!r}")
        return s
    return check


def _shape(v: Any) -> tuple[int, int, int]:
    if not isinstance(v, list) or len(v) not in (1, 3):
        raise ValueError("must be [N] (a chain along x) or [Nx, Ny, Nz]")
    n = [_positive_int(c) for c in v]
    n += [1] * (3 - len(n))
    if n[0] * n[1] * n[2] > MAX_ATOMS:
        raise ValueError(f"has {n[0] * n[1] * n[2]:,} atoms; the limit is {MAX_ATOMS:,}")
    if n[0] * n[1] * n[2] < 2:
        raise ValueError("must have at least two atoms")
    return (n[0], n[1], n[2])


MAX_ATOMS = 1_000_000
MAX_COILS = 200          # the page's spring: 60 chords a coil, 16 sides: 190,000 vertices
MAX_BOND_COILS = 50      # every bond of a lattice drawn as a helix


def _whole(v: Any) -> int:
    if isinstance(v, bool) or not isinstance(v, int):
        raise ValueError(f"must be a whole number, got {type(v).__name__}")
    if v < 0:
        raise ValueError(f"must be >= 0, got {v}")
    return v


def _coils(limit: int, whole: bool = False) -> Callable[[Any], float]:
    def check(v: Any) -> float:
        x = _positive_int(v) if whole else _positive(v)
        if x > limit:
            raise ValueError(f"must be at most {limit}, got {x:g}")
        return x
    return check


def _fov(v: Any) -> float:
    x = _positive(v)
    if x >= math.pi:
        raise ValueError(f"must be below pi (radians), got {x:g}")
    return x


# section -> key -> checker; the keys are the dataclasses' fields.
_CHECKS: dict[str, dict[str, Callable[[Any], Any]]] = {
    "scene": {"title": _text, "width": _canvas, "height": _canvas,
              "background": parse_color},
    "camera": {"center": _vec, "forward": _nonzero_vec, "up": _nonzero_vec, "fov": _fov,
               "range": _positive},
    "physics": {"dt": _positive, "g": _vec, "integrator": _choice(*integrators.NAMES)},
    "damping": {"b": _non_negative},
    "drive": {"type": _choice("none", "support", "force"), "amplitude": _positive,
              "omega": _positive, "direction": _nonzero_vec},
    "holder": {"pos": _vec, "size": _positive_vec, "color": parse_color},
    "spring": {"k": _positive, "L0": _positive, "radius": _positive, "thickness": _non_negative,
               "coils": _coils(MAX_COILS, whole=True), "color": parse_color, "k3": _non_negative,
               "yield_stretch": _positive},
    "ball": {"m": _positive, "radius": _positive, "pos": _vec, "p": _vec, "color": parse_color},
    "render": {"fps": _positive_int, "duration": _non_negative, "speed": _positive,
               "color_by": _choice(*COLOR_BY)},
    "lattice": {"shape": _shape, "spacing": _positive, "density": _positive,
                "fixed": _choice(*FIXED_MODES)},
    "bond": {"k": _positive, "color": parse_color, "style": _choice(*BOND_STYLES),
             "radius": _positive, "thickness": _non_negative, "coils": _coils(MAX_BOND_COILS)},
    "atom": {"m": _positive, "molar_mass": _positive, "radius": _positive, "color": parse_color},
    "start": {"kick": _vec, "temperature": _non_negative, "seed": _whole},
    "pull": {"force": _non_negative},
}

# sections of the page's ball-on-a-spring scene, and of a lattice of atoms
BALL_SECTIONS = ("drive", "holder", "spring", "ball")
LATTICE_SECTIONS = ("lattice", "bond", "atom", "start", "pull")


def from_dict(data: dict[str, Any], source: str = "<dict>") -> Config:
    """Check a parsed TOML document and build a :class:`Config`; defaults fill what is absent."""
    cfg = Config(source=source)
    if "lattice" in data:
        wrong = [sec for sec in BALL_SECTIONS if sec in data]
        if wrong:
            raise UserError(f"{source}: [{wrong[0]}] does not apply to a [lattice] config "
                            f"(a lattice has [{'], ['.join(LATTICE_SECTIONS)}])")
        # gravity is nothing beside the bonds (m g / k ~ 1e-26 m for atoms): off unless given
        physics_table = data.get("physics")
        if not (isinstance(physics_table, dict) and "g" in physics_table):
            cfg = replace(cfg, physics=replace(cfg.physics, g=(0.0, 0.0, 0.0)))
        cfg = replace(cfg, lattice=LatticeCfg())
    else:
        wrong = [sec for sec in LATTICE_SECTIONS if sec in data]
        if wrong:
            raise UserError(f"{source}: [{wrong[0]}] needs a [lattice] section (shape, spacing, "
                            "fixed) to describe the atoms")
    for section, table in data.items():
        if section not in _CHECKS:
            raise UserError(f"{source}: unknown section [{section}] "
                            f"(known: {', '.join(_CHECKS)})")
        if not isinstance(table, dict):
            raise UserError(f"{source}: [{section}] must be a table")
        checks = _CHECKS[section]
        values = {}
        for key, value in table.items():
            if key not in checks:
                raise UserError(f"{source}: unknown key '{key}' in [{section}] "
                                f"(known: {', '.join(checks)})")
            try:
                values[key] = checks[key](value)
            except ValueError as exc:
                raise UserError(f"{source}: [{section}] {key} {exc}") from None
        cfg = replace(cfg, **{section: replace(getattr(cfg, section), **values)})
    _check_whole(cfg)
    return cfg


def _check_whole(cfg: Config, flags: dict[str, str] | None = None) -> None:
    """Checks that involve more than one key.

    ``flags`` maps "section.key" to the command-line flag that set it, so a
    message names the flag rather than the file when the flag is to blame.
    """
    src = cfg.source
    flags = flags or {}

    def where(*keys: str) -> str:
        named = [flags[k] for k in keys if k in flags]
        if named:
            return " ".join(named)
        section, key = keys[0].split(".")
        return f"{src}: [{section}] {key}"

    c = cfg.camera
    if abs(float(np.dot(c.forward, c.up))) >= 0.999999 * np.linalg.norm(c.forward) * np.linalg.norm(c.up):
        raise UserError(f"{src}: [camera] up must not be parallel to [camera] forward")
    if cfg.render.color_by != "none" and not cfg.is_lattice:
        raise UserError(f"{where('render.color_by')}: colouring by {cfg.render.color_by} is for "
                        "the atoms of a [lattice] config")
    if cfg.is_lattice:
        _check_lattice(cfg, where)
        problem = stability_problem(cfg)
        if problem:
            raise UserError(f"{where('physics.dt', 'physics.integrator')}: {problem}")
        return

    d = cfg.drive
    if d.type != "none":
        for key in ("amplitude", "omega"):
            if getattr(d, key) <= 0:
                raise UserError(f"{src}: [drive] {key} is required (> 0) when type = {d.type!r}")
    s = cfg.spring
    weight_stretch = cfg.ball.m * float(np.linalg.norm(cfg.physics.g)) / s.k
    if s.yield_stretch <= weight_stretch:
        raise UserError(f"{src}: [spring] yield_stretch {s.yield_stretch:g} m is not above the "
                        f"stretch the ball's weight alone needs, mg/k = {weight_stretch:.4g} m: "
                        "the spring could never hold the ball")
    if d.type != "none" and d.omega * cfg.physics.dt > MAX_DRIVE_PHASE_PER_STEP:
        raise UserError(f"{where('drive.omega', 'physics.dt')}: a drive at {d.omega:g} rad/s "
                        f"needs dt <= {MAX_DRIVE_PHASE_PER_STEP / d.omega:.3g} s (at least "
                        f"{2 * math.pi / MAX_DRIVE_PHASE_PER_STEP:.0f} steps per drive period), "
                        f"dt is {cfg.physics.dt:g} s")
    problem = stability_problem(cfg)
    if problem:
        raise UserError(f"{where('physics.dt', 'physics.integrator')}: {problem}")
    if np.allclose(cfg.ball.pos, cfg.holder.pos, rtol=0, atol=1e-12):
        raise UserError(f"{src}: [ball] pos must differ from [holder] pos (the spring has no direction)")


MAX_DRIVE_PHASE_PER_STEP = 2 * math.pi / 12   # a drive period needs a dozen steps at least


def _check_lattice(cfg: Config, where: Callable[..., str]) -> None:
    src, lat, atom = cfg.source, cfg.lattice, cfg.atom
    if (atom.m is None) == (atom.molar_mass is None):
        raise UserError(f"{src}: [atom] needs exactly one of m (kg) and molar_mass (kg/mol)")
    if (lat.spacing is None) == (lat.density is None):
        raise UserError(f"{src}: [lattice] needs exactly one of spacing (m) and density (kg/m^3)")
    nx, ny, nz = lat.shape
    if cfg.pull.force > 0:
        if lat.fixed != "start":
            raise UserError(f"{src}: [pull] force needs [lattice] fixed = \"start\" (the bar is "
                            f"held at its x = 0 end and pulled at the other), got {lat.fixed!r}")
        if nx < 2:
            raise UserError(f"{src}: [pull] force needs at least two atoms along x, "
                            f"[lattice] shape has {nx}")
    held = fixed_mask(lat.shape, lat.fixed)
    if held.all():
        raise UserError(f"{src}: [lattice] fixed = {lat.fixed!r} holds every atom of shape "
                        f"{list(lat.shape)}: nothing can move")
    if any(cfg.start.kick) and cfg.start.temperature > 0:
        raise UserError(f"{src}: [start] takes a kick or a temperature, not both (the kick's "
                        "energy would be counted as heat and the heat would blur the pulse)")
    if any(cfg.start.kick) and len(first_free_layer(lat.shape, held)) == 0:
        raise UserError(f"{src}: [start] kick has no free atom to kick")


def stability_problem(cfg: Config) -> str | None:
    """Why the config's step would make its integrator blow up, with a step that would not."""
    omega, gamma = physics.mode_bounds(build.system(cfg))
    what = "a bound on the fastest mode's omega" if cfg.is_lattice else "omega = sqrt(k/m)"
    return integrators.stability_problem(cfg.physics.integrator, omega, gamma, cfg.physics.dt,
                                         what)


def load(path: str | Path) -> Config:
    """Read and check a TOML config file."""
    path = Path(path)
    try:
        raw = path.read_bytes()
    except FileNotFoundError:
        raise UserError(f"{path}: no such config file") from None
    except IsADirectoryError:
        raise UserError(f"{path}: is a directory, not a config file") from None
    except OSError as exc:
        raise UserError(f"{path}: cannot read ({exc.strerror})") from None
    try:
        data = tomllib.loads(raw.decode("utf-8"))
    except UnicodeDecodeError:
        raise UserError(f"{path}: not UTF-8 text") from None
    except tomllib.TOMLDecodeError as exc:
        raise UserError(f"{path}: invalid TOML: {exc}") from None
    except RecursionError:      # tomllib recurses once per level of nested tables
        raise UserError(f"{path}: values nested too deeply (a config needs two levels)") \
            from None
    return from_dict(data, source=str(path))


def override(cfg: Config, section: str, **values: Any) -> Config:
    """Return ``cfg`` with command-line values in ``section``, checked like the file's.

    None values are skipped; a bad value raises :class:`UserError` naming the flag
    (``--key``).
    """
    checks = _CHECKS[section]
    checked = {key: check_flag(f"--{key}", checks[key], value)
               for key, value in values.items() if value is not None}
    if not checked:
        return cfg
    new = replace(cfg, **{section: replace(getattr(cfg, section), **checked)})
    _check_whole(new, {f"{section}.{key}": f"--{key}" for key in checked})
    return new


def check_flag(flag: str, check: Callable[[Any], Any], value: Any) -> Any:
    """Run one of this module's checks on a command-line value; errors name ``flag``."""
    try:
        return check(value)
    except ValueError as exc:
        raise UserError(f"{flag} {exc}") from None


non_negative = _non_negative
