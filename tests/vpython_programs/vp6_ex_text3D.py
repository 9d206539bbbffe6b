from visual import *
# Stands for VPython 6's examples/text3D.py: 3D text with its measures marked.
# Features: text(text=, align=, depth=, color=) and its start, upper_left,
# upper_right, lower_left, height, descent, widths, axis; curves given pos= lists whose
# points are read back as c.pos[0], c.pos[1] (arrays); labels and spheres at the marks.
scene.range = 3
scene.autocenter = True
word = text(text="Spring", align='left', depth=0.2, color=color.cyan)
up = (word.upper_left - word.start).norm()
rise = curve(color=color.orange, radius=0.02,
             pos=[word.start - 0.2*word.axis,
                  word.start - 0.2*word.axis + word.height*up])
label(pos=0.5*(rise.pos[0] + rise.pos[1]), xoffset=-30, text='height')
span = curve(color=color.orange, radius=0.02,
             pos=[word.upper_left + 0.1*up, word.upper_right + 0.1*up])
label(pos=0.5*(span.pos[0] + span.pos[1]), yoffset=30, text='width')
for corner in [word.upper_left, word.upper_right, word.lower_left, word.start]:
    sphere(pos=corner, radius=0.05, color=color.red)
print(len(word.widths), round(word.descent, 3))
