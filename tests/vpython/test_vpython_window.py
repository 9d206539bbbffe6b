"""The VPython renderer draws on plain VTK (springscene.view.window): a run's child process
imports neither ``pyvista.plotting`` nor matplotlib unless the program makes a graph."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

PROGRAM = '''from vpython import *
import sys
ball = sphere(pos=vector(0, 0, 0), radius=0.5, color=color.red)
box(pos=vector(1, 0, 0), size=vector(0.5, 0.5, 0.5), color=color.green, opacity=0.5)
local_light(pos=vector(0, 2, 2), color=color.gray(0.5))
{graph}
for i in range(10):
    rate(50)
    ball.pos.x += 0.05
    {plot}
with open({modules!r}, "w") as f:
    f.write("\\n".join(sorted(sys.modules)))
'''


def _child_modules(tmp_path: Path, with_graph: bool) -> set[str]:
    """The modules of the supervised child when the program ends (its frames drawn)."""
    modules = tmp_path / "modules.txt"
    prog = tmp_path / "prog.py"
    prog.write_text(PROGRAM.format(
        graph="g = gcurve(color=color.blue)" if with_graph else "",
        plot="g.plot(i, i * i)" if with_graph else "pass",
        modules=str(modules)))
    out = tmp_path / "x.gif"
    done = subprocess.run([sys.executable, "-m", "springscene.app", "vpython", str(prog),
                           "--out", str(out), "--draft", "--quiet", "--no-page"],
                          capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr
    assert out.stat().st_size > 0
    return set(modules.read_text().split("\n"))


def _loaded(modules: set[str], package: str) -> bool:
    return any(m == package or m.startswith(package + ".") for m in modules)


@pytest.mark.parametrize("with_graph", [False, True])
def test_child_imports_matplotlib_only_for_a_graph(tmp_path, with_graph):
    modules = _child_modules(tmp_path, with_graph)
    # the program's frames were drawn in this process, with VTK's OpenGL renderer
    assert "springscene.vpython.draw.renderer" in modules
    assert "vtkmodules.vtkRenderingOpenGL2" in modules
    assert "pyvista" in modules                      # pyvista's core (PolyData) stays
    assert not _loaded(modules, "pyvista.plotting")
    assert _loaded(modules, "matplotlib") == with_graph
