from vpython import *
# Surfaces made of vertex, triangle and quad objects (VPython 7).
# A tetrahedron of four triangles (each with its own three vertices, so its faces are flat)
# beside a sheet of quads whose vertices move: a wave runs across it.

scene.width = 800
scene.height = 500
scene.title = "vertex, triangle and quad"
scene.range = 2.2
scene.forward = vector(0, -0.5, -1)

# the tetrahedron
corners = [vector(1, 1, 1), vector(-1, -1, 1), vector(-1, 1, -1), vector(1, -1, -1)]
colors = [color.red, color.green, color.blue, color.yellow]
centre = vector(-1.2, 0, 0)
for i in range(4):
    a, b, c = [corners[j] for j in range(4) if j != i]
    n = norm(cross(b - a, c - a))
    if dot(n, a) < 0:               # outward, counterclockwise
        b, c = c, b
        n = -n
    vs = [vertex(pos=centre + 0.5*p, normal=n, color=colors[k]) for k, p in
          zip([j for j in range(4) if j != i], [a, b, c])]
    triangle(vs=vs)

# the sheet: (N+1) x (N+1) shared vertices, N x N quads
N = 12
L = 1.6
sheet = []
for i in range(N + 1):
    row = []
    for j in range(N + 1):
        x = 0.3 + L*j/N
        z = -L/2 + L*i/N
        row.append(vertex(pos=vector(x, -0.6, z), normal=vector(0, 1, 0),
                          color=color.hsv_to_rgb(vector(j/N*0.7, 0.9, 1))))
    sheet.append(row)
for i in range(N):
    for j in range(N):
        quad(vs=[sheet[i][j], sheet[i+1][j], sheet[i+1][j+1], sheet[i][j+1]])

t = 0
dt = 0.02
while t < 3:
    rate(50)
    for i in range(N + 1):
        for j in range(N + 1):
            v = sheet[i][j]
            phase = 3*v.pos.x - 4*t
            v.pos.y = -0.6 + 0.15*sin(phase)
            v.normal = norm(vector(-0.45*cos(phase), 1, 0))
    t += dt
