from visual.graph import *
# Stands for VPython 6's examples/doublependulum.py: a swinging bar in a frame with a
# second frame hung at its end. Features: only `from visual.graph import *` (which gave
# all of visual: scene, box, frame, cos), scene.title, frames holding boxes and
# cylinders, frame.axis, frame.rotate(axis=, angle=), rate(1/dt).
scene.title = 'Swinging bar'
g = 9.8
L = 0.8                      # pivot to the end of the bar
pivot = vector(0, 0, 0)
scene.center = pivot - vector(0, L/2, 0)
stand = box(pos=(0, -0.5, -0.15), size=(0.06, 1.2, 0.06), color=(0.5, 0.5, 0.6))
arm = frame(pos=pivot)
bar = box(frame=arm, pos=(L/2, 0, 0), size=(L, 0.05, 0.05), color=color.orange)
pin = cylinder(frame=arm, pos=(L, 0, -0.05), axis=(0, 0, 0.1), radius=0.02,
               color=color.yellow)
arm.axis = (0, -1, 0)
tray = frame(pos=pivot + arm.axis*L)
plate = box(frame=tray, pos=(0, -0.05, 0), size=(0.3, 0.02, 0.2), color=color.green)
theta = 1.0                  # from the vertical
omega = 0.0
arm.rotate(axis=(0, 0, 1), angle=theta)
tray.pos = pivot + arm.axis*L
dt = 0.001
t = 0.
while t < 1.5:
    rate(1/dt)
    alpha = -1.5*g/L*sin(theta)          # a uniform bar about its end
    omega += alpha*dt
    theta += omega*dt
    arm.rotate(axis=(0, 0, 1), angle=omega*dt)
    tray.pos = pivot + arm.axis*L
    t = t + dt
print(round(theta, 4))
