"""VPython's object geometry: templates, frames, sizes and batched placement."""

import numpy as np
import pytest

from springscene.view.geometry import HelixFrame
from springscene.vpython.geometry import placement
import springscene.vpython.api as vp
from springscene.vpython.geometry import meshes

UNIT_KINDS = {            # kind: (template, points, triangles, centred)
    "sphere": (meshes.sphere, 842, 1680, True),
    "box": (meshes.box, 24, 12, True),
    "cylinder": (meshes.cylinder, 4 * 50 + 2, 4 * 50, False),
    "cone": (meshes.cone, 3 * 200 + 1, 2 * 200, False),
    "pyramid": (meshes.pyramid, 16, 6, False),
}


def face_normals(mesh):
    p, t = mesh.points, mesh.triangles
    return np.cross(p[t[:, 1]] - p[t[:, 0]], p[t[:, 2]] - p[t[:, 0]])


def assert_winding_outward(mesh):
    """Each triangle's cross-product normal agrees with its vertices' normals."""
    fn = face_normals(mesh)
    area = np.linalg.norm(fn, axis=1)
    keep = area > 1e-14 * max(area.max(), 1e-300)          # skip degenerate slivers at poles
    vn = mesh.normals[mesh.triangles].sum(axis=1)
    assert np.all(np.einsum("ij,ij->i", fn[keep], vn[keep]) > 0)


def assert_mesh_arrays(mesh):
    assert mesh.points.dtype == np.float64 and mesh.points.shape[1] == 3
    assert mesh.normals.shape == mesh.points.shape
    assert mesh.triangles.dtype == np.int64 and mesh.triangles.shape[1] == 3
    assert mesh.triangles.min() >= 0 and mesh.triangles.max() < len(mesh.points)
    assert np.allclose(np.linalg.norm(mesh.normals, axis=1), 1)


# -- templates ----------------------------------------------------------------------------

@pytest.mark.parametrize("kind", list(UNIT_KINDS))
def test_template_counts_and_bounds(kind):
    make, n_points, n_triangles, centred = UNIT_KINDS[kind]
    mesh = make()
    assert_mesh_arrays(mesh)
    assert len(mesh.points) == n_points and len(mesh.triangles) == n_triangles
    lo, hi = mesh.points.min(axis=0), mesh.points.max(axis=0)
    assert np.all(hi[1:] <= 0.5 + 1e-12) and np.all(lo[1:] >= -0.5 - 1e-12)
    if centred:
        assert -0.5 - 1e-12 <= lo[0] and hi[0] <= 0.5 + 1e-12
        assert np.allclose(mesh.points.mean(axis=0), 0, atol=1e-9)
    else:
        assert lo[0] == 0 and hi[0] == 1                      # end-anchored: x from 0 to 1


@pytest.mark.parametrize("kind", list(UNIT_KINDS))
def test_template_normals_outward_and_winding(kind):
    mesh = UNIT_KINDS[kind][0]()
    centre = (mesh.points.min(axis=0) + mesh.points.max(axis=0)) / 2
    assert np.all(np.einsum("ij,ij->i", mesh.normals, mesh.points - centre) >= 0)
    assert_winding_outward(mesh)


def test_round_kinds_are_exact_circles():
    cyl, cone = meshes.cylinder(), meshes.cone()
    assert np.allclose(np.hypot(cyl.points[2:, 1], cyl.points[2:, 2]), 0.5)
    rim = cone.points[1:401]                                  # base rim and side ring
    assert np.allclose(np.hypot(rim[:, 1], rim[:, 2]), 0.5)
    assert np.all(cone.points[401:] == [1, 0, 0])             # one apex vertex per side
    # the side normals of a cone of radius 1/2 and height 1: (1, 2 r_hat) / sqrt(5)
    assert np.allclose(cone.normals[201:401, 0], 1 / np.sqrt(5))
    r_hat = cone.points[201:401, 1:] / 0.5
    assert np.allclose(cone.normals[201:401, 1:], 2 * r_hat / np.sqrt(5))
    sphere = meshes.sphere()
    assert np.allclose(np.linalg.norm(sphere.points, axis=1), 0.5, atol=1e-7)


def test_box_faces_are_flat():
    box = meshes.box()
    for face in range(6):
        n = box.normals[4 * face:4 * face + 4]
        assert np.all(n == n[0])
        assert np.allclose(box.points[4 * face:4 * face + 4] @ n[0], 0.5)


def test_sphere_template_is_pyvistas_sphere():
    import pyvista as pv

    ref = pv.Sphere(radius=0.5, theta_resolution=30, phi_resolution=30)
    mesh = meshes.sphere()
    assert np.array_equal(mesh.points, np.asarray(ref.points, dtype=float))
    assert np.array_equal(mesh.triangles, np.asarray(ref.faces).reshape(-1, 4)[:, 1:])
    assert np.allclose(mesh.normals, mesh.points / np.linalg.norm(mesh.points, axis=1)[:, None])
    # placed with size 2r and the default frame it is the scene's ball of radius r
    r, c = 0.025, np.array([0.1, -0.2, 0.3])
    pts, _ = placement.place(mesh, c, placement.frames([1, 0, 0], [0, 1, 0]), np.full(3, 2 * r))
    ball = pv.Sphere(radius=r, center=c, theta_resolution=30, phi_resolution=30)
    assert np.allclose(pts, ball.points, rtol=0, atol=1e-7)


def test_templates_are_cached_and_read_only():
    assert meshes.cylinder() is meshes.cylinder()
    with pytest.raises(ValueError):
        meshes.box().points[0, 0] = 1.0


# -- frames -------------------------------------------------------------------------------

@pytest.mark.parametrize("axis", [(0, -0.18, 0), (0.05, -0.12, 0.03), (0, 0, 2), (-1, 0, 0),
                                  (-3, 0.1, 0)], ids=["hanging", "tilted", "z", "reversed", "nearly-reversed"])
def test_frames_match_helix_frame_for_first_axis_change(axis):
    hf = HelixFrame()
    R = hf.set_axis(axis)
    assert np.allclose(placement.frames(axis, hf.up)[0], R)
    up = placement.adjust_up([1, 0, 0], axis, [0, 1, 0])
    assert np.allclose(placement.frames(axis, up)[0], R)


def test_frames_vectorised_and_orthonormal():
    rng = np.random.default_rng(1)
    axis, up = rng.normal(size=(50, 3)), rng.normal(size=(50, 3))
    F = placement.frames(axis, up)
    assert F.shape == (50, 3, 3)
    assert np.allclose(np.einsum("mji,mjk->mik", F, F), np.eye(3))
    assert np.allclose(np.linalg.det(F), 1)
    assert np.allclose(F[:, :, 0], axis / np.linalg.norm(axis, axis=1)[:, None])
    Y = up - np.einsum("ij,ij->i", up, F[:, :, 0])[:, None] * F[:, :, 0]
    assert np.allclose(F[:, :, 1], Y / np.linalg.norm(Y, axis=1)[:, None])


def test_frames_up_parallel_to_axis_uses_vpythons_fallback():
    axis = [[0, 1, 0], [0, -3, 0], [2, 0, 0], [1e-300, 0, 0], [0, 0, 0], [0, 5, 0]]
    up = [[0, 1, 0], [0, 1, 0], [1, 0, 0], [0, 1, 0], [0, 1, 0], [0, 0, 0]]
    F = placement.frames(axis, up)
    assert np.all(np.isfinite(F))
    assert np.allclose(np.linalg.det(F), 1)
    # up parallel: VPython takes up = (1, 0, 0) instead ...
    assert np.allclose(F[0], np.column_stack([(0, 1, 0), (1, 0, 0), (0, 0, -1)]))
    # ... and (0, 1, 0) when the axis is along x too
    assert np.allclose(F[2], np.eye(3))
    assert np.allclose(F[3], np.eye(3))                       # tiny axis still has a direction
    assert np.allclose(F[4], np.eye(3))                       # zero axis: taken as x


def test_adjust_up_follows_vpython():
    # perpendicular already: unchanged; half turn: negated; zero axis: unchanged
    up = placement.adjust_up([[1, 0, 0]] * 3, [[0, 0, 1], [-1, 0.5, 0], [0, 0, 0]], [0, 1, 0])
    assert np.allclose(up[0], (0, 1, 0))
    assert np.allclose(up[2], (0, 1, 0))
    assert np.isclose(np.dot(up[1], (-1, 0.5, 0)), np.dot((0, 1, 0), (1, 0, 0)) * np.sqrt(1.25))
    flipped = placement.adjust_up([0, 1, 0], [0, -1, 0], [0.6, 0.8, 0])
    assert np.allclose(flipped, (-0.6, -0.8, 0))


# -- placement ----------------------------------------------------------------------------

@pytest.mark.parametrize("axis", [(1, 0, 0), (0, -2, 0), (0.3, 0.4, -1.2), (0, 1, 0)])
def test_placed_cylinder_spans_pos_to_pos_plus_axis(axis):
    p, a, r = np.array([0.5, -1.0, 2.0]), np.asarray(axis, dtype=float), 0.2
    L = np.linalg.norm(a)
    R = placement.frames(a, placement.adjust_up([1, 0, 0], a, [0, 1, 0]))
    mesh = meshes.cylinder()
    pts, normals = placement.place(mesh, p, R, [L, 2 * r, 2 * r])
    rel = pts - p
    along = rel @ (a / L)
    assert along.min() >= -1e-12 and along.max() <= L * (1 + 1e-12)
    radial = np.linalg.norm(rel - along[:, None] * a / L, axis=1)
    assert radial.max() <= r * (1 + 1e-12)
    assert np.allclose(pts[1], p + a, rtol=0, atol=1e-14)     # the far cap's centre
    far = mesh.points[:, 0] == 1
    assert np.allclose(along[far], L)
    assert np.allclose(normals[1], a / L)


def test_box_along_y_has_the_expected_bounds():
    # box(axis=vector(0,2,0), height=0.5, width=0.3): VPython turns up to (-1, 0, 0)
    axis = np.array([0.0, 2.0, 0.0])
    up = placement.adjust_up([1, 0, 0], axis, [0, 1, 0])
    assert np.allclose(up, (-1, 0, 0))
    for u in (up, [0, 1, 0]):                                # and the parallel-up fallback
        pts, _ = placement.place(meshes.box(), [1, 1, 1], placement.frames(axis, u), [2, 0.5, 0.3])
        assert np.allclose(pts.min(axis=0), (0.75, 0, 0.85))
        assert np.allclose(pts.max(axis=0), (1.25, 2, 1.15))


def test_nonuniform_scale_normals_are_the_ellipsoids_gradient():
    rng = np.random.default_rng(3)
    M = 4
    pos, size = rng.normal(size=(M, 3)), rng.uniform(0.2, 3, size=(M, 3))
    R = placement.frames(rng.normal(size=(M, 3)), rng.normal(size=(M, 3)))
    mesh = meshes.sphere()
    pts, normals = placement.place(mesh, pos, R, size)
    n = len(mesh.points)
    for m in range(M):
        w = pts[m * n:(m + 1) * n]
        q = (w - pos[m]) @ R[m]                               # local coordinates
        semi = size[m] / 2
        assert np.allclose(np.sum((q / semi) ** 2, axis=1), 1, atol=1e-6)
        grad = (2 * q / semi ** 2) @ R[m].T                   # of sum (q_i / a_i)^2, in world
        grad /= np.linalg.norm(grad, axis=1)[:, None]
        assert np.allclose(normals[m * n:(m + 1) * n], grad, atol=1e-6)


def test_place_broadcasts_and_tiles():
    mesh = meshes.box()
    pos = np.arange(9, dtype=float).reshape(3, 3)
    pts, normals = placement.place(mesh, pos, np.eye(3), [1, 1, 1])
    assert pts.shape == normals.shape == (72, 3)
    assert np.allclose(pts[24:48], mesh.points + pos[1])
    tris = placement.tile(mesh.triangles, len(mesh.points), 3)
    assert tris.shape == (36, 3) and tris.dtype == np.int64
    assert np.array_equal(tris[12:24], mesh.triangles + 24)
    cells = placement.vtk_cells(tris)
    assert cells.shape == (36 * 4,) and np.all(cells[::4] == 3)
    assert np.array_equal(cells.reshape(-1, 4)[:, 1:], tris)


def test_zero_size_gives_finite_normals():
    pts, normals = placement.place(meshes.sphere(), [0, 0, 0], np.eye(3), [1, 0, 1])
    assert np.all(np.isfinite(pts)) and np.all(np.isfinite(normals))


# -- arrow --------------------------------------------------------------------------------

def test_arrow_dims_defaults():
    assert np.allclose(meshes.arrow_dims(1), (0.1, 0.2, 0.3))
    assert np.allclose(meshes.arrow_dims(5), (0.5, 1.0, 1.5))
    assert np.allclose(meshes.arrow_dims(2, headwidth=0.7), (0.2, 0.7, 0.6))


def test_arrow_dims_short_and_thin_rules():
    # a set shaftwidth makes the head longer than half the arrow: the unset ones shrink
    assert np.allclose(meshes.arrow_dims(1, shaftwidth=0.5), (0.5, 1 / 3, 0.5))
    # a shaft thinner than 2% of the length: the unset ones grow
    assert np.allclose(meshes.arrow_dims(1, shaftwidth=0.01), (0.01, 0.04, 0.06))
    # a set headlength is kept even when longer than the arrow
    assert np.allclose(meshes.arrow_dims(1, headlength=2), (0.025, 0.05, 2))


@pytest.mark.parametrize("length, kw", [(1.0, {}), (3.0, {"shaftwidth": 0.4}), (1.0, {"headlength": 2})])
def test_arrow_tip_at_length(length, kw):
    sw, hw, hl = meshes.arrow_dims(length, **kw)
    mesh = meshes.arrow(length, sw, hw, hl)
    assert_mesh_arrays(mesh)
    assert len(mesh.points) == 40 and len(mesh.triangles) == 18
    assert mesh.points[:, 0].max() == length
    assert np.allclose(mesh.points[mesh.points[:, 0] == length], (length, 0, 0))
    shaft, head = mesh.points[:24], mesh.points[24:]
    assert np.allclose(np.abs(shaft[:, 1:]), sw / 2)
    assert np.allclose(sorted({shaft[:, 0].min(), shaft[:, 0].max()}), sorted({0.0, length - hl}))
    assert np.isclose(np.abs(head[:, 1:]).max(), hw / 2)
    assert_winding_outward(mesh)


def test_arrow_placed_along_its_axis():
    axis = np.array([0.0, 0.0, -2.0])
    mesh = meshes.arrow(2.0, *meshes.arrow_dims(2.0))
    pts, _ = placement.place(mesh, [1, 1, 1], placement.frames(axis, [0, 1, 0]), [1, 1, 1])
    assert np.allclose(pts[np.argmin(pts[:, 2])], (1, 1, -1))


# -- ring and tube ------------------------------------------------------------------------

def test_ring_lies_in_the_yz_plane_at_radius_plus_minus_thickness():
    R, t = 1.5, 0.1
    mesh = meshes.ring(R, t)
    assert_mesh_arrays(mesh)
    assert len(mesh.points) == 60 * 20 and len(mesh.triangles) == 2 * 60 * 20
    p = mesh.points
    rho = np.hypot(p[:, 1], p[:, 2])                          # distance from the axis (x)
    assert np.allclose((rho - R) ** 2 + p[:, 0] ** 2, t ** 2)  # on the tube around the centre line
    assert np.isclose(rho.min(), R - t) and np.isclose(rho.max(), R + t)
    assert np.isclose(np.abs(p[:, 0]).max(), t)
    assert_winding_outward(mesh)
    # its size, VPython's way: thickness is the cross section's radius
    ring = vp.ring(radius=R, thickness=t)
    assert np.allclose(ring.size.value, (0.2, 3.2, 3.2))
    assert np.isclose(ring.radius, R) and np.isclose(ring.thickness, t)


def test_ring_with_axis_z_lies_in_xy():
    pts, _ = placement.place(meshes.ring(1, 0.1), [0, 0, 5], placement.frames([0, 0, 3], [0, 1, 0]), [1, 1, 1])
    assert np.allclose(np.abs(pts[:, 2] - 5).max(), 0.1)
    assert np.isclose(np.hypot(pts[:, 0], pts[:, 1]).max(), 1.1)


@pytest.mark.parametrize("start_cap", [False, True])
def test_tube_passes_through_its_points(start_cap):
    pts = np.array([[0, 0, 0], [1, 0, 0], [1, 2, 0], [1, 2, 0.5], [1, 2, 0.5]], dtype=float)
    radius = np.array([0.1, 0.2, 0.1, 0.05, 0.05])
    mesh = meshes.tube(pts, radius, start_cap=start_cap)
    assert_mesh_arrays(mesh)
    S, sides = len(pts) - 1, 16
    cap = 4 * sides + 1
    per = 2 * sides + cap * (2 if start_cap else 1)
    assert len(mesh.points) == S * per
    seg = mesh.points.reshape(S, per, 3)
    for s in range(S):
        a, b = pts[s], pts[s + 1]
        start, end = seg[s, :sides], seg[s, sides:2 * sides]
        assert np.allclose(start.mean(axis=0), a) and np.allclose(end.mean(axis=0), b)
        assert np.allclose(np.linalg.norm(start - a, axis=1), radius[s])
        assert np.allclose(np.linalg.norm(end - b, axis=1), radius[s + 1])
        if np.any(b != a):
            assert np.allclose((start - a) @ (b - a), 0)      # cross sections perpendicular
        joint = seg[s, 2 * sides:2 * sides + cap]
        assert np.allclose(np.linalg.norm(joint - b, axis=1), radius[s + 1])
    assert_winding_outward(mesh)


def test_tube_with_scalar_radius_and_no_joints():
    mesh = meshes.tube([[0, 0, 0], [0, 1, 0], [0, 1, 1]], 0.01, sides=8, joints=False)
    assert len(mesh.points) == 2 * 2 * 8 and len(mesh.triangles) == 2 * 2 * 8
    with pytest.raises(ValueError):
        meshes.tube([[0, 0, 0]], 0.1)


# -- sizes --------------------------------------------------------------------------------

def test_default_sizes_and_radius_rules():
    """VPython's size rules on its objects: default sizes, radius <-> size, what an axis
    or a size changes."""
    defaults = {vp.sphere: (2, 2, 2), vp.cylinder: (1, 2, 2), vp.cone: (1, 2, 2),
                vp.helix: (1, 2, 2), vp.arrow: (1, 0.2, 0.2), vp.ring: (0.2, 2.2, 2.2),
                vp.box: (1, 1, 1), vp.pyramid: (1, 1, 1), vp.ellipsoid: (1, 1, 1)}
    for make, size in defaults.items():
        assert np.allclose(make().size.value, size), make
    assert vp.sphere().radius == 1 and vp.helix().radius == 1
    assert vp.ring().radius == pytest.approx(1)
    assert np.allclose(vp.sphere(radius=0.025).size.value, (0.05, 0.05, 0.05))
    c = vp.cylinder(size=vp.vector(3, 2, 2))
    c.radius = 0.5
    assert np.allclose(c.size.value, (3, 1, 1))
    r = vp.ring()
    r.radius = 2
    assert np.allclose(r.size.value, (0.2, 4.2, 4.2))
    r = vp.ring()
    r.thickness = 0.3
    assert np.allclose(r.size.value, (0.6, 2.6, 2.6))
    assert vp.helix().thickness == pytest.approx(0.1)              # radius / 10 by default
    b = vp.box()
    b.length = 3                                                   # length is size.x and axis
    assert np.allclose(b.axis.value, (3, 0, 0)) and np.allclose(b.size.value, (3, 1, 1))
    s = vp.sphere()
    s.axis = vp.vector(3, 0, 0)                                    # a sphere's axis: its turn
    assert np.allclose(s.size.value, (2, 2, 2))
    g = vp.ring()
    g.size = vp.vector(1, 1, 1)                                    # a ring's size: not its axis
    assert np.allclose(g.axis.value, (1, 0, 0))


def test_tube_vertex_points_maps_vertices_to_their_polyline_point():
    pts = np.array([[0, 0, 0], [1, 0, 0], [1, 1, 0]], dtype=float)
    for start_cap in (False, True):
        mesh = meshes.tube(pts, 0.1, start_cap=start_cap)
        owner = meshes.tube_vertex_points(len(pts), start_cap=start_cap)
        assert owner.shape == (len(mesh.points),)
        assert np.all(np.linalg.norm(mesh.points - pts[owner], axis=1) <= 0.1 + 1e-12)


def test_adjust_up_broadcasts_one_axis_change_over_many_ups():
    ups = np.array([[0, 1, 0], [0, 0, 1], [0.6, 0.8, 0]])
    out = placement.adjust_up([1, 0, 0], [0, -1, 0], ups)
    assert out.shape == (3, 3)
    assert np.allclose(out[0], (1, 0, 0)) and np.allclose(out[1], (0, 0, 1))
    assert np.allclose(out[2], (0.8, -0.6, 0))
