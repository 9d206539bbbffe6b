from vpython import *
# A student's lab that raises after a few frames: a red box climbs, then a division by zero.
scene.width = 240
scene.height = 160
block = box(color=color.red)
t = 0
while True:
    rate(50)
    t += 0.02
    block.pos.y = t
    if t > 0.2:
        speed = 1 / (t - t)
