from visual import *
from visual.graph import *
from random import random, seed
# Stands for VPython 6's examples/gas.py: hard spheres in a box, moved as numpy arrays,
# with a histogram of their speeds. Features: mag() of an N x 3 array, ghistogram
# (accumulate, average) beside a gcurve, a display(title=, center=), box edges as
# curves, less_equal/greater_equal masks, arrays of positions and momenta.
seed(7)
N = 12
L = 1.0
R = 0.05
scene = display(title="Box of atoms", width=400, height=400, center=(L/2, L/2, L/2))
speeds = gdisplay(x=0, y=400, width=400, height=240, xtitle='v', ytitle='N')
mean_line = gcurve(color=color.cyan)
counts = ghistogram(bins=arange(0, 3, 0.25), accumulate=1, average=1, color=color.red)
for edge in [[(0, 0, 0), (L, 0, 0), (L, L, 0), (0, L, 0), (0, 0, 0)],
             [(0, 0, L), (L, 0, L), (L, L, L), (0, L, L), (0, 0, L)]]:
    curve(pos=edge, color=(0.6, 0.6, 0.6))
atoms = []
start = []
for i in range(N):
    start.append((R + (L - 2*R)*random(), R + (L - 2*R)*random(), R + (L - 2*R)*random()))
    atoms.append(sphere(pos=start[-1], radius=R, color=color.yellow))
pos = array(start)
p = array([(random() - 0.5, random() - 0.5, random() - 0.5) for i in range(N)])
m = 1.0
dt = 0.02
t = 0
while t < 1:
    rate(50)
    v = mag(p/m)
    counts.plot(data=v)
    mean_line.plot(pos=(t, v.mean()))
    pos = pos + (p/m)*dt
    low = less_equal(pos, R)
    p = p - p*low + abs(p*low)
    high = greater_equal(pos, L - R)
    p = p - p*high - abs(p*high)
    for i in range(N):
        atoms[i].pos = pos[i]
    t += dt
