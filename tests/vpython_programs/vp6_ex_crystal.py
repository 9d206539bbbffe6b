from visual import *
from random import random, seed
# Stands for VPython 6's examples/crystal.py: atoms joined by helix springs, moved with
# numpy. Features: color.hsv_to_rgb((h, s, v)) with a tuple, helices between spheres,
# atoms' own p (an array) and neighbour lists, array(), sqrt(sum(square(r), -1)),
# in-place a.p += ... and a.pos += ..., .norm() and .mag of vectors.
seed(3)
L = 1.0
k = 1.0
m = 1.0
atoms = []
for n in range(4):
    atoms.append(sphere(pos=(n*L - 1.5*L, 0, 0), radius=0.2,
                        color=color.hsv_to_rgb((n/4.0, 1, 1))))
    atoms[-1].p = array((0.0, 0.0, 0.0))
atoms[0].p = array((0.2, 0.1*random(), 0.0))
walls = [vector(-2.5*L, 0, 0), vector(2.5*L, 0, 0)]
springs = []
for n in range(5):
    left = atoms[n - 1].pos if n > 0 else walls[0]
    right = atoms[n].pos if n < 4 else walls[1]
    springs.append(helix(pos=left, axis=right - left, radius=0.08, thickness=0.02,
                         color=(1, 0.5, 0)))
dt = 0.05
t = 0
while t < 3:
    rate(50)
    for n, a in enumerate(atoms):
        near = [walls[0] if n == 0 else atoms[n - 1].pos,
                walls[1] if n == 3 else atoms[n + 1].pos]
        r = array(near) - a.pos
        rmag = sqrt(sum(square(r), -1)).reshape(-1, 1)
        a.p += k*dt*sum((1 - L/rmag)*r, 0)
    for a in atoms:
        a.pos += a.p*dt/m
    for n, s in enumerate(springs):
        left = atoms[n - 1].pos if n > 0 else walls[0]
        right = atoms[n].pos if n < 4 else walls[1]
        s.pos = left
        s.axis = (right - left).mag*(right - left).norm()
    t += dt
