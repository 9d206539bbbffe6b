"""springscene.vpython's vector and math names against VPython 7's behaviour."""

import copy
import math
import pickle
import random
import time

import numpy as np
import pytest

from springscene import build, config
from springscene.model import physics
from wikiloop import wiki_loop
from springscene.vpython.api import vmath

from springscene.vpython.core import vectors as V
from springscene.vpython.core import turns as T
from springscene.vpython.core.vectors import (as_vector, comp, cross, diff_angle, dot, hat, mag,
                                             mag2, norm, proj, rotate, vec, vector)


def xyz(v):
    return (v.x, v.y, v.z)


# -- construction ---------------------------------------------------------

def test_construct_from_components_stores_floats():
    v = vector(1, np.float32(2.5), np.int64(-3))
    assert xyz(v) == (1.0, 2.5, -3.0)
    assert all(type(c) is float for c in xyz(v))
    assert vec is vector


def test_construct_copy_is_independent():
    a = vector(1, 2, 3)
    b = vector(a)
    b.x = 10
    assert a.x == 1 and b == vector(10, 2, 3)


@pytest.mark.parametrize("args", [(), (1,), (1, 2), (1, 2, 3, 4), ([1, 2, 3],), ((1, 2, 3),)])
def test_construct_anything_else_is_type_error(args):
    with pytest.raises(TypeError, match="A vector needs 3 components"):
        vector(*args)


def test_random_components_in_range_and_from_random_random():
    random.seed(7)
    vs = [vector.random() for _ in range(500)]
    assert all(-1 <= c <= 1 for v in vs for c in xyz(v))
    assert min(v.x for v in vs) < -0.9 and max(v.x for v in vs) > 0.9
    random.seed(7)
    r = [random.random() for _ in range(3)]
    assert xyz(vs[0]) == tuple(-1.0 + 2.0 * c for c in r)     # VPython's formula


# -- arithmetic -----------------------------------------------------------

def test_arithmetic_values():
    a, b = vector(1, 2, 3), vector(0.5, -1, 4)
    assert a + b == vector(1.5, 1, 7)
    assert a - b == vector(0.5, 3, -1)
    assert a * 2 == 2 * a == vector(2, 4, 6)
    assert a / 2 == vector(0.5, 1, 1.5)
    assert -a == vector(-1, -2, -3)
    assert +a == a and +a is not a


def test_arithmetic_is_componentwise_float_ops_bit_for_bit():
    rng = random.Random(1)
    for _ in range(200):
        x, y, z, u, w, t, s = (rng.uniform(-10, 10) for _ in range(7))
        a, b = vector(x, y, z), vector(u, w, t)
        assert xyz(a + b) == (x + u, y + w, z + t)
        assert xyz(a - b) == (x - u, y - w, z - t)
        assert xyz(a * s) == xyz(s * a) == (x * s, y * s, z * s)
        assert xyz(a / s) == (x / s, y / s, z / s)
        assert a.mag == math.sqrt(x**2 + y**2 + z**2)
        m = math.sqrt(x**2 + y**2 + z**2)
        assert xyz(a.norm()) == xyz(norm(a)) == xyz(a.hat) == (x / m, y / m, z / m)
        assert a.mag2 == x**2 + y**2 + z**2
        assert a.dot(b) == x * u + y * w + z * t


@pytest.mark.parametrize("s", [np.float64(2), np.float32(2), np.int64(2), np.int32(2), True, 2, 2.0])
def test_numbers_of_any_kind_scale(s):
    v = vector(1, 2, 3)
    for r in (v * s, s * v, v / (s * 1)):
        assert type(r) is vector and all(type(c) is float for c in xyz(r))
    assert v * s == s * v == vector(float(s), 2 * float(s), 3 * float(s))


@pytest.mark.parametrize("expr", [
    "v + 1", "1 + v", "v - 1", "2 - v", "2 / v", "v * w", "v / w", "v * 'a'",
    "v + (1, 2, 3)", "v + [1, 2, 3]", "v * (1 + 2j)", "v + np.float64(1)",
])
def test_operator_errors_are_type_errors(expr):
    v, w = vector(1, 2, 3), vector(4, 5, 6)
    with pytest.raises(TypeError):
        eval(expr)


def test_error_message_is_pythons():
    with pytest.raises(TypeError, match=r"unsupported operand type\(s\) for \+: 'vector' and 'int'"):
        vector(1, 2, 3) + 1
    with pytest.raises(TypeError, match=r"for /: 'int' and 'vector'"):
        2 / vector(1, 2, 3)


def test_division_by_zero():
    with pytest.raises(ZeroDivisionError):
        vector(1, 2, 3) / 0


def test_augmented_assignment_makes_a_new_vector():
    a = vector(1, 2, 3)
    alias = a
    a += vector(1, 1, 1)
    assert a == vector(2, 3, 4) and alias == vector(1, 2, 3) and a is not alias
    a *= 2
    assert a == vector(4, 6, 8) and alias == vector(1, 2, 3)


# -- comparisons and protocols VPython does not have ------------------------

def test_equality_is_exact():
    assert vector(1, 2, 3) == vector(1.0, 2.0, 3.0)
    assert vector(0.1 + 0.2, 0, 0) != vector(0.3, 0, 0)
    assert not (vector(1, 2, 3) != vector(1, 2, 3))
    assert vector(1, 2, 3).equals(vector(1, 2, 3))
    assert vector(1, 2, 3) != (1, 2, 3) and not vector(1, 2, 3) == [1, 2, 3]
    assert vector(0, 0, 0) != 0


def test_unhashable_not_iterable_no_len_no_abs():
    v = vector(1, 2, 3)
    with pytest.raises(TypeError, match="unhashable"):
        hash(v)
    with pytest.raises(TypeError):
        list(v)
    with pytest.raises(TypeError):
        x, y, z = v
    with pytest.raises(TypeError):
        len(v)
    with pytest.raises(TypeError):
        abs(v)
    assert bool(vector(0, 0, 0))                      # always true, as VPython


def test_numpy_sees_a_vector_as_one_object():
    v = vector(1, 2, 3)
    assert np.array(v).shape == () and np.array([v, v]).shape == (2,)


def test_indexing():
    v = vector(1, 2, 3)
    assert (v[0], v[1], v[2], v[-1], v[np.int64(1)]) == (1, 2, 3, 3, 2)
    v[1] = 5
    assert v == vector(1, 5, 3) and type(v.y) is float
    for bad in (3, -4):
        with pytest.raises(IndexError):
            v[bad]
        with pytest.raises(IndexError):
            v[bad] = 0
    with pytest.raises(TypeError):
        v[1.0]


# -- text -------------------------------------------------------------------

@pytest.mark.parametrize("v, s", [
    ((1, 2.5, 1e-7), "<1, 2.5, 1e-07>"),
    ((0, -0.0, 100), "<0, -0, 100>"),
    ((1 / 3, 123456789, -2.5e-5), "<0.333333, 1.23457e+08, -2.5e-05>"),
    ((1e16, 0.1 + 0.2, 1234567), "<1e+16, 0.3, 1.23457e+06>"),
])
def test_str_is_6g(v, s):
    assert str(vector(*v)) == s
    assert repr(vector(*v)) == "vector(" + s[1:-1] + ")"   # VPython 7.6's repr
    assert f"{vector(*v)}" == s


# -- magnitude and direction --------------------------------------------------

def test_zero_vector():
    z = vector(0, 0, 0)
    assert z.mag == mag(z) == 0.0 and z.mag2 == mag2(z) == 0.0
    assert z.norm() == norm(z) == z.hat == hat(z) == vector(0, 0, 0)
    assert z.norm() is not z
    assert z.diff_angle(vector(1, 0, 0)) == math.pi / 2    # hat . hat = 0, as VPython


def test_mag_setter_rescales():
    v = vector(3, 4, 0)
    v.mag = 10
    assert v == vector(6, 8, 0)
    v.mag2 = 25
    assert v == vector(3, 4, 0)
    z = vector(0, 0, 0)
    z.mag = 5                                           # no direction: stays zero
    assert z == vector(0, 0, 0)


def test_hat_setter_keeps_magnitude():
    v = vector(3, 4, 0)
    v.hat = vector(0, 0, -7)
    assert v == vector(0, 0, -5)
    v.hat = (1, 0, 0)
    assert v == vector(5, 0, 0)


def test_value():
    v = vector(1, 2, 3)
    assert v.value == [1.0, 2.0, 3.0] and type(v.value) is list
    v.value = (4, 5, 6)
    assert v == vector(4, 5, 6)
    v.value = vector(7, 8, 9)
    assert v == vector(7, 8, 9)
    with pytest.raises(TypeError, match="value must be a vector"):
        v.value = (1, 2)
    assert v._xyz() == (7.0, 8.0, 9.0)


# -- products, projections, angles ----------------------------------------------

def test_dot_cross():
    a, b = vector(1, 0, 0), vector(0, 1, 0)
    assert cross(a, b) == a.cross(b) == vector(0, 0, 1)
    assert cross(b, a) == vector(0, 0, -1)
    assert dot(vector(1, 2, 3), vector(4, -5, 6)) == 12.0
    c = cross(vector(1, 2, 3), vector(4, 5, 6))
    assert c == vector(-3, 6, -3)


def test_proj_comp():
    a, b = vector(3, 4, 5), vector(0, 2, 0)
    assert proj(a, b) == a.proj(b) == vector(0, 4, 0)
    assert comp(a, b) == a.comp(b) == 4.0
    assert comp(a, vector(1, 1, 0)) == pytest.approx(7 / math.sqrt(2), rel=1e-15)
    assert proj(a, vector(0, 0, 0)) == vector(0, 0, 0)


def test_diff_angle():
    assert diff_angle(vector(1, 0, 0), vector(0, 3, 0)) == pytest.approx(math.pi / 2, rel=1e-15)
    assert vector(1, 0, 0).diff_angle(vector(1, 1, 0)) == pytest.approx(math.pi / 4, rel=1e-15)


def test_diff_angle_is_clamped_against_round_off():
    v = vector(1, 1, 1)
    assert v.hat.dot(v.hat) > 1                       # round-off: acos would give nan
    assert v.diff_angle(v) == 0.0 and v.diff_angle(2 * v) == 0.0
    assert (-v).hat.dot(v.hat) < -1
    assert v.diff_angle(-v) == math.pi
    rng = random.Random(3)
    for _ in range(2000):
        u = vector(rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1))
        assert 0 <= u.diff_angle(3.7 * u) <= 1e-7 and not math.isnan(u.diff_angle(u))
        assert math.pi - 1e-7 <= u.diff_angle(-u) <= math.pi


def rodrigues(axis, angle):
    u = np.asarray(axis, float) / np.linalg.norm(axis)
    K = np.array([[0, -u[2], u[1]], [u[2], 0, -u[0]], [-u[1], u[0], 0]])
    return np.eye(3) + math.sin(angle) * K + (1 - math.cos(angle)) * K @ K


def test_rotate_about_z_by_default():
    r = vector(1, 0, 0).rotate(math.pi / 2)
    assert xyz(r) == pytest.approx((0, 1, 0), abs=1e-15)
    assert xyz(rotate(vector(0, 1, 0), math.pi / 2)) == pytest.approx((-1, 0, 0), abs=1e-15)
    assert vector(1, 2, 3).rotate(0.0) == vector(1, 2, 3)
    assert vector(1, 2, 3).rotate() == vector(1, 2, 3)


def test_rotate_about_an_axis_matches_rotation_matrix():
    rng = random.Random(5)
    for _ in range(100):
        v = [rng.uniform(-3, 3) for _ in range(3)]
        axis = [rng.uniform(-3, 3) for _ in range(3)]
        angle = rng.uniform(-7, 7)
        got = vector(*v).rotate(angle, vector(*axis))
        assert xyz(got) == pytest.approx(tuple(rodrigues(axis, angle) @ v), abs=1e-12)
        assert got.mag == pytest.approx(vector(*v).mag, rel=1e-13)
        assert xyz(rotate(vector(*v), angle=angle, axis=vector(*axis))) == xyz(got)
    with pytest.raises(TypeError):
        vector(1, 0, 0).rotate(1.0, (0, 0, 1))


def test_rotate_is_vpythons_formula_bit_for_bit():
    """VPython's matrix m11..m33 from u = axis.hat, then m @ v, in its order."""
    v, axis, angle = vector(0.3, -1.7, 2.2), vector(1, 2, -0.5), 0.77
    u = axis.hat
    x, y, z = u.x, u.y, u.z
    c, s = math.cos(angle), math.sin(angle)
    t = 1.0 - c
    m = [[t*x*x + c, t*x*y - z*s, t*x*z + y*s],
         [t*x*y + z*s, t*y*y + c, t*y*z - x*s],
         [t*x*z - y*s, t*y*z + x*s, t*z*z + c]]
    want = tuple(r[0]*v.x + r[1]*v.y + r[2]*v.z for r in m)
    assert xyz(v.rotate(angle, axis)) == want
    w = vector(v)
    w.rotate_in_place(angle, axis)
    assert xyz(w) == want


def test_adjust_up_hanging_spring():
    """A spring's axis turned from (1,0,0) to straight down turns up from y to x."""
    axis, up = vector(1, 0, 0), vector(0, 1, 0)
    saved = T.adjust_up(axis, vector(0, -0.2, 0), up, None)
    assert saved is None
    assert axis == vector(0, -0.2, 0)
    assert xyz(up) == pytest.approx((1, 0, 0), abs=1e-15)


def test_adjust_up_leaves_perpendicular_up_and_saves_zero_axis():
    axis, up = vector(1, 0, 0), vector(0, 1, 0)
    T.adjust_up(axis, vector(0, 0, 2), up, None)      # new axis already square to up
    assert up == vector(0, 1, 0) and axis == vector(0, 0, 2)
    saved = T.adjust_up(axis, vector(0, 0, 0), up, None)
    assert saved is axis


def test_object_rotate_turns_axis_and_up():
    axis, up = vector(1, 0, 0), vector(0, 1, 0)
    T.object_rotate(axis, up, math.pi / 2, vector(0, 0, 1))
    assert xyz(axis) == pytest.approx((0, 1, 0), abs=1e-15)
    assert xyz(up) == pytest.approx((-1, 0, 0), abs=1e-15)


# -- change notification --------------------------------------------------------

class Counter:
    def __init__(self):
        self.n = 0

    def __call__(self):
        self.n += 1


@pytest.mark.parametrize("mutate", [
    lambda v: setattr(v, "x", 5), lambda v: setattr(v, "y", 5), lambda v: setattr(v, "z", 5),
    lambda v: setattr(v, "mag", 2), lambda v: setattr(v, "mag2", 2),
    lambda v: setattr(v, "hat", vector(0, 0, 1)), lambda v: setattr(v, "value", (4, 5, 6)),
    lambda v: v.__setitem__(2, 9.0), lambda v: v.rotate_in_place(0.3, vector(1, 1, 0)),
])
def test_every_mutation_notifies_once_after_the_change(mutate):
    v = vector(1, 2, 3)
    seen = []
    v._on_change = lambda: seen.append(v._xyz())
    before = v._xyz()
    mutate(v)
    assert seen == [v._xyz()] and v._xyz() != before


def test_operators_and_reads_do_not_notify():
    v, w = vector(1, 2, 3), vector(4, 5, 6)
    c = Counter()
    v._on_change = c
    results = [v + w, w + v, v - w, -v, +v, v * 2, 2 * v, v / 2, v.hat, v.norm(), norm(v),
               v.cross(w), v.proj(w), v.rotate(1.0), vector(v), copy.copy(v), copy.deepcopy(v),
               pickle.loads(pickle.dumps(v))]
    _ = (v.x, v.y, v.z, v.mag, v.mag2, v.value, v[0], v.dot(w), v.comp(w), v.diff_angle(w),
         str(v), repr(v), v == w)
    assert c.n == 0
    assert all(type(r) is vector and r._on_change is None for r in results)
    assert copy.deepcopy(v) == v == pickle.loads(pickle.dumps(v))


def test_quiet_setters_and_vpython_helpers_do_not_notify():
    v = vector(1, 2, 3)
    c = Counter()
    v._on_change = c
    v._x_set(7)
    v._y_set(8)
    v._z_set(9)
    assert v == vector(7, 8, 9) and c.n == 0
    axis = vector(1, 0, 0)
    axis._on_change = c
    up = vector(0, 1, 0)
    up._on_change = c
    T.adjust_up(axis, vector(1, 1, 0), up, None)
    T.object_rotate(axis, up, 0.5, vector(0, 0, 1))
    assert c.n == 0


def test_default_on_change_is_none():
    assert vector(1, 2, 3)._on_change is None
    v = vector(1, 2, 3)
    v.x = 2                                            # no callback set: no error
    assert v.x == 2.0


# -- as_vector ----------------------------------------------------------------

def test_as_vector():
    v = vector(1, 2, 3)
    assert as_vector(v, "pos") is v
    for seq in ((1, 2, 3), [1.0, 2, 3], np.array([1, 2, 3]), (np.float32(1), 2, np.int8(3))):
        got = as_vector(seq, "pos")
        assert type(got) is vector and got == v
    for bad in ("abc", (1, 2), [1, 2, 3, 4], 5, None, ("1", 2, 3), (1, 2, 1j)):
        with pytest.raises(TypeError, match="^pos must be a vector$"):
            as_vector(bad, "pos")


def test_module_exports():
    want = {'comp', 'cross', 'diff_angle', 'dot', 'hat', 'mag', 'mag2', 'norm', 'proj',
            'rotate', 'vec', 'vector'}
    assert set(V.__all__) == want and set(T.__all__) == {'adjust_axis', 'adjust_up',
                                                         'object_rotate'}
    ns = {}
    exec("from springscene.vpython.core.vectors import *", ns)
    assert want <= set(ns) and "as_vector" not in ns
    exec("from springscene.vpython.api import *", ns)          # VPython's namespace has all
    assert {'adjust_axis', 'adjust_up', 'object_rotate'} <= set(ns)


# -- the wiki's loop, with these vectors, bit for bit -----------------------------

CFG = config.load("configs/wiki.toml")


@pytest.mark.parametrize("start, p0", [
    ((0, -0.18533333333333335, 0), (0, 0, 0)),
    ((0.03, -0.12, 0.01), (0.002, 0.01, -0.001)),   # a swinging, compressed start
])
def test_wiki_loop_bit_identical_to_physics_engine(start, p0):
    ref = wiki_loop(2000, start, p0, vector, mag, norm)     # the page's loop, our vectors
    s = build.system(config.override(CFG, "ball", pos=start, p=p0))
    got = np.empty_like(ref)
    for n in range(len(ref)):
        physics.step(s)
        got[n, :3], got[n, 3:] = s.pos[1], s.p[1]
    assert np.array_equal(got, ref)   # exact, not approximate


# -- vmath -----------------------------------------------------------------------

def test_vmath_math_names_are_maths():
    public = [n for n in dir(math) if not n.startswith("_")]
    for name in public:
        assert vmath.NAMES[name] is getattr(math, name)
    assert vmath.NAMES["pi"] is math.pi and vmath.NAMES["e"] is math.e
    for name in ("sqrt", "sin", "cos", "tan", "asin", "acos", "atan", "atan2", "exp", "log",
                 "log10", "floor", "ceil", "fabs", "radians", "degrees", "factorial", "pow",
                 "inf", "nan", "tau", "hypot"):
        assert vmath.NAMES[name] is getattr(math, name)


def test_vmath_other_names():
    assert vmath.NAMES["random"] is random.random
    assert vmath.NAMES["arange"] is np.arange
    assert vmath.NAMES["clock"] is time.perf_counter
    for absent in ("randint", "uniform", "seed", "rate", "sleep", "vector", "mag", "scene",
                   "sphere", "color", "math", "time", "numpy", "np"):
        assert absent not in vmath.NAMES
    assert vmath.__all__ == list(vmath.NAMES)
    ns = {}
    exec("from springscene.vpython.api.vmath import *", ns)
    assert {k: ns[k] for k in vmath.NAMES} == vmath.NAMES


def test_combin_and_sign():
    combin, sign = vmath.NAMES["combin"], vmath.NAMES["sign"]
    assert combin(5, 2) == 10.0 and type(combin(5, 2)) is float
    assert [combin(10, k) for k in range(11)] == [float(math.comb(10, k)) for k in range(11)]
    assert combin(0, 0) == 1.0
    with pytest.raises(ValueError, match="Illegal arguments"):
        combin(3, 5)
    assert (sign(3.2), sign(-0.1), sign(0), sign(-0.0), sign(math.nan)) == (1, -1, 0, 0, 0)


def test_a_vector_over_zero_is_inf_and_nan_in_vpython6_and_an_error_in_vpython7():
    v = V.vector(2, -3, 0)
    with pytest.raises(ZeroDivisionError):
        v / 0
    V.set_lenient(True)          # VPython 6's C++ vector divides as IEEE does
    try:
        x, y, z = xyz(v / 0.0)
        assert (x, y) == (math.inf, -math.inf) and math.isnan(z)
        x, y, _ = xyz(v / -0.0)
        assert (x, y) == (-math.inf, math.inf)
    finally:
        V.set_lenient(False)


def test_a_canvas_side_written_as_text_is_taken_as_the_browser_takes_it():
    import springscene.vpython.api as vp
    vp.reset()
    c = vp.canvas(height="500", width=" 320 ")
    assert (c.width, c.height) == (320, 500)
    with pytest.raises(ValueError, match="a canvas height must be a number of pixels"):
        c.height = "500px"
