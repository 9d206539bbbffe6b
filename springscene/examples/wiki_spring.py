"""The wiki page's ball and spring, as a VPython 7 program (Model 14's loop).

Run it headless:  springscene vpython examples/wiki_spring.py --out renders/wiki_spring.mp4
It draws what `springscene render configs/wiki.toml` draws, and its ball follows
`springscene simulate configs/wiki.toml` to the last bit.
"""
from vpython import *

scene.width = 900
scene.height = 600
scene.background = color.white
scene.title = "Ball and Spring Model of Matter"
scene.caption = ("A ball hangs from a fixed holder on a helix spring, stepped by the "
                 "momentum principle: Euler-Cromer with dt = 0.01 s.\n"
                 "k = 15 N/m, m = 0.10 kg, L0 = 0.10 m, g = &lt;0, -9.8, 0&gt; m/s&sup2;.")
scene.center = vector(0, -0.10, 0)

k = 15            # spring stiffness, N/m
L0 = 0.10         # relaxed length, m
m = 0.10          # ball's mass, kg
g = vector(0, -9.8, 0)
dt = 0.01         # time step, s

holder = box(pos=vector(0, 0, 0), size=vector(0.2, 0.01, 0.2), color=color.gray(0.5))
# start at rest 0.02 m below equilibrium: y = -(L0 + m|g|/k + 0.02)
ball = sphere(pos=vector(0, -0.18533333333333335, 0), radius=0.025, color=color.red)
ball.p = vector(0, 0, 0)
spring = helix(pos=holder.pos, axis=ball.pos - holder.pos, radius=0.015,
               thickness=0.003, coils=15, color=color.cyan)

t = 0
while True:
    rate(100)
    L = ball.pos - holder.pos
    Fs = -k * (mag(L) - L0) * norm(L)
    Fg = m * g
    Fnet = Fs + Fg
    ball.p = ball.p + Fnet * dt
    ball.pos = ball.pos + (ball.p / m) * dt
    spring.axis = ball.pos - holder.pos
    t = t + dt
