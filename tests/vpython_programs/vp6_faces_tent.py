from visual import *
# A VPython 6 program drawing with faces: a four-sided tent of triangles built point by
# point in a turning frame, its normals made and smoothed, plus a flat two-sided sheet.
scene.range = 3
scene.background = (0.2, 0.2, 0.3)
f = frame(pos=(-1.2, 0, 0))
tent = faces(frame=f, color=color.orange)
peak = (0, 1.5, 0)
corners = [(1, 0, 1), (1, 0, -1), (-1, 0, -1), (-1, 0, 1)]
for i in range(4):
    a, b = corners[i], corners[(i + 1) % 4]
    tent.append(pos=a)
    tent.append(pos=b)
    tent.append(pos=peak)
tent.make_normals()
tent.smooth(0.5)
# the sheet: one array of corners, a colour per vertex, seen from both sides
sheet = faces(pos=[(0.5, -1, 0), (2.5, -1, 0), (2.5, 1, 0),
                   (0.5, -1, 0), (2.5, 1, 0), (0.5, 1, 0)])
sheet.color = [color.red, color.red, color.yellow, color.red, color.yellow, color.yellow]
sheet.make_normals()
sheet.make_twosided()
t = 0
while t < 1:
    rate(50)
    f.rotate(angle=0.06, axis=(0, 1, 0))
    sheet.pos[:, 1] += 0.004          # in place: the sheet rises
    t += 0.02
print(len(tent.pos), len(sheet.pos), round(sheet.normal[6][2]))
