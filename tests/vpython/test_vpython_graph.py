"""springscene.vpython's graphs, widgets and page: VPython 7's behaviour, headless.

Graphs: every ``plot`` form records the same points, plot objects go to the current
graph (one is made if there is none), drawings show the series' colours and grow with
``upto``, PNGs and the video strip have the right sizes. Widgets: VPython's defaults,
the notes saying nobody used them. Page: the program's HTML as it is, the video,
disabled controls, graph images; written atomically.
"""

from __future__ import annotations

import math
import os
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pytest

from springscene.vpython.api import graphs as G
from springscene.vpython.page import graph_images as GI   # graphs as pictures
from springscene.vpython.core import widgets as W
from springscene.vpython.core.vectors import set_lenient
from springscene.vpython.page import html_page as P


class V:
    """Anything with .x .y .z, as VPython's vector."""

    def __init__(self, x: float, y: float, z: float) -> None:
        self.x, self.y, self.z = x, y, z


RED, GREEN, BLUE = V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)


@pytest.fixture(autouse=True)
def fresh():
    G.reset()
    W.reset()
    yield
    G.reset()
    W.reset()


def count_color(img: np.ndarray, rgb: tuple[int, int, int], tol: int = 40) -> int:
    """Pixels within ``tol`` of ``rgb`` in every channel."""
    return int((np.abs(img.astype(int) - rgb) <= tol).all(axis=-1).sum())


# --------------------------------------------------------------------------- graph: data

PTS = [[1.0, 2.0], [3.0, 4.0]]


def test_every_plot_form_records_the_same_points():
    forms = []
    c = G.gcurve(); c.plot(1, 2); c.plot(3, 4); forms.append(c)
    c = G.gcurve(); c.plot([1, 2]); c.plot((3, 4)); forms.append(c)
    c = G.gcurve(); c.plot([1, 2], [3, 4]); forms.append(c)
    c = G.gcurve(); c.plot([[1, 2], [3, 4]]); forms.append(c)
    c = G.gcurve(); c.plot(((1, 2), (3, 4))); forms.append(c)
    c = G.gcurve(); c.plot(pos=(1, 2)); c.plot(pos=[(3, 4)]); forms.append(c)
    c = G.gcurve(); c.plot(data=[[1, 2], [3, 4]]); forms.append(c)
    c = G.gcurve(); c.plot(np.array([[1, 2], [3, 4]])); forms.append(c)
    c = G.gdots(data=[[1, 2], [3, 4]]); forms.append(c)
    c = G.gvbars(pos=[(1, 2), (3, 4)]); forms.append(c)
    c = G.gcurve(); c.plot(np.float64(1), np.int64(2)); c.plot([3, 4]); forms.append(c)
    for c in forms:
        assert c.data == PTS


def test_bad_plots_fail_as_vpython_does():
    c = G.gcurve()
    with pytest.raises(AttributeError, match="Must be plot"):
        c.plot(5)
    with pytest.raises(AttributeError, match="Cannot currently change color"):
        c.plot(pos=(1, 2), color=RED)
    with pytest.raises(AttributeError, match="2-dimensional"):
        c.plot([1, 2, 3])
    with pytest.raises(TypeError, match="Cannot plot a vector"):
        c.plot(0, V(1, 2, 3))
    assert c.data == []


def test_data_replaces_and_delete_clears_what_is_shown():
    c = G.gcurve(data=PTS)
    c.data = [[5, 6]]
    assert c.data == [[5.0, 6.0]]
    c.delete()
    assert c.data == [[5.0, 6.0]] and c.shown_count() == 0     # VPython keeps its list
    c.plot(7, 8)
    assert c.shown().tolist() == [[7.0, 8.0]]


def test_interval_keeps_the_first_call_then_every_nth():
    c = G.gcurve(interval=3)
    for i in range(1, 11):
        c.plot(i, i)
    assert [p[0] for p in c.data] == [1, 4, 7, 10]
    none = G.gdots(interval=0)
    none.plot(1, 1)
    assert none.data == []


def test_default_graph_and_current_graph():
    assert G.graphs() == [] and G.graph.get_selected() is None
    c = G.gcurve()                       # no graph yet: one is made
    assert len(G.graphs()) == 1 and c.graph is G.graphs()[0]
    g1 = c.graph
    g2 = G.graph(title="second")
    assert G.gdots().graph is g2         # the most recent graph is current
    g1.select()
    assert G.gvbars().graph is g1
    assert G.ghbars(graph=g2).graph is g2
    assert [len(g.series) for g in G.graphs()] == [2, 2]
    with pytest.raises(AttributeError, match="cannot be modified"):
        c.graph = g2
    g2.delete()
    assert G.graphs() == [g1]


def test_graph_defaults_and_options():
    g = G.graph(foo=3)                   # VPython keeps unknown graph attributes
    assert (g.width, g.height, g.fast, g.scroll, g.align) == (640, 400, True, False, "none")
    assert g.xmin is None and g.title == "" and g.user_attributes == {"foo": 3}
    with pytest.raises(AttributeError, match="both xmin and xmax"):
        G.graph(scroll=True, xmin=0)
    with pytest.raises(AttributeError, match="greater than xmin"):
        G.graph(scroll=True, xmin=2, xmax=1)
    with pytest.raises(AttributeError, match="background must be a vector"):
        G.graph(background="white")


def test_series_options_match_glowscript():
    c = G.gcurve(color=RED, width=4, markers=True, dot=True, label="x")
    assert c.color is RED and c.marker_color is RED and c.dot_color is RED
    assert c.radius == 4 and c.dot_radius == 6 and c.legend is True
    d = G.gdots(size=10)
    assert d.radius == 5 and d.size == 10 and d.legend is False
    assert G.gdots().radius == 3 and G.gvbars().delta == 1 and G.ghbars().horizontal
    with pytest.raises(AttributeError, match="^colour is not an attribute of a series$"):
        G.gcurve(colour=RED)
    with pytest.raises(AttributeError, match="These are not attributes.*a, b"):
        G.gdots(a=1, b=2)
    with pytest.raises(AttributeError, match="markers only to graph curves"):
        G.gdots(markers=True)
    with pytest.raises(AttributeError, match="moving dot only"):
        G.gvbars(dot=True)
    with pytest.raises(AttributeError, match="color must be a vector"):
        G.gcurve(color="red")


def test_reset_forgets_graphs():
    G.gcurve().plot(1, 1)
    G.reset()
    assert G.graphs() == [] and G.graph.get_selected() is None
    assert G.gcurve().graph in G.graphs()


# --------------------------------------------------------------------------- graph: drawing

def sine_graph(label: str = "y", **limits):
    g = G.graph(title="<b>y</b> of t", xtitle="t", ytitle="y", **limits)
    c = G.gcurve(color=RED, label=label, width=3)
    for t in np.linspace(0, 6, 200):
        c.plot(t, np.sin(t))
    return g, c


def test_draw_shows_the_curve_in_its_colour_and_grows_with_upto():
    g, c = sine_graph(label="", xmin=0, xmax=6, ymin=-1, ymax=1)
    img = GI.draw(g, 500, 300)
    assert img.shape == (300, 500, 3) and img.dtype == np.uint8
    assert count_color(img, (255, 0, 0)) > 300
    assert count_color(img, (255, 255, 255)) > 0.5 * img.shape[0] * img.shape[1]
    few = GI.draw(g, 500, 300, upto=20)          # a tenth of the points, on the same axes
    assert 20 < count_color(few, (255, 0, 0)) < count_color(img, (255, 0, 0)) / 4
    none = GI.draw(g, 500, 300, upto=0)
    assert count_color(none, (255, 0, 0), tol=60) == 0
    assert GI.draw(g).shape == (400, 640, 3)           # the graph's own size


def test_autoscaled_axes_follow_the_points_so_far():
    g, c = sine_graph()
    GI.draw(g, 500, 300, upto=20)
    panel = GI._figures[(id(g), 500, 300)].panels[0]
    assert panel.ax.get_xlim() == pytest.approx((0.0, 0.6))       # to the next whole tick
    GI.draw(g, 500, 300)
    assert panel.ax.get_xlim() == pytest.approx((0.0, 6.0))
    lo, hi = panel.ax.get_ylim()
    assert lo < -1 and hi > 1 and hi - lo <= 3              # the data, a margin, whole ticks


def test_a_constant_that_wobbles_in_its_last_digits_is_drawn_as_a_constant():
    # 40.9576 give or take a few ulps: a span matplotlib would tick a quadrillion times
    G.reset()
    g = G.graph()
    c = G.gcurve(color=V(1, 0, 0))
    for i in range(20):
        c.plot(i, 40.9576 + (i % 3) * 7.1e-15)
    img = GI.draw(g, 500, 300)
    lo, hi = GI._figures[(id(g), 500, 300)].panels[0].ax.get_ylim()
    assert lo < 40.9576 < hi and 0.5 < hi - lo < 2          # widened by about 1 %, as Flot
    assert count_color(img, (255, 0, 0)) > 200


def test_a_graph_of_a_fractional_size_is_drawn_at_whole_pixels():
    # 0.45 * 562.5 px high (the corpus's hardSphereGasItv): 253 rows, not a broadcast error
    G.reset()
    g = G.graph(width=450, height=0.45 * 562.5)
    G.gcurve(color=V(1, 0, 0), data=[[0, 0], [1, 1]])
    assert GI.draw(g).shape == (253, 450, 3)


def test_draw_bars_dots_and_hidden_series():
    g = G.graph(xmin=0, xmax=10, ymin=0, ymax=10)
    bars = G.gvbars(color=V(0, 0.6, 0), delta=0.8, data=[[i, i] for i in range(1, 9)])
    dots = G.gdots(color=BLUE, data=[[i, 9 - i] for i in range(1, 9)])
    img = GI.draw(g, 400, 300)
    # bars are filled with their colour at half opacity, edged in it
    assert count_color(img, (127, 178, 127), tol=25) > 2000
    assert count_color(img, (0, 0, 255)) > 100
    dots.visible = False
    assert count_color(GI.draw(g, 400, 300), (0, 0, 255)) == 0
    bars.delete()
    assert count_color(GI.draw(g, 400, 300), (127, 178, 127), tol=25) == 0
    h = G.graph()
    G.ghbars(color=RED, data=[[3, 1], [5, 2]])
    assert count_color(GI.draw(h, 300, 200), (255, 127, 127), tol=25) > 500


def test_draw_backgrounds_and_log_axes():
    g = G.graph(background=V(0, 0, 0), logy=True)     # GlowScript lightens dark backgrounds
    c = G.gcurve(color=BLUE)
    for x in range(1, 50):
        c.plot(x, 10.0 ** (x / 10))
    c.plot(60, -1)                                    # not drawable on a log axis
    img = GI.draw(g, 400, 300)
    assert count_color(img, (127, 127, 127), tol=3) > 20000
    assert count_color(img, (0, 0, 255)) > 100


def test_write_images_at_each_graphs_size(tmp_path):
    g1, _ = sine_graph()
    G.graph(width=300, height=200)
    G.gdots(data=[[0, 0], [1, 1]])
    paths = GI.write_images(G.graphs(), tmp_path, "run")
    assert [p.name for p in paths] == ["run-graph1.png", "run-graph2.png"]
    from PIL import Image

    assert [Image.open(p).size for p in paths] == [(640, 400), (300, 200)]


def test_graph_strip_stacks_graphs():
    g1, c = sine_graph()
    G.graph(title="bars")
    bars = G.gvbars(color=GREEN)
    strip = GI.GraphStrip(G.graphs(), 640)
    assert strip.size == (640, 480)
    frames = []
    for i in range(120):
        c.plot(6 + i * 0.05, np.cos(i * 0.05))
        if i % 10 == 0:
            bars.plot(i / 10, i % 4)
        frames.append(strip.draw())
    assert frames[-1].shape == (480, 640, 3) and frames[-1].dtype == np.uint8
    assert count_color(frames[-1][:240], (255, 0, 0)) > 300          # top: the curve
    assert count_color(frames[-1][240:], (127, 255, 127), tol=25) > 300   # bottom: bars
    assert not np.array_equal(frames[5], frames[-1])
    assert GI.GraphStrip([], 640).size == (640, 0)


# --------------------------------------------------------------------------- widgets

def set_k(evt):
    pass


class Anchor:
    def __init__(self, where: str) -> None:
        self._anchor = where


def test_controls_need_bind_and_keep_vpython_defaults():
    with pytest.raises(AttributeError, match="bind missing"):
        W.slider()
    s = W.slider(bind=set_k)
    assert (s.min, s.max, s.value, s.length, s.width, s.vertical) == (0, 1, 0, 400, 10, False)
    assert s.step == pytest.approx(0.001)
    s2 = W.slider(bind=set_k, min=2, max=4, id="k")
    assert s2.value == 2 and s2.step == pytest.approx(0.002) and s2.id == "k"
    with pytest.raises(AttributeError, match="cannot be changed"):
        s2.max = 5
    b = W.button(bind=set_k, text="Run")
    assert b.text == "Run" and b.disabled is False
    cb = W.checkbox(bind=set_k, text="trail")
    assert cb.checked is False
    m = W.menu(bind=set_k, choices=["a", "b", "c"])
    assert m.selected is None and m.index is None
    m2 = W.menu(bind=set_k, choices=["a", "b", "c"], index=1)
    assert m2.selected == "b" and m2.index == 1
    wi = W.winput(bind=set_k, prompt="k:", text="3")
    assert wi.type == "numeric" and wi.number is None and wi.text == "3"
    with pytest.raises(AttributeError, match="number"):
        W.winput(bind=set_k, number=3)
    r1 = W.radio(bind=set_k, text="A", name="g", checked=True)
    r2 = W.radio(bind=set_k, text="B", name="g")
    r2.checked = True
    assert (r1.checked, r2.checked) == (False, True)


def test_notes_say_nobody_used_the_controls():
    W.slider(bind=set_k, value=0.5)
    W.button(bind=lambda e: None, text="Go")
    W.checkbox(bind=set_k, text="show", checked=True)
    W.menu(bind=set_k, choices=["x", "y"], selected="y")
    W.winput(bind=set_k)
    W.skipped("scene.pause(): returned at once")
    W.skipped("scene.pause(): returned at once")
    assert W.notes() == [
        "slider (bind=set_k): never moved; value stays 0.5",
        "button 'Go' (bind=<lambda>): never clicked",
        "checkbox 'show' (bind=set_k): never clicked; stays checked",
        "menu (bind=set_k): never changed; selected stays 'y'",
        "winput (bind=set_k): nothing typed; text stays ''",
        "scene.pause(): returned at once",
    ]


def test_widgets_in_order_anchors_and_reset():
    t = W.wtext(text="k = <b>1</b>")
    b = W.button(bind=set_k, text="top", pos=Anchor("title"))
    s = W.slider(bind=set_k, pos=Anchor("caption"))
    gone = W.checkbox(bind=set_k)
    gone.delete()
    assert W.widgets_in_order() == [t, b, s]
    assert [w.anchor for w in (t, b, s)] == ["caption", "title", "caption"]
    assert W.button(bind=set_k, pos=[0, 1]).anchor == "title"     # VPython's own form
    with pytest.raises(AttributeError, match="print_anchor"):
        W.wtext(text="x", pos=Anchor("print"))
    t.text = 2
    assert t.text == "2"
    W.reset()
    assert W.widgets_in_order() == [] and W.notes() == []


# --------------------------------------------------------------------------- page

class Collect(HTMLParser):
    def __init__(self) -> None:
        super().__init__()
        self.tags: list[tuple[str, dict]] = []
        self.title = ""
        self._in_title = False

    def handle_starttag(self, tag, attrs):
        self.tags.append((tag, dict(attrs)))
        self._in_title = tag == "title"

    def handle_endtag(self, tag):
        self._in_title = False

    def handle_data(self, data):
        if self._in_title:
            self.title += data


def make_page(tmp_path: Path, **over) -> tuple[str, Collect]:
    G.reset()
    g = G.graph(width=320, height=200)
    G.gcurve(data=PTS)
    GI.write_images([g], tmp_path, "run")
    W.wtext(text="<i>k</i> = 5", pos=Anchor("title"))
    W.button(bind=set_k, text="Pause")
    W.slider(bind=set_k, min=0, max=10, value=5)
    W.checkbox(bind=set_k, text="trail", checked=True)
    W.menu(bind=set_k, choices=["slow", "fast"], selected="fast")
    W.radio(bind=set_k, text="on", name="r")
    W.winput(bind=set_k, prompt="Mass:", text="2")
    args = dict(title_html="<b>Spring</b> demo &amp; more", caption_html="line 1\nline 2",
                media="run.mp4", media_kind="video", width=640, height=480,
                graph_images=["run-graph1.png"], widgets=W.widgets_in_order())
    args.update(over)
    out = P.write_page(tmp_path / "page.html", **args)
    text = out.read_text(encoding="utf-8")
    parser = Collect()
    parser.feed(text)
    parser.close()
    return text, parser


def test_page_shows_title_video_caption_controls_and_graphs(tmp_path):
    text, parser = make_page(tmp_path)
    assert text.startswith("<!DOCTYPE html>") and '<meta charset="utf-8">' in text
    assert parser.title == "Spring demo & more"
    assert "<b>Spring</b> demo &amp; more" in text            # the program's HTML, as is
    assert "line 1\nline 2" in text and "white-space: pre" in text
    tags = parser.tags
    video = [a for t, a in tags if t == "video"]
    assert len(video) == 1 and video[0]["src"] == "run.mp4"
    assert {"controls", "loop", "muted", "autoplay", "playsinline"} <= set(video[0])
    assert (video[0]["width"], video[0]["height"]) == ("640", "480")
    imgs = [a for t, a in tags if t == "img"]
    assert imgs == [{"class": "vp-graph", "src": "run-graph1.png", "width": "320",
                     "height": "200", "alt": "graph 1"}]
    controls = [(t, a) for t, a in tags if t in ("button", "input", "select")]
    assert [t for t, _ in controls] == ["button", "input", "input", "select", "input", "input"]
    assert all("disabled" in a for _, a in controls)
    rng = next(a for t, a in controls if a.get("type") == "range")
    assert (rng["min"], rng["max"], rng["value"]) == ("0", "10", "5")
    assert "checked" in next(a for t, a in controls if a.get("type") == "checkbox")
    assert "checked" not in next(a for t, a in controls if a.get("type") == "radio")
    assert next(a for t, a in controls if a.get("type") == "text")["value"] == "2"
    assert "<option selected>fast</option>" in text
    # the wtext went to the title area, the controls to the caption area
    title_end, caption_start = text.index('<div class="vp-canvas">'), text.index("line 1")
    assert text.index("<i>k</i> = 5") < title_end
    assert text.index("Pause") > caption_start and text.index("Mass:") > caption_start
    assert [p.name for p in tmp_path.iterdir() if p.name.endswith(".tmp")] == []


def test_page_for_an_image_and_placeholders(tmp_path):
    W.reset()
    b = W.button(bind=set_k, text="Go")
    caption = f"before {W.placeholder(b)} after"
    path = P.write_page(tmp_path / "sub" / "page.html", title_html="", caption_html=caption,
                        media=str(tmp_path / "sub" / "my run.gif"), media_kind="gif",
                        width=300, height=200, graph_images=[], widgets=[b])
    text = path.read_text(encoding="utf-8")
    assert '<img src="my%20run.gif" width="300" height="200"' in text
    assert "<title>my run.gif</title>" in text
    assert text.index("before") < text.index("Go") < text.index("after")
    with pytest.raises(ValueError):
        P.write_page(tmp_path / "x.html", title_html="", caption_html="", media="a.mp4",
                     media_kind="movie", width=1, height=1, graph_images=[], widgets=[])


def test_page_write_is_atomic(tmp_path, monkeypatch):
    make_page(tmp_path)
    before = (tmp_path / "page.html").read_text(encoding="utf-8")

    def broken(src, dst):
        raise OSError("disk full")

    monkeypatch.setattr(os, "replace", broken)
    with pytest.raises(OSError):
        make_page(tmp_path, caption_html="new caption")
    assert (tmp_path / "page.html").read_text(encoding="utf-8") == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["page.html", "run-graph1.png"]


def test_vpython6_dots_in_their_own_colours_are_hidden_and_cleared_with_their_series():
    G.reset()
    set_lenient(True)
    try:
        d = G.gdots(color=V(1, 0, 0))
        d.plot(pos=(0, 0))
        d.plot(pos=(1, 1), color=(0, 0, 1))
        blue = d._tints[(0.0, 0.0, 1.0)]
        d.visible = False
        assert not blue.visible
        d.delete()
        assert blue.shown_count() == 0 == d.shown_count()
    finally:
        set_lenient(False)


def test_vpython6_square_dots_are_drawn_square():
    """gdots(shape="square") (VPython 6 only): a square of side 2 radius fills 4/pi of the
    round dot's pixels, each dot alone on the axes."""
    def blue(shape: str) -> int:
        G.reset()
        g = G.graph(xmin=0, xmax=10, ymin=0, ymax=10)
        set_lenient(True)
        try:
            G.gdots(color=BLUE, radius=10, shape=shape, data=[[2, 2], [5, 5], [8, 8]])
        finally:
            set_lenient(False)
        return count_color(GI.draw(g, 400, 300), (0, 0, 255))

    round_, square = blue("round"), blue("square")
    assert round_ > 3 * 250                        # three dots 20 px across
    assert square / round_ == pytest.approx(4 / math.pi, rel=0.08)
