from visual import *
# Stands for VPython 6's examples/labels.py: labels pinned to parts of an object.
# Features: label(text=, pos=(x, y) with two numbers, space=, xoffset=, yoffset=,
# opacity=), a two-line text with \n, a cylinder with default pos.
rod = cylinder(axis=(2, 0, 0), radius=0.1, color=color.green)
left = label(text="start", xoffset=-20, yoffset=15, opacity=0.4)
right = label(text="end", pos=(2, 0), space=0.15, opacity=0.4)
middle = label(text="the\nmiddle", pos=(1, 0), xoffset=0, yoffset=-30, opacity=0.7)
print(middle.text.count("\n") + 1, right.pos)
