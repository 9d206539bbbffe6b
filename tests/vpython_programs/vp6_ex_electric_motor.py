from visual import *
# Stands for VPython 6's examples/electric_motor.py: a geared shaft with a slotted
# rotor turning in its frame; a click would pause it. Features: VPython 6's shapes as
# Polygons cut with - and grown with += in loops, Polygon([...]), shapes.gear,
# shapes.rectangle(rotate=), extrusions given pos= lists and paths.line(np=) with
# twist=, nested frames, rotate(angle=, axis=), materials, scene.mouse.events polled.
scene.autocenter = True
motor = frame(axis=(0, 0, 1))
rotor = frame(frame=motor)
slotted = shapes.circle(radius=1.5)
for i in range(8):
    a = i*2*pi/8
    slotted = slotted - shapes.rectangle(pos=(1.5*cos(a), 1.5*sin(a)), width=0.8,
                                         height=0.2, rotate=a)
slotted = slotted - shapes.circle(radius=0.3)
core = extrusion(pos=[(0, 0, 0), (0, 0, 2)], shape=slotted, color=(0.7, 0.7, 0.7),
                 material=materials.rough, frame=rotor)
tooth = Polygon([(-0.1, -0.3), (0.1, -0.3), (0.1, 0.3), (-0.1, 0.3)])
for n in range(3):
    tooth += shapes.circle(pos=(0, -0.3 + 0.3*n), radius=0.12, np=6)
winding = extrusion(frame=rotor, pos=paths.circle(radius=1.0), shape=tooth,
                    color=(0.8, 0.5, 0.1))
pinion = extrusion(frame=rotor, pos=paths.line(start=(0, 0, -0.2), end=(0, 0, -1.2), np=6),
                   shape=shapes.gear(n=10, radius=0.4), twist=0.05, material=materials.blazed)
shaft = cylinder(frame=rotor, pos=(0, 0, -1.5), axis=(0, 0, 4.5), radius=0.28)
running = True
t = 0
while t < 1:
    rate(50)
    if running:
        rotor.rotate(angle=pi/50, axis=(0, 0, 1))
    if scene.mouse.events:
        if scene.mouse.getevent().click == 'left':
            running = not running
    t += 0.02
