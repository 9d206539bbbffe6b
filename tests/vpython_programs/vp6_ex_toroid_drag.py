from visual import *
# Stands for VPython 6's examples/toroid_drag.py, here a square current loop: the
# magnetic field at points the example would take from the mouse (here a fixed row of
# points). Features: curve(x=, y=, z=) given arrays, the curve's pos as an array
# (loop.pos[1:] - loop.pos[:-1]), mag() of an N x 3 array and rmag.shape = (-1, 1),
# cross() of arrays, arrows, scene.mouse.events polled (nobody drags).
k = 1e-7
I = 1.0
s = arange(0, 4.01, 0.05)
side = clip(s, 0, 1) - clip(s - 2, 0, 1)
up = clip(s - 1, 0, 1) - clip(s - 3, 0, 1)
loop = curve(x=side - 0.5, y=up - 0.5, z=0*s, color=(1, 0.7, 0.2), radius=0.01)
delta = loop.pos[1:] - loop.pos[:-1]
centre = (loop.pos[:-1] + loop.pos[1:])/2.
scene.range = 1.2
Bscale = 0.3/(2*sqrt(2)*k*I/(pi*0.5))

def BField(obs):
    r = obs - centre
    rmag = mag(r)
    rmag.shape = (-1, 1)
    return (k*I*cross(delta, r)/rmag**3).sum(axis=0)

fields = []
for x in (-0.3, 0, 0.3):
    if scene.mouse.events:
        scene.mouse.getevent()
    obs = vector(x, 0.1, 0.2)
    fields.append(arrow(pos=obs, axis=Bscale*BField(obs), shaftwidth=0.02, color=(0, 1, 1)))
    rate(10)
print(len(loop.pos), fields[1].axis)
