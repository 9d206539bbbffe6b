from visual import *
# Stands for VPython 6's examples/convex.py: convex hulls of many kinds of point sets;
# the last one follows the mouse. Features: convex(color=) filled by append(pos=), pos=
# transpose((x, y, 0*t)) of arange arrays, a list of vectors, .color as a tuple read
# and set, a loop polling scene.mouse.clicked (nobody clicks) and setting
# hull.pos[-1] = scene.mouse.pos, as the example does.
scene.range = 3
ring = convex(color=(0.5, 0.25, 0))
plate = convex(color=(0, 0.4, 0.4))
tri = convex(color=(0.4, 0, 0.4))
a = arange(0, 2*pi, 2*pi/5)
tri.pos = transpose((cos(a) - 1.5, sin(a) + 1.5, 0*a))
for a in arange(0, 2*pi, 0.3):
    ring.append(pos=(1.5 + cos(a), -1, sin(a)))
    ring.append(pos=(1.5 + cos(a), -0.7, sin(a)))
corners = []
for i in range(8):
    corners.append(vector(i % 2 - 2, (i//2) % 2 - 1.5, (i//4) % 2))
plate.pos = corners
ring.color = (ring.color[0]*2, ring.color[1]*2, ring.color[2]*2)
tip = convex(pos=[(1, 1, 0), (2, 1, 0), (1.5, 2, 0.3), (1.5, 1.5, 0)], color=color.green)
n = 0
while n < 15:
    rate(10)
    if scene.mouse.clicked:
        tip.append(pos=scene.mouse.getclick().pos)
    tip.pos[-1] = scene.mouse.pos
    n += 1
print(len(ring.pos), ring.color)
