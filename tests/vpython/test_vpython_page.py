"""The page as the video: VPython's layout of titles, canvases, captions and graphs.

Numbers from VPython 7.6.5's page in headless Chromium (measured 2026-11-25): body
margin 8 px, background #f1f2f4, font 14.4 px sans-serif drawn as Liberation Sans,
a plain text line 16 px high, a 2-line title holding <sub> and <sup> 40 px high, the
canvas right under the title and the caption right under the canvas, a graph right
under the caption.
"""

from __future__ import annotations

import textwrap

import imageio.v3 as iio
import numpy as np

from springscene.vpython.text import html_text
from springscene.vpython.run.runner import run_program
from springscene.vpython.run.options import RunOptions

BG = (241, 242, 244)


def write(tmp_path, source: str, name: str = "prog.py"):
    p = tmp_path / name
    p.write_text(textwrap.dedent(source))
    return p


def rows_where(img, rgb, tol=30):
    return np.nonzero((np.abs(img.astype(int) - rgb).max(axis=-1) < tol).all(axis=1))[0]


# ---- the title and caption HTML ----------------------------------------------------------

def test_parse_keeps_styles_and_breaks():
    lines = html_text.parse("a <b>bold</b> <i>it</i>\nx<sub>1</sub><br>v<sup>2</sup>\n")
    assert len(lines) == 3                                   # the trailing break adds none
    assert [r.text for r in lines[0]] == ["a ", "bold", " ", "it"]
    assert lines[0][1].bold and lines[0][3].italic and not lines[0][0].bold
    assert lines[1][1].script == -1 and lines[2][1].script == 1
    assert html_text.parse("&lt;0, -9.8, 0&gt; m/s&sup2;")[0][0].text == "<0, -9.8, 0> m/s²"


def test_line_heights_are_chromiums():
    one = html_text.render_html("Ball and Spring", 300)
    two = html_text.render_html("Ball\nand Spring", 300)
    scripts = html_text.render_html("x<sub>1</sub> v<sup>2</sup>\nsecond line", 300)
    assert (one.shape[0], two.shape[0]) == (16, 32)
    assert scripts.shape[0] == 40                            # 24 + 16, as in Chromium
    assert html_text.render_html("", 300).shape == (0, 300, 3)


def test_bold_text_has_the_browsers_width():
    """"Spring" in bold at 14.4 px: 46 px in VPython's page (Liberation Sans, not DejaVu's
    53)."""
    img = html_text.render_html("<b>Spring</b>", 200, background=(255, 255, 255))
    cols = np.nonzero((img.min(axis=2) < 128).any(axis=0))[0]
    assert 43 <= cols.max() - cols.min() + 1 <= 47


def test_long_lines_wrap_at_the_width_and_words_stay_whole():
    text = "word " * 40
    img = html_text.render_html(text, 200)
    assert img.shape[1] == 200 and img.shape[0] >= 16 * 8
    for line in html_text._wrap(html_text.parse(text)[0], 200, html_text.FONT_PX):
        assert "".join(r.text for r in line).strip().split(" ")[0] == "word"


# ---- the page ------------------------------------------------------------------------------

PAGE = """
    from vpython import *
    scene.width, scene.height = 300, 200
    scene.background = color.white
    scene.title = "Title"
    scene.caption = "Caption one\\ncaption two"
    box(color=color.red)
    g = graph(width=260, height=150, title="y")
    c = gcurve(color=color.blue)
    for i in range(5):
        rate(50)
        c.plot(i, i * i)
"""


def test_page_order_title_canvas_caption_graph(tmp_path):
    r = run_program(write(tmp_path, PAGE), tmp_path / "p.png")
    img = iio.imread(tmp_path / "p.png")
    assert tuple(img[3, 3]) == BG and r.size == (img.shape[1], img.shape[0])
    white = rows_where(img[:, 8:308], (255, 255, 255), tol=1)
    canvas_top = white.min()
    assert canvas_top == 8 + 16                       # one title line above the canvas
    assert tuple(img[canvas_top, 7]) == BG and tuple(img[canvas_top, 8]) == (255, 255, 255)
    caption_rows = img[canvas_top + 200:canvas_top + 232, 8:200]
    assert (caption_rows.min(axis=2) < 100).any()     # caption text under the canvas
    graph_top = canvas_top + 200 + 32
    graph = img[graph_top:graph_top + 150, 8:268].astype(int)
    assert (np.abs(graph - (0, 0, 255)).max(axis=2) < 60).sum() > 20     # the blue curve
    assert img.shape == (8 + 16 + 200 + 32 + 150 + 8, 8 + 300 + 8, 3)


def test_canvas_only_is_the_canvas_alone(tmp_path):
    run_program(write(tmp_path, PAGE), tmp_path / "c.png", RunOptions(canvas_only=True))
    img = iio.imread(tmp_path / "c.png")
    assert img.shape == (200, 300, 3) and tuple(img[2, 2]) == (255, 255, 255)


def test_graph_keeps_its_place_before_its_first_point(tmp_path):
    """The first frame comes before the first plot: the graph's place is kept (blank), so
    the video's size holds the graph once it is drawn."""
    frames = []
    run_program(write(tmp_path, PAGE), tmp_path / "p.mp4", RunOptions(page=False),
                on_frame=lambda i, img: frames.append(img))
    assert len({f.shape for f in frames}) == 1
    first, last = frames[0].astype(int), frames[-1].astype(int)
    bottom = slice(first.shape[0] - 8 - 150, first.shape[0] - 8)
    assert (first[bottom, 8:268] == BG).all()
    assert (np.abs(last[bottom, 8:268] - (0, 0, 255)).max(axis=2) < 60).sum() > 20


def test_two_canvases_in_page_order(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        a = canvas(width=200, height=100, background=color.red)
        box(canvas=a)
        b = canvas(width=120, height=80, background=color.blue, title="second")
        sphere(canvas=b)
    """)
    run_program(prog, tmp_path / "two.png")
    img = iio.imread(tmp_path / "two.png").astype(int)
    red = rows_where(img[:, 9:11], (255, 0, 0), tol=5)          # the canvases' left edges
    blue = rows_where(img[:, 9:11], (0, 0, 255), tol=5)
    assert red.min() == 8 and len(red) >= 90
    assert blue.min() >= red.max() + 16                   # below it, after its title
    assert img.shape[1] == 8 + 200 + 8


def test_a_canvas_resized_mid_run_is_shown_at_its_new_size(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        scene.width, scene.height = 300, 200
        scene.background = color.red
        box(size=vector(0.1, 0.1, 0.1))
        rate(10)
        scene.width, scene.height = 200, 120
        rate(10)
    """)
    frames = []
    r = run_program(prog, tmp_path / "r.mp4", RunOptions(page=False),
                    on_frame=lambda i, img: frames.append(img))
    assert r.frames == len(frames) >= 2 and len({f.shape for f in frames}) == 1
    def canvas_size(img):
        rows, cols = np.nonzero((img.astype(int) != BG).any(axis=2))
        return cols.max() - cols.min() + 1, rows.max() - rows.min() + 1

    assert canvas_size(frames[0]) == (300, 200) and canvas_size(frames[-1]) == (200, 120)
    assert tuple(frames[-1][8 + 150, 8 + 250]) == BG         # padded with the page


def test_no_page_text_twice_and_page_named_after_the_video(tmp_path):
    r = run_program(write(tmp_path, PAGE), tmp_path / "run.mp4", RunOptions(frames=2))
    page = (tmp_path / "run.html").read_text()
    assert r.page == tmp_path / "run.html" and not (tmp_path / "page.html").exists()
    # the interactive page: GlowScript replays the run, the video is linked from it
    assert page.count('href="run.mp4"') == 1 and "<video" not in page
    assert "glow.min.js" in page
    assert (tmp_path / "run-graph1.png").exists()          # the graphs beside it as figures


def test_page_that_grows_is_cut_with_a_note(tmp_path):
    prog = write(tmp_path, """
        from vpython import *
        scene.width, scene.height = 200, 100
        box()
        for i in range(3):
            rate(10)
            scene.append_to_caption("line\\n")
    """)
    frames = []
    r = run_program(prog, tmp_path / "g.mp4", RunOptions(page=False),
                    on_frame=lambda i, img: frames.append(img))
    assert len({f.shape for f in frames}) == 1
    assert any("the page grew" in n for n in r.notes)


def test_canvas_only_resized_mid_run_keeps_the_video_whole(tmp_path):
    """--canvas-only: the video keeps the first size (every frame written, a note)."""
    prog = write(tmp_path, """
        from vpython import *
        scene.width, scene.height = 200, 120
        box()
        for i in range(3):
            rate(10)
        scene.width, scene.height = 300, 200
        for i in range(3):
            rate(10)
    """)
    import imageio_ffmpeg

    r = run_program(prog, tmp_path / "r.mp4", RunOptions(page=False, canvas_only=True, fps=10))
    reader = imageio_ffmpeg.read_frames(str(tmp_path / "r.mp4"))
    assert next(reader)["size"] == (200, 120)
    assert sum(1 for _ in reader) == r.frames >= 6
    reader.close()
    assert any("resized" in n for n in r.notes)


def test_scene_capture_saves_the_canvas_alone_beside_the_output(tmp_path):
    """scene.capture("name") is the canvas at its own size (no page around it), as
    VPython's; capture("") gets a name instead of a hidden ".png"."""
    prog = write(tmp_path, """
        from vpython import *
        scene.width, scene.height = 200, 120
        scene.title = "not in the capture"
        box(color=color.red)
        scene.capture("snap")
        scene.capture("")
    """)
    out = tmp_path / "out"
    out.mkdir()
    r = run_program(prog, out / "run.png", RunOptions(page=False))
    snap = iio.imread(out / "snap.png")
    assert snap.shape[:2] == (120, 200)
    assert (out / "run-capture.png").exists()
    assert sorted(p.name for p in out.iterdir()) == ["run-capture.png", "run.png", "snap.png"]
    assert sorted(p.name for p in r.images) == ["run-capture.png", "snap.png"]
