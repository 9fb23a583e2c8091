"""The trimesh drop-in's penetration depths: exact for convex meshes (against the library's
certified depth of the same solids as shapes, and against values known by hand), a certified
lower bound for other closed meshes, none for open ones."""

import numpy as np
import pytest

import cga_collide as cc
from cga_collide.trimesh import CollisionManager
from conftest import random_poses, translation

trimesh = pytest.importorskip("trimesh")

ULP = 1.0 - np.nextafter(1.0, 0.0)


@pytest.fixture(scope="module")
def box():
    return trimesh.creation.box(extents=[1.0, 1.0, 1.0])


def contacts(mesh_a, pose_a, mesh_b, pose_b):
    m = CollisionManager()
    m.add_object("a", mesh_a, pose_a)
    m.add_object("b", mesh_b, pose_b)
    hit, data = m.in_collision_internal(return_data=True)
    return hit, data, m


def reference(shape_a, pose_a, shape_b, pose_b):
    """The library's certified depth of the two solids as shapes (checked against an
    independent exact reference in the workspace tests)."""
    sd = cc.signed_distance_at(shape_a, pose_a, shape_b, pose_b)
    return max(-sd.value, 0.0), sd.error_bound


@pytest.mark.parametrize(
    "x, depth",
    [
        (0.5, 0.5),  # deep
        (1.0 - 1e-9, 1.0 - (1.0 - 1e-9)),  # shallow
        (np.nextafter(1.0, 0.0), ULP),  # one ulp
        (1.0, 0.0),  # faces flush: touching
        (0.0, 1.0),  # coincident: every face normal is a least direction
    ],
)
def test_box_depths_are_exact(box, x, depth):
    hit, data, m = contacts(box, np.eye(4), box, translation(x))
    assert hit and data
    for c in data:
        assert c.depth_kind == "exact" and c.depth == depth
        assert np.isclose(np.linalg.norm(c.normal), 1.0)
    if depth > 0 and x > 0:
        assert np.allclose(data[0].normal, [1.0, 0.0, 0.0])  # push b along +x
    d, names = m.min_distance_internal(return_names=True)
    assert names == ("a", "b") and d == -depth


def test_tilted_box_on_an_edge(box):
    # b turned 45 degrees about z, its edge sunk into a's +x face
    half_diagonal = np.sqrt(0.5)
    pose = cc.pose_from_degrees([0.0, 0.0, 45.0], [0.5 + half_diagonal - 0.125, 0.0, 0.0])
    _, data, _ = contacts(box, np.eye(4), box, pose)
    want, bound = reference(cc.Cuboid.axis_aligned([0, 0, 0], [0.5] * 3), np.eye(4),
                            cc.Cuboid.axis_aligned([0, 0, 0], [0.5] * 3), pose)
    assert abs(want - 0.125) < 1e-15
    assert data and all(abs(c.depth - want) <= bound + 1e-15 for c in data)
    assert np.allclose(data[0].normal, [1.0, 0.0, 0.0])


def test_cylinder_standing_on_a_face(box):
    cylinder = trimesh.creation.cylinder(radius=0.2, height=0.4, sections=8)
    assert len(np.unique(cylinder.vertices, axis=0)) <= 128
    z = 0.5 + 0.2 - 0.05  # bottom 0.05 below the box's top face
    _, data, m = contacts(box, np.eye(4), cylinder, translation(0.1, -0.1, z))
    want = 0.5 - (z - 0.2)
    assert data and all(c.depth_kind == "exact" and abs(c.depth - want) <= 1e-16 for c in data)
    assert np.allclose(data[0].normal, [0.0, 0.0, 1.0])
    assert m.min_distance_single(box, translation(0.0, 0.0, 3.0)) > 0.0


def test_random_convex_pairs_match_the_reference(box):
    tetra = trimesh.Trimesh(
        vertices=[[0, 0, 0], [1.0, 0, 0], [0, 1.0, 0], [0, 0, 1.0]],
        faces=[[0, 2, 1], [0, 1, 3], [0, 3, 2], [1, 2, 3]],
    )
    shapes = {
        "box": cc.Cuboid.axis_aligned([0, 0, 0], [0.5] * 3),
        "tetra": cc.ConvexHull(np.asarray(tetra.vertices)),
    }
    meshes = {"box": box, "tetra": tetra}
    poses = random_poses(60, seed=7, spread=0.6)
    checked = 0
    for k in range(0, 60, 2):
        ka, kb = ("box", "tetra") if k % 4 else ("box", "box")
        hit, data, m = contacts(meshes[ka], poses[k], meshes[kb], poses[k + 1])
        if not hit:
            continue
        want, bound = reference(shapes[ka], poses[k], shapes[kb], poses[k + 1])
        for c in data:
            assert c.depth_kind == "exact"
            assert abs(c.depth - want) <= bound + 1e-14 * max(want, 1.0)
        assert abs(-m.min_distance_internal() - want) <= bound + 1e-14 * max(want, 1.0)
        checked += 1
    assert checked >= 10


def two_cubes():
    """A closed, non-convex mesh: unit cubes centred at the origin and at x = 3."""
    a = trimesh.creation.box(extents=[1.0, 1.0, 1.0])
    b = a.copy()
    b.apply_translation([3.0, 0.0, 0.0])
    return trimesh.util.concatenate([a, b])


def test_closed_non_convex_meshes_get_the_deepest_vertex(box):
    # b's corner (0.4, 0.4, 0.4) inside a's first cube, 0.1 from its faces; a's corner
    # (0.5, 0.5, 0.5) inside b, 0.1 from b's faces: both vertices are 0.1 deep, as is the pair
    pose = translation(0.9, 0.9, 0.9)
    _, data, m = contacts(two_cubes(), np.eye(4), box, pose)
    assert data
    for c in data:
        assert c.depth_kind == "vertex" and abs(c.depth - 0.1) <= 1e-15
        assert np.isclose(np.linalg.norm(c.normal), 1.0) and np.isclose(np.abs(c.normal).max(), 1.0)
    d, data = m.min_distance_internal(return_data=True)
    assert abs(d + 0.1) <= 1e-15
    gap = data.point("b") - data.point("a")
    assert abs(np.linalg.norm(gap) - 0.1) <= 1e-15


def test_vertex_depth_is_a_lower_bound(box):
    # a convex mesh with more than MAX_HULL_POINTS (128) vertices gets the vertex depth: never above the depth of
    # the ball it is inscribed in (which is above its own), and here the vertex on the x axis
    # is the deepest point: exactly 1 - x
    sphere = trimesh.creation.icosphere(subdivisions=3, radius=0.5)
    assert len(sphere.vertices) > 128 and np.isclose(np.abs(sphere.vertices).max(), 0.5)
    for x in (0.6, 0.8, 0.95):
        _, data, _ = contacts(box, np.eye(4), sphere, translation(x, 0.0, 0.0))
        ball, bound = reference(cc.Cuboid.axis_aligned([0, 0, 0], [0.5] * 3), np.eye(4),
                                cc.Ball([0.0, 0.0, 0.0], 0.5), translation(x, 0.0, 0.0))
        assert data and all(c.depth_kind == "vertex" for c in data)
        assert all(0.0 < c.depth <= ball + bound for c in data)
        lowest = sphere.vertices[:, 0].min() + x
        assert all(abs(c.depth - (0.5 - lowest)) <= 1e-15 for c in data)


def test_crossing_without_a_vertex_inside_has_depth_zero():
    # two long thin bars crossing at right angles: the surfaces cross, no vertex is inside
    bar = trimesh.creation.box(extents=[4.0, 0.2, 0.2])
    turned = cc.pose_from_degrees([0.0, 0.0, 90.0])
    tall = trimesh.creation.box(extents=[4.0, 0.2, 0.3])
    _, data, _ = contacts(bar, np.eye(4), tall, turned)
    assert data
    # both convex with 8 vertices: exact, 0.25 along z (2.1 along x or y)
    assert all(c.depth_kind == "exact" and abs(c.depth - 0.25) <= 1e-15 for c in data)
    assert all(np.allclose(np.abs(c.normal), [0.0, 0.0, 1.0]) for c in data)
    _, data, _ = contacts(two_cubes(), np.eye(4), tall, translation(3.0))
    assert data and all(c.depth_kind == "vertex" and c.depth == 0.0 for c in data)
    assert all(np.isclose(np.linalg.norm(c.normal), 1.0) for c in data)


def test_shape_depth_of_a_cylinder_lying_on_a_box():
    # The exact cylinder (not a mesh) sunk 0.125 into the top face of a box: certified depth.
    table = cc.Cuboid.axis_aligned([0.0, 0.0, 0.0], [2.0, 2.0, 0.5])
    lying = cc.Cylinder([-1.0, 0.0, 0.875], [1.0, 0.0, 0.875], 0.5)
    sd = cc.signed_distance(table, lying)
    assert sd.kind == "penetrating"
    assert abs(sd.value + 0.125) <= sd.error_bound < 1e-13
    assert np.allclose(sd.normal, [0.0, 0.0, 1.0])
    resting = cc.Cylinder([-1.0, 0.0, 1.0], [1.0, 0.0, 1.0], 0.5)
    sd = cc.signed_distance(table, resting)
    assert (sd.kind, sd.value, sd.error_bound) == ("touching", 0.0, 0.0)
