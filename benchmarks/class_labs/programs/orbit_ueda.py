GlowScript 3.2 VPython
# Lab 3: orbit of the earth -- ueda
scene.range = 2.4e+11
G = 6.7e-11
Msun = 2e+30
mearth = 6e+24
sun = sphere(pos=vec(0, 0, 0), radius=7e+09, color=vec(0.6, 0.2, 0.9))
earth = sphere(pos=vec(1.5e+11, 0, 0), radius=3e+09, color=color.cyan)
earth.p = mearth*vec(0, 2.989e+04, 0)
attach_trail(earth, color=color.blue)
graph(title="Energy", xtitle="t (s)", ytitle="J")
Kcurve = gcurve(color=color.red, label="K")
Ucurve = gcurve(color=color.blue, label="U")
Ecurve = gcurve(color=color.black, label="K + U")
dt = 51840
t = 0

while True:
    rate(200)
    r = earth.pos - sun.pos
    Fgrav = -G*Msun*mearth/mag(r)**2*norm(r)
    earth.p = earth.p + Fgrav*dt
    earth.pos = earth.pos + earth.p/mearth*dt
    t = t + dt
    K = mag(earth.p)**2/(2*mearth)
    U = -G*Msun*mearth/mag(r)
    Kcurve.plot(t, K)
    Ucurve.plot(t, U)
    Ecurve.plot(t, K + U)
    if mag(r) < sun.radius:
        print("crashed at t = " + t)
        break
