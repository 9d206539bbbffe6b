"""Scene configs: TOML files read into checked dataclasses, and the physics system they describe.

Every key is checked: an unknown section or key, a wrong type, a non-finite
number or a value out of range raises :class:`~springscene.errors.UserError`
with a one-line message naming the file and the key.
"""

from __future__ import annotations

import math
import tomllib
from dataclasses import dataclass, field, replace
from pathlib import Path
from typing import Any, Callable

import numpy as np

from .colors import Color, parse_color
from .errors import UserError
from . import integrators, physics
from .physics import Drive, System

Vec = tuple[float, float, float]


@dataclass(frozen=True)
class SceneCfg:
    title: str = "Ball and Spring Model of Matter"
    width: int = 900
    height: int = 600
    background: Color = (1.0, 1.0, 1.0)


@dataclass(frozen=True)
class CameraCfg:
    """VPython's canvas camera: ``range`` None means autoscale."""

    center: Vec = (0.0, 0.0, 0.0)
    forward: Vec = (0.0, 0.0, -1.0)
    up: Vec = (0.0, 1.0, 0.0)
    fov: float = math.pi / 3
    range: float | None = None


@dataclass(frozen=True)
class PhysicsCfg:
    dt: float = 0.01
    g: Vec = (0.0, -9.8, 0.0)
    integrator: str = "euler-cromer"


@dataclass(frozen=True)
class DampingCfg:
    """Linear drag on the ball, F = -b v (kg/s)."""

    b: float = 0.0


@dataclass(frozen=True)
class DriveCfg:
    """``support``: the holder moves as A sin(omega t) along ``direction`` (A in m).
    ``force``: the ball feels F0 cos(omega t) along ``direction`` (A = F0 in N)."""

    type: str = "none"
    amplitude: float = 0.0
    omega: float = 0.0
    direction: Vec = (0.0, 1.0, 0.0)


@dataclass(frozen=True)
class HolderCfg:
    pos: Vec = (0.0, 0.0, 0.0)
    size: Vec = (0.2, 0.01, 0.2)
    color: Color = (0.5, 0.5, 0.5)


@dataclass(frozen=True)
class SpringCfg:
    k: float = 15.0
    L0: float = 0.10
    radius: float = 0.015
    thickness: float = 0.003
    coils: int = 15
    color: Color = (0.0, 1.0, 1.0)
    k3: float = 0.0                       # stiffening, N/m^3: F = -(k s + k3 s^3)
    yield_stretch: float = math.inf       # elastic limit of |stretch| (m); beyond it L0 sets


@dataclass(frozen=True)
class BallCfg:
    m: float = 0.10
    radius: float = 0.025
    pos: Vec = (0.0, -0.18533333333333335, 0.0)
    p: Vec = (0.0, 0.0, 0.0)
    color: Color = (1.0, 0.0, 0.0)


@dataclass(frozen=True)
class RenderCfg:
    fps: int = 50
    duration: float = 10.0      # simulated seconds
    speed: float = 1.0          # simulated seconds per video second (1: real time)
    color_by: str = "none"      # lattice atoms: "displacement" or "speed", with a colour bar


# ---- the ball-and-spring model of matter: a lattice of atoms joined by bonds ----------

FIXED_MODES = ("none", "ends", "start", "outer")
COLOR_BY = ("none", "displacement", "speed")
BOND_STYLES = ("auto", "helix", "cylinder", "line")
AVOGADRO = 6.02214076e23      # 1/mol
BOLTZMANN = 1.380649e-23      # J/K


@dataclass(frozen=True)
class LatticeCfg:
    """A simple cubic lattice: ``shape`` atoms along x, y, z (a chain is [N] along x).

    ``spacing`` is the bond's relaxed length d; instead, ``density`` (kg/m^3) gives
    d = (m/density)^(1/3), one atom per cube of side d. ``fixed``: which atoms are
    held: none; the two x ends (a chain's end atoms, a bar's end faces); the
    start (the x = 0 end only); or the outer layer.
    """

    shape: tuple[int, int, int] = (10, 1, 1)
    spacing: float | None = None
    density: float | None = None
    fixed: str = "ends"


@dataclass(frozen=True)
class BondCfg:
    """Every bond is a spring of stiffness ``k`` relaxed at the lattice spacing.

    ``style`` draws them as helices, cylinders or lines; ``auto`` takes helices
    up to :data:`springscene.lattice.HELIX_MAX_BONDS` bonds and cylinders beyond.
    ``radius`` (the helix's, or the cylinder's) and ``thickness`` (the helix's wire)
    default to fractions of the spacing.
    """

    k: float = 15.0
    color: Color = (0.0, 1.0, 1.0)
    style: str = "auto"
    radius: float | None = None
    thickness: float | None = None
    coils: int = 5


@dataclass(frozen=True)
class AtomCfg:
    """Each atom's mass ``m`` (kg), or its ``molar_mass`` (kg/mol): m = molar_mass / N_A.

    ``radius`` is only drawn (default a quarter of the spacing).
    """

    m: float | None = None
    molar_mass: float | None = None
    radius: float | None = None
    color: Color = (1.0, 0.0, 0.0)


@dataclass(frozen=True)
class StartCfg:
    """How the atoms start: at their sites, at rest, except for

    ``kick``: this velocity (m/s) given to the first free atom along x (every free
    atom of the first free layer, in a crystal), which launches a pulse;
    ``temperature``: random thermal momenta (Maxwell-Boltzmann, K), from ``seed``.
    """

    kick: Vec = (0.0, 0.0, 0.0)
    temperature: float = 0.0
    seed: int = 0


@dataclass(frozen=True)
class PullCfg:
    """A steady force (N, along +x) on the last face (x end), shared by its atoms."""

    force: float = 0.0


@dataclass(frozen=True)
class Config:
    scene: SceneCfg = field(default_factory=SceneCfg)
    camera: CameraCfg = field(default_factory=CameraCfg)
    physics: PhysicsCfg = field(default_factory=PhysicsCfg)
    damping: DampingCfg = field(default_factory=DampingCfg)
    drive: DriveCfg = field(default_factory=DriveCfg)
    holder: HolderCfg = field(default_factory=HolderCfg)
    spring: SpringCfg = field(default_factory=SpringCfg)
    ball: BallCfg = field(default_factory=BallCfg)
    render: RenderCfg = field(default_factory=RenderCfg)
    lattice: LatticeCfg | None = None      # a lattice config: atoms and bonds, no ball
    bond: BondCfg = field(default_factory=BondCfg)
    atom: AtomCfg = field(default_factory=AtomCfg)
    start: StartCfg = field(default_factory=StartCfg)
    pull: PullCfg = field(default_factory=PullCfg)
    source: str = "<defaults>"

    @property
    def driven(self) -> bool:
        return self.drive.type != "none"

    @property
    def is_lattice(self) -> bool:
        """A chain or crystal of atoms ([lattice]) rather than the page's ball on a spring."""
        return self.lattice is not None

    def system(self, omega: Any = None) -> System:
        """The physics system. A lattice config's is :func:`springscene.lattice.build`'s.

        Otherwise the ball on its spring: node 0 the fixed holder, node 1 the ball, spring 0 from holder to ball.

        With ``omega`` an array of N drive frequencies, N independent copies side by
        side (holder 2c, ball 2c+1, spring c), copy c driven at ``omega[c]``: a
        resonance sweep as one system.
        """
        if self.is_lattice:
            from . import lattice

            return lattice.build(self)
        w = np.atleast_1d(np.asarray(self.drive.omega if omega is None else omega, float))
        n = len(w) if omega is not None else 1
        holder, ball = np.arange(0, 2 * n, 2), np.arange(1, 2 * n, 2)
        pos = np.empty((2 * n, 3))
        pos[holder], pos[ball] = self.holder.pos, self.ball.pos
        p = np.zeros((2 * n, 3))
        p[ball] = self.ball.p
        drive = None
        if self.driven:
            nodes = holder if self.drive.type == "support" else ball
            drive = Drive(self.drive.type, nodes, self.drive.amplitude, w, self.drive.direction)
        s = self.spring
        return System(
            pos=pos, p=p, m=np.tile([1.0, self.ball.m], n), fixed=np.tile([True, False], n),
            i=holder, j=ball, k=s.k, L0=s.L0, k3=s.k3, yield_stretch=s.yield_stretch,
            g=self.physics.g, dt=self.physics.dt, b=np.tile([0.0, self.damping.b], n),
            drive=drive, integrator=self.physics.integrator,
        )


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
    from . import lattice

    held = lattice.fixed_mask(lat.shape, lat.fixed)
    if held.all():
        raise UserError(f"{src}: [lattice] fixed = {lat.fixed!r} holds every atom of shape "
                        f"{list(lat.shape)}: nothing can move")
    if any(cfg.start.kick) and cfg.start.temperature > 0:
        raise UserError(f"{src}: [start] takes a kick or a temperature, not both (the kick's "
                        "energy would be counted as heat and the heat would blur the pulse)")
    if any(cfg.start.kick) and len(lattice.first_free_layer(lat.shape, held)) == 0:
        raise UserError(f"{src}: [start] kick has no free atom to kick")


def stability_problem(cfg: Config) -> str | None:
    """Why the config's step would make its integrator blow up, with a step that would not."""
    name, dt = cfg.physics.integrator, cfg.physics.dt
    omega, gamma = physics.mode_bounds(cfg.system())
    omega, gamma = np.unique(np.column_stack([omega, gamma]), axis=0).T   # a lattice repeats them
    if integrators.stable(name, omega, gamma, dt):
        return None
    w, gm = float(omega.max()), float(gamma.max())
    h_max = integrators.largest_stable_step(name, omega, gamma, dt)
    rule = {"euler-cromer": "needs omega*dt < 2", "verlet": "needs omega*dt < 2",
            "rk4": "needs omega*dt < 2.83",
            "euler": f"grows the amplitude more than {integrators.EULER_MAX_GROWTH_PER_PERIOD:g}x "
                     "per period"}[name]
    damped = f", b/2m = {gm:.3g} /s" if gm > 0 else ""
    what = "a bound on the fastest mode's omega" if cfg.is_lattice else "omega = sqrt(k/m)"
    return (f"dt = {dt:g} s is unstable for {name} ({what} = {w:.4g} rad/s, "
            f"omega*dt = {w * dt:.3g}{damped}; {name} {rule}); "
            f"use dt <= {integrators.suggest_step(h_max):g} s")


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
