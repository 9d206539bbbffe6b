from visual import *
# Stands for VPython 6's examples/gyro.py: a spinning wheel hanging from a spring, with
# a 3D text label that follows it; a click would pause. Features: helix(coils=,
# thickness=), a frame holding a disk and stripe curves given pos= lists, frame.rotate
# (angle=) and rotate(axis=, angle=), arrow(length=0), text(...) moved by its own
# frame (tag.frame.pos), scene.visible toggled, scene.mouse.clicked polled.
scene.title = 'Hanging wheel'
scene.visible = 0
top = vector(0, 1., 0)
ks = 60.
L0 = 0.8
M = 1.
g = 9.8
spring = helix(pos=top, axis=(0, -L0, 0), coils=8, radius=0.04, thickness=0.02,
               color=(1, 0.7, 0.2))
wheel = frame(pos=top + spring.axis)
disk = cylinder(frame=wheel, pos=(0, 0, -0.05), axis=(0, 0, 0.1), radius=0.3,
                color=(0.5, 0.5, 0.5))
stripe = curve(frame=wheel, color=color.black, pos=[(0, -0.28, 0.06), (0, 0.28, 0.06)])
marker = arrow(length=0, shaftwidth=0.03, color=color.red)
tag = text(text='w', height=0.15, depth=0.02, align='center', color=color.yellow)
p = vector(0, 0, 0)
dt = 0.01
t = 0.
while t < 2:
    rate(50)
    if scene.mouse.clicked:
        scene.mouse.getclick()
    Fspring = -ks*norm(spring.axis)*(mag(spring.axis) - L0)
    p = p + (Fspring + vector(0, -M*g, 0))*dt
    wheel.pos = wheel.pos + (p/M)*dt
    spring.axis = wheel.pos - top
    wheel.rotate(angle=0.2, axis=(0, 0, 1))
    marker.pos = wheel.pos + vector(0.4, 0, 0)
    marker.axis = 0.05*p
    tag.frame.pos = wheel.pos + vector(-0.5, 0, 0)
    if t == 0.:
        scene.visible = 1
    t = t + dt
print(round(wheel.pos.y, 4))
