"""The off-screen window on plain VTK (springscene.view.window): what pv.Plotter gave,
without pyvista.plotting or matplotlib (the meshes are pyvista's core), and the memory a
GIF of the wiki scene takes."""

from __future__ import annotations

import json
import subprocess
import sys
import textwrap

import numpy as np
import pytest
from pyvista.core import PolyData, Sphere
from vtkmodules.vtkCommonCore import vtkUnsignedCharArray

from conftest import ROOT, WIKI
from springscene.view import backend, window
from springscene.view.scene import LIGHTS, grab

# a 30 s GIF of the page's scene peaks at 287 MiB (pyvista's core, which makes the meshes,
# about 31 of them); a venv installed moments before (CI's) reads about 25 MiB more, its
# just-written libraries mapped from the page cache in larger pieces (the same run after
# `drop_caches`: 286 MiB). pyvista.plotting and matplotlib, which the window avoids, would
# add about 80 MiB.
GIF_PEAK_MIB = 330


@pytest.fixture(scope="module", autouse=True)
def chosen_backend():
    backend.select("auto")


def read_back(win: window.Window) -> np.ndarray:
    w, h = win.window_size
    return grab(win.ren_win, w, h, vtkUnsignedCharArray())


def look_down_z(win: window.Window, distance: float = 1.0) -> None:
    cam = win.renderer.GetActiveCamera()
    cam.SetPosition(0, 0, distance)
    cam.SetFocalPoint(0, 0, 0)
    cam.SetViewUp(0, 1, 0)
    cam.SetViewAngle(30)
    cam.SetClippingRange(0.01, 10)


def run_main(*args: str) -> dict:
    """The CLI's main in a fresh interpreter: its status, which of pyvista, pyvista.plotting
    and matplotlib it imported, and its peak RSS (MiB): the kernel's VmHWM of the new
    program, since ``getrusage``'s ``ru_maxrss`` of a child of this (large) pytest process
    starts at the parent's size, kept across the fork and exec."""
    code = textwrap.dedent(f"""
        import json, sys
        from springscene.app.cli import main

        def peak_mib():        # this program's own high-water mark
            for line in open("/proc/self/status"):
                if line.startswith("VmHWM:"):
                    return int(line.split()[1]) / 1024

        status = main({list(args)!r})
        print(json.dumps({{"status": status,
                          "modules": sorted(m for m in ("matplotlib", "pyvista", "pyvista.plotting")
                                            if m in sys.modules),
                          "peak_mib": peak_mib()}}))
    """)
    proc = subprocess.run([sys.executable, "-c", code], cwd=ROOT, capture_output=True,
                          text=True, timeout=600)
    assert proc.returncode == 0, proc.stderr
    report = json.loads(proc.stdout.strip().splitlines()[-1])
    assert report["status"] in (0, None)
    return report


def test_a_wiki_gif_loads_no_pyvista_plotting_nor_matplotlib_and_stays_in_its_memory(tmp_path):
    """A 3 s GIF of the page's scene imports pyvista's core (its meshes) but neither
    ``pyvista.plotting`` nor matplotlib, and peaks under :data:`GIF_PEAK_MIB` (the set-up and the first
    frames are the peak: a 30 s GIF peaks within a few MiB of it)."""
    out = tmp_path / "wiki.gif"
    report = run_main("render", str(WIKI), "--out", str(out), "--duration", "3")
    assert out.stat().st_size > 10_000
    assert report["modules"] == ["pyvista"]
    assert report["peak_mib"] < GIF_PEAK_MIB


def test_a_lattice_still_loads_no_pyvista_plotting(tmp_path):
    """The chain (no colour map: no matplotlib either) draws its pyvista meshes in the
    plain-VTK window too."""
    out = tmp_path / "chain.png"
    report = run_main("still", str(ROOT / "configs" / "chain.toml"), "--time", "2e-13",
                      "--out", str(out))
    assert out.stat().st_size > 1_000
    assert report["modules"] == ["pyvista"]


def test_size_and_background_read_back():
    win = window.Window((64, 48), (0.2, 0.4, 0.6), multisamples=0)
    try:
        img = read_back(win)
        assert img.shape == (48, 64, 3)
        assert win.window_size == (64, 48)
        assert (img == (51, 102, 153)).all()      # round(255 * c), as pyvista's Color
    finally:
        win.close()


def test_lights_are_directional_scene_lights_in_gray_rounded_to_1_255():
    win = window.Window((32, 32), (1, 1, 1), lights=LIGHTS)
    try:
        lights = win.renderer.GetLights()
        assert lights.GetNumberOfItems() == len(LIGHTS)
        lights.InitTraversal()
        for direction, intensity in LIGHTS:
            light = lights.GetNextItem()
            assert light.GetPosition() == pytest.approx(direction)
            assert light.GetFocalPoint() == (0.0, 0.0, 0.0)
            assert not light.GetPositional() and light.LightTypeIsSceneLight()
            assert light.GetDiffuseColor() == pytest.approx((round(255 * intensity) / 255,) * 3)
        assert not win.renderer.GetAutomaticLightCreation()
    finally:
        win.close()


@pytest.mark.parametrize("towards_camera", [True, False])
def test_a_light_lights_the_side_it_shines_on(towards_camera):
    """A smooth-shaded white sphere, no ambient: lit from the camera's side its centre is
    bright; lit from behind it is as dark as the (black) background."""
    win = window.Window((40, 40), (0, 0, 0), lights=[((0, 0, 1 if towards_camera else -1), 1.0)])
    try:
        ball = Sphere(radius=0.2, theta_resolution=30, phi_resolution=30)
        actor = win.add_actor(window.mesh_actor(ball, smooth_shading=True))
        prop = actor.GetProperty()
        prop.SetInterpolationToPhong()
        prop.SetAmbient(0.0)
        prop.SetSpecular(0.0)
        look_down_z(win)
        centre = read_back(win)[18:22, 18:22].astype(int)
        if towards_camera:
            assert (centre > 240).all()
        else:
            assert (centre < 5).all()
    finally:
        win.close()


def test_title_is_a_text_actor_along_the_top_edge():
    win = window.Window((300, 120), (1, 1, 1))
    try:
        blank = read_back(win)
        win.add_actor(window.title_actor("A ball on a spring", 12, (0, 0, 0)), name="title",
                      pickable=False)
        assert win.renderer.actors["title"].GetClassName() == "vtkCornerAnnotation"
        assert win.renderer.GetViewProps().GetNumberOfItems() == 1
        img = read_back(win)
        changed = np.nonzero((img != blank).any(axis=2))
        rows, cols = changed
        assert len(rows) > 50                              # some text is drawn
        assert rows.max() < 40                             # in the top third
        assert abs((cols.min() + cols.max()) / 2 - 150) < 8   # centred
        assert img[rows, cols].min() < 60                  # in black
        win.remove_actor("title")
        assert "title" not in win.renderer.actors
        assert (read_back(win) == blank).all()
    finally:
        win.close()


def test_smooth_shading_computes_normals_only_when_missing():
    """As ``add_mesh(smooth_shading=True)``: point normals computed into a mesh without
    them (pyvista's ``compute_normals``), a sphere's own normals kept."""
    pts = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0]], float)
    flat = PolyData(pts, faces=[4, 0, 1, 2, 3])
    window.mesh_actor(flat)
    assert flat.point_data.active_normals is None
    window.mesh_actor(flat, smooth_shading=True)
    assert flat.point_data.active_normals_name == "Normals"
    assert np.allclose(np.abs(flat.point_data["Normals"]), (0, 0, 1))
    ball = Sphere(radius=1.0, theta_resolution=12, phi_resolution=12)
    normals = np.array(ball.point_data["Normals"])
    window.mesh_actor(ball, smooth_shading=True)
    assert np.array_equal(ball.point_data["Normals"], normals)


def test_pyvista_color_rounds_to_1_255():
    assert window.pyvista_color((0.3, 0.8, 1.0)) == (76 / 255, 204 / 255, 1.0)
