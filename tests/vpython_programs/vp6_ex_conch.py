from visual import *
# Stands for VPython 6's examples/conch.py: a horn extruded along a rising spiral.
# Features: extrusion given its path as pos= (a list of tuples), a ring shape from
# shapes.circle(thickness=), a scale per path point, a colour per path point,
# materials.marble, an extrusion in a frame that is then rotated, math.cos.
horn_path = []
sizes = []
shades = []
for k in range(40):
    a = 0.25*k
    r = 0.05*a
    horn_path.append((r*math.cos(a), 0.06*k, r*math.sin(a)))
    sizes.append((0.2 + 0.02*k, 0.2 + 0.02*k))
    shades.append((1, 0.4 + 0.015*k, 0.2))
ring_shape = shapes.circle(radius=0.5, thickness=0.05)
horn = extrusion(frame=frame(), shape=ring_shape, pos=horn_path, scale=sizes,
                 color=shades, material=materials.marble)
horn.frame.rotate(angle=pi/3)
print(len(horn.pos))
