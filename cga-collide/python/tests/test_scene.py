"""Scene from Python: the Rust doc example, and every answer against a brute force over all
pairs of colliders' pose queries."""

import itertools

import numpy as np
import pytest

import cga_collide as cc
from conftest import random_poses, rotation_z, translation

I = np.eye(4)


@pytest.fixture(scope="module")
def cube():
    return cc.Collider.cuboid(np.zeros(3), np.ones(3))


def test_the_rust_doc_example(cube):
    scene = cc.Scene()
    a = scene.add(cube)
    b = scene.add(cube, translation(1.0))
    c = scene.add(cube, rotation_z(45.0, t=(5.0, 0.0, 0.0)))
    assert len(scene) == 3 and [o.index for o in scene.ids()] == [0, 1, 2]
    assert scene.colliding_pairs() == [(a, b)]
    scene.set_pose(c, translation(2.0))
    assert scene.colliding_pairs() == [(a, b), (b, c)]
    scene.exclude_pair(a, b)
    assert scene.colliding_pairs() == [(b, c)]
    p, q, d = scene.nearest_pair()
    assert (p, q, d.distance) == (b, c, 0.0)
    scene.include_pair(a, b)
    assert scene.colliding_with(b) == [a, c]
    assert np.array_equal(scene.pose(c), translation(2.0))


def test_handles_errors_and_removal(cube):
    scene = cc.Scene()
    a = scene.add(cube)
    b = scene.add(cube, translation(0.5))
    assert scene.remove(b).num_triangles == 12
    with pytest.raises(cc.CgaError, match="not in the scene"):
        scene.set_pose(b, I)
    c = scene.add(cube, translation(0.5))  # reuses b's slot, a new generation
    assert c.index == b.index and c != b
    assert scene.colliding_pairs() == [(a, c)]
    with pytest.raises(cc.CgaError, match="last row"):
        scene.add(cube, np.diag([1.0, 1.0, 1.0, 2.0]))
    with pytest.raises(cc.CgaError, match="2 objects and 1 poses"):
        scene.set_poses([a, c], np.stack([I]))
    with pytest.raises(cc.CgaError, match="pose: .*complex"):
        scene.set_pose(a, np.eye(4, dtype=np.complex128))
    assert scene.nearest_pair() is not None and cc.Scene().nearest_pair() is None


def test_groups_and_solid(cube):
    scene = cc.Scene()
    big = cc.Collider.cuboid(np.full(3, -1.0), np.full(3, 2.0))
    a = scene.add(big)
    b = scene.add(cube)  # inside a, surfaces apart
    assert scene.colliding_pairs() == []
    scene.set_solid(True)
    assert scene.colliding_pairs() == [(a, b)]
    scene.set_groups(b, 0b10, 0b10)
    scene.set_groups(a, 0b01, 0b01)
    assert scene.colliding_pairs() == []


def test_scene_equals_brute_force():
    rng = np.random.default_rng(11)
    shapes = [cc.Collider.cuboid(np.zeros(3), rng.uniform(0.5, 2.0, 3)) for _ in range(4)]
    scene = cc.Scene()
    n = 40
    poses = random_poses(n, seed=12, spread=5.0)
    kinds = [shapes[k % 4] for k in range(n)]
    ids = [scene.add(kinds[k], poses[k]) for k in range(n)]

    def brute(poses):
        pairs = [
            (ids[i], ids[j])
            for i, j in itertools.combinations(range(n), 2)
            if kinds[i].collides_at(poses[i], kinds[j], poses[j])
        ]
        within = [
            (ids[i], ids[j])
            for i, j in itertools.combinations(range(n), 2)
            if kinds[i].within_distance_at(poses[i], kinds[j], poses[j], 0.3)
        ]
        return pairs, within

    for step in range(3):
        pairs, within = brute(poses)
        assert scene.colliding_pairs() == pairs
        assert scene.pairs_within_distance(0.3) == within
        assert 0 < len(pairs) < n * (n - 1) // 2
        for k in (0, 7):
            want = sorted({q for p in pairs for q in p if ids[k] in p} - {ids[k]})
            assert scene.colliding_with(ids[k]) == want
        probe = cc.Collider.cuboid(np.zeros(3), np.ones(3))
        hits = [ids[i] for i in range(n) if probe.collides_at(I, kinds[i], poses[i])]
        assert scene.colliding_at(probe, I) == hits
        # With pairs touching, the nearest pair is one of them, at distance 0.
        p, q, d = scene.nearest_pair()
        assert (p, q) in pairs and d.distance == 0.0
        # move everything in one call
        poses = random_poses(n, seed=20 + step, spread=5.0)
        scene.set_poses(ids, poses)


def test_nearest_pair_and_nearest_to_equal_brute_force():
    """Objects apart (a jittered grid, random turns), so the nearest pair is a real distance
    query; the scene's answers against every pair's certified distance."""
    rng = np.random.default_rng(31)
    shapes = [cc.Collider.cuboid(np.zeros(3), rng.uniform(0.3, 1.0, 3)) for _ in range(3)]
    grid = [(x, y, z) for x in range(3) for y in range(3) for z in range(2)]
    n = len(grid)
    poses = random_poses(n, seed=32, spread=0.4)
    poses[:, :3, 3] += 3.0 * np.array(grid)
    kinds = [shapes[k % 3] for k in range(n)]
    scene = cc.Scene()
    ids = [scene.add(kinds[k], poses[k]) for k in range(n)]
    assert scene.colliding_pairs() == []
    dist = {
        (i, j): kinds[i].distance_at(poses[i], kinds[j], poses[j])
        for i, j in itertools.combinations(range(n), 2)
    }
    best = min(d.distance for d in dist.values())
    slack = max(d.error_bound for d in dist.values())
    p, q, d = scene.nearest_pair()
    i, j = sorted((ids.index(p), ids.index(q)))
    assert 0.0 < d.distance <= best + d.error_bound + slack
    assert abs(d.distance - dist[(i, j)].distance) <= d.error_bound + dist[(i, j)].error_bound
    # The witnesses lie on the two objects' surfaces, that far apart.
    assert np.isclose(np.linalg.norm(d.witness_a - d.witness_b), d.distance, rtol=1e-12, atol=0)
    for k in (0, 7, n - 1):
        other, dk = scene.nearest_to(ids[k])
        mine = {(a if b == k else b): dist[(a, b)] for a, b in dist if k in (a, b)}
        want = min(x.distance for x in mine.values())
        o = ids.index(other)
        assert o != k and dk.distance <= want + dk.error_bound + slack
        assert abs(dk.distance - mine[o].distance) <= dk.error_bound + mine[o].error_bound


def test_segment_hits(cube):
    scene = cc.Scene()
    a = scene.add(cube)
    scene.add(cube, translation(0.0, 5.0))
    c = scene.add(cube, translation(3.0))
    assert scene.segment_hits(np.array([-1.0, 0.3, 0.6]), np.array([10.0, 0.3, 0.6])) == [a, c]
    other, d = scene.nearest_to(a)
    assert other == c and abs(d.distance - 2.0) <= d.error_bound
