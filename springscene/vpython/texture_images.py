"""The pictures behind VPython's built-in ``textures``, made here: numpy, seeded, no download.

GlowScript's own images (``flower_texture.jpg``, ...) are photographs fetched
from the web; springscene draws off-line, so each name gets a picture made
from noise that reads as what the name says: wood grain, granite speckle,
gravel, brushed metal, rock, rough, a rug, cobble stones, stucco, flowers. They
are deterministic (one seed per name), seamless (periodic noise, so a repeated
texture has no visible joint), made once per process (:func:`builtin_image`
caches them) and take a few tens of milliseconds each.

``earth`` is a map: Natural Earth I shaded relief (public domain), downsampled,
shipped as ``data/earth.jpg`` (see ``data/README.md``), equirectangular with
longitude -180 at the left edge and north at the top, as GlowScript's.

Every image is ``(height, width, 3)`` uint8 with row 0 at the top of the
picture; the renderer puts the top at texture v = 1 as WebGL's
``UNPACK_FLIP_Y_WEBGL`` does (GlowScript ``WebGLRenderer.js``
``handleLoadedTexture``).
"""

from __future__ import annotations

import functools
import zlib
from importlib import resources

import numpy as np

SIZE = 512                  # px: each generated texture is SIZE x SIZE
EARTH_FILE = "earth.jpg"    # in springscene/vpython/data


# -- noise --------------------------------------------------------------------------------

def _rng(name: str) -> np.random.Generator:
    return np.random.default_rng(zlib.crc32(name.encode()))


def _unit(a: np.ndarray) -> np.ndarray:
    """``a`` stretched to [0, 1]."""
    lo, hi = float(a.min()), float(a.max())
    return (a - lo) / (hi - lo if hi > lo else 1.0)


def noise(rng, n: int = SIZE, beta: float = 1.0, stretch=(1.0, 1.0), low: float = 1.0):
    """Seamless ``n x n`` noise in [0, 1] with a 1/f^beta spectrum.

    ``stretch`` = (along rows, along columns): a larger number there makes the
    noise finer in that direction (streaks run the other way). Frequencies
    below ``low`` cycles per picture are left out.
    """
    f = np.fft.fftfreq(n) * n
    fy, fx = np.meshgrid(f * stretch[0], f * stretch[1], indexing="ij")
    k = np.hypot(fx, fy)
    spectrum = np.fft.fft2(rng.standard_normal((n, n)))
    spectrum *= np.where(k < low, 0.0, 1.0 / np.maximum(k, 1.0) ** beta)
    return _unit(np.real(np.fft.ifft2(spectrum)))


def cells(rng, cells_across: int, n: int = SIZE):
    """Seamless Voronoi cells: (distance to the nearest seed, to the second, cell id).

    One jittered seed per grid cell; distances in cell widths.
    """
    jitter = 0.15 + 0.7 * rng.random((cells_across, cells_across, 2))
    y, x = (np.mgrid[0:n, 0:n] + 0.5) * (cells_across / n)
    ci, cj = np.floor(y).astype(int), np.floor(x).astype(int)
    d1 = np.full((n, n), np.inf)
    d2 = np.full((n, n), np.inf)
    ids = np.zeros((n, n), dtype=int)
    for di in (-1, 0, 1):
        for dj in (-1, 0, 1):
            ni, nj = ci + di, cj + dj
            wi, wj = ni % cells_across, nj % cells_across
            d = np.hypot(ni + jitter[wi, wj, 0] - y, nj + jitter[wi, wj, 1] - x)
            closer = d < d1
            d2 = np.where(closer, d1, np.minimum(d2, d))
            ids = np.where(closer, wi * cells_across + wj, ids)
            d1 = np.where(closer, d, d1)
    return d1, d2, ids


def _ramp(t: np.ndarray, *colours) -> np.ndarray:
    """Colours (0..1 RGB) blended along ``t`` in [0, 1], evenly spaced stops."""
    stops = np.asarray(colours, dtype=float)
    x = np.clip(t, 0, 1) * (len(stops) - 1)
    i = np.minimum(np.floor(x).astype(int), len(stops) - 2)
    f = (x - i)[..., None]
    return stops[i] * (1 - f) + stops[i + 1] * f


def _to_uint8(rgb: np.ndarray) -> np.ndarray:
    return np.clip(np.rint(rgb * 255), 0, 255).astype(np.uint8)


# -- the pictures -------------------------------------------------------------------------

def wood(rng) -> np.ndarray:
    """Light planed wood: growth rings bent by slow noise, grain running left to right."""
    n = SIZE
    y = np.arange(n)[:, None] / n
    bend = noise(rng, beta=2.0, stretch=(1.0, 4.0))
    rings = np.sin(2 * np.pi * (9 * y + 1.6 * bend)) * 0.5 + 0.5
    rings = rings ** 3
    grain = noise(rng, beta=0.8, stretch=(1.0, 24.0), low=4)
    t = 0.65 * rings + 0.35 * grain
    return _ramp(t, (0.86, 0.66, 0.42), (0.76, 0.54, 0.31), (0.55, 0.35, 0.18))


def wood_old(rng) -> np.ndarray:
    """Weathered grey-brown boards: four planks with dark joints and worn grain."""
    n = SIZE
    y = np.arange(n)[:, None] / n
    planks = 4
    in_plank = (y * planks) % 1.0
    shade = rng.uniform(-0.08, 0.08, planks)[np.floor(y * planks).astype(int) % planks]
    grain = noise(rng, beta=0.9, stretch=(1.0, 30.0), low=4)
    blotch = noise(rng, beta=1.8)
    t = 0.55 * grain + 0.3 * blotch + shade
    rgb = _ramp(t, (0.70, 0.64, 0.55), (0.52, 0.45, 0.36), (0.30, 0.25, 0.20))
    joint = np.exp(-((np.minimum(in_plank, 1 - in_plank) * n / planks) / 2.0) ** 2)
    return rgb * (1 - 0.75 * joint[..., None])


def granite(rng) -> np.ndarray:
    """Pink-grey granite: interlocked grains of feldspar, quartz and black mica."""
    d1, d2, ids = cells(rng, 72)
    minerals = np.array([(0.80, 0.58, 0.52), (0.70, 0.50, 0.46), (0.62, 0.60, 0.60),
                         (0.86, 0.84, 0.82), (0.16, 0.15, 0.15), (0.30, 0.28, 0.28)])
    kind = rng.choice(len(minerals), size=72 * 72, p=[0.3, 0.15, 0.2, 0.15, 0.12, 0.08])
    tone = 0.85 + 0.3 * rng.random(72 * 72)
    rgb = minerals[kind[ids]] * tone[ids][..., None]
    rgb *= (0.9 + 0.2 * noise(rng, beta=0.3, low=64))[..., None]
    return rgb * (0.75 + 0.25 * np.clip((d2 - d1) * 3, 0, 1))[..., None]


def gravel(rng) -> np.ndarray:
    """Small rounded pebbles of many greys and browns, dark between them."""
    d1, d2, ids = cells(rng, 24)
    palette = _ramp(rng.random(24 * 24), (0.42, 0.40, 0.38), (0.62, 0.56, 0.48),
                    (0.75, 0.72, 0.68), (0.50, 0.44, 0.36))
    edge = np.clip((d2 - d1) * 4.0, 0, 1)
    dome = np.clip(1.0 - 0.6 * d1, 0.4, 1.0)
    speck = 0.85 + 0.3 * noise(rng, beta=0.3, low=32)
    return palette[ids] * (edge * dome * speck)[..., None]


def metal(rng) -> np.ndarray:
    """Brushed steel: fine horizontal streaks on a light, slightly blue grey."""
    streaks = noise(rng, beta=0.7, stretch=(1.0, 40.0), low=2)
    sheen = noise(rng, beta=2.2)
    t = 0.6 * streaks + 0.4 * sheen
    return _ramp(t, (0.50, 0.52, 0.55), (0.72, 0.74, 0.77), (0.86, 0.87, 0.89))


def rock(rng) -> np.ndarray:
    """Grey-brown rock face: layered fractal noise with dark cracks."""
    body = noise(rng, beta=1.2)
    detail = noise(rng, beta=0.6, low=8)
    ridge = 1.0 - np.abs(2 * noise(rng, beta=1.6) - 1)
    crack = np.clip((ridge - 0.93) / 0.07, 0, 1)
    t = 0.6 * body + 0.4 * detail
    rgb = _ramp(t, (0.30, 0.27, 0.24), (0.50, 0.46, 0.41), (0.66, 0.62, 0.56))
    return rgb * (1 - 0.6 * crack[..., None])


def rough(rng) -> np.ndarray:
    """A rough, grainy light grey-beige surface (sandpaper, concrete)."""
    grain = noise(rng, beta=0.25, low=16)
    lumps = noise(rng, beta=1.0, low=4)
    t = 0.55 * grain + 0.45 * lumps
    return _ramp(t, (0.40, 0.38, 0.35), (0.66, 0.63, 0.58), (0.88, 0.86, 0.82))


def rug(rng) -> np.ndarray:
    """An oriental rug: red field, a central diamond medallion, blue and cream borders."""
    n = SIZE
    y, x = (np.mgrid[0:n, 0:n] + 0.5) / n * 2 - 1                 # -1..1
    edge = np.maximum(np.abs(x), np.abs(y))
    diamond = np.abs(x) + np.abs(y)
    red, navy, cream, gold = (0.62, 0.10, 0.10), (0.10, 0.14, 0.38), (0.90, 0.84, 0.68), \
        (0.85, 0.62, 0.20)
    rgb = np.empty((n, n, 3))
    rgb[:] = red
    motif = (np.cos(8 * np.pi * x) * np.cos(8 * np.pi * y)) > 0.6    # small diamonds
    rgb[motif & (edge < 0.72)] = (0.45, 0.06, 0.08)
    rgb[diamond < 0.62] = navy
    rgb[diamond < 0.52] = cream
    rgb[diamond < 0.42] = red
    rgb[(diamond < 0.22)] = gold
    rgb[(edge > 0.76) & (edge < 0.92)] = navy
    ring = (edge > 0.80) & (edge < 0.88) & (np.cos(20 * np.pi * (x + y)) > 0.3)
    rgb[ring] = cream
    rgb[(edge >= 0.72) & (edge <= 0.76)] = cream
    rgb[edge >= 0.92] = gold
    wear = 0.88 + 0.24 * noise(rng, beta=0.4, low=16)
    return rgb * wear[..., None]


def stones(rng) -> np.ndarray:
    """Cobble stones: large rounded stones of varied grey and tan set in dark mortar."""
    d1, d2, ids = cells(rng, 6)
    palette = _ramp(rng.random(36), (0.46, 0.44, 0.42), (0.64, 0.58, 0.50), (0.72, 0.70, 0.66))
    edge = np.clip((d2 - d1 - 0.05) * 6.0, 0, 1)
    dome = np.clip(1.1 - 0.5 * d1, 0.5, 1.0)
    surface = 0.8 + 0.35 * noise(rng, beta=0.9, low=8)
    rgb = palette[ids] * (dome * surface)[..., None]
    mortar = np.array([0.22, 0.21, 0.20])
    return rgb * edge[..., None] + mortar * (1 - edge[..., None])


def stucco(rng) -> np.ndarray:
    """Off-white stucco: soft blotches and small pits."""
    blotch = noise(rng, beta=1.4, low=2)
    pits = noise(rng, beta=0.3, low=32) > 0.82
    t = 0.8 * blotch
    rgb = _ramp(t, (0.80, 0.77, 0.71), (0.90, 0.88, 0.83), (0.96, 0.95, 0.91))
    rgb[pits] *= 0.82
    return rgb


def flower(rng) -> np.ndarray:
    """Flowers: a few large pink-magenta blooms with yellow hearts on green leaves."""
    n = SIZE
    leaves = noise(rng, beta=1.3)
    rgb = _ramp(leaves, (0.10, 0.28, 0.08), (0.22, 0.48, 0.14), (0.42, 0.62, 0.22))
    y, x = (np.mgrid[0:n, 0:n] + 0.5) / n
    for _ in range(7):
        cy, cx, r = rng.random(), rng.random(), rng.uniform(0.09, 0.17)
        petals = int(rng.integers(5, 8))
        turn = rng.uniform(0, 2 * np.pi)
        dy = (y - cy + 0.5) % 1.0 - 0.5                     # seamless: nearest copy
        dx = (x - cx + 0.5) % 1.0 - 0.5
        rho, phi = np.hypot(dx, dy) / r, np.arctan2(dy, dx) + turn
        outline = 0.55 + 0.45 * np.abs(np.cos(petals * phi / 2))
        petal = rho < outline
        shade = np.clip(1.15 - 0.5 * rho, 0, 1)[..., None]
        pink = np.array([0.93, 0.35, 0.62]) * shade + np.array([0.05, 0.05, 0.10]) * rho[..., None]
        rgb = np.where(petal[..., None], pink, rgb)
        rgb[rho < 0.22] = (0.98, 0.82, 0.20)
        rgb[(rho < 0.22) & (noise_dots(rho, phi))] = (0.80, 0.55, 0.10)
    return rgb


def noise_dots(rho: np.ndarray, phi: np.ndarray) -> np.ndarray:
    """Stamen dots in a flower's heart."""
    return (np.cos(14 * phi) * np.cos(40 * rho)) > 0.5


GENERATORS = {
    "flower": flower, "granite": granite, "gravel": gravel, "metal": metal, "rock": rock,
    "rough": rough, "rug": rug, "stones": stones, "stucco": stucco, "wood": wood,
    "wood_old": wood_old,
}
NAMES = tuple(sorted([*GENERATORS, "earth"]))


@functools.cache
def builtin_image(name: str) -> np.ndarray:
    """The picture of built-in texture ``name`` (``(h, w, 3)`` uint8, read-only), made once."""
    if name == "earth":
        image = earth()
    else:
        image = _to_uint8(GENERATORS[name](_rng(name)))
    image.setflags(write=False)
    return image


def earth() -> np.ndarray:
    """The Earth map shipped in package data (Natural Earth I, public domain)."""
    import imageio.v3 as iio  # noqa: PLC0415  heavy: imageio

    data = resources.files("springscene.vpython").joinpath("data", EARTH_FILE).read_bytes()
    image = np.asarray(iio.imread(data, extension=".jpg"))
    return np.ascontiguousarray(image[..., :3])


__all__ = ["builtin_image", "noise", "cells", "NAMES", "GENERATORS", "SIZE"]
