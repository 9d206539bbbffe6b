GlowScript 3.2 VPython
# Lab 3: orbit of the earth -- chen
scene.range = 2.4e+11
G = 6.7e-11
Msun = 2e+30
mearth = 6e+24
sun = sphere(pos=vec(0, 0, 0), radius=7e+09, color=color.orange)
earth = sphere(pos=vec(1.5e+11, 0, 0), radius=3e+09, color=vec(1, 0.5, 0.3), make_trail=True, interval=5)
earth.p = mearth*vec(0, 2.69e+04, 0)
graph(title="distance", xtitle="time (s)", ytitle="|r| (m)")
rplot = gcurve(color=color.magenta)
dt = 43200
t = 0

while True:
    rate(250)
    r = earth.pos - sun.pos
    Fgrav = -G*Msun*mearth/mag(r)**2*norm(r)
    earth.p = earth.p + Fgrav*dt
    earth.pos = earth.pos + earth.p/mearth*dt
    t = t + dt
    rplot.plot(pos=(t, mag(r)))
    if mag(r) < sun.radius:
        print("crashed at t = " + t)
        break
