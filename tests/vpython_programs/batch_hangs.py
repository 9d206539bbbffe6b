from vpython import *
# A student's lab that never gives a frame: a loop with no rate(), so it needs --timeout.
scene.width = 240
scene.height = 160
ball = sphere(color=color.green)
while True:
    ball.pos.x += 0.001
