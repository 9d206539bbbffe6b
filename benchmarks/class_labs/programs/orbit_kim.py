GlowScript 3.2 VPython
# Lab 3: orbit of the craft -- kim
scene.range = 8.19e+07
G = 6.7e-11
Mearth = 6e+24
mcraft = 15000
earth = sphere(pos=vec(0, 0, 0), radius=6.4e+06, color=color.yellow)
craft = sphere(pos=vec(5.12e+07, 0, 0), radius=1.5e+06, color=color.orange)
craft.p = mcraft*vec(0, 2242, 0)
attach_trail(craft, color=color.blue)
graph(title="distance", xtitle="time (s)", ytitle="|r| (m)")
rplot = gcurve(color=color.yellow)
dt = 115
t = 0

while True:
    rate(500)
    r = craft.pos - earth.pos
    Fgrav = -G*Mearth*mcraft/mag(r)**2*norm(r)
    craft.p = craft.p + Fgrav*dt
    craft.pos = craft.pos + craft.p/mcraft*dt
    t = t + dt
    rplot.plot(pos=(t, mag(r)))
    if mag(r) < earth.radius:
        print("crashed at t =", t)
        break
