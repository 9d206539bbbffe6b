from visual import *
# Stands for VPython 6's examples/faces_cone.py: a faces object filled by numpy slices.
# Features: faces(pos=zeros((3N, 3)), frame=), in-place slices model.pos[0::3, 0] = ...,
# normals copied from pos then edited, a colour per vertex from
# color.hsv_to_rgb((h, s, v)) with a tuple, arange, a turning frame.
spin = frame()
stand = box(size=(0.3, 0.3, 0.3), pos=(0, -1.2, 0))
N = 8
fan = faces(pos=zeros((N*3, 3), float), frame=spin)
a = arange(0, 2*pi + 2*pi/N, 2*pi/N)
fan.pos[0::3, 0] = 1.5*cos(a[:-1])        # the rim, counter-clockwise from below
fan.pos[0::3, 2] = 1.5*sin(a[:-1])
fan.pos[1::3, 0] = 1.5*cos(a[1:])
fan.pos[1::3, 2] = 1.5*sin(a[1:])
fan.pos[2::3, 1] = -1                     # the tip points down
fan.normal = fan.pos
fan.normal[2::3, 0] = cos(a[1:])
fan.normal[2::3, 2] = sin(a[1:])
fan.normal[:, 1] = -0.6
fan.color = fan.pos
for v in range(3*N):
    fan.color[v] = color.hsv_to_rgb(((v // 3)/float(N), 0.8, 1))
t = 0
while t < 1:
    rate(50)
    spin.rotate(angle=0.03)
    t += 0.02
print(len(fan.pos))
