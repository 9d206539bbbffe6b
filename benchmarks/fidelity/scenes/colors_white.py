# a row of named colours and grays on white, a tilted view
from vpython import *
scene.width, scene.height = 480, 320
scene.background = color.white
scene.forward = vector(-0.3, -0.4, -1)
cols = [color.red, color.green, color.blue, color.yellow, color.cyan, color.magenta,
        color.orange, color.purple, color.gray(0.3), color.black]
for i, c in enumerate(cols):
    box(pos=vector(-4.5 + i, 0, 0), size=vector(0.8, 0.8 + 0.15 * i, 0.8), color=c)
