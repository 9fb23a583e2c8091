"""Shapes wherever a Collider goes: against a mesh (the collider's shape questions and the
module functions, equal to the shape against each triangle), under poses and in batches, and
in a Scene beside meshes. Pairs whose exact engine the library does not have yet are skipped
(see ``test_shapes.answer``)."""

import numpy as np
import pytest

import cga_collide as cc
from conftest import random_poses, translation
from test_shapes import KINDS, answer, shape_of


@pytest.fixture(scope="module")
def cube():
    """The closed unit cube [0, 1]^3 (12 triangles)."""
    return cc.Collider.cuboid(np.zeros(3), np.ones(3))


def triangles(mesh, pose=np.eye(4)):
    """Every triangle of a mesh at ``pose``, as a ``Triangle`` (corners placed in float64,
    the placement rule)."""
    v = mesh.vertices @ pose[:3, :3].T + pose[:3, 3]
    return [cc.Triangle(*v[f]) for f in mesh.faces]


def decided(f, *args):
    """``f(*args)``, or ``None`` when the library refuses the pair (no exact engine)."""
    try:
        return f(*args)
    except cc.CgaError as e:
        if "no exact" in str(e):
            return None
        raise


POSES = [np.eye(4), translation(0.5, 0.5, 0.5), translation(1.5, 0.25, 0.5), translation(3.0)]


@pytest.mark.parametrize("kind", KINDS)
@pytest.mark.parametrize("where", range(len(POSES)))
def test_shape_against_a_mesh_is_the_shape_against_each_triangle(cube, kind, where):
    s = shape_of(kind).placed(POSES[where])
    each = [answer(cc.intersects, s, t) for t in triangles(cube)]
    hits = answer(cube.shape_hits, s)
    assert list(hits) == [i for i, hit in enumerate(each) if hit]
    assert cube.intersects_shape(s) == any(each)
    assert cc.intersects(s, cube) == cc.intersects(cube, s) == any(each)
    for c in (0.0, 0.25, 1.0):
        # Every triangle asked, so the expected answer does not depend on their order: a
        # triangle refused (cylinders and cones with c > 0 the pair filter leaves undecided)
        # leaves the mesh's answer to the others.
        each_near = [decided(cc.within_distance, s, t, c) for t in triangles(cube)]
        for mesh_near in (
            lambda: cube.shape_within_distance(s, c),
            lambda: cc.within_distance(cube, s, c),
            lambda: cc.within_distance(s, cube, c),
        ):
            if True in each_near:
                assert mesh_near() is True
            elif None not in each_near:
                assert mesh_near() is False
            else:  # refused, unless the refused triangles' boxes are proved out of reach
                assert decided(mesh_near) in (None, False)
    d = answer(cube.distance_to_shape, s)
    best = min(answer(cc.distance, t, s).distance for t in triangles(cube))
    assert abs(d.distance - best) <= 2 * d.error_bound + 1e-15
    swapped = answer(cc.distance, s, cube)
    assert swapped.distance == d.distance
    assert np.array_equal(swapped.witness_a, d.witness_b)
    assert np.array_equal(swapped.witness_b, d.witness_a)
    # a shape inside the closed cube meets no triangle but the solid
    assert cube.intersects_shape_solid(s) == (any(each) or where == 1)


@pytest.mark.parametrize("kind", KINDS)
def test_poses_and_batches_with_a_mesh_equal_placed_calls(cube, kind):
    s = shape_of(kind)
    pm, ps = random_poses(8, 20, spread=1.0), random_poses(8, 21, spread=1.5)
    hits = answer(cc.intersects_batch, cube, s, pm, ps)
    back = answer(cc.intersects_batch, s, cube, ps, pm)
    ds = answer(cc.distance_batch, cube, s, pm, ps)
    near = answer(cc.within_distance_batch, s, cube, ps, pm, 0.3)
    assert np.array_equal(hits, back)
    for i in range(len(pm)):
        assert hits[i] == cube.intersects_shape_at(pm[i], s, ps[i]) == cc.intersects_at(s, ps[i], cube, pm[i])
        assert hits[i] == (len(cube.shape_hits_at(pm[i], s, ps[i])) > 0)
        assert near[i] == cube.shape_within_distance_at(pm[i], s, ps[i], 0.3)
        d = cube.distance_to_shape_at(pm[i], s, ps[i])
        assert ds.distance[i] == d.distance and ds.error_bound[i] == d.error_bound


def test_mesh_arguments_of_the_module_functions(cube):
    other = cc.Collider.cuboid(np.ones(3), 2 * np.ones(3))
    assert cc.intersects(cube, other) == cube.collides(other) is True
    assert cc.within_distance(cube, other, 0.0) is True
    assert cc.distance(cube, other).distance == cube.distance(other).distance
    far = translation(5.0)
    assert cc.intersects_at(cube, np.eye(4), other, far) is False
    assert list(cc.intersects_batch(cube, other, np.eye(4), np.stack([np.eye(4), far]))) == [True, False]
    with pytest.raises(cc.CgaError, match="clearance"):
        cc.within_distance(cube, other, float("nan"))
    with pytest.raises(TypeError, match="or a Collider"):
        cc.intersects(cube, "cube")
    with pytest.raises(TypeError, match="shape: expected a shape"):
        cube.intersects_shape(cube)


def test_a_scene_holds_shapes_beside_meshes(cube):
    scene = cc.Scene()
    mesh = scene.add(cube)
    ball = scene.add_shape(cc.Ball([0, 0, 0], 0.5), translation(1.5, 0.5, 0.5))  # touches x = 1
    plate = scene.add_shape(cc.Triangle([0, 0, 0], [4, 0, 0], [0, 4, 0]), translation(0, 0, -1))
    far = scene.add_shape(cc.Segment([0, 0, 0], [1, 0, 0]), translation(10, 0, 0))
    assert [scene.kind(o) for o in (mesh, ball, plate, far)] == ["mesh", "ball", "triangle", "segment"]
    assert scene.shape(ball) == cc.Ball([0, 0, 0], 0.5)  # in its own frame
    with pytest.raises(cc.CgaError):
        scene.collider(ball)
    with pytest.raises(cc.CgaError):
        scene.shape(mesh)
    assert scene.colliding_pairs() == [(mesh, ball)]
    assert scene.colliding_with(ball) == [mesh]
    assert scene.colliding_at(cc.Ball([0, 0, 0], 1.0), translation(10, 0, 0.5)) == [far]
    assert scene.colliding_at(cube, translation(1.0)) == [mesh, ball]
    assert scene.pairs_within_distance(1.0) == [(mesh, ball), (mesh, plate), (ball, plate)]
    scene.set_pose(far, translation(0.5, 0.5, -1.0))  # now it lies on the plate
    assert scene.colliding_pairs() == [(mesh, ball), (plate, far)]
    nearest = scene.nearest_to(far)
    assert nearest is not None and nearest[0] == plate and nearest[1].distance == 0.0
    assert scene.remove(ball) == cc.Ball([0, 0, 0], 0.5)
    assert type(scene.remove(mesh)) is cc.Collider
    assert len(scene) == 2


def test_a_scene_with_a_floor(cube):
    """A half-space in a scene (its world box is unbounded)."""
    scene = cc.Scene()
    mesh = scene.add(cube)
    floor = scene.add_shape(cc.HalfSpace([0, 0, 0], [0, 0, 1]), translation(0, 0, -1))
    box = scene.add_shape(cc.Cuboid.axis_aligned([0, 0, 0], [0.5, 0.5, 0.5]), translation(5, 0, 0))
    assert answer(scene.colliding_pairs) == []
    scene.set_pose(box, translation(5, 0, -1.5))  # touches z = -1 from below: inside the floor
    assert answer(scene.colliding_pairs) == [(floor, box)]
    scene.set_pose(mesh, translation(0, 0, -2.0))  # the cube's top face on z = -1
    assert answer(scene.colliding_pairs) == [(mesh, floor), (floor, box)]
