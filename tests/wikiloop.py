"""The wiki page's own loop (Model 14), line by line: the reference springscene's physics
is compared with, bit for bit."""

import math

import numpy as np


class vector:
    """VPython's vector arithmetic (vpython/vector.py), for the reference loop."""

    def __init__(self, x, y, z):
        self.x, self.y, self.z = float(x), float(y), float(z)

    def __add__(self, o):
        return vector(self.x + o.x, self.y + o.y, self.z + o.z)

    def __sub__(self, o):
        return vector(self.x - o.x, self.y - o.y, self.z - o.z)

    def __mul__(self, s):
        return vector(self.x * s, self.y * s, self.z * s)

    __rmul__ = __mul__

    def __truediv__(self, s):
        return vector(self.x / s, self.y / s, self.z / s)


def mag(v):
    return math.sqrt(v.x ** 2 + v.y ** 2 + v.z ** 2)


def norm(v):
    smag = mag(v)
    return v / smag if smag > 0 else vector(0, 0, 0)


def wiki_loop(n_steps, ball_pos, ball_p=(0, 0, 0), vector=vector, mag=mag, norm=norm):
    """The page's Model 14 loop, line by line (on any vector type with its mag and norm)."""
    holder_pos = vector(0, 0, 0)
    pos, p = vector(*ball_pos), vector(*ball_p)
    k, L0, m, g, dt = 15, 0.10, 0.10, vector(0, -9.8, 0), 0.01
    out = []
    for _ in range(n_steps):
        L = pos - holder_pos
        Fs = -k * (mag(L) - L0) * norm(L)
        Fg = m * g
        Fnet = Fs + Fg
        p = p + Fnet * dt
        pos = pos + (p / m) * dt
        out.append((pos.x, pos.y, pos.z, p.x, p.y, p.z))
    return np.array(out)
