"""Scene configs: TOML files read into checked dataclasses (:mod:`springscene.settings`).

Every key is checked: an unknown section or key, a wrong type, a non-finite
number or a value out of range raises :class:`~springscene.errors.UserError`
with a one-line message naming the file and the key.
"""

from __future__ import annotations

import math
import os
import stat
import sys
from dataclasses import replace
from pathlib import Path
from typing import Any, Callable

import numpy as np

from . import build, ranges
from .colors import parse_color
from .errors import UserError
from .model import integrators, physics
from .model.lattice import first_free_layer, fixed_mask
from .settings import (BOND_STYLES, COLOR_BY, FIXED_MODES, AtomCfg, BallCfg, BondCfg,  # noqa: F401
                       CameraCfg, Config, DampingCfg, DriveCfg, HolderCfg, LatticeCfg, PhysicsCfg,
                       PullCfg, RenderCfg, SceneCfg, SpringCfg, StartCfg, Vec)

if sys.version_info >= (3, 11):
    import tomllib
else:                       # the same parser, before it joined the standard library
    import tomli as tomllib

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


def _direction(v: Any) -> Vec:
    """A direction: any finite non-zero vector, scaled by a power of two (exactly, so the
    direction is unchanged) when its length would overflow or underflow."""
    x, y, z = _nonzero_vec(v)
    exponent = math.frexp(max(abs(x), abs(y), abs(z)))[1]
    if abs(exponent) > 500:
        x, y, z = (math.ldexp(c, -exponent) for c in (x, y, z))
    return (x, y, z)


def _in(lo: float, hi: float, unit: str) -> Callable[[Any], float]:
    """A number between ``lo`` and ``hi`` (in ``unit``); a non-positive one is told so as
    :func:`_positive` (or :func:`_non_negative` when ``lo`` is 0) tells it."""
    def check(v: Any) -> float:
        x = _positive(v) if lo > 0 else _non_negative(v)
        if not lo <= x <= hi:
            span = (f"at least {ranges.fmt(lo)}" if hi == math.inf else
                    f"between {ranges.fmt(lo)} and {ranges.fmt(hi)}")
            raise ValueError(f"must be {span} {unit}, got {ranges.fmt(x)}")
        return x
    return check


def _vec_within(hi: float, unit: str, what: str = "each component") -> Callable[[Any], Vec]:
    """Three numbers, each at most ``hi`` (in ``unit``) in size."""
    def check(v: Any) -> Vec:
        x, y, z = _vec(v)
        top = max(abs(x), abs(y), abs(z))
        if top > hi:
            raise ValueError(f"must have {what} within +-{ranges.fmt(hi)} {unit}, "
                             f"got {ranges.fmt(top)}")
        return (x, y, z)
    return check


MAX_TITLE = 300     # characters: a title is one line across the canvas (900 px show ~75)
MAX_WORD = 100      # characters of any other text: a colour, a choice


def _text(v: Any, limit: int = MAX_WORD) -> str:
    if not isinstance(v, str):
        raise ValueError(f"must be a string, got {type(v).__name__}")
    if len(v) > limit:
        raise ValueError(f"must be at most {limit} characters, got {len(v):,}")
    return v


def _title(v: Any) -> str:
    return _text(v, MAX_TITLE)


def _color(v: Any):
    if isinstance(v, str):
        _text(v)
    return parse_color(v)


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


MIN_FOV, MAX_FOV = 1e-3, 3.1     # radians: 0.06 to 178 degrees (VTK's view angle stops at 179)


def _fov(v: Any) -> float:
    x = _positive(v)
    if x >= math.pi:
        raise ValueError(f"must be below pi (radians), got {x:g}")
    if not MIN_FOV <= x <= MAX_FOV:
        raise ValueError(f"must be between {MIN_FOV:g} and {MAX_FOV:g} rad, got {x:g}")
    return x


# Absolute ranges (SI), wide enough for the page's metre-scale scenes and for atoms;
# what depends on the scene's scale is checked against it in springscene.ranges.
MASS = _in(1e-30, 1e6, "kg")
STIFFNESS = _in(1e-9, 1e12, "N/m")
LENGTH = _in(1e-15, 1e6, "m")            # a femtometre to 1000 km
SPEED_OF_LIGHT = 299_792_458.0

# section -> key -> checker; the keys are the dataclasses' fields.
_CHECKS: dict[str, dict[str, Callable[[Any], Any]]] = {
    "scene": {"title": _title, "width": _canvas, "height": _canvas,
              "background": _color},
    "camera": {"center": _vec, "forward": _direction, "up": _direction, "fov": _fov,
               "range": _positive},
    "physics": {"dt": _in(1e-20, math.inf, "s"),      # its top: the integrator's stability
                "g": _vec_within(1e4, "m/s^2"), "integrator": _choice(*integrators.NAMES)},
    "damping": {"b": _in(0, 1e9, "kg/s")},
    "drive": {"type": _choice("none", "support", "force"), "amplitude": _positive,
              "omega": _in(1e-9, 1e20, "rad/s"), "direction": _direction},
    "holder": {"pos": _vec, "size": _positive_vec, "color": _color},
    "spring": {"k": STIFFNESS, "L0": LENGTH, "radius": _positive, "thickness": _non_negative,
               "coils": _coils(MAX_COILS, whole=True), "color": _color,
               "k3": _non_negative, "yield_stretch": _positive},
    "ball": {"m": MASS, "radius": _positive, "pos": _vec, "p": _vec, "color": _color},
    "render": {"fps": _positive_int, "duration": _non_negative, "speed": _positive,
               "color_by": _choice(*COLOR_BY)},
    "lattice": {"shape": _shape, "spacing": LENGTH, "density": _in(1e-3, 1e6, "kg/m^3"),
                "fixed": _choice(*FIXED_MODES)},
    "bond": {"k": STIFFNESS, "color": _color, "style": _choice(*BOND_STYLES),
             "radius": _positive, "thickness": _non_negative, "coils": _coils(MAX_BOND_COILS)},
    "atom": {"m": MASS, "molar_mass": _in(1e-7, 1e4, "kg/mol"), "radius": _positive,
             "color": _color},
    "start": {"kick": _vec_within(SPEED_OF_LIGHT, "m/s (the speed of light)"),
              "temperature": _non_negative, "seed": _whole},     # its top: ranges
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
        values = _checked_table(source, section, table)
        cfg = replace(cfg, **{section: replace(getattr(cfg, section), **values)})
    _check_whole(cfg)
    return cfg


def _checked_table(source: str, section: str, table: dict[str, Any]) -> dict[str, Any]:
    """The keys of one ``[section]``, each through its check; errors name file and key."""
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
    return values


def changed(cfg: Config, changes: dict[str, Any]) -> Config:
    """``cfg`` with ``changes``, checked as the same values in its TOML file would be.

    ``changes`` maps a section to a table of keys (``{"spring": {"k": 20}}``), or a key
    to a value (``{"k": 20}``) where only one of the config's sections has that key.
    This is :meth:`springscene.settings.Config.replace`.
    """
    own = [s for s in _CHECKS
           if s not in (BALL_SECTIONS if cfg.is_lattice else LATTICE_SECTIONS)]
    tables: dict[str, dict[str, Any]] = {}
    for name, value in changes.items():
        if name in _CHECKS:
            if name not in own:
                raise UserError(f"{cfg.source}: [{name}] does not apply to this config "
                                f"(its sections: {', '.join(own)})")
            if not isinstance(value, dict):
                raise UserError(f"{cfg.source}: [{name}] must be a table (a dict of keys)")
            tables.setdefault(name, {}).update(value)
            continue
        homes = [s for s in own if name in _CHECKS[s]]
        if len(homes) != 1:
            what = (f"is in [{'], ['.join(homes)}]: name the section, e.g. "
                    f"{homes[-1]}={{{name!r}: ...}}" if homes else
                    f"is not a key of any of its sections ({', '.join(own)})")
            raise UserError(f"{cfg.source}: '{name}' {what}")
        tables.setdefault(homes[0], {})[name] = value
    new = cfg
    for section, table in tables.items():
        values = _checked_table(cfg.source, section, table)
        new = replace(new, **{section: replace(getattr(new, section), **values)})
    _check_whole(new)
    return new


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
        ranges.check(cfg, where)
        problem = stability_problem(cfg)
        if problem:
            raise UserError(f"{where('physics.dt', 'physics.integrator')}: {problem}")
        return

    d = cfg.drive
    if d.type != "none":
        for key in ("amplitude", "omega"):
            if getattr(d, key) <= 0:
                raise UserError(f"{src}: [drive] {key} is required (> 0) when type = {d.type!r}")
    ranges.check(cfg, where)
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


MAX_CONFIG_BYTES = 1_000_000     # the page's config is 900 bytes; a larger file is no config

_NOT_REGULAR = ((stat.S_ISDIR, "is a directory, not a config file"),
                (stat.S_ISFIFO, "is a named pipe (FIFO), not a config file"),
                (stat.S_ISCHR, "is a character device, not a config file"),
                (stat.S_ISBLK, "is a block device, not a config file"),
                (stat.S_ISSOCK, "is a socket, not a config file"))


def read_config_bytes(path: Path) -> bytes:
    """The bytes of a config file: a regular file of at most :data:`MAX_CONFIG_BYTES`
    (a FIFO would wait for a writer forever, ``/dev/zero`` never ends)."""
    try:
        fd = os.open(path, os.O_RDONLY | os.O_NONBLOCK)    # a FIFO opens without a writer
    except FileNotFoundError:
        raise UserError(f"{path}: no such config file") from None
    except OSError as exc:
        raise UserError(f"{path}: cannot read ({exc.strerror})") from None
    mode = os.fstat(fd).st_mode
    if not stat.S_ISREG(mode):
        os.close(fd)
        what = next((what for test, what in _NOT_REGULAR if test(mode)), "is not a regular file")
        raise UserError(f"{path}: {what}")
    with os.fdopen(fd, "rb") as fh:
        try:
            raw = fh.read(MAX_CONFIG_BYTES + 1)
        except OSError as exc:
            raise UserError(f"{path}: cannot read ({exc.strerror})") from None
    if len(raw) > MAX_CONFIG_BYTES:
        raise UserError(f"{path}: is over {MAX_CONFIG_BYTES:,} bytes; a config is a short "
                        "TOML file")
    return raw


def load(path: str | Path) -> Config:
    """Read and check a TOML config file."""
    path = Path(path)
    raw = read_config_bytes(path)
    try:
        data = tomllib.loads(raw.decode("utf-8-sig"))   # (a BOM, as some editors write)
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

Config.checker = changed      # cfg.replace(...) checks through this module
