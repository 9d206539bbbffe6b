"""VPython 7's widgets (``button``, ``slider``, ``menu``, ``checkbox``, ``radio``, ``winput``,
``wtext``) when nobody is there to use them.

A program run headless has no user: controls are made with VPython's arguments,
defaults and checks, keep their initial values, and their ``bind`` functions are
never called. Each control made leaves one note saying so (e.g. ``slider
(bind=set_k): never moved; value stays 0.5``); :func:`skipped` adds other notes
(the canvas reports ``scene.bind``, ``scene.waitfor`` and ``scene.pause`` here), and
:func:`notes` lists them once each, in order. ``wtext`` is real: its text is shown
on the page. :func:`widgets_in_order` gives the controls and wtexts made (and not
deleted) for :mod:`..page.html_page` to draw, each with ``kind`` and ``anchor`` ("title" or
"caption").

VPython facts followed (``vpython/vpython.py`` of vpython-jupyter, and GlowScript's
widget code): every control needs ``bind`` ("bind missing"); ``pos`` is
``scene.caption_anchor`` (default) or ``scene.title_anchor``, and ``print_anchor`` is
refused; keywords a control does not know become plain attributes (``id=`` etc.);
slider: min 0, max 1, step 0.001*(max-min), value = min, length 400, width 10;
menu: ``choices`` required, ``selected`` None unless given (or ``index``); checkbox
and radio: unchecked, radio buttons with one ``name`` form a group; winput: type
'numeric', text '', number None until a user types, 100 x 20 px; button text ''.
"""

from __future__ import annotations

import builtins
import sys
from typing import Any, Callable

from .attributes import Linked

__all__ = [
    "button", "checkbox", "radio", "menu", "slider", "winput", "wtext",
    "skipped", "notes", "reset", "widgets_in_order", "set_placement_hook", "placeholder",
]

_made: list["_Widget"] = []
_notes: list["str | _Control"] = []        # a control stands for its note, made late
_radio_groups: dict[str, list["radio"]] = {}
_hook: Callable[["_Widget"], None] | None = None
_count = 0


def _anchor_of(pos: Any, kind: str) -> str:
    """"title" or "caption" for a widget's ``pos`` (an anchor of a canvas, or VPython's own
    ``[canvas_idx, 1 or 2]`` form).

    Raises
    ------
    AttributeError
        For ``print_anchor`` (VPython 7 refuses it).
    """
    where = getattr(pos, "_anchor", None)
    if where is None and isinstance(pos, (list, tuple)) and len(pos) == 2:
        where = {1: "title", 2: "caption"}.get(pos[1])
    if where == "print" or (isinstance(pos, int) and pos == 3):
        raise AttributeError(f'{kind}: Cannot specify "print_anchor" in VPython 7.')
    return "title" if where == "title" else "caption"


def _fn_name(fn: Any) -> str:
    return getattr(fn, "__name__", None) or repr(fn)


def _short(value: Any) -> str:
    return repr(value) if isinstance(value, str) else str(value)


class _Widget:
    """What every control and wtext has: its kind, anchor, place in order, ``delete()``."""

    kind = "widget"

    def _register(self, pos: Any) -> None:
        global _count
        self.anchor = _anchor_of(pos, self.kind) if pos is not None else "caption"
        _count += 1
        self.seq = _count
        self.deleted = False
        _made.append(self)
        if _hook is not None:
            _hook(self)

    def delete(self) -> None:
        """Remove it from the page."""
        self.deleted = True


class _Control(_Widget):
    """A control: needs ``bind`` (never called here); ``disabled``; unknown keywords kept."""

    _own: tuple[str, ...] = ()

    def _setup(self, args: dict[str, Any]) -> None:
        pos = args.pop("pos", None)
        self.canvas = args.pop("canvas", None)
        if "bind" not in args:
            raise AttributeError("bind missing")
        self._bind = args.pop("bind")
        for a in ("color", "textcolor", "background"):
            if a in args and not all(hasattr(args[a], c) for c in "xyz") \
                    and not (isinstance(args[a], (list, tuple)) and len(args[a]) == 3):
                raise AttributeError(f"{a} must be a vector")
        for a, v in args.items():                  # VPython: own attributes set, others kept
            if a in self._own:
                setattr(self, "_" + a, v)
            else:
                setattr(self, a, v)
        self._register(pos)
        _notes.append(self)

    bind = Linked(readonly="bind cannot be changed",
                  doc="The function a user's action would call (never, here).")
    disabled = Linked(doc="Whether the control is greyed out.")

    def note(self) -> str:
        """What happened to it with nobody there."""
        return f"{self.kind} (bind={_fn_name(self._bind)}): never used"


class button(_Control):
    """A push button (VPython's ``button``): ``text``, ``color``, ``background``, ``disabled``."""

    kind = "button"
    _own = ("text", "color", "textcolor", "background", "disabled")

    def __init__(self, **args: Any) -> None:
        self._text = ""
        self._color = (0.0, 0.0, 0.0)
        self._background = (1.0, 1.0, 1.0)
        self._disabled = False
        if "textcolor" in args:                    # legacy name of color
            args["color"] = args.pop("textcolor")
        self._setup(args)

    text = Linked(doc="The button's text (HTML).")
    color = Linked(doc="Text colour.")
    textcolor = color
    background = Linked(doc="Button colour.")

    def note(self) -> str:
        return f"button {_short(self._text)} (bind={_fn_name(self._bind)}): never clicked"


class checkbox(_Control):
    """A checkbox (VPython's ``checkbox``): ``text``, ``checked`` (False), ``disabled``."""

    kind = "checkbox"
    _own = ("checked", "text", "disabled")

    def __init__(self, **args: Any) -> None:
        self._checked = False
        self._text = ""
        self._disabled = False
        self._setup(args)

    text = Linked(doc="The text beside the box (HTML).")
    checked = Linked(doc="Whether it is ticked.")

    def note(self) -> str:
        state = "checked" if self._checked else "unchecked"
        return (f"checkbox {_short(self._text)} (bind={_fn_name(self._bind)}): "
                f"never clicked; stays {state}")


class radio(_Control):
    """A radio button (VPython's ``radio``): ``text``, ``checked`` (False), ``name`` (a group)."""

    kind = "radio"
    _own = ("checked", "text", "disabled", "name")

    def __init__(self, **args: Any) -> None:
        self._checked = False
        self._text = ""
        self._name = ""
        self._disabled = False
        self._setup(args)
        if not isinstance(self._name, str):
            raise AttributeError("A radio group name must be a string.")
        if self._name:
            _radio_groups.setdefault(self._name, []).append(self)

    text = Linked(doc="The text beside the button (HTML).")

    @property
    def checked(self) -> bool:
        """Whether it is on; turning one on turns the others of its group off."""
        return self._checked

    @checked.setter
    def checked(self, value: bool) -> None:
        if self._checked == value:
            return
        for r in _radio_groups.get(self._name, []) if self._name else []:
            r._checked = False
        self._checked = value

    name = Linked(readonly="Cannot change the name attribute of a radio widget.",
                  doc="The group's name ('' for none); fixed.")

    def note(self) -> str:
        state = "checked" if self._checked else "unchecked"
        return (f"radio {_short(self._text)} (bind={_fn_name(self._bind)}): "
                f"never clicked; stays {state}")


class menu(_Control):
    """A drop-down menu (VPython's ``menu``): ``choices`` (required), ``selected`` or ``index``."""

    kind = "menu"
    _own = ("selected", "choices", "index", "disabled")

    def __init__(self, **args: Any) -> None:
        self._selected: Any = None
        self._disabled = False
        if "choices" not in args:
            raise AttributeError("A menu must have a a list of choices.")
        self._choices = list(args.pop("choices"))
        if "index" in args:
            args["selected"] = self._choices[args.pop("index")]
        self._setup(args)

    choices = Linked(list, doc="The menu's entries.")
    selected = Linked(doc="The chosen entry, or None.")

    @property
    def index(self) -> int | None:
        """The chosen entry's position, or None."""
        if self._selected is None:
            return None
        return self._choices.index(self._selected)

    @index.setter
    def index(self, value: int) -> None:
        self._selected = self._choices[value]

    def note(self) -> str:
        return (f"menu (bind={_fn_name(self._bind)}): never changed; "
                f"selected stays {_short(self._selected)}")


def _fixed() -> Linked:
    """A slider attribute VPython fixes once the slider is made."""
    return Linked(readonly="{name} cannot be changed after creating a slider",
                  doc="The slider's {name} (fixed once made).")


class slider(_Control):
    """A slider (VPython's ``slider``): ``min`` 0, ``max`` 1, ``step`` 0.001*(max-min),
    ``value`` (= min), ``length`` 400, ``width`` 10, ``vertical``, ``align``; fixed once made
    except ``value`` and ``disabled``."""

    kind = "slider"
    _own = ("vertical", "min", "max", "step", "value", "length", "width", "left", "right",
            "top", "bottom", "align", "disabled")

    def __init__(self, **args: Any) -> None:
        self._vertical = False
        self._min = args.get("min", 0)
        self._max = args.get("max", 1)
        self._step = 0.001 * (self._max - self._min)
        self._value = self._min
        self._length = 400
        self._width = 10
        self._left = self._right = self._top = self._bottom = 0
        self._align = "left"
        self._disabled = False
        self._setup(args)

    vertical = _fixed()
    min = _fixed()
    max = _fixed()
    step = _fixed()
    length = _fixed()
    width = _fixed()
    left = _fixed()
    right = _fixed()
    top = _fixed()
    bottom = _fixed()
    align = _fixed()

    value = Linked(doc="The slider's value.")

    def note(self) -> str:
        return (f"slider (bind={_fn_name(self._bind)}): never moved; "
                f"value stays {_short(self._value)}")


class winput(_Control):
    """A text box (VPython's ``winput``): ``prompt``, ``type`` 'numeric' or 'string',
    ``text`` (''), ``number`` (None: nobody typed), ``width`` 100, ``height`` 20."""

    kind = "winput"
    _own = ("width", "height", "text", "type", "disabled")

    def __init__(self, **args: Any) -> None:
        self._text = ""
        self._type = "numeric"
        self._number = None
        self._width = 100
        self._height = 20
        self._disabled = False
        self.prompt = ""
        self._setup(args)
        if self._type not in ("numeric", "string"):
            raise AttributeError('A winput type must be "numeric" or "string".')

    text = Linked(doc="The text in the box.")
    number = Linked(readonly="Cannot change the winput {name} attribute.",
                    doc="The typed text's value for type 'numeric' (None: nothing typed).")
    width = Linked(readonly="Cannot change the winput {name} attribute.",
                   doc="Box width in pixels (fixed).")
    height = Linked(readonly=True, doc="Box height in pixels.")
    type = Linked(readonly="Cannot change the winput {name} attribute.",
                  doc="'numeric' or 'string' (fixed).")

    def note(self) -> str:
        return (f"winput (bind={_fn_name(self._bind)}): nothing typed; "
                f"text stays {_short(self._text)}")


class wtext(_Widget):
    """Text in the title or caption area that the program can change (VPython's ``wtext``).

    Parameters
    ----------
    text : str
        HTML, shown as it is when the program ends.
    pos : anchor, optional
        ``scene.caption_anchor`` (default) or ``scene.title_anchor``.
    """

    kind = "wtext"

    def __init__(self, **args: Any) -> None:
        self._text = str(args.pop("text", ""))
        pos = args.pop("pos", None)
        for a, v in args.items():
            setattr(self, a, v)
        self._register(pos)

    text = Linked(str, doc="The text (HTML); setting it changes what the page shows.")


# --------------------------------------------------------------------------- module state

def skipped(note: str) -> None:
    """Record something a user would have done that did not happen here."""
    _notes.append(str(note))


# what ``input()`` answers when no one is at a terminal: a small positive number reads as
# a count, a speed or an angle, and "press Enter" prompts take it too
NO_USER_ANSWER = "1"


def program_input(prompt: Any = "") -> str:
    """A program's ``input()``: the terminal's answer when there is a user there or a
    line waiting on standard input; with neither, ``NO_USER_ANSWER``, noted."""
    stdin = sys.stdin
    if stdin is not None and not stdin.closed and stdin.isatty():
        return builtins.input(prompt)
    print(prompt, end="", flush=True)
    line = stdin.readline() if stdin is not None and not stdin.closed else ""
    if line:
        return line.rstrip("\n")
    print(NO_USER_ANSWER)
    skipped(f"input({str(prompt)!r}): no user at a terminal; answered {NO_USER_ANSWER!r}")
    return NO_USER_ANSWER


def notes() -> list[str]:
    """Every note, each once, in the order first made (a control's tells its value now)."""
    return list(dict.fromkeys(n if isinstance(n, str) else n.note() for n in _notes))


def widgets_in_order() -> list[_Widget]:
    """The controls and wtexts made (and not deleted), in the order made."""
    return [w for w in _made if not w.deleted]


def set_placement_hook(fn: Callable[[_Widget], None] | None) -> None:
    """Call ``fn(widget)`` as each widget is made (the canvas can then put
    :func:`placeholder` into its caption or title, so the page shows the widget where the
    program put it among the text); None to stop."""
    global _hook
    _hook = fn


def placeholder(w: _Widget) -> str:
    """The HTML comment :func:`springscene.vpython.page.html_page.write_page` replaces with ``w``."""
    return f"<!--vpython-widget-{w.seq}-->"


def reset() -> None:
    """Forget every control, wtext and note (before running another program)."""
    global _count
    _made.clear()
    _notes.clear()
    _radio_groups.clear()
    _count = 0
