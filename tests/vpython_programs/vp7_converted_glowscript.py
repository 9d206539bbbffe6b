from vpython import *
#GlowScript 2.7 VPython
# A GlowScript program converted to VPython 7 (the header left as a comment, the import
# added) that still uses GlowScript's names: display, gdisplay and floats in range.
scene = display(title="converted", width=400, height=300)
g = gdisplay(title="x(t)", xtitle="t", ytitle="x")
xs = gcurve(color=color.magenta)
cube = box(pos=vec(-1, 0, 0), size=vec(0.3, 0.3, 0.3), color=color.yellow)
for t in range(0, 1, 0.05):
    rate(20)
    cube.pos.x = -1 + 2*t
    xs.plot(t, cube.pos.x)
print("x =", round(cube.pos.x, 2))
