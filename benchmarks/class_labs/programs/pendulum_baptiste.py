from visual import *
from visual.graph import *
# Lab 4: simple pendulum, L = 1.2 m -- baptiste
scene.center = vector(0, -0.6, 0)
scene.range = 1.08
pivot = vector(0, 0, 0)
L = 1.2
g = 9.8
theta = 20*pi/180
omega = 0

ceiling = box(pos=pivot, size=vector(0.4, 0.02, 0.2), color=color.gray(0.7))
mass = sphere(pos=pivot + L*vector(sin(theta), -cos(theta), 0), radius=0.05, color=vector(0.6, 0.2, 0.9), make_trail=True, retain=200)
string = cylinder(pos=pivot, axis=mass.pos - pivot, radius=0.005)
gdisplay(title="theta vs t", xtitle="t (s)", ytitle="theta (rad)")
thplot = gcurve(color=vector(1, 0.5, 0.3))
dt = 0.01
t = 0

while t < 20:
    rate(100)
    alpha = -(g/L)*sin(theta)
    omega = omega + alpha*dt
    theta = theta + omega*dt
    mass.pos = pivot + L*vector(sin(theta), -cos(theta), 0)
    string.axis = mass.pos - pivot
    thplot.plot(pos=(t, theta))
    t = t + dt
