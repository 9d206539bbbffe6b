"""Textured surfaces lit as GlowScript lights them: the picture is part of the surface's
colour, the highlight is not.

GlowScript (VPython 7.6.5, ``shaders/opaque_render_fragment.shader`` and the peel shaders
``peel_color_fragmentC1``-``C4``, ``lightAt``): ``diffuse_color = diffuse_color *
texture(texmap, mat_pos).xyz`` *before* the lights are summed, so the texel colours the
ambient term (``light_ambient * diffuse_color``) and the diffuse terms, while the
specular term ``specular_color * lcolor * pow(...)`` (``specular_color`` a fixed 0.8 grey)
is added untinted: a textured earth shows a white highlight.

VTK 9 multiplies the finished, lit colour by the texel (``fragOutput0 = fragOutput0 *
tcolor`` in ``vtkOpenGLPolyDataMapper``'s ``//VTK::TCoord::Impl``): the highlight comes
out tinted (blue over the ocean, brown on wood) and dimmed. :func:`shade_textured` moves
the texel into the ambient and diffuse colours and drops VTK's multiplication, as
replacements in VTK's fragment shader on top of :mod:`.materials`'s rules (the
same technique; a replacement whose text VTK no longer writes does nothing, and
tests/vpython/test_vpython_textures.py measures the highlight).
"""

from __future__ import annotations

from .materials import shade_as_glowscript

# VTK 9.5's fragment shader text (vtkOpenGLPolyDataMapper::ReplaceShaderColor / ...TCoord)
_DIFFUSE = "vec3 diffuseColor = diffuseIntensity * vertexColorVSOutput.rgb;"
# GlowScript's filter (WebGLRenderer.js handleLoadedTexture): TEXTURE_MIN_FILTER
# LINEAR_MIPMAP_NEAREST, bilinear in one mipmap level. VTK's vtkTexture offers only
# LINEAR_MIPMAP_LINEAR (with anisotropy), which blends two levels and blurs fine pictures
# (gravel, granite): the level is chosen here and read with textureLod. OpenGL ES 3.0
# (section 3.8.10.4) picks level ceil(lod + 1/2) - 1; real VPython's pictures (Chromium,
# SwiftShader) measured sharper than that: one level finer fits them best (VPython's
# Textures.py demo, boxes / spheres / cylinders: mean dE00 1.99 / 1.77 / 1.69 against
# 2.41 / 1.61 / 1.92 with the formula's level and 2.50 for boxes with VTK's filter).
_LOD = ("  vec2 glowSize = vec2(textureSize(actortexture, 0));\n"
        "  vec2 glowDx = dFdx(tcoordVCVSOutput) * glowSize;\n"
        "  vec2 glowDy = dFdy(tcoordVCVSOutput) * glowSize;\n"
        "  float glowLod = 0.5 * log2(max(dot(glowDx, glowDx), dot(glowDy, glowDy)));\n"
        "  float glowLevel = max(ceil(glowLod + 0.5) - 2.0, 0.0);\n")
_TEXEL_FIRST = (_DIFFUSE, _DIFFUSE + "\n" + _LOD +
                "  vec3 glowTexel = textureLod(actortexture, tcoordVCVSOutput, glowLevel).rgb;\n"
                "  ambientColor = ambientColor * glowTexel;\n"
                "  diffuseColor = diffuseColor * glowTexel;")
# VTK writes its texel multiplication after the replacements made after its own (checked):
# the tag it goes in is emptied before VTK's replacements instead
_NO_TEXEL_AFTER = "//VTK::TCoord::Impl"
TEXTURE_RULES = (_TEXEL_FIRST,)


# Bump maps (opaque_render_fragment.shader lightAt): ``Nb = 2.0*texture(bumpmap,
# mat_pos).xyz - 1.0; normal = normalize(Nb.x*bumpX + Nb.y*cross(normal, bumpX) +
# Nb.z*normal)``, after the texel and before the lights. ``bumpX`` is the mesh's
# ``bumpaxis`` (lib/glow/mesh.js makeCube, makeSphere, makeCylinder, makeCone): the way the
# mesh's own texture coordinate u grows, turned round where the mapping is mirrored (the
# far half of a cylinder's side, where v runs back). So bumpX = h * dp/du with h the sign
# of (normal x dp/du) . dp/dv. VTK has no such attribute: dp/du and dp/dv are taken from
# the screen derivatives of the position and the drawn texture coordinates, and the flips
# and turns (which move mat_pos, not bumpaxis) undone by ``frame`` (:func:`bump_frame`).
_BUMP = """//VTK::Normal::Impl
  vec3 glowDp1 = dFdx(vertexVC.xyz);
  vec3 glowDp2 = dFdy(vertexVC.xyz);
  vec2 glowDt1 = dFdx(tcoordVCVSOutput);
  vec2 glowDt2 = dFdy(tcoordVCVSOutput);
  float glowDet = glowDt1.x * glowDt2.y - glowDt1.y * glowDt2.x;
  vec3 glowDpDu = (glowDp1 * glowDt2.y - glowDp2 * glowDt1.y) * sign(glowDet);
  vec3 glowDpDv = (glowDp2 * glowDt1.x - glowDp1 * glowDt2.x) * sign(glowDet);
  vec3 glowU = UU * glowDpDu + UV * glowDpDv;
  vec3 glowV = VU * glowDpDu + VV * glowDpDv;
  float glowHand = dot(cross(normalVCVSOutput, glowU), glowV) < 0.0 ? -1.0 : 1.0;
  vec3 glowX = glowHand * (glowU - dot(glowU, normalVCVSOutput) * normalVCVSOutput);
  glowX = glowX / max(length(glowX), 1e-20);
  vec2 glowBumpSize = vec2(textureSize(bumpmap, 0));
  vec2 glowBx = dFdx(tcoordVCVSOutput) * glowBumpSize;
  vec2 glowBy = dFdy(tcoordVCVSOutput) * glowBumpSize;
  float glowBumpLod = 0.5 * log2(max(dot(glowBx, glowBx), dot(glowBy, glowBy)));
  vec3 glowNb = 2.0 * textureLod(bumpmap, tcoordVCVSOutput,
                                 max(ceil(glowBumpLod + 0.5) - 2.0, 0.0)).xyz - 1.0;
  normalVCVSOutput = normalize(glowNb.x * glowX
      + glowNb.y * cross(normalVCVSOutput, glowX) + glowNb.z * normalVCVSOutput);
"""
BUMP_SAMPLER = "bumpmap"        # the property texture's name, the shader's sampler


def bump_frame(flipx: bool, flipy: bool, turn: int) -> tuple[int, int, int, int]:
    """(du'/du, dv'/du, du'/dv, dv'/dv): how the drawn coordinates (u', v') follow the
    mesh's own (u, v), whose directions are then a*dp/du' + b*dp/dv'.

    (u', v') are (u, v) flipped, then turned (render_vertex.shader; turn 1: (v, 1 - u),
    2: (1 - u, 1 - v), 3: (1 - v, u)).
    """
    fx, fy = (-1 if flipx else 1), (-1 if flipy else 1)
    return {0: (fx, 0, 0, fy), 1: (0, -fx, fy, 0), 2: (-fx, 0, 0, -fy),
            3: (0, fx, -fy, 0)}[turn % 4]


def shade_textured(actor, transparent: bool, frame: tuple | None = None) -> None:
    """GlowScript's lighting rules (:func:`.materials.shade_as_glowscript`) for a textured,
    lit actor, with the texture in the surface colour and an untinted highlight; with
    ``frame`` (:func:`bump_frame`) the normals bent by the property's ``bumpmap`` texture."""
    shade_as_glowscript(actor, transparent)
    shader = actor.GetShaderProperty()
    shader.AddFragmentShaderReplacement(_NO_TEXEL_AFTER, True, "", False)
    for original, replacement in TEXTURE_RULES:
        shader.AddFragmentShaderReplacement(original, False, replacement, True)
    if frame is not None:
        bump = _BUMP
        for name, value in zip(("UU", "UV", "VU", "VV"), frame):
            bump = bump.replace(name + " *", f"{value:.1f} *")
        shader.AddFragmentShaderReplacement("//VTK::Normal::Impl", False, bump, False)


__all__ = ["shade_textured", "bump_frame", "TEXTURE_RULES", "BUMP_SAMPLER"]
