"""VPython 6 in depth: a curve's points as live numpy arrays, the vector functions on
N x 3 arrays, ``from visual.graph import *``, VPython 6's colour functions, and the
positional arguments VPython 6's constructors took; each through the real runner."""

from __future__ import annotations

import ast
import importlib
import textwrap

import numpy as np
import pytest

from conftest import ROOT
from springscene.vpython.core.canvases import canvas
from springscene.vpython.core.vectors import vector
from springscene.vpython.objects.curves import LivePoints, curve
from springscene.vpython.record.reader import lines, read
from springscene.vpython.run.options import RunOptions
from springscene.vpython.run.runner import run_program

PROGRAMS = ROOT / "tests" / "vpython_programs"
vector_module = importlib.import_module("springscene.vpython.core.vectors")


def write(tmp_path, source: str, name: str = "prog.py"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(source).lstrip("\n"))
    return path


def printed(rec) -> dict[str, list]:
    """What the program printed, ``name value ...`` a line, by name."""
    out = {}
    for line in rec.printed.splitlines():
        name, _, rest = line.partition(" ")
        out[name] = rest
    return out


@pytest.fixture
def lenient():
    vector_module.set_lenient(True)
    yield
    vector_module.set_lenient(False)


# ---- 1. a curve's points as arrays ------------------------------------------------------

def test_curve_arrays_edited_in_place_change_the_points(tmp_path):
    run_program(PROGRAMS / "vp6_curve_arrays.py", tmp_path / "run.jsonl")
    rec = read(tmp_path / "run.jsonl")
    said = printed(rec)
    line = [[0, 0.5, -1], [2, 0.5, -1], [4, 0.5, -1], [1, 2, -1], [8, 0.5, -1]]
    assert ast.literal_eval(said["line"]) == line
    assert ast.literal_eval(said["dots"]) == [[0, 1, 0], [2, 3, 2]]
    assert ast.literal_eval(said["colours"]) == [[0.5, 0, 0], [0.5, 1, 0], [0.5, 0, 1],
                                                 [0.5, 1, 1]]
    band = [[0, 1, 0], [1, 2, 0], [2, 3, 0], [3, 4, 0], [3, 5, 0], [3, 6, 0]]
    assert ast.literal_eval(said["band"]) == band          # grown: the last point repeated
    colours = ast.literal_eval(said["band_colours"])
    assert colours[3:] == [[0.5, 1, 1]] * 3                  # ... its colour too
    # what the recording saw is what the program saw
    assert np.allclose(rec["line"].points(), line)
    assert np.allclose(rec["dots"].points(), [[0, 1, 0], [2, 3, 2]])
    assert np.allclose(rec["band"].points(), band)


def _rope_points(truth: list):
    """An ``on_frame`` that keeps the rope's points as the program has them."""
    def on_frame(i, image):
        rope = next(o for cv in canvas._all for o in cv._objects if o._kind == "curve")
        truth.append([p["pos"].value for p in rope._pts])
    return on_frame


def test_curve_edits_through_its_y_array_are_recorded_each_frame(tmp_path):
    truth = []
    run_program(PROGRAMS / "vp6_curve_wave.py", tmp_path / "run.jsonl", RunOptions(fps=10),
                on_frame=_rope_points(truth))
    rec = read(tmp_path / "run.jsonl")
    rope = rec["rope"]
    assert len(truth) >= 15
    heights = []
    for f, expected in enumerate(truth):
        got = rope.points(f)
        assert np.allclose(got, np.array(expected).reshape(-1, 3)), f
        assert np.ptp(got[:, 1]) < 1e-9                         # the rope stays straight
        heights.append(got[0, 1])
    assert np.all(np.diff(heights) > 0.1)                      # lifted, frame by frame
    assert np.allclose(rope.points()[:, 1], 2.0)
    assert np.allclose(rope.points()[:, 0], np.arange(-4, 4.01, 0.5))
    kinds = {k for line in lines(tmp_path / "run.jsonl")
             for c in line.get("points", {}).values() for k in c}
    assert "reset" in kinds                                    # edits, as modify() gives


def _rows_of(mask: np.ndarray) -> float:
    return float(np.nonzero(mask)[0].mean())


def test_rope_lifted_through_c_y_is_drawn_where_its_points_are(tmp_path):
    frames, truth = [], []
    keep = _rope_points(truth)

    def on_frame(i, img):
        frames.append(img.astype(int))
        keep(i, img)
    run_program(PROGRAMS / "vp6_curve_wave.py", tmp_path / "v.mp4",
                RunOptions(page=False, fps=10, canvas_only=True), on_frame=on_frame)
    assert frames[0].shape == (300, 300, 3)
    red = (frames[0][..., 0] > 150) & (frames[0][..., 1] < 80)
    low_post, high_post = _rows_of(red[:, :150]), _rows_of(red[:, 150:])   # y = -2, +2
    assert low_post - high_post > 80

    def rope_row(img):
        yellow = (img[..., 0] > 150) & (img[..., 1] > 150) & (img[..., 2] < 100)
        assert yellow.sum() > 200
        return _rows_of(yellow)

    for img, pts in zip(frames, truth):       # the rope's row, from the posts' rows
        y = pts[0][1]
        assert abs(rope_row(img) - (low_post + (y + 2) / 4 * (high_post - low_post))) < 4, y
    rows = [rope_row(f) for f in frames]
    assert rows[0] - rows[-1] > 0.8 * (low_post - high_post)   # lifted most of the way


def test_live_arrays_views_copies_and_numpy_writers(lenient):
    c = curve(pos=[(0, 0, 0), (1, 0, 0), (2, 0, 0)])
    pos = c.pos
    assert isinstance(pos, LivePoints) and pos.shape == (3, 3)
    copy = pos.copy()
    copy[0] = (9, 9, 9)                                        # a copy is the program's own
    assert c._pts[0]["pos"].value == [0, 0, 0]
    edits = c._edits
    np.add(pos[:, 2], 5.0, out=pos[:, 2])                      # numpy writing into a view
    assert [p["pos"].z for p in c._pts] == [5, 5, 5] and c._edits == edits + 1
    pos[1] = pos[1]                                            # nothing changes: no edit
    assert c._edits == edits + 1
    assert type(pos * 2) is np.ndarray and type(pos.sum(axis=0)) is np.ndarray
    pos[2] += vector(1, 0, 0)                                  # a vector, in place
    assert c._pts[2]["pos"].value == [3, 0, 5]
    assert (vector(1, 1, 1) - pos).tolist()[2] == [-2, 1, -4]  # a vector less the rows
    c.append(pos=(3, 0, 0))
    pos[0, 0] = -1                                             # an old view still writes
    assert c._pts[0]["pos"].x == -1 and c.pos.shape == (4, 3)
    c.color = [(1, 0, 0)] * 4
    c.append(pos=(4, 0, 0))                                    # VPython 6: last colour goes on
    assert c._pts[-1]["color"].value == [1, 0, 0]
    c.color = (0, 1, 0)                                        # one colour for every point
    assert all("color" not in p for p in c._pts) and c.color[2].tolist() == [0, 1, 0]
    edits = c._edits
    c.pos = c.pos.tolist()                                     # the same points: no edit
    assert c._edits == edits
    c.y = [1, 2, 3, 4, 5, 6, 7]                                # grown: counted as an edit
    assert c._edits > edits and c.npoints == 7 and c._pts[-1]["pos"].value == [4, 7, 0]
    c.pos = ()
    assert c.npoints == 0 and c.pos.shape == (0, 3)
    c.append(pos=(np.float64(1), 0, np.int64(2)))              # numpy numbers: one point
    assert c.npoints == 1 and c._pts[0]["pos"].value == [1, 0, 2]
    with pytest.raises(ValueError, match="Nx3"):
        c.pos = np.zeros((2, 4))


def test_vpython7_curves_keep_their_api(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        c = curve(pos=[vector(0, 0, 0), vector(1, 0, 0)])
        try:
            c.pos
        except AttributeError as e:
            print("pos", e)
        try:
            c.pos = [vector(0, 0, 0)]
        except AttributeError as e:
            print("set", e)
        c.x = 5
        print("x", c.x, c.npoints)
    """)
    run_program(prog, tmp_path / "run.jsonl")
    said = printed(read(tmp_path / "run.jsonl"))
    assert said["pos"] == 'object does not have a "pos" attribute'
    assert said["set"] == "use object methods to change its shape"
    assert said["x"] == "5 2"


# ---- 2. the vector functions on N x 3 arrays --------------------------------------------

def test_vector_functions_work_row_by_row_on_arrays(tmp_path):
    run_program(PROGRAMS / "vp6_array_math.py", tmp_path / "run.jsonl")
    said = {k: ast.literal_eval(v) if k != "one" else v
            for k, v in printed(read(tmp_path / "run.jsonl")).items()}
    a = np.array([[3.0, 4, 0], [1, 2, 2], [0, 0, 0], [0, 0, 5]])
    b = np.array([[1.0, 0, 0], [0, 1, 0], [0, 0, 1], [1, 1, 1]])
    rows = np.linalg.norm(a, axis=1)
    assert np.allclose(said["mag"], rows)
    assert np.allclose(said["mag2"], rows ** 2)
    unit = np.divide(a, rows[:, None], out=np.zeros_like(a), where=rows[:, None] > 0)
    assert np.allclose(said["norm"], unit)                     # a zero row stays zero
    assert np.allclose(said["cross"], np.cross(a, b))
    assert np.allclose(said["cross_v"], np.cross(a, [0, 0, 1]))
    assert np.allclose(said["dot_v"], a @ [1, 1, 1])
    assert np.allclose(said["dot_rows"], (a * b).sum(axis=1))
    assert said["one"] == "5.0 2.0 5.0"
    assert np.allclose(said["wire"], rows)                     # a curve's pos, less a vector


def test_vector_functions_refuse_what_vpython6_refused(tmp_path):
    prog = write(tmp_path, """
        from visual import *
        for f, args in ((mag, (zeros((4, 2)),)), (cross, (zeros((4, 3)), zeros((5, 3))))):
            try:
                f(*args)
            except ValueError as e:
                print(f.__name__, e)
        print("matrix", dot(identity(3), array([[1.0, 2, 3]] * 3)).tolist())
    """)
    run_program(prog, tmp_path / "run.jsonl")
    said = printed(read(tmp_path / "run.jsonl"))
    assert said["mag"] == "Array must be Nx3 in shape."
    assert said["cross"] == "Array shape mismatch."
    assert ast.literal_eval(said["matrix"]) == [[1, 2, 3]] * 3   # numpy's dot, as visual's


# ---- 3, 4, 5. visual.graph, colours, positional arguments -------------------------------

def test_graph_import_colours_and_positional_arguments(tmp_path):
    result = run_program(PROGRAMS / "vp6_graph_colors.py", tmp_path / "run.jsonl")
    assert result.dialect == "VPython 6"
    rec = read(tmp_path / "run.jsonl")
    said = printed(rec)
    assert said["hsv_to_rgb"] == "(0.0, 1.0, 1.0)"
    assert said["rgb_to_hsv"] == "(0.0, 1.0, 1.0)"
    assert ast.literal_eval(said["vector"]) == pytest.approx((2 / 3, 1, 1))
    assert said["gray"] == "(0.25, 0.25, 0.25) grayscale (0.99, 0.99, 0.99)"
    assert said["four"] == "(1.0, 1.0, 1.0)"                  # only the first three count
    assert said["text"] == "<0, 1, 0>"
    assert said["series"] == "4.0 0.5 True"
    assert said["sphere"] == "takes keywords only"            # as VPython 6's sphere did
    assert np.allclose(rec["ball"].color[-1], [0, 1, 1])      # scene, sphere: from visual.graph


def test_graph_import_alone_runs_a_vpython6_scene(tmp_path):
    prog = write(tmp_path, """
        from visual.graph import *
        scene.title = "graph only"
        ball = sphere(pos=(0, 1, 0), color=color.orange)
        g = gcurve(color=color.red)
        for i in range(5):
            rate(50)
            ball.pos = ball.pos + vector(0.1, 0, 0)
            g.plot(pos=(i, sqrt(i)))
        print("ok", round(ball.x, 3), frame is not None, mag(vector(3, 4, 0)))
    """)
    run_program(prog, tmp_path / "run.jsonl")
    rec = read(tmp_path / "run.jsonl")
    assert printed(rec)["ok"] == "0.5 True 5.0"
    assert np.allclose(rec["ball"].pos[-1], [0.5, 1, 0])


def test_shapes_and_paths_take_vpython6s_order_of_arguments(tmp_path):
    # VPython 6's shapes are Polygons: each contour its corners, once
    prog = write(tmp_path, """
        from visual import *
        def same(a, b):
            return [list(map(tuple, c)) for c in a] == [list(map(tuple, c)) for c in b]
        print("ngon", len(shapes.ngon((0, 0), 6, 2)[0]),
              same(shapes.ngon((0, 0), 6, 2), shapes.ngon(pos=(0, 0), np=6, length=2)))
        print("star", len(shapes.star((0, 0), 2, 7)[0]))
        print("cross", same(shapes.cross((0, 0), 2, 0.5), shapes.cross(width=2, thickness=0.5)))
        print("list", len(shapes.pointlist([(0, 0), (1, 0), (1, 1)])[0]))
        print("path", paths.triangle((0, 0, 0), 3, 4) == paths.triangle(length=4))
        print("circle", same(shapes.circle((1, 1), 2, 16),
                             shapes.circle(pos=(1, 1), radius=2, np=16)))
    """)
    run_program(prog, tmp_path / "run.jsonl")
    said = printed(read(tmp_path / "run.jsonl"))
    assert said["ngon"] == "6 True"                 # np=6 second, as VPython 6 took it
    assert said["star"] == "14"                     # radius, then n=7 points
    assert said["cross"] == said["path"] == said["circle"] == "True"
    assert said["list"] == "3"


def test_append_takes_vpython6s_colour_and_retain(tmp_path):
    prog = write(tmp_path, """
        from visual import *
        trail = curve(color=color.white)
        for i in range(30):
            trail.append(pos=(i, 0, 0), retain=10)          # the newest ten kept
        print("kept", trail.npoints, trail.x[0], trail.x[-1])
        trail.append((40, 0, 0), (0, 1, 0), 4)               # pos, colour, retain
        print("coloured", trail.npoints, trail.color[-1].tolist(), trail.color[0].tolist())
        trail.append(pos=(41, 0, 0), red=1)                  # the last colour, red changed
        print("red", trail.color[-1].tolist())
        two = curve()
        two.append((0, 0, 0), (5, 5, 5))                    # not a colour: two points
        print("two", two.npoints)
    """)
    run_program(prog, tmp_path / "run.jsonl")
    rec = read(tmp_path / "run.jsonl")
    said = printed(rec)
    assert said["kept"] == "10 20.0 29.0"
    assert said["coloured"] == "4 [0.0, 1.0, 0.0] [1.0, 1.0, 1.0]"
    assert said["red"] == "[1.0, 1.0, 0.0]"
    assert said["two"] == "2"
    assert np.allclose(rec["trail"].points()[:, 0], [27, 28, 29, 40, 41])
