from visual import *
from random import uniform, seed
# Stands for VPython 6's examples/planar.py: nodes joined by links that follow them
# (the example's nodes are dragged by the mouse; here they slide on their own).
# Features: cylinders with an attribute of their own (icolor), curves given an
# attribute of their own (ends=) and their colour by c.red/.green/.blue, c.pos set to
# a list of points every frame, a grid of curves, scene.mouse.events polled.
seed(2)
scene.forward = (-0.25, -0.25, -1)
nodes = []
for a in arange(-pi, pi, 2*pi/6):
    n = cylinder(pos=(6*sin(a), 0, 6*cos(a)), axis=(0, uniform(0.5, 3), 0))
    n.color = n.icolor = (0.5, 0.5, 1)
    nodes.append(n)
links = []
for i in range(6):
    c = curve(ends=[nodes[i].pos, nodes[(i + 2) % 6].pos], radius=0.15)
    c.red = 0
    c.green = uniform(0.3, 1)
    c.blue = 0
    c.pos = c.ends
    links.append(c)
for i in range(5):
    curve(pos=[(4*i - 8, 0, -8), (4*i - 8, 0, 8)], color=color.cyan)
t = 0
while t < 1:
    rate(25)
    if scene.mouse.events:
        scene.mouse.getevent()
    nodes[0].pos = nodes[0].pos + vector(0.1, 0, 0)
    for i, lnk in enumerate(links):
        lnk.pos = [nodes[i].pos, nodes[(i + 2) % 6].pos]
    t += 0.04
