"""A ball bouncing inside a box: elastic walls, gravity, a see-through front."""
from vpython import *

scene.title = "A ball bouncing in a box"
scene.background = color.gray(0.15)
scene.forward = vector(-0.4, -0.3, -1)

side = 4.0
thk = 0.3
s2 = 2 * side - thk
s3 = 2 * side + thk
walls = [
    box(pos=vector(side, 0, 0), size=vector(thk, s2, s3), color=color.red),
    box(pos=vector(-side, 0, 0), size=vector(thk, s2, s3), color=color.red),
    box(pos=vector(0, -side, 0), size=vector(s3, thk, s3), color=color.blue),
    box(pos=vector(0, side, 0), size=vector(s3, thk, s3), color=color.blue),
    box(pos=vector(0, 0, -side), size=vector(s3, s3, thk), color=color.gray(0.7)),
]
ball = sphere(color=color.green, radius=0.4, make_trail=True, retain=200,
              trail_radius=0.05)
ball.mass = 1.0
ball.p = vector(-0.15, -0.23, +0.27) * 30
g = vector(0, -9.8, 0)
limit = side - thk / 2 - ball.radius

dt = 0.005
while True:
    rate(200)
    ball.p = ball.p + ball.mass * g * dt
    ball.pos = ball.pos + (ball.p / ball.mass) * dt
    if not -limit < ball.pos.x < limit:
        ball.p.x = -ball.p.x
    if not -limit < ball.pos.y < limit:
        ball.p.y = -ball.p.y
    if not -limit < ball.pos.z < limit:
        ball.p.z = -ball.p.z
