"""What every drawable VPython object shares: its canvas, visibility and change flag.

An object goes to the canvas given as ``canvas=``, else to the current one
(:meth:`..core.canvases.canvas.get_selected`). It only marks itself changed (``_dirty``);
the renderer (:mod:`springscene.vpython.draw.renderer`) reads the objects of a canvas once
a frame. :mod:`.standard_attributes`, :mod:`.curves` and :mod:`.labels` build on :class:`_Base`.
"""

from __future__ import annotations

from ..core.attributes import Linked
from ..core.canvases import canvas
from ..core.vectors import vector


def _current_canvas():
    return canvas.get_selected()


def component(attribute: str, index: int) -> property:
    """One component of a vector attribute (``red`` is ``color.x``): read from the stored
    vector; a write sets the whole attribute to a new vector, so that its check and its
    change notice run as for any other write."""
    store = "_" + attribute

    def read(self):
        return getattr(self, store)._xyz()[index]

    def write(self, value) -> None:
        parts = list(getattr(self, store)._xyz())
        parts[index] = value
        setattr(self, attribute, vector(*parts))

    return property(read, write)


class _Base:
    """What every drawable object shares: its canvas, visibility and change flag."""

    _kind = "object"

    _frame = None        # VPython 6's frame holding the object (:mod:`.frames`)

    def _register(self, args: dict) -> None:
        cv = args.pop("canvas", None)
        if cv is None:
            cv = args.pop("display", None)     # VPython 6's name for it
        self._canvas = cv if cv is not None else _current_canvas()
        self._dirty = True
        self._canvas._add(self)
        if args.get("frame") is not None:
            self.frame = args.pop("frame")
        args.pop("frame", None)
        args.pop("display", None)

    @property
    def frame(self):
        """VPython 6's frame the object is in (None: the world)."""
        return self._frame

    @frame.setter
    def frame(self, parent) -> None:
        if self._frame is not None and self in self._frame._children:
            self._frame._children.remove(self)
        self._frame = parent
        if parent is not None:
            parent._children.append(self)
        self._dirty = True

    _looks = 0    # changes to anything but the position, counted by :meth:`_touch`

    def _touch(self) -> None:
        """Mark the object changed: the renderer draws it anew, and ``_looks`` counts one
        more change to something other than its position. A position change marks only
        ``_dirty``, so that a recorder (:mod:`..record.recorder`) reads a moving object's
        position alone, and all of its attributes only when ``_looks`` moved."""
        self._dirty = True
        self._looks += 1

    canvas = Linked(readonly="canvas cannot be modified")
    visible = Linked(bool, dirty=True)

    def delete(self) -> None:
        """Remove the object from its canvas, as VPython's ``obj.delete()`` does."""
        self._visible = False
        self._canvas._remove(self)

    def _ipython_display_(self) -> None:   # VPython prints nothing for an object
        pass
