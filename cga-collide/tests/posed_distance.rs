//! Clearance and distance under poses (`Collider::pairs_within_distance_at`,
//! `within_distance_at`, `distance_at`) answer exactly what placing the meshes first
//! (`Collider::placed`) and asking `query::mesh_pairs_within_distance`,
//! `query::meshes_within_distance` and `query::mesh_distance` answers: random poses on small
//! meshes, cubes at exactly distance `c` (dyadic translations, exact and quarter-turn
//! rotations), bad clearances and bad poses.

use cga_collide::collider::Collider;
use cga_collide::shape::mesh::TriMesh;
use cga_collide::Error;
use nalgebra::{Isometry3, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};
use proptest::prelude::*;

mod common;
use common::{cube, iso};

/// Every clearance and distance query under the poses against the placed copies.
fn check(
    a: &Collider,
    pa: &Isometry3<f64>,
    b: &Collider,
    pb: &Isometry3<f64>,
    c: f64,
) -> Result<Vec<(u32, u32)>, TestCaseError> {
    let (wa, wb) = (a.placed(pa).unwrap(), b.placed(pb).unwrap());
    let want = wa.pairs_within_distance(&wb, c);
    prop_assert_eq!(&a.pairs_within_distance_at(pa, b, pb, c).unwrap(), &want);
    prop_assert_eq!(
        a.within_distance_at(pa, b, pb, c).unwrap(),
        wa.within_distance(&wb, c)
    );
    prop_assert_eq!(a.distance_at(pa, b, pb).unwrap(), wa.distance(&wb).unwrap());
    Ok(want)
}

/// Unit cubes subdivided once (48 triangles, many parallel faces and equal distances).
fn subdivided_cube() -> TriMesh {
    cube([0, 0, 0], [1, 1, 1]).subdivided()
}

/// The built-in bunny scaled to a box of side 1/4 (3 674 triangles).
fn small_bunny() -> TriMesh {
    let unit = TriMesh::bunny().unit();
    let v = unit
        .vertices()
        .iter()
        .map(|p| Point3::from(p.coords * 0.25))
        .collect();
    TriMesh::new(v, unit.triangles().to_vec()).unwrap()
}

/// Exact rotations (identity, half turns) and rounded quarter turns.
fn lattice_rotation(k: usize) -> UnitQuaternion<f64> {
    let q = |w, x, y, z| UnitQuaternion::new_unchecked(Quaternion::new(w, x, y, z));
    match k {
        0 => UnitQuaternion::identity(),
        1 => q(0.0, 1.0, 0.0, 0.0),
        2 => q(0.0, 0.0, 1.0, 0.0),
        3 => q(0.0, 0.0, 0.0, 1.0),
        4 => UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2),
        _ => UnitQuaternion::from_axis_angle(&Vector3::x_axis(), -std::f64::consts::FRAC_PI_2),
    }
}

fn clearance() -> impl Strategy<Value = f64> {
    prop_oneof![
        1 => Just(0.0),
        2 => (0i32..=8).prop_map(|v| f64::from(v) * 0.125),
        3 => 0.0f64..1.0,
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// Random soups (with degenerate triangles) and subdivided cubes at random poses.
    #[test]
    fn random_poses_match_placed(
        seed in any::<u64>(), pa in iso(), pb in iso(), c in clearance(), cubes in any::<bool>(),
    ) {
        let (a, b) = if cubes {
            (Collider::new(subdivided_cube()), Collider::new(cube([0, 0, 0], [1, 2, 1])))
        } else {
            (
                Collider::new(common::random_soup(seed, 30, 1.5)),
                Collider::new(common::random_soup(seed ^ 0x9e37, 40, 1.5)),
            )
        };
        check(&a, &pa, &b, &pb, c)?;
    }

    /// Axis-aligned cubes moved by dyadic amounts, at exact and quarter-turn rotations, with
    /// `c` the exact gap, the `f64` below it and above it: contacts at exactly distance `c`.
    #[test]
    fn cubes_at_exactly_distance_c(
        size in prop::array::uniform3(1i32..3), t in prop::array::uniform3(-24i32..25),
        k in 0usize..6, l in 0usize..6,
    ) {
        let a = Collider::new(cube([0, 0, 0], size));
        let b = Collider::new(subdivided_cube());
        // B's corner offsets in eighths: the gap along each axis is a multiple of 1/8.
        let tb = t.map(|v| f64::from(v) * 0.125);
        let pa = Isometry3::from_parts(Translation3::identity(), lattice_rotation(k));
        let pb = Isometry3::from_parts(Translation3::new(tb[0], tb[1], tb[2]), lattice_rotation(l));
        let d = a.placed(&pa).unwrap().distance(&b.placed(&pb).unwrap()).unwrap();
        for c in [d.distance, d.distance.next_down(), d.distance.next_up(), 0.125, 0.25] {
            check(&a, &pa, &b, &pb, c)?;
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(6))]

    /// The bunny (scaled down) against a subdivided cube and against itself, near contact.
    #[test]
    fn bunny_matches_placed(pa in iso(), pb in iso(), c in 0.0f64..0.02, itself in any::<bool>()) {
        let a = Collider::new(small_bunny());
        let b = if itself { a.clone() } else { Collider::new(subdivided_cube()) };
        // Bring B within about 0.3 of A (the poses' translations are up to 1.5 per axis).
        let near = Isometry3::from_parts(
            Translation3::from(pb.translation.vector * 0.2),
            pb.rotation,
        );
        check(&a, &pa, &b, &(pa * near), c)?;
    }
}

#[test]
fn exact_gaps_are_found_without_placing() {
    let a = Collider::new(cube([0, 0, 0], [1, 1, 1]));
    let id = Isometry3::identity();
    // A gap of exactly 1/2 along x, after a (rounded) quarter turn of B about z.
    let pb = Isometry3::from_parts(Translation3::new(2.5, 0.0, 0.0), lattice_rotation(4));
    let placed = a.placed(&pb).unwrap();
    let at = a.pairs_within_distance_at(&id, &a, &pb, 0.5).unwrap();
    assert_eq!(at, a.pairs_within_distance(&placed, 0.5));
    // The placed coordinates are rounded: whatever the gap is exactly, both agree on it, and
    // a half turn (exact) gives exactly 1/2: B is [1.5, 2.5] × [0, 1] × [0, 1].
    let half = Isometry3::from_parts(Translation3::new(2.5, 1.0, 0.0), lattice_rotation(3));
    assert!(!a
        .pairs_within_distance_at(&id, &a, &half, 0.5)
        .unwrap()
        .is_empty());
    assert!(a
        .pairs_within_distance_at(&id, &a, &half, 0.5f64.next_down())
        .unwrap()
        .is_empty());
    assert!(a.within_distance_at(&id, &a, &half, 0.5).unwrap());
    assert!(!a
        .within_distance_at(&id, &a, &half, 0.5f64.next_down())
        .unwrap());
    let d = a.distance_at(&id, &a, &half).unwrap();
    assert_eq!(d.distance, 0.5);
    assert!(d.error_bound < 1e-13);
    check(&a, &id, &a, &half, 0.5).unwrap();
    // Both meshes moved far from the origin: only the relative placement matters to the
    // answer, and the translations' rounding is paid by the margin.
    let far = Isometry3::translation(1000.25, -3.5, 7.0);
    check(&a, &far, &a, &(far * half), 0.5).unwrap();
    check(&a, &far, &a, &(far * pb), 0.5).unwrap();
}

#[test]
fn bad_clearances_behave_like_the_placed_queries() {
    let a = Collider::new(cube([0, 0, 0], [1, 1, 1]));
    let b = Collider::new(subdivided_cube());
    let (id, pb) = (Isometry3::identity(), Isometry3::translation(3.0, 0.0, 0.0));
    let n = a.mesh().num_triangles() * b.mesh().num_triangles();
    for c in [
        f64::NAN,
        -0.0,
        -1.0,
        f64::NEG_INFINITY,
        f64::INFINITY,
        f64::MAX,
        1e300,
    ] {
        let pairs = check(&a, &id, &b, &pb, c).unwrap();
        let all = c >= 1e300;
        assert_eq!(pairs.len(), if all { n } else { 0 }, "{c}");
        assert_eq!(a.within_distance_at(&id, &b, &pb, c).unwrap(), all, "{c}");
    }
}

#[test]
fn bad_poses_are_typed_errors() {
    let a = Collider::new(cube([0, 0, 0], [1, 1, 1]));
    let id = Isometry3::identity();
    let mut nan = id;
    nan.translation.vector.y = f64::NAN;
    let skew = Isometry3::from_parts(
        Translation3::identity(),
        UnitQuaternion::new_unchecked(Quaternion::new(0.5, 0.0, 0.0, 0.0)),
    );
    let far = Isometry3::translation(0.0, 0.0, 1e300);
    for (p, want) in [
        (nan, Error::NonFinitePose),
        (skew, Error::NotUnitRotation { norm_squared: 0.25 }),
        (
            far,
            Error::OutOfRange {
                magnitude: 1e300,
                limit: 9.774714424757689e297, // the pose queries' range
            },
        ),
    ] {
        for (pa, pb) in [(&id, &p), (&p, &id)] {
            // Bad poses win over bad clearances, as `placed()?` comes first.
            for c in [0.5, f64::NAN, -1.0, f64::INFINITY] {
                assert_eq!(a.pairs_within_distance_at(pa, &a, pb, c), Err(want.clone()));
                assert_eq!(a.within_distance_at(pa, &a, pb, c), Err(want.clone()));
            }
            assert_eq!(a.distance_at(pa, &a, pb), Err(want.clone()));
        }
    }
}

#[test]
fn ties_pick_the_smallest_pair_in_both() {
    // Facing subdivided faces: many triangle pairs at exactly the same distance.
    let a = Collider::new(subdivided_cube());
    let id = Isometry3::identity();
    for t in [[1.5, 0.0, 0.0], [1.25, 0.5, 0.0], [0.0, 0.0, -1.75]] {
        let pb = Isometry3::translation(t[0], t[1], t[2]);
        let d = a.distance_at(&id, &a, &pb).unwrap();
        let placed = a.placed(&pb).unwrap();
        assert_eq!(d, a.distance(&placed).unwrap());
        // The smallest pair among those at that distance.
        let ties = a.pairs_within_distance(&placed, d.distance);
        assert!(ties.len() > 1, "{t:?}");
        assert_eq!(d.triangles, Some(ties[0]), "{t:?}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// Parallel grids at a random rotation: the facing pairs tie up to the rounding of the
    /// placed coordinates (the near-ties where the two searches could part; 2,000 cases agreed
    /// when this was written).
    #[test]
    fn parallel_grids_near_ties_match_placed(pa in iso(), gap in 0.01f64..0.5, sx in -2.0f64..2.0, sy in -2.0f64..2.0) {
        let g = Collider::new(common::grid(3, 0.0));
        let pb = pa * Isometry3::translation(sx, sy, gap);
        check(&g, &pa, &g, &pb, gap)?;
    }
}
