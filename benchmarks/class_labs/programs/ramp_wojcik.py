from vpython import *
# Lab 4: cart on a ramp, 7 degrees -- wojcik
angle = 7*pi/180
along = vector(cos(angle), sin(angle), 0)
scene.center = 1.5*along
scene.range = 1.7
ramp = box(pos=1.5*along - vector(0, 0.03, 0), axis=3*along, size=vector(3, 0.02, 0.3), color=color.gray(0.8))
cart = box(pos=vector(0, 0, 0), axis=0.2*along, size=vector(0.2, 0.06, 0.1), color=color.red)
m = 0.5
g = 9.8
mu = 0.0
s = 0.0
v = 2.0    # m/s up the ramp
graph(title="cart", xtitle="t (s)", ytitle="s (m), v (m/s)")
splot = gcurve(color=color.blue, label="s")
vplot = gcurve(color=color.red, label="v")
dt = 0.01
t = 0

while s >= 0:
    rate(100)
    a = -g*sin(angle) - mu*g*cos(angle)*(1 if v > 0 else -1)
    v = v + a*dt
    s = s + v*dt
    cart.pos = s*along
    splot.plot(t, s)
    vplot.plot(t, v)
    t = t + dt
print("back at the bottom after", t)
