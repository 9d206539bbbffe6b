# pyramid, ellipsoid, ring and arrow on a white background
from vpython import *
scene.width, scene.height = 480, 320
scene.background = color.white
pyramid(pos=vector(-3.6, 0.8, 0), size=vector(1.6, 1.4, 1.4), color=color.blue)
ellipsoid(pos=vector(0, 0.8, 0), size=vector(2.2, 1.2, 1.0), color=color.red)
ring(pos=vector(3, 0.8, 0), axis=vector(1, 0.3, 0.4), radius=0.9, thickness=0.2, color=color.orange)
arrow(pos=vector(-4, -1.6, 0), axis=vector(3, 0.8, 0), color=color.green)
arrow(pos=vector(0.5, -2.2, 0), axis=vector(1.5, 1.2, 0.6), shaftwidth=0.3, color=color.purple)
pyramid(pos=vector(3, -1.6, 0), axis=vector(0.5, 1.2, 0.3), size=vector(1.4, 1.0, 1.0), color=color.cyan)
