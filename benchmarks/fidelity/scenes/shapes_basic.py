# sphere, box, cylinder and cone on the default black background
from vpython import *
scene.width, scene.height = 480, 320
sphere(pos=vector(-3, 0.8, 0), radius=0.9, color=color.red)
box(pos=vector(0, 0.8, 0), size=vector(1.6, 1.2, 1.0), color=color.green)
cylinder(pos=vector(2.2, 0.8, 0), axis=vector(1.6, 0, 0), radius=0.6, color=color.cyan)
cone(pos=vector(-3.8, -1.6, 0), axis=vector(1.4, 0.6, 0), radius=0.7, color=color.orange)
box(pos=vector(0.4, -1.6, 0), size=vector(2.4, 0.6, 1.2), axis=vector(1, 0.4, 0.3), color=color.magenta)
cylinder(pos=vector(2.6, -2.2, 0), axis=vector(0.4, 1.4, 0.5), radius=0.4, color=color.yellow)
