# labels: box or not, alignments, offsets with the leader line, several lines, border, font
from vpython import *
scene.width, scene.height = 480, 320
scene.background = color.white
a = sphere(pos=vector(-3, 1, 0), radius=0.5, color=color.red)
b = box(pos=vector(2.5, -1, 0), size=vector(1, 1, 1), color=color.blue)
label(pos=a.pos, text='sphere', xoffset=40, yoffset=40, color=color.black)
label(pos=b.pos, text='box<br>two lines', xoffset=-60, yoffset=30, border=8, color=color.blue)
label(pos=vector(0, 2.2, 0), text='centre, no box', box=False, color=color.black, height=16)
label(pos=vector(-2, -1.5, 0), text='left', align='left', background=color.yellow, color=color.black)
label(pos=vector(0, 0, 0), text='right', align='right', font='serif', color=color.red, opacity=0)
label(pos=vector(1, 1, 0), text='mono 20', font='monospace', height=20, line=False, color=color.green)
