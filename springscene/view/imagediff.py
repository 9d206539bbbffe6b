"""How far one picture of a scene is from another: per-object silhouettes and colours.

Made to measure springscene's pictures against real VPython's (``make fidelity``,
tests/vpython/test_fidelity.py) and general enough for any two renderings of one scene:

* :func:`ciede2000` -- the CIEDE2000 colour difference of two sRGB pictures, per pixel
  (scikit-image's ``rgb2lab`` and ``deltaE_ciede2000``; D65, 2 degree observer),
* :func:`id_masks` -- one silhouette per object from an "ids" picture, where each object
  is drawn in one colour of a palette,
* :func:`iou` -- intersection over union of two silhouettes,
* :func:`erode` -- a silhouette less its border pixels,
* :func:`compare_scene` -- all of these for a scene drawn twice (normal and ids pictures
  from each renderer): a :class:`SceneComparison` with one :class:`ObjectComparison` per
  object and the whole picture's numbers.

Pictures are ``(H, W, 3)`` uint8 sRGB arrays (an alpha channel is ignored).
"""
from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

#: the issue's targets for a picture against real VPython
TARGET_IOU = 0.98            # each object's silhouette, intersection over union
TARGET_MEAN_DE = 2.0         # mean CIEDE2000 inside each object
TARGET_OVER_DE = 5.0         # a pixel "differs visibly" above this CIEDE2000 ...
TARGET_OVER_PERCENT = 1.0    # ... and at most this % of a picture's pixels may


def _rgb(image) -> np.ndarray:
    a = np.asarray(image)
    if a.ndim != 3 or a.shape[2] not in (3, 4):
        raise ValueError(f"a picture is (H, W, 3) or (H, W, 4), not {a.shape}")
    return a[..., :3]


def ciede2000(a, b) -> np.ndarray:
    """CIEDE2000 colour difference of two sRGB pictures, pixel by pixel.

    Parameters
    ----------
    a, b : array_like, (H, W, 3) or (H, W, 4)
        Pictures of the same size: uint8 (0-255) or floats in [0, 1].

    Returns
    -------
    numpy.ndarray
        (H, W) float array of Delta E 2000 (kL = kC = kH = 1). 1 is about the smallest
        difference a person sees side by side; 2 is small; above 5 is plainly different.
    """
    from skimage.color import deltaE_ciede2000, rgb2lab  # noqa: PLC0415  heavy: scikit-image

    ra, rb = _rgb(a), _rgb(b)
    if ra.shape != rb.shape:
        raise ValueError(f"pictures differ in size: {ra.shape} and {rb.shape}")
    return deltaE_ciede2000(rgb2lab(_unit(ra)), rgb2lab(_unit(rb)))


def _unit(rgb: np.ndarray) -> np.ndarray:
    if rgb.dtype == np.uint8:
        return rgb.astype(np.float64) / 255.0
    return np.clip(rgb.astype(np.float64), 0.0, 1.0)


def id_masks(image, palette, *, min_level: float = 0.3,
             tolerance: float = 0.2) -> np.ndarray:
    """Split an "ids" picture into one silhouette per palette colour.

    Every object is drawn in its own palette colour, each with its largest component 1,
    over a black background. A pixel belongs to colour ``k`` when it is bright enough
    (its largest component at least ``min_level``) and its chromaticity -- the pixel
    divided by its largest component -- is within ``tolerance`` (each component) of
    colour ``k``. Dividing by the largest component keeps a colour that a renderer
    darkened (GlowScript's emissive shading falls off where a surface turns away from the
    viewer; an anti-aliased edge is the colour times its coverage) with its object, and
    rejects edge pixels that mix two objects' colours.

    Parameters
    ----------
    image : array_like, (H, W, 3) uint8
    palette : sequence of (r, g, b)
        Colours in [0, 1], each with its largest component 1.
    min_level : float
        Darkest accepted largest component, in [0, 1]: 0.3 counts an edge pixel covered
        by more than about a third.
    tolerance : float
        Largest accepted difference of chromaticity per component.

    Returns
    -------
    numpy.ndarray
        (len(palette), H, W) boolean silhouettes.
    """
    rgb = _unit(_rgb(image))
    pal = np.asarray(palette, dtype=np.float64).reshape(-1, 3)
    if not np.allclose(pal.max(axis=1), 1.0):
        raise ValueError("each palette colour needs its largest component 1")
    level = rgb.max(axis=2)
    chroma = rgb / np.maximum(level, 1e-6)[..., None]
    near = np.abs(chroma[None] - pal[:, None, None, :]).max(axis=3) <= tolerance
    return near & (level >= min_level)[None]


def iou(a, b) -> float:
    """Intersection over union of two boolean silhouettes (NaN when both are empty)."""
    a, b = np.asarray(a, bool), np.asarray(b, bool)
    union = np.count_nonzero(a | b)
    return float(np.count_nonzero(a & b) / union) if union else float("nan")


def erode(mask, pixels: int = 1) -> np.ndarray:
    """The silhouette ``mask`` less ``pixels`` rings of border pixels (4-neighbours; the
    picture's edge counts as outside)."""
    m = np.asarray(mask, bool)
    for _ in range(pixels):
        p = np.pad(m, 1, constant_values=False)
        m = m & p[:-2, 1:-1] & p[2:, 1:-1] & p[1:-1, :-2] & p[1:-1, 2:]
    return m


@dataclass
class ObjectComparison:
    """One object of a scene in two pictures.

    Attributes
    ----------
    name : str
    iou : float
        Its silhouettes' intersection over union (NaN if in neither picture).
    mean_de : float
        Mean CIEDE2000 inside both silhouettes, eroded by a pixel (NaN if none).
    over_percent : float
        % of those pixels with CIEDE2000 above :data:`TARGET_OVER_DE`.
    pixels : tuple of int
        Its silhouette's pixels in the first and in the second picture.
    """

    name: str
    iou: float
    mean_de: float
    over_percent: float
    pixels: tuple[int, int]

    def passes(self, min_iou: float = TARGET_IOU, max_de: float = TARGET_MEAN_DE) -> bool:
        """Whether it meets the targets (an object in neither picture passes)."""
        if self.pixels == (0, 0):
            return True
        return self.iou >= min_iou and not self.mean_de > max_de


@dataclass
class SceneComparison:
    """A scene in two pictures: each object, and the whole picture.

    Attributes
    ----------
    objects : list of ObjectComparison
    mean_de : float
        Mean CIEDE2000 over the whole picture.
    over_percent : float
        % of the picture's pixels with CIEDE2000 above :data:`TARGET_OVER_DE`.
    """

    objects: list[ObjectComparison] = field(default_factory=list)
    mean_de: float = float("nan")
    over_percent: float = float("nan")

    def passes(self) -> bool:
        """Whether every object and the whole picture meet the targets."""
        return (all(o.passes() for o in self.objects)
                and self.over_percent <= TARGET_OVER_PERCENT)


def compare_scene(a, b, ids_a, ids_b, palette, names=None,
                  palette_b=None) -> SceneComparison:
    """Compare two pictures of one scene, object by object.

    Parameters
    ----------
    a, b : array_like, (H, W, 3)
        The scene as two renderers draw it.
    ids_a, ids_b : array_like, (H, W, 3)
        The same scene with each object drawn flat in its palette colour (on black),
        by the same two renderers.
    palette : sequence of (r, g, b)
        The id colours; object ``k`` is ``palette[k]``.
    names : sequence of str, optional
        The objects' names (default ``object k``); its length is the number of objects.
    palette_b : sequence of (r, g, b), optional
        The objects' id colours in ``ids_b`` when the second renderer numbered them
        differently (default ``palette``); object ``k`` is ``palette_b[k]`` there, and
        ``None`` for an object it did not draw.

    Returns
    -------
    SceneComparison
    """
    de = ciede2000(a, b)
    names = list(names) if names is not None else [f"object {k}" for k in range(len(palette))]
    masks_a = id_masks(ids_a, palette[:len(names)])
    colours_b = list(palette_b if palette_b is not None else palette)[:len(names)]
    empty = np.zeros(masks_a.shape[1:], bool)
    masks_b = [empty if c is None else id_masks(ids_b, [c])[0] for c in colours_b]
    out = SceneComparison(mean_de=float(de.mean()),
                          over_percent=float(100.0 * np.mean(de > TARGET_OVER_DE)))
    for name, ma, mb in zip(names, masks_a, masks_b):
        inside = erode(ma & mb)
        d = de[inside]
        out.objects.append(ObjectComparison(
            name, iou(ma, mb),
            float(d.mean()) if d.size else float("nan"),
            float(100.0 * np.mean(d > TARGET_OVER_DE)) if d.size else float("nan"),
            (int(ma.sum()), int(mb.sum()))))
    return out
