"""VPython's linked attributes declared once (:mod:`springscene.vpython.core.attributes`):
a value converted or refused with the attribute's name, stored in its slot, the change
told to the renderer or the object; in-place vector changes reaching the object; writes
refused as VPython words it; nothing kept per object."""

from __future__ import annotations

import operator
import traceback

import pytest

import springscene.vpython.api as vpython_module
from springscene.vpython.core import attributes, checks
from springscene.vpython.objects import shared_defaults
from springscene.vpython.core.attributes import Linked
from springscene.vpython.core.checks import _vec, one_of
from springscene.vpython.objects.shared_defaults import Default
from springscene.vpython.core.vectors import vector
from springscene.vpython.run import runner


class Thing:
    """A small object with one attribute of each kind."""

    _HOOKS = {"_spin": "_on_spin"}
    _SPIN = shared_defaults.default(0, 1, 0)      # every Thing's until it sets its own

    radius = Linked(float, dirty=True)
    count = Linked(int)
    note = Linked()
    pos = Linked(_vec, then="_moved", hook=True)
    kind = Linked(one_of("curve", "points"), then="_moved")
    colour = Linked(_vec, dirty=True)
    spin = Linked(_vec, dirty=True, live=True)
    canvas = Linked(readonly="canvas cannot be modified")
    owner = Linked(readonly=True, store="_made_by")
    fixed = Linked(readonly="{name} cannot be changed after creating a slider")
    label = Linked(str, dirty=True, get=lambda self: self._label or "unnamed")
    width = Linked(set=lambda self, value: setattr(self, "_width", 2 * float(value)))
    height = Linked(float, doc="The {name} in pixels.")
    textcolor = colour

    def __init__(self) -> None:
        self.moves = 0
        self._spin = self._SPIN
        self._canvas = self._made_by = "scene"
        self._fixed, self._label = 3, ""

    def _moved(self) -> None:
        self.moves += 1

    def _on_spin(self) -> None:
        self._dirty = True

    def _live(self, name: str) -> vector:      # as :meth:`.objects.standard._live`
        v = getattr(self, name)
        if type(v) is Default:
            v = vector(v)
            setattr(self, name, v)
        v._on_change = getattr(self, self._HOOKS[name])
        return v


class Plain:
    owner = property(lambda self: self._made_by)


def test_a_type_converts_the_value_and_refuses_as_python_does():
    t = Thing()
    t.radius, t.count, t.note = "2.5", 3.9, [1]
    assert (t.radius, t.count, t.note) == (2.5, 3, [1]) and type(t.radius) is float
    with pytest.raises(ValueError, match="could not convert string to float: 'x'"):
        t.radius = "x"
    assert t.radius == 2.5


def test_a_check_names_the_attribute_in_vpython_s_message():
    t = Thing()
    with pytest.raises(TypeError, match="^pos must be a vector$"):
        t.pos = "left"
    with pytest.raises(TypeError, match="^colour must be a vector$"):
        t.colour = 3
    with pytest.raises(ValueError, match="^kind must be 'curve' or 'points'$"):
        t.kind = "line"
    assert t.moves == 0 and "_pos" not in vars(t) and "_kind" not in vars(t)


def test_a_change_marks_the_object_changed_or_calls_its_method():
    t = Thing()
    t.count = 2
    assert not hasattr(t, "_dirty")           # kept, nothing told
    t.radius = 1
    assert t._dirty is True
    t._dirty = False
    t.label = "ball"
    assert t._dirty is True and t.label == "ball"
    t.kind = "points"
    t.pos = (1, 2, 3)
    assert t.moves == 2 and t.pos == vector(1, 2, 3) and t.kind == "points"


def test_a_change_calls_the_method_as_the_object_s_class_has_it():
    class Counted(Thing):
        def _moved(self) -> None:
            self.moves += 10

    c = Counted()
    c.kind = "points"
    c.pos = (0, 0, 0)
    c.pos.x = 1
    assert c.moves == 30


def test_a_hooked_vector_is_the_object_s_own_and_its_changes_reach_it():
    t = Thing()
    mine = vector(1, 2, 3)
    t.pos = mine
    assert t.pos is not mine and t.pos == mine and mine._on_change is None
    mine.x = 5                                # the program's vector is not linked
    assert t.moves == 1 and t.pos.x == 1
    t.pos.x = 7                               # the object's is
    t.pos.rotate_in_place(angle=1.0)
    assert t.moves == 3


def test_a_vector_read_live_is_copied_from_the_shared_default_and_hooked():
    a, b = Thing(), Thing()
    shared = a._spin
    assert b._spin is shared and shared._on_change is None
    spin = a.spin
    assert spin is not shared and a.spin is spin and spin._on_change is not None
    a._dirty = False
    spin.z = 4
    assert a._dirty is True and b.spin == vector(0, 1, 0) and shared == vector(0, 1, 0)


def test_a_vector_component_notifies_its_owner():
    v = vector(1, 2, 3)
    v.x = "4"                                 # no owner: nothing to tell
    calls = []
    v._on_change = lambda: calls.append(v.y)
    v.y = 7
    assert v == vector(4, 7, 3) and calls == [7.0]
    with pytest.raises(ValueError):
        v.z = "far"
    with pytest.raises(AttributeError, match="shared default vector cannot be changed"):
        shared_defaults.default(0, 0, 0).x = 1


def test_a_read_only_attribute_refuses_a_write_in_pythons_words():
    t = Thing()
    assert (t.canvas, t.owner, t.fixed) == ("scene", "scene", 3)
    with pytest.raises(AttributeError, match="^canvas cannot be modified$"):
        t.canvas = "other"
    with pytest.raises(AttributeError, match="^fixed cannot be changed after creating a slider$"):
        t.fixed = 4
    with pytest.raises(AttributeError) as plain:
        Plain().owner = 1
    with pytest.raises(AttributeError) as linked:
        t.owner = 1
    assert str(linked.value) == str(plain.value).replace("Plain", "Thing")   # Python's own
    assert (t.canvas, t.owner, t.fixed) == ("scene", "scene", 3)


def test_its_own_read_and_write_two_names_and_a_docstring():
    t = Thing()
    assert t.label == "unnamed"
    t.width = 3
    assert t.width == 6.0
    t.textcolor = (1, 0, 0)
    assert t.colour == vector(1, 0, 0) and t.colour is t.textcolor
    assert Thing.height.__doc__ == "The height in pixels."


def test_the_class_holds_plain_properties_and_the_object_only_its_values():
    t = Thing()
    before = set(vars(t))
    t.radius, t.count, t.pos = 1, 2, vector(0, 0, 0)
    assert set(vars(t)) - before == {"_radius", "_count", "_pos", "_dirty"}
    for name in ("radius", "pos", "spin", "canvas", "owner"):
        assert type(vars(Thing)[name]) is property
    assert type(Thing.radius.fget) is operator.attrgetter      # a plain read runs no Python


def test_a_write_s_frames_are_the_package_s_and_left_out_of_the_program_s_line():
    """The runner reports the program's innermost line (:func:`..run.runner._program_line`)
    by leaving out frames inside springscene: a write's and its check's are."""
    t = Thing()
    try:
        t.pos = "left"
    except TypeError as exc:
        frames = traceback.extract_tb(exc.__traceback__)
        where = runner._program_line(exc)
    assert [f.filename for f in frames[1:]] == [attributes.__file__, checks.__file__]
    assert where == f"{frames[0].filename}, line {frames[0].lineno}: "


@pytest.mark.parametrize("args", [
    {"dirty": True, "then": "_moved"}, {"hook": True}, {"convert": float, "readonly": True},
    {"convert": float, "set": print}, {"live": True, "get": print}, {"readonly": "no", "dirty": True},
])
def test_a_declaration_that_says_two_things_is_refused(args):
    with pytest.raises(TypeError, match="Linked"):
        Linked(**args)


def test_hook_wants_a_vector_check_and_notify_a_type():
    with pytest.raises((TypeError, RuntimeError)):
        type("Bad", (), {"p": Linked(float, then="_moved", hook=True)})
    with pytest.raises((TypeError, RuntimeError)):
        type("Bad", (), {"p": Linked(_vec, notify=True)})


# -- the API's own attributes, as VPython has them ----------------------------------------

@pytest.fixture
def vp():
    vpython_module.reset()
    return vpython_module


@pytest.mark.parametrize("make, name, value, error, message", [
    ("sphere()", "pos", "x", TypeError, "pos must be a vector"),
    ("sphere()", "axis", 1, TypeError, "axis must be a vector"),
    ("sphere()", "trail_type", "dots", ValueError, "trail_type must be 'curve' or 'points'"),
    ("sphere()", "canvas", None, AttributeError, "canvas cannot be modified"),
    ("label()", "color", None, TypeError, "color must be a vector"),
    ("curve()", "size_units", "cm", ValueError, "size_units must be 'pixels' or 'world'"),
    ("canvas()", "forward", "vector(0, 0, 0)", ValueError, "forward cannot be the zero vector"),
    ("vertex(pos=vector(0, 0, 0))", "texpos", "vector(0, 0, 1)", AttributeError,
     "the z component of texpos must currently be zero"),
    ("compound([box()])", "origin", "vector(0, 0, 0)", AttributeError,
     'The compound "origin" attribute is read-only; change "pos" instead.'),
    ("slider(bind=print)", "min", 2, AttributeError,
     "min cannot be changed after creating a slider"),
    ("winput(bind=print)", "type", "string", AttributeError,
     "Cannot change the winput type attribute."),
    ("radio(bind=print)", "name", "g", AttributeError,
     "Cannot change the name attribute of a radio widget."),
    ("gcurve()", "color", "red", AttributeError, "color must be a vector"),
])
def test_the_api_refuses_as_vpython_does(vp, make, name, value, error, message):
    obj = eval(make, vars(vp))
    value = eval(value, vars(vp)) if isinstance(value, str) and "(" in value else value
    with pytest.raises(error) as refused:
        setattr(obj, name, value)
    assert str(refused.value) == message


def test_the_api_tells_the_renderer_and_the_objects_of_a_change(vp):
    ball, tag, line = vp.sphere(), vp.label(), vp.curve(vp.vector(0, 0, 0), vp.vector(1, 0, 0))
    corners = [vp.vertex(pos=vp.vector(i, i * i, 0)) for i in range(3)]
    tri = vp.triangle(vs=corners)
    for obj in (ball, tag, line, tri):
        obj._dirty = False
    ball.opacity, tag.text, line.radius, corners[0].pos.y = 0.5, "hi", 0.1, 2
    assert ball._dirty and tag._dirty and line._dirty and tri._dirty
    version, ball._dirty = line._version, False
    line.color.x = 0.5
    ball.pos.x = 3
    assert line._version == version + 1 and ball._dirty and ball.pos == vp.vector(3, 0, 0)
