"""The recording (docs/recording.md): a run as data, written frame by frame and read back.

The wiki program's ball against the page's own loop; only changes written; curves and
trails as point lists (retain included); labels, deletions, graphs and printed text; the
program's names and globals; gzip and a file cut short; bad flags; memory kept bounded.
"""

from __future__ import annotations

import gzip
import json
import re
import textwrap

import numpy as np
import pytest

from conftest import ROOT, run_cli
from springscene import config, render
from springscene.errors import ProgramError, UserError
from springscene.vpython.record.reader import numbers, read
from springscene.vpython.run.options import RunOptions
from springscene.vpython.run.runner import run_program

EXAMPLES = ROOT / "examples"


def write(tmp_path, source: str, name: str = "prog.py"):
    path = tmp_path / name
    path.write_text(textwrap.dedent(source))
    return path


def lines(path) -> list[dict]:
    opener = gzip.open if str(path).endswith(".gz") else open
    with opener(path, "rt") as fh:
        return [json.loads(line) for line in fh]


def record(tmp_path, program, **options):
    out = tmp_path / "run.jsonl"
    result = run_program(program, out, RunOptions(**options))
    return result, read(out)


def test_the_wiki_ball_is_the_page_loop_bit_for_bit(tmp_path):
    result, rec = record(tmp_path, EXAMPLES / "wiki_spring.py", frames=50)
    assert (result.frames, result.ended, rec.frames) == (50, "frames", 50)
    assert np.array_equal(rec.times, np.arange(50) / 50)
    traj = render.simulate(config.load(WIKI_CONFIG), 1.0)
    assert np.array_equal(rec["ball"].pos, traj.pos[2 * np.arange(50)])   # exact
    # the spring is redrawn along ball.pos - holder.pos at every frame
    assert np.array_equal(rec["spring"].axis, rec["ball"].pos - rec["holder"].pos)
    assert rec["spring"].kind == "helix" and rec["holder"].kind == "box"
    assert np.all(rec["spring"].coils == 15)
    assert rec.globals["k"] == 15 and rec.globals["m"] == 0.1
    assert np.array_equal(rec.globals["g"], [0, -9.8, 0])
    assert "sphere" not in rec.globals and "pi" not in rec.globals    # VPython's own names
    cv = rec.canvases[0]
    assert (cv["width"], cv["height"], cv["background"]) == (900, 600, [1, 1, 1])
    assert cv["title"] == "Ball and Spring Model of Matter"
    snap = rec.at(0.5)
    assert snap.frame == 25 and np.array_equal(snap["ball"].pos, rec["ball"].pos[25])


WIKI_CONFIG = ROOT / "configs" / "wiki.toml"


def test_a_video_run_records_the_frames_it_films(tmp_path):
    seen = []

    def on_frame(i, image):
        from springscene.vpython.core.canvases import canvas
        ball = next(o for o in canvas._all[0]._objects if o._kind == "sphere")
        seen.append(ball.pos.value)

    result = run_program(EXAMPLES / "wiki_spring.py", tmp_path / "w.mp4",
                         RunOptions(frames=10, fps=25, antialias=False,
                                    record=str(tmp_path / "w.jsonl.gz")),
                         on_frame=on_frame)
    assert result.recording == tmp_path / "w.jsonl.gz" and (tmp_path / "w.mp4").is_file()
    rec = read(tmp_path / "w.jsonl.gz")
    assert rec.frames == result.frames == 10
    assert np.array_equal(rec["ball"].pos, np.array(seen))


def test_only_what_changed_is_written(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        a = sphere(pos=vector(-1, 0, 0))
        b = sphere(pos=vector(1, 0, 0), color=color.red)
        c = box()
        for i in range(20):
            rate(50)
            a.pos.x += 0.1          # in place
            if i == 10:
                c.color = color.green
    """)
    run_program(prog, tmp_path / "run.jsonl", RunOptions(fps=50))
    frames = [line for line in lines(tmp_path / "run.jsonl") if "frame" in line]
    assert [o["kind"] for o in frames[0]["new"]] == ["sphere", "sphere", "box"]
    for line in frames[1:]:
        assert "new" not in line
        assert set(line["set"]) <= {"pos", "color"}
        assert line["set"]["pos"]["ids"] == [0]
        assert numbers(line["set"]["pos"]).shape == (3,)
    changed_colour = [line["frame"] for line in frames if "color" in line.get("set", {})]
    assert len(changed_colour) == 1
    colour = frames[changed_colour[0]]["set"]["color"]
    assert colour["ids"] == [2] and numbers(colour).tolist() == [0.0, 1.0, 0.0]
    rec = read(tmp_path / "run.jsonl")
    # frame f is taken at the f-th rate(), after f moves; the last is the scene the
    # program left when it ended, at its end time
    assert rec.frames == 21 and rec.times[-1] == pytest.approx(0.4)
    assert np.allclose(rec["a"].pos[:, 0], -1 + 0.1 * np.arange(21))


def test_trails_and_curves_are_point_lists(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        ball = sphere(make_trail=True, retain=5)
        path = curve(pos=[vector(0, 0, 0), vector(1, 0, 0)], color=color.blue)
        for i in range(30):
            rate(25)
            ball.pos = vector(i * 0.1, (i * 0.1) ** 2, 0)
            if i == 12:
                path.modify(1, pos=vector(2, 2, 0))
            if i == 20:
                path.append(vector(3, 0, 0), color=color.red)
    """)
    truth = {}

    def on_frame(i, image):
        from springscene.vpython.core.canvases import canvas
        for o in canvas._all[0]._objects:
            if o._kind == "curve":
                truth.setdefault(id(o), []).append([p["pos"].value for p in o._pts])

    run_program(prog, tmp_path / "run.jsonl", RunOptions(fps=25), on_frame=on_frame)
    rec = read(tmp_path / "run.jsonl")
    curves = rec.of_kind("curve")
    assert len(curves) == 2
    trail = next(c for c in curves if c.first["retain"] == 5)
    shape = rec["path"]
    truths = list(truth.values())
    for track, expected in zip((trail, shape) if len(truths[0][-1]) <= 5 else (shape, trail),
                               truths):
        for f in range(len(expected)):         # the video's frames (then the end's)
            assert np.allclose(track.points(f), np.array(expected[f]).reshape(-1, 3)), f
    assert len(trail.points()) == 5                    # retain keeps the newest five
    assert np.allclose(shape.points()[-1], [3, 0, 0])
    kinds = {k for line in lines(tmp_path / "run.jsonl") for c in line.get("points", {}).values()
             for k in c}
    assert kinds == {"reset", "append", "drop"}       # appends stay appends


def test_labels_deletions_graphs_and_printed_text(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        ball = sphere()
        tag = label(pos=vector(0, 1, 0), text="t = 0")
        gone = box(pos=vector(2, 0, 0))
        g = graph(title="height", xtitle="t", ytitle="y")
        line = gcurve(color=color.red, label="y")
        for i in range(10):
            rate(10)
            t = (i + 1) * 0.1
            tag.text = "t = {:.1f}".format(t)
            line.plot(t, t * t)
            print("step", i)
            if i == 4:
                gone.delete()
    """)
    _, rec = record(tmp_path, prog, fps=10)
    texts = rec["tag"].text
    assert texts[0] == "t = 0" and texts[-2] == "t = 0.9"
    assert texts[-1] == "t = 1.0"        # the scene the program left: a frame at its end
    assert rec["tag"].kind == "label"
    gone = rec["gone"] if "gone" in rec else rec.of_kind("box")[0]
    assert gone.deleted is not None
    assert np.isnan(gone.pos[gone.deleted:]).all() and not np.isnan(gone.pos[:gone.deleted]).any()
    (series,) = rec.series
    assert series.kind == "gcurve" and series.label == "y" and series.color == (1, 0, 0)
    assert series.graph["title"] == "height"
    xy = series.points()
    assert np.allclose(xy[:, 1], xy[:, 0] ** 2) and len(xy) >= 9
    assert len(series.points(frame=3)) < len(xy)          # the graph grows with the frames
    assert rec.printed.startswith("step 0\nstep 1\n") and "step 8\n" in rec.printed


def test_gzip_and_a_recording_cut_short(tmp_path):
    _, rec = record(tmp_path, EXAMPLES / "bounce.py", frames=20, fps=25)
    full = (tmp_path / "run.jsonl").read_text()
    with gzip.open(tmp_path / "run.jsonl.gz", "wt") as fh:
        fh.write(full)
    again = read(tmp_path / "run.jsonl.gz")
    assert again.frames == rec.frames and np.array_equal(again["ball"].pos, rec["ball"].pos)
    cut = full[: full.rindex('{"frame":10') + 20]       # killed mid-line: no end line
    (tmp_path / "cut.jsonl").write_text(cut)
    short = read(tmp_path / "cut.jsonl")
    assert short.frames == 10 and short.end is None
    (tmp_path / "other.jsonl").write_text('{"hello": 1}\n')
    with pytest.raises(UserError, match="not a springscene recording"):
        read(tmp_path / "other.jsonl")


def test_a_program_error_keeps_the_recording_up_to_it(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        b = sphere()
        for i in range(10):
            rate(10)
            b.pos.x += 1
        raise ValueError("no more data")
    """)
    with pytest.raises(ProgramError, match="no more data"):
        run_program(prog, tmp_path / "v.mp4", RunOptions(fps=10, antialias=False,
                                                         record=str(tmp_path / "r.jsonl")))
    assert sorted(p.name for p in tmp_path.iterdir()) == ["prog.py", "r.jsonl", "v.html",
                                                          "v.mp4"]
    rec = read(tmp_path / "r.jsonl")
    assert rec.times[-1] == 1.0 and len(rec.times) == 11 and rec["b"].pos[-1, 0] == 10
    assert (rec.error["type"], rec.error["message"], rec.error["t"], rec.error["line"]) == (
        "ValueError", "no more data", 1.0, 7)


@pytest.mark.parametrize("args, message", [
    (["--record", "r.txt"], "r.txt: the recording is a .jsonl or .jsonl.gz file"),
    (["--record", "nowhere/r.jsonl"], "nowhere/r.jsonl: folder"),
    (["--out", "r.jsonl", "--record", "s.jsonl"], "the output r.jsonl is the recording already"),
    (["--out", "r.jsonl", "--fps", "0"], "--fps 0: must be a whole number above 0"),
])
def test_bad_record_flags_are_one_line_exit_2(tmp_path, cli, args, message):
    (tmp_path / "p.py").write_text("from vpython import *\nsphere()\n")
    args = [str(tmp_path / a) if a.endswith((".txt", ".jsonl")) else a for a in args]
    if str(tmp_path / "r.jsonl") not in args:
        args = ["--out", tmp_path / "v.mp4"] + args
    proc = cli("vpython", tmp_path / "p.py", *args)
    err = proc.stderr
    assert proc.returncode == 2 and err.count("\n") == 1 and message in err, err
    assert sorted(p.name for p in tmp_path.iterdir()) == ["p.py"]


def test_the_command_writes_the_recording_beside_the_video(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        b = sphere()
        while True:
            rate(50)
            b.pos.x += 0.01
    """)
    proc = run_cli("vpython", str(prog), "--out", str(tmp_path / "v.mp4"), "--draft",
                   "--duration", "1", "--fps", "25", "--record", str(tmp_path / "v.jsonl"))
    assert proc.returncode == 0, proc.stderr
    assert f"wrote {tmp_path / 'v.jsonl'}" in proc.stdout
    rec = read(tmp_path / "v.jsonl")
    assert rec.frames == 25 and np.allclose(np.diff(rec["b"].pos[:, 0]), 0.02)
    leftovers = [p.name for p in tmp_path.iterdir() if p.name.startswith(".")]
    assert leftovers == []


def test_recording_memory_is_bounded(tmp_path):
    """A long run of a thousand moving spheres: the recording adds well under 50 MB to the
    run's peak (it holds one row an object, not the frames), drawn or not."""
    prog = write(tmp_path, """
        from vpython import *
        balls = [sphere(pos=vector(i % 10, (i // 10) % 10, i // 100), radius=0.2)
                 for i in range(1000)]
        t = 0
        while True:
            rate(25)
            t += 0.04
            for i, b in enumerate(balls):
                b.pos.y = (i // 10) % 10 + 0.3 * sin(t + i)
    """)

    def peak(*extra) -> float:
        proc = run_cli("vpython", str(prog), "--duration", "60", "--fps", "5", "--draft",
                       "--no-page", *extra)
        assert proc.returncode == 0, proc.stderr
        found = re.search(r"peak memory ([\d.]+)M", proc.stdout)
        return float(found.group(1))

    plain = peak("--out", str(tmp_path / "a.mp4"))
    recorded = peak("--out", str(tmp_path / "b.mp4"), "--record", str(tmp_path / "b.jsonl"))
    assert read(tmp_path / "b.jsonl").frames == 300
    assert recorded - plain < 50, (plain, recorded)


def test_a_label_and_a_solid_changing_colour_in_one_frame(tmp_path):
    """A label's colours may be unset (the canvas's): recorded as null, then as numbers
    beside the solids' in the same frame."""
    prog = write(tmp_path, """
        from vpython import *
        b = sphere()
        tag = label(pos=vector(0, 1, 0), text="hi")
        for i in range(5):
            rate(10)
            b.color = vector(i / 10, 0, 0)
            tag.color = vector(0, i / 10, 0)
    """)
    _, rec = record(tmp_path, prog, fps=10)
    assert rec["tag"].first["color"] is None                 # the canvas's until set
    assert np.allclose(rec["tag"].color[1:, 1], np.arange(5) / 10)
    assert np.allclose(rec["b"].color[1:, 0], np.arange(5) / 10)


def test_objects_in_a_vpython6_frame_are_recorded_where_they_are_drawn(tmp_path):
    prog = write(tmp_path, """
        from visual import *
        f = frame()
        inside = box(frame=f, pos=(1, 0, 0))
        path = curve(pos=[(0, 0, 0), (1, 1, 0)])
        for i in range(6):
            rate(10)
            f.pos.x += 1
            if i == 3:
                f.visible = False
    """)
    _, rec = record(tmp_path, prog, fps=10)
    box = rec["inside"]
    assert np.array_equal(box.pos[:, 0], np.arange(1, 8))      # the world's: 1 + frame's x
    assert box.visible.tolist() == [1, 1, 1, 1, 0, 0, 0]       # hidden with its frame
    assert len(rec["path"].points()) == 2                      # a curve after it: recorded


def test_a_curves_colour_and_place_change_without_its_points_sent_again(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        c = curve(pos=[vector(i, 0, 0) for i in range(500)])
        for i in range(20):
            rate(10)
            c.origin = vector(0, i, 0)
            c.color = vector(1, i / 20, 0)
            if i == 10:
                c.modify(3, pos=vector(3, 5, 0))
    """)
    _, rec = record(tmp_path, prog, fps=10)
    changes = [list(line.get("points", {}).values()) for line in lines(tmp_path / "run.jsonl")
               if "frame" in line]
    resets = [f for f, c in enumerate(changes) if c and "reset" in c[0]]
    assert len(resets) == 2                           # made, and the one modify()
    assert rec["c"].points(resets[1])[3].tolist() == [3, 5, 0]
    assert rec["c"].origin[-1].tolist() == [0, 19, 0]


def test_a_page_for_a_huge_scene_is_the_picture_page_with_a_note(tmp_path):
    """Past PAGE_MAX_OBJECTS the recording made only for the page gives up at once (its
    memory is not spent): the page shows the picture, and a note says why."""
    from springscene.vpython.run import runner

    prog = write(tmp_path, f"""
        from vpython import *
        scene.width, scene.height = 120, 80
        for i in range({runner.PAGE_MAX_OBJECTS + 1}):
            sphere(pos=vector(i % 80, i // 80, 0), radius=0.3)
    """)
    result = run_program(prog, tmp_path / "big.png", RunOptions())
    assert any("more than 5,000 objects" in n for n in result.notes)
    page = (tmp_path / "big.html").read_text()
    assert "glow.min.js" not in page and 'src="big.png"' in page
    assert sorted(p.name for p in tmp_path.iterdir()) == ["big.html", "big.png", "prog.py"]


# Every way a program changes a solid, helix, arrow, ring or compound through VPython's
# attributes: the recorder reads a moving object's position alone and the rest only when
# the object counted a change (``_looks``), so each of these must be counted.
_CHANGES = {
    "pos": lambda o, vp: setattr(o, "pos", vp.vector(1, 2, 3)),
    "pos.x": lambda o, vp: setattr(o.pos, "x", 7),
    "axis": lambda o, vp: setattr(o, "axis", vp.vector(0, 2, 1)),
    "axis.y": lambda o, vp: setattr(o.axis, "y", 3),
    "up": lambda o, vp: setattr(o, "up", vp.vector(1, 0, 1)),
    "up.z": lambda o, vp: setattr(o.up, "z", 0.5),
    "size": lambda o, vp: setattr(o, "size", vp.vector(2, 3, 4)),
    "size.z": lambda o, vp: setattr(o.size, "z", 5),
    "length": lambda o, vp: setattr(o, "length", 3),
    "height": lambda o, vp: setattr(o, "height", 3),
    "width": lambda o, vp: setattr(o, "width", 3),
    "color": lambda o, vp: setattr(o, "color", vp.color.red),
    "color.y": lambda o, vp: setattr(o.color, "y", 0.25),
    "red": lambda o, vp: setattr(o, "red", 0.5),
    "opacity": lambda o, vp: setattr(o, "opacity", 0.5),
    "shininess": lambda o, vp: setattr(o, "shininess", 0.1),
    "emissive": lambda o, vp: setattr(o, "emissive", True),
    "visible": lambda o, vp: setattr(o, "visible", False),
    "rotate": lambda o, vp: o.rotate(angle=0.5, axis=vp.vector(0, 0, 1)),
}
_OWN_CHANGES = {
    "sphere": {"radius": lambda o, vp: setattr(o, "radius", 2)},
    "cylinder": {"radius": lambda o, vp: setattr(o, "radius", 2)},
    "arrow": {n: (lambda n: lambda o, vp: setattr(o, n, 0.3))(n)
              for n in ("shaftwidth", "headwidth", "headlength")}
    | {"round": lambda o, vp: setattr(o, "round", True)},
    "helix": {"coils": lambda o, vp: setattr(o, "coils", 9),
              "thickness": lambda o, vp: setattr(o, "thickness", 0.3),
              "ccw": lambda o, vp: setattr(o, "ccw", False),
              "radius": lambda o, vp: setattr(o, "radius", 2)},
    "ring": {"thickness": lambda o, vp: setattr(o, "thickness", 0.3),
             "radius": lambda o, vp: setattr(o, "radius", 2)},
}


def _recorded_rows(recorder, objs):
    """The rows the recorder holds for ``objs`` (what it wrote last), by kind."""
    out = []
    for o in objs:
        _, kind, row = recorder._ids[id(o)]
        out.append(recorder._tables[kind].rows[row].copy())
    return out


@pytest.mark.parametrize("kind", ["sphere", "box", "cylinder", "arrow", "helix", "ring",
                                  "compound"])
def test_every_change_to_a_solid_is_recorded_though_positions_are_read_apart(tmp_path, kind):
    import springscene.vpython.api as vp
    from springscene.vpython.record.recorder import Recorder
    changes = {**_CHANGES, **_OWN_CHANGES.get(kind, {})}
    for name, change in changes.items():
        vp.reset()

        def make():
            if kind == "compound":
                return vp.compound([vp.box(), vp.sphere(pos=vp.vector(1, 0, 0))])
            return getattr(vp, kind)(pos=vp.vector(0.5, 0, 0))
        still, moving, changed = make(), make(), make()
        recorder = Recorder(tmp_path / "r.jsonl", 25)
        try:
            recorder.take()
            moving.pos.y += 1            # read apart: only its position
            change(changed, vp)
            recorder.take()
            rows = _recorded_rows(recorder, [still, moving, changed])
            table = recorder._tables[recorder._ids[id(changed)][1]]
            truth = table.gather([still, moving, changed])
        finally:
            recorder.close({})
        np.testing.assert_array_equal(np.array(rows), truth, err_msg=f"{kind}.{name}")
        assert not np.array_equal(rows[2], rows[0]), (kind, name)


def test_globals_holding_none_and_deleted_objects_are_not_names(tmp_path):
    # a program's None (VPython 6's material_test keeps one) is no object's id, nor is a
    # list holding one, nor an object deleted before the end
    program = write(tmp_path, """
        from vpython import *
        ball = sphere()
        nothing = None
        some = [ball, None]
        gone = box()
        gone.visible = False
        gone.delete()
        rate(10)
    """)
    _, run = record(tmp_path, program, fps=10)
    assert set(run.names) == {"ball"}
