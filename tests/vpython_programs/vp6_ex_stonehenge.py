from visual import *
import time
# Stands for VPython 6's examples/stonehenge.py: a ring of slabs with pictures, a clock,
# a rolling log and rising smoke rings; the mouse would roam. Features:
# materials.texture(data=, mapping="rectangular"), color.hsv_to_rgb((h, s, v)) with a
# tuple, rotate(vector, axis=, angle=), a class holding objects, ring, pyramid, cone in
# a frame turned about an origin, ellipsoid, 3D text, scene.userspin/userzoom, and the
# roam check of scene.mouse.events (nobody presses).
scene.title = "Small henge"
scene.range = (8, 8, 8)
scene.center = (0, 1, 0)
scene.userspin = False
scene.userzoom = False
picture = materials.texture(data=array([[(1, 0, 0), (1, 1, 1)], [(1, 1, 1), (0, 0, 1)]]),
                            mapping="rectangular")
floor = box(pos=(0, -0.1, 0), size=(14, 0.2, 14), color=color.orange, material=materials.wood)
for i in range(6):
    a = i*2*pi/6
    slab = box(pos=(5*cos(a), 1.5, 5*sin(a)), axis=(cos(a), 0, sin(a)), size=(0.4, 3, 2))
    box(pos=slab.pos + vector(-0.25*cos(a), 0, -0.25*sin(a)), axis=slab.axis,
        size=(0.1, 1, 1), material=picture)

class Dial:
    def __init__(self, pos, radius):
        self.marks = [sphere(pos=vector(pos) + rotate(radius*scene.up, axis=(0, 0, 1),
                                                      angle=-2*pi*n/12), radius=radius/15,
                             color=color.hsv_to_rgb((n/12., 1, 1))) for n in range(12)]
        self.hand = arrow(pos=pos, axis=0.9*radius*scene.up, shaftwidth=radius/10)

    def show(self, minute):
        self.hand.axis = rotate(0.9*scene.up, axis=(0, 0, 1), angle=-2*pi*minute/60)

dial = Dial((0, 2, -4.6), 1.0)
pyramid(pos=(-2, 0, -1), size=(1.5, 1.5, 1.5), axis=(0, 2, 0), color=(0, 0.6, 0),
        material=materials.marble)
smoke = [ring(pos=(2, 0.5 + 0.2*i, 1), axis=(0, 1, 0), radius=0.1 + 0.02*i,
              thickness=0.03, color=(0.8, 0.8, 0.8)) for i in range(8)]
spinner = frame(pos=(0, 1, 2))
for nn in range(4):
    cc = cone(frame=spinner, pos=(0.3, 0, 0), axis=(0.6, 0, 0), radius=0.15, color=color.yellow)
    cc.rotate(angle=0.5*nn*pi, axis=(0, 1, 0), origin=(0, 0, 0))
cloud = ellipsoid(pos=(0, 4, -3), size=(3, 1, 1), color=(1, 0.5, 0.5), opacity=0.3)
text(pos=(0, 3.2, 4.8), text="Henge", color=color.yellow, depth=0.2, height=0.5, align="center")
roam = False
t = 0
while t < 1:
    if scene.mouse.events:
        m = scene.mouse.getevent()
        roam = m.press or m.drag
    spinner.rotate(angle=0.1, axis=(0, 1, 0), origin=(0, 0, 0))
    cloud.rotate(angle=0.02, origin=(0, 0, 0), axis=(0, 1, 0))
    for s in smoke:
        s.pos = s.pos + vector(0, 0.01, 0)
    dial.show(time.localtime(time.time())[4])
    rate(30)
    t += 1/30.
