# opacity 0.5 objects in front of opaque ones
from vpython import *
scene.width, scene.height = 480, 320
scene.background = color.white
sphere(pos=vector(-2.6, 0.6, -1.5), radius=1, color=color.red)
box(pos=vector(-1.5, 0, 0.8), size=vector(2, 1.5, 0.5), color=color.blue, opacity=0.5)
cylinder(pos=vector(1, -1, -1), axis=vector(0, 2, 0), radius=0.8, color=color.green)
sphere(pos=vector(2, 0.2, 1), radius=1, color=color.yellow, opacity=0.5)
box(pos=vector(0, -2, 0), size=vector(6, 0.3, 2), color=color.gray(0.5), opacity=0.3)
