from visual import *
# Stands for VPython 6's examples/boxlighttest.py: a grey block lit by coloured lights
# that circle it. Features: materials.rough and materials.emissive, local_light and
# distant_light with colours taken from objects, chained assignment
# (lamp.pos = bulb.pos = ...), vector(...) scaled by a number, cos/sin from visual.
R = 2.5
ang1 = ang2 = 0.0
block = box(size=(2, 2, 2), color=(0.6, 0.6, 0.6), material=materials.rough)
bulb1 = sphere(radius=0.25, pos=(R, 0, 0), color=color.red, material=materials.emissive)
bulb2 = sphere(radius=0.25, pos=(0, R, 0), color=color.cyan, material=materials.emissive)
pointer = arrow(pos=(0, 0, R + 2), axis=(0, 0, -1), color=color.green,
                material=materials.emissive)
lamp1 = local_light(pos=bulb1.pos, color=bulb1.color)
lamp2 = local_light(pos=bulb2.pos, color=bulb2.color)
sun = distant_light(direction=(0, 0, 1), color=pointer.color)
t = 0
while t < 2:
    rate(50)
    lamp1.pos = bulb1.pos = R*vector(cos(ang1), sin(ang1), 0)
    ang1 += 0.05
    lamp2.pos = bulb2.pos = R*vector(0, cos(ang2), sin(ang2))
    ang2 += 0.03
    t += 0.02
print(round(mag(bulb1.pos), 6), round(ang1, 6))
