"""RapydScript's syntax that Python lacks, put into Python line for line.

GlowScript compiles a Web VPython program with RapydScript-NG (``lib/rapydscript/
compiler.js`` in vpython/glowscript), whose parser accepts a few forms CPython does not,
and course programs use them:

- ``else if c:`` (``if_()`` reads any statement after ``else``): read as ``elif c:``;
- ``return x = y`` (an assignment is an expression there): ``x = y; return x``, ``x``
  bound where JavaScript binds it (a local of the function if it has one by that name,
  else the enclosing function's, else the program's);
- a ``def`` used as an expression, ``scene.bind("click", def (evt):`` with its body
  below and the call closed on the line after it; or ``f = def(x): ...``: the function is
  defined on the ``def``'s line under a name of its own and the call, joined, takes the
  line that closed it (its code keeps the line the statement began on, for tracebacks);
- ``nonlocal x`` where no enclosing function has an ``x`` (the whole program is a
  function in GlowScript, so it means the program's ``x``): ``global x``.

:func:`translate` works on the tokens of the source and keeps every line where it was;
:func:`fix_tree` does the scoping part on the parsed program. Only a program CPython
cannot parse as it is is translated (``compiling``).
"""

from __future__ import annotations

import ast
import io
import re
import tokenize
from dataclasses import dataclass, field

_SKIP = (tokenize.NL, tokenize.COMMENT, tokenize.INDENT, tokenize.DEDENT,
         tokenize.ENCODING)
_ASSIGN = {"=", "+=", "-=", "*=", "/=", "//=", "%=", "**=", "&=", "|=", "^=", ">>=",
           "<<=", "@="}
_OPEN, _CLOSE = "([{", ")]}"


@dataclass
class Translation:
    """A source as Python: the lines each kind of change touched (1-based), the names a
    ``return x = y`` assigns at each line, and the statements whose code moved to a
    later line (that line → the line they began on)."""

    source: str
    else_if: list[int] = field(default_factory=list)
    return_assign: dict[int, list[str]] = field(default_factory=dict)
    anonymous_def: list[int] = field(default_factory=list)
    moved: dict[int, int] = field(default_factory=dict)
    nonlocal_global: list[int] = field(default_factory=list)

    @property
    def changed(self) -> bool:
        return bool(self.touched())

    def touched(self) -> set[int]:
        """The lines a translation wrote."""
        return {*self.else_if, *self.return_assign, *self.anonymous_def, *self.moved}

    def notes(self) -> list[str]:
        """One ``springscene: note:`` line for each kind of change, naming its lines."""
        kinds = [(self.else_if, "`else if` read as `elif`"),
                 (sorted(self.return_assign), "`return x = y` read as `x = y; return x`"),
                 (self.anonymous_def, "a `def` used as an expression made a named function"),
                 (self.nonlocal_global, "`nonlocal` of a program variable read as `global`")]
        return [f"{_lines(lines)}: {what} (RapydScript's syntax, as GlowScript reads it)"
                for lines, what in kinds if lines]


def _lines(lines: list[int]) -> str:
    lines = sorted(set(lines))
    return ("line " if len(lines) == 1 else "lines ") + ", ".join(map(str, lines))


def _tokens(source: str) -> list[tokenize.TokenInfo]:
    """The source's tokens, up to an unclosed string or bracket if it has one."""
    tokens: list[tokenize.TokenInfo] = []
    try:
        tokens.extend(tokenize.generate_tokens(io.StringIO(source).readline))
    except (tokenize.TokenError, SyntaxError):
        pass
    return tokens


def _logical_lines(tokens: list[tokenize.TokenInfo]) -> list[list[tokenize.TokenInfo]]:
    """The tokens of each logical line (no comments, blank lines or indentation)."""
    lines, current = [], []
    for tok in tokens:
        if tok.type in _SKIP:
            continue
        if tok.type in (tokenize.NEWLINE, tokenize.ENDMARKER):
            if current:
                lines.append(current + [tok])
            current = []
        else:
            current.append(tok)
    return lines


def translate(source: str) -> Translation:
    """``source`` with RapydScript's forms put in Python, every line where it was."""
    result = Translation(source)
    for _ in range(1000):            # one anonymous def at a time, each pass re-read
        tokens = _tokens(result.source)
        lines = result.source.splitlines(keepends=True)
        logical = _logical_lines(tokens)
        if not _anonymous_def(lines, logical, result):
            break
        result.source = "".join(lines)
    lines = result.source.splitlines(keepends=True)
    for toks in _logical_lines(_tokens(result.source)):
        _return_assign(lines, toks, result)     # (edits right of an ``else if``'s)
        _else_if(lines, toks, result)
    result.source = "".join(lines)
    return result


def _edit(lines: list[str], row: int, start: int, end: int, text: str) -> None:
    """Replace columns ``start:end`` of 1-based line ``row``."""
    line = lines[row - 1]
    lines[row - 1] = line[:start] + text + line[end:]


def _else_if(lines: list[str], toks: list[tokenize.TokenInfo], result: Translation) -> None:
    """A logical line beginning ``else if`` begins ``elif``."""
    if len(toks) > 2 and toks[0].string == "else" and toks[1].string == "if" \
            and toks[0].start[0] == toks[1].start[0]:
        row = toks[0].start[0]
        _edit(lines, row, toks[0].start[1], toks[1].end[1], "elif")
        result.else_if.append(row)


def _return_at(toks: list[tokenize.TokenInfo]) -> int | None:
    """Where a logical line's ``return`` is: first, or after a compound statement's
    colon on the same line (``if c: return x = y``)."""
    depth = 0
    for i, tok in enumerate(toks):
        if tok.type == tokenize.OP and tok.string in _OPEN:
            depth += 1
        elif tok.type == tokenize.OP and tok.string in _CLOSE:
            depth -= 1
        elif depth == 0 and tok.type == tokenize.NAME and tok.string == "return" and \
                (i == 0 or toks[i - 1].string == ":"):
            return i
    return None


def _return_assign(lines: list[str], toks: list[tokenize.TokenInfo],
                   result: Translation) -> None:
    """``return T = V`` (or ``T += V``) → ``T = V; return T`` on the same lines."""
    at = _return_at(toks)
    if at is None:
        return
    toks = toks[at:]
    depth = 0
    for i, tok in enumerate(toks[1:-1], 1):
        if tok.type == tokenize.NAME and tok.string == "lambda":
            return
        if tok.type == tokenize.OP and tok.string in _OPEN:
            depth += 1
        elif tok.type == tokenize.OP and tok.string in _CLOSE:
            depth -= 1
        elif depth == 0 and tok.type == tokenize.OP and tok.string in _ASSIGN:
            break
    else:
        return
    if i == 1 or toks[0].start[0] != tok.start[0]:
        return
    first, last = toks[0].start[0], toks[-2].end[0]
    target = lines[first - 1][toks[1].start[1]:tok.start[1]].strip()
    end_col = toks[-2].end[1]
    _edit(lines, last, end_col, end_col, f"; return {target}")
    _edit(lines, first, toks[0].start[1], toks[1].start[1], "")
    result.return_assign[first] = _names_in(target)


def _names_in(target: str) -> list[str]:
    """The plain names an assignment's target binds (``a``, ``a, b``; none for ``a.x``,
    ``a[0]``)."""
    if not re.fullmatch(r"[\w\s,()]+", target):
        return []
    try:
        return [n.id for n in ast.walk(ast.parse(target, mode="eval"))
                if isinstance(n, ast.Name)]
    except SyntaxError:
        return []


def _anonymous_def(lines: list[str], logical: list[list[tokenize.TokenInfo]],
                   result: Translation) -> bool:
    """The first ``def`` used as an expression made a named function; whether one was."""
    for toks in logical:
        for i, tok in enumerate(toks):
            if tok.type != tokenize.NAME or tok.string != "def" or i == 0 or \
                    toks[i - 1].string == "async":
                continue
            return _name_it(lines, toks, i, result)
    return False


def _name_it(lines: list[str], toks: list[tokenize.TokenInfo], i: int,
             result: Translation) -> bool:
    """``toks[i]`` is a ``def`` inside an expression: rewrite it, or leave it (False)."""
    row = toks[i].start[0]
    j = i + 1
    if toks[j].type == tokenize.NAME:           # a named function expression
        j += 1
    if toks[j].string != "(":
        return False
    depth, k = 0, j
    for k in range(j, len(toks)):
        depth += toks[k].string in _OPEN and toks[k].type == tokenize.OP
        depth -= toks[k].string in _CLOSE and toks[k].type == tokenize.OP
        if depth == 0:
            break
    colon = k + 1
    if colon >= len(toks) or toks[colon].string != ":" or toks[colon].start[0] != row:
        return False
    params = lines[row - 1][toks[j].start[1]:toks[k].end[1]]
    start = toks[0].start[0]
    indent = len(lines[start - 1]) - len(lines[start - 1].lstrip(" \t"))
    pad = lines[start - 1][:indent]
    # ``f = def(x): ...``: a def statement named f, on the same line
    if i == 2 and toks[0].type == tokenize.NAME and toks[1].string == "=" and start == row:
        rest = lines[row - 1][toks[colon].start[1]:]
        lines[row - 1] = f"{pad}def {toks[0].string}{params}{rest}"
        result.anonymous_def.append(row)
        return True
    if toks[colon + 1].start[0] == row or start != row:   # one-line body, or a call above
        return False
    body_end = _body_end(lines, row, indent)
    if body_end is None:
        return False
    closing = lines[body_end - 1].lstrip(" \t")
    if not closing or closing[0] not in _CLOSE + ",":
        return False
    name = f"anonymous_def_{row}"
    head = lines[row - 1][:toks[i].start[1]].strip()
    lines[row - 1] = f"{pad}def {name}{params}:\n"
    lines[body_end - 1] = f"{pad}{head}{name}{closing}"
    result.anonymous_def.append(row)
    result.moved[body_end] = result.moved.pop(row, row)
    return True


def _body_end(lines: list[str], row: int, indent: int) -> int | None:
    """The line after a block starting below ``row`` that is indented past ``indent``."""
    seen = False
    for n in range(row + 1, len(lines) + 1):
        text = lines[n - 1]
        stripped = text.lstrip(" \t")
        if not stripped.strip() or stripped.startswith("#"):
            continue
        if len(text) - len(stripped) <= indent:
            return n if seen else None
        seen = True
    return None


# ---- the scoping part, on the parsed program ----------------------------------------------

def _bound_here(fn: ast.FunctionDef | ast.AsyncFunctionDef, skip: set[int]) -> set[str]:
    """The names ``fn`` binds itself (parameters, assignments, imports, defs), leaving out
    the statements at the lines in ``skip``."""
    args = fn.args
    names = {a.arg for a in args.posonlyargs + args.args + args.kwonlyargs}
    names |= {a.arg for a in (args.vararg, args.kwarg) if a is not None}
    declared: set[str] = set()
    stack = list(fn.body)
    while stack:
        node = stack.pop()
        if isinstance(node, (ast.Global, ast.Nonlocal)):
            declared |= set(node.names)
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            names.add(node.name)
            continue
        if isinstance(node, ast.Lambda):
            continue
        if isinstance(node, ast.stmt) and node.lineno in skip:
            continue
        if isinstance(node, ast.Name) and isinstance(node.ctx, (ast.Store, ast.Del)):
            names.add(node.id)
        elif isinstance(node, ast.alias):
            names.add((node.asname or node.name).split(".")[0])
        stack.extend(ast.iter_child_nodes(node))
    return names - declared


def _functions(tree: ast.AST, outer: tuple = ()):
    """Each function with the functions around it, outermost first."""
    for node in ast.iter_child_nodes(tree):
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef)):
            yield node, outer
            yield from _functions(node, outer + (node,))
        elif not isinstance(node, ast.Lambda):
            yield from _functions(node, outer)


def fix_tree(tree: ast.Module, done: Translation) -> ast.Module:
    """The scoping of the translated forms, and moved statements back at their lines."""
    for fn, outer in list(_functions(tree)):
        _declare_return_targets(fn, outer, done)
        _nonlocal_to_global(fn, outer, done)
    _move_back(tree, done.moved)
    return tree


def _declare_return_targets(fn, outer: tuple, done: Translation) -> None:
    """A ``return x = y``'s ``x`` bound where JavaScript binds it."""
    lines = {n.lineno for n in ast.walk(fn) if isinstance(n, ast.stmt)
             and n.lineno in done.return_assign}
    here = {line for line in lines if _directly_in(fn, line)}
    if not here:
        return
    local = _bound_here(fn, here)
    for name in sorted({n for line in here for n in done.return_assign[line]} - local):
        around = next((f for f in reversed(outer) if name in _bound_here(f, set())), None)
        decl = ast.Nonlocal([name]) if around is not None else ast.Global([name])
        fn.body.insert(0, ast.copy_location(decl, fn.body[0]))


def _directly_in(fn, line: int) -> bool:
    """Whether a statement at ``line`` is ``fn``'s own (not a nested function's)."""
    stack = list(fn.body)
    while stack:
        node = stack.pop()
        if isinstance(node, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef,
                             ast.Lambda)):
            continue
        if isinstance(node, ast.stmt) and node.lineno == line:
            return True
        stack.extend(ast.iter_child_nodes(node))
    return False


def _nonlocal_to_global(fn, outer: tuple, done: Translation) -> None:
    """``nonlocal x`` with no enclosing function binding ``x``: the program's ``x``."""
    for node in fn.body:
        if not isinstance(node, ast.Nonlocal):
            continue
        free = [n for n in node.names
                if not any(n in _bound_here(f, set()) for f in outer)]
        if not free:
            continue
        node.names = [n for n in node.names if n not in free]
        fn.body.insert(fn.body.index(node), ast.copy_location(ast.Global(free), node))
        if not node.names:
            fn.body.remove(node)
        done.nonlocal_global.append(node.lineno)


def _move_back(tree: ast.Module, moved: dict[int, int]) -> None:
    """A statement whose code a translation moved down to another line reports the line it
    began on."""
    if not moved:
        return
    for stmt in ast.walk(tree):
        if not isinstance(stmt, ast.stmt) or stmt.lineno not in moved:
            continue
        if isinstance(stmt, (ast.FunctionDef, ast.AsyncFunctionDef, ast.ClassDef)):
            continue
        line, origin = stmt.lineno, moved[stmt.lineno]
        for node in ast.walk(stmt):
            if getattr(node, "lineno", None) != line:
                continue
            if node.end_lineno == node.lineno:
                node.end_lineno = origin
            node.lineno = origin
