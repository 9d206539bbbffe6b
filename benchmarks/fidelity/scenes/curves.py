# curves: thin (radius 0) and thick (radius > 0), one coloured per point
from vpython import *
scene.width, scene.height = 480, 320
curve(pos=[vector(-4, -2, 0), vector(-2, 2, 0), vector(0, -2, 0), vector(2, 2, 0)], color=color.white)
curve(pos=[vector(-4, 0, 0), vector(-1, 1, 0), vector(1, 0.5, 1), vector(4, 1.5, 0)], radius=0.12, color=color.cyan)
c = curve(radius=0.08)
for i in range(60):
    t = i / 59
    c.append(pos=vector(-3 + 6 * t, -1.5 + 0.6 * sin(12 * t), 0), color=vector(t, 0.3, 1 - t))
