GlowScript 3.2 VPython
# Lab 2: projectile with air resistance (golf ball) -- horvat
scene.width = 800
scene.height = 450
scene.center = vec(18, 6, 0)
scene.range = 22

ground = box(pos=vec(20, -0.3, 0), size=vec(50, 0.5, 6), color=color.green)
proj = sphere(pos=vec(0, 0, 0), radius=0.6, color=color.orange)
path = curve(color=color.cyan)
m = 0.046        # kg
C = 0.00039    # 1/2 rho Cd A, kg/m
g = vec(0, -9.8, 0)
theta = 50*pi/180
v = 22*vec(cos(theta), sin(theta), 0)
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
    path.append(pos=proj.pos)
    vg = vg + g*dt
    ghost.pos = ghost.pos + vg*dt
    t = t + dt

print("range:", proj.pos.x)
print("time: " + t)
