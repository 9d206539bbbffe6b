GlowScript 3.2 VPython
# Lab 4: simple pendulum, L = 1.0 m -- zhou
scene.center = vec(0, -0.5, 0)
scene.range = 0.9
pivot = vec(0, 0, 0)
L = 1.0
g = 9.8
theta = 20*pi/180
omega = 0

ceiling = box(pos=pivot, size=vec(0.4, 0.02, 0.2), color=color.gray(0.7))
ball = sphere(pos=pivot + L*vec(sin(theta), -cos(theta), 0), radius=0.05, color=color.yellow)
string = cylinder(pos=pivot, axis=ball.pos - pivot, radius=0.005)
graph(title="theta vs t", xtitle="t (s)", ytitle="theta (rad)")
thplot = gcurve(color=color.cyan)
dt = 0.01
t = 0

while True:
    rate(100)
    alpha = -(g/L)*sin(theta)
    omega = omega + alpha*dt
    theta = theta + omega*dt
    ball.pos = pivot + L*vec(sin(theta), -cos(theta), 0)
    string.axis = ball.pos - pivot
    thplot.plot(pos=(t, theta))
    t = t + dt
