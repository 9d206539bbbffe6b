from visual import *
# Stands for VPython 6's examples/crossproduct.py, here torque = r x F with F turning on
# its own (the example's green vector is dragged by the mouse). Features: a grid curve
# given a pos= list, labels with opacity=0, box=0, line=0, arrows with shaftwidth=,
# cross() of a numpy array and a vector, scene.autoscale = 0, scene.forward, a loop
# polling scene.mouse.events and getevent() (nobody clicks).
scene.title = "Torque = r x F"
grid = curve(pos=[(-4, -4, 0), (4, -4, 0), (4, 4, 0), (-4, 4, 0), (-4, -4, 0),
                  (0, -4, 0), (0, 4, 0), (4, 4, 0), (4, 0, 0), (-4, 0, 0)])
caption = label(pos=(0, 5, 0), text="Cyan = Orange x Magenta", opacity=0, box=0, line=0)
rvec = array([3, 0, 0])
Fvec = vector(0, 2, 0)
r = arrow(pos=(0, 0, 0), axis=rvec, shaftwidth=0.3, color=color.orange)
F = arrow(pos=(0, 0, 0), axis=Fvec, shaftwidth=0.3, color=color.magenta)
torque = arrow(pos=(0, 0, 0), axis=cross(rvec, Fvec), shaftwidth=0.3, color=color.cyan)
scene.autoscale = 0
scene.forward = (-1, -0.6, -1)
clicks = 0
angle = 0
while angle < 2*pi:
    rate(50)
    if scene.mouse.events:
        m = scene.mouse.getevent()
        if m.click:
            clicks += 1
    angle += 0.1
    F.axis = 2*vector(cos(angle + pi/2), sin(angle + pi/2), 0.5)
    torque.axis = cross(rvec, F.axis)
print(clicks, torque.axis)
