"""The ball-and-spring model of a solid: a 4 x 4 x 4 crystal of atoms joined by springs.

The outer atoms are held; the inner ones start with random thermal kicks (a fixed
seed) and vibrate. Every atom is a sphere and every bond a helix, moved by the
same momentum-principle loop as the wiki's single spring.
"""
import random as rnd

from vpython import *

scene.title = "Ball and spring model of a solid"
scene.caption = "64 atoms, 144 bonds: k = 15 N/m, m = 0.1 kg, L0 = 0.1 m (no gravity)."
scene.background = color.white
scene.forward = vector(-0.5, -0.4, -1)

N, d, k, m, dt = 4, 0.1, 15.0, 0.1, 0.002
rnd.seed(7)
atoms = {}
for i in range(N):
    for j in range(N):
        for l in range(N):
            outer = i in (0, N - 1) or j in (0, N - 1) or l in (0, N - 1)
            a = sphere(pos=d * vector(i - 1.5, j - 1.5, l - 1.5), radius=0.018,
                       color=color.gray(0.55) if outer else color.red)
            a.fixed = outer
            a.p = vector(0, 0, 0) if outer else 0.02 * vector.random()
            atoms[i, j, l] = a

bonds = []
for (i, j, l), a in atoms.items():
    for di, dj, dl in ((1, 0, 0), (0, 1, 0), (0, 0, 1)):
        b = atoms.get((i + di, j + dj, l + dl))
        if b is not None:
            s = helix(pos=a.pos, axis=b.pos - a.pos, radius=0.006, thickness=0.002,
                      coils=6, color=color.cyan)
            bonds.append((a, b, s))

while True:
    rate(500)
    for a, b, s in bonds:
        L = b.pos - a.pos
        F = -k * (mag(L) - d) * norm(L)
        b.p = b.p + F * dt
        a.p = a.p - F * dt
    for a in atoms.values():
        if not a.fixed:
            a.pos = a.pos + (a.p / m) * dt
        else:
            a.p = vector(0, 0, 0)
    for a, b, s in bonds:
        s.pos = a.pos
        s.axis = b.pos - a.pos
