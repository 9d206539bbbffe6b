"""Which VPython a program was written for, and how to run it in CPython.

Three dialects run unmodified:

- **VPython 7** (``from vpython import *``, ``import vpython``): run as it is. One
  converted from GlowScript (its header left as a comment, ``#GlowScript 3.0 VPython``)
  also gets the GlowScript names it uses and never defines (``display``, ``gdisplay``;
  ``range`` of floats), with a note (:func:`.glowscript.converted_names`).
- **VPython 6** (``from visual import *``, ``import visual``, ``visual.graph``, ...):
  run as it is, with :mod:`.visual6`'s modules importable and VPython 6's vectors
  (tuples as vectors, vectors as sequences) turned on for the run.
- **Web VPython / GlowScript** (first line ``GlowScript 3.2 VPython``, ``GlowScript 1.1
  VPython``, ``Web VPython 3.2``, or that header left as a comment in a program that
  imports nothing; no imports): the header is blanked (line numbers stay), the program
  runs with the names its page gives it (VPython's, math's, ``random()``, ...;
  :func:`.glowscript.names`, by the header's version), and the leniencies of its compiler
  that CPython lacks are put in: ``"t = " + t`` concatenates a string and a number, as
  JavaScript does; a function ignores extra arguments; RapydScript's ``else if``,
  ``return x = y`` and ``def`` as an expression are read as Python
  (:mod:`.rapydscript`, with a note naming the lines); GlowScript 1.x and 2.0's
  ``scene.caption.text(s)``. A JavaScript program (``GlowScript 3.2 JavaScript``,
  ``JavaScript 3.2``, or ``GlowScript 3.2`` with no language, which GlowScript reads as
  JavaScript, when it is not Python) is refused in one line.

:func:`detect` reads the source; :func:`compile_program` gives the code to run.
"""

from __future__ import annotations

import ast
import html
import math
import numbers
import re
from decimal import Decimal
from dataclasses import dataclass, field
from typing import Any

from ...errors import UserError
from .glowscript import before
from .rapydscript import Translation, fix_tree, translate

# ide.js (parseVersionHeader): the first line names the language and version
# ("GlowScript 3.2 VPython", "Web VPython 3.2", "GlowScript 2.7 RapydScript", "GlowScript
# 3.2 JavaScript", "JavaScript 3.2"; "GlowScript 3.2" alone is JavaScript; "3.3dev")
_HEADER = re.compile(r"^\s*(GlowScript|Web\s*VPython|JavaScript)\s+(\d+(?:\.\d+)*)(?:dev)?"
                     r"(?:[ \t]+(\w+))?", re.I)
# the header left as a comment when a program was saved as a .py file or converted
_COMMENTED = re.compile(r"^\s*#+\s*(GlowScript|Web\s*VPython)\s+(\d+(?:\.\d+)*)", re.I)
_VISUAL = re.compile(r"^\s*(from\s+(visual|vis)(\.\w+)?\s+import|import\s+(visual|vis)\b)",
                     re.M)
_VPYTHON = re.compile(r"^\s*(from\s+vpython(\.\w+)?\s+import|import\s+vpython\b)", re.M)


@dataclass
class Dialect:
    """What a program was written for: ``kind`` is "vpython7", "vpython6" or
    "glowscript"; ``name`` is what the user is told ("Web VPython 3.2")."""

    kind: str
    name: str
    version: str = ""
    language: str = "VPython"
    notes: list[str] = field(default_factory=list)
    #: a VPython 7 program converted from GlowScript: its commented header's version
    converted: str = ""
    #: the names a converted program uses and never binds (:func:`compile_program`)
    unbound: set[str] = field(default_factory=set)



def detect(source: str) -> Dialect:
    """The dialect of ``source``, from its header line or its imports."""
    m = _HEADER.match(_first_code(source.splitlines()))
    if m:
        return _glowscript(m)
    imports_vpython = _VPYTHON.search(source)
    if _VISUAL.search(source) and not imports_vpython:
        return Dialect("vpython6", "VPython 6")
    commented = next((c for c in map(_COMMENTED.match, _first_lines(source)) if c), None)
    if commented and not imports_vpython:       # saved from the page as a .py file
        family = "GlowScript" if commented.group(1).lower().startswith("glow") \
            else "Web VPython"
        version = commented.group(2)
        return Dialect("glowscript", f"{family} {version}", version)
    if commented:
        return Dialect("vpython7", "VPython 7", converted=commented.group(2))
    return Dialect("vpython7", "VPython 7")


def _glowscript(m: re.Match) -> Dialect:
    """A header line's dialect: a program with no language named after "GlowScript 2.7"
    is JavaScript to GlowScript (``language`` "", decided when it is compiled)."""
    family, version, language = m.group(1).lower(), m.group(2), (m.group(3) or "").lower()
    if family.startswith("web"):
        return Dialect("glowscript", f"Web VPython {version}", version)
    if family == "javascript" or language == "javascript":
        return Dialect("glowscript", f"GlowScript {version}", version, "JavaScript")
    named = {"vpython": "VPython", "rapydscript": "RapydScript"}.get(language, language)
    return Dialect("glowscript", f"GlowScript {version}", version, named)


def _first_lines(source: str, count: int = 6) -> list[str]:
    """The first ``count`` lines that are not blank."""
    return [line for line in source.splitlines() if line.strip()][:count]


def strip_header(source: str) -> str:
    """The source with its GlowScript header line blanked (so line numbers stay)."""
    lines = source.splitlines(keepends=True)
    first = _first_code(lines)
    if _HEADER.match(first):
        lines[lines.index(first)] = "\n"
    return "".join(lines)


def _first_code(lines: list[str]) -> str:
    """The first line that is neither blank nor a comment (the header's place; comments
    such as ``# -*- coding: utf-8 -*-`` may come before it in a saved file)."""
    return next((line for line in lines if line.strip()
                 and not line.lstrip().startswith("#")), "")


def _is_text(node: ast.AST) -> bool:
    """A node that is certainly a string: a literal, an f-string, ``str(...)``, or a
    sum with one of those in it."""
    if isinstance(node, ast.Constant):
        return isinstance(node.value, str)
    if isinstance(node, ast.JoinedStr):
        return True
    if isinstance(node, ast.Call) and isinstance(node.func, ast.Name):
        return node.func.id in ("str", "repr", "format", "__gs_add__")
    if isinstance(node, ast.BinOp) and isinstance(node.op, ast.Add):
        return _is_text(node.left) or _is_text(node.right)
    return False


class _TextPlus(ast.NodeTransformer):
    """``"a" + x`` → ``__gs_add__("a", x)``: JavaScript's ``+`` joins a string and a
    number; CPython raises. Only sums with a string in them are touched, so the
    arithmetic of the program runs at full speed."""

    def visit_BinOp(self, node: ast.BinOp) -> ast.AST:
        self.generic_visit(node)
        if isinstance(node.op, ast.Add) and (_is_text(node.left) or _is_text(node.right)):
            call = ast.Call(func=ast.Name("__gs_add__", ast.Load()),
                            args=[node.left, node.right], keywords=[])
            return ast.copy_location(call, node)
        return node

    def visit_AugAssign(self, node: ast.AugAssign) -> ast.AST:
        self.generic_visit(node)
        if isinstance(node.op, ast.Add) and _is_text(node.value) and \
                isinstance(node.target, ast.Name):
            value = ast.Call(func=ast.Name("__gs_iadd__", ast.Load()),
                             args=[ast.Name(node.target.id, ast.Load()), node.value],
                             keywords=[])
            return ast.copy_location(ast.Assign(targets=[node.target], value=value), node)
        return node


def _js_number(x: float) -> str:
    """A number as JavaScript writes it: ``2.0`` → ``2``, ``1e-05`` → ``0.00001``,
    ``1e-07`` → ``1e-7``, ``nan`` → ``NaN``, ``inf`` → ``Infinity``."""
    if isinstance(x, numbers.Integral):
        return str(int(x))
    x = float(x)
    if math.isnan(x):
        return "NaN"
    if math.isinf(x):
        return "Infinity" if x > 0 else "-Infinity"
    if x.is_integer() and abs(x) < 1e21:
        return str(int(x))
    text = repr(x)
    if "e" not in text:
        return text
    mantissa, exponent = text.split("e")
    e = int(exponent)
    if -6 <= e < 21:
        return format(Decimal(text), "f")
    return f"{mantissa}e{'+' if e > 0 else '-'}{abs(e)}"


def _js_scalar(value: Any) -> bool:
    """A value JavaScript's ``+`` writes into text by itself (a number, a bool, None, a
    vector, a list: a JavaScript array); anything else keeps Python's ``+`` (and its
    ``__radd__``)."""
    return value is None or isinstance(value, (numbers.Number, list, tuple)) or \
        hasattr(value, "_xyz")


def js_text(value: Any) -> str:
    """A value as JavaScript's ``+`` writes it into a string (``1.0`` → ``"1"``)."""
    if isinstance(value, bool):
        return "true" if value else "false"
    if value is None:
        return "null"
    if isinstance(value, numbers.Number):
        return _js_number(value)
    if hasattr(value, "_xyz"):
        return "< " + ", ".join(_js_number(c) for c in value._xyz()) + " >"
    if isinstance(value, (list, tuple)):        # an array's toString: items joined by ","
        return ",".join("" if v is None else js_text(v) for v in value)
    return str(value)


def gs_add(a: Any, b: Any) -> Any:
    """``a + b`` as GlowScript does it: text and a number (bool, vector) joined, else
    Python's ``+``."""
    if isinstance(a, str) and not isinstance(b, str) and _js_scalar(b):
        return a + js_text(b)
    if isinstance(b, str) and not isinstance(a, str) and _js_scalar(a):
        return js_text(a) + b
    return a + b


def gs_iadd(a: Any, b: Any) -> Any:
    """``a += b``: joined as :func:`gs_add` for text and a number, else Python's ``+=``
    (a list extended in place)."""
    if isinstance(a, str) or (isinstance(b, str) and _js_scalar(a)
                              and not isinstance(a, list)):
        return gs_add(a, b)
    a += b
    return a


def gs_same(a: Any, b: Any) -> bool:
    """JavaScript's ``===``, which RapydScript makes of ``is``: numbers, text and bools
    compare by value (``True is 1`` is false), anything else by identity."""
    for kind in (bool, str):
        if isinstance(a, kind) or isinstance(b, kind):
            return isinstance(a, kind) and isinstance(b, kind) and a == b
    if isinstance(a, numbers.Number) and isinstance(b, numbers.Number):
        return a == b
    return a is b


class _IsLiteral(ast.NodeTransformer):
    """``key is 'left'`` → ``key == 'left'``: RapydScript compiles ``is`` to ``===``,
    which compares values (the GlowScript docs write key handlers so)."""

    def visit_Compare(self, node: ast.Compare) -> ast.AST:
        self.generic_visit(node)
        if len(node.ops) == 1 and isinstance(node.ops[0], (ast.Is, ast.IsNot)) and any(
                isinstance(x, ast.Constant) and x.value is not None
                for x in (node.left, node.comparators[0])):
            same = ast.Call(func=ast.Name("__gs_same__", ast.Load()),
                            args=[node.left, node.comparators[0]], keywords=[])
            if isinstance(node.ops[0], ast.IsNot):
                same = ast.UnaryOp(op=ast.Not(), operand=same)
            return ast.copy_location(same, node)
        operands = [node.left, *node.comparators]
        ops = []
        for op, left, right in zip(node.ops, operands, operands[1:]):
            literal = any(isinstance(x, ast.Constant) and x.value is not None
                          and not isinstance(x.value, bool) for x in (left, right))
            if literal and isinstance(op, ast.Is):
                op = ast.Eq()
            elif literal and isinstance(op, ast.IsNot):
                op = ast.NotEq()
            ops.append(op)
        node.ops = ops
        return node


class _Push(ast.NodeTransformer):
    """``L.append(a, b)`` → ``__gs_push__(L, a, b)``: RapydScript's list ``append`` is
    JavaScript's ``push``, which takes several items. Only calls with two or more
    positional arguments are touched (a Python ``append`` takes one)."""

    def visit_Call(self, node: ast.Call) -> ast.AST:
        self.generic_visit(node)
        f = node.func
        if isinstance(f, ast.Attribute) and f.attr == "append" and len(node.args) >= 2 \
                and not node.keywords and not any(isinstance(a, ast.Starred)
                                                  for a in node.args):
            call = ast.Call(func=ast.Name("__gs_push__", ast.Load()),
                            args=[f.value, *node.args], keywords=[])
            return ast.copy_location(call, node)
        return node


def gs_push(target: Any, *items: Any) -> Any:
    """JavaScript's ``push`` for a list; anything else's own ``append``."""
    if isinstance(target, list):
        target.extend(items)
        return len(target)
    return target.append(*items)


def _names_loaded(node: ast.AST) -> set[str]:
    return {n.id for n in ast.walk(node) if isinstance(n, ast.Name)
            and isinstance(n.ctx, ast.Load)}


def _hoistable(node: ast.AST) -> bool:
    """A top-level ``def`` whose definition needs nothing from the program (no
    decorators, constant defaults), so that it can run before the code above it."""
    if not isinstance(node, ast.FunctionDef) or node.decorator_list:
        return False
    defaults = node.args.defaults + [d for d in node.args.kw_defaults if d is not None]
    return all(isinstance(d, ast.Constant) or (isinstance(d, ast.UnaryOp)
                                              and isinstance(d.operand, ast.Constant))
               for d in defaults)


def hoist_functions(tree: ast.Module) -> ast.Module:
    """JavaScript hoists function declarations: a GlowScript program may name a function
    above its ``def`` (``button(bind=start)`` ... ``def start(b):``). Each top-level
    function used above its definition is also defined at the top."""
    early: list[ast.stmt] = []
    for i, node in enumerate(tree.body):
        if not _hoistable(node):
            continue
        used_above = any(node.name in _names_loaded(stmt) for stmt in tree.body[:i])
        if used_above:
            early.append(node)
    if early:
        tree.body = early + tree.body
    return tree


class _ExtraArguments(ast.NodeTransformer):
    """``def f(x, y)`` called as ``f(0, 0, 0)``: a JavaScript function (RapydScript makes
    one of each ``def``) ignores the arguments it has no parameter for, so each of the
    program's functions without a ``*args`` takes and ignores them."""

    def visit_FunctionDef(self, node: ast.FunctionDef) -> ast.AST:
        self.generic_visit(node)
        if node.args.vararg is None:
            node.args.vararg = ast.copy_location(ast.arg("__gs_ignored__"), node)
        return node

    visit_AsyncFunctionDef = visit_FunctionDef


def transform(tree: ast.Module) -> ast.Module:
    """The GlowScript leniencies CPython lacks, put into a parsed program."""
    tree = _TextPlus().visit(tree)
    tree = _ExtraArguments().visit(tree)
    tree = _IsLiteral().visit(tree)
    tree = _Push().visit(tree)
    tree = hoist_functions(tree)
    return ast.fix_missing_locations(tree)


_SPACES = re.compile(r"[\u00a0\u1680\u2000-\u200b\u202f\u205f\u3000\ufeff]")


def glowscript_whitespace(source: str) -> str:
    """GlowScript's reading of indentation: each leading tab or space is one space, and
    Unicode spaces (pasted from a web page) are plain spaces."""
    lines = []
    for line in _SPACES.sub(" ", source).splitlines(keepends=True):
        body = line.lstrip(" \t")
        lines.append(" " * (len(line) - len(body)) + body)
    return "".join(lines)


def _parse_glowscript(source: str, filename: str) -> tuple[ast.Module, Translation]:
    """The program parsed, as it is or with GlowScript's reading of indentation; failing
    that, with RapydScript's syntax put in Python (:mod:`.rapydscript`). A syntax error
    is the first one CPython finds, or, when only a translation parses that far, the
    error in the translated program (at a line the translation did not touch)."""
    source = strip_header(source)
    texts = (source, glowscript_whitespace(source))
    first = None
    for text in texts:
        try:
            return ast.parse(text, filename, "exec"), Translation(text)
        except SyntaxError as exc:      # TabError, IndentationError, U+00A0 ...
            first = first or exc
    later = None
    for text in texts:
        done = translate(text)
        if not done.changed:
            continue
        try:
            return ast.parse(done.source, filename, "exec"), done
        except SyntaxError as exc:
            if later is None and exc.lineno not in done.touched():
                later = exc
    raise (later or first).with_traceback(None) from None


def compile_program(source: str, filename: str, dialect: Dialect):
    """The program's code object for ``dialect`` (a ``SyntaxError`` is the program's; a
    JavaScript program is refused as a :class:`UserError`). What was translated is said
    in ``dialect.notes``; a converted VPython 7 program's unbound names are kept in
    ``dialect.unbound``."""
    if dialect.kind == "vpython7" and dialect.converted:
        try:
            tree = ast.parse(source, filename, "exec")
        except SyntaxError as exc:
            raise exc.with_traceback(None) from None
        dialect.unbound = unbound_names(tree)
        return compile(tree, filename, "exec")
    if dialect.kind != "glowscript":
        return compile(source, filename, "exec")
    if dialect.language == "JavaScript":
        raise UserError(f"{filename}: {dialect.name} JavaScript is not a VPython program "
                        f"(springscene runs VPython)")
    try:
        tree, done = _parse_glowscript(source, filename)
    except SyntaxError:
        if dialect.language == "":
            raise UserError(f"{filename}: \"{dialect.name}\" with no language after it is a "
                            f"JavaScript program to GlowScript, not a VPython program (its "
                            f"VPython programs begin \"{dialect.name} VPython\")") from None
        raise
    tree = fix_tree(tree, done)
    dialect.notes.extend(done.notes())
    if before(dialect.version, "2.1"):
        tree = _JQueryText().visit(tree)
    return compile(transform(tree), filename, "exec")


def unbound_names(tree: ast.Module) -> set[str]:
    """The names a program reads and never binds anywhere (no assignment, parameter,
    ``def``, ``class``, import or ``global`` of that name)."""
    read, bound = set(), set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Name):
            (read if isinstance(node.ctx, ast.Load) else bound).add(node.id)
        elif isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            bound.add(node.name)
        elif isinstance(node, ast.arg):
            bound.add(node.arg)
        elif isinstance(node, ast.alias):
            bound.add((node.asname or node.name).split(".")[0])
        elif isinstance(node, (ast.Global, ast.Nonlocal)):
            bound.update(node.names)
    return read - bound


class _JQueryText(ast.NodeTransformer):
    """GlowScript 1.x and 2.0 (``canvas.js`` of ``package/glow.1.1.min.js``): a canvas's
    ``title`` and ``caption`` are page elements, written with jQuery's
    ``scene.caption.text(s)``, ``.html(s)`` and ``.append(s)``. Such calls go to
    :func:`gs_jquery`."""

    def visit_Call(self, node: ast.Call) -> ast.AST:
        self.generic_visit(node)
        f = node.func
        if isinstance(f, ast.Attribute) and f.attr in _JQUERY and \
                isinstance(f.value, ast.Attribute) and f.value.attr in ("title", "caption") \
                and not node.keywords and len(node.args) <= 1:
            call = ast.Call(func=ast.Name("__gs_jquery__", ast.Load()),
                            args=[f.value.value, ast.Constant(f.value.attr),
                                  ast.Constant(f.attr), *node.args], keywords=[])
            return ast.copy_location(call, node)
        return node


_JQUERY = ("text", "html", "append")


def gs_jquery(owner: Any, place: str, method: str, *value: Any) -> Any:
    """jQuery's ``text``, ``html`` and ``append`` on a canvas's title or caption:
    ``text(s)`` sets it to ``s`` as plain text, ``html(s)`` as HTML, ``append(s)`` adds
    HTML; with no argument, the text there."""
    if not value:
        return getattr(owner, place)
    if method == "append":
        getattr(owner, f"append_to_{place}")(value[0])
    else:
        text = js_text(value[0])
        setattr(owner, place, html.escape(text, quote=False) if method == "text" else text)
    return owner


#: the helpers :func:`transform` writes calls to, by the names it gives them
HELPERS = {"__gs_add__": gs_add, "__gs_iadd__": gs_iadd, "__gs_same__": gs_same,
           "__gs_push__": gs_push, "__gs_jquery__": gs_jquery}
