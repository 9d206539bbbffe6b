"""The wiki's spring with live graphs: y(t) and the energies K, U and K + U."""
from vpython import *

scene.width, scene.height = 600, 400
scene.background = color.white
scene.title = "Ball on a spring, with graphs"
scene.center = vector(0, -0.12, 0)

k, L0, m, dt = 15, 0.10, 0.10, 0.01
g = vector(0, -9.8, 0)
holder = box(size=vector(0.2, 0.01, 0.2), color=color.gray(0.5))
ball = sphere(pos=vector(0, -0.20, 0), radius=0.025, color=color.red)
ball.p = vector(0, 0, 0)
spring = helix(pos=holder.pos, axis=ball.pos - holder.pos, radius=0.015, thickness=0.003,
               coils=15, color=color.cyan)

gy = graph(title="Height of the ball", xtitle="t (s)", ytitle="y (m)", width=600, height=250)
y_curve = gcurve(graph=gy, color=color.blue, label="y")
ge = graph(title="Energy", xtitle="t (s)", ytitle="E (J)", width=600, height=250)
K_curve = gcurve(graph=ge, color=color.red, label="K")
U_curve = gcurve(graph=ge, color=color.green, label="Us + Ug")
E_dots = gdots(graph=ge, color=color.black, label="K + U")

t = 0
while t < 3:
    rate(100)
    L = ball.pos - holder.pos
    ball.p = ball.p + (-k * (mag(L) - L0) * norm(L) + m * g) * dt
    ball.pos = ball.pos + (ball.p / m) * dt
    spring.axis = ball.pos - holder.pos
    t = t + dt
    K = mag2(ball.p) / (2 * m)
    U = 0.5 * k * (mag(ball.pos - holder.pos) - L0) ** 2 + m * 9.8 * ball.pos.y
    y_curve.plot(t, ball.pos.y)
    K_curve.plot(t, K)
    U_curve.plot(t, U)
    if round(t / dt) % 10 == 0:
        E_dots.plot(t, K + U)
