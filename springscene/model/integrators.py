"""Time integrators for the momentum principle, and the steps at which they stay stable.

Each integrator advances positions ``x`` and momenta ``p`` by one step ``h``.
Forces come in two parts: ``f(x, t)``, the conservative and driving forces
(springs, gravity, a drive), and linear drag ``-beta p`` with ``beta = b/m`` per
node (None for no drag). Each returns ``(x, p, heat)``, ``heat`` being the
kinetic energy the drag took out during the step, computed from the very
impulses applied, so ``K + Us + Ug + E_thermal`` changes only by the integrator's
own error.

- ``euler``: x and p both from the old state, drag included (energy grows).
- ``euler-cromer``: the page's: p first, then x with the new p (symplectic Euler).
- ``verlet``: velocity Verlet: a half kick, a drift, a half kick (second order).
- ``rk4``: the classical fourth-order Runge-Kutta, drag included.

In the kicks of Euler-Cromer and Verlet the drag acts on the mean of the old and
new momentum (the trapezoidal rule, solved exactly since it is linear):
``p' = (p (1 - beta h/2) + F h) / (1 + beta h/2)``. This keeps their accuracy
with damping (the page's explicit ``-b p/m`` would shift the damped frequency
at first order in b dt), makes the heat never negative, and never lets drag
alone blow up, so over-damped motion is stable at any step. Without drag the
kick is the page's ``p = p + Fnet*dt``, bit for bit.

Nothing here knows about springs: :mod:`springscene.model.physics` supplies ``f``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable

import numpy as np

Force = Callable[[np.ndarray, float], np.ndarray]


def _heat(Fd: np.ndarray, p0: np.ndarray, p1: np.ndarray, m, h: float) -> float:
    """Kinetic energy a drag impulse ``Fd*h`` removed while p went from p0 to p1.

    The change of K = |p|^2/2m is h F . (p0 + p1) / 2m exactly, so the drag's
    share is this.
    """
    return -h * float(np.sum(Fd * (p0 + p1) / (2.0 * m)))


def kick(p, F, beta, m, h: float):
    """p' = p + (F - beta (p + p')/2) h, solved for p'; returns (p', heat)."""
    if beta is None:
        return p + F * h, 0.0
    c = beta * (h / 2)
    p1 = (p * (1 - c) + F * h) / (1 + c)
    return p1, _heat(-beta * (p + p1) / 2, p, p1, m, h)


def euler(x, p, m, t, h, f: Force, beta=None):
    F = f(x, t)
    if beta is None:
        return x + (p / m) * h, p + F * h, 0.0
    Fd = -beta * p
    p1 = p + (F + Fd) * h
    return x + (p / m) * h, p1, _heat(Fd, p, p1, m, h)


def euler_cromer(x, p, m, t, h, f: Force, beta=None):
    p1, heat = kick(p, f(x, t), beta, m, h)     # the page's  p = p + Fnet*dt
    return x + (p1 / m) * h, p1, heat            # pos = pos + (p/m)*dt


def verlet(x, p, m, t, h, f: Force, beta=None):
    ph, heat1 = kick(p, f(x, t), beta, m, h / 2)
    x1 = x + (ph / m) * h
    p1, heat2 = kick(ph, f(x1, t + h), beta, m, h / 2)
    return x1, p1, heat1 + heat2


def rk4(x, p, m, t, h, f: Force, beta=None):
    def rates(xs, ps, ts):
        F = f(xs, ts)
        v = ps / m
        if beta is None:
            return v, F, 0.0
        Fd = -beta * ps
        return v, F + Fd, -float(np.sum(Fd * v))

    v1, F1, q1 = rates(x, p, t)
    v2, F2, q2 = rates(x + v1 * (h / 2), p + F1 * (h / 2), t + h / 2)
    v3, F3, q3 = rates(x + v2 * (h / 2), p + F2 * (h / 2), t + h / 2)
    v4, F4, q4 = rates(x + v3 * h, p + F3 * h, t + h)
    x1 = x + (v1 + 2 * v2 + 2 * v3 + v4) * (h / 6)
    p1 = p + (F1 + 2 * F2 + 2 * F3 + F4) * (h / 6)
    return x1, p1, (q1 + 2 * q2 + 2 * q3 + q4) * (h / 6)


EULER_MAX_GROWTH_PER_PERIOD = 2.0


def leapfrog_frequency(omega, dt: float) -> np.ndarray:
    """The frequency Euler-Cromer and Verlet run a linear mode of frequency omega at:
    (2/dt) asin(omega dt / 2)."""
    return 2.0 / dt * np.arcsin(np.clip(np.asarray(omega) * dt / 2, -1, 1))


@dataclass(frozen=True)
class Integrator:
    """Everything said about one integrator, in one place.

    ``name`` is the config's and the flag's word; ``label`` the figures' and tables';
    ``order`` its global order of accuracy; ``step`` the function; ``omega_dt_limit``
    the largest omega*dt at which an undamped mode stays bounded (None: never, Euler
    amplifies every mode); ``rule`` the words a refusal uses; ``mode_frequency(omega,
    dt)`` the frequency it runs an undamped linear mode at, where known in closed form.
    """

    name: str
    label: str
    order: int
    step: Callable
    omega_dt_limit: float | None
    rule: str
    mode_frequency: Callable[[np.ndarray, float], np.ndarray] | None = None


INTEGRATORS: dict[str, Integrator] = {i.name: i for i in (
    Integrator("euler", "Euler", 1, euler, None,
               f"grows the amplitude more than {EULER_MAX_GROWTH_PER_PERIOD:g}x per period"),
    Integrator("euler-cromer", "Euler-Cromer", 1, euler_cromer, 2.0, "needs omega*dt < 2",
               leapfrog_frequency),
    Integrator("verlet", "Verlet", 2, verlet, 2.0, "needs omega*dt < 2", leapfrog_frequency),
    Integrator("rk4", "RK4", 4, rk4, 2 * math.sqrt(2), "needs omega*dt < 2.83"),
)}
DEFAULT = "euler-cromer"      # the page's
NAMES = tuple(INTEGRATORS)
STEPPERS = {name: i.step for name, i in INTEGRATORS.items()}
ORDER = {name: i.order for name, i in INTEGRATORS.items()}


# ---- stability ----------------------------------------------------------------------------

def amplification(name: str, omega, gamma, h: float) -> np.ndarray:
    """One step of ``name`` on x'' = -omega^2 x - 2 gamma x' as (..., 2, 2) matrices on (x, v).

    Computed by running the integrator itself on the two basis states, so it is
    exactly the map the simulation applies to a linear mode.
    """
    w2 = np.asarray(omega, dtype=float) ** 2
    g2 = 2 * np.asarray(gamma, dtype=float)
    w2, g2 = np.broadcast_arrays(w2, g2)

    def f(x, t):
        return -w2 * x

    cols = []
    for x0, v0 in ((1.0, 0.0), (0.0, 1.0)):
        x1, v1, _ = STEPPERS[name](np.full(w2.shape, x0), np.full(w2.shape, v0), 1.0, 0.0, h, f,
                                   g2)
        cols.append(np.stack([x1, v1], axis=-1))
    return np.stack(cols, axis=-1)


def growth(name: str, omega, gamma, h: float) -> np.ndarray:
    """Largest factor by which one step multiplies a linear mode (its spectral radius);
    infinite where a step overflows (a huge ``h``)."""
    with np.errstate(over="ignore", invalid="ignore"):
        a = amplification(name, omega, gamma, h)
    finite = np.isfinite(a).all(axis=(-2, -1))
    rho = np.abs(np.linalg.eigvals(np.where(finite[..., None, None], a, 0.0))).max(axis=-1)
    return np.where(finite, rho, np.inf)


def stable(name: str, omega, gamma, h: float) -> bool:
    """Whether ``h`` keeps every (omega, gamma) mode bounded.

    Euler-Cromer, Verlet and RK4 must not amplify any mode (spectral radius 1 at
    most; for an undamped mode that is omega*h < 2, 2 and 2.83). Euler amplifies
    every undamped mode, so it is allowed as long as the amplitude grows by less
    than ``EULER_MAX_GROWTH_PER_PERIOD`` per oscillation period.
    """
    rho = growth(name, omega, gamma, h)
    if name != "euler":
        return bool(np.all(rho <= 1.0 + 1e-12))
    w = np.asarray(omega, dtype=float) * np.ones_like(rho)
    steps_per_period = np.where(w > 0, 2 * math.pi / np.maximum(w * h, 1e-300), 1.0)
    with np.errstate(over="ignore"):
        per_period = np.exp(np.log(np.maximum(rho, 1e-300)) * np.minimum(steps_per_period, 1e6))
    return bool(np.all(per_period <= EULER_MAX_GROWTH_PER_PERIOD) and np.all(rho < 10))


def largest_stable_step(name: str, omega, gamma, h_hint: float) -> float:
    """The largest stable step (bisection on :func:`stable`)."""
    lo, hi = 0.0, max(h_hint, 1e-300)
    while stable(name, omega, gamma, hi) and hi < 1e6:
        lo, hi = hi, hi * 2
    while lo == 0.0 and hi > 1e-300:       # a hint far too large: come down by halves
        if stable(name, omega, gamma, hi / 2):
            lo = hi / 2
        else:
            hi /= 2
    for _ in range(60):
        mid = (lo + hi) / 2
        lo, hi = (mid, hi) if stable(name, omega, gamma, mid) else (lo, mid)
    return lo


def suggest_step(h_max: float) -> float:
    """A round step comfortably inside the stable range: 1, 2 or 5 x 10^n, at most h_max/2."""
    target = h_max / 2
    if not (target > 0 and math.isfinite(target)):     # absurd stiffness or mass: no round step
        return target
    exp = math.floor(math.log10(target))
    for mant in (5, 2, 1):
        if mant * 10.0 ** exp <= target:
            return mant * 10.0 ** exp
    return 10.0 ** (exp - 1)


def stability_problem(name: str, omega, gamma, dt: float, what: str) -> str | None:
    """Why ``dt`` would make integrator ``name`` blow up on modes (omega, gamma), with a
    step that would not; None when it is stable. ``what`` names omega's bound."""
    omega, gamma = np.unique(np.column_stack([np.ravel(omega), np.ravel(gamma)]), axis=0).T
    if stable(name, omega, gamma, dt):
        return None
    w, gm = float(omega.max()), float(gamma.max())
    h_max = largest_stable_step(name, omega, gamma, dt)
    damped = f", b/2m = {gm:.3g} /s" if gm > 0 else ""
    advice = (f"use dt <= {suggest_step(h_max):g} s" if h_max > 0 else
              "no time step is stable: the values are too large")
    return (f"dt = {dt:g} s is unstable for {name} ({what} = {w:.4g} rad/s, "
            f"omega*dt = {w * dt:.3g}{damped}; {name} {INTEGRATORS[name].rule}); {advice}")
