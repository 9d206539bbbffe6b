from vpython import *
# Lab 3: orbit of the sat -- santos
scene.range = 8.19e+07
G = 6.7e-11
Mearth = 6e+24
msat = 1000
earth = sphere(pos=vector(0, 0, 0), radius=6.4e+06, color=vec(0.6, 0.2, 0.9))
sat = sphere(pos=vector(5.12e+07, 0, 0), radius=1.5e+06, color=vec(0.6, 0.2, 0.9))
sat.p = msat*vector(0, 2242, 0)
attach_trail(sat, color=vec(0.6, 0.2, 0.9))
graph(title="Energy", xtitle="t (s)", ytitle="J")
Kcurve = gcurve(color=color.red, label="K")
Ucurve = gcurve(color=color.blue, label="U")
Ecurve = gcurve(color=color.black, label="K + U")
dt = 34
t = 0

while True:
    rate(1000)
    r = sat.pos - earth.pos
    Fgrav = -G*Mearth*msat/mag(r)**2*norm(r)
    sat.p = sat.p + Fgrav*dt
    sat.pos = sat.pos + sat.p/msat*dt
    t = t + dt
    K = mag(sat.p)**2/(2*msat)
    U = -G*Mearth*msat/mag(r)
    Kcurve.plot(t, K)
    Ucurve.plot(pos=(t, U))
    Ecurve.plot(pos=(t, K + U))
    if mag(r) < earth.radius:
        print("crashed at t =", t)
        break
