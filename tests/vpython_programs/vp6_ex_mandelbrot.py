from __future__ import division
from visual.graph import *
# Stands for VPython 6's examples/mandelbrot.py, here a Julia set: a fractal drawn as
# square graph dots. Features: gdisplay(xmin=, xmax=, ymin=, ymax=), gdots(shape=
# 'square', size=), plot(pos=, color=) per point, color.hsv_to_rgb((h, s, v)) with a
# tuple, complex arithmetic, arange from `from visual.graph import *`.
XMIN, XMAX, YMIN, YMAX = -1.5, 1.5, -1, 1
g = gdisplay(width=450, height=300, xmin=XMIN, xmax=XMAX, ymin=YMIN, ymax=YMAX)
cells = gdots(shape='square', size=4)
step = 0.05
c0 = complex(-0.8, 0.156)
limit = 40
drawn = 0
for y0 in arange(YMIN, YMAX, step):
    for x0 in arange(XMIN, XMAX, step):
        z = complex(x0, y0)
        n = 0
        while abs(z) < 2 and n < limit:
            z = z*z + c0
            n += 1
        if 0.1 < n/limit < 1:
            cells.plot(pos=(x0, y0), color=color.hsv_to_rgb((n/limit, 1, 1)))
            drawn += 1
print(drawn)
