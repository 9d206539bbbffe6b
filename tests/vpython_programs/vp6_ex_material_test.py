from visual import *
# Stands for VPython 6's examples/material_test.py: a board of VPython 6's materials
# shown on boxes, then on spheres. Features: materials.* looked up by name, objects
# given an attribute of their own (index=), label(box=0), clearing the scene by
# setting every one of scene.objects invisible, scene.fov, scene.center given two
# numbers, scene.mouse.events and scene.kb.keys polled (nobody clicks or types).
names = ['wood', 'rough', 'marble', 'plastic', 'emissive', 'shiny']
lookup = {"wood": materials.wood, "rough": materials.rough, "marble": materials.marble,
          "plastic": materials.plastic, "emissive": materials.emissive,
          "shiny": materials.shiny}

def clear():
    for obj in scene.objects:
        obj.visible = False

def show(index, x, y, as_sphere):
    mat = lookup[names[index]]
    if as_sphere:
        sphere(pos=(x, y, 0), radius=0.35, material=mat, index=index, color=color.orange)
    else:
        box(pos=(x, y, 0), size=(0.6, 0.6, 0.6), material=mat, index=index,
            color=color.orange)
    label(pos=(x, y - 0.5), box=0, text=names[index])

for as_sphere in (False, True):
    clear()
    scene.range = 2.2
    scene.fov = 0.5
    scene.center = (1, 0.5)
    for i in range(len(names)):
        show(i, i % 3, 1 - i//3, as_sphere)
    for n in range(10):
        rate(20)
        if scene.mouse.events:
            scene.mouse.getevent()
        elif scene.kb.keys:
            scene.kb.getkey()
print(len([o for o in scene.objects if o.visible]))
