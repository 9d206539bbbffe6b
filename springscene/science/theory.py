"""Closed forms for a ball on one spring: the page's formulas, to set beside the simulation.

Along the spring's line of motion (the direction of g), with x the ball's
displacement from equilibrium, the linear model is::

    m x'' = -k x - b x' + F(t)

- undamped: x = A cos(omega0 t + phi), omega0 = sqrt(k/m), T = 2 pi sqrt(m/k);
- under-damped (gamma = b/2m < omega0): x = A e^(-gamma t) cos(omega_d t + phi),
  omega_d = sqrt(omega0^2 - gamma^2);
- critically damped: x = (x0 + (v0 + gamma x0) t) e^(-gamma t);
- over-damped: x = c1 e^(r1 t) + c2 e^(r2 t), r = -gamma +- sqrt(gamma^2 - omega0^2);
- driven steady state: A(omega) = (F0/m) / sqrt((omega0^2 - omega^2)^2 + (2 gamma omega)^2).

A driven support y_h = A_s sin(omega t) is the same as an external force with
F0 = k A_s (the spring pulls the ball by k times the holder's displacement).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from .. import build
from ..errors import UserError
from ..model import physics
from ..settings import Config


@dataclass(frozen=True)
class Oscillator:
    """The linear damped oscillator of a config, from its initial state.

    ``axis`` is the unit vector of motion (up, against g); ``x0``, ``v0`` the
    ball's initial displacement from equilibrium and velocity along it.
    """

    m: float
    k: float
    b: float
    g: float             # |g|
    L0: float
    x0: float
    v0: float
    axis: tuple[float, float, float]
    equilibrium: tuple[float, float, float]
    s_eq: float | None = None   # equilibrium stretch; m g / k when None

    @classmethod
    def from_config(cls, cfg: Config) -> "Oscillator":
        g = np.asarray(cfg.physics.g, float)
        gmag = float(np.linalg.norm(g))
        holder = np.asarray(cfg.holder.pos, float)
        ball = np.asarray(cfg.ball.pos, float)
        if gmag > 0:
            axis = -g / gmag
        else:
            axis = (holder - ball) / np.linalg.norm(holder - ball)
        m, k, k3 = cfg.ball.m, cfg.spring.k, cfg.spring.k3
        s_eq = stiffening_stretch(k, k3, m * gmag)
        k_lin = k + 3 * k3 * s_eq ** 2       # a stiffening spring, linearised about equilibrium
        eq = holder - axis * (cfg.spring.L0 + s_eq)
        x0 = float(np.dot(ball - eq, axis))
        v0 = float(np.dot(cfg.ball.p, axis)) / m
        return cls(m, k_lin, cfg.damping.b, gmag, cfg.spring.L0, x0, v0, tuple(axis), tuple(eq),
                   s_eq)

    # -- constants -----------------------------------------------------------------------
    @property
    def omega0(self) -> float:
        return math.sqrt(self.k / self.m)

    @property
    def gamma(self) -> float:
        return self.b / (2 * self.m)

    @property
    def regime(self) -> str:
        g, w = self.gamma, self.omega0
        if g == 0:
            return "undamped"
        if math.isclose(g, w, rel_tol=1e-9):
            return "critically damped"
        return "under-damped" if g < w else "over-damped"

    @property
    def omega_d(self) -> float:
        """Angular frequency of the (damped) oscillation; 0 when it does not oscillate."""
        if self.regime in ("critically damped", "over-damped"):
            return 0.0
        return math.sqrt(self.omega0 ** 2 - self.gamma ** 2)

    @property
    def period(self) -> float:
        return 2 * math.pi / self.omega_d if self.omega_d > 0 else math.inf

    @property
    def equilibrium_stretch(self) -> float:
        """Delta L = m g / k (the root of k s + k3 s^3 = m g for a stiffening spring)."""
        return self.m * self.g / self.k if self.s_eq is None else self.s_eq

    @property
    def amplitude(self) -> float:
        """Initial amplitude sqrt(x0^2 + (v0/omega0)^2) (of the undamped motion)."""
        return math.hypot(self.x0, self.v0 / self.omega0)

    @property
    def energy(self) -> float:
        """Oscillation energy about equilibrium, 1/2 k A^2 (= K + Us + Ug - their minimum)."""
        return 0.5 * self.k * self.amplitude ** 2

    @property
    def decay_rate(self) -> float:
        """Rate of the slowest exponential in x(t): gamma, or gamma - sqrt(gamma^2 - omega0^2)."""
        g, w = self.gamma, self.omega0
        return g if g <= w else g - math.sqrt(g * g - w * w)

    # -- motion --------------------------------------------------------------------------
    def x(self, t) -> np.ndarray:
        """Displacement from equilibrium along ``axis`` at times t (no drive)."""
        return self._xv(np.asarray(t, float))[0]

    def v(self, t) -> np.ndarray:
        return self._xv(np.asarray(t, float))[1]

    def _xv(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        g, w, x0, v0 = self.gamma, self.omega0, self.x0, self.v0
        regime = self.regime
        if regime in ("undamped", "under-damped"):
            wd = self.omega_d
            B = (v0 + g * x0) / wd
            c, s, e = np.cos(wd * t), np.sin(wd * t), np.exp(-g * t)
            x = e * (x0 * c + B * s)
            v = e * ((-g * x0 + B * wd) * c + (-x0 * wd - g * B) * s)
            return x, v
        if regime == "critically damped":
            B = v0 + g * x0
            e = np.exp(-g * t)
            return e * (x0 + B * t), e * (B - g * (x0 + B * t))
        q = math.sqrt(g * g - w * w)
        r1, r2 = -g + q, -g - q
        c2 = (v0 - r1 * x0) / (r2 - r1)
        c1 = x0 - c2
        e1, e2 = np.exp(r1 * t), np.exp(r2 * t)
        return c1 * e1 + c2 * e2, c1 * r1 * e1 + c2 * r2 * e2

    def envelope(self, t) -> np.ndarray:
        """A e^(-gamma t) for the under-damped motion."""
        if self.omega_d == 0:
            raise ValueError(f"a {self.regime} motion has no envelope")
        B = (self.v0 + self.gamma * self.x0) / self.omega_d
        return math.hypot(self.x0, B) * np.exp(-self.gamma * np.asarray(t, float))

    def mechanical_energy(self, t) -> np.ndarray:
        """1/2 m v^2 + 1/2 k x^2 about equilibrium at times t."""
        x, v = self._xv(np.asarray(t, float))
        return 0.5 * self.m * v ** 2 + 0.5 * self.k * x ** 2


def stiffening_stretch(k: float, k3: float, F: float) -> float:
    """The stretch s >= 0 at which k s + k3 s^3 = F (F >= 0): m g / k when k3 = 0."""
    if k3 == 0 or F == 0:
        return F / k
    roots = np.roots([k3, 0.0, k, -F])
    return float(min(r.real for r in roots if abs(r.imag) < 1e-12 and r.real >= 0))


SETTLED = 1e-3     # a transient counts as gone once it has decayed to this fraction


def drive_force_amplitude(cfg: Config) -> float:
    """F0 of the config's drive: the force's amplitude, or k A for a driven support."""
    d = cfg.drive
    if d.type == "support":
        return cfg.spring.k * d.amplitude
    return d.amplitude


def check_drive_along_motion(cfg: Config, command: str) -> None:
    """The closed forms are one-dimensional: the drive must act along the line of motion."""
    axis = np.asarray(Oscillator.from_config(cfg).axis)
    u = np.asarray(cfg.drive.direction, float)
    if abs(float(np.dot(u / np.linalg.norm(u), axis))) < 0.999:
        raise UserError(f"{cfg.source}: [drive] direction {list(cfg.drive.direction)} is not along "
                        f"the line of motion {[round(float(c), 6) for c in axis]} (against g); "
                        f"{command} compares with the one-dimensional closed forms")


def steady_amplitude(omega, omega0: float, gamma: float, F0: float, m: float) -> np.ndarray:
    """A(omega) = (F0/m) / sqrt((omega0^2 - omega^2)^2 + (2 gamma omega)^2)."""
    w = np.asarray(omega, float)
    return (F0 / m) / np.sqrt((omega0 ** 2 - w ** 2) ** 2 + (2 * gamma * w) ** 2)


def permanent_set(osc: Oscillator, yield_stretch: float) -> float | None:
    """How much L0 grows when the motion first stretches the spring past its elastic limit.

    Perfect plasticity: elastic until the stretch reaches ``yield_stretch`` (the
    closed form gives the speed v_y there), then the spring force stays at
    k s_y, so the ball slows under a constant net force m a = k s_y - m g and
    the drag -b v: it travels d = v_y/beta - (a/beta^2) ln(1 + beta v_y/a)
    (beta = b/m; d = v_y^2 / 2a without drag) before it stops, and L0 grows by d.
    None when the limit is below the weight's own stretch (the spring never holds).
    """
    s_eq = osc.equilibrium_stretch
    a = (osc.k * yield_stretch - osc.m * osc.g) / osc.m
    if a <= 0:
        return None
    t = np.linspace(0.0, 4 * math.pi / osc.omega0, 400_001)
    x = osc.x(t)
    reach = np.flatnonzero(s_eq - x >= yield_stretch)    # stretch = s_eq - x along the axis
    if not len(reach):
        return 0.0
    i = int(reach[0])
    if i == 0:
        v_y = abs(osc.v0)
    else:   # interpolate the crossing
        x_y = s_eq - yield_stretch
        f = (x[i - 1] - x_y) / (x[i - 1] - x[i])
        v = osc.v(t[i - 1:i + 1])
        v_y = abs(v[0] + f * (v[1] - v[0]))
    beta = osc.b / osc.m
    if beta == 0:
        return v_y ** 2 / (2 * a)
    return v_y / beta - (a / beta ** 2) * math.log1p(beta * v_y / a)


def rest_potential(cfg: Config, L0: float | None = None) -> float:
    """Us + Ug (J) with the ball at rest at equilibrium, the spring relaxed at ``L0``
    (default: the config's; a run that took a permanent set: its final length): the zero
    of the energy measured "about equilibrium" (K + Us + Ug - this)."""
    osc = Oscillator.from_config(cfg)
    axis = np.asarray(osc.axis)
    s = build.system(cfg)
    if L0 is not None:
        s.L0[:] = L0
    stretch = stiffening_stretch(cfg.spring.k, cfg.spring.k3, cfg.ball.m * osc.g)
    s.pos[1] = np.asarray(cfg.holder.pos) - axis * (float(s.L0[0]) + stretch)
    s.p[:] = 0.0
    e = physics.energies(s)
    return e.Us + e.Ug
