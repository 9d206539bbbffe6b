"""A projectile with a trail: launched at 20 m/s, 40 degrees above the ground."""
from vpython import *

scene.title = "Projectile motion with a trail"
scene.caption = "v0 = 20 m/s at 40&deg;, g = 9.8 m/s&sup2;, no drag. The arrow is the velocity."
scene.center = vector(20, 5, 0)
scene.range = 22

ground = box(pos=vector(20, -0.25, 0), size=vector(44, 0.5, 6), color=color.green)
ball = sphere(pos=vector(0, 0.5, 0), radius=0.5, color=color.orange, make_trail=True,
              trail_color=color.yellow, retain=400)
v = 20 * vector(cos(radians(40)), sin(radians(40)), 0)
m = 0.2
ball.p = m * v
g = vector(0, -9.8, 0)
velocity = arrow(pos=ball.pos, axis=0.2 * v, color=color.cyan, shaftwidth=0.25)

dt = 0.01
t = 0
while ball.pos.y >= 0.5:
    rate(100)
    ball.p = ball.p + m * g * dt
    ball.pos = ball.pos + (ball.p / m) * dt
    velocity.pos = ball.pos
    velocity.axis = 0.2 * ball.p / m
    t = t + dt
label(pos=ball.pos + vector(0, 3, 0), text=f"range {ball.pos.x:.1f} m after {t:.2f} s",
      height=16, color=color.white)
