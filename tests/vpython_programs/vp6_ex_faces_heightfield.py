from visual import *
# Stands for VPython 6's examples/faces_heightfield.py: a height field drawn as faces.
# Features: classes building a vertex list, faces(frame=, color=) given its pos as a
# list of numpy rows, make_normals(), smooth(), make_twosided(), a numpy grid made by
# broadcasting (x[:, None] + zero), zeros(shape + (3,)).
class Surface:
    def __init__(self):
        self.frame = frame()
        self.skin = faces(frame=self.frame, color=color.magenta)
        self.corners = []

    def quad(self, *v):
        for n in range(len(v) - 2):
            self.corners.extend([v[0], v[n + 1], v[n + 2]])

class Saddle(Surface):
    def __init__(self, xs, hs, zs):
        Surface.__init__(self)
        grid = zeros(xs.shape + (3,), float)
        grid[..., 0], grid[..., 1], grid[..., 2] = xs, hs, zs
        for i in range(xs.shape[0] - 1):
            for j in range(xs.shape[1] - 1):
                self.quad(grid[i, j], grid[i, j + 1], grid[i + 1, j + 1], grid[i + 1, j])
        self.skin.pos = self.corners
        self.skin.make_normals()
        self.skin.smooth()
        self.skin.make_twosided()

scene.forward = (0.3, -0.7, -1)
scene.range = 1.8
u = arange(-1, 1.01, 0.25)
zero = zeros((len(u), len(u)), float)
x, z = u[:, None] + zero, u + zero
surface = Saddle(x, 0.5*x*z, z)
print(len(surface.skin.pos))
