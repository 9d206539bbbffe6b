from visual import *
import sys
# Stands for VPython 6's examples/glinfo.py: a report of the graphics system.
# Features: scene.title, scene.info() (VPython 6's OpenGL report, a string), toggling
# scene.visible, sys.path walked as the example does.
print("Python", sys.version_info[0], "with", len(sys.path), "entries on its path")
scene.title = "Graphics report"
cube = box(color=color.green)
scene.visible = 1
report = scene.info()
print(report)
