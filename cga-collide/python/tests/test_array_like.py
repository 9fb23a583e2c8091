"""What numpy users pass: every array-like that float64 holds exactly gives the answers of the
float64 arrays; everything else is a CgaError naming the argument. Also the scalars that may not
be NaN (points, tolerances, distances) and `pose_from_degrees`."""

import importlib.util

import numpy as np
import pytest

import cga_collide as cc
from cga_collide import motion
from conftest import REPO


@pytest.fixture(scope="module")
def cube():
    return cc.Collider.cuboid(np.zeros(3), np.ones(3))


def nested_tuple(x):
    return tuple(map(nested_tuple, x)) if isinstance(x, list) else x


def exact_forms(a: np.ndarray):
    """``a`` (float64, values exact in float32) as the other things a numpy user may pass."""
    fortran = np.asfortranarray(a)
    doubled = np.repeat(a, 2, axis=-1)
    strided = doubled[..., ::2]  # a non-contiguous view with the same values
    assert not strided.flags.c_contiguous and np.array_equal(strided, a)
    return {
        "list": a.tolist(),
        "tuple": nested_tuple(a.tolist()),
        "float32": a.astype(np.float32),
        "float16": a.astype(np.float16),
        "fortran": fortran,
        "strided": strided,
        "big-endian": a.astype(">f8"),
    }


def integer_forms(a: np.ndarray):
    assert np.array_equal(a, np.round(a))
    return {dtype: a.astype(dtype) for dtype in (np.int8, np.int32, np.int64, np.uint16, np.uint64)} | {
        "python ints": a.astype(np.int64).tolist()
    }


# Poses whose entries are exact in float16: quarter turns and small translations.
QUARTER_TURNS = np.array(
    [
        [[0.0, -1, 0, 1.5], [1, 0, 0, 0.25], [0, 0, 1, -0.5], [0, 0, 0, 1]],
        [[1.0, 0, 0, 0.75], [0, 0, -1, 0], [0, 1, 0, 0.5], [0, 0, 0, 1]],
        [[0.0, 0, 1, 2.0], [0, 1, 0, 0], [-1, 0, 0, 0], [0, 0, 0, 1]],
    ]
)


@pytest.mark.parametrize("form", list(exact_forms(QUARTER_TURNS[0])))
def test_poses_in_every_exact_form(cube, form):
    for pose in QUARTER_TURNS:
        want = (cube.collides_at(np.eye(4), cube, pose), cube.distance_at(pose, cube, np.eye(4)).distance)
        given = exact_forms(pose)[form]
        got = (cube.collides_at(np.eye(4), cube, given), cube.distance_at(given, cube, np.eye(4)).distance)
        assert got == want
    poses = exact_forms(QUARTER_TURNS)[form]
    assert np.array_equal(cube.collides_batch(cube, poses, np.eye(4)), cube.collides_batch(cube, QUARTER_TURNS, np.eye(4)))


def test_integer_poses(cube):
    pose = np.array([[0, -1, 0, 1], [1, 0, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], dtype=np.float64)
    want = cube.intersecting_pairs_at(pose, cube, np.eye(4))
    for name, given in integer_forms(pose).items():
        if name == np.uint64 or name == np.uint16:
            continue  # -1 has no unsigned form
        assert np.array_equal(cube.intersecting_pairs_at(given, cube, np.eye(4)), want), name


def test_meshes_in_every_exact_form(cube):
    vertices, faces = cube.vertices * 0.5, cube.faces
    want = cc.Collider(vertices, faces)
    for name, v in exact_forms(vertices).items():
        for fname, f in integer_forms(faces).items():
            c = cc.Collider(v, f)
            assert np.array_equal(c.vertices, want.vertices), (name, fname)
            assert np.array_equal(c.faces, want.faces), (name, fname)
    assert cc.Collider(cube.vertices.astype(np.int32), faces.tolist()).collides(cube)


def test_points_and_shapes_in_every_exact_form(cube):
    p, q = np.array([0.5, 0.5, -1.0]), np.array([0.5, 0.5, 2.0])
    tri = np.array([[0.5, 0.5, -1.0], [0.5, 2.0, 0.5], [2.0, 0.5, 0.5]])
    want = (cube.segment_hits(p, q), cube.triangle_hits(tri), cube.contains_point(p), cube.ball_hits(p, 1.5))
    for name in exact_forms(p):
        pf, qf, tf = (exact_forms(x)[name] for x in (p, q, tri))
        got = (cube.segment_hits(pf, qf), cube.triangle_hits(tf), cube.contains_point(pf), cube.ball_hits(pf, 1.5))
        for g, w in zip(got, want):
            assert np.array_equal(g, w), name
    assert cube.contains_point((1, 1, 1)) and not cube.contains_point([2, 0, 0])
    assert cc.Collider.cuboid([0, 0, 0], (1, 1, 1)).collides(cube)


def test_motion_in_every_exact_form():
    queries = np.array(
        [
            [[[0.25, 0.25, 1.0], [0.25, 0.25, -1.0]], [[0, 0, 0]] * 2, [[1, 0, 0]] * 2, [[0, 1, 0]] * 2],
            [[[2.0, 0.25, 1.0], [2.0, 0.25, -1.0]], [[0, 0, 0]] * 2, [[1, 0, 0]] * 2, [[0, 1, 0]] * 2],
        ]
    )
    want = motion.vertex_face_first_contact_batch(queries, 0.0)
    for name, given in exact_forms(queries).items():
        got = motion.vertex_face_first_contact_batch(given, 0.0)
        assert np.array_equal(got, want, equal_nan=True), name
        assert motion.vertex_face_touch(given[0][0], given[0][1:]), name
    assert motion.vertex_face_touch(queries[0, 0].tolist(), queries[0, 1:].astype(np.float32))


@pytest.mark.parametrize(
    "given, words",
    [
        (np.eye(4, dtype=np.complex128), "complex"),
        (np.eye(4).astype(object), "not an array of real numbers"),
        (np.eye(4).astype(str), "not an array of real numbers"),
        ([[1, 0, 0, 0], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, "1"]], "not an array of real numbers"),
        (np.eye(4, dtype=bool), "booleans"),
        ([[1, 0, 0, 2**53 + 1], [0, 1, 0, 0], [0, 0, 1, 0], [0, 0, 0, 1]], r"entry \[0, 3\] = 9007199254740993 is beyond 2\^53"),
        (np.full((4, 4), 2**60, dtype=np.uint64), r"entry \[0, 0\] = 1152921504606846976 is beyond 2\^53"),
        ([[1, 0, 0], [0, 1, 0]], "expected an array of numbers|shape"),
        (object(), "not an array of real numbers"),
        ("eye", "not an array of real numbers"),
    ],
)
def test_lossy_or_ambiguous_input_names_the_argument(cube, given, words):
    with pytest.raises(cc.CgaError, match=f"^pose_b: .*({words})"):
        cube.collides_at(np.eye(4), cube, given)
    with pytest.raises(cc.CgaError, match=f"^poses_a: .*({words})"):
        cube.collides_batch(cube, given, np.eye(4))
    assert issubclass(cc.CgaError, ValueError)


def test_lossy_input_everywhere_names_the_argument(cube):
    bad = np.zeros(3, dtype=np.complex128)
    with pytest.raises(cc.CgaError, match="^p: "):
        cube.contains_point(bad)
    with pytest.raises(cc.CgaError, match="^centre: "):
        cube.sphere_hits(bad, 1.0)
    with pytest.raises(cc.CgaError, match="^q: "):
        cube.segment_hits(np.zeros(3), ["x", "y", "z"])
    with pytest.raises(cc.CgaError, match="^triangle_corners: "):
        cube.triangle_hits(np.zeros((3, 3), dtype=object))
    with pytest.raises(cc.CgaError, match="^vertices: "):
        cc.Collider(np.zeros((3, 3), dtype=np.complex64), [[0, 1, 2]])
    with pytest.raises(cc.CgaError, match="^faces: "):
        cc.Collider(np.eye(3), [[0, 1, 2.5]])
    with pytest.raises(cc.CgaError, match="^degrees: "):
        cc.pose_from_degrees([0, 0, 1j])
    with pytest.raises(cc.CgaError, match="^vertex: "):
        motion.vertex_face_touch(np.zeros((2, 3), dtype=bool), np.zeros((3, 2, 3)))
    # a long double beyond float64's precision
    if np.finfo(np.longdouble).nmant > 52:
        fine = np.eye(4, dtype=np.longdouble)
        assert cube.collides_at(fine, cube, np.eye(4))
        fine[0, 3] = np.longdouble(1) + np.finfo(np.longdouble).eps
        with pytest.raises(cc.CgaError, match="^pose_a: .*round"):
            cube.collides_at(fine, cube, np.eye(4))


# ---------------------------------------------------------------- NaN where it is not allowed


@pytest.mark.parametrize("p", [[np.nan, 0.5, 0.5], [0.5, np.inf, 0.5]])
def test_contains_point_refuses_a_non_finite_point(cube, p):
    with pytest.raises(cc.CgaError, match=r"^p: coordinate \d is not finite"):
        cube.contains_point(p)
    with pytest.raises(cc.CgaError, match=r"^p: coordinate \d is not finite"):
        cube.contains_point_at(np.eye(4), np.array(p))


FALLING = np.array([[0.2, 0.2, 1.0], [0.2, 0.2, -1.0]])
STILL_FACE = np.array([[[0.0, 0, 0]] * 2, [[1.0, 0, 0]] * 2, [[0.0, 1, 0]] * 2])
EDGE_A = np.array([[[-1.0, 0, 1], [-1.0, 0, -1]], [[1.0, 0, 1], [1.0, 0, -1]]])
EDGE_B = np.array([[[0.0, -1, 0]] * 2, [[0.0, 1, 0]] * 2])
QUERIES = np.stack([np.concatenate([FALLING[None], STILL_FACE])] * 3)


def tolerance_calls():
    cube = cc.Collider.cuboid(np.zeros(3), np.ones(3))
    still = np.stack([np.eye(4)] * 2)
    start = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0.0]])
    return {
        "vertex_face_first_contact": lambda t: motion.vertex_face_first_contact(FALLING, STILL_FACE, t),
        "edge_edge_first_contact": lambda t: motion.edge_edge_first_contact(EDGE_A, EDGE_B, t),
        "vertex_face_first_contact_batch": lambda t: motion.vertex_face_first_contact_batch(QUERIES, t),
        "edge_edge_first_contact_batch": lambda t: motion.edge_edge_first_contact_batch(QUERIES, t),
        "contacts_during": lambda t: cube.contacts_during(still, cube, still, t),
        "step_self_contacts": lambda t: motion.step_self_contacts(start, [[0, 1, 2]], start, t),
    }


@pytest.mark.parametrize("name", list(tolerance_calls()))
@pytest.mark.parametrize("tolerance", [np.nan, -1.0, -1e-300, np.inf])
def test_motion_tolerances_must_be_finite_and_not_negative(name, tolerance):
    call = tolerance_calls()[name]
    with pytest.raises(cc.CgaError, match="^tolerance: expected a finite width of time"):
        call(tolerance)
    call(0.0)
    call(1e-9)


def test_distance_bounds_may_not_be_nan(cube):
    for call in (
        lambda c: cube.within_distance(cube, c),
        lambda c: cube.within_distance_at(np.eye(4), cube, np.eye(4), c),
        lambda c: cube.within_distance_batch(cube, np.eye(4), np.eye(4), c),
        lambda c: cube.pairs_within_distance(cube, c),
        lambda c: cube.pairs_within_distance_at(np.eye(4), cube, np.eye(4), c),
        lambda c: cc.Scene().pairs_within_distance(c),
    ):
        with pytest.raises(cc.CgaError, match="^c: expected a distance, got NaN"):
            call(np.nan)
        call(0.5)


# ---------------------------------------------------------------- pose_from_degrees


def test_pose_from_degrees_is_the_rust_convention():
    # The Rust doc example: a quarter turn about z then a move along +x takes (1, 0, 0) to (1, 1, 0).
    pose = cc.pose_from_degrees([0.0, 0.0, 90.0], [1.0, 0.0, 0.0])
    assert pose.shape == (4, 4) and pose.dtype == np.float64
    assert np.allclose(pose @ [1.0, 0, 0, 1], [1.0, 1.0, 0, 1], atol=1e-15, rtol=0)
    assert np.array_equal(cc.pose_from_degrees((0, 0, 0)), np.eye(4))
    rng = np.random.default_rng(3)
    for ax, ay, az in rng.uniform(-180, 180, size=(20, 3)):
        a, b, c = np.radians([ax, ay, az])
        rx = np.array([[1, 0, 0], [0, np.cos(a), -np.sin(a)], [0, np.sin(a), np.cos(a)]])
        ry = np.array([[np.cos(b), 0, np.sin(b)], [0, 1, 0], [-np.sin(b), 0, np.cos(b)]])
        rz = np.array([[np.cos(c), -np.sin(c), 0], [np.sin(c), np.cos(c), 0], [0, 0, 1]])
        t = rng.uniform(-5, 5, 3)
        pose = cc.pose_from_degrees([ax, ay, az], t)
        assert np.allclose(pose[:3, :3], rz @ ry @ rx, atol=1e-14, rtol=0)
        assert np.array_equal(pose[:3, 3], t) and np.array_equal(pose[3], [0, 0, 0, 1])
    # Its poses are accepted by every query (a rotation within ROTATION_TOLERANCE).
    cube = cc.Collider.cuboid(np.zeros(3), np.ones(3))
    assert cube.collides_at(cc.pose_from_degrees([30, 40, 50], [0.5, 0, 0]), cube, np.eye(4))
    with pytest.raises(cc.CgaError, match=r"^translation: expected an array of shape \(3\)"):
        cc.pose_from_degrees([0, 0, 0], [1, 2])
    with pytest.raises(cc.CgaError, match=r"^degrees: coordinate 1 is not finite"):
        cc.pose_from_degrees([0, np.nan, 0])


def test_make_scene_writes_the_same_rotation():
    """`benches/make_scene.py` (standard library only, so it keeps its own formula) places
    objects with the rotation of `pose_from_degrees`."""
    path = REPO / "cga-collide" / "benches" / "make_scene.py"
    spec = importlib.util.spec_from_file_location("make_scene", path)
    make_scene = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(make_scene)
    for angles in np.random.default_rng(5).uniform(-180, 180, size=(20, 3)):
        want = cc.pose_from_degrees(angles)[:3, :3]
        assert np.allclose(make_scene.rotation(*angles), want, atol=1e-14, rtol=0)
