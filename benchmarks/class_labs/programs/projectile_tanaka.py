GlowScript 3.2 VPython
# Lab 2: projectile with air resistance (soccer ball) -- tanaka
scene.width = 900
scene.height = 400
scene.center = vec(18, 6, 0)
scene.range = 22

ground = box(pos=vec(20, -0.3, 0), size=vec(50, 0.5, 6), color=color.green)
ball = sphere(pos=vec(0, 0, 0), radius=0.6, color=color.magenta)
attach_trail(ball, color=color.green)
m = 0.43        # kg
C = 0.01072    # 1/2 rho Cd A, kg/m
g = vec(0, -9.8, 0)
theta = 40*pi/180
v = 18*vec(cos(theta), sin(theta), 0)
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
print("time: " + t)
