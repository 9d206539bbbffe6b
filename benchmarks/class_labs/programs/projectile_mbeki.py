GlowScript 3.2 VPython
# Lab 2: projectile with air resistance (golf ball) -- mbeki
scene.width = 1000
scene.height = 450
scene.center = vec(18, 6, 0)
scene.range = 22

ground = box(pos=vec(20, -0.3, 0), size=vec(50, 0.5, 6), color=color.green)
ball = sphere(pos=vec(0, 0, 0), radius=0.6, color=vec(1, 0.5, 0.3))
path = curve(color=color.orange)
m = 0.046        # kg
C = 0.00039    # 1/2 rho Cd A, kg/m
g = vec(0, -9.8, 0)
theta = 55*pi/180
v = 24*vec(cos(theta), sin(theta), 0)
dt = 0.01
t = 0
graph(title="height", xtitle="t (s)", ytitle="y (m)")
yplot = gcurve(color=color.red)

while ball.pos.y >= 0:
    rate(100)
    Fdrag = -C*mag(v)*v
    F = m*g + Fdrag
    v = v + F/m*dt
    ball.pos = ball.pos + v*dt
    path.append(pos=ball.pos)
    yplot.plot(pos=(t, ball.pos.y))
    t = t + dt

print("range:", ball.pos.x)
print("time:", t)
