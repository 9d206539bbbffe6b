from visual import *
# Stands for VPython 6's examples/gyro2.py: a spinning top on a pedestal, precessing.
# Features: a frame aimed by setting its axis from polar angles, cylinders with
# materials.rough inside it, frame.rotate(angle=) for the spin, a thin trail curve
# grown with append(pos=), several calculation steps per picture.
scene.title = 'Precessing top'
Lshaft = 0.8
r = Lshaft/2
M = 1.0
Rdisk = 0.3
I = 0.5*M*Rdisk**2
g = 9.8
spin = 40.0                              # spin angular velocity
theta = pi/4                             # fixed tilt from the vertical
phi = 0.0
phidot = M*g*r/(I*spin)                  # slow (gyroscopic) precession rate
post = box(pos=(0, -0.4, 0), size=(0.08, 0.8, 0.08), color=(0.4, 0.4, 0.5))
top = frame(axis=(sin(theta)*sin(phi), cos(theta), sin(theta)*cos(phi)))
shaft = cylinder(frame=top, axis=(Lshaft, 0, 0), radius=0.02, color=(0, 1, 0),
                 material=materials.rough)
disk = cylinder(frame=top, pos=(r - 0.04, 0, 0), axis=(0.08, 0, 0), radius=Rdisk,
                color=(0.2, 0.4, 1), material=materials.rough)
trail = curve(radius=0.005, color=(1, 1, 0))
dt = 0.0005
Nsteps = 20
t = 0.
while t < 1.5:
    rate(100)
    for step in range(Nsteps):
        phi = phi + phidot*dt
    top.axis = vector(sin(theta)*sin(phi), cos(theta), sin(theta)*cos(phi))
    top.rotate(angle=spin*dt*Nsteps)
    trail.append(pos=top.pos + top.axis*Lshaft)
    t = t + dt*Nsteps
print(round(phi, 6))
