from visual import *
# VPython 6 keeps a curve's points as numpy arrays: a program reads them and edits
# them in place, a column, a row or the whole array at a time.
line = curve(x=arange(5), color=color.red)       # five points along x
line.pos[:, 1] += 0.5                             # every y up by a half
line.x *= 2                                       # every x doubled
line.pos[3] = (1, 2, 3)                           # one point moved
line.z = -1.0                                     # one z for all
print("line", line.pos.tolist())

dots = points(pos=[(0, 0, 0), (1, 1, 1)], color=color.blue)
dots.pos[-1] = (2, 2, 2)
dots.y += 1
print("dots", dots.pos.tolist())

band = curve(pos=[(x, 0, 0) for x in range(4)])
band.color = [(1, 0, 0), (0, 1, 0), (0, 0, 1), (1, 1, 1)]   # a colour for each point
band.red = 0.5                                               # every point's red
print("colours", band.color.tolist())
band.pos = band.pos + vector(0, 1, 0)                        # the whole array, set
band.y = array([1.0, 2, 3, 4, 5, 6])      # six points: the last one repeated, then y set
print("band", band.pos.tolist())
print("band_colours", band.color.tolist())
