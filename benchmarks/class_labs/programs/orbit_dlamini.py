Web VPython 3.2
# Lab 3: orbit of the moon -- dlamini
scene.range = 8.19e+07
G = 6.7e-11
Mearth = 6e+24
mmoon = 7.3e+22
earth = sphere(pos=vec(0, 0, 0), radius=6.4e+06, color=color.orange)
moon = sphere(pos=vec(5.12e+07, 0, 0), radius=1.5e+06, color=color.yellow)
moon.p = mmoon*vec(0, 2242, 0)
attach_trail(moon, color=color.red)
graph(title="distance", xtitle="time (s)", ytitle="|r| (m)")
rplot = gcurve(color=color.magenta)
dt = 115
t = 0

while True:
    rate(500)
    r = moon.pos - earth.pos
    Fgrav = -G*Mearth*mmoon/mag(r)**2*norm(r)
    moon.p = moon.p + Fgrav*dt
    moon.pos = moon.pos + moon.p/mmoon*dt
    t = t + dt
    rplot.plot(pos=(t, mag(r)))
    if mag(r) < earth.radius:
        print("crashed at t =", t)
        break
