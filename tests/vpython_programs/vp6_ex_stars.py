from visual import *
# Stands for VPython 6's examples/stars.py: stars pulling on each other; two collide and
# merge. Features: display(title=, width=, height=, range=, forward=), spheres with
# make_trail and interval, N x 3 numpy arrays, pos - pos[:, newaxis], newaxis forces,
# less_equal(...) - identity(N) for hits, nonzero(hit.flat), divmod, trail_object.
G = 6.7e-11
Msun = 2e30
Rsun = 2e9
L = 2e10
scene = display(title="Merging stars", width=400, height=400, range=2*L, forward=(-1, -1, -1))
start = [(-L, 0, 0), (L, 0, 0), (0, L, 0), (0, -L, L/2)]
vel = [(2e4, 0, 0), (-2e4, 0, 0), (0, 0, 3e4), (0, 3e4, 0)]
Nstars = len(start)
stars = [sphere(pos=start[i], radius=Rsun, color=[color.red, color.green, color.blue,
                color.yellow][i], make_trail=True, interval=5) for i in range(Nstars)]
pos = array(start, float)
m = array([Msun]*Nstars).reshape(Nstars, 1)
p = m*array(vel, float)
radius = array([Rsun]*Nstars)
dt = 2000.0
merged = 0
for step in range(400):
    rate(200)
    r = pos - pos[:, newaxis]
    for n in range(Nstars):
        r[n, n] = 1e6
    rmag = sqrt(sum(square(r), -1))
    hit = less_equal(rmag, radius + radius[:, newaxis]) - identity(Nstars)
    F = G*m*m[:, newaxis]*r/rmag[:, :, newaxis]**3
    for n in range(Nstars):
        F[n, n] = 0
    p = p + sum(F, 1)*dt
    pos = pos + (p/m)*dt
    for i in range(Nstars):
        stars[i].pos = pos[i]
    for ij in sort(nonzero(hit.flat)[0]).tolist():
        i, j = divmod(ij, Nstars)
        if not (stars[i].visible and stars[j].visible):
            continue
        p[i] = p[i] + p[j]
        m[i, 0] = m[i, 0] + m[j, 0]
        stars[j].trail_object.visible = False
        stars[j].visible = False
        p[j] = (0, 0, 0)
        m[j, 0] = 1e-30*Msun
        pos[j] = (100*L, 0, 0)
        merged += 1
print(merged, step)
