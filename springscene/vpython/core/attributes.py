"""VPython's linked attributes, each declared once: how a value is checked, where it is
kept, what a change does.

An attribute of a VPython object (``ball.pos``, ``label.text``, ``curve.radius``) does
three things when a program sets it: it turns the value into what the object keeps
(``_vec(value, "pos")``, ``float(value)``), refusing bad input with VPython's message,
naming the attribute; it stores it in a private slot (``_pos``); and it tells whoever
needs to know (``_dirty`` for the renderer, which redraws only changed objects, or a
method of the object, such as a curve's ``_touch``). A class says that in one line::

    pos = Linked(_vec, then="_on_pos_change", hook=True, live=True)
    text = Linked(str, dirty=True)
    canvas = Linked(readonly="canvas cannot be modified")

:class:`Linked` is a declaration, not the descriptor a program meets: when its class is
made (``__set_name__``) it puts in its place a plain ``property``. Its read is
``operator.attrgetter(store)``, or for a ``live`` vector a small function that hooks the
vector on a program's first read. Its write is a small function over the attribute's
slot, check and change method, one a kind of change (:func:`_typed_writers`,
:func:`_named_writers`), chosen when the class is made, so that a write tests nothing
about its declaration. Writes go through ``setattr``, so a class's own ``__setattr__``
(an extrusion's, 3D text's, a shared default vector's) sees them as it would
``self._pos = value``. Nothing is stored per object: the property is the class's.
"""

from __future__ import annotations

from operator import attrgetter
from sys import intern
from typing import Callable

_READ_ONLY = object()      # ``readonly=True``: Python's own "has no setter" refusal


class Linked:
    """An attribute declared once; its class gets a ``property`` made from it.

    Parameters
    ----------
    convert
        What a value set becomes: a type (``float``, ``int``, ``str``, ``bool``, ``list``)
        is called with the value; any other callable with the value and the attribute's
        name, so its error names it (``_vec(value, "axis")``: "axis must be a vector").
        None: the value is kept as given.
    dirty
        A change marks the object changed (``self._dirty = True``): the renderer redraws it.
    then
        The name of a method a change calls, after the value is stored (a curve's
        ``_touch``, a solid's ``_on_pos_change``).
    hook
        The stored vector's in-place changes (``ball.pos.x = 2``) call ``then`` too.
    notify
        A vector's own component: a change calls the hook its owner put in the vector's
        ``_on_change``, if any.
    live
        A vector read as a program gets it (:meth:`..objects.standard_attributes.standard._live`): the
        object's own, copied from a shared default first, hooked on the first read.
    get, set
        The attribute's read or write, when it is its own (a default read from the
        canvas; a write linked to other attributes); ``set`` converts for itself.
    readonly
        A write refused: True with Python's own ``AttributeError``, or a message
        (``{name}`` is the attribute's name) as VPython words it.
    store
        Where the value is kept (default: ``"_" + name``).
    doc
        The attribute's docstring (``{name}`` is its name).

    One declaration under two names (``textcolor = color``) is one attribute under both,
    as one ``property`` would be; ``a = b = Linked()`` is one attribute too, kept in
    ``_a``.
    """

    __slots__ = ("convert", "dirty", "then", "hook", "notify", "live", "get", "set",
                 "readonly", "store", "doc", "made")

    def __init__(self, convert: Callable | None = None, *, dirty: bool = False,
                 then: str | None = None, hook: bool = False, notify: bool = False,
                 live: bool = False, get: Callable | None = None, set: Callable | None = None,
                 readonly: bool | str = False, store: str | None = None,
                 doc: str | None = None) -> None:
        changes = sum((bool(dirty), then is not None, notify, set is not None, bool(readonly)))
        if changes > 1 or (hook and then is None) or (live and get is not None) or (
                convert is not None and (set is not None or readonly)):
            raise TypeError("Linked: at most one of dirty, then, notify, set and readonly; "
                            "hook only with then; live not with get; convert not with set "
                            "or readonly")
        self.convert, self.dirty, self.then, self.hook = convert, dirty, then, hook
        self.notify, self.live, self.get, self.set = notify, live, get, set
        self.readonly = _READ_ONLY if readonly is True else readonly or None
        self.store, self.doc = store, doc
        self.made: property | None = None

    def __set_name__(self, owner: type, name: str) -> None:
        # a second name for the same declaration (``textcolor = color``) is the same attribute
        if self.made is None:
            self.made = self.build(name)
        setattr(owner, name, self.made)
        self.made.__set_name__(owner, name)     # Python's "has no setter" names it, as written

    def build(self, name: str) -> property:
        """The ``property`` this declaration makes for the attribute ``name``."""
        store = intern(self.store or "_" + name)    # the slot's name, as an attribute's is
        fget = self.get or (_live_reader(store) if self.live else attrgetter(store))
        if self.readonly is _READ_ONLY:
            fset = None
        elif self.readonly is not None:
            fset = _refuser(self.readonly.replace("{name}", name))
        elif self.set is not None:
            fset = self.set
        else:
            fset = _writer(self, name, store)
        return property(fget, fset, None, self.doc and self.doc.replace("{name}", name))


def _live_reader(store: str) -> Callable:
    def read(self):
        v = getattr(self, store)
        if v._on_change is None:         # hooked on a program's first read
            v = self._live(store)
        return v
    return read


def _as_given(value):
    return value


def _writer(d: Linked, name: str, store: str) -> Callable:
    """The write ``d`` declares: one a kind of change, in two families, one for a type
    (``convert(value)``), one for a check that names the attribute (``convert(value,
    name)``), so that no write tests which it is."""
    convert = _as_given if d.convert is None else d.convert
    if isinstance(convert, type) or convert is _as_given:
        if d.hook:
            raise TypeError(f"Linked {name}: hook=True needs a vector check such as _vec")
        return _typed_writers(convert, store, d.then)["notify" if d.notify else _action(d)]
    if d.notify:
        raise TypeError(f"Linked {name}: notify=True is a vector component's: convert=float")
    return _named_writers(convert, name, store, d.then)[_action(d)]


def _action(d: Linked) -> str:
    if d.then is not None:
        return "hooked" if d.hook else "then"
    return "dirty" if d.dirty else "store"


def _typed_writers(convert: Callable, store: str, then: str | None) -> dict[str, Callable]:
    def write(self, value):
        setattr(self, store, convert(value))

    def write_dirty(self, value):
        setattr(self, store, convert(value))
        self._dirty = True

    def write_then(self, value):
        setattr(self, store, convert(value))
        getattr(self, then)()

    def write_notify(self, value):
        setattr(self, store, convert(value))
        if self._on_change is not None:
            self._on_change()

    return {"store": write, "dirty": write_dirty, "then": write_then, "notify": write_notify}


def _named_writers(convert: Callable, name: str, store: str,
                   then: str | None) -> dict[str, Callable]:
    def write(self, value):
        setattr(self, store, convert(value, name))

    def write_dirty(self, value):
        setattr(self, store, convert(value, name))
        self._dirty = True

    def write_then(self, value):
        setattr(self, store, convert(value, name))
        getattr(self, then)()

    def write_hooked(self, value):
        value = convert(value, name)
        setattr(self, store, value)
        changed = value._on_change = getattr(self, then)
        changed()

    return {"store": write, "dirty": write_dirty, "then": write_then, "hooked": write_hooked}


def _refuser(message: str) -> Callable:
    def refuse(self, value):
        raise AttributeError(message)
    return refuse
