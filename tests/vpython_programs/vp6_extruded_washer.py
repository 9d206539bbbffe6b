from visual import *
# A VPython 6 program extruding Polygon shapes: a square washer (a square less a round
# hole) swept straight, widening and twisting, coloured point by point; a ring of
# triangles swept round a Polygon loop; all in a frame that turns, the column growing
# fatter as VPython 6 redrew an extrusion whose scale was set.
scene.range = 4
scene.forward = (0, -1, -1)
scene.background = (0.15, 0.15, 0.2)
f = frame()
washer = shapes.rectangle(width=2) - shapes.circle(radius=0.5)
column = extrusion(frame=f, pos=[(0, -2, 0), (0, 0, 0), (0, 2, 0)], shape=washer,
                   scale=[(1, 1), (1.2, 1.2), (0.8, 0.8)], twist=0.3,
                   color=[color.red, color.yellow, color.red])
loop = Polygon([(-3, -3), (3, -3), (3, 3), (-3, 3)])
ring = extrusion(frame=f, pos=loop, shape=shapes.triangle(length=0.6), color=color.cyan)
t = 0
while t < 1:
    rate(50)
    f.rotate(angle=0.03, axis=(0, 1, 0))
    column.xscale = column.yscale = 1 + t
    t += 0.02
print(len(washer), washer.isHole(1), round(washer.area(), 3), column.pos.shape,
      column.scale[1].round(2).tolist(), len(ring.pos))
