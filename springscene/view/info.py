"""What springscene renders with: backend, OpenGL renderer, library versions."""

from __future__ import annotations

import platform
from importlib.metadata import version

from . import backend


def info(backend_name: str = "auto") -> dict[str, str]:
    chosen = backend.select(backend_name)
    from vtkmodules.vtkRenderingCore import vtkRenderWindow, vtkRenderer  # noqa: PLC0415  heavy: VTK
    import vtkmodules.vtkRenderingOpenGL2  # noqa: PLC0415, F401  heavy: VTK; registers the OpenGL windows

    rw = vtkRenderWindow()
    rw.SetOffScreenRendering(1)
    rw.SetSize(8, 8)
    rw.AddRenderer(vtkRenderer())
    rw.Render()
    gl = backend.gl_info(rw)
    out = {
        "backend": f"{backend.window_backend(rw)} (asked: {backend_name}, chosen: {chosen})",
        "render window": rw.GetClassName(),
        "GL vendor": gl.get("vendor", "?"),
        "GL renderer": gl.get("renderer", "?"),
        "GL version": gl.get("version", "?"),
        "python": platform.python_version(),
    }
    for pkg in ("springscene", "vtk", "pyvista", "numpy", "imageio", "imageio-ffmpeg", "pillow"):
        out[pkg] = version(pkg)
    rw.Finalize()
    return out
