"""springscene.view.imagediff: CIEDE2000 against Sharma, Wu & Dalal's published test data,
silhouettes from id pictures, IoU, and a scene compared with itself and with a change."""
import math

import numpy as np
import pytest
from skimage.color import lab2rgb, rgb2lab

from springscene.view import imagediff

# G. Sharma, W. Wu, E. N. Dalal, "The CIEDE2000 color-difference formula: implementation
# notes, supplementary test data, and mathematical observations", Color Res. Appl. 30
# (2005), table 1: (L*, a*, b*) pairs and their Delta E 2000.
SHARMA = [
    ((50.0, 2.6772, -79.7751), (50.0, 0.0, -82.7485), 2.0425),
    ((50.0, 0.0, 0.0), (50.0, -1.0, 2.0), 2.3669),
    ((50.0, -1.0, 2.0), (50.0, 0.0, 0.0), 2.3669),
    ((50.0, 2.49, -0.001), (50.0, -2.49, 0.0009), 7.1792),
    ((50.0, 2.49, -0.001), (50.0, -2.49, 0.0011), 7.2195),
    ((50.0, -0.001, 2.49), (50.0, 0.0009, -2.49), 4.8045),
    ((50.0, -0.001, 2.49), (50.0, 0.0011, -2.49), 4.7461),
    ((50.0, 2.5, 0.0), (50.0, 0.0, -2.5), 4.3065),
    ((50.0, 2.5, 0.0), (73.0, 25.0, -18.0), 27.1492),
    ((50.0, 2.5, 0.0), (61.0, -5.0, 29.0), 22.8977),
    ((50.0, 2.5, 0.0), (56.0, -27.0, -3.0), 31.9030),
    ((50.0, 2.5, 0.0), (58.0, 24.0, 15.0), 19.4535),
    ((50.0, 2.5, 0.0), (50.0, 3.1736, 0.5854), 1.0000),
    ((50.0, 2.5, 0.0), (50.0, 3.2972, 0.0), 1.0000),
    ((50.0, 2.5, 0.0), (50.0, 1.8634, 0.5757), 1.0000),
    ((50.0, 2.5, 0.0), (50.0, 3.2592, 0.3350), 1.0000),
    ((60.2574, -34.0099, 36.2677), (60.4626, -34.1751, 39.4387), 1.2644),
    ((63.0109, -31.0961, -5.8663), (62.8187, -29.7946, -4.0864), 1.2630),
    ((61.2901, 3.7196, -5.3901), (61.4292, 2.2480, -4.9620), 1.8731),
    ((35.0831, -44.1164, 3.7933), (35.0232, -40.0716, 1.5901), 1.8645),
    ((22.7233, 20.0904, -46.6940), (23.0331, 14.9730, -42.5619), 2.0373),
    ((36.4612, 47.8580, 18.3852), (36.2715, 50.5065, 21.2231), 1.4146),
    ((90.8027, -2.0831, 1.4410), (91.1528, -1.6435, 0.0447), 1.4441),
    ((90.9257, -0.5406, -0.9208), (88.6381, -0.8985, -0.7239), 1.5381),
    ((6.7747, -0.2908, -2.4247), (5.8714, -0.0985, -2.2286), 0.6377),
    ((2.0776, 0.0795, -1.1350), (0.9033, -0.0636, -0.5514), 0.9082),
]


def _in_gamut_rgb(lab):
    """The sRGB colour of a CIELAB one, or None when sRGB cannot show it exactly."""
    rgb = lab2rgb(np.array([[lab]], float))
    back = rgb2lab(rgb)[0, 0]
    return rgb if np.allclose(back, lab, atol=1e-4) else None


def test_ciede2000_matches_sharmas_published_pairs():
    checked = 0
    for lab1, lab2, want in SHARMA:
        a, b = _in_gamut_rgb(lab1), _in_gamut_rgb(lab2)
        if a is None or b is None:
            continue
        got = imagediff.ciede2000(a, b)
        assert got.shape == (1, 1)
        assert got[0, 0] == pytest.approx(want, abs=1e-4), (lab1, lab2)
        checked += 1
    assert checked >= 15          # most of the table lies inside sRGB


def test_ciede2000_of_uint8_pictures():
    a = np.zeros((2, 3, 3), np.uint8)
    b = a.copy()
    b[0, 0] = (255, 255, 255)                    # black against white: L* 0 against 100
    d = imagediff.ciede2000(a, b)
    assert d.shape == (2, 3)
    assert d[0, 0] == pytest.approx(100.0, abs=0.01)
    assert np.count_nonzero(d) == 1
    with pytest.raises(ValueError):
        imagediff.ciede2000(a, b[:1])


def test_iou():
    a = np.zeros((4, 4), bool)
    b = a.copy()
    a[:2, :2] = True                   # 4 pixels
    b[:2, :3] = True                   # 6 pixels, 4 shared
    assert imagediff.iou(a, b) == pytest.approx(4 / 6)
    assert imagediff.iou(a, a) == 1.0
    assert imagediff.iou(a, ~a) == 0.0
    assert math.isnan(imagediff.iou(np.zeros((2, 2), bool), np.zeros((2, 2), bool)))


def test_erode_takes_one_ring_of_border_pixels():
    m = np.zeros((7, 7), bool)
    m[1:6, 1:6] = True
    assert imagediff.erode(m).sum() == 9
    assert imagediff.erode(m, 2).sum() == 1
    assert imagediff.erode(np.ones((3, 3), bool)).sum() == 1     # the edge is outside


PALETTE = [(1.0, 0.0, 0.0), (0.0, 1.0, 0.0), (1.0, 0.5, 0.0)]


def test_id_masks_keep_darkened_colours_and_reject_mixes():
    img = np.zeros((1, 6, 3), np.uint8)
    img[0, 0] = (255, 0, 0)          # red
    img[0, 1] = (120, 0, 0)          # red darkened (GlowScript's emissive falloff, an edge)
    img[0, 2] = (40, 0, 0)           # too dark: an edge pixel barely covered
    img[0, 3] = (255, 128, 0)        # orange, not red
    img[0, 4] = (128, 128, 0)        # half red, half green: an edge between two objects
    img[0, 5] = (0, 250, 3)          # green
    m = imagediff.id_masks(img, PALETTE)
    assert m.shape == (3, 1, 6)
    assert m[0, 0].tolist() == [True, True, False, False, False, False]
    assert m[1, 0].tolist() == [False, False, False, False, False, True]
    assert m[2, 0].tolist() == [False, False, False, True, False, False]
    with pytest.raises(ValueError):
        imagediff.id_masks(img, [(0.5, 0.0, 0.0)])


def _scene(shift=0, tint=(200, 60, 60)):
    img = np.full((40, 60, 3), 255, np.uint8)
    ids = np.zeros_like(img)
    img[10:30, 10 + shift:30 + shift] = tint
    ids[10:30, 10 + shift:30 + shift] = (255, 0, 0)
    img[5:15, 40:55] = (40, 40, 200)
    ids[5:15, 40:55] = (0, 255, 0)
    return img, ids


def test_compare_scene_with_itself_passes():
    img, ids = _scene()
    c = imagediff.compare_scene(img, img, ids, ids, PALETTE, ["box", "ball"])
    assert [o.name for o in c.objects] == ["box", "ball"]
    assert all(o.iou == 1.0 and o.mean_de == 0.0 for o in c.objects)
    assert c.objects[0].pixels == (400, 400)
    assert c.mean_de == 0.0 and c.over_percent == 0.0
    assert c.passes()


def test_compare_scene_finds_a_moved_and_recoloured_object():
    img, ids = _scene()
    img2, ids2 = _scene(shift=2, tint=(200, 90, 60))
    c = imagediff.compare_scene(img, img2, ids, ids2, PALETTE, ["box", "ball"])
    box, ball = c.objects
    assert box.iou == pytest.approx(360 / 440)          # 20x18 shared of 20x22
    assert box.mean_de > 5 and box.over_percent == 100.0
    assert not box.passes()
    assert ball.iou == 1.0 and ball.mean_de == 0.0 and ball.passes()
    assert c.over_percent == pytest.approx(100 * 440 / 2400)   # 400 recoloured + 40 moved
    assert not c.passes()


def test_compare_scene_with_the_second_renderer_numbering_differently():
    img, ids = _scene()
    swapped = ids.copy()                     # the second renderer's box green, ball red
    swapped[np.all(ids == (255, 0, 0), axis=2)] = (0, 255, 0)
    swapped[np.all(ids == (0, 255, 0), axis=2)] = (255, 0, 0)
    same = imagediff.compare_scene(img, img, ids, swapped, PALETTE, ["box", "ball"],
                                   palette_b=[PALETTE[1], PALETTE[0]])
    assert [o.iou for o in same.objects] == [1.0, 1.0]
    wrong = imagediff.compare_scene(img, img, ids, swapped, PALETTE, ["box", "ball"])
    assert [o.iou for o in wrong.objects] == [0.0, 0.0]
    missing = imagediff.compare_scene(img, img, ids, ids, PALETTE, ["box", "ball"],
                                      palette_b=[PALETTE[0], None])
    assert missing.objects[1].iou == 0.0 and missing.objects[1].pixels == (150, 0)
    assert not missing.objects[1].passes()
