from visual.graph import *
# VPython 6's graph module gives the 3D names too; its colours are tuples; some
# objects take a first argument without its name.
ball = sphere(pos=(0, 0, 0), radius=0.5, color=color.hsv_to_rgb((0.5, 1, 1)))
scene.background = color.gray(0.2)
print("hsv_to_rgb", color.hsv_to_rgb((0.5, 1, 1)))
print("rgb_to_hsv", color.rgb_to_hsv((1, 0, 0)))
print("vector", color.rgb_to_hsv(vector(0, 0, 1)))
print("gray", color.gray(0.25), "grayscale", color.rgb_to_grayscale((1, 1, 1)))
print("four", color.hsv_to_rgb([0, 0, 1, 0.5]))
title = text((0, 1, 0), text="hi", height=0.5)
print("text", title.pos)
spots = gdots(4, color=color.red)
bars = gvbars(0.5, color=color.blue)
line = gcurve(True, color=color.green)
print("series", spots.size, bars.delta, line.dot)
try:
    sphere((1, 0, 0))
except TypeError:
    print("sphere takes keywords only")
