from visual import *
# Stands for VPython 6's examples/extruded_columns.py: two pillars and an arch built of
# extrusions. Features: extrusion with pos= paths (a list, paths.line(np=),
# paths.circle, paths.arc), scale= lists, shapes.ngon(roundness=, invert=),
# shapes.rectangle, shapes.circle, a shape minus a shape, nested frames rotated,
# scene.autocenter and scene.visible off while building.
scene.range = 3
scene.forward = (-0.4, -0.3, -1)
scene.autocenter = True
scene.visible = False

def pillar(pos, height=2.0):
    p = frame(pos=pos)
    body = shapes.ngon(radius=0.15, np=12, roundness=0.0, invert=True)
    extrusion(frame=p, pos=[(0, 0, 0), (0, height, 0)], shape=body,
              scale=[(1, 1), (0.85, 0.85)])
    band = shapes.rectangle(width=0.05) - shapes.circle(pos=(0.02, 0.02), radius=0.03)
    extrusion(frame=p, pos=paths.circle(radius=0.17), shape=band)
    cap = frame(frame=p, pos=(0, height, 0))
    extrusion(frame=cap, pos=paths.line(end=(0, 0.2, 0), np=4),
              scale=[(1, 1), (1.1, 1.1), (1.2, 1.2), (1.4, 1.4)],
              shape=shapes.rectangle(width=0.25, roundness=0.2, invert=True))
    return p

left = pillar((-0.8, 0, 0))
right = pillar((0.8, 0, 0))
arch = frame(pos=(0, 2.2, 0))
extrusion(frame=arch, pos=paths.arc(radius=0.8, angle1=0, angle2=pi),
          shape=shapes.ngon(np=6, radius=0.1))
arch.rotate(angle=pi/2)
base = box(size=(3, 0.1, 1), pos=(0, -0.05, 0))
scene.visible = True
