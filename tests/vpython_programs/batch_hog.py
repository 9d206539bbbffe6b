from vpython import *
# A student's lab that blows up its memory after a few frames (over --max-memory).
scene.width = 240
scene.height = 160
rod = cylinder(color=color.cyan)


def keep_everything():
    return [b"\x01" * (100 << 20) for i in range(40)]


t = 0
while True:
    rate(50)
    t += 0.02
    rod.pos.x = t
    if t > 0.1:
        kept = keep_everything()
