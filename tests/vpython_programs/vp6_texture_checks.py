from visual import *
# A VPython 6 program texturing boxes with pictures made from numbers: a luminance
# checkerboard over the whole box (its colour multiplying it), an RGB "sign" on one face
# only; halfway the first box's material is swapped for a finer board.
scene.range = 3
scene.background = (0.8, 0.8, 0.8)
board = array([[0, 0, 1, 1], [0, 0, 1, 1], [1, 1, 0, 0], [1, 1, 0, 0]], float)
checks = materials.texture(data=board, mapping="rectangular", interpolate=False)
sign = materials.texture(data=[[color.red, color.blue], [color.blue, color.red]],
                         mapping="sign", interpolate=False)
left = box(pos=(-1.3, 0, 0), axis=(0, 0, 1), size=(2, 2, 2), color=color.orange,
           material=checks)
right = box(pos=(1.3, 0, 0), axis=(0, 0, 1), size=(2, 2, 2), color=color.green,
            material=sign)
t = 0
while t < 1:
    rate(20)
    t += 0.05
    if abs(t - 0.5) < 0.01:
        fine = materials.texture(data=tile(board, (2, 2)), mapping="rectangular",
                                 interpolate=False)
        left.material = fine
print(checks.mapping, sign.texture_value["place"])
