from visual import *
# Stands for VPython 6's examples/bounce2.py: a ball with momentum rattling in a room
# of walls. Features: boxes sized by length/height/width with RGB tuple colours, a
# sphere's own mass and p attributes, chained comparisons on ball.x/.y/.z, flipping
# one component of a vector attribute.
half = 3.0
wall = 0.2
walls = [box(pos=(half, 0, 0), length=wall, height=2*half, width=2*half, color=color.magenta),
         box(pos=(-half, 0, 0), length=wall, height=2*half, width=2*half, color=color.magenta),
         box(pos=(0, -half, 0), length=2*half, height=wall, width=2*half, color=(0.2, 0.6, 1)),
         box(pos=(0, 0, -half), length=2*half, height=2*half, width=wall, color=(0.8, 0.8, 0.8))]
ball = sphere(color=color.yellow, radius=0.5)
ball.mass = 2.0
ball.p = vector(0.9, -0.6, 0.4)
limit = half - wall/2 - ball.radius
dt = 0.2
t = 0
while t < 40:
    rate(50)
    ball.pos = ball.pos + (ball.p/ball.mass)*dt
    if not (limit > ball.x > -limit):
        ball.p.x = -ball.p.x
    if not (limit > ball.y > -limit):
        ball.p.y = -ball.p.y
    if not (limit > ball.z > -limit):
        ball.p.z = -ball.p.z
    t = t + dt
