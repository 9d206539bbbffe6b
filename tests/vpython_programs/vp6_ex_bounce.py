from visual import *
# Stands for VPython 6's examples/bounce.py: a ball dropped on a slab bounces back up.
# Features: box and sphere by keywords, tuples as positions, a velocity kept as the
# ball's own attribute, .y shortcuts, an Euler step under rate().
slab = box(pos=(0, -0.5, 0), length=3, height=0.2, width=3, color=color.orange)
pebble = sphere(pos=(0, 2.5, 0), radius=0.3, color=color.cyan)
pebble.velocity = vector(0, 0, 0)
bounces = 0
dt = 0.005
t = 0
while t < 2:
    rate(200)
    pebble.pos = pebble.pos + pebble.velocity*dt
    if pebble.y < slab.y + pebble.radius and pebble.velocity.y < 0:
        pebble.velocity.y = -pebble.velocity.y
        bounces = bounces + 1
    else:
        pebble.velocity.y = pebble.velocity.y - 9.8*dt
    t = t + dt
print(bounces, round(pebble.y, 3))
