"""Surfaces shaded and blended as GlowScript (VPython 7's renderer) does it.

GlowScript's rules, read in VPython 7.6.5's GlowScript 3.2 (lib/glow/WebGLRenderer.js and
shaders/*.shader), and what VTK does unless told otherwise:

* **No face is culled and no normal is flipped** (WebGLRenderer.js, ``render``:
  ``gl.enable(gl.CULL_FACE)`` is commented out; ``opaque_render_fragment`` and
  ``peel_color_fragmentC1``-``C4`` light every fragment with its own normal,
  ``normal = normalize(es_normal)``). The far, inner side of a half-transparent sphere or
  box is lit with its outward normal, which faces away from the viewer: mostly ambient.
  VTK always turns a back face's normal toward the viewer (``if (gl_FrontFacing ==
  false) normalVCVSOutput = -normalVCVSOutput``), which lit those faces like front ones.
* **Specular for every light, whatever side the light is on** (``calc_color``:
  ``pow(max(dot(R, normalize(pos)), 0.0), 100.0*shininess)`` with no ``N·L > 0``
  test); VTK's ``sign(df)`` drops it where ``N·L <= 0``.
* **In transparent layers the specular colour is the first light's** (the peel shaders'
  ``calc_color`` multiplies by ``LC(0)``, the opaque one by ``lcolor``): the 0.3 grey
  light makes a 0.8 highlight on a transparent object, the "bright rim".
* **Each layer's colour is clamped to [0, 1]** before blending (the peels are RGBA8
  textures; ``output_color = vec4(color, vcolor.a)``); VTK's peels are float.
* **Depth peeling, four transparent layers, front to back over the opaque picture**
  (``render``: ``subrender`` PEEL_C0/D0 for the opaque colour and depth, C1-C4 for the
  transparent layers nearest first, then ``merge_fragment``:
  ``c1.rgb*c1.a + (1-c1.a)*(c2.rgb*c2.a + ... + (1-c4.a)*c0.rgb)``). VTK's depth
  peeling with four peels and an occlusion ratio of 0 is that blend where at most four
  transparent surfaces overlap. VTK peels dual (a front and a back layer a peel), so
  where more overlap it still blends the deeper ones that GlowScript drops: four
  half-transparent spheres in a row measured mean dE00 0.8-1.4 against real VPython.
* **No anti-aliasing once anything is transparent**: GlowScript then draws the whole
  scene, opaque objects too, into plain textures (``makeTexture``, ``ktexture = 1``,
  "This destroys antialiasing") and merges them onto the canvas.

* **Emissive surfaces glow, dimmed towards their outline** (``lightAt``, "From VPython
  materials.emissive", the same in the opaque and the transparent layers): no lights,
  ``color * min(1, 1.1*(1.5*N.V)^0.4)`` (:func:`shade_emissive`); VTK unlit draws
  ambient + diffuse, a flat 1.2x the colour.

The shading rules are applied as replacements in VTK's own fragment shader
(``vtkShaderProperty``), made after VTK has written it, so they are tied to the text
of VTK 9's ``vtkOpenGLPolyDataMapper`` (a replacement that no longer matches does
nothing; tests/vpython/test_vpython_opacity.py measures the pictures).
"""

from __future__ import annotations

import numpy as np

PEELS = 4                       # GlowScript's transparent layers: C1, C2, C3, C4
MAX_LIGHTS = 32                 # GlowScript's light_pos[32]

_UNFLIP = ("if (gl_FrontFacing == false) { normalVCVSOutput = -normalVCVSOutput; }", "")
_SPECULAR_ANY_SIDE = (("sf = sign(df)*pow(", "sf = pow("),                   # distant lights
                      ("sf = sign(df)*attenuation*pow(", "sf = attenuation*pow("))  # local
_CLAMPED = ("vec4(ambientColor + diffuse + specular, opacity)",
            "vec4(clamp(ambientColor + diffuse + specular, 0.0, 1.0), opacity)")
_FIRST_LIGHT_SPECULAR = tuple((f"specular += (sf * lightColor{i});",
                               "specular += (sf * lightColor0);") for i in range(1, MAX_LIGHTS))

OPAQUE_RULES = (_UNFLIP, *_SPECULAR_ANY_SIDE, _CLAMPED)
TRANSPARENT_RULES = OPAQUE_RULES + _FIRST_LIGHT_SPECULAR


def shade_as_glowscript(actor, transparent: bool) -> None:
    """Give a lit surface actor GlowScript's lighting rules (those of its transparent
    layers when ``transparent``)."""
    shader = actor.GetShaderProperty()
    shader.ClearAllFragmentShaderReplacements()
    for original, replacement in TRANSPARENT_RULES if transparent else OPAQUE_RULES:
        shader.AddFragmentShaderReplacement(original, False, replacement, True)


# GlowScript's emissive surface (opaque_render_fragment and peel_color_fragmentC1-C4,
# ``lightAt``, "From VPython materials.emissive"): no lights, the colour dimmed towards
# the outline, ``d = dot(normalize(-pos), normal)``, ``color = diffuse_color *
# min(1, 1.1*pow(1.5*d, 0.4))`` (``pos`` the eye-space point: the direction to the eye
# per fragment). Full colour where the surface is within about 58 degrees of facing the
# eye, black at the outline. A surface facing away (the far side of a transparent
# sphere) has d < 0, and GLSL leaves pow of a negative number undefined: real VPython
# (SwiftShader) draws it as bright as the near side, as if d were |d| (a 0.5-opaque
# emissive magenta sphere over black measured 192 = 0.75*255 at its centre, not 128:
# both layers full), which is what VTK's normal turned toward the eye gives. So the
# emissive rule keeps VTK's flip. In VTK 9's shader ``vertexVC`` is the eye-space point
# and ``diffuseColor`` the vertex colour.
GLOW = "min(1.0, 1.1 * pow(1.5 * max(dot(normalize(-vertexVC.xyz), normalVCVSOutput), 0.0), 0.4))"
_GLOWING = ("vec4(ambientColor + diffuse + specular, opacity)",
            f"vec4(diffuseColor * {GLOW}, opacity)")
EMISSIVE_RULES = (_GLOWING,)


def glow_factor(cos_to_eye):
    """GlowScript's emissive dimming for surfaces at ``cos_to_eye`` = N·V (numpy)."""
    return np.minimum(1.0, 1.1 * np.power(1.5 * np.maximum(cos_to_eye, 0.0), 0.4))


def shade_emissive(actor) -> None:
    """Give an emissive surface actor GlowScript's emissive rule (opaque and transparent
    layers alike). The actor must stay lit in VTK (``LightingOn``): VTK's unlit shader
    has no normals; the lights' sums are computed and then dropped."""
    shader = actor.GetShaderProperty()
    shader.ClearAllFragmentShaderReplacements()
    for original, replacement in EMISSIVE_RULES:
        shader.AddFragmentShaderReplacement(original, False, replacement, True)


class Transparency:
    """The renderer's way of drawing: GlowScript's depth peeling without anti-aliasing
    while any batch is transparent, the plain anti-aliased drawing otherwise."""

    def __init__(self, window, samples: int) -> None:
        self.renderer = window.renderer
        self.ren_win = window.ren_win
        self.samples = samples            # MSAA samples of a scene with nothing transparent
        self.ren_win.SetMultiSamples(samples)
        self.peeling = False
        self.renderer.SetMaximumNumberOfPeels(PEELS)
        self.renderer.SetOcclusionRatio(0.0)

    def sync(self, batches) -> None:
        """Peel (or stop peeling) as the batches shown now need."""
        peeling = any(_shows_translucent(p) for b in batches for p in (b, *b.parts))
        if peeling == self.peeling:
            return
        self.renderer.SetUseDepthPeeling(peeling)
        self.ren_win.SetMultiSamples(0 if peeling else self.samples)
        self.peeling = peeling


def _shows_translucent(batch) -> bool:
    """A batch (or a part of one) drawn now, and transparent."""
    return batch.translucent and not batch.empty and batch.actor is not None


__all__ = ["Transparency", "shade_as_glowscript", "shade_emissive", "glow_factor", "PEELS"]
