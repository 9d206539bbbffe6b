from vpython import *
# The Moon orbits the Earth: a gravitational force model, momentum principle.
# (Radii of the Earth and Moon are drawn 10 times too large so they can be seen.)

scene.width = 800
scene.height = 500
scene.title = "The Moon orbiting a spinning Earth"
scene.background = color.black

G = 6.7e-11
mEarth = 6e24
mMoon = 7e22
REarth = 6.4e6
RMoon = 1.75e6
dEM = 3.84e8

earth = sphere(pos=vector(0, 0, 0), radius=10*REarth, texture=textures.earth, shininess=0.2)
moon = sphere(pos=vector(dEM, 0, 0), radius=10*RMoon, color=color.gray(0.85),
              texture=textures.rough, make_trail=True, trail_color=color.yellow, retain=300)
scene.range = 1.2*dEM
scene.forward = vector(0, -0.35, -1)

vMoon = sqrt(G*mEarth/dEM)          # a circular orbit
pMoon = mMoon*vector(0, 0, -vMoon)
omega = 2*pi/86164                  # one turn of the Earth a sidereal day

t = 0
dt = 3600
while t < 28*24*3600:
    rate(200)
    r = moon.pos - earth.pos
    F = -G*mEarth*mMoon*norm(r)/mag(r)**2
    pMoon = pMoon + F*dt
    moon.pos = moon.pos + (pMoon/mMoon)*dt
    earth.rotate(angle=omega*dt, axis=vector(0, 1, 0))
    t = t + dt
