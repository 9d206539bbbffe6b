from __future__ import division
from visual import *
# Stands for VPython 6's examples/texture_and_lighting.py: a ball with a texture made
# from an array rolls on a table under a swinging lamp. Features: materials.texture(
# data=an RGBA array, mapping=, interpolate=False), materials.wood and emissive,
# scene.lights = [] then distant_light and a local_light in a frame, scene.ambient from
# color.gray(), a frame rotated like a pendulum, ball.rotate for rolling.
checks = zeros([8, 8, 4], float)
for i in range(8):
    for j in range(8):
        checks[i][j] = (1, 1, 0, 1) if (i + j) % 2 else (0.2, 0.2, 1, 0.6)
pattern = materials.texture(data=checks, mapping="spherical", interpolate=False)
scene.forward = (-0.1, -0.3, -1)
table = box(pos=(0, -0.25, 0), size=(8, 0.5, 4), color=color.orange, material=materials.wood)
hanger = frame(pos=(0, 6, 0), axis=(0, -1, 0))
cord = curve(frame=hanger, pos=[(0, 0, 0), (3, 0, 0)])
bulb = sphere(frame=hanger, pos=(3, 0, 0), radius=0.15, color=color.white,
              material=materials.emissive)
scene.lights = []
scene.ambient = color.gray(0.3)
distant_light(direction=(4, 3, 5), color=color.gray(0.4))
local_light(frame=hanger, pos=(3, 0, 0), color=color.gray(0.5))
R = 1
ball = sphere(pos=(-2, R, 0), radius=R, material=pattern)
v = vector(1.5, 0, 0)
dt = 0.04
t = 0
while t < 2:
    rate(50)
    ball.pos += v*dt
    ball.rotate(axis=(0, 0, 1), angle=-v.x*dt/R)
    hanger.rotate(axis=(1, 0, 0), angle=0.02*cos(2*t))
    t += dt
