GlowScript 2.2 VPython
# A Web VPython program in the RapydScript forms GlowScript accepts and Python does not:
# `else if`, `return x = y`, a `def` passed as an argument, `nonlocal` of a program
# variable. Each ball's colour says which branch ran; its height, what a return assigned.
scene.background = color.white
scene.range = 4
level = 0

def classify(n):
    if n < 0:
        return color.blue
    else if n == 0:
        return color.green
    else  if n < 10:
        return color.red
    else:
        return color.black

def raise_level(step):
    return level = level + step

balls = []
for i, n in enumerate([-5, 0, 5]):
    balls.append(sphere(pos=vec(2*i - 2, 0, 0), radius=0.5, color=classify(n)))

raised = raise_level(1.5)
balls[2].pos.y = level

scene.bind("click", def (evt):
    nonlocal level
    level = -1
)

later = []
later.append(def ():
    balls[0].pos.y = -level
)
for f in later:
    f()
print("raised", raised, "level", level, "ball0 y", balls[0].pos.y)
