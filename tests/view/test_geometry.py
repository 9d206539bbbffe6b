"""Mesh geometry: VPython's helix, its frame rule, and the spring spanning holder to ball."""

import numpy as np
import pytest

from springscene.view.geometry import CHORDS_PER_COIL, TUBE_SIDES, HelixFrame, HelixTube


def test_hanging_spring_frame_is_vpythons():
    frame = HelixFrame()                      # VPython's defaults: axis x, up y
    R = frame.set_axis((0, -0.18, 0))
    X, Y, Z = R.T
    assert np.allclose(X, (0, -1, 0))
    assert np.allclose(Y, (1, 0, 0))          # up rotated with the axis
    assert np.allclose(Z, (0, 0, 1))


def test_up_kept_when_axis_already_perpendicular():
    frame = HelixFrame(axis=(0, -1, 0), up=(1, 0, 0))
    R = frame.set_axis((0, 0, -2))            # perpendicular to up: up stays
    assert np.allclose(R[:, 1], (1, 0, 0))


@pytest.mark.parametrize("axis", [(0, -0.185, 0), (0, -0.06, 0), (0.05, -0.12, 0.03)],
                         ids=["stretched", "compressed", "tilted"])
def test_centerline_starts_at_pos_plus_radius_z_and_ends_at_ball(axis):
    pos = np.array([0.0, 0.0, 0.0])
    tube = HelixTube(radius=0.015, thickness=0.003, coils=15)
    frame = HelixFrame()
    R = frame.set_axis(axis)
    c = tube.centerline(np.linalg.norm(axis)) @ R.T + pos
    assert len(c) == 15 * CHORDS_PER_COIL + 1
    assert np.allclose(c[0], pos + 0.015 * R[:, 2])          # pos + radius * Z
    assert np.allclose(c[-1], pos + np.asarray(axis) + 0.015 * R[:, 2])  # whole turns: same phase
    # the axis line itself runs from the holder to the ball
    assert np.allclose(c.mean(axis=0), pos + np.asarray(axis) / 2, atol=0.015 / 15)


def test_tube_wire_has_the_thickness_as_diameter():
    tube = HelixTube(radius=0.015, thickness=0.003, coils=15)
    frame = HelixFrame()
    axis = np.array([0, -0.18, 0.0])
    pts, normals = tube.points((0, 0, 0), axis, frame.set_axis(axis))
    c = tube.centerline(0.18) @ frame.set_axis(axis).T
    rings = pts.reshape(-1, TUBE_SIDES, 3)
    dist = np.linalg.norm(rings - c[:, None, :], axis=2)
    assert np.allclose(dist, 0.0015)                          # wire radius = thickness / 2
    assert np.allclose(np.linalg.norm(normals, axis=1), 1)
    # the wire's cross-section is perpendicular to the centre line
    tangent = np.gradient(c, axis=0)
    tangent /= np.linalg.norm(tangent, axis=1)[:, None]
    n = normals.reshape(-1, TUBE_SIDES, 3)
    assert np.abs(np.einsum("ijk,ik->ij", n[1:-1], tangent[1:-1])).max() < 1e-3


def test_faces_index_every_point():
    tube = HelixTube(radius=0.015, thickness=0.003, coils=3)
    faces = tube.faces().reshape(-1, 5)
    assert (faces[:, 0] == 4).all()
    assert len(faces) == (tube.n_rings - 1) * TUBE_SIDES
    assert set(np.unique(faces[:, 1:])) == set(range(tube.n_rings * TUBE_SIDES))
