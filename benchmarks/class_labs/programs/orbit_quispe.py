from vpython import *
# Lab 3: orbit of the moon -- quispe
scene.range = 8.19e+07
G = 6.7e-11
Mearth = 6e+24
mmoon = 7.3e+22
earth = sphere(pos=vector(0, 0, 0), radius=6.4e+06, color=color.cyan)
moon = sphere(pos=vector(5.12e+07, 0, 0), radius=1.5e+06, color=color.red, make_trail=True)
moon.p = mmoon*vector(0, 2242, 0)
graph(title="Energy", xtitle="t (s)", ytitle="J")
Kcurve = gcurve(color=color.red, label="K")
Ucurve = gcurve(color=color.blue, label="U")
Ecurve = gcurve(color=color.black, label="K + U")
dt = 34
t = 0

while t < 1e9:
    rate(1000)
    r = moon.pos - earth.pos
    Fgrav = -G*Mearth*mmoon/mag(r)**2*norm(r)
    moon.p = moon.p + Fgrav*dt
    moon.pos = moon.pos + moon.p/mmoon*dt
    t = t + dt
    K = mag(moon.p)**2/(2*mmoon)
    U = -G*Mearth*mmoon/mag(r)
    Kcurve.plot(t, K)
    Ucurve.plot(t, U)
    Ecurve.plot(t, K + U)
    if mag(r) < earth.radius:
        print("crashed at t =", t)
        break
