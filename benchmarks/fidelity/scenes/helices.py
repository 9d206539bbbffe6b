# helices: along x, tilted, hanging, thick and thin
from vpython import *
scene.width, scene.height = 480, 320
helix(pos=vector(-4, 1.5, 0), axis=vector(3, 0, 0), radius=0.5, coils=6, color=color.yellow)
helix(pos=vector(0.5, 0.5, 0), axis=vector(2.5, 1.5, 0), radius=0.5, coils=5, thickness=0.15, color=color.cyan)
helix(pos=vector(-2, 0.5, 0), axis=vector(0, -3, 0.8), radius=0.4, coils=8, color=color.orange)
helix(pos=vector(1, -1.8, -0.5), axis=vector(2.5, 0, 1.5), radius=0.6, coils=4, thickness=0.25, color=color.green)
