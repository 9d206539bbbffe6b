# points of several sizes and colours, pixels and world units
from vpython import *
scene.width, scene.height = 480, 320
scene.range = 4
p = points(radius=6, color=color.yellow)
for i in range(12):
    p.append(pos=vector(-4 + 0.7 * i, 1.5 + 0.3 * sin(i), 0))
points(pos=[vector(-2, -1, 0), vector(0, -1, 0), vector(2, -1, 0)], radius=12, color=color.cyan)
points(pos=[vector(-1, -2.5, 0), vector(1, -2.5, 0)], size_units='world', radius=0.4, color=color.red)
