"""The ball-and-spring model of matter: chains and simple cubic crystals of atoms joined by bonds.

A lattice config ([lattice], [bond], [atom], [start], [pull]) describes atoms of
mass m on the sites of an nx x ny x nz simple cubic grid of spacing d, each bonded
to its nearest neighbours by a spring of stiffness k relaxed at d. :func:`build`
turns it into the same :class:`~springscene.model.physics.System` the page's single
spring uses, with ``grid`` set so that the engine computes the bond forces by
slicing the grid.

Sites are numbered in C order of (x, y, z) index and centred on the origin; a
chain (shape [N]) lies along x. Atomic values come from the material:
m = molar_mass / N_A and d = (m / density)^(1/3) (one atom per cube of side d).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from . import integrators, physics
from .constants import AVOGADRO, BOLTZMANN

HELIX_MAX_BONDS = 300     # style "auto": helices up to this many bonds, cylinders beyond


def atomic_mass(molar_mass: float) -> float:
    """Mass of one atom (kg) from the molar mass (kg/mol)."""
    return molar_mass / AVOGADRO


def spacing_from_density(m: float, density: float) -> float:
    """Interatomic spacing d = (m / rho)^(1/3) (m): one atom per cube of side d."""
    return (m / density) ** (1.0 / 3.0)


def fixed_mask(shape: tuple[int, int, int], fixed: str) -> np.ndarray:
    """Which sites are held (N,) for ``fixed`` = none, ends, start or outer."""
    index = np.indices(shape)
    held = np.zeros(shape, dtype=bool)
    if fixed in ("ends", "start"):
        held[0] = True
        if fixed == "ends":
            held[-1] = True
    elif fixed == "outer":
        for a, n in enumerate(shape):
            if n > 1:
                held |= (index[a] == 0) | (index[a] == n - 1)
    elif fixed != "none":
        raise ValueError(f"unknown fixed mode {fixed!r}")
    return held.ravel()


def first_free_layer(shape: tuple[int, int, int], held: np.ndarray) -> np.ndarray:
    """The free sites with the smallest x index among free sites (the kicked atoms)."""
    free = ~held.reshape(shape)
    layers = np.flatnonzero(free.any(axis=(1, 2)))
    if not len(layers):
        return np.zeros(0, dtype=np.intp)
    mask = np.zeros(shape, dtype=bool)
    mask[layers[0]] = free[layers[0]]
    return np.flatnonzero(mask.ravel())


def last_layer(shape: tuple[int, int, int]) -> np.ndarray:
    """The sites of the last x layer (the pulled face)."""
    mask = np.zeros(shape, dtype=bool)
    mask[-1] = True
    return np.flatnonzero(mask.ravel())


@dataclass(frozen=True)
class Lattice:
    """A lattice config's numbers: shape, spacing d (m), atomic mass m (kg), stiffness k (N/m)."""

    shape: tuple[int, int, int]
    d: float
    m: float
    k: float
    fixed: str

    @property
    def n_atoms(self) -> int:
        return math.prod(self.shape)

    @property
    def dims(self) -> int:
        """1 for a chain along x, 2 or 3 for a slab or a crystal."""
        return sum(n > 1 for n in self.shape)

    @property
    def is_chain(self) -> bool:
        return self.shape[1] == self.shape[2] == 1

    def sites(self) -> np.ndarray:
        """Rest positions (N, 3), centred on the origin."""
        idx = np.indices(self.shape).reshape(3, -1).T.astype(float)
        return (idx - (np.asarray(self.shape) - 1) / 2.0) * self.d

    def held(self) -> np.ndarray:
        return fixed_mask(self.shape, self.fixed)

    # closed forms of the linear chain (theory beside the measurements)
    @property
    def omega0(self) -> float:
        """sqrt(k/m) (rad/s)."""
        return math.sqrt(self.k / self.m)

    @property
    def sound_speed(self) -> float:
        """Long-wavelength speed of sound v = d sqrt(k/m) (m/s)."""
        return self.d * self.omega0

    @property
    def youngs_modulus(self) -> float:
        """Y = k/d (Pa): stress F/d^2 per bond over strain (F/k)/d."""
        return self.k / self.d

    def dispersion(self, q) -> np.ndarray:
        """omega(q) = 2 sqrt(k/m) |sin(q d / 2)| (rad/s)."""
        return 2.0 * self.omega0 * np.abs(np.sin(np.asarray(q, float) * self.d / 2.0))


def thermal_momenta(m: float, temperature: float, free: np.ndarray, seed: int,
                    zero_total: bool) -> np.ndarray:
    """Maxwell-Boltzmann momenta (len(free), 3) scaled so that K = (dof/2) k_B T exactly.

    With ``zero_total`` (a crystal no atom of which is held) the mean momentum is
    taken out first, so the crystal does not drift, and dof = 3 (n - 1).
    """
    rng = np.random.default_rng(seed)
    p = rng.standard_normal((len(free), 3)) * math.sqrt(m * BOLTZMANN * temperature)
    dof = 3 * len(free)
    if zero_total:
        p -= p.mean(axis=0)
        dof -= 3
    K = float(np.sum(p * p)) / (2 * m)
    target = 0.5 * dof * BOLTZMANN * temperature
    return p * math.sqrt(target / K) if K > 0 else p


def build(lat: Lattice, *, kick=(0.0, 0.0, 0.0), temperature: float = 0.0, seed: int = 0,
          pull: float = 0.0, g=(0.0, 0.0, 0.0), dt: float, b: float = 0.0,
          integrator: str = integrators.DEFAULT) -> physics.System:
    """The physics system of a lattice: grid nodes and bonds; atoms at rest on their sites
    except for a ``kick`` (m/s) to the first free layer or thermal momenta at
    ``temperature`` (K, from ``seed``); a ``pull`` (N, along +x) shared by the last face."""
    pos = lat.sites()
    n = len(pos)
    held = lat.held()
    free = np.flatnonzero(~held)
    p = np.zeros((n, 3))
    if temperature > 0:
        p[free] = thermal_momenta(lat.m, temperature, free, seed, zero_total=not held.any())
    if any(kick):
        p[first_free_layer(lat.shape, held)] += lat.m * np.asarray(kick, float)
    F_ext = None
    if pull > 0:
        face = last_layer(lat.shape)
        F_ext = np.zeros((n, 3))
        F_ext[face, 0] = pull / len(face)
    i, j = physics.grid_bonds(lat.shape)
    return physics.System(
        pos=pos, p=p, m=lat.m, fixed=held, i=i, j=j, k=lat.k, L0=lat.d, g=g, dt=dt, b=b,
        F_ext=F_ext, integrator=integrator, grid=lat.shape,
    )
