"""What a scene config says, as frozen dataclasses: one per TOML section, and :class:`Config`.

Plain data with the defaults of the wiki page; nothing here reads a file or checks a
value (:mod:`springscene.config` does both) or builds physics (:mod:`springscene.build`).
Drawing code is handed the sections it draws with (``SceneCfg``, ``CameraCfg``, ...).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any, Callable, ClassVar

from .colors import Color
from .model import integrators

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
    integrator: str = integrators.DEFAULT


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
    up to :data:`springscene.model.lattice.HELIX_MAX_BONDS` bonds and cylinders beyond.
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

    # set by springscene.config (which checks values; this module only holds them)
    checker: ClassVar[Callable[[Config, dict[str, Any]], Config] | None] = None

    def replace(self, **changes: Any) -> Config:
        """A copy with ``changes``, each checked as the same value in the TOML file would be.

        Parameters
        ----------
        **changes
            A section and a dict of its keys, as in the TOML file
            (``spring={"k": 20, "L0": 0.12}``), or a key alone where only one of the
            config's sections has it (``k=20``, ``dt=0.005``, ``b=0.1``).

        Returns
        -------
        Config
            A new config; this one is unchanged (configs are frozen).

        Raises
        ------
        UserError
            A bad value, with the one-line message a TOML file with that value gets,
            e.g. ``wiki.toml: [spring] k must be > 0, got -1``; or a key that is in
            several sections (``radius``: name the section).

        Examples
        --------
        >>> import springscene
        >>> cfg = springscene.load_config("wiki")
        >>> cfg.replace(k=20).spring.k
        20.0
        >>> cfg.replace(ball={"m": 0.2}, dt=0.005).physics.dt
        0.005
        >>> cfg.replace(k=-1)
        Traceback (most recent call last):
        springscene.errors.UserError: wiki.toml: [spring] k must be > 0, got -1
        """
        if Config.checker is None:
            raise RuntimeError("import springscene.config to check a config's changes")
        return Config.checker(self, changes)

    @property
    def driven(self) -> bool:
        return self.drive.type != "none"

    @property
    def is_lattice(self) -> bool:
        """A chain or crystal of atoms ([lattice]) rather than the page's ball on a spring."""
        return self.lattice is not None

