from __future__ import division
from visual import *
from random import uniform, seed
# Stands for VPython 6's examples/medusa.py: a jellyfish of extrusions that wave.
# Features: VPython 6's shapes as Polygons (shapes.circle() - shapes.circle(pos=)),
# poly.contour(0), extrusions given x=/y=/z= arrays and pos= lists, a colour list,
# scale changed in place, xscale/yscale, tail.y set from an expression of tail.x,
# frames rotated, materials.emissive, `from random import *` style uniform().
seed(5)
crescent = shapes.circle(radius=0.8) - shapes.circle(pos=(-0.4, 0), radius=0.7)
rim = crescent.contour(0)
rim.append(rim[0])
arc = arange(0, 2*pi + pi/10, pi/20)
bell = extrusion(y=0.02*cos(arc), x=0, z=-0.02*sin(arc), shape=rim, color=color.magenta,
                 material=materials.emissive)
tails = []
for n in range(3):
    start = [(-0.1 - 0.1*i, -0.1*n, 0.1*n) for i in range(16)]
    tails.append(extrusion(frame=frame(), pos=start, shape=shapes.circle(radius=0.02),
                           color=[(1, 0.5, 0), (1, 1, 0)]*8, material=materials.emissive))
    for i in range(len(tails[-1].scale) - 1):
        tails[-1].scale[i] = uniform(0.8, 1.2)
    tails[-1].scale[-1] = 0.2
t = 0
while t < 1:
    rate(25)
    bell.yscale = 1 + 0.1*sin(4*t)
    bell.xscale = 1 - 0.1*sin(4*t)
    for n, tail in enumerate(tails):
        tail.y = -0.1*n + sin(3*tail.x + 5*t)*tail.x*0.2
        tail.frame.rotate(axis=(0, 0, 1), angle=0.002)
    t += 0.04
