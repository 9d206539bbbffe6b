from __future__ import division
from visual import *
from visual.graph import *
# A VPython 6 program (Python 3 syntax): display, tuples as vectors, materials,
# obj.x/.y shortcuts, a frame, a gdisplay with a gcurve, numpy names from visual.
scene = display(title="Bouncing ball", width=600, height=400, x=0, y=0,
                center=(0, 2, 0), background=(0.9, 0.9, 1), foreground=color.black)
floor = box(pos=(0, 0, 0), length=8, height=0.2, width=3, color=color.green,
            material=materials.wood)
ball = sphere(pos=(-3, 4, 0), radius=0.4, color=color.red, material=materials.shiny)
ball.velocity = vector(1.5, 0, 0)
marks = [sphere(pos=(x, 0.2, 1.2), radius=0.08, color=color.blue) for x in arange(-3, 4, 1)]
# a pinwheel: a frame holding two boxes, turned as one
wheel = frame(pos=(3, 3, 0))
box(frame=wheel, pos=(0.5, 0, 0), size=(1, 0.15, 0.15), color=color.yellow)
box(frame=wheel, pos=(0, 0.5, 0), size=(0.15, 1, 0.15), color=color.yellow)

plot = gdisplay(x=0, y=400, width=600, height=200, xtitle="t", ytitle="y")
ycurve = gcurve(gdisplay=plot, color=color.red)

dt = 0.005
t = 0
while t < 3:
    rate(200)
    ball.pos = ball.pos + ball.velocity*dt
    if ball.y < ball.radius + 0.1:
        ball.velocity.y = abs(ball.velocity.y)
    else:
        ball.velocity.y = ball.velocity.y - 9.8*dt
    ycurve.plot(pos=(t, ball.y))
    wheel.rotate(angle=0.02, axis=(0, 0, 1))
    t = t + dt
print(mag(ball.velocity - (1.5, 0, 0)) > 0, len(marks))
