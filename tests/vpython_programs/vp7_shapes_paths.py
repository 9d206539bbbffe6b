from vpython import *
# Shapes and paths: the two pictures of the VPython documentation, side by side.
# Left: a circular shape swept round a rectangular path (a picture frame of pipe).
# Right: a rectangular shape swept round a circular path (a flat ring, like a tyre).
# Below: a rounded bar with a hole, and a label in serif letters, right-aligned.

scene.width = 800
scene.height = 500
scene.background = color.gray(0.2)
scene.forward = vec(0, -0.5, -1)

frame_pipe = extrusion(path=paths.rectangle(width=3, height=2),
                       shape=shapes.circle(radius=0.2),
                       pos=vec(-2.5, 0, 0), color=color.cyan)

tyre = extrusion(path=paths.circle(radius=1.2),
                 shape=shapes.rectangle(width=0.3, height=0.6),
                 pos=vec(2.5, 0, 0), color=color.magenta)

bar = extrusion(path=[vec(-1.5, -2, 0), vec(1.5, -2, 0)],
                shape=[shapes.rectangle(width=0.8, height=0.8, roundness=0.3),
                       shapes.circle(radius=0.2)],
                color=color.green)

caption = text(text="shapes\nand paths", font="serif", align="right",
               pos=vec(4, 2.2, 0), height=0.4, color=color.yellow, billboard=True)

for i in range(100):
    rate(50)
    tyre.rotate(angle=0.03, axis=vec(0, 1, 0))
