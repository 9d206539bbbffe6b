Web VPython 3.2
# Lab 2: projectile with air resistance (tennis ball) -- eriksen
scene.width = 1000
scene.height = 450
scene.center = vec(18, 6, 0)
scene.range = 22

ground = box(pos=vec(20, -0.3, 0), size=vec(50, 0.5, 6), color=color.green)
proj = sphere(pos=vec(0, 0, 0), radius=0.6, color=color.magenta)
attach_trail(proj, color=vec(1, 0.5, 0.3))
m = 0.057        # kg
C = 0.00096    # 1/2 rho Cd A, kg/m
g = vec(0, -9.8, 0)
theta = 35*pi/180
v = 20*vec(cos(theta), sin(theta), 0)
dt = 0.01
t = 0
top_printed = False

while proj.pos.y >= 0:
    rate(100)
    Fdrag = -C*mag(v)*v
    F = m*g + Fdrag
    v = v + F/m*dt
    proj.pos = proj.pos + v*dt
    if v.y < 0 and not top_printed:
        print("max height: " + proj.pos.y)
        top_printed = True
    t = t + dt

print("range:", proj.pos.x)
print("time: " + t)
