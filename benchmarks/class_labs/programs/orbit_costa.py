from visual import *
from visual.graph import *
# Lab 3: orbit of the earth -- costa
scene.range = 2.4e+11
G = 6.7e-11
Msun = 2e+30
mearth = 6e+24
sun = sphere(pos=vector(0, 0, 0), radius=7e+09, color=color.cyan)
earth = sphere(pos=vector(1.5e+11, 0, 0), radius=3e+09, color=color.green, make_trail=True, interval=5)
earth.p = mearth*vector(0, 3.288e+04, 0)
gdisplay(title="Energy", xtitle="t (s)", ytitle="J")
Kcurve = gcurve(color=color.red)
Ucurve = gcurve(color=color.blue)
Ecurve = gcurve(color=color.black)
dt = 43200
t = 0

while t < 1e9:
    rate(250)
    r = earth.pos - sun.pos
    Fgrav = -G*Msun*mearth/mag(r)**2*norm(r)
    earth.p = earth.p + Fgrav*dt
    earth.pos = earth.pos + earth.p/mearth*dt
    t = t + dt
    K = mag(earth.p)**2/(2*mearth)
    U = -G*Msun*mearth/mag(r)
    Kcurve.plot(pos=(t, K))
    Ucurve.plot(pos=(t, U))
    Ecurve.plot(pos=(t, K + U))
    if mag(r) < sun.radius:
        print("crashed at t =", t)
        break
