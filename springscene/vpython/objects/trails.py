"""Where ``make_trail`` puts a trail's points: at VPython's renders, or at ``pos`` changes.

Web VPython and VPython 7 build an object's trail in the browser (GlowScript,
``lib/glow/primitives.js``: ``makeTrail``, ``attach_trail``, ``__update_trail``;
``lib/glow/WebGLRenderer.js``: the render loop's ``cvs.trails``). Their rules, kept here:

- At construction the trail takes the object's colour (or ``trail_color``) and, when the
  program gave ``pos``, that point (and that setting of ``pos`` is the first change an
  ``interval`` counts). Without ``pos`` it waits until ``pos`` is set.
- A ``curve`` trail with no ``interval`` gets a point at each render (60 a program second,
  :mod:`..core.runtime`; not at each video frame: a ``retain`` then keeps as many seconds
  of trail as in VPython at any frame rate): the object's position when it moved since
  the last such point, at most ``pps`` a second, never while the object is invisible.
  Positions in between are never seen: the trail is the path sampled at the renders. A
  video frame between two renders shows the object up to 1/60 s of its motion past the
  trail's end (in a browser, the picture of the last render shows both there).
- With ``interval = n`` (a ``points`` trail has ``interval = 1`` unless given), every
  n-th change of ``pos`` (in place too: ``ball.pos.x = 1``) adds a point, the first
  change always when the trail is empty; renders add nothing.
- A point takes the trail's colour when it is added: a new ``trail_color`` colours the
  points to come (the trail's colour is the object's when it was made, or ``trail_color``).
- ``make_trail = False`` stops the trail (its points stay); ``True`` again starts a new
  piece at the object. ``clear_trail()`` empties every piece, and the next render or
  counted change starts afresh.

VPython 6 (``visual``) kept the trail in Python and added a point at every change of
``pos``, ``x``, ``y`` or ``z`` (``src/core/primitive.cpp`` ``set_pos``, ``vis/primitives.py``
``trail_update``): :class:`..standard_attributes.standard` keeps that rule itself.

The objects whose trail follows the renders are listed here (:func:`follow`);
``at_render`` is called at each render by :mod:`..api.attachments`.
"""

from __future__ import annotations

from fractions import Fraction

from ..core import runtime
from ..core.vectors import vector

_FOLLOWED: dict[int, object] = {}     # id -> object whose trail may take a point at a render


def interval(obj) -> int:
    """The object's interval as its trail counts it: 0 for a point at each render."""
    if obj._interval and obj._interval > 0:
        return int(obj._interval)
    return 1 if obj._trail_type == "points" else 0


def follow(obj) -> None:
    """Let the renders add points to ``obj``'s trail (for the run)."""
    _FOLLOWED.setdefault(id(obj), obj)


def begin(obj, pos_given: bool) -> None:
    """``make_trail=True`` at construction: the trail's first piece, in the object's colour
    now, with the given ``pos`` as its first point."""
    obj._pos_set = pos_given
    obj._new_trail_piece()
    follow(obj)
    if pos_given:
        obj._trail.append(vector(obj._pos))
        pos_changed(obj)    # GlowScript then sets pos from the arguments: counted for interval


def pos_changed(obj) -> None:
    """A change of ``pos`` (the object's trail running): counted when an interval is set."""
    obj._pos_set = True
    follow(obj)
    n = interval(obj)
    if n <= 0 or not obj._visible:
        return
    count = obj._ninterval + 1
    empty = obj._trail is None or obj._trail.npoints == 0
    obj._ninterval = 0 if count >= n else count
    if count >= n or (count == 1 and empty):
        obj._add_trail_point()


def render_point(obj) -> None:
    """What a render adds to ``obj``'s trail: its position, when it moved since the last
    point a render added (and ``pps`` allows one now)."""
    if not obj._make_trail or not obj._visible or not obj._pos_set or interval(obj) > 0:
        return
    pos, last = obj._pos, obj._trail_last
    if last is not None and pos.equals(last):
        return
    if not _pps_allows(obj):
        return
    obj._add_trail_point()
    obj._trail_last = vector(pos)


def _pps_allows(obj) -> bool:
    """``pps`` > 0: a point once at least 1/pps program seconds passed since the last."""
    pps = obj._pps
    if not pps or pps <= 0 or runtime.current() is None:
        return True
    now = runtime.current().clock
    last = obj.__dict__.get("_pps_last")
    if last is not None and now - last < 1 / Fraction(pps):
        return False
    obj.__dict__["_pps_last"] = now
    return True


def keep_colours(trail) -> None:
    """Before ``trail_color`` changes: GlowScript gives each point the trail's colour when
    it is added, so the points made so far keep the colour they were made in."""
    old = trail._color
    kept = False
    for p in trail._pts:
        if "color" not in p:
            p["color"] = vector(old)
            kept = True
    if kept:
        trail._changed()


def restarted(obj) -> None:
    """After ``clear_trail()``: the next render or counted change starts the trail."""
    obj._trail_last = None
    obj._ninterval = 0
    obj.__dict__.pop("_pps_last", None)


def at_render() -> None:
    """A render: every followed object's trail brought up to its position."""
    for obj in list(_FOLLOWED.values()):
        render_point(obj)


def reset() -> None:
    """Forget the followed objects (a new run)."""
    _FOLLOWED.clear()
