from visual import *
from visual.graph import *
# Lab 2: projectile with air resistance (golf ball) -- fischer
scene.width = 1000
scene.height = 450
scene.center = vector(18, 6, 0)
scene.range = 22

ground = box(pos=vector(20, -0.3, 0), size=vector(50, 0.5, 6), color=color.green)
ball = sphere(pos=vector(0, 0, 0), radius=0.6, color=color.orange, make_trail=True)
m = 0.046        # kg
C = 0.00039    # 1/2 rho Cd A, kg/m
g = vector(0, -9.8, 0)
theta = 55*pi/180
v = 20*vector(cos(theta), sin(theta), 0)
dt = 0.01
t = 0

while ball.pos.y >= 0:
    rate(100)
    Fdrag = -C*mag(v)*v
    F = m*g + Fdrag
    v = v + F/m*dt
    ball.pos = ball.pos + v*dt
    t = t + dt

print("range:", ball.pos.x)
print("time:", t)
