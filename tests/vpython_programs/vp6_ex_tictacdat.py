from visual import *
# Stands for VPython 6's examples/tictacdat.py: the board and the winning lines of a
# tic-tac-toe game as data. Features: a grid drawn as one curve grown with
# append(pos=(x, 0, z)) in nested arange loops, assert, integer division //, lists of
# lines of tuples built with arange.
def board(n=3, ds=1., gridcolor=(.6, .6, .6)):
    assert n > 1, "n must be > 1"
    half = n*ds/2.
    lines = curve(color=gridcolor)
    for z in arange(-half, half + ds/2, ds):
        lines.append(pos=(-half, 0, z))
        lines.append(pos=(half, 0, z))
        lines.append(pos=(-half, 0, z))
    for x in arange(-half, half + ds/2, ds):
        lines.append(pos=(x, 0, -half))
        lines.append(pos=(x, 0, half))
        lines.append(pos=(x, 0, -half))
    return lines

def winning_lines(n=3):
    wins = []
    for a in arange(0, n, 1):
        wins.append([(a, b) for b in range(n)])        # a row
        wins.append([(b, a) for b in range(n)])        # a column
    wins.append([(b, b) for b in range(n)])
    wins.append([(b, n - 1 - b) for b in range(n)])
    return wins

grid = board()
print(len(winning_lines()), "ways to win")
