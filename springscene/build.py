"""From a checked :class:`~springscene.settings.Config` to the physics it describes.

:func:`system` is the one place a config becomes a :class:`~springscene.model.physics.System`:
the page's holder, spring and ball (node 0 the fixed holder, node 1 the ball, spring 0
from holder to ball), N such pairs side by side for a resonance sweep, or a lattice of
atoms (:func:`lattice`, :func:`springscene.model.lattice.build`).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from .model import lattice as lattice_model
from .model.physics import Drive, System
from .settings import Config


def lattice(cfg: Config) -> lattice_model.Lattice:
    """A lattice config's numbers: m from ``m`` or ``molar_mass``, d from ``spacing`` or
    ``density``."""
    lat, atom = cfg.lattice, cfg.atom
    m = atom.m if atom.m is not None else lattice_model.atomic_mass(atom.molar_mass)
    d = lat.spacing if lat.spacing is not None else lattice_model.spacing_from_density(
        m, lat.density)
    return lattice_model.Lattice(tuple(lat.shape), d, m, cfg.bond.k, lat.fixed)


def system(cfg: Config, omega: Any = None) -> System:
    """The physics system of ``cfg``, at t = 0.

    With ``omega`` an array of N drive frequencies, N independent copies side by
    side (holder 2c, ball 2c+1, spring c), copy c driven at ``omega[c]``: a
    resonance sweep as one system.
    """
    if cfg.is_lattice:
        st = cfg.start
        return lattice_model.build(
            lattice(cfg), kick=st.kick, temperature=st.temperature, seed=st.seed,
            pull=cfg.pull.force, g=cfg.physics.g, dt=cfg.physics.dt, b=cfg.damping.b,
            integrator=cfg.physics.integrator)
    w = np.atleast_1d(np.asarray(cfg.drive.omega if omega is None else omega, float))
    n = len(w) if omega is not None else 1
    holder, ball = np.arange(0, 2 * n, 2), np.arange(1, 2 * n, 2)
    pos = np.empty((2 * n, 3))
    pos[holder], pos[ball] = cfg.holder.pos, cfg.ball.pos
    p = np.zeros((2 * n, 3))
    p[ball] = cfg.ball.p
    drive = None
    if cfg.driven:
        nodes = holder if cfg.drive.type == "support" else ball
        drive = Drive(cfg.drive.type, nodes, cfg.drive.amplitude, w, cfg.drive.direction)
    s = cfg.spring
    return System(
        pos=pos, p=p, m=np.tile([1.0, cfg.ball.m], n), fixed=np.tile([True, False], n),
        i=holder, j=ball, k=s.k, L0=s.L0, k3=s.k3, yield_stretch=s.yield_stretch,
        g=cfg.physics.g, dt=cfg.physics.dt, b=np.tile([0.0, cfg.damping.b], n),
        drive=drive, integrator=cfg.physics.integrator,
    )
