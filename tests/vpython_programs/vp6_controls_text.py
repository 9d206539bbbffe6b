from visual.controls import *
# A VPython 6 program that imports only visual.controls (which gave all of visual):
# a window of controls, 3D text moved through its own frame, a gdots series of square
# dots, and the renderer's report.
c = controls(title="Speed")
s = slider(pos=(0, 0), min=0, max=10, value=5)
ball = sphere(pos=(-2, 0, 0), radius=0.5, color=color.red)
word = text(text="hi", height=0.6, depth=0.1, align="center", color=color.yellow)
dots = gdots(shape="square", size=2, color=color.blue)
report = scene.info()
print(report.splitlines()[0])
t = 0
while t < 1:
    rate(20)
    ball.pos.x += 0.1
    word.frame.pos = ball.pos + vector(0, 1, 0)
    dots.plot(pos=(t, sin(t)))
    t += 0.05
print(dots.shape, round(word.pos.x, 2), round(word.pos.y, 2))
