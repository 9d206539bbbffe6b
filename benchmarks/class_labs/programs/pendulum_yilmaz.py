from vpython import *
# Lab 4: simple pendulum, L = 0.75 m -- yilmaz
scene.center = vector(0, -0.375, 0)
scene.range = 0.675
pivot = vector(0, 0, 0)
L = 0.75
g = 9.8
theta = 45*pi/180
omega = 0

ceiling = box(pos=pivot, size=vector(0.4, 0.02, 0.2), color=color.gray(0.7))
bob = sphere(pos=pivot + L*vector(sin(theta), -cos(theta), 0), radius=0.05, color=color.yellow)
string = cylinder(pos=pivot, axis=bob.pos - pivot, radius=0.005)
graph(title="theta vs t", xtitle="t (s)", ytitle="theta (rad)")
thplot = gcurve(color=vec(0.6, 0.2, 0.9))
dt = 0.01
t = 0

while True:
    rate(100)
    alpha = -(g/L)*sin(theta)
    omega = omega + alpha*dt
    theta = theta + omega*dt
    bob.pos = pivot + L*vector(sin(theta), -cos(theta), 0)
    string.axis = bob.pos - pivot
    thplot.plot(pos=(t, theta))
    t = t + dt
