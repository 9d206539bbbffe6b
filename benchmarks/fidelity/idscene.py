"""The "ids" variant of a fidelity scene: the same VPython 7 program with code appended
that paints every object one flat colour of a palette, so that a picture of it splits
into one silhouette per object (:func:`springscene.view.imagediff.id_masks`).

The appended code runs unchanged in real VPython 7 and in springscene. It

* hides labels and clears trails (they have no id: the whole-picture numbers measure them),
* makes every other object opacity 1, shininess 0, untextured, not emissive, and lights
  the scene with a white ambient light alone (no lights): GlowScript's shader
  (shaders/opaque_render_fragment.shader, ``lightAt``) then gives ``light_ambient *
  diffuse_color``, the colour itself, flat, for every kind of object. (``emissive`` is not
  flat there: it darkens by ``min(1, 1.1 (1.5 N.V)^0.4)`` towards the outline, and helices,
  arrows, extrusions and points ignore it and come out black with no lights),
* sets a black background,
* builds compounds and extrusions white (a line after ``from vpython import *`` wraps
  ``compound`` and ``extrusion``): GlowScript keeps their parts' colours in the vertices
  and multiplies them by the object's ``color`` (compound.js; springscene does the same),
  so only a white-built one shows its id colour as it is,
* numbers the objects in an order both renderers agree on. ``scene.objects`` is a Python
  ``set`` in real VPython (``canvas._objz`` in vpython.py), so its order is not
  creation order: objects are sorted by kind and then by position (the first point for a
  curve or points), and each scene keeps its objects at distinct places,
* writes the numbering (kind, position, palette index) to a JSON file beside the picture,
  so the harness can check both renderers numbered the same objects alike.
"""
from __future__ import annotations

import itertools

# Colours with components in {0, 0.5, 1} and at least one component 1: an anti-aliased
# edge against the black background (the colour times a coverage) is never near another
# palette colour's exact value, except where it is exactly half of a pure colour, and
# those half colours (max component 0.5) are left out.  Pure colours come first.
_LEVELS = (0.0, 0.5, 1.0)
PALETTE: tuple[tuple[float, float, float], ...] = tuple(sorted(
    (c for c in itertools.product(_LEVELS, repeat=3) if max(c) == 1.0),
    key=lambda c: (sum(v == 0.5 for v in c), c[::-1])))

_CODE = '''

# ---- springscene fidelity harness: every object a flat id colour (benchmarks/fidelity) ----
def _fidelity_ids(_out, _palette):
    import json as _json
    def _kind(o):
        return type(o).__name__.lower()
    def _where(o):
        try:
            if _kind(o) in ("curve", "points"):
                p = o.point(0)["pos"]
            else:
                p = o.pos
            return [round(p.x, 3), round(p.y, 3), round(p.z, 3)]
        except Exception:
            return [0.0, 0.0, 0.0]
    objs = []
    for o in list(scene.objects):
        if _kind(o) == "label":
            o.visible = False
            continue
        if getattr(o, "make_trail", False):
            o.make_trail = False
            o.clear_trail()
        objs.append(o)
    objs.sort(key=lambda o: (_kind(o), _where(o)))
    table = []
    for i, o in enumerate(objs):
        c = _palette[i % len(_palette)]
        if getattr(o, "texture", None) is not None:
            o.texture = None
        o.color = vector(c[0], c[1], c[2])
        if _kind(o) in ("curve", "points"):
            for n in range(o.npoints):
                o.modify(n, color=vector(c[0], c[1], c[2]))
        o.emissive = False
        o.shininess = 0
        if _kind(o) not in ("curve", "points"):
            o.opacity = 1
        table.append({"kind": _kind(o), "pos": _where(o), "id": i})
    scene.background = color.black
    scene.ambient = color.white
    scene.lights = []
    with open(_out, "w") as fh:
        _json.dump(table, fh)

_fidelity_ids(@OUT@, @PALETTE@)
'''


_WHITE_PARTS = (
    "\n# ---- springscene fidelity harness: compounds and extrusions built white ----\n"
    "def compound(objs, _compound=compound, **args):\n"
    "    for o in objs:\n"
    "        o.color = vector(1, 1, 1)\n"
    "    return _compound(objs, **args)\n"
    "def extrusion(_extrusion=extrusion, **args):\n"
    "    args['color'] = vector(1, 1, 1)\n"
    "    return _extrusion(**args)\n")


def _after_import(source: str) -> str:
    lines = source.split("\n")
    for n, line in enumerate(lines):
        if line.replace(" ", "") == "fromvpythonimport*":
            return "\n".join(lines[:n + 1]) + _WHITE_PARTS + "\n".join(lines[n + 1:])
    return source


def ids_program(source: str, table_path: str) -> str:
    """The program ``source`` with the id-colouring code appended (and compounds and
    extrusions built white); the numbering of the objects is written to ``table_path``
    (JSON) when the program reaches its end."""
    source = _after_import(source)
    code = _CODE.replace("@OUT@", repr(str(table_path)))
    code = code.replace("@PALETTE@", repr([list(c) for c in PALETTE]))
    return source.rstrip("\n") + "\n" + code
