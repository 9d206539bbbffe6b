"""Off-screen OpenGL backends: choose EGL or OSMesa before VTK makes a window.

VTK's PyPI wheels pick their render window class from the environment variable
``VTK_DEFAULT_OPENGL_WINDOW`` when the first window is made. Forcing OSMesa
without libOSMesa on the machine makes VTK crash, so a backend's library is
looked for first and its absence is a :class:`UserError` naming the Debian package.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import os

from ..errors import UserError

BACKENDS = ("auto", "egl", "osmesa")

_WINDOW_CLASS = {"egl": "vtkEGLRenderWindow", "osmesa": "vtkOSOpenGLRenderWindow"}
_LIBRARY = {"egl": ("EGL", "libEGL.so.1", "libegl1 and libegl-mesa0"),
            "osmesa": ("OSMesa", "libOSMesa.so.8", "libosmesa6")}

_selected: str | None = None


def library_present(backend: str) -> bool:
    """True when the shared library the backend needs can be loaded."""
    name, soname, _ = _LIBRARY[backend]
    for candidate in (ctypes.util.find_library(name), soname):
        if not candidate:
            continue
        try:
            ctypes.CDLL(candidate)
            return True
        except OSError:
            continue
    return False


def select(backend: str = "auto") -> str:
    """Choose the off-screen backend for this process and return "egl" or "osmesa".

    ``auto`` takes EGL when libEGL is present, else OSMesa. Must be called before
    the first render window is made; a second call with another backend is an error.
    """
    global _selected
    if backend not in BACKENDS:
        raise UserError(f"--backend: unknown backend {backend!r} (choose from {', '.join(BACKENDS)})")
    if backend == "auto":
        backend = "egl" if library_present("egl") else "osmesa"
    if not library_present(backend):
        _, soname, package = _LIBRARY[backend]
        raise UserError(f"--backend {backend}: {soname} not found; install Debian's {package} "
                        f"(apt-get install {package.replace(' and ', ' ')})")
    if _selected is not None and _selected != backend:
        raise UserError(f"--backend {backend}: this process already renders with {_selected}")
    _selected = backend
    os.environ["VTK_DEFAULT_OPENGL_WINDOW"] = _WINDOW_CLASS[backend]
    _quiet_vtk()
    return backend


def _quiet_vtk() -> None:
    """Keep VTK's warnings and log lines off stderr."""
    from vtkmodules.vtkCommonCore import vtkLogger, vtkObject  # noqa: PLC0415  heavy: VTK

    vtkObject.GlobalWarningDisplayOff()
    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_OFF)


def window_backend(render_window) -> str:
    """Which backend a VTK render window really is ("egl", "osmesa" or its class name)."""
    name = render_window.GetClassName()
    for backend, cls in _WINDOW_CLASS.items():
        if name == cls:
            return backend
    return name


def gl_info(render_window) -> dict[str, str]:
    """Vendor, renderer and version strings of a render window's OpenGL context."""
    info = {}
    for line in render_window.ReportCapabilities().splitlines():
        for key in ("vendor", "renderer", "version"):
            prefix = f"OpenGL {key} string:"
            if line.startswith(prefix):
                info[key] = line[len(prefix):].strip()
    return info
