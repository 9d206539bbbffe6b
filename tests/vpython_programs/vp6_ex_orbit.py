from visual import *
# Stands for VPython 6's examples/orbit.py: a binary pair circling their centre of mass.
# Features: spheres with make_trail=True, interval=, their own mass and p attributes,
# G*m1*m2*dist/mag(dist)**3, a loop over a list of objects, numbers like 1e11.
G = 6.7e-11
heavy = sphere(pos=(-5e10, 0, 0), radius=1.2e10, color=color.orange,
               make_trail=True, interval=5)
heavy.mass = 3e30
heavy.p = vector(0, 1.5e4, 0)*heavy.mass
light = sphere(pos=(1.5e11, 0, 0), radius=0.8e10, color=color.cyan,
               make_trail=True, interval=5)
light.mass = 1e30
light.p = -heavy.p
dt = 2e4
steps = 0
while steps < 300:
    rate(200)
    dist = light.pos - heavy.pos
    force = G*heavy.mass*light.mass*dist/mag(dist)**3
    heavy.p = heavy.p + force*dt
    light.p = light.p - force*dt
    for star in [heavy, light]:
        star.pos = star.pos + star.p/star.mass*dt
    steps += 1
print(steps, mag(heavy.p + light.p))
