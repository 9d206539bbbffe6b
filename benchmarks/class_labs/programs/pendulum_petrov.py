GlowScript 3.2 VPython
# Lab 4: simple pendulum, L = 1.0 m -- petrov
scene.center = vec(0, -0.5, 0)
scene.range = 0.9
pivot = vec(0, 0, 0)
L = 1.0
g = 9.8
theta = 30*pi/180
omega = 0

ceiling = box(pos=pivot, size=vec(0.4, 0.02, 0.2), color=color.gray(0.7))
bob = sphere(pos=pivot + L*vec(sin(theta), -cos(theta), 0), radius=0.05, color=color.orange, make_trail=True, retain=200)
string = cylinder(pos=pivot, axis=bob.pos - pivot, radius=0.005)
graph(title="theta vs t", xtitle="t (s)", ytitle="theta (rad)")
thplot = gcurve(color=color.yellow)
dt = 0.01
t = 0

while True:
    rate(100)
    alpha = -(g/L)*sin(theta)
    omega = omega + alpha*dt
    theta = theta + omega*dt
    bob.pos = pivot + L*vec(sin(theta), -cos(theta), 0)
    string.axis = bob.pos - pivot
    thplot.plot(t, theta)
    t = t + dt
