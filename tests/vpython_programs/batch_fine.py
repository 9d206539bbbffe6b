from vpython import *
# A student's lab that runs: an orange ball rolls right on a small canvas.
scene.width = 240
scene.height = 160
scene.background = color.white
ball = sphere(pos=vector(-1, 0, 0), radius=0.3, color=color.orange)
t = 0
while t < 5:
    rate(50)
    ball.pos.x = -1 + 0.5 * t
    t += 0.02
print("the ball ended at", ball.pos.x)
