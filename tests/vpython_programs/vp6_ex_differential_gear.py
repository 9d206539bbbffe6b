from visual import *
# Stands for VPython 6's examples/differential_gear.py: two gears meshing at right
# angles, tapered like bevel gears. Features: shapes.gear, a shape minus a circle,
# extrusion with pos=paths.line(np=), a scale= list made by a helper, twist=, gears
# moved into another gear's frame (f.frame = ...), rotate(axis=, angle=, origin=), a
# half-transparent box, label(yoffset=, line=0), scene.mouse.events and scene.kb.keys
# polled (nobody clicks or types).
scene.forward = (0.3, -0.5, -0.8)
scene.title = "Bevel gears"

def taper(start=(1., 1.), end=(1., 1.), np=2):
    return [(start[0] + (end[0] - start[0])*i/(np - 1),
             start[1] + (end[1] - start[1])*i/(np - 1)) for i in range(np)]

big = extrusion(shape=shapes.gear(n=20, radius=3.0) - shapes.circle(radius=1.0),
                pos=paths.line(start=(0, 0, 0), end=(0, 0, 1), np=4),
                scale=taper(end=(0.8, 0.8), np=4), frame=frame(), color=color.cyan)
small = extrusion(shape=shapes.gear(n=10, radius=1.5),
                  pos=paths.line(start=(0, 0, 0), end=(0, 0, 1), np=4),
                  scale=taper(end=(0.7, 0.7), np=4), twist=0.02, frame=frame(),
                  color=color.orange)
small.frame.frame = big.frame
small.frame.rotate(axis=(0, 1, 0), angle=pi/2)
small.frame.pos = (-2.6, 0, 2.2)
guard = box(frame=big.frame, pos=(0, 0, -1), size=(6, 6, 0.2), color=(0, 0, 1), opacity=0.4)
note = label(yoffset=200, line=0, text="CLICK TO PAUSE")
run = True
ratio = 20/10.
turns = 0
while turns < 40:
    if scene.mouse.events:
        if scene.mouse.getevent().click == 'left':
            run = not run
    if scene.kb.keys:
        note.text = "KEY " + scene.kb.getkey()
    if run:
        big.frame.rotate(axis=(0, 0, 1), angle=pi/100)
        small.frame.rotate(axis=(1, 0, 0), angle=ratio*pi/100, origin=small.frame.pos)
        turns += 1
    rate(50)
