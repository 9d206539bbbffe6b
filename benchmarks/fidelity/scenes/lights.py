# shininess 0, 0.6 (default) and 1, a local light and an extra distant light
from vpython import *
scene.width, scene.height = 480, 320
sphere(pos=vector(-3, 0, 0), radius=1.1, color=color.white, shininess=0)
sphere(pos=vector(0, 0, 0), radius=1.1, color=vector(0.9, 0.6, 0.3))
sphere(pos=vector(3, 0, 0), radius=1.1, color=color.cyan, shininess=1)
box(pos=vector(0, -2.2, 0), size=vector(8, 0.3, 2), color=vector(0.5, 0.5, 0.6))
local_light(pos=vector(0, 2.5, 2.5), color=vector(0.5, 0.2, 0.2))
distant_light(direction=vector(-0.5, 0.2, 0.8), color=vector(0.1, 0.1, 0.3))
