from visual import *
# Stands for VPython 6's examples/toroid.py, here a single current loop: the field at
# its centre by the Biot-Savart law. Features: a curve grown by append() from an
# invisible arrow turned with rotate(angle=, axis=), arrows with shaftwidth and a zero
# axis, then `for pt in loop.pos` (the curve's points as an array), vector(pt - old),
# cross(), .mag, printed results.
R = 0.2
I = 1.
k = 1e-7
nsteps = 60
loop = curve(color=(1., .7, .2), radius=0.004)
spoke = arrow(pos=(0, 0, 0), axis=(R, 0, 0), visible=0)
for n in arange(0, nsteps + 1):
    loop.append(pos=spoke.axis)
    spoke.rotate(angle=2*pi/nsteps, axis=(0, 0, 1))
probes = [arrow(pos=(0, 0, z), axis=(0, 0, 0), color=(0, .6, 1), shaftwidth=0.01)
          for z in (0, 0.1, 0.2)]
Bideal = 2*pi*k*I/R
scale = 0.1/Bideal
old = loop.pos[0]
for pt in loop.pos:
    dl = vector(pt - old)
    source = old + dl/2.
    for b in probes:
        r = vector(b.pos - source)
        if r.mag > 0:
            b.axis = b.axis + k*I*cross(dl, r)/r.mag**3*scale
    old = pt
print("centre:", probes[0].axis.mag/scale, "ideal:", Bideal)
