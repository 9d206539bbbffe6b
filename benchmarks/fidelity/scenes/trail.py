# make_trail on a ball moving in a circle (a finite loop). VPython 7 sends the ball's
# position to the browser at its update pace, and the trail gets a point per update, so
# the loop starts once the page is drawing (sleep) and runs slowly enough (rate(15)) for
# every step to reach the trail (a rerun of real VPython still differs by a few hundred
# pixels along the trail: its timing).
from vpython import *
scene.width, scene.height = 480, 320
scene.range = 3
ball = sphere(pos=vector(2, 0, 0), radius=0.25, color=color.red, make_trail=True, trail_radius=0.05)
post = cylinder(pos=vector(0, 0, -0.5), axis=vector(0, 0, 1), radius=0.1, color=color.white)
sleep(1)
for i in range(46):
    rate(15)
    t = 2 * pi * 0.75 * i / 45
    ball.pos = vector(2 * cos(t), 1.5 * sin(t), 0)
