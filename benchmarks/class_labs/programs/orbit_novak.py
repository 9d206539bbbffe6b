Web VPython 3.2
# Lab 3: orbit of the sat -- novak
scene.range = 5.12e+07
G = 6.7e-11
Mearth = 6e+24
msat = 1000
earth = sphere(pos=vec(0, 0, 0), radius=6.4e+06, color=color.blue)
sat = sphere(pos=vec(3.2e+07, 0, 0), radius=1.5e+06, color=vec(0.6, 0.2, 0.9))
sat.p = msat*vec(0, 3899, 0)
attach_trail(sat, color=vec(1, 0.5, 0.3))
graph(title="distance", xtitle="time (s)", ytitle="|r| (m)")
rplot = gcurve(color=color.red)
dt = 17
t = 0

while True:
    rate(1000)
    r = sat.pos - earth.pos
    Fgrav = -G*Mearth*msat/mag(r)**2*norm(r)
    sat.p = sat.p + Fgrav*dt
    sat.pos = sat.pos + sat.p/msat*dt
    t = t + dt
    rplot.plot(t, mag(r))
    if mag(r) < earth.radius:
        print("crashed at t =", t)
        break
