"""The solid primitives from Python: constructors (array-likes in, CgaError naming the argument
on bad input), properties, repr and pickling, the generic queries against the Rust answers
reached through other entry points, and poses and batches against placed single calls.

A pair whose exact engine the library does not have yet is skipped, never passed: the library
answers it with a ``CgaError`` saying "no exact ... test", or (while an engine is being written)
a Rust panic "not implemented"; the skip message names the pair."""

import itertools
import json
import pickle
import subprocess

import numpy as np
import pytest

import cga_collide as cc
from conftest import REPO, random_poses, translation
from test_rust_agreement import cga_binary

# ---------------------------------------------------------------------------------- helpers


def answer(f, *args):
    """``f(*args)``, or a skip when the library has no exact engine for the pair yet."""
    try:
        return f(*args)
    except cc.CgaError as e:
        if "no exact" in str(e):
            pytest.skip(f"engine not merged: {e}")
        raise
    except BaseException as e:  # a Rust panic is a PanicException, a BaseException
        if type(e).__name__ == "PanicException" and "not implemented" in str(e):
            pytest.skip(f"engine not merged: {e}")
        raise


def one_of_each():
    """A shape of every kind, each holding the origin and within distance 1 of it (the
    half-space holds x >= 0)."""
    return {
        "ball": cc.Ball([0.25, 0, 0], 0.5),
        "cuboid": cc.Cuboid([0, 0, 0], [[0.5, 0, 0], [0, 0.25, 0.25], [0, -0.25, 0.25]]),
        "capsule": cc.Capsule([-0.5, 0, 0], [0.5, 0, 0], 0.25),
        "cylinder": cc.Cylinder([0, 0, -0.5], [0, 0, 0.5], 0.5),
        "cone": cc.Cone([0, 0, 0.75], [0, 0, -0.25], 0.5),
        "halfspace": cc.HalfSpace([0, 0, 0], [-1, 0, 0]),
        "convex": cc.ConvexHull([[0, 0, 0], [0.5, 0, 0], [0, 0.5, 0], [0, 0, 0.5]]),
        "triangle": cc.Triangle([-0.5, -0.5, 0], [0.5, -0.5, 0], [0, 0.5, 0]),
        "segment": cc.Segment([0, -0.5, 0.5], [0, 0.5, -0.5]),
    }


KINDS = list(one_of_each())


def shape_of(kind):
    return one_of_each()[kind]


# ---------------------------------------------------------------------------------- constructors

POINT = np.array([0.5, -1.0, 2.0])
OTHER = np.array([1.5, 0.25, -2.0])
AXES = np.array([[1.0, 0.0, 0.0], [0.0, 0.5, 0.5], [0.0, -0.25, 0.25]])


def builders():
    """(class, arguments as float64 arrays, {property: expected value}) for every class."""
    return [
        (cc.Ball, (POINT, 0.75), {"centre": POINT, "radius": 0.75}),
        (cc.Cuboid, (POINT, AXES), {"centre": POINT, "half_axes": AXES}),
        (cc.Capsule, (POINT, OTHER, 0.5), {"a": POINT, "b": OTHER, "radius": 0.5}),
        (cc.Cylinder, (POINT, OTHER, 0.5), {"a": POINT, "b": OTHER, "radius": 0.5}),
        (cc.Cone, (POINT, OTHER, 0.5), {"apex": POINT, "base": OTHER, "radius": 0.5}),
        (cc.HalfSpace, (POINT, OTHER), {"point": POINT, "normal": OTHER}),
        (cc.ConvexHull, (np.stack([POINT, OTHER, AXES[1]]),), {"points": np.stack([POINT, OTHER, AXES[1]])}),
        (cc.Triangle, (POINT, OTHER, AXES[1]), {"vertices": np.stack([POINT, OTHER, AXES[1]])}),
        (cc.Segment, (POINT, OTHER), {"a": POINT, "b": OTHER}),
    ]


def forms(x):
    """``x`` as a list, a tuple, float32, Fortran order and a strided view (values exact in
    float32)."""
    if np.ndim(x) == 0:
        return {"float": float(x), "numpy float32": np.float32(x), "0-d array": np.array(x)}
    doubled = np.repeat(x, 2, axis=-1)
    return {
        "list": x.tolist(),
        "tuple": tuple(map(tuple, x)) if x.ndim == 2 else tuple(x),
        "float32": x.astype(np.float32),
        "fortran": np.asfortranarray(x),
        "strided": doubled[..., ::2],
    }


@pytest.mark.parametrize("cls, args, props", builders(), ids=lambda v: getattr(v, "__name__", ""))
def test_constructors_take_every_array_like(cls, args, props):
    reference = cls(*args)
    for form in forms(args[0]):
        built = cls(forms(args[0])[form], *args[1:])
        assert built == reference, form
    for name, want in props.items():
        got = getattr(reference, name)
        assert np.array_equal(got, want), name
        if isinstance(got, np.ndarray):
            assert got.dtype == np.float64
            got[...] = 7.0  # a fresh array: the shape is unchanged
            assert np.array_equal(getattr(reference, name), want)
    assert isinstance(reference, cc.Shape)


@pytest.mark.parametrize("cls, args, props", builders(), ids=lambda v: getattr(v, "__name__", ""))
def test_repr_and_pickle_give_the_same_shape(cls, args, props):
    s = cls(*args)
    assert eval(repr(s), {k: getattr(cc, k) for k in cc.__all__}) == s
    assert pickle.loads(pickle.dumps(s)) == s
    assert type(pickle.loads(pickle.dumps(s))) is cls


def test_a_radius_is_any_exact_number():
    ball = cc.Ball(POINT, 0.75)
    for r in forms(np.float64(0.75)).values():
        assert cc.Ball(POINT, r) == ball
    assert cc.Capsule(POINT, OTHER, 2) == cc.Capsule(POINT, OTHER, 2.0)
    with pytest.raises(cc.CgaError, match="radius: expected numbers that float64 holds exactly"):
        cc.Ball(POINT, np.longdouble(1) / 3)


def test_kinds_and_equality():
    shapes = one_of_each()
    for kind, s in shapes.items():
        assert s.kind == kind
    for a, b in itertools.combinations(shapes.values(), 2):
        assert a != b
    assert cc.Ball([0, 0, 0], 1) == cc.Ball((0, 0, 0), 1.0)
    assert cc.Ball([0, 0, 0], 1) != cc.Ball([0, 0, 0], 2)
    assert cc.Ball([0, 0, 0], 1) != "a ball"
    big = cc.ConvexHull(np.arange(60.0).reshape(20, 3))
    assert repr(big) == "ConvexHull(<20 points>)"
    with pytest.raises(TypeError):
        cc.Shape()


def test_axis_aligned_cuboid():
    box = cc.Cuboid.axis_aligned([1, 2, 3], (0.5, 0.25, 0))
    assert type(box) is cc.Cuboid
    assert np.array_equal(box.half_axes, np.diag([0.5, 0.25, 0.0]))
    assert box == cc.Cuboid([1, 2, 3], np.diag([0.5, 0.25, 0.0]))
    with pytest.raises(cc.CgaError, match="half extent is negative"):
        cc.Cuboid.axis_aligned([0, 0, 0], [1, -1, 1])
    with pytest.raises(cc.CgaError, match="half_extents"):
        cc.Cuboid.axis_aligned([0, 0, 0], [1, np.nan, 1])
    with pytest.raises(cc.CgaError, match="half_extents"):
        cc.Cuboid.axis_aligned([0, 0, 0], [1, 1])


def bad_inputs():
    """(class, arguments, text the CgaError must contain)."""
    nan, inf = float("nan"), float("inf")
    p, q = [0, 0, 0], [1, 0, 0]
    return [
        (cc.Ball, ([0, nan, 0], 1), "centre"),
        (cc.Ball, ([0, 0], 1), "centre"),
        (cc.Ball, (p, -1), "radius is negative"),
        (cc.Ball, (p, nan), "radius is not finite"),
        (cc.Ball, (p, inf), "radius is not finite"),
        (cc.Ball, (p, [1, 2]), "radius"),
        (cc.Ball, (p, True), "radius"),
        (cc.Cuboid, (p, np.eye(3)[:2]), "half_axes"),
        (cc.Cuboid, (p, [[1, 0, 0], [0, inf, 0], [0, 0, 1]]), "half_axes[1]"),
        (cc.Cuboid, ([inf, 0, 0], np.eye(3)), "centre"),
        (cc.Capsule, (p, [nan, 0, 0], 1), "`b`"),
        (cc.Capsule, (p, q, -0.5), "radius is negative"),
        (cc.Cylinder, ([inf, 0, 0], q, 1), "`a`"),
        (cc.Cylinder, (p, q, -1), "radius is negative"),
        (cc.Cylinder, (q, q, 1), "coincide"),
        (cc.Cone, ([0, 0, nan], q, 1), "`apex`"),
        (cc.Cone, (p, [0, 0, 0, 0], 1), "base"),
        (cc.Cone, (p, q, -2), "radius is negative"),
        (cc.Cone, (q, q, 1), "degenerate"),
        (cc.HalfSpace, (p, [0, 0, 0]), "normal is zero"),
        (cc.HalfSpace, (p, [0, inf, 0]), "`normal`"),
        (cc.HalfSpace, ([[0, 0, 0]], q), "point"),
        (cc.ConvexHull, (np.zeros((0, 3)),), "no points"),
        (cc.ConvexHull, ([[0, 0, 0], [1, 1, nan]],), "point 1"),
        (cc.ConvexHull, ([0, 0, 0],), "points"),
        (cc.Triangle, (p, q, [0, inf, 0]), "`c`"),
        (cc.Triangle, (p, q, "abc"), "c"),
        (cc.Segment, (p, [1 + 1j, 0, 0]), "b"),
        (cc.Segment, ([nan, 0, 0], q), "`a`"),
    ]


@pytest.mark.parametrize("cls, args, says", bad_inputs(), ids=lambda v: getattr(v, "__name__", None))
def test_bad_input_is_a_cga_error_naming_the_argument(cls, args, says):
    with pytest.raises(cc.CgaError) as e:
        cls(*args)
    assert says in str(e.value)


def test_placed_is_the_placement_rule():
    pose = cc.pose_from_degrees([0, 0, 90], [1, 2, 3])
    for kind, s in one_of_each().items():
        moved = s.placed(pose)
        assert type(moved) is type(s) and moved.kind == kind
        assert s.placed(np.eye(4)) == s
    ball = cc.Ball([1, 0, 0], 0.5).placed(pose)
    assert np.allclose(ball.centre, pose[:3, :3] @ [1, 0, 0] + pose[:3, 3], rtol=0, atol=1e-15)
    assert ball.radius == 0.5
    half = cc.HalfSpace([0, 0, 0], [0, 0, 2]).placed(translation(0, 0, 5))
    assert np.array_equal(half.point, [0, 0, 5]) and np.array_equal(half.normal, [0, 0, 2])
    with pytest.raises(cc.CgaError, match="pose"):
        cc.Ball([0, 0, 0], 1).placed(np.diag([2.0, 1, 1, 1]))
    with pytest.raises(cc.CgaError, match="beyond the limit"):
        cc.Capsule([0, 0, 0], [1, 0, 0], 1).placed(translation(1e300))


# ---------------------------------------------------------------------------------- query arguments


def test_query_arguments_are_checked():
    a, b = cc.Ball([0, 0, 0], 1), cc.Ball([3, 0, 0], 1)
    with pytest.raises(TypeError, match="b: expected a shape"):
        cc.intersects(a, 3)
    with pytest.raises(TypeError, match="a: expected a shape"):
        cc.distance(np.zeros(3), b)
    with pytest.raises(cc.CgaError, match="clearance"):
        cc.within_distance(a, b, float("nan"))
    with pytest.raises(cc.CgaError, match="clearance"):
        cc.within_distance(a, b, -1.0)
    with pytest.raises(cc.CgaError, match="pose_b"):
        cc.intersects_at(a, np.eye(4), b, np.eye(3))
    with pytest.raises(cc.CgaError, match="pose_a"):
        cc.distance_at(a, np.diag([1.0, 1, -1, 1]), b, np.eye(4))
    with pytest.raises(cc.CgaError, match=r"poses_a\[1\]"):
        cc.intersects_batch(a, b, np.stack([np.eye(4), 2 * np.eye(4)]), np.eye(4))
    with pytest.raises(cc.CgaError, match="same number"):
        cc.intersects_batch(a, b, random_poses(2, 1), random_poses(3, 2))
    # balls, triangles and segments take any finite value; the queries check the range
    with pytest.raises(cc.CgaError, match="`centre` has the value 1e200, beyond the limit"):
        cc.intersects(cc.Ball([1e200, 0, 0], 1), b)
    # a placed value out of range: the library's batch error names the item
    far = np.stack([np.eye(4), translation(1e300)])
    with pytest.raises(cc.CgaError, match="pose 1 of the batch"):
        cc.within_distance_batch(a, b, far, np.eye(4), 1.0)


# ---------------------------------------------------------------------------------- Rust answers

ULP = np.nextafter(2.0, 3.0)


def test_ball_pairs_are_exact_at_contact():
    unit = cc.Ball([0, 0, 0], 1)
    assert cc.intersects(unit, cc.Ball([2, 0, 0], 1))
    assert not cc.intersects(unit, cc.Ball([ULP, 0, 0], 1))
    assert cc.within_distance(unit, cc.Ball([3, 0, 0], 1), 1.0)
    assert not cc.within_distance(unit, cc.Ball([np.nextafter(3.0, 4.0), 0, 0], 1), 1.0)
    assert cc.intersects(unit, cc.Segment([1, -1, 0], [1, 1, 0]))
    assert not cc.intersects(unit, cc.Segment([np.nextafter(1.0, 2.0), -1, 0], [1, 1, 0]))
    d = cc.distance(unit, cc.Segment([3, -1, 0], [3, 1, 0]))
    assert abs(d.distance - 2.0) <= d.error_bound
    assert d.triangles is None
    assert np.allclose(d.witness_a, [1, 0, 0]) and np.allclose(d.witness_b, [3, 0, 0])


def random_triangle(rng, spread=1.0):
    return rng.uniform(-spread, spread, size=(3, 3))


def single(corners):
    return cc.Collider(corners, [[0, 1, 2]])


@pytest.mark.parametrize("seed", range(4))
def test_ball_segment_triangle_pairs_equal_the_colliders_answers(seed):
    """The generic entry points against the collider's own exact shape queries (Rust answers
    reached another way): a one-triangle mesh against segments, triangles and balls."""
    rng = np.random.default_rng(seed)
    for _ in range(60):
        t = random_triangle(rng)
        tri, mesh = cc.Triangle(*t), single(t)
        p, q = rng.uniform(-1, 1, size=(2, 3))
        assert cc.intersects(tri, cc.Segment(p, q)) == (len(mesh.segment_hits(p, q)) > 0)
        assert cc.intersects(cc.Segment(p, q), tri) == (len(mesh.segment_hits(p, q)) > 0)
        u = random_triangle(rng)
        assert cc.intersects(tri, cc.Triangle(*u)) == (len(mesh.triangle_hits(u)) > 0)
        c, r = rng.uniform(-1, 1, size=3), rng.uniform(0, 0.6)
        assert cc.intersects(cc.Ball(c, r), tri) == (len(mesh.ball_hits(c, r)) > 0)
        other = single(u)
        d, dm = cc.distance(tri, cc.Triangle(*u)), mesh.distance(other)
        assert abs(d.distance - dm.distance) <= d.error_bound + dm.error_bound
        for c in (0.0, 0.1, 0.5):
            assert cc.within_distance(tri, cc.Triangle(*u), c) == mesh.within_distance(other, c)


def as_json(s):
    """A shape as the ``cga shapes`` command line reads it."""
    p = lambda x: [float(v) for v in x]  # noqa: E731
    if isinstance(s, cc.Ball):
        return {"ball": {"center": p(s.centre), "radius": s.radius}}
    if isinstance(s, cc.Cuboid):
        return {"cuboid": {"center": p(s.centre), "half_axes": [p(h) for h in s.half_axes]}}
    if isinstance(s, (cc.Capsule, cc.Cylinder)):
        return {s.kind: {"a": p(s.a), "b": p(s.b), "radius": s.radius}}
    if isinstance(s, cc.Cone):
        return {"cone": {"apex": p(s.apex), "base": p(s.base), "radius": s.radius}}
    if isinstance(s, cc.HalfSpace):
        return {"halfspace": {"point": p(s.point), "normal": p(s.normal)}}
    if isinstance(s, cc.ConvexHull):
        return {"convex": {"points": [p(x) for x in s.points]}}
    if isinstance(s, cc.Triangle):
        return {"triangle": {"points": [p(x) for x in s.vertices]}}
    return {"segment": {"points": [p(s.a), p(s.b)]}}


def test_answers_equal_the_command_lines(tmp_path):
    """``cga shapes`` (the Rust answers, from the workspace's release build) on the same pairs:
    every kind against every kind where the library answers, and random ball, segment and
    triangle pairs near contact. Skipped without a ``cga`` binary that has ``shapes``."""
    binary = cga_binary()
    if binary is None or subprocess.run([binary, "shapes", "--help"], capture_output=True).returncode:
        pytest.skip("no cga binary with `cga shapes` (cargo build --release -p cga-cli, or set CGA_BIN)")
    rng = np.random.default_rng(7)
    pairs = []
    for a, b in itertools.product(one_of_each().values(), repeat=2):
        for pose in (np.eye(4), translation(1.0, 0.25), translation(10.0)):
            pairs.append((a, b.placed(pose)))
    for _ in range(200):
        t, u = random_triangle(rng, 0.5), random_triangle(rng, 0.5)
        c, r = rng.uniform(-1, 1, size=3), float(rng.uniform(0, 0.5))
        pairs += [(cc.Triangle(*t), cc.Triangle(*u)), (cc.Ball(c, r), cc.Triangle(*t)),
                  (cc.Segment(t[0], u[1]), cc.Triangle(*u)), (cc.Ball(c, r), cc.Segment(*t[:2]))]
    want, lines = [], []
    for a, b in pairs:
        try:
            want.append(answer(cc.intersects, a, b))
        except pytest.skip.Exception:
            continue  # the engine is not merged: the command line has no answer either
        lines.append(json.dumps({"a": as_json(a), "b": as_json(b)}))
    path = tmp_path / "pairs.jsonl"
    path.write_text("\n".join(lines) + "\n")
    out = subprocess.run([binary, "shapes", str(path), "--json"], capture_output=True, text=True, cwd=REPO)
    assert out.returncode == 0, out.stderr
    rust = json.loads(out.stdout.splitlines()[0])
    assert rust["pairs"] == len(want)
    assert rust["answers"] == want


# ---------------------------------------------------------------------------------- every kind


@pytest.mark.parametrize("kind_a, kind_b", list(itertools.product(KINDS, KINDS)))
def test_every_pair_answers_the_constructed_truth(kind_a, kind_b):
    """Each shape holds the origin: every pair meets. Moved 10 apart (the half-space away from
    the other shape), none meets, and the distance is more than 8."""
    a, b = shape_of(kind_a), shape_of(kind_b)
    assert answer(cc.intersects, a, b) is True
    assert answer(cc.within_distance, a, b, 0.0) is True
    assert answer(cc.distance, a, b).distance <= answer(cc.distance, a, b).error_bound
    if kind_a == kind_b == "halfspace":
        return  # x >= 0 and x >= 10 always meet
    # the half-space x >= 0 moves to x >= 10; any other shape moves to the other one's left
    away = translation(10.0)
    pa, pb = (away, np.eye(4)) if kind_a == "halfspace" else (np.eye(4), away)
    assert answer(cc.intersects_at, a, pa, b, pb) is False
    d = answer(cc.distance_at, a, pa, b, pb)
    assert d.distance - d.error_bound > 8.0
    assert answer(cc.within_distance_at, a, pa, b, pb, 8.0) is False


@pytest.mark.parametrize("kind_a, kind_b", list(itertools.product(KINDS, KINDS)))
def test_poses_and_batches_equal_placed_single_calls(kind_a, kind_b):
    a, b = shape_of(kind_a), shape_of(kind_b)
    k = 12
    pa, pb = random_poses(k, 10, spread=0.8), random_poses(k, 11, spread=0.8)
    hits = answer(cc.intersects_batch, a, b, pa, pb)
    near = answer(cc.within_distance_batch, a, b, pa, pb, 0.25)
    ds = answer(cc.distance_batch, a, b, pa, pb)
    assert hits.dtype == np.bool_ and hits.shape == (k,) and len(ds) == k
    for i in range(k):
        placed_a, placed_b = a.placed(pa[i]), b.placed(pb[i])
        assert hits[i] == cc.intersects_at(a, pa[i], b, pb[i]) == cc.intersects(placed_a, placed_b)
        assert near[i] == cc.within_distance(placed_a, placed_b, 0.25)
        d = cc.distance(placed_a, placed_b)
        assert ds.distance[i] == d.distance and ds.error_bound[i] == d.error_bound
        assert np.array_equal(ds.witness_a[i], d.witness_a)
        assert np.array_equal(ds.witness_b[i], d.witness_b)
        assert np.array_equal(ds.triangles[i], [-1, -1])
    # one (4, 4) pose stands for every query
    assert np.array_equal(cc.intersects_batch(a, b, pa[3], pb), [cc.intersects_at(a, pa[3], b, p) for p in pb])


# ---------------------------------------------------------------------------------- trimesh


def test_the_trimesh_drop_in_keeps_meshes_as_meshes():
    trimesh = pytest.importorskip("trimesh")
    from cga_collide.trimesh import CollisionManager

    m = CollisionManager()
    for name, mesh in {
        "box": trimesh.creation.box(extents=[1, 1, 1]),
        "cylinder": trimesh.creation.cylinder(radius=0.5, height=1.0, sections=16),
        "sphere": trimesh.creation.icosphere(subdivisions=1),
    }.items():
        oid = m.add_object(name, mesh)
        collider = m._scene.collider(oid)
        assert type(collider) is cc.Collider and not isinstance(collider, cc.Shape)
        assert collider.num_triangles == len(mesh.faces)
        assert np.array_equal(collider.vertices, mesh.vertices)


def test_convex_hull_corners_are_exact():
    """The hull keeps only its corners: points inside, on faces and on edges go; a point one
    ulp outside a face is a corner, one ulp inside is not."""
    cube = np.array([[i & 1, i >> 1 & 1, i >> 2 & 1] for i in range(8)], dtype=float)
    extras = np.array([[0.5, 0.5, 0.5], [0.5, 0.5, 1.0], [0.5, 0.0, 0.0], [1.0, 1.0, 1.0]])
    h = cc.ConvexHull(np.vstack([cube, extras]))
    assert h.dimension == 3
    assert h.corners.shape == (8, 3)
    assert {tuple(c) for c in h.corners} == {tuple(c) for c in cube}
    assert h.triangles.shape == (12, 3) and h.triangles.dtype == np.int64
    assert h.points.shape == (12, 3)
    outside = cc.ConvexHull(np.vstack([cube, [[0.5, 0.5, np.nextafter(1.0, 2.0)]]]))
    assert outside.corners.shape == (9, 3)
    inside = cc.ConvexHull(np.vstack([cube, [[0.5, 0.5, np.nextafter(1.0, 0.0)]]]))
    assert inside.corners.shape == (8, 3)
    flat = cc.ConvexHull([[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0.5, 0, 0]])
    assert (flat.dimension, flat.corners.shape, flat.triangles.shape) == (2, (4, 3), (0, 3))
    assert cc.ConvexHull([[1, 2, 3]]).dimension == 0
    assert cc.ConvexHull([[0, 0, 0], [1, 1, 1], [2, 2, 2]]).corners.shape == (2, 3)
