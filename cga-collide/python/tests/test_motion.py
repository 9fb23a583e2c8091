"""cga_collide.motion and Collider.contacts_during: continuous collision from Python, with the
Rust names; answers checked against each other (batch and single calls, the rigid motion of two
colliders and the primitive tests of its pairs) and bad inputs refused with clear errors."""

import itertools

import numpy as np
import pytest

import cga_collide as cc
from cga_collide import motion
from conftest import translation

STILL_FACE = np.array([[[0.0, 0, 0]] * 2, [[1.0, 0, 0]] * 2, [[0.0, 1, 0]] * 2])  # (3, 2, 3)
FALLING = np.array([[0.2, 0.2, 1.0], [0.2, 0.2, -1.0]])  # (2, 3): through z = 0 at t = 0.5


def motion_of(start: np.ndarray, end: np.ndarray) -> np.ndarray:
    return np.stack([start, end])


# ---------------------------------------------------------------- primitives


def test_falling_vertex_through_a_triangle():
    assert motion.vertex_face_touch(FALLING, STILL_FACE)
    t = motion.vertex_face_first_contact(FALLING, STILL_FACE, 1e-9)
    assert isinstance(t, motion.ContactTime)
    assert t.lo <= 0.5 <= t.hi and t.width == t.hi - t.lo <= 1e-9
    assert t.is_exact == (t.lo == t.hi == 0.5)
    assert t.safe_time() is not None and t.safe_time() < 0.5
    narrowest = motion.vertex_face_first_contact(FALLING, STILL_FACE, 0.0)
    assert narrowest.lo <= 0.5 <= narrowest.hi and narrowest.width <= t.width
    assert "ContactTime(lo=" in repr(t)
    # Beside the triangle: never.
    beside = FALLING + np.array([2.0, 0, 0])
    assert not motion.vertex_face_touch(beside, STILL_FACE)
    assert motion.vertex_face_first_contact(beside, STILL_FACE) is None


def test_contact_at_the_start_has_no_safe_time():
    on_face = np.array([[0.2, 0.2, 0.0], [0.2, 0.2, 1.0]])
    t = motion.vertex_face_first_contact(on_face, STILL_FACE)
    assert t.lo == t.hi == 0.0 and t.is_exact and t.safe_time() is None


def test_crossing_edges():
    a = np.array([[[-1.0, 0, 1], [-1.0, 0, -1]], [[1.0, 0, 1], [1.0, 0, -1]]])  # falls along x
    b = np.array([[[0.0, -1, 0]] * 2, [[0.0, 1, 0]] * 2])  # still, along y
    assert motion.edge_edge_touch(a, b)
    t = motion.edge_edge_first_contact(a, b, 1e-12)
    assert t.lo <= 0.5 <= t.hi and t.safe_time() < 0.5
    assert not motion.edge_edge_touch(a + np.array([0, 0, 5.0]), b)
    assert motion.edge_edge_first_contact(a + np.array([0, 0, 5.0]), b) is None


def random_queries(k: int, seed: int) -> np.ndarray:
    """k (4, 2, 3) queries: a point falling through z = 0 and a jittered triangle near it,
    about half of them touching."""
    rng = np.random.default_rng(seed)
    q = rng.uniform(-1, 1, size=(k, 4, 2, 3))
    q[:, 0, 0, 2] = rng.uniform(0.1, 1, size=k)
    q[:, 0, 1, 2] = rng.uniform(-1, -0.1, size=k)
    q[:, 1:, :, 2] *= 0.05
    return q


def test_batches_equal_single_calls():
    q = random_queries(300, 7)
    vf = motion.vertex_face_touch_batch(q)
    ee = motion.edge_edge_touch_batch(q)
    assert vf.shape == ee.shape == (300,) and vf.dtype == ee.dtype == np.bool_
    assert 0 < vf.sum() < 300
    vf_t = motion.vertex_face_first_contact_batch(q, 1e-9)
    ee_t = motion.edge_edge_first_contact_batch(q, 1e-9)
    assert vf_t.shape == ee_t.shape == (300, 2) and vf_t.dtype == np.float64
    for k in range(300):
        assert vf[k] == motion.vertex_face_touch(q[k, 0], q[k, 1:])
        assert ee[k] == motion.edge_edge_touch(q[k, :2], q[k, 2:])
        for batch_t, single in (
            (vf_t[k], motion.vertex_face_first_contact(q[k, 0], q[k, 1:], 1e-9)),
            (ee_t[k], motion.edge_edge_first_contact(q[k, :2], q[k, 2:], 1e-9)),
        ):
            if single is None:
                assert np.isnan(batch_t).all()
            else:
                assert (batch_t[0], batch_t[1]) == (single.lo, single.hi)
        # The first contact exists exactly when they touch.
        assert vf[k] == (not np.isnan(vf_t[k, 0]))
        assert ee[k] == (not np.isnan(ee_t[k, 0]))
    empty = np.zeros((0, 4, 2, 3))
    assert motion.vertex_face_touch_batch(empty).shape == (0,)
    assert motion.edge_edge_first_contact_batch(empty).shape == (0, 2)


@pytest.mark.parametrize(
    "call, error, words",
    [
        (lambda: motion.vertex_face_touch(FALLING[0], STILL_FACE), cc.CgaError, r"vertex: expected an array of shape \(2, 3\)"),
        (lambda: motion.vertex_face_touch(FALLING, STILL_FACE[:2]), cc.CgaError, r"face: expected an array of shape \(3, 2, 3\)"),
        (lambda: motion.vertex_face_touch(FALLING.astype(np.complex128), STILL_FACE), cc.CgaError, "vertex: .*complex"),
        (lambda: motion.vertex_face_touch([["a", "b", "c"]] * 2, STILL_FACE), cc.CgaError, "vertex: .*not an array of real numbers"),
        (lambda: motion.vertex_face_touch(np.array([[0.2, 0.2, np.nan], [0.2, 0.2, -1]]), STILL_FACE), cc.CgaError, "vertex.start"),
        (lambda: motion.vertex_face_first_contact(FALLING, np.where(STILL_FACE == 1, np.inf, STILL_FACE)), cc.CgaError, "face"),
        (lambda: motion.edge_edge_touch(np.zeros((2, 3)), np.zeros((2, 2, 3))), cc.CgaError, r"a: expected an array of shape \(2, 2, 3\)"),
        (lambda: motion.edge_edge_first_contact(np.zeros((2, 2, 3)), np.zeros((2, 2, 3), bool)), cc.CgaError, "b: .*booleans"),
        (lambda: motion.vertex_face_touch_batch(np.zeros((5, 3, 2, 3))), cc.CgaError, r"points: expected an array of shape \(k, 4, 2, 3\)"),
        (lambda: motion.edge_edge_touch_batch(np.zeros((5, 4, 2, 3), object)), cc.CgaError, "points: .*object"),
    ],
)
def test_bad_primitive_inputs(call, error, words):
    with pytest.raises(error, match=words):
        call()


def test_non_finite_batch_item_is_named():
    q = random_queries(5, 1)
    q[3, 2, 1, 0] = np.nan
    for f in (motion.vertex_face_touch_batch, motion.edge_edge_touch_batch, motion.vertex_face_first_contact_batch):
        with pytest.raises(cc.CgaError, match=r"points\[3\]"):
            f(q)


# ---------------------------------------------------------------- two moving colliders


@pytest.fixture(scope="module")
def wall_and_bullet():
    return cc.Collider.cuboid(np.zeros(3), np.ones(3)), cc.Collider.cuboid(np.zeros(3), np.full(3, 0.1))


def edges_of(faces: np.ndarray):
    return sorted({tuple(sorted((int(t[i]), int(t[(i + 1) % 3])))) for t in faces for i in range(3)})


def test_tunnelling_cube_is_caught(wall_and_bullet):
    wall, bullet = wall_and_bullet
    before, after = translation(-1.0, 0.45, 0.45), translation(2.0, 0.45, 0.45)
    still = motion_of(np.eye(4), np.eye(4))
    assert not bullet.collides_at(before, wall, np.eye(4))
    assert not bullet.collides_at(after, wall, np.eye(4))
    hit = bullet.contacts_during(motion_of(before, after), wall, still, 1e-9)
    assert isinstance(hit, motion.MotionContacts) and len(hit) == len(hit.pairs) > 0
    first = hit.first_contact
    assert first.lo <= 0.3 <= first.hi and first.safe_time() < 0.3  # front face reaches x = 0
    assert set(hit.first_pairs) <= set(hit.pairs) and hit.first_pairs
    kinds = {p[0] for p in hit.pairs}
    assert kinds <= {"vertex_face", "face_vertex", "edge_edge"} and "edge_edge" in kinds
    assert hit.pairs == sorted(hit.pairs, key=lambda p: (["vertex_face", "face_vertex", "edge_edge"].index(p[0]), p[1:]))
    assert hit.vertex_face.shape[1:] == (2,) and hit.face_vertex.shape[1:] == (2,)
    assert hit.edge_edge.shape[1:] == (2, 2) and hit.edge_edge.dtype == np.int64
    assert len(hit.vertex_face) + len(hit.face_vertex) + len(hit.edge_edge) == len(hit.pairs)
    assert "MotionContacts(pairs=" in repr(hit)

    # Every pair, and only those, touches by the primitive tests (translations place vertices
    # exactly, so numpy's placed positions are the library's).
    va = np.stack([bullet.vertices + before[:3, 3], bullet.vertices + after[:3, 3]], axis=1)  # (n, 2, 3)
    vb = np.stack([wall.vertices, wall.vertices], axis=1)
    fa, fb = bullet.faces, wall.faces
    expected = []
    for v, f in itertools.product(range(len(va)), range(len(fb))):
        expected.append((("vertex_face", v, f), np.concatenate([va[v][None], vb[fb[f]]])))
    for f, v in itertools.product(range(len(fa)), range(len(vb))):
        expected.append((("face_vertex", f, v), np.concatenate([vb[v][None], va[fa[f]]])))
    for ea, eb in itertools.product(edges_of(fa), edges_of(fb)):
        expected.append((("edge_edge", ea, eb), np.concatenate([va[list(ea)], vb[list(eb)]])))
    vf_like = [i for i, (p, _) in enumerate(expected) if p[0] != "edge_edge"]
    ee_like = [i for i, (p, _) in enumerate(expected) if p[0] == "edge_edge"]
    points = np.stack([q for _, q in expected])
    touch = np.zeros(len(expected), bool)
    touch[vf_like] = motion.vertex_face_touch_batch(points[vf_like])
    touch[ee_like] = motion.edge_edge_touch_batch(points[ee_like])
    assert {p for (p, _), t in zip(expected, touch) if t} == set(hit.pairs)


def test_no_motion_no_contact_and_symmetry(wall_and_bullet):
    wall, bullet = wall_and_bullet
    far = motion_of(translation(5.0), translation(6.0))
    still = motion_of(np.eye(4), np.eye(4))
    none = bullet.contacts_during(far, wall, still)
    assert none.pairs == [] and none.first_contact is None and none.first_pairs == []
    assert none.vertex_face.shape == (0, 2) and none.edge_edge.shape == (0, 2, 2)
    # The same motion seen from the wall: face_vertex and vertex_face swap, same first contact.
    path = motion_of(translation(-1.0, 0.45, 0.45), translation(2.0, 0.45, 0.45))
    ab = bullet.contacts_during(path, wall, still, 0.0)
    ba = wall.contacts_during(still, bullet, path, 0.0)
    assert ab.first_contact == ba.first_contact
    assert sorted(map(tuple, ab.vertex_face)) == sorted(map(tuple, ba.face_vertex[:, ::-1]))
    assert sorted(map(tuple, ab.face_vertex)) == sorted(map(tuple, ba.vertex_face[:, ::-1]))
    assert sorted(map(tuple, ab.edge_edge.reshape(-1, 4))) == sorted(map(tuple, ba.edge_edge[:, ::-1].reshape(-1, 4)))


@pytest.mark.parametrize(
    "poses, other_poses, error, words",
    [
        (np.eye(4), None, cc.CgaError, r"poses: expected an array of shape \(2, 4, 4\)"),
        (np.zeros((3, 4, 4)), None, cc.CgaError, r"poses: expected an array of shape \(2, 4, 4\)"),
        (np.stack([np.eye(4)] * 2).astype(np.complex64), None, cc.CgaError, "poses: .*complex"),
        (None, np.stack([np.eye(4), np.diag([2.0, 1, 1, 1])]), cc.CgaError, r"other_poses\[1\]: the upper-left 3x3 block is not a rotation"),
        (np.stack([np.full((4, 4), np.nan), np.eye(4)]), None, cc.CgaError, r"poses\[0\]: entry \[0, 0\] is not finite"),
    ],
)
def test_bad_motions(wall_and_bullet, poses, other_poses, error, words):
    wall, bullet = wall_and_bullet
    still = motion_of(np.eye(4), np.eye(4))
    with pytest.raises(error, match=words):
        bullet.contacts_during(still if poses is None else poses, wall, still if other_poses is None else other_poses)


# ---------------------------------------------------------------- a deforming mesh


def two_triangles():
    start = np.array(
        [[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.2, 0.2, 1], [0.3, 0.2, 1], [0.2, 0.3, 1]], dtype=np.float64
    )
    faces = np.array([[0, 1, 2], [3, 4, 5]])
    end = start.copy()
    end[3:, 2] -= 2.0  # the second triangle falls through the first
    return start, faces, end


def test_step_self_contacts_on_two_triangles():
    start, faces, end = two_triangles()
    c = motion.step_self_contacts(start, faces, end, 1e-9)
    assert isinstance(c, motion.StepContacts)
    assert c.vertex_face.dtype == np.int64
    assert c.vertex_face.tolist() == [[3, 0], [4, 0], [5, 0]]
    assert c.edge_edge.shape == (0, 2, 2)  # the small triangle falls inside the big one
    assert c.first_contact.lo <= 0.5 <= c.first_contact.hi and c.first_contact.safe_time() < 0.5
    assert c.vertex_face_candidates >= 3 and c.edge_edge_candidates >= 0
    assert "StepContacts(vertex_face=3" in repr(c)
    # Nothing moves: nothing touches.
    still = motion.step_self_contacts(start, faces, start)
    assert still.vertex_face.shape == (0, 2) and still.first_contact is None
    # Each pair agrees with the primitive test.
    tracks = np.stack([start, end], axis=1)
    for v, f in c.vertex_face:
        assert motion.vertex_face_touch(tracks[v], tracks[faces[f]])


def test_step_edges_cross():
    # A stick-like thin triangle swept across another's edge gives edge-edge contacts.
    start = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0.5, -1, 1], [0.5, 2, 1], [0.6, 2, 1]], dtype=np.float64)
    faces = np.array([[0, 1, 2], [3, 4, 5]])
    end = start.copy()
    end[3:, 2] -= 2.0
    c = motion.step_self_contacts(start, faces, end)
    assert len(c.edge_edge) > 0 and c.edge_edge.shape[1:] == (2, 2)
    tracks = np.stack([start, end], axis=1)
    for a, b in c.edge_edge:
        assert tuple(a) < tuple(b) and a[0] < a[1] and b[0] < b[1]
        assert motion.edge_edge_touch(tracks[a], tracks[b])


@pytest.mark.parametrize(
    "change, error, words",
    [
        (lambda s, f, e: (s, f, e[:5]), cc.CgaError, "6"),
        (lambda s, f, e: (s, f, e.astype(np.complex128)), cc.CgaError, "vertices_end: .*complex"),
        (lambda s, f, e: (s, f, np.where(e == 1.0, np.nan, e)), cc.CgaError, "not finite|NaN|non-finite"),
        (lambda s, f, e: (s, f + 3, e), cc.CgaError, "vertex index"),
        (lambda s, f, e: (s[:, :2].copy(), f, e), cc.CgaError, r"vertices_start: expected an array of shape \(k, 3\)"),
        (lambda s, f, e: (s, f.astype(np.float64), e), cc.CgaError, "faces: expected integers"),
    ],
)
def test_bad_steps(change, error, words):
    with pytest.raises(error, match=words):
        motion.step_self_contacts(*change(*two_triangles()))
