from visual import *
# Stands for VPython 6's examples/wave.py: pulses on two strings of masses and springs,
# each in its own window. Features: several display()s, curve(x=arange(...),
# display=, color=, and attributes of its own such as k= and mass=), the curve's pos
# and x as arrays (band.x[:20], band.pos[1:] - band.pos[:-1]), band.pos = band.pos + ...
windows = [display(x=0, y=30 + 180*i, width=500, height=160) for i in range(2)]
windows[0].title = "k=4 N/m, mass=1 kg"
windows[1].title = "k=4 N/m, mass=0.25 kg"
strings = [curve(x=arange(-40, 40), display=windows[0], color=color.orange, k=4., mass=1.0),
           curve(x=arange(-40, 40), display=windows[1], color=color.cyan, k=4., mass=0.25)]
for s in strings:
    s.radius = 0.5
    s.momentum = zeros((80, 3), float)
    s.momentum[:20, 1] = sin((s.x[:20] + 40)*pi/20.0)*2
dt = 0.1
t = 0
while t < 8:
    rate(50)
    for s in strings:
        s.momentum[0] = s.momentum[-1] = vector(0, 0, 0)
        s.pos = s.pos + s.momentum/s.mass*dt
        pull = s.k*(s.pos[1:] - s.pos[:-1])
        s.momentum[:-1] = s.momentum[:-1] + pull*dt
        s.momentum[1:] = s.momentum[1:] - pull*dt
    t += dt
