"""The VTK renderer of VPython's canvases: objects batched into actors (meshes, instances,
impostors), lit and blended by GlowScript's rules, labels drawn over the frame, and the
camera's autoscale."""
