"""VPython's objects as numpy triangle meshes, with no drawing library: unit meshes of each
kind, where copies go, helices, tubes and points, textured layouts, thinning on screen."""
