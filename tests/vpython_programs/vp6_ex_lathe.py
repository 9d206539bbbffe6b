from visual import *
# Stands for VPython 6's examples/lathe.py: a solid of revolution made of convex slices.
# Features: convex(pos=an N x 3 float64 array, frame=, color=), zeros((n, 3), float64),
# absolute(), arange, a profile split where it turns concave, the frame turned upright
# by setting its axis, scene.autocenter, the `if __name__ == '__main__':` guard.
def band(ring, radii, heights, group, color):
    n = len(ring)
    pts = zeros((len(radii)*n, 3), float64)
    for j in range(len(radii)):
        pts[j*n:(j + 1)*n] = ring*radii[j] + (heights[j], 0, 0)
    return convex(pos=pts, frame=group, color=color)

def turned(profile, length, sides=24, color=(1, 1, 1), pos=(0, 0, 0)):
    radii = absolute(profile)
    a = arange(0, 2*pi, 2*pi/sides)
    ring = zeros((sides, 3), float64)
    ring[:, 1] = cos(a)
    ring[:, 2] = sin(a)
    heights = arange(0, length, float(length)/len(radii))
    group = frame(pos=pos)
    first = 0
    for i in range(1, len(radii) - 1):
        if radii[i + 1] + radii[i - 1] - 2*radii[i] >= 0:     # concave here
            band(ring, radii[first:i], heights[first:i], group, color)
            first = i - 1
    band(ring, radii[first:], heights[first:], group, color)
    return group

if __name__ == '__main__':
    scene.autocenter = True
    vase = turned([0.6, 0.9, 1.0, 0.8, 0.4, 0.3, 0.4, 0.6], 3.0,
                  color=color.orange, pos=(-1.5, 0, 0))
    vase.axis = (0, 1, 0)
    peg = turned([0.3, 0.3, 0.3, 0.3], 2.0, color=color.cyan, pos=(1.5, 0, 0))
    peg.axis = (0, 1, 0)
    print(len(vase.objects), len(peg.objects))
