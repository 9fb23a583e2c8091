//! Pose queries (`Collider::*_at`, the batches) answer exactly what placing the meshes first
//! (`Collider::placed`) and asking the placed copies answers, and what brute force answers, on
//! random poses including touching and coplanar contacts.

use cga_collide::collider::{Collider, Mode, PosePair};
use cga_collide::shape::mesh::TriMesh;
use cga_collide::Error;
use cga_collide::{Ball, Segment, Sphere, Triangle};
use nalgebra::{Isometry3, Point3, Quaternion, Translation3, UnitQuaternion, Vector3};
use proptest::prelude::*;

mod common;
use common::{cube, iso};

/// `n × n` unit squares in the plane z = 0, two triangles each.
fn grid(n: u32) -> TriMesh {
    common::grid(n, 0.0)
}

fn random_soup(seed: u64, n: usize) -> TriMesh {
    common::random_soup(seed, n, 1.5)
}

/// Rotations that are exact in `f64` (identity and half turns: quaternion components 0, ±1)
/// and quarter turns (rounded), with integer translations: touching and coplanar contacts.
fn lattice_pose() -> impl Strategy<Value = Isometry3<f64>> {
    (0usize..7, prop::array::uniform3(-3i32..4)).prop_map(|(r, t)| {
        let q = match r {
            0 => UnitQuaternion::identity(),
            1 => UnitQuaternion::new_unchecked(Quaternion::new(0.0, 1.0, 0.0, 0.0)),
            2 => UnitQuaternion::new_unchecked(Quaternion::new(0.0, 0.0, 1.0, 0.0)),
            3 => UnitQuaternion::new_unchecked(Quaternion::new(0.0, 0.0, 0.0, 1.0)),
            4 => UnitQuaternion::from_axis_angle(&Vector3::z_axis(), std::f64::consts::FRAC_PI_2),
            5 => UnitQuaternion::from_axis_angle(&Vector3::x_axis(), -std::f64::consts::FRAC_PI_2),
            _ => UnitQuaternion::from_euler_angles(0.3, -0.2, 0.1),
        };
        Isometry3::from_parts(Translation3::new(t[0] as f64, t[1] as f64, t[2] as f64), q)
    })
}

/// Every pose query against `placed()` + the same query (both modes), and brute force.
fn check(
    a: &Collider,
    pa: &Isometry3<f64>,
    b: &Collider,
    pb: &Isometry3<f64>,
) -> Result<(), TestCaseError> {
    let (wa, wb) = (a.placed(pa).unwrap(), b.placed(pb).unwrap());
    let want = wa.clone().with_mode(Mode::Brute).intersecting_pairs(&wb);
    prop_assert_eq!(&wa.intersecting_pairs(&wb), &want);
    prop_assert_eq!(&a.intersecting_pairs_at(pa, b, pb).unwrap(), &want);
    let (ba, bb) = (
        a.clone().with_mode(Mode::Brute),
        b.clone().with_mode(Mode::Brute),
    );
    prop_assert_eq!(&ba.intersecting_pairs_at(pa, &bb, pb).unwrap(), &want);
    prop_assert_eq!(ba.collides_at(pa, &bb, pb).unwrap(), !want.is_empty());
    prop_assert_eq!(a.collides_at(pa, b, pb).unwrap(), !want.is_empty());
    prop_assert_eq!(a.collides_at(pa, b, pb).unwrap(), wa.collides(&wb));
    prop_assert_eq!(
        a.collides_solid_at(pa, b, pb).unwrap(),
        wa.clone().with_mode(Mode::Brute).collides_solid(&wb)
    );
    Ok(())
}

#[test]
fn touching_cubes_and_coplanar_grids() {
    let a = Collider::new(cube([0, 0, 0], [2, 2, 2]));
    let unit = Collider::new(cube([0, 0, 0], [1, 1, 1]));
    let id = Isometry3::identity();
    // face, edge and corner contact, overlap, gap; the second cube only moved.
    for (t, touching) in [
        ([2.0, 0.0, 0.0], true),
        ([2.0, 2.0, 0.0], true),
        ([2.0, 2.0, 2.0], true),
        ([1.0, 1.0, 1.0], true),
        ([3.0, 0.0, 0.0], false),
        ([2.0 + 1e-15, 0.0, 0.0], false),
    ] {
        let pb = Isometry3::translation(t[0], t[1], t[2]);
        assert_eq!(a.collides_at(&id, &unit, &pb).unwrap(), touching, "{t:?}");
        check(&a, &id, &unit, &pb).unwrap();
    }
    // A half turn about x is exact: the flipped grid lies in the same plane, shifted by half a
    // cell (coplanar overlaps everywhere).
    let g = Collider::new(grid(4));
    let flip = Isometry3::from_parts(
        Translation3::new(0.5, 4.5, 0.0),
        UnitQuaternion::new_unchecked(Quaternion::new(0.0, 1.0, 0.0, 0.0)),
    );
    let pairs = g.intersecting_pairs_at(&id, &g, &flip).unwrap();
    assert!(!pairs.is_empty());
    check(&g, &id, &g, &flip).unwrap();
    // Both meshes moved: the answer depends only on the placed coordinates.
    let shift = Isometry3::translation(10.0, -3.0, 7.0);
    check(&g, &shift, &g, &(shift * flip)).unwrap();
    // Nested solids: no surface contact, but the small cube is inside the big one.
    let inner = Isometry3::translation(0.5, 0.5, 0.5);
    assert!(!a.collides_at(&id, &unit, &inner).unwrap());
    assert!(a.collides_solid_at(&id, &unit, &inner).unwrap());
    assert!(unit.collides_solid_at(&inner, &a, &id).unwrap());
}

#[test]
fn bunny_against_bunny_near_contact() {
    let b = Collider::new(TriMesh::bunny().unit());
    let mut rng = cga_collide::testing::adversarial::SplitMix64(3);
    for _ in 0..6 {
        let pa = Isometry3::new(
            Vector3::new(rng.float(-0.1, 0.1), rng.float(-0.1, 0.1), 0.0),
            Vector3::new(
                rng.float(-3.0, 3.0),
                rng.float(-3.0, 3.0),
                rng.float(-3.0, 3.0),
            ),
        );
        let pb = Isometry3::new(
            Vector3::new(
                rng.float(0.4, 0.8),
                rng.float(-0.1, 0.1),
                rng.float(-0.1, 0.1),
            ),
            Vector3::new(
                rng.float(-3.0, 3.0),
                rng.float(-3.0, 3.0),
                rng.float(-3.0, 3.0),
            ),
        );
        check(&b, &pa, &b, &pb).unwrap();
    }
}

#[test]
fn batches_answer_each_pose() {
    let b = Collider::new(TriMesh::bunny().unit());
    let poses: Vec<PosePair> = (0..24)
        .map(|k| {
            let x = 0.3 + 0.04 * k as f64;
            PosePair::new(
                Isometry3::identity(),
                Isometry3::new(
                    Vector3::new(x, 0.0, 0.0),
                    Vector3::new(0.0, 0.1 * k as f64, 0.0),
                ),
            )
        })
        .collect();
    let hits = b.collides_batch(&b, &poses).unwrap();
    let pairs = b.intersecting_pairs_batch(&b, &poses).unwrap();
    assert!(hits.iter().any(|&h| h) && hits.iter().any(|&h| !h));
    for (k, p) in poses.iter().enumerate() {
        let want = b
            .placed(&p.a)
            .unwrap()
            .intersecting_pairs(&b.placed(&p.b).unwrap());
        assert_eq!(pairs[k], want);
        assert_eq!(hits[k], !want.is_empty());
    }
    let mut bad = poses.clone();
    bad[5].b.translation.vector.y = f64::INFINITY;
    assert_eq!(
        b.collides_batch(&b, &bad),
        Err(Error::InBatch {
            index: 5,
            source: Box::new(Error::NonFinitePose)
        })
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Random soups (with degenerate triangles) at random poses.
    #[test]
    fn random_poses_match_placed(seed in any::<u64>(), pa in iso(), pb in iso()) {
        let a = Collider::new(random_soup(seed, 40));
        let b = Collider::new(random_soup(seed ^ 0x9e37, 50));
        check(&a, &pa, &b, &pb)?;
    }

    /// Integer cubes and grids at exact and quarter-turn poses: touching and coplanar contacts.
    #[test]
    fn lattice_poses_match_placed(
        lo in prop::array::uniform3(-2i32..2), size in prop::array::uniform3(1i32..3),
        pa in lattice_pose(), pb in lattice_pose(), use_grid in any::<bool>(),
    ) {
        let hi = [lo[0] + size[0], lo[1] + size[1], lo[2] + size[2]];
        let a = Collider::new(cube(lo, hi));
        let b = if use_grid { Collider::new(grid(3)) } else { Collider::new(cube([0, 0, 0], size)) };
        check(&a, &pa, &b, &pb)?;
    }

    /// Mesh–shape queries and containment at a pose equal the placed mesh's (both modes).
    #[test]
    fn shape_queries_match_placed(
        seed in any::<u64>(), p in iso(), k in 0usize..1000, l in 0usize..1000,
        r in 0.0f64..1.5, lattice in lattice_pose(), q in prop::array::uniform3(-2.0f64..2.0),
    ) {
        for (c, pose) in [
            (Collider::new(random_soup(seed, 60)), p),
            (Collider::new(cube([0, 0, 0], [2, 1, 1])), lattice),
        ] {
            let placed = c.placed(&pose).unwrap();
            let vs = placed.mesh().vertices();
            // Shapes through placed vertices (touching), and random ones.
            let (u, w) = (vs[k % vs.len()], vs[l % vs.len()]);
            let x = Point3::from(q);
            for s in [Segment::new(u, w).unwrap(), Segment::new(x, u).unwrap(), Segment::new(u, u).unwrap()] {
                let want = placed.clone().with_mode(Mode::Brute).segment_hits(&s);
                prop_assert_eq!(&placed.segment_hits(&s), &want);
                prop_assert_eq!(&c.segment_hits_at(&pose, &s).unwrap(), &want);
            }
            let t = Triangle::new(u, w, x).unwrap();
            prop_assert_eq!(c.triangle_hits_at(&pose, &t).unwrap(), placed.clone().with_mode(Mode::Brute).triangle_hits(&t));
            for centre in [u, x] {
                let s = Sphere::new(centre, r).unwrap();
                prop_assert_eq!(c.sphere_hits_at(&pose, &s).unwrap(), placed.clone().with_mode(Mode::Brute).sphere_hits(&s));
                let bl = Ball::new(centre, r).unwrap();
                prop_assert_eq!(c.ball_hits_at(&pose, &bl).unwrap(), placed.clone().with_mode(Mode::Brute).ball_hits(&bl));
            }
            for point in [u, x, nalgebra::center(&u, &w)] {
                prop_assert_eq!(
                    c.contains_point_at(&pose, &point).unwrap(),
                    placed.clone().with_mode(Mode::Brute).contains_point(&point)
                );
            }
        }
    }
}
