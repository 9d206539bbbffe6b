GlowScript 3.2 VPython
# Lab 3: orbit of the earth -- kowalski
scene.range = 2.4e+11
G = 6.7e-11
Msun = 2e+30
mearth = 6e+24
sun = sphere(pos=vec(0, 0, 0), radius=7e+09, color=vec(0.6, 0.2, 0.9))
earth = sphere(pos=vec(1.5e+11, 0, 0), radius=3e+09, color=color.orange)
earth.p = mearth*vec(0, 2.989e+04, 0)
attach_trail(earth, color=vec(0.6, 0.2, 0.9))
graph(title="distance", xtitle="time (s)", ytitle="|r| (m)")
rplot = gcurve(color=color.yellow)
dt = 51840
t = 0

while t < 1e9:
    rate(200)
    r = earth.pos - sun.pos
    Fgrav = -G*Msun*mearth/mag(r)**2*norm(r)
    earth.p = earth.p + Fgrav*dt
    earth.pos = earth.pos + earth.p/mearth*dt
    t = t + dt
    rplot.plot(t, mag(r))
    if mag(r) < sun.radius:
        print("crashed at t =", t)
        break
