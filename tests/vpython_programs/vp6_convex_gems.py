from visual import *
# A VPython 6 program drawing convex hulls: a cube of corners with points inside, a
# gem grown point by point with append, and a flat hexagon (points in one plane).
scene.range = 3.5
cube = convex(pos=[(x, y, z) for x in (-2.5, -1.5) for y in (-0.5, 0.5)
                   for z in (-0.5, 0.5)] + [(-2, 0, 0), (-2.1, 0.2, 0.1)],
              color=color.green)
gem = convex(color=(0.3, 0.5, 1))
for k in range(12):
    a = 2 * pi * k / 12
    gem.append(pos=(cos(a), 0.4 * (k % 2), sin(a)))
gem.append(pos=(0, -1.2, 0))
t = arange(0, 2 * pi, pi / 3)
hexagon = convex(pos=transpose((2 + 0.8 * cos(t), 0.8 * sin(t), 0 * t)), color=color.yellow)
hexagon.green = 0.6                  # one colour, changed by component
while True:
    rate(30)
    gem.pos[-1] = gem.pos[-1] + (0, -0.03, 0)    # the gem's tip lengthens
    if gem.pos[-1][1] < -1.8:
        break
print(len(cube.pos), len(gem.pos), hexagon.color)
