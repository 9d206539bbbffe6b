from vpython import *
# Lab 2: projectile with air resistance (baseball) -- xu
scene.width = 900
scene.height = 400
scene.center = vec(18, 6, 0)
scene.range = 22

ground = box(pos=vec(20, -0.3, 0), size=vec(50, 0.5, 6), color=color.green)
proj = sphere(pos=vec(0, 0, 0), radius=0.6, color=color.magenta, make_trail=True)
m = 0.145        # kg
C = 0.00121    # 1/2 rho Cd A, kg/m
g = vec(0, -9.8, 0)
theta = 35*pi/180
v = 24*vec(cos(theta), sin(theta), 0)
dt = 0.01
t = 0
ghost = sphere(pos=vec(0, 0, 0), radius=0.4, color=color.white, make_trail=True)
vg = v

while proj.pos.y >= 0:
    rate(100)
    Fdrag = -C*mag(v)*v
    F = m*g + Fdrag
    v = v + F/m*dt
    proj.pos = proj.pos + v*dt
    vg = vg + g*dt
    ghost.pos = ghost.pos + vg*dt
    t = t + dt

print("range:", proj.pos.x)
print("time:", t)
