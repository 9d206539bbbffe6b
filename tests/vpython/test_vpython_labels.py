"""Labels placed and drawn as VPython 7.6.5 (GlowScript 3.2) draws them.

The rules are GlowScript's ``label.__update`` (lib/glow/primitives.js) and ``parse_html`` /
``display_2D`` (lib/glow/api_misc.js): line pitch 1.3 height, the first line's middle
0.4 height below the block's top, the box ``border`` px outside the text, the box beyond
the leader line's end; the pictures are real VPython's (tests/baselines/labels).
"""

from __future__ import annotations

import math
import textwrap
from pathlib import Path

import numpy as np
import pytest
from PIL import Image

import springscene.vpython.api
from springscene.view import camera
from springscene.vpython.draw import label_overlay
from springscene.vpython.text import fonts, label_layout
from springscene.vpython.draw.renderer import Renderer

BASELINES = Path(__file__).resolve().parents[1] / "baselines" / "labels"


def tens(text, family, size, bold=False, italic=False):
    """A stand-in measureText: every character 10 px at height 15 (scaled by size)."""
    return 10.0 * len(text) * size / 15


def place(text, align="center", pos=(300, 200), offset=(0, 0), height=15, border=5, **kw):
    return label_layout.place(text, "sans", height, align, pos, offset, border, tens, **kw)


# ---- layout: label.__update and parse_html ------------------------------------------------

@pytest.mark.parametrize("align, left", [("center", 300 - 50), ("left", 300), ("right", 200)])
def test_box_around_one_line_by_alignment(align, left):
    g = place("abcdefghij", align)                          # 100 px of text
    # box: border 5 outside the text; top 0.4 h + border above pos.y, height h + 2 border
    assert g.rect == pytest.approx((left - 5, 200 - 6 - 5, 110, 25))
    assert g.line is None
    (run,) = g.runs
    assert (run.x, run.y, run.size) == pytest.approx((left, 200, 15))   # middle of the text


def test_multiline_pitch_is_1_3_height_and_lines_align_by_their_own_width():
    g = place("abcd\nab<br>abcdef", "right")
    assert len(g.runs) == 3
    assert [r.y for r in g.runs] == pytest.approx([200, 219.5, 239])
    assert g.rect == pytest.approx((300 - 60 - 5, 189, 70, 15 + 2 * 19.5 + 10))
    assert [r.x + tens(r.text, "", 15) for r in g.runs] == pytest.approx([300] * 3)
    g = place("abcd\nab", "center")
    assert [r.x for r in g.runs] == pytest.approx([280, 290])


@pytest.mark.parametrize("offset, rect, line_end", [
    ((0, 40), (300 - 30, 200 - 40 - 25, 60, 25), (300, 160)),     # above: bottom centre
    ((0, -40), (300 - 30, 200 + 40, 60, 25), (300, 240)),         # below: top centre
    ((60, 10), (300 + 60, 200 - 10 - 12.5, 60, 25), (360, 190)),  # right: left middle
    ((-60, 10), (300 - 60 - 60, 200 - 10 - 12.5, 60, 25), (240, 190)),   # left: right middle
])
def test_offset_puts_the_box_beyond_the_leader_line(offset, rect, line_end):
    g = place("abcde", pos=(300, 200), offset=offset)         # 50 px of text, border 5
    assert g.rect == pytest.approx(rect)
    assert g.line == pytest.approx((300, 200, *line_end))


def test_space_starts_the_leader_line_away_from_pos():
    g = place("ab", offset=(30, -40), space=10)
    assert g.line == pytest.approx((306, 208, 330, 240))


def test_html_styles_sizes_and_shifts():
    lines, width, _ = label_layout.parse("x<sup>2</sup> <b>b</b><i>i</i>y<sub>k</sub>",
                                         "Arial", 15, tens)
    (_, parts), = lines
    got = [(p[2], p[3], p[1], p[4], p[5]) for p in parts]   # text, size, y, bold, italic
    assert got == [("x", 15, 0, False, False), ("2", 12, -4.5, False, False),
                   (" ", 15, 0, False, False), ("b", 15, 0, True, False),
                   ("i", 15, 0, False, True), ("y", 15, 0, False, False),
                   ("k", 12, 4.5, False, False)]
    assert width == pytest.approx(10 * 5 + 8 * 2)


def test_parse_keeps_glowscript_quirks():
    # unknown tags stay as text ('</u>' as '<u>'); '<' with no '>' after it is text
    (_, parts), = label_layout.parse("<u>a</u> 1<2", "Arial", 15, tens)[0]
    assert "".join(p[2] for p in parts) == "<u>a<u> 1<2"
    # text after the last tag is drawn plain even inside an open <b>
    (_, parts), = label_layout.parse("<b>a</b>c<b>d", "Arial", 15, tens)[0]
    assert [(p[2], p[4]) for p in parts] == [("a", True), ("c", False), ("d", False)]
    # Verdana is drawn at 13/15 of the height
    assert label_layout.parse("ab", "Verdana", 15, tens)[2] == pytest.approx(13)


# ---- fonts: what headless Chromium draws with -----------------------------------------------

def test_fonts_are_the_browsers_and_widths_are_its_measure_text():
    assert Path(fonts.font_file("Arial")).name == "LiberationSans-Regular.ttf"
    assert Path(fonts.font_file("Georgia", True, True)).name == \
        "LiberationSerif-BoldItalic.ttf"
    assert Path(fonts.font_file("monospace")).name == "DejaVuSansMono.ttf"
    # Liberation Sans advances (units of 2048 per em): C 1479, e 1139, n 1139, t 569, r 682,
    # space 569, b 1139, o 1139, x 1024, H 1479, g 1139
    units = 1479 + 1139 + 1139 + 569 + 1139 + 682 + 569 + 1139 + 1139 + 1024 + 569 + 1479 + 1139
    assert fonts.width("Center box Hg", "Arial", 15) == pytest.approx(units * 15 / 2048,
                                                                            abs=0.02)
    assert fonts.width("Mono font", "monospace", 15) == pytest.approx(9 * 1233 * 15 / 2048,
                                                                            abs=0.02)
    # textBaseline 'middle' of Liberation Sans: typo ascender 1491, descender -431
    assert fonts.middle(fonts.font_file("Arial")) == pytest.approx(
        (1491 - 431) / (2 * (1491 + 431)))


# ---- colours and placement of a label object ------------------------------------------------

@pytest.fixture
def vp():
    springscene.vpython.api.reset()
    return springscene.vpython.api


def test_default_colours_follow_glowscripts_rule(vp):
    lab = vp.label(text="a", pixel_pos=True, pos=vp.vec(100, 100, 0))
    s = label_overlay.spec(lab, None, 640, 400, (0.0, 0.0, 0.0))
    assert s.text_rgb == s.line_rgb == (255, 255, 255) and s.fill_rgba == (0, 0, 0, 0.66)
    s = label_overlay.spec(lab, None, 640, 400, (1.0, 1.0, 1.0))     # exactly white: black
    assert s.text_rgb == (0, 0, 0) and s.fill_rgba[:3] == (255, 255, 255)
    s = label_overlay.spec(lab, None, 640, 400, (0.5, 0.5, 0.5))
    assert s.text_rgb == (255, 255, 255) and s.fill_rgba[:3] == (127, 127, 127)
    lab.color, lab.background, lab.opacity = vp.color.red, vp.color.blue, 0.25
    s = label_overlay.spec(lab, None, 640, 400, (1.0, 1.0, 1.0))
    assert s.text_rgb == s.line_rgb == (255, 0, 0) and s.fill_rgba == (0, 0, 255, 0.25)
    lab.linecolor, lab.linewidth = vp.color.green, 3
    s = label_overlay.spec(lab, None, 640, 400, (1.0, 1.0, 1.0))
    assert s.line_rgb == (0, 255, 0) and s.linewidth == 3


def test_pixel_pos_counts_from_the_bottom_and_its_yoffset_points_down(vp):
    lab = vp.label(text="ab", pixel_pos=True, pos=vp.vec(100, 50, 0), yoffset=30)
    g = label_overlay.spec(lab, None, 640, 400, (0.0, 0.0, 0.0)).geometry
    assert g.line == pytest.approx((100, 350, 100, 380))        # GlowScript negates yoffset


def test_3d_pos_is_projected_and_rounded_and_hidden_behind_the_camera(vp):
    view = camera.view((0, 0, 0), (0, 0, -1), (0, 1, 0), math.pi / 3, 2.0, 640, 400)
    lab = vp.label(text="ab", pos=vp.vec(1, 0.5, 0))
    g = label_overlay.spec(lab, view, 640, 400, (0.0, 0.0, 0.0)).geometry
    assert g.runs[0].y == 150 and g.runs[0].x + fonts.width("ab", "Arial", 15) / 2 == \
        pytest.approx(420)                                       # 100 px per unit at range 2
    lab.pos = vp.vec(0, 0, 10)                                  # behind the camera
    assert label_overlay.spec(lab, view, 640, 400, (0.0, 0.0, 0.0)) is None


# ---- rasterising ----------------------------------------------------------------------------

def test_rectangles_have_exact_area_coverage():
    img = np.zeros((20, 20, 3), np.uint8)
    geo = label_layout.Geometry((2.25, 3.5, 10.5, 6.0), None, (), "Arial")
    out = label_overlay.composite(img, [label_overlay.Spec(geo, (0, 0, 0), (255, 255, 255),
                                                     (255, 255, 255, 1.0), 1.0, False)])
    assert out[..., 0].sum() / 255 == pytest.approx(10.5 * 6.0, abs=0.1)
    assert out[5, 2, 0] == 191 and out[5, 3, 0] == 255 and out[3, 5, 0] == 128
    r0, c0, ring = label_overlay._box_cover((20, 20, 3), 2.5, 2.5, 10, 6, 1.0)   # 1 px wide outline
    assert (r0, c0) == (2, 2) and ring.sum() == pytest.approx(11 * 7 - 9 * 5)
    assert ring[1:6, 0].tolist() == [1.0] * 5 and ring[2, 2] == 0.0


# ---- against real VPython's pictures ---------------------------------------------------------

ON_BLACK = """
    scene.width = 640
    scene.height = 400
    scene.range = 2
    label(pixel_pos=True, pos=vec(120, 360, 0), text='Center box Hg')
    label(pixel_pos=True, pos=vec(60, 300, 0), text='Left aligned', align='left')
    label(pixel_pos=True, pos=vec(600, 300, 0), text='Right aligned', align='right')
    label(pixel_pos=True, pos=vec(480, 360, 0), text='Line one\\nsecond line<br>3rd')
    label(pixel_pos=True, pos=vec(80, 40, 0), text='small ten', height=10)
    label(pixel_pos=True, pos=vec(460, 50, 0), text='Big 24 px', height=24)
    label(pos=vec(-1, 0, 0), text='up right', xoffset=60, yoffset=40)
    label(pos=vec(1.2, 0, 0), text='left', xoffset=-50, yoffset=10)
    label(pos=vec(0.5, -0.8, 0), text='down', xoffset=10, yoffset=-40, box=False)
"""
ON_WHITE = """
    scene.width = 640
    scene.height = 400
    scene.range = 2
    scene.background = color.white
    label(pixel_pos=True, pos=vec(120, 360, 0), text='Serif font', font='serif')
    label(pixel_pos=True, pos=vec(460, 360, 0), text='Mono font', font='monospace')
    label(pixel_pos=True, pos=vec(120, 290, 0), text='<b>Bold</b> and <i>italic</i>')
    label(pixel_pos=True, pos=vec(460, 290, 0), text='x<sup>2</sup> + y<sub>i</sub>')
    label(pixel_pos=True, pos=vec(120, 220, 0), text='red on blue', color=color.red,
          background=color.blue, opacity=0.5)
    label(pixel_pos=True, pos=vec(460, 220, 0), text='no box', box=False)
    label(pixel_pos=True, pos=vec(120, 150, 0), text='border 10', border=10,
          linecolor=color.green, linewidth=3)
    label(pixel_pos=True, pos=vec(460, 150, 0), text='opaque', background=color.yellow,
          opacity=1)
    label(pixel_pos=True, pos=vec(300, 60, 0), text='pix offset', xoffset=40, yoffset=30,
          linecolor=color.red)
    label(pixel_pos=True, pos=vec(560, 60, 0), text='hidden', visible=False)
"""
# Box outlines in real VPython's pictures (left, top, right, bottom: centres of the
# strokes, px), worked out from GlowScript's rules with Liberation/DejaVu widths; text
# boxes are where its glyphs are (first and last inked column and row).
BLACK_BOXES = {"Center box Hg": (66.64, 29, 173.36, 54), "Left aligned": (55, 89, 142.58, 114),
               "Right aligned": (507.4, 89, 605, 114), "3rd": (437.05, 29, 522.95, 93),
               "small ten": (55, 351, 105, 371), "Big 24 px": (405, 335.4, 515, 369.4),
               "up right": (279.6, 147.5, 340.0, 172.5), "left": (360, 177.5, 390.37, 202.5)}
WHITE_BOXES = {"Serif font": (86.46, 29, 153.54, 54), "Mono font": (414.36, 29, 505.64, 54),
               "Bold": (66.6, 99, 173.4, 124), "x2": (434.3, 99, 485.7, 124),
               "pix offset": (339.6, 357.5, 409.75, 382.5)}


def frame_of(vp, program):
    namespace = dict(vars(vp))
    exec(textwrap.dedent(program), namespace)       # noqa: S102 - the test's own program
    r = Renderer(vp.scene)
    try:
        return r.frame().astype(float)
    finally:
        r.close()


def stroke_centre(img, bg, box, side):
    """Centre of one side of a box outline: darkness-weighted, in a +-2 px window."""
    left, top, right, bottom = box
    d = np.abs(img - np.array(bg, float)).max(axis=2) / 255
    if side in ("left", "right"):
        c = int(left if side == "left" else right) - 2
        prof = d[int(top) + 4:int(bottom) - 3, c:c + 5].mean(axis=0)
    else:
        r = int(top if side == "top" else bottom) - 2
        prof = d[r:r + 5, int(left) + 4:int(right) - 3].mean(axis=1)
    return float((prof * (np.arange(5) + (c if side in ("left", "right") else r) + 0.5)).sum()
                 / prof.sum())


def _reference(name):
    return np.asarray(Image.open(BASELINES / name).convert("RGB"), dtype=float)


@pytest.mark.parametrize("program, picture, bg, boxes", [
    (ON_BLACK, "real_vpython_on_black.png", (0, 0, 0), BLACK_BOXES),
    (ON_WHITE, "real_vpython_on_white.png", (255, 255, 255), WHITE_BOXES)])
def test_labels_match_real_vpythons_picture(vp, program, picture, bg, boxes):
    ref = _reference(picture)
    ours = frame_of(vp, program)
    assert ours.shape == ref.shape
    for name, box in boxes.items():
        for k, side in enumerate(("left", "top", "right", "bottom")):
            want = stroke_centre(ref, bg, box, side)
            assert want == pytest.approx(box[k], abs=0.3), (name, side)      # the rule
            assert stroke_centre(ours, bg, box, side) == pytest.approx(want, abs=0.3), \
                (name, side)
    diff = np.abs(ours - ref).max(axis=2)
    assert diff.mean() < 0.8                     # before: 6.7 (on black) and 5.3 (on white)
    assert (diff > 64).sum() < 400               # before: 9135 and 7157 pixels


def test_text_lands_where_real_vpythons_does(vp):
    ref = _reference("real_vpython_on_black.png")
    ours = frame_of(vp, ON_BLACK)
    for left, top, right, bottom in BLACK_BOXES.values():
        win = (slice(int(top) + 2, int(bottom) - 1), slice(int(left) + 2, int(right) - 1))
        boxes = []
        for img in (ref, ours):
            rows, cols = np.nonzero(img[win].max(axis=2) > 90)
            boxes.append(np.array([cols.min(), rows.min(), cols.max(), rows.max()]))
        assert np.abs(boxes[0] - boxes[1]).max() <= 1
