GlowScript 3.2 VPython
# Lab: a mass on a vertical spring (in the style of a Matter & Interactions lab).
# Written for glowscript.org: no imports, strings joined to numbers with +,
# a function bound to a button above its def, a float range.
scene.title = "<b>Mass on a spring</b>"
scene.background = color.white
scene.range = 0.3
scene.center = vec(0, -0.15, 0)

ceiling = box(pos=vec(0, 0, 0), size=vec(0.2, 0.01, 0.2), color=color.gray(0.5))
ball = sphere(pos=vec(0, -0.25, 0), radius=0.025, color=color.orange)
spring = helix(pos=ceiling.pos, axis=ball.pos - ceiling.pos, color=color.cyan,
               thickness=0.003, coils=20, radius=0.015)
button(bind=pause_sim, text="Pause")        # pause_sim is defined further down
info = label(pos=vec(0.1, 0.05, 0), text="t = 0 s", box=False, color=color.black)

m = 0.1
k = 15
L0 = 0.1
g = vec(0, -9.8, 0)
p = m*vec(0, 0, 0)
dt = 0.01
running = True

def pause_sim(b):
    global running
    running = not running

gr = graph(title="y(t)", xtitle="t (s)", ytitle="y (m)")
yplot = gcurve(color=color.blue)

t = 0
for step in range(0, 2/dt):                 # a float stop, as GlowScript allows
    rate(100)
    L = ball.pos - ceiling.pos
    Fs = -k*(mag(L) - L0)*norm(L)
    p = p + (Fs + m*g)*dt
    ball.pos = ball.pos + (p/m)*dt
    spring.axis = ball.pos - ceiling.pos
    yplot.plot(t, ball.pos.y)
    info.text = "t = " + round(t, 2) + " s"
    t = t + dt
print("period = " + 2*pi*sqrt(m/k))
