"""VPython 6's own examples (vpython/visual.obsolete, ``examples/``), each stood for by a
program of ours in tests/vpython_programs/vp6_ex_<example>.py that uses the same
features in a scene of its own.

Every example that needs no mouse or keyboard (or polls them and runs without) has one
program here; each is run through the runner to a recording (nothing drawn) and its
values checked against the physics or the geometry it was built from; a few are drawn
as a draft still and checked for their objects' pixels. The programs whose features are
not in springscene yet are strict xfails naming the feature: once it lands they pass,
the xfail fails loudly, and its mark is to be removed.
"""

from __future__ import annotations

import colorsys

import numpy as np
import pytest
from PIL import Image

from conftest import ROOT
from springscene.vpython.record.reader import read
from springscene.vpython.run.options import RunOptions
from springscene.vpython.run.runner import run_program

PROGRAMS = ROOT / "tests" / "vpython_programs"

# The examples of visual.obsolete's examples/ that need no input ("no") or poll the mouse
# or keyboard and run without it ("opt"), from the survey of issue 26.
NO_INPUT = ("bounce bounce2 boxlighttest conch crystal doublependulum extruded_columns "
            "faces_cone faces_heightfield gas glinfo graphtest gyro2 labels lathe lorenz "
            "mandelbrot medusa orbit randombox stars text3D texture_and_lighting tictacdat "
            "toroid wave").split()
OPTIONAL_INPUT = ("convex crossproduct electric_motor gyro differential_gear material_test "
                  "stonehenge toroid_drag planar").split()


# -- helpers ------------------------------------------------------------------------------

def kinds(rec) -> dict[str, int]:
    out: dict[str, int] = {}
    for tr in rec.objects:
        out[tr.kind] = out.get(tr.kind, 0) + 1
    return out


def extrusions(rec) -> list:
    """The extrusions (recorded as compounds, as VPython 7 makes them; or as their own kind)."""
    return [tr for tr in rec.objects if tr.kind in ("extrusion", "compound")]


def extent(track) -> np.ndarray:
    """An object's size at the end, smallest first (its box, whichever way it turned)."""
    return np.sort(last(track, "size"))


def last(track, attribute):
    return getattr(track, attribute)[-1]


def printed_numbers(rec) -> list[float]:
    words = rec.printed.replace("<", " ").replace(">", " ").replace(",", " ").split()
    out = []
    for w in words:
        try:
            out.append(float(w))
        except ValueError:
            pass
    return out


# -- the checks, one a program ------------------------------------------------------------

def check_bounce(rec):
    assert kinds(rec) == {"box": 1, "sphere": 1}
    y, vy, bounces, t = 2.5, 0.0, 0, 0.0               # the program's loop, again
    while t < 2:
        y = y + vy * 0.005
        if y < -0.5 + 0.3 and vy < 0:
            vy, bounces = -vy, bounces + 1
        else:
            vy = vy - 9.8 * 0.005
        t = t + 0.005
    assert rec.globals["bounces"] == bounces >= 1
    assert last(rec["pebble"], "pos") == pytest.approx([0, y, 0], abs=1e-9)
    assert rec["pebble"].pos[:, 1].min() > -0.5 + 0.3 - 0.1      # never through the slab


def check_bounce2(rec):
    assert kinds(rec) == {"box": 4, "sphere": 1}
    x = rec["ball"].pos
    limit = 3.0 - 0.1 - 0.5
    assert np.abs(x).max() <= limit + 0.1               # one step past a wall at most
    assert x[:, 0].max() > limit - 0.3 and x[:, 0].min() < -limit + 0.3   # wall to wall
    assert np.abs(np.diff(x[:, 1])).max() <= 0.6 / 2 * 0.2 * 5 + 1e-9   # |p_y|/m dt, 5 a frame


def check_boxlighttest(rec):
    assert kinds(rec) == {"box": 1, "sphere": 2, "arrow": 1}
    b1, b2 = rec["bulb1"].pos, rec["bulb2"].pos
    assert np.allclose(np.linalg.norm(b1, axis=1), 2.5) and np.allclose(b1[:, 2], 0)
    assert np.allclose(np.linalg.norm(b2, axis=1), 2.5) and np.allclose(b2[:, 0], 0)
    a = rec.globals["ang1"] - 0.05                       # the angle of the last move
    assert b1[-1] == pytest.approx([2.5 * np.cos(a), 2.5 * np.sin(a), 0])
    lights = rec.canvases[0]["lights"]
    local = [lt for lt in lights if lt["kind"] == "local_light"]
    assert [lt["color"] for lt in local] == [[1, 0, 0], [0, 1, 1]]
    assert local[0]["pos"] == pytest.approx(b1[-1])      # the lamp moved with its bulb
    assert any(lt["kind"] == "distant_light" and lt["color"] == [0, 1, 0] for lt in lights)


def check_conch(rec):
    assert set(kinds(rec)) <= {"extrusion", "compound"} and len(extrusions(rec)) == 1
    assert printed_numbers(rec) == [40]                 # a path point each
    rise, widest = 0.06 * 39, 2 * (0.05 * 0.25 * 39 + 0.5 * (0.2 + 0.02 * 39))
    assert rise < extent(extrusions(rec)[0])[-1] < rise + widest     # the horn's length


def check_crystal(rec):
    assert kinds(rec) == {"sphere": 4, "helix": 5}
    atoms, springs = rec["atoms"], rec["springs"]
    for n, atom in enumerate(atoms):
        assert last(atom, "color") == pytest.approx(colorsys.hsv_to_rgb(n / 4, 1, 1))
        # each spring runs from the atom (or wall) on its left to the next atom
        assert np.allclose(springs[n].pos + springs[n].axis, atom.pos)
    assert np.allclose(last(springs[4], "pos") + last(springs[4], "axis"), [2.5, 0, 0])
    assert abs(atoms[0].pos[-1, 0] - atoms[0].pos[0, 0]) > 0.01          # it moved


def check_doublependulum(rec):
    assert kinds(rec) == {"box": 3, "cylinder": 1}
    theta, omega, t = 1.0, 0.0, 0.0
    while t < 1.5:
        omega += -1.5 * 9.8 / 0.8 * np.sin(theta) * 0.001
        theta += omega * 0.001
        t += 0.001
    assert rec.globals["theta"] == pytest.approx(theta, abs=1e-9)
    end = 0.8 * np.array([np.sin(theta), -np.cos(theta), 0])
    assert last(rec["plate"], "pos") == pytest.approx(end + [0, -0.05, 0], abs=1e-6)
    bar = last(rec["bar"], "pos")                       # the bar's middle, half way out
    assert bar[:2] == pytest.approx(end[:2] / 2, abs=1e-6)


def check_extruded_columns(rec):
    assert kinds(rec)["box"] == 1 and len(extrusions(rec)) == 7 == len(rec.objects) - 1
    bodies = [tr for tr in extrusions(rec) if abs(extent(tr)[-1] - 2) < 0.05]
    assert len(bodies) == 2                             # the two shafts, 2 tall
    for body, x in zip(bodies, (-0.8, 0.8)):
        assert 0.25 < extent(body)[1] < 0.31            # a 12-gon of radius 0.15
        assert last(body, "pos")[[0, 1]] == pytest.approx([x, 1], abs=0.05)


def check_faces_cone(rec):
    assert kinds(rec) == {"box": 1, "faces": 1}
    assert printed_numbers(rec) == [3 * 8]


def check_faces_heightfield(rec):
    assert kinds(rec) == {"faces": 1}
    side = len(np.arange(-1, 1.01, 0.25)) - 1
    assert printed_numbers(rec) == [side * side * 2 * 3 * 2]    # two-sided triangles


def check_gas(rec):
    assert kinds(rec) == {"curve": 2, "sphere": 12}
    pos = np.stack([a.pos for a in rec["atoms"]], axis=1)
    assert pos.min() > 0.05 - 0.02 and pos.max() < 0.95 + 0.02    # kept in the box
    means = [s for s in rec.series if s.kind == "gcurve"][0].points()
    assert len(means) == 50
    assert np.ptp(means[:, 1]) < 1e-9 < means[0, 1]     # walls keep every speed
    assert any(s.kind != "gcurve" for s in rec.series)  # the histogram


def check_glinfo(rec):
    assert kinds(rec) == {"box": 1}
    first, *report = rec.printed.strip().splitlines()
    assert first.startswith("Python 3") and "".join(report).strip()


def check_graphtest(rec):
    by_kind = {}
    for s in rec.series:
        by_kind.setdefault(s.kind, []).append(s)
    decay = by_kind["gcurve"][0].points()
    assert len(decay) == 40 and decay[0].tolist() == [0, 4]
    assert decay[5, 1] == pytest.approx(4 * np.exp(-0.25) * np.cos(2.0))
    assert len(by_kind["gdots"][0].points()) == 40
    bars = {tuple(p) for s in by_kind["gvbars"] for p in s.points().tolist()}
    assert {(5, 2), (15, 3), (25, 2), (35, 1), (45, 2)} <= bars   # both plots counted


def check_gyro2(rec):
    assert kinds(rec) == {"box": 1, "cylinder": 2, "curve": 1}
    tip = rec["trail"].points()
    assert len(tip) >= 140                              # one point a picture
    assert np.allclose(tip[:, 1], 0.8 * np.cos(np.pi / 4))         # steady tilt
    assert np.allclose(np.hypot(tip[:, 0], tip[:, 2]), 0.8 * np.sin(np.pi / 4))
    phidot = 9.8 * 0.4 / (0.5 * 0.3 ** 2 * 40)
    assert rec.globals["phi"] == pytest.approx(phidot * rec.globals["t"], rel=1e-6)
    disk = last(rec["disk"], "axis")
    assert disk / np.linalg.norm(disk) == pytest.approx(tip[-1] / 0.8, abs=1e-6)


def check_labels(rec):
    assert kinds(rec) == {"cylinder": 1, "label": 3}
    assert last(rec["right"], "pos").tolist() == [2, 0, 0]
    assert last(rec["middle"], "text") == "the\nmiddle"
    assert last(rec["middle"], "yoffset") == -30 and last(rec["left"], "xoffset") == -20


def check_lathe(rec):
    slices = rec.of_kind("convex")
    assert len(slices) == sum(printed_numbers(rec)) >= 3
    colours = {tuple(np.round(last(s, "color"), 3)) for s in slices}
    assert colours == {(1, 0.6, 0), (0, 1, 1)}


def check_lorenz(rec):
    assert kinds(rec) == {"curve": 1, "box": 5}
    y = np.array([1.0, 1.0, 0.0])
    for _ in np.arange(0, 30, 0.02):
        d = np.array([-y[1] - y[2], y[0] + 0.2 * y[1], 0.2 + y[2] * (y[0] - 5.7)])
        y = y + d * 0.02
    pts = rec["path"].points()
    assert len(pts) == 1500 and pts[-1] == pytest.approx(y, abs=1e-9)


def check_mandelbrot(rec):
    drawn = 0
    for y0 in np.arange(-1, 1, 0.05):
        for x0 in np.arange(-1.5, 1.5, 0.05):
            z, n = complex(x0, y0), 0
            while abs(z) < 2 and n < 40:
                z, n = z * z + complex(-0.8, 0.156), n + 1
            drawn += 0.1 < n / 40 < 1
    assert drawn > 100
    dots = [s for s in rec.series if s.kind == "gdots"]      # one series a colour plotted
    assert sum(len(s.points()) for s in dots) == drawn == rec.globals["drawn"]
    colours = [s.color for s in dots]
    assert len(dots) > 5 and len(set(colours)) == len(colours)


def check_medusa(rec):
    assert len(extrusions(rec)) == 4 == len(rec.objects)
    for tail in rec["tails"]:
        assert 1.45 < extent(tail)[-1] < 1.7            # 16 points 0.1 apart
    assert extent(rec["bell"])[-1] == pytest.approx(1.6 + 0.04, abs=0.1)   # the crescent


def check_orbit(rec):
    assert kinds(rec) == {"sphere": 2, "curve": 2}
    heavy, light = rec["heavy"].pos, rec["light"].pos
    cm = (3 * heavy + light) / 4
    assert np.abs(cm).max() < 1e-6 * 1e11               # the centre of mass stays put
    assert np.linalg.norm(heavy[-1] - heavy[0]) > 1e9   # while both move
    trails = [tr.points() for tr in rec.of_kind("curve")]
    assert all(55 <= len(p) <= 61 for p in trails)      # a point every 5 steps of 300


def check_randombox(rec):
    assert kinds(rec) == {"curve": 2, "box": 40, "arrow": 1, "cylinder": 1}
    counts = sorted(len(tr.points()) for tr in rec.of_kind("curve"))
    assert counts == [5, 48]
    sizes = np.array([last(b, "size") for b in rec.of_kind("box")])
    assert sizes.min() >= 1 and sizes.max() <= 4        # randrange(1, 5)


def check_stars(rec):
    assert kinds(rec) == {"sphere": 4, "curve": 4}
    merged = int(rec.globals["merged"])
    visible = [last(s, "visible") for s in rec["stars"]]
    assert merged >= 1 and sum(visible) == 4 - merged
    trails = rec.of_kind("curve")
    assert sum(last(tr, "visible") for tr in trails) == 4 - merged   # gone with its star


def check_text3D(rec):
    assert kinds(rec) == {"compound": 1, "curve": 2, "label": 2, "sphere": 4}   # 3D text
    rise = rec["rise"].points()
    assert len(rise) == 2 and np.linalg.norm(rise[1] - rise[0]) > 0.1
    count, descent = rec.printed.split()[:2]        # one line's width; the descender
    assert count == "1" and 0.1 < float(descent) < 0.4
    span = rec["span"].points()                     # upper_left to upper_right: the width
    assert np.linalg.norm(span[1] - span[0]) > 2


def check_texture_and_lighting(rec):
    assert kinds(rec)["sphere"] == 2 and kinds(rec)["box"] == 1
    assert last(rec["ball"], "pos") == pytest.approx([-2 + 1.5 * 0.04 * 50, 1, 0], abs=0.07)
    lights = rec.canvases[0]["lights"]
    assert [lt["kind"] for lt in lights] == ["distant_light", "local_light"]


def check_tictacdat(rec):
    assert kinds(rec) == {"curve": 1}
    assert len(rec["grid"].points()) == 2 * 4 * 3        # 4 lines each way, 3 points each
    assert rec.printed.strip() == "8 ways to win"


def check_toroid(rec):
    assert kinds(rec) == {"curve": 1, "arrow": 4}
    assert len(rec["loop"].points()) == 61
    centre, ideal = printed_numbers(rec)
    assert centre == pytest.approx(ideal, rel=0.01)     # mu0 I / 2R
    probes = rec["probes"]
    assert [np.linalg.norm(last(p, "axis")) for p in probes] == sorted(
        (np.linalg.norm(last(p, "axis")) for p in probes), reverse=True)


def check_wave(rec):
    strings = rec["strings"]
    assert [len(s.points()) for s in strings] == [80, 80]
    assert len({s.canvas for s in strings}) == 2       # a window each
    fronts = []
    for s in strings:
        y = s.points()[:, 1]
        assert y[0] == 0 and y[-1] == 0                  # the ends held
        fronts.append(np.nonzero(np.abs(y) > 0.01 * np.abs(y).max())[0].max())
    # waves run at sqrt(k/m) points a second: 2 and 4 for 8 s, from a pulse 20 wide
    assert 20 + 12 <= fronts[0] <= 20 + 20 and fronts[1] >= fronts[0] + 10


def check_convex(rec):
    assert kinds(rec) == {"convex": 4}
    assert printed_numbers(rec)[0] == 42
    assert last(rec["ring"], "color").tolist() == [1, 0.5, 0]


def check_crossproduct(rec):
    assert kinds(rec) == {"curve": 1, "label": 1, "arrow": 3}
    r, F, torque = rec["r"].axis, rec["F"].axis, rec["torque"].axis
    assert np.allclose(torque, np.cross(r, F))          # at every frame
    assert np.ptp(F[:, 0]) > 3                          # while F turns
    assert rec.globals["clicks"] == 0


def check_electric_motor(rec):
    assert kinds(rec)["cylinder"] == 1 and len(extrusions(rec)) == 3 == len(rec.objects) - 1
    assert extent(rec["core"]) == pytest.approx([2, 3, 3], abs=0.02)   # slots cut in the rim
    axis = rec["shaft"].axis
    assert np.allclose(axis, axis[0]) and np.allclose(np.linalg.norm(axis, axis=1), 4.5)
    up = rec["core"].up                                 # turning about the shaft
    assert np.linalg.norm(up[-1] - up[0]) > 0.1


def check_gyro(rec):
    assert kinds(rec) == {"helix": 1, "cylinder": 1, "curve": 1, "arrow": 1, "compound": 1}
    y, p, t = -0.8, 0.0, 0.0                            # the wheel below the top; its p
    while t < 2:
        p += (60 * (-y - 0.8) - 9.8) * 0.01             # the spring's pull and gravity
        y += p * 0.01
        t += 0.01
    assert last(rec["spring"], "axis") == pytest.approx([0, y, 0], abs=1e-9)
    assert rec["spring"].axis[1:, 1].max() < -0.8       # it hangs, stretched (from frame 1)
    assert last(rec["disk"], "pos") == pytest.approx([0, 1 + y, -0.05], abs=1e-9)
    assert last(rec["tag"], "pos")[0] < -0.3            # the text followed its frame


def check_differential_gear(rec):
    assert len(extrusions(rec)) == 2 == len(rec.objects) - 2
    assert kinds(rec)["box"] == 1 and kinds(rec)["label"] == 1
    big, small = last(rec["big"], "size"), last(rec["small"], "size")
    assert 6 < np.sort(big)[-1] < 7.5 and np.sort(big)[-1] > 1.5 * np.sort(small)[-1]
    assert rec.globals["turns"] == 40


def check_material_test(rec):
    assert kinds(rec) == {"box": 6, "label": 12, "sphere": 6}
    assert all(last(b, "visible") == 0 for b in rec.of_kind("box"))
    assert all(last(s, "visible") == 1 for s in rec.of_kind("sphere"))
    texts = [last(lb, "text") for lb in rec.of_kind("label") if last(lb, "visible")]
    assert sorted(texts) == sorted(["wood", "rough", "marble", "plastic", "emissive", "shiny"])


def check_stonehenge(rec):
    k = kinds(rec)
    assert k["ring"] == 8 and k["cone"] == 4 and k["pyramid"] == 1
    marks = [s for s in rec.of_kind("sphere") if last(s, "size")[0] == pytest.approx(2 / 15)]
    assert [tuple(last(s, "color")) for s in marks] == [
        pytest.approx(colorsys.hsv_to_rgb(n / 12, 1, 1)) for n in range(12)]
    ring = rec.of_kind("ring")[0].pos
    assert ring[-1, 1] > ring[0, 1]                     # the smoke rises


def check_toroid_drag(rec):
    assert kinds(rec) == {"curve": 1, "arrow": 3}
    pts = rec["loop"].points()
    assert len(pts) == 81
    delta, centre = np.diff(pts, axis=0), (pts[1:] + pts[:-1]) / 2
    scale = 0.3 / (2 * np.sqrt(2) * 1e-7 / (np.pi * 0.5))
    for arrow in rec["fields"]:
        r = last(arrow, "pos") - centre                 # Biot-Savart, summed here again
        B = (1e-7 * np.cross(delta, r) / np.linalg.norm(r, axis=1)[:, None] ** 3).sum(0)
        assert last(arrow, "axis") == pytest.approx(scale * B, rel=1e-6)


def check_planar(rec):
    assert kinds(rec) == {"cylinder": 6, "curve": 11}
    nodes, links = rec["nodes"], rec["links"]
    for frame in (0, rec.frames - 1):
        for i, link in enumerate(links):
            ends = link.points(frame)
            assert np.allclose(ends, [nodes[i].pos[frame], nodes[(i + 2) % 6].pos[frame]])
    assert nodes[0].pos[-1, 0] > nodes[0].pos[0, 0] + 1       # the node slid, its links too


# -- the table ----------------------------------------------------------------------------

def needs(feature: str):
    return pytest.mark.xfail(strict=True, reason=f"needs {feature}")



EXAMPLES = {
    "bounce": check_bounce,
    "bounce2": check_bounce2,
    "boxlighttest": check_boxlighttest,
    "conch": check_conch,
    "crystal": check_crystal,
    "doublependulum": check_doublependulum,
    "extruded_columns": check_extruded_columns,
    "faces_cone": check_faces_cone,
    "faces_heightfield": check_faces_heightfield,
    "gas": check_gas,
    "glinfo": check_glinfo,
    "graphtest": check_graphtest,
    "gyro2": check_gyro2,
    "labels": check_labels,
    "lathe": check_lathe,
    "lorenz": check_lorenz,
    "mandelbrot": check_mandelbrot,
    "medusa": check_medusa,
    "orbit": check_orbit,
    "randombox": check_randombox,
    "stars": check_stars,
    "text3D": check_text3D,
    "texture_and_lighting": check_texture_and_lighting,
    "tictacdat": check_tictacdat,
    "toroid": check_toroid,
    "wave": check_wave,
    "convex": check_convex,
    "crossproduct": check_crossproduct,
    "electric_motor": check_electric_motor,
    "gyro": check_gyro,
    "differential_gear": check_differential_gear,
    "material_test": check_material_test,
    "stonehenge": check_stonehenge,
    "toroid_drag": check_toroid_drag,
    "planar": check_planar,
}


def _cases():
    for example, entry in EXAMPLES.items():
        check, *marks = entry if isinstance(entry, tuple) else (entry,)
        yield pytest.param(example, check, marks=marks, id=example)


def program(example: str):
    return PROGRAMS / f"vp6_ex_{example}.py"


def test_the_table_covers_the_examples_that_run_without_input():
    assert sorted(EXAMPLES) == sorted(NO_INPUT + OPTIONAL_INPUT)
    assert len(EXAMPLES) == 35
    ours = sorted(p.name for p in PROGRAMS.glob("vp6_ex_*.py"))
    assert ours == sorted(program(e).name for e in EXAMPLES)
    for example in EXAMPLES:                            # each says what it stands for
        assert f"examples/{example}.py" in program(example).read_text()


# -- draft stills -------------------------------------------------------------------------

def still(example: str, tmp_path) -> np.ndarray:
    out = tmp_path / "still.png"
    run_program(program(example), out, RunOptions(fps=10, duration=5, antialias=False,
                                                  page=False, canvas_only=True))
    return np.asarray(Image.open(out).convert("RGB")).astype(int)


def near(img, rgb, tol=60) -> np.ndarray:
    return np.abs(img - np.array(rgb)).max(axis=-1) < tol


def test_bounce_still_has_the_pebble_above_the_slab(tmp_path):
    img = still("bounce", tmp_path)
    pebble = np.nonzero(near(img, (0, 255, 255), 90))
    slab = np.nonzero((img[..., 0] > 150) & (img[..., 1] > 60) & (img[..., 1] < 180)
                      & (img[..., 2] < 60))
    assert pebble[0].size > 300 and slab[0].size > 2000
    assert pebble[0].max() < slab[0].min()              # rows: the pebble is higher
    assert abs(pebble[1].mean() - slab[1].mean()) < 10  # above its middle


def test_lathe_still_has_an_upright_orange_vase_and_a_cyan_peg(tmp_path):
    img = still("lathe", tmp_path)
    vase = np.nonzero((img[..., 0] > 120) & (img[..., 2] < 60) & (img[..., 1] < img[..., 0]))
    peg = np.nonzero((img[..., 2] > 120) & (img[..., 1] > 120) & (img[..., 0] < 60))
    assert vase[0].size > 1000 and peg[0].size > 300
    assert vase[1].mean() < peg[1].mean()               # the vase on the left
    assert np.ptp(vase[0]) > np.ptp(vase[1])            # turned upright: taller than wide


def test_crossproduct_still_has_three_arrows(tmp_path):
    img = still("crossproduct", tmp_path)
    for rgb in ((255, 150, 0), (255, 0, 255), (0, 255, 255)):
        lit = (img[..., 0] * rgb[0] + img[..., 1] * rgb[1] + img[..., 2] * rgb[2]) / 255
        other = img.sum(-1) - lit
        assert ((lit > 150) & (other < 0.5 * lit)).sum() > 150, rgb


def test_faces_heightfield_still_is_a_magenta_surface(tmp_path):
    img = still("faces_heightfield", tmp_path)
    magenta = (img[..., 0] > 80) & (img[..., 2] > 80) & (img[..., 1] < 0.5 * img[..., 0])
    assert magenta.sum() > 5000
    rows, cols = np.nonzero(magenta)
    h, w = magenta.shape
    assert abs(cols.mean() - w / 2) < w / 8 and abs(rows.mean() - h / 2) < h / 6


def test_lorenz_still_colours_its_curve_by_speed(tmp_path):
    img = still("lorenz", tmp_path)
    r, g = img[..., 0], img[..., 1]
    slow = np.nonzero((g > r + 60) & (g > 100))          # green: the slow inner turns
    fast = np.nonzero((r > g + 60) & (r > 100))          # magenta: the fast outer loop
    assert slow[0].size > 100 and fast[0].size > 300
    h, w = r.shape
    spread = [np.hypot(rows - h / 2, cols - w / 2).mean() for rows, cols in (slow, fast)]
    assert spread[0] < spread[1]                        # the slow part inside the fast


# -- each program to its recording (after the stills, which load the renderer once) ---

@pytest.mark.parametrize("example, check", list(_cases()))
def test_the_program_standing_for_the_example(example, check, tmp_path):
    out = tmp_path / "run.jsonl"
    result = run_program(program(example), out, RunOptions(fps=10, duration=5))
    assert result.ended == "program"                   # bounded: each ends by itself
    check(read(out))
