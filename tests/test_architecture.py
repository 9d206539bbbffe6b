"""The shape of the package (docs/architecture.md): layers importing only downward, a
numpy-only model, drawing that never steps physics, one home per fact, short rooms.

The layer contracts are import-linter's (``[tool.importlinter]`` in pyproject.toml) and
the import rules ruff's (``[tool.ruff]``); these tests run both, so CI holds them.
"""

from __future__ import annotations

import ast
import re
import subprocess
import tomllib
import sys
from pathlib import Path

import pytest
from importlinter.cli import lint_imports

from conftest import ROOT

PACKAGE = ROOT / "springscene"
BIN = Path(sys.executable).parent
MAX_MODULE_LINES = 600
MAX_FUNCTION_LINES = 60
HEAVY = ("vtkmodules", "pyvista", "matplotlib", "cycler", "imageio", "imageio_ffmpeg", "PIL", "tqdm",
         "skimage",
         "distributed",   # Dask's (springscene[dask]): only for batch --scheduler
         "IPython")     # the notebook's: not a dependency, there only inside a notebook
# standard modules slow enough to matter at start-up: importlib.metadata took 50 ms of the
# window before springscene's signal handlers are in place (springscene.app.signals)
SLOW_AT_START = ("importlib.metadata",)


def _modules() -> list[Path]:
    return sorted(PACKAGE.rglob("*.py"))


def _tool(name: str, *args: str) -> subprocess.CompletedProcess:
    return subprocess.run([str(BIN / name), *args], cwd=ROOT, capture_output=True, text=True,
                          timeout=300)


def test_layer_contracts_hold(capsys, monkeypatch):
    """Layers import only downward, the model is numpy only, drawing never imports the
    stepping (timeline, integrators, build, config, science), the VPython rooms import
    only the rooms below them, and no module cycle exists (import-linter, in this
    process: it reads the sources, it imports none)."""
    monkeypatch.chdir(ROOT)
    status = lint_imports(no_cache=True)
    out = capsys.readouterr().out
    assert status == 0, out[-3000:]
    contracts = tomllib.loads((ROOT / "pyproject.toml").read_text())["tool"]["importlinter"]
    names = [c["name"] for c in contracts["contracts"]]
    assert any(c.get("containers") == ["springscene.vpython"] for c in contracts["contracts"])
    for name in names:
        assert f"{name} KEPT" in out, name
    assert "BROKEN" not in out


def test_imports_at_the_top_except_heavy_ones():
    """ruff: no import inside a function (PLC0415) but the marked heavy ones; no unused or
    undefined names (F)."""
    proc = _tool("ruff", "check", "springscene", "--output-format", "concise")
    assert proc.returncode == 0, proc.stdout[-3000:] + proc.stderr[-2000:]


def test_every_import_inside_a_function_is_a_heavy_one_with_its_reason():
    for path in _modules():
        for n, line in enumerate(path.read_text().splitlines(), 1):
            if "noqa: PLC0415" not in line:
                continue
            where = f"{path.relative_to(ROOT)}:{n}"
            assert re.search(r"noqa: PLC0415[^#]*\s+heavy: \S", line), f"{where}: no reason"
            module = re.match(r"\s*(?:from|import)\s+([\w.]+)", line).group(1)
            assert module.split(".")[0] in HEAVY or module in SLOW_AT_START, \
                f"{where}: {module} is not a heavy dependency"


def test_the_model_loads_no_drawing_in_a_fresh_interpreter():
    code = ("import sys\n"
            "import springscene.model.physics, springscene.model.integrators\n"
            "import springscene.model.lattice, springscene.model.timeline\n"
            "import springscene.build, springscene.config\n"
            f"print(sorted(m for m in sys.modules if m.split('.')[0] in {HEAVY!r}))\n")
    proc = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                          cwd=ROOT, timeout=120)
    assert proc.returncode == 0, proc.stderr
    assert proc.stdout.strip() == "[]"


def _functions(tree: ast.AST):
    for node in ast.walk(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            yield node


def test_no_module_or_function_is_too_long():
    long = []
    for path in _modules():
        src = path.read_text()
        if len(src.splitlines()) > MAX_MODULE_LINES:
            long.append(f"{path.relative_to(ROOT)}: {len(src.splitlines())} lines")
        for fn in _functions(ast.parse(src)):
            n = fn.end_lineno - fn.lineno + 1
            if n > MAX_FUNCTION_LINES:
                long.append(f"{path.relative_to(ROOT)}:{fn.lineno} {fn.name}: {n} lines")
    assert not long, "\n".join(long)


def test_drawing_is_handed_settings_and_states_never_a_config():
    """No function of springscene.view takes a whole Config, and none steps the physics."""
    for path in sorted((PACKAGE / "view").glob("*.py")):
        tree = ast.parse(path.read_text())
        for fn in _functions(tree):
            for arg in fn.args.args + fn.args.kwonlyargs:
                note = ast.unparse(arg.annotation) if arg.annotation else ""
                assert not re.search(r"\bConfig\b", note), \
                    f"{path.name}: {fn.name}({arg.arg}: {note})"
        for node in ast.walk(tree):
            if isinstance(node, ast.Attribute) and node.attr in ("step", "run", "play"):
                owner = ast.unparse(node.value)
                assert owner not in ("physics", "timeline"), f"{path.name}: {owner}.{node.attr}"


@pytest.mark.parametrize("word", ['"euler"', '"verlet"', '"rk4"', '"euler-cromer"'])
def test_integrator_names_live_in_their_record(word):
    """Names, orders, stability rules and labels come from model.integrators.INTEGRATORS;
    only the figures' colour per integrator is keyed by name elsewhere."""
    users = [p.relative_to(ROOT) for p in _modules()
             if word in p.read_text() and p.name != "integrators.py"
             and "INTEGRATOR_COLORS" not in p.read_text()]
    assert not users, users


def test_one_si_prefix_table_one_matplotlib_setup_one_set_of_lights():
    prefix_tables = [p.relative_to(ROOT) for p in _modules()
                     if re.search(r'\(1e-12, "p"\)', p.read_text())]
    assert prefix_tables == [Path("springscene/units.py")]
    rc_setups = [p.relative_to(ROOT) for p in _modules()
                 if re.search(r"rc_context\(|rcParams\.update\(|style\.context\(", p.read_text())]
    assert rc_setups == [Path("springscene/view/plotstyle.py")]
    lights = [p.relative_to(ROOT) for p in _modules() if "0.22, 0.44, 0.88" in p.read_text()]
    assert lights == [Path("springscene/view/scene.py")]


def test_no_vpython_module_shares_a_name_with_a_vpython_object():
    """``from vpython import *`` gives objects (``vector``, ``canvas``, ``graph``, ``shapes``,
    ``textures``, ...) from :mod:`springscene.vpython.api`; no module of the rooms they
    live in (api, objects, core) has one of their names, so an import of either can
    never give the other."""
    from springscene.vpython import api

    modules = {p.stem for room in ("api", "objects", "core")
               for p in (PACKAGE / "vpython" / room).glob("*.py")}
    assert not modules & set(api.__all__)
    assert not [n for n in ("vector", "canvas", "graph", "shapes", "textures")
                if isinstance(getattr(api, n), type(api))]


def test_no_module_forwards_names_to_another_of_ours():
    """No proxies between rooms: a ``__getattr__`` in springscene.vpython never forwards a
    name to another springscene module (a wrapper of a stream or of numpy.random may)."""
    for path in (PACKAGE / "vpython").rglob("*.py"):
        tree = ast.parse(path.read_text())
        ours = {a.asname or a.name for n in ast.walk(tree)
                if isinstance(n, ast.ImportFrom) and n.level for a in n.names}
        for node in ast.walk(tree):
            if isinstance(node, ast.FunctionDef) and node.name == "__getattr__":
                targets = {c.args[0].id for c in ast.walk(node) if isinstance(c, ast.Call)
                           and isinstance(c.func, ast.Name) and c.func.id == "getattr"
                           and c.args and isinstance(c.args[0], ast.Name)}
                assert not targets & ours, f"{path.relative_to(ROOT)} forwards to {targets}"


def test_architecture_doc_has_short_tables_naming_every_vpython_module():
    """docs/architecture.md: one short table a package (no cell over 300 characters), and
    each module of springscene.vpython's rooms named in its own room's section."""
    doc = (ROOT / "docs" / "architecture.md").read_text()
    cells = [c for line in doc.splitlines() if line.startswith("|") for c in line.split("|")]
    assert max(map(len, cells)) <= 300
    sections = {}
    for part in doc.split("\n### ")[1:]:
        heading, _, body = part.partition("\n")
        body = body.split("\n## ")[0]
        for room in re.findall(r"`vpython/(\w+)/`", heading):
            sections[room] = body
    for room in sorted(p for p in (PACKAGE / "vpython").iterdir() if (p / "__init__.py").exists()):
        assert room.name in sections, f"no section for vpython/{room.name}/"
        for module in room.glob("*.py"):
            if module.stem != "__init__":
                assert re.search(rf"`(\w+\.)?{module.stem}`", sections[room.name]), module
