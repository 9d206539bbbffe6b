"""The sensible range of a config's numbers, beyond each key's own: sizes, positions,
motions and the camera measured against the scene's own scale.

:mod:`springscene.config` checks each key alone against an absolute range (a mass
between 1e-30 and 1e6 kg, a stiffness between 1e-9 and 1e12 N/m, ...) wide enough
for the page's metre-scale scenes and the atoms of the model of matter alike. What
cannot be bounded absolutely is bounded here against the scene's length: the
spring's relaxed length L0 (a lattice's spacing d) and, for what is drawn, the
larger of L0 and the spring's length at the start. So that a number one typo away
from the intended one never gives a blank picture, a numpy error or a run that
blows up: one line naming the key and its allowed range.
"""

from __future__ import annotations

import math
from typing import Callable

import numpy as np

from . import build
from .errors import UserError
from .model.constants import BOLTZMANN
from .settings import Config

MAX_POSITION = 1e6       # of the scene's length: float64 still resolves 1e-10 of it
MAX_STRETCH = 1000       # of L0 (d): the start, the hanging weight, a kick, a drive (a soft
                         # spring's sag is tens of L0; what is drawn is checked apart: SEEN)
MAX_ATOM_STRETCH = 10    # of the spacing d: a kick, heat, a pull, gravity (a crystal, not
                         # a gas: atoms a few spacings off have left the model)
DRAWN = (1e-6, 10.0)     # sizes drawn (radii, thickness, holder) against the length
SEEN = 0.01              # the largest drawn size against the length: a few pixels at least
CAMERA_RANGE = (0.01, 10.0)    # [camera] range against the scene's size (its half-diagonal)
CAMERA_OFFSET = 10.0     # autoscaled: [camera] center at most this many sizes away
MAX_DAMPING = 1e6        # of critical damping, 2 sqrt(k m)
MAX_K3 = 1e6             # k3 L0^2 / k: the cubic force passes the linear one at L0/1000

Where = Callable[..., str]


def fmt(x: float) -> str:
    """A number as a message shows it: ``1e6``, ``0.015``, ``1.5e-10``."""
    s = f"{x:.3g}"
    mant, e, exp = s.partition("e")
    return f"{mant}e{int(exp)}" if e else s


def norm(v) -> float:
    """|v| without overflow or underflow for any finite components."""
    a = np.abs(np.asarray(v, float))
    top = float(a.max()) if a.size else 0.0
    if top == 0.0:
        return 0.0
    return top * float(np.sqrt(np.sum((a / top) ** 2)))


def _between(where: str, value: float, lo: float, hi: float, unit: str, why: str) -> None:
    if not lo <= value <= hi:
        raise UserError(f"{where} {fmt(value)} {unit}: it must be between {fmt(lo)} and "
                        f"{fmt(hi)} {unit} ({why})")


def _at_most(where: str, value: float, hi: float, unit: str, why: str) -> None:
    """``where`` is ``value`` ``unit`` (``"m from [holder] pos"``): at most ``hi``."""
    if value > hi:
        raise UserError(f"{where} {fmt(value)} {unit}: at most {fmt(hi)} {unit.split()[0]} "
                        f"({why})")


def check(cfg: Config, where: Where) -> None:
    """Every relative range of ``cfg``; ``where("section.key")`` names a key in a message."""
    if cfg.is_lattice:
        _lattice(cfg, where)
    else:
        _ball(cfg, where)
    _camera(cfg, where)


# ---- the page's ball on a spring --------------------------------------------------------

def spring_length(cfg: Config) -> float:
    """The spring's length at the start, |ball.pos - holder.pos| (m)."""
    return norm(np.subtract(cfg.ball.pos, cfg.holder.pos))


def _ball(cfg: Config, where: Where) -> None:
    s, L0 = cfg.spring, cfg.spring.L0
    _at_most(f"{where('holder.pos')} is", norm(cfg.holder.pos), MAX_POSITION * L0,
             "m from the origin",
             f"{fmt(MAX_POSITION)} times the spring's L0 = {fmt(L0)} m, where float64 still "
             "resolves its motion")
    D = spring_length(cfg)
    _at_most(f"{where('ball.pos')} is", D, MAX_STRETCH * L0, "m from [holder] pos",
             f"{MAX_STRETCH} times the spring's relaxed length L0 = {fmt(L0)} m")
    _motions(cfg, where)
    S = max(L0, D, reach(cfg))
    drawn = f"{fmt(DRAWN[0])} to {fmt(DRAWN[1])} times the spring's length, {fmt(S)} m"
    for key, value in (("spring.radius", s.radius), ("spring.thickness", s.thickness),
                       ("ball.radius", cfg.ball.radius)):
        if value != 0:
            _between(f"{where(key)} is", value, DRAWN[0] * S, DRAWN[1] * S, "m", drawn)
    for value in cfg.holder.size:
        _between(f"{where('holder.size')} has", value, DRAWN[0] * S, DRAWN[1] * S, "m", drawn)
    largest = max(max(cfg.holder.size), 2 * cfg.ball.radius, s.thickness or s.radius / 10)
    if largest < SEEN * S:
        raise UserError(f"{where('ball.radius')}, [holder] size and [spring] thickness: the "
                        f"largest, {fmt(largest)} m, is under {fmt(SEEN)} of the spring's "
                        f"length {fmt(S)} m: nothing would be seen")
    _damping(cfg, where, s.k, cfg.ball.m)


def _stretches(cfg: Config) -> tuple[float, float, float]:
    """How far the ball's start moves it from rest (m): the hanging weight's stretch mg/k,
    a starting momentum's amplitude |p|/sqrt(k m), and a drive's (its amplitude, or F/k)."""
    m, k, d = cfg.ball.m, cfg.spring.k, cfg.drive
    drive = 0.0 if d.type == "none" else d.amplitude / (1 if d.type == "support" else k)
    return m * norm(cfg.physics.g) / k, norm(cfg.ball.p) / math.sqrt(k * m), drive


def reach(cfg: Config) -> float:
    """About the longest the spring gets (m): L0 and those stretches together."""
    return cfg.spring.L0 + sum(_stretches(cfg))


def _motions(cfg: Config, where: Where) -> None:
    s, L0, k = cfg.spring, cfg.spring.L0, cfg.spring.k
    weight, kick, _ = _stretches(cfg)
    _at_most(f"{where('ball.m')}, [physics] g and [spring] k: the ball's weight stretches "
             "the spring by mg/k =",
             weight, MAX_STRETCH * L0, "m", f"{MAX_STRETCH} times L0 = {fmt(L0)} m")
    _at_most(f"{where('spring.k3')} is", s.k3, MAX_K3 * k / L0 ** 2, "N/m^3",
             f"{fmt(MAX_K3)} k/L0^2: the cubic force would pass the linear one at a stretch "
             "under L0/1000")
    _at_most(f"{where('ball.p')} gives an amplitude |p|/sqrt(k m) =", kick,
             MAX_STRETCH * L0, "m", f"{MAX_STRETCH} times L0 = {fmt(L0)} m")
    d = cfg.drive
    if d.type != "none":
        why = (f"{MAX_STRETCH} times L0 = {fmt(L0)} m" if d.type == "support" else
               f"{MAX_STRETCH} k L0: the spring's force at a stretch of {MAX_STRETCH} L0")
        _at_most(f"{where('drive.amplitude')} is", d.amplitude,
                 MAX_STRETCH * L0 * (1 if d.type == "support" else k),
                 "m" if d.type == "support" else "N", why)


def _damping(cfg: Config, where: Where, k: float, m: float) -> None:
    critical = 2 * math.sqrt(k * m)
    _at_most(f"{where('damping.b')} is", cfg.damping.b, MAX_DAMPING * critical, "kg/s",
             f"{fmt(MAX_DAMPING)} times critical damping 2 sqrt(k m) = {fmt(critical)} kg/s")


# ---- a lattice of atoms -----------------------------------------------------------------

def _lattice(cfg: Config, where: Where) -> None:
    lat = build.lattice(cfg)
    d, m, k = lat.d, lat.m, lat.k
    drawn = f"{fmt(DRAWN[0])} to {fmt(DRAWN[1])} times the spacing d = {fmt(d)} m"
    for key, value in (("atom.radius", cfg.atom.radius), ("bond.radius", cfg.bond.radius),
                       ("bond.thickness", cfg.bond.thickness)):
        if value:
            _between(f"{where(key)} is", value, DRAWN[0] * d, DRAWN[1] * d, "m", drawn)
    why = f"{MAX_ATOM_STRETCH} times the spacing d = {fmt(d)} m"
    _at_most(f"{where('start.kick')} gives an amplitude |kick|/sqrt(k/m) =",
             norm(cfg.start.kick) / math.sqrt(k / m), MAX_ATOM_STRETCH * d, "m", why)
    _at_most(f"{where('start.temperature')} gives a thermal amplitude sqrt(k_B T/k) =",
             math.sqrt(BOLTZMANN * cfg.start.temperature / k), MAX_ATOM_STRETCH * d, "m", why)
    face = lat.shape[1] * lat.shape[2]
    _at_most(f"{where('pull.force')} stretches each bond by F/(k n_face) =",
             cfg.pull.force / (k * face), MAX_ATOM_STRETCH * d, "m", why)
    _at_most(f"{where('physics.g')} stretches a bond by mg/k =",
             m * norm(cfg.physics.g) / k, MAX_ATOM_STRETCH * d, "m", why)
    _damping(cfg, where, k, m)


# ---- the camera -------------------------------------------------------------------------

def scene_box(cfg: Config) -> tuple[np.ndarray, np.ndarray]:
    """The smallest and largest corner of what is drawn at the start (m)."""
    if cfg.is_lattice:
        lat = build.lattice(cfg)
        r = max(cfg.atom.radius or 0.25 * lat.d, cfg.bond.radius or 0.15 * lat.d)
        half = (np.asarray(lat.shape, float) - 1) / 2 * lat.d + r
        return -half, half
    h, b = np.asarray(cfg.holder.pos, float), np.asarray(cfg.ball.pos, float)
    half, r, s = np.asarray(cfg.holder.size, float) / 2, cfg.ball.radius, cfg.spring
    wire = s.radius + (s.thickness / 2 if s.thickness > 0 else s.radius / 20)
    lo = np.min([h - half, b - r, np.minimum(h, b) - wire], axis=0)
    hi = np.max([h + half, b + r, np.maximum(h, b) + wire], axis=0)
    return lo, hi


def _camera(cfg: Config, where: Where) -> None:
    lo, hi = scene_box(cfg)
    # the scene's half-diagonal, or the spring's reach when the motion goes farther (a
    # soft spring sags metres below where it starts: a camera set on the motion is fine)
    size = max(norm(hi - lo) / 2, 0.0 if cfg.is_lattice else reach(cfg))
    middle = (lo + hi) / 2
    c = cfg.camera
    what = f"half its diagonal, {fmt(size)} m"
    if c.range is not None:
        _between(f"{where('camera.range')} is", c.range, CAMERA_RANGE[0] * size,
                 CAMERA_RANGE[1] * size, "m", f"{fmt(CAMERA_RANGE[0])} to "
                 f"{fmt(CAMERA_RANGE[1])} times the scene's size, {what}")
        w, h = cfg.scene.width, cfg.scene.height
        aspect = max(w / h, h / w)        # range is the half-size of the smaller side
        limit, why = size + 2 * c.range * aspect, f"beyond it [camera] range {fmt(c.range)} m " \
            "frames none of the scene"
    else:
        limit, why = CAMERA_OFFSET * size, f"{fmt(CAMERA_OFFSET)} times the scene's size, " \
            f"{what}: farther, autoscale shows it as a speck"
    off = norm(np.asarray(c.center, float) - middle)
    if off > limit:
        raise UserError(f"{where('camera.center')} [{', '.join(fmt(v) for v in c.center)}] is "
                        f"{fmt(off)} m from the scene's middle "
                        f"[{', '.join(fmt(v) for v in middle)}]: at most {fmt(limit)} m ({why})")
