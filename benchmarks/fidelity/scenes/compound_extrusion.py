# a compound (box, sphere, cylinder) and an extrusion of a circle along a path
from vpython import *
scene.width, scene.height = 480, 320
scene.background = color.white
b = box(pos=vector(0, 0, 0), size=vector(2, 0.4, 1), color=color.blue)
s = sphere(pos=vector(0, 0.6, 0), radius=0.4, color=color.red)
c = cylinder(pos=vector(-1, 0, 0), axis=vector(0, 1.2, 0), radius=0.15, color=color.green)
robot = compound([b, s, c], pos=vector(-2, 0.3, 0))
robot.rotate(angle=0.5, axis=vector(0, 1, 0))
extrusion(path=[vector(1, -1, 0), vector(2, 0, 0), vector(3, -0.5, 0.5), vector(3.5, 1, 0)],
          shape=shapes.circle(radius=0.3), color=color.orange)
extrusion(path=paths.arc(radius=1.2, angle2=pi), shape=shapes.rectangle(width=0.3, height=0.2),
          pos=vector(-1, -1.6, 0), color=color.magenta)
