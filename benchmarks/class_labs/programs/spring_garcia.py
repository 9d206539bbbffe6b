from vpython import *
# Lab 1: mass on a horizontal spring -- garcia
scene.title = "SHM"
scene.background = vec(0.9, 0.9, 1)
scene.center = vec(0.15, 0, 0)

k = 15      # N/m
m = 0.22    # kg
L0 = 0.3   # m
A = 0.12    # initial stretch, m
dt = 0.001

wall = box(pos=vec(-0.05, 0, 0), size=vec(0.02, 0.15, 0.15), color=color.gray(0.6))
ball = sphere(pos=vec(L0 + A, 0, 0), radius=0.035, color=color.green)
ball.p = m*vec(0, 0, 0)
spring = helix(pos=wall.pos, axis=ball.pos - wall.pos, radius=0.02, coils=12, thickness=0.004, color=color.magenta)

graph(title="Energy", xtitle="t (s)", ytitle="E (J)")
Kgraph = gcurve(color=color.blue, label="K")
Ugraph = gcurve(color=color.red, label="Us")
Egraph = gcurve(color=color.black, label="K + Us")

t = 0
crossings = []
while t < 2.6:
    rate(1000)
    L = ball.pos - wall.pos
    s_before = mag(L) - L0
    Fs = -k*(mag(L) - L0)*norm(L)
    ball.p = ball.p + Fs*dt
    ball.pos = ball.pos + ball.p/m*dt
    spring.axis = ball.pos - wall.pos
    t = t + dt
    stretch = mag(ball.pos - wall.pos) - L0
    if s_before < 0 and stretch >= 0:
        crossings.append(t)
        if len(crossings) == 3:
            print("period =", (crossings[2] - crossings[0])/2)
    K = mag(ball.p)**2/(2*m)
    Us = 0.5*k*stretch**2
    Kgraph.plot(t, K)
    Ugraph.plot(t, Us)
    Egraph.plot(t, K + Us)
