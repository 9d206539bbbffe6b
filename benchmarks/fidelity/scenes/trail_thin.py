# Thin default trails (make_trail=True alone: GlowScript draws a curve of radius 0 as a
# tube 4 range/width thick) and where their points go. VPython 7 builds the trail in the
# browser (primitives.js makeTrail, the render loop): a point at each render, so what
# the program does to pos between renders is never seen; no point at a pos not given.
# The loop is slow (rate(15)) so that most iterations reach a render: headless Chromium on
# SwiftShader, on a loaded machine, still goes without an update now and then (its own
# trail points, read from GlowScript: 39 of the 47 a render each step would give, other
# steps missing at each run, at rate(15) and at rate(6) alike), so real VPython's trail
# has a few longer chords where springscene's, a point each render, follows the path.
from vpython import *
scene.width, scene.height = 480, 320
scene.range = 3
arc = sphere(pos=vector(-1, 1, 0), radius=0.15, color=color.cyan, make_trail=True)
late = sphere(radius=0.15, color=color.orange, make_trail=True)    # no pos given
late.pos = vector(1, 1.5, 0)                                       # its trail starts here
steps = sphere(pos=vector(-3.5, -2.2, 0), radius=0.15, color=color.green, make_trail=True)
zigzag = sphere(pos=vector(0.5, -1, 0), radius=0.15, color=color.magenta, make_trail=True)
sleep(3)
for i in range(1, 46):
    rate(15)
    t = 2 * pi * 0.7 * i / 45
    arc.pos = vector(-1 - 1.5 * sin(t), 1.5 * cos(t) - 0.5, 0)
    late.pos = vector(1 + 0.06 * i, 1.5 + 0.6 * sin(3 * t), 0)
    steps.pos.x += 0.07              # two changes an iteration, one render: a straight line
    steps.pos.y += 0.05
    zigzag.pos = zigzag.pos + vector(0.04, 0.8, 0)    # up and back down between renders
    zigzag.pos = zigzag.pos + vector(0.04, -0.8 - 0.02, 0)
