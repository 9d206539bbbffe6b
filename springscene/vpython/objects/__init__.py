"""VPython's 3D objects as plain Python data: what every object shares and its standard
attributes, the solids, curves and points, labels, triangles and quads, VPython 6's frame,
and the objects made once from meshes (compound, extrusion, 3D text, with the ``shapes``
and ``paths`` libraries they are made from)."""
