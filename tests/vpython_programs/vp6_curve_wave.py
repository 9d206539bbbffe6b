from visual import *
# A rope lifted a little each step through its y array (c.y += ...), between two
# red posts that mark where it starts and where it ends.
scene = display(width=300, height=300, background=(0, 0, 0))
scene.autoscale = False
scene.range = 5
box(pos=(-4.6, -2, 0), size=(0.4, 0.4, 0.4), color=color.red)
box(pos=(4.6, 2, 0), size=(0.4, 0.4, 0.4), color=color.red)
rope = curve(x=arange(-4, 4.01, 0.5), y=-2, radius=0.08, color=color.yellow)
for step in range(100):
    rate(50)
    rope.y += 0.04
print("top", rope.y.max())
