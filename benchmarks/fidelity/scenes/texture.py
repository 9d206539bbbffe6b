# a textured sphere (the earth) beside a plain one
from vpython import *
scene.width, scene.height = 480, 320
earth = sphere(pos=vector(-1, 0, 0), radius=1.5, texture=textures.earth)
box(pos=vector(2.5, 0, 0), size=vector(1.5, 1.5, 1.5), texture=textures.wood)
