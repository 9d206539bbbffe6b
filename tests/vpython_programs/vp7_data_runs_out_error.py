# Lab: a cart's model played against its measured positions, 25 readings a second.
# The loop runs one step past the end of the data, as a lab does when its model runs
# longer than the measurement: an IndexError at t = 2 s, after 2 s of animation.
from vpython import *

scene.width, scene.height = 400, 240
scene.background = color.black
scene.range = 1.2                 # a fixed view: the cart's place in the picture is its x

v = 1.0                           # m/s, the model's speed
measured = [-1.5 + v*(n + 1)/25 + 0.01*(-1)**n for n in range(49)]    # 49 readings

cart = sphere(pos=vec(-1.5, 0, 0), radius=0.1, color=color.red)
reading = box(pos=vec(-1.5, -0.3, 0), size=vec(0.05, 0.05, 0.05), color=color.green)

t = 0
dt = 1/25
i = 0
while True:
    rate(25)
    t = t + dt
    cart.pos.x = -1.5 + v*t       # the model
    reading.pos.x = measured[i]   # the measurement: IndexError once i reaches 49
    i = i + 1
