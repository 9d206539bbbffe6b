from visual import *
from random import random, randrange, seed
# Stands for VPython 6's examples/randombox.py: a cloud of random boxes in a wire cube.
# Features: boxes from a function with randrange sizes and random() RGB tuples, a wire
# frame as one curve grown with append(pos=), an arrow with shaftwidth=, a tilted
# cylinder, a coil curve from arange with cos/sin.
seed(11)

def scatter_box():
    box(pos=vector(randrange(-20, 20), randrange(-20, 20), randrange(-20, 20)),
        length=randrange(1, 5), height=randrange(1, 5), width=randrange(1, 5),
        color=(random(), random(), random()))

def wire_square(s):
    c = curve(color=color.white, radius=0.3)
    for pt in [(-s, -s, 0), (s, -s, 0), (s, s, 0), (-s, s, 0), (-s, -s, 0)]:
        c.append(pos=pt)
    return c

scene.title = "Scattered boxes"
edge = wire_square(25.)
n = 0
while n < 40:
    scatter_box()
    n = n + 1
arrow(axis=(0, 8, 0), shaftwidth=2, color=color.red)
disk = cylinder(pos=(10, 10, -10), axis=(1, 0, 1), radius=3, color=(0.3, 0.3, 1))
coil = curve(color=(1, 0.7, 0.1), radius=0.3)
turns = arange(0, 6*pi, pi/8)
for a in turns:
    coil.append(pos=(-12 + 2*cos(a), a/2 - 10, 2*sin(a)))
print(len(turns))
