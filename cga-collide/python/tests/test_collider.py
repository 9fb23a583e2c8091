"""Collider from Python: numpy in and out, every question in its three forms, errors,
pickling, and agreement between forms (batch and single calls, box tree and brute force,
poses and meshes placed first)."""

import pickle
import threading

import numpy as np
import pytest

import cga_collide as cc
from conftest import REPO, random_poses, rotation_z, translation

DATA = REPO / "cga-collide" / "data"
I = np.eye(4)


@pytest.fixture(scope="module")
def cube():
    return cc.Collider.cuboid(np.zeros(3), np.ones(3))


@pytest.fixture(scope="module")
def bunny():
    return cc.Collider.load(str(DATA / "bunny.obj"))


def placed(c: cc.Collider, pose: np.ndarray) -> cc.Collider:
    """The collider's mesh moved by ``pose`` in numpy, built anew."""
    v = c.vertices @ pose[:3, :3].T + pose[:3, 3]
    return cc.Collider(v, c.faces)


# ---------------------------------------------------------------- building


def test_from_arrays_and_accessors(cube):
    c = cc.Collider(cube.vertices, cube.faces)
    assert c.num_triangles == 12 and c.vertices.shape == (8, 3) and c.faces.shape == (12, 3)
    assert c.vertices.dtype == np.float64 and c.faces.dtype == np.int64
    assert np.array_equal(c.bounds, [[0, 0, 0], [1, 1, 1]])
    assert c.is_closed() and c.mode == "bvh" and c.with_mode("brute").mode == "brute"
    # any integer dtype for faces, any memory layout for vertices
    c32 = cc.Collider(np.asfortranarray(cube.vertices), cube.faces.astype(np.uint32))
    assert c32.collides(c)
    assert "Collider(triangles=12" in repr(c)


def test_load_formats(bunny):
    assert bunny.num_triangles > 1000
    armadillo = cc.Collider.load(str(DATA / "armadillo.off.gz"))
    assert armadillo.num_triangles > 1000


@pytest.mark.parametrize(
    "vertices, faces, error, words",
    [
        (np.zeros((3, 3), np.complex128), np.array([[0, 1, 2]]), cc.CgaError, "vertices: .*complex"),
        ([[0.0, 0, 0], [1, 0, 0], [0, 1]], np.array([[0, 1, 2]]), cc.CgaError, "vertices: expected an array of numbers"),
        (np.zeros((3, 2)), np.array([[0, 1, 2]]), cc.CgaError, "shape"),
        (np.zeros((3, 3)), np.array([[0.0, 1, 2]]), cc.CgaError, "faces: expected integers"),
        (np.zeros((3, 3)), np.array([[True, False, True]]), cc.CgaError, "faces: expected integers"),
        (np.zeros((3, 3)), np.array([[0, 1, 3]]), cc.CgaError, "face 0: vertex index 3"),
        (np.zeros((3, 3)), np.array([[0, -1, 2]]), cc.CgaError, "vertex index -1"),
        (np.zeros((3, 3)), np.zeros((0, 3), np.int64), cc.CgaError, "empty"),
        (np.array([[0, 0, 0], [1, 0, np.nan], [0, 1, 0.0]]), np.array([[0, 1, 2]]), cc.CgaError, "vertex 1"),
    ],
)
def test_bad_meshes_raise_clear_errors(vertices, faces, error, words):
    with pytest.raises(error, match=words):
        cc.Collider(vertices, faces)


def test_file_errors_name_the_file_and_line(tmp_path):
    with pytest.raises(cc.CgaError, match="cannot read"):
        cc.Collider.load(str(tmp_path / "missing.obj"))
    bad = tmp_path / "bad.obj"
    bad.write_text("v 0 0 0\nv 1 0 0\nv 0 1 x\nf 1 2 3\n")
    with pytest.raises(cc.CgaError, match=r"bad\.obj:3"):
        cc.Collider.load(str(bad))
    with pytest.raises(cc.CgaError, match="unknown mesh format"):
        cc.Collider.load(str(tmp_path / "x.xyz"))
    assert issubclass(cc.CgaError, ValueError)


# ---------------------------------------------------------------- poses


@pytest.mark.parametrize(
    "pose, error, words",
    [
        (np.eye(4, dtype=np.complex128), cc.CgaError, "complex"),
        (np.eye(4, dtype=bool), cc.CgaError, "booleans"),
        (np.eye(4).astype(str), cc.CgaError, "not an array of real numbers"),
        (np.eye(3), cc.CgaError, r"shape \(4, 4\)"),
        (np.diag([2.0, 2.0, 2.0, 1.0]), cc.CgaError, "not a rotation"),
        (np.diag([1.0, 1.0, -1.0, 1.0]), cc.CgaError, "det"),
        (np.diag([1.0, 1.0, 1.0, 2.0]), cc.CgaError, "last row"),
        (translation(np.inf), cc.CgaError, r"entry \[0, 3\] is not finite"),
    ],
)
def test_bad_poses_are_refused(cube, pose, error, words):
    with pytest.raises(error, match=words):
        cube.collides_at(pose, cube, I)
    with pytest.raises(error, match="pose_b"):
        cube.collides_at(I, cube, pose)


def test_bad_batches_say_which_pose(cube):
    poses = np.stack([I, I, np.diag([1.0, 1.0, 1.0, 3.0])])
    with pytest.raises(cc.CgaError, match=r"poses_a\[2\]"):
        cube.collides_batch(cube, poses, I)
    with pytest.raises(cc.CgaError, match="3 poses and poses_b has 2"):
        cube.collides_batch(cube, np.stack([I, I, I]), np.stack([I, I]))
    far = np.stack([I, translation(1e300)])
    with pytest.raises(cc.CgaError, match="pose 1 of the batch"):
        cube.distance_batch(cube, far, I)
    with pytest.raises(cc.CgaError, match="scale the meshes"):
        cube.distance_at(I, cube, translation(1e300))


def test_the_rust_doc_example(cube):
    # the same numbers as the Rust collider module's example
    there = translation(1.5)
    assert not cube.collides_at(I, cube, there)
    assert cube.within_distance_at(I, cube, there, 0.5)
    assert not cube.within_distance_at(I, cube, there, np.nextafter(0.5, 0))
    d = cube.distance_at(I, cube, there)
    assert abs(d.distance - 0.5) <= d.error_bound < 1e-12
    assert np.isclose(np.linalg.norm(d.witness_a - d.witness_b), d.distance)
    assert d.triangles is not None and float(d) == d.distance
    hits = cube.collides_batch(cube, np.stack([I, I]), np.stack([there, I]))
    assert hits.dtype == np.bool_ and hits.tolist() == [False, True]


def test_touching_is_exact(cube):
    assert cube.collides_at(I, cube, translation(1.0))  # face to face
    assert not cube.collides_at(I, cube, translation(np.nextafter(1.0, 2.0)))
    assert cube.contact_class_at(I, cube, translation(1.0)) == "touching"
    assert cube.contact_class_at(I, cube, translation(0.5)) == "penetrating"
    assert cube.contact_class_at(I, cube, translation(1.5)) == "disjoint"
    small = cc.Collider.cuboid(np.full(3, 0.25), np.full(3, 0.75))
    assert cube.contact_class(small) == "b_inside_a"
    assert not cube.collides(small) and cube.collides_solid(small)


def test_every_question_answers(cube, bunny):
    t = translation(0.5)
    assert cube.intersecting_pairs_at(I, cube, t).shape[1] == 2
    assert cube.intersecting_pairs(cube).dtype == np.int64
    assert cube.pairs_within_distance_at(I, cube, translation(1.25), 0.25).shape[0] > 0
    assert cube.pairs_within_distance(cube, 0.0).shape[0] > 0
    contacts = cube.contacts_at(I, cube, translation(1.0))
    assert contacts and {k for _, k, _ in contacts} <= {"point", "segment", "polygon"}
    (i, j), kind, pts = contacts[0]
    assert pts.shape[1] == 3
    assert cube.contains_point(np.full(3, 0.5)) and not cube.contains_point(np.full(3, 2.0))
    assert cube.contains_point_at(translation(5.0), np.array([5.5, 0.5, 0.5]))
    assert cube.segment_hits(np.array([0.3, 0.6, -1.0]), np.array([0.3, 0.6, 2.0])).size == 2
    assert cube.segment_hits_at(translation(5.0), np.array([5.3, 0.6, -1.0]), np.array([5.3, 0.6, 2.0])).size == 2
    tri = np.array([[0.5, 0.5, -1.0], [0.6, 0.5, 2.0], [0.5, 0.6, 2.0]])
    assert cube.triangle_hits(tri).size >= 2 and cube.triangle_hits_at(I, tri).size >= 2
    assert cube.sphere_hits(np.full(3, 0.5), 0.5).size > 0
    assert cube.sphere_hits(np.full(3, 0.5), 0.1).size == 0
    assert cube.ball_hits(np.full(3, 0.5), 0.1).size == 0  # inside, away from the surface
    assert cube.sphere_hits_at(I, np.full(3, 0.5), 0.5).size > 0
    assert cube.ball_hits_at(I, np.full(3, 1.0), 0.1).size > 0
    assert not cube.self_intersects() and cube.self_intersections().shape == (0, 2)
    d2, wa, wb, tris = cube.exact_distance(placed(cube, translation(1.5)))
    from fractions import Fraction

    assert d2 == Fraction(1, 4) and all(isinstance(x, Fraction) for x in wa + wb)
    assert not bunny.self_intersects() or bunny.self_intersections().shape[0] > 0


def test_self_intersection_found():
    # two triangles crossing each other, sharing no vertex
    v = np.array([[0, 0, 0], [2, 0, 0], [0, 2, 0], [0.5, 0.5, -1], [0.6, 0.5, 1], [0.5, 0.6, 1]], float)
    c = cc.Collider(v, np.array([[0, 1, 2], [3, 4, 5]]))
    assert c.self_intersects()
    assert c.self_intersections().tolist() == [[0, 1]]


# ---------------------------------------------------------------- agreement


def test_batch_equals_single_calls(bunny):
    pa, pb = random_poses(64, seed=1, spread=6.0), random_poses(64, seed=2, spread=6.0)
    single = [bunny.collides_at(a, bunny, b) for a, b in zip(pa, pb)]
    assert bunny.collides_batch(bunny, pa, pb).tolist() == single
    assert 0 < sum(single) < len(single)
    solid = [bunny.collides_solid_at(a, bunny, b) for a, b in zip(pa, pb)]
    assert bunny.collides_solid_batch(bunny, pa, pb).tolist() == solid
    within = [bunny.within_distance_at(a, bunny, b, 0.01) for a, b in zip(pa, pb)]
    assert bunny.within_distance_batch(bunny, pa, pb, 0.01).tolist() == within
    pairs = bunny.intersecting_pairs_batch(bunny, pa[:8], pb[:8])
    for k in range(8):
        assert np.array_equal(pairs[k], bunny.intersecting_pairs_at(pa[k], bunny, pb[k]))
    db = bunny.distance_batch(bunny, pa[:8], pb[:8])
    assert len(db) == 8 and db.witness_a.shape == (8, 3) and db.triangles.shape == (8, 2)
    for k in range(8):
        d = bunny.distance_at(pa[k], bunny, pb[k])
        assert db.distance[k] == d.distance and db.error_bound[k] == d.error_bound
    # one (4, 4) pose is used for every query
    assert bunny.collides_batch(bunny, I, pb).tolist() == [bunny.collides_at(I, bunny, b) for b in pb]


def test_modes_agree(bunny):
    brute = bunny.with_mode("brute")
    pa, pb = random_poses(16, seed=3, spread=6.0), random_poses(16, seed=4, spread=6.0)
    assert bunny.collides_batch(bunny, pa, pb).tolist() == brute.collides_batch(brute, pa, pb).tolist()


def test_poses_agree_with_meshes_placed_first(bunny):
    for k, (a, b) in enumerate(zip(random_poses(12, 5, 6.0), random_poses(12, 6, 6.0))):
        assert bunny.collides_at(a, bunny, b) == placed(bunny, a).collides(placed(bunny, b)), k


def test_rotation_about_z(cube):
    # a cube turned 45 degrees about z around its centre, centred at x = 1.6: its corner
    # reaches x = 1.6 - sqrt(2)/2 < 1, into the unit cube; 0.5 further it does not
    centre = np.array([0.5, 0.5, 0.0])
    turn = rotation_z(45.0, t=(1.6, 0.5, 0.0)) @ translation(*-centre)
    assert 1.6 - np.sqrt(0.5) < 1.0 and cube.collides_at(I, cube, turn)
    assert not cube.collides_at(I, cube, translation(0.5) @ turn)


# ---------------------------------------------------------------- pickling and threads


def test_pickle_round_trip(bunny):
    for c in (bunny, bunny.with_mode("brute")):
        back = pickle.loads(pickle.dumps(c))
        assert back.mode == c.mode and back.num_triangles == c.num_triangles
        assert np.array_equal(back.vertices, c.vertices) and np.array_equal(back.faces, c.faces)
        pa, pb = random_poses(32, 7, 6.0), random_poses(32, 8, 6.0)
        assert back.collides_batch(c, pa, pb).tolist() == c.collides_batch(c, pa, pb).tolist()
        assert back.distance_at(pa[0], c, pb[0]).distance == c.distance_at(pa[0], c, pb[0]).distance


def test_corrupt_pickle_is_an_error(cube):
    data = cube.to_bytes()
    with pytest.raises(cc.CgaError, match="truncated"):
        cc.Collider.from_bytes(data[:20])
    with pytest.raises(cc.CgaError, match="but 455 follow"):
        cc.Collider.from_bytes(data[:-1])
    with pytest.raises(cc.CgaError, match="not a serialized collider"):
        cc.Collider.from_bytes(b"x" * len(data))
    with pytest.raises(cc.CgaError, match="follow the header"):
        cc.Collider.from_bytes(data + b"\0")
    for i in range(0, len(data), 7):  # a flipped byte is refused or read as some valid collider
        bad = bytearray(data)
        bad[i] ^= 0xFF
        try:
            cc.Collider.from_bytes(bytes(bad))
        except cc.CgaError:
            pass


def test_bytes_keep_the_tree_and_skip_the_build(bunny):
    import time

    data = bunny.to_bytes()
    back = cc.Collider.from_bytes(data)
    assert back.to_bytes() == data
    t = time.perf_counter()
    for _ in range(3):
        cc.Collider.from_bytes(data)
    read = time.perf_counter() - t
    t = time.perf_counter()
    for _ in range(3):
        cc.Collider(bunny.vertices, bunny.faces)
    build = time.perf_counter() - t
    print(f"from_bytes {read / 3 * 1e3:.2f} ms, build {build / 3 * 1e3:.2f} ms")


def test_threads_share_colliders(bunny):
    pa, pb = random_poses(64, 9, 6.0), random_poses(64, 10, 6.0)
    want = bunny.collides_batch(bunny, pa, pb).tolist()
    got = {}

    def work(k):
        got[k] = [bunny.collides_at(a, bunny, b) for a, b in zip(pa, pb)]

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    assert all(got[k] == want for k in range(4))
