from vpython import *
# Newton's second law, in 3D letters, with a washer and a star made by extrusion.
# Written in the style of a PHYS 1 demo: make the objects, then spin them with rate().

scene.title = "F = ma"
scene.background = color.white
scene.range = 4

law = text(text="F = ma", pos=vec(0, 1.2, 0), align="center", height=1,
           color=color.blue, depth=0.3)

# A washer: a ring-shaped shape (circle with thickness) pushed along a short straight path
washer = extrusion(path=[vec(0, 0, 0), vec(0, 0, -0.4)],
                   shape=shapes.circle(radius=0.8, thickness=0.4),
                   pos=vec(-2, -1.2, 0), color=color.orange)

# A star pushed along a line, twisted a little at each of the path's points
star = extrusion(path=paths.line(start=vec(0, 0, 0), end=vec(0, 0, -0.6), np=7),
                 shape=shapes.star(n=5, radius=0.9, iradius=0.4),
                 twist=0.05, pos=vec(2, -1.2, 0), color=color.red,
                 end_face_color=color.yellow)

t = 0
dt = 0.01
while t < 2:
    rate(100)
    washer.rotate(angle=0.02, axis=vec(0, 1, 0))
    star.rotate(angle=-0.02, axis=vec(0, 0, 1))
    t += dt
