"""Drawing: the off-screen backend, VPython's camera, meshes, the scenes, the overlays and
matplotlib's look. A view is handed states (or arrays) and the settings it draws with;
it never steps the physics and never sees a whole config."""
