"""GlowScript's lighting rules are edits of VTK's own generated fragment shader
(:mod:`springscene.vpython.draw.materials`, :mod:`springscene.vpython.draw.texture_shading`). A
replacement whose original text is no longer in VTK's shader (another VTK release)
does nothing and says nothing; these tests read the shader VTK compiled and check that
every rule took: its original text gone, its replacement there."""

from __future__ import annotations

import numpy as np
import pytest

from springscene.view import backend
from springscene.vpython.draw import materials


def compiled_fragment_shader(setup, positional: bool = False) -> str:
    """The fragment shader source VTK compiles for a sphere actor set up by ``setup``, lit
    by two distant lights (and a local one when ``positional``: VTK's shader for local
    lights is another)."""
    backend.select("auto")
    import pyvista as pv
    from vtkmodules.util.misc import calldata_type
    from vtkmodules.vtkCommonCore import VTK_OBJECT, vtkCommand

    pl = pv.Plotter(off_screen=True, window_size=(64, 64), lighting="none")
    for i in range(2):
        pl.add_light(pv.Light(position=(i + 1, 1, 1), light_type="camera light"))
    if positional:
        local = pv.Light(position=(0, 2, 2), light_type="scene light")
        local.positional = True
        pl.add_light(local)
    mesh = pv.Sphere()
    mesh["tc"] = np.zeros((mesh.n_points, 2))
    mesh.active_texture_coordinates = mesh["tc"]
    actor = pl.add_mesh(mesh, color="red", smooth_shading=True)
    setup(actor)
    sources = []

    @calldata_type(VTK_OBJECT)
    def grab(caller, event, program):
        sources.append(program.GetFragmentShader().GetSource())

    pl.ren_win.Render()
    mapper = actor.GetMapper()
    inner = mapper.GetPolyDataMapper() if hasattr(mapper, "GetPolyDataMapper") else mapper
    inner.AddObserver(vtkCommand.UpdateShaderEvent, grab)
    actor.GetShaderProperty().Modified()         # compile again, with the observer on
    pl.ren_win.Render()
    pl.close()
    assert sources, "VTK compiled no shader"
    return sources[-1]


def assert_took(sources: list[str], rules) -> None:
    """No rule's original is left in any shader, and each rule's replacement is in one
    (a rule for local lights only appears in the shader for local lights)."""
    for original, replacement in rules:
        assert not any(original in s for s in sources), f"not replaced: {original!r}"
        if replacement:
            assert any(replacement in s for s in sources), f"missing: {replacement!r}"


@pytest.mark.parametrize("transparent", [False, True], ids=["opaque", "transparent"])
def test_glowscript_lighting_rules_take(transparent):
    sources = [compiled_fragment_shader(
        lambda a: materials.shade_as_glowscript(a, transparent), positional=p)
        for p in (False, True)]
    assert_took(sources, materials.TRANSPARENT_RULES if transparent
                else materials.OPAQUE_RULES)


def test_emissive_rule_takes():
    source = compiled_fragment_shader(materials.shade_emissive)
    assert_took([source], materials.EMISSIVE_RULES)
    assert materials.GLOW in source


def test_unshaded_actor_keeps_vtks_own_lighting():
    """The check can fail: without the rules VTK's originals are there."""
    sources = [compiled_fragment_shader(lambda a: None, positional=p) for p in (False, True)]
    lit = 2                                   # lightColor0, lightColor1: in every shader here
    for original, _ in materials.TRANSPARENT_RULES[:len(materials.OPAQUE_RULES) + lit]:
        assert any(original in s for s in sources), original
