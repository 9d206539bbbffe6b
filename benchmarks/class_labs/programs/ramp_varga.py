GlowScript 3.2 VPython
# Lab 4: cart on a ramp, 7 degrees -- varga
angle = 7*pi/180
along = vec(cos(angle), sin(angle), 0)
scene.center = 1.5*along
scene.range = 1.7
ramp = box(pos=1.5*along - vec(0, 0.03, 0), axis=3*along, size=vec(3, 0.02, 0.3), color=color.gray(0.8))
cart = box(pos=vec(0, 0, 0), axis=0.2*along, size=vec(0.2, 0.06, 0.1), color=vec(1, 0.5, 0.3))
m = 0.5
g = 9.8
mu = 0.0
s = 0.0
v = 2.4    # m/s up the ramp
graph(title="cart", xtitle="t (s)", ytitle="s (m), v (m/s)")
splot = gcurve(color=color.blue, label="s")
vplot = gcurve(color=color.red, label="v")
dt = 1e-9
tmax = 5
times = [n*dt for n in range(int(tmax/dt))]   # every time step
for t in times:
    rate(100)
    a = -g*sin(angle) - mu*g*cos(angle)*(1 if v > 0 else -1)
    v = v + a*dt
    s = s + v*dt
    cart.pos = s*along
    splot.plot(pos=(t, s))
    vplot.plot(pos=(t, v))
print("back at the bottom after", t)
