from visual import *
from visual.graph import *
# Lab 3: orbit of the earth -- lopez
scene.range = 2.4e+11
G = 6.7e-11
Msun = 2e+30
mearth = 6e+24
sun = sphere(pos=vector(0, 0, 0), radius=7e+09, color=color.yellow)
earth = sphere(pos=vector(1.5e+11, 0, 0), radius=3e+09, color=color.yellow, make_trail=True, interval=5)
earth.p = mearth*vector(0, 2.69e+04, 0)
gdisplay(title="distance", xtitle="time (s)", ytitle="|r| (m)")
rplot = gcurve(color=vector(0.6, 0.2, 0.9))
dt = 51840
t = 0

while t < 1e9:
    rate(250)
    r = earth.pos - sun.pos
    Fgrav = -G*Msun*mearth/mag(r)**2*norm(r)
    earth.p = earth.p + Fgrav*dt
    earth.pos = earth.pos + earth.p/mearth*dt
    t = t + dt
    rplot.plot(pos=(t, mag(r)))
    if mag(r) < sun.radius:
        print("crashed at t =", t)
        break
