# autoscale during an animation: a projectile with a trail leaves the first view (the
# range grows as it goes), then the program ends. It starts once the page is drawing
# (sleep) and rate(15) lets every step reach the browser and the trail (see trail.py).
from vpython import *
scene.width, scene.height = 480, 320
scene.background = color.white
ground = box(pos=vector(0, -0.1, 0), size=vector(3, 0.2, 1), color=color.green)
ball = sphere(pos=vector(0, 0, 0), radius=0.3, color=color.blue, make_trail=True)
v = vector(6, 9, 0)
g = vector(0, -9.8, 0)
dt = 0.04
sleep(1)
while ball.pos.y >= 0:
    rate(15)
    v = v + g * dt
    ball.pos = ball.pos + v * dt
