"""Spring lab: a block on a horizontal spring, stepped by the momentum principle.

A student's VPython 7 program, as handed in. It prints the period it measures and
plots the energies; test_spring_lab.py is the instructor's check of it.
"""
from vpython import *

scene.title = "Spring lab: a block on a frictionless table"
scene.background = color.white
scene.center = vector(0, 0, 0)

k = 20            # spring stiffness, N/m
m = 0.5           # block's mass, kg
L0 = 0.3          # relaxed length, m
A = 0.1           # pulled out this far, then let go, m
dt = 0.001        # time step, s

wall = box(pos=vector(-0.3, 0, 0), size=vector(0.02, 0.2, 0.2), color=color.gray(0.5))
ball = sphere(pos=wall.pos + vector(L0 + A, 0, 0), radius=0.04, color=color.red)
ball.p = vector(0, 0, 0)
spring = helix(pos=wall.pos, axis=ball.pos - wall.pos, radius=0.02, thickness=0.004,
               coils=12, color=color.orange)

energy = graph(title="Energy of the block and spring", xtitle="t (s)", ytitle="energy (J)")
K_curve = gcurve(color=color.blue, label="K")
U_curve = gcurve(color=color.red, label="Us")
E_curve = gcurve(color=color.black, label="K + Us")

t = 0
crossings = []                     # times the block passes x = L0 going right
while t < 5:
    rate(1000)
    L = ball.pos - wall.pos
    stretch_before = mag(L) - L0
    Fs = -k * (mag(L) - L0) * norm(L)
    ball.p = ball.p + Fs * dt
    ball.pos = ball.pos + (ball.p / m) * dt
    spring.axis = ball.pos - wall.pos
    t = t + dt
    stretch = mag(ball.pos - wall.pos) - L0
    if stretch_before < 0 <= stretch:
        crossings.append(t)
    K = mag(ball.p) ** 2 / (2 * m)
    Us = 0.5 * k * stretch ** 2
    K_curve.plot(t, K)
    U_curve.plot(t, Us)
    E_curve.plot(t, K + Us)

period = (crossings[-1] - crossings[0]) / (len(crossings) - 1)
print("measured period:", round(period, 4), "s")
