from visual import *
# Stands for VPython 6's examples/lorenz.py, here with Roessler's equations: a curve
# grown point by point, coloured by speed. Features: curve(color=, radius=) with
# append(pos=, color=) per point, a grid of boxes from arange, a vector's components as
# y[0], y[1], y[2], clip() of a one-item list, `for t in arange(...)` under rate().
scene.title = "Roessler attractor"
scene.center = vector(0, -1, 3)
scene.forward = (0, 0.6, -1)
path = curve(color=color.white, radius=0.08)
for x in arange(-10, 11, 5):
    box(pos=(x, 0, -0.5), axis=(0, 20, 0), height=0.1, width=0.1, color=(0.5, 0.5, 0.5))
dt = 0.02
y = vector(1, 1, 0)
for t in arange(0, 30, dt):
    dydt = vector(-y[1] - y[2],
                  y[0] + 0.2*y[1],
                  0.2 + y[2]*(y[0] - 5.7))
    y = y + dydt*dt
    c = clip([mag(dydt)*0.1], 0, 1)[0]
    path.append(pos=y, color=(c, 1 - c, 0.5))
    rate(500)
print(len(arange(0, 30, dt)), y)
