GlowScript 3.2 VPython
# Lab 1: mass on a horizontal spring -- haddad
scene.title = "Lab 1: block on a spring"
scene.background = color.black
scene.center = vec(0.125, 0, 0)

k = 16      # N/m
m = 0.25    # kg
L0 = 0.25   # m
A = 0.1    # initial stretch, m
dt = 0.001

wall = box(pos=vec(-0.05, 0, 0), size=vec(0.02, 0.15, 0.15), color=color.gray(0.6))
ball = sphere(pos=vec(L0 + A, 0, 0), radius=0.04, color=color.blue)
ball.p = m*vec(0, 0, 0)
spring = helix(pos=wall.pos, axis=ball.pos - wall.pos, radius=0.02, coils=15, thickness=0.004, color=color.green)

graph(title="Energy", xtitle="t (s)", ytitle="E (J)")
Kgraph = gcurve(color=color.blue, label="K")
Ugraph = gcurve(color=color.red, label="Us")
Egraph = gcurve(color=color.black, label="K + Us")

t = 0
crossings = []
while t < 2.8:
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
    K = mag(ball.p)**2/(2*m)
    Us = 0.5*k*stretch**2
    Kgraph.plot(t, K)
    Ugraph.plot(t, Us)
    Egraph.plot(t, K + Us)

T = (crossings[-1] - crossings[0])/(len(crossings) - 1)
print("measured period: " + T)
print("expected:", 2*pi*sqrt(m/k))
