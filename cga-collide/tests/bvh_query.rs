//! The hierarchy never misses a candidate, and both query modes give identical exact answers,
//! on random placements including touching and coplanar contacts.

use cga_collide::bounding::BuildStrategy;
use cga_collide::collider::{Collider, Mode};
use cga_collide::shape::mesh::TriMesh;
use cga_collide::{Ball, Intersects, Segment, Sphere, Triangle};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use proptest::prelude::*;

mod common;
use common::{cube, grid, iso};

fn random_soup(seed: u64, n: usize) -> TriMesh {
    common::random_soup(seed, n, 2.0)
}

/// Pure exact oracle: every triangle, no box filter at all.
fn oracle<Q>(c: &Collider, q: &Q) -> Vec<u32>
where
    Triangle: Intersects<Q>,
{
    (0..c.mesh().num_triangles() as u32)
        .filter(|&i| c.triangle(i).intersects(q))
        .collect()
}

fn check_pairs(a: &Collider, b: &Collider) -> Result<(), TestCaseError> {
    prop_assert_eq!(a.box_pairs_bvh(b), {
        let mut v = a.box_pairs_brute(b);
        v.sort_unstable();
        v
    });
    let brute = a.clone().with_mode(Mode::Brute).intersecting_pairs(b);
    let bvh = a.intersecting_pairs(b);
    prop_assert_eq!(&brute, &bvh);
    prop_assert_eq!(
        a.clone().with_mode(Mode::Brute).collides(b),
        !brute.is_empty()
    );
    prop_assert_eq!(a.collides(b), !brute.is_empty());
    Ok(())
}

#[test]
fn self_contact_and_far_apart() {
    let solid = cube([0, 0, 0], [3, 2, 1]).subdivided().subdivided();
    let c = Collider::new(solid.clone());
    // A mesh against itself: every triangle meets itself (and its neighbours).
    let pairs = c.intersecting_pairs(&c);
    assert!(pairs.len() > c.mesh().num_triangles());
    assert!((0..c.mesh().num_triangles() as u32).all(|i| pairs.binary_search(&(i, i)).is_ok()));
    assert_eq!(
        c.clone().with_mode(Mode::Brute).intersecting_pairs(&c),
        pairs
    );
    let median = Collider::with_strategy(solid, BuildStrategy::Median);
    assert_eq!(median.intersecting_pairs(&c), pairs);
    let bunny = Collider::new(TriMesh::bunny());
    let far = bunny
        .placed(&Isometry3::translation(100.0, 0.0, 0.0))
        .unwrap();
    assert!(!bunny.collides(&far));
    assert!(bunny
        .clone()
        .with_mode(Mode::Brute)
        .intersecting_pairs(&far)
        .is_empty());
}

#[test]
fn touching_and_coplanar_boxes() {
    let a = Collider::new(cube([0, 0, 0], [2, 2, 2]));
    // face contact, edge contact, corner contact, overlap, gap of one ulp-free unit
    for (lo, hi, touching) in [
        ([2, 0, 0], [4, 2, 2], true),
        ([2, 2, 0], [4, 4, 2], true),
        ([2, 2, 2], [3, 3, 3], true),
        ([1, 1, 1], [3, 3, 3], true),
        ([3, 0, 0], [4, 2, 2], false),
        ([0, 0, 2], [1, 1, 3], true),
    ] {
        let b = Collider::new(cube(lo, hi));
        let pairs = a.clone().with_mode(Mode::Brute).intersecting_pairs(&b);
        assert_eq!(pairs, a.intersecting_pairs(&b));
        assert_eq!(!pairs.is_empty(), touching, "{lo:?} {hi:?}");
        assert_eq!(a.collides(&b), touching);
    }
    // coplanar grids shifted by half a cell
    let g = Collider::new(grid(4, 0.0));
    let h = g.placed(&Isometry3::translation(0.5, 0.5, 0.0)).unwrap();
    let pairs = g.clone().with_mode(Mode::Brute).intersecting_pairs(&h);
    assert!(!pairs.is_empty());
    assert_eq!(pairs, g.intersecting_pairs(&h));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Random placements of random soups: the hierarchy enumerates exactly the pairs of
    /// overlapping triangle boxes, and the modes agree.
    #[test]
    fn mesh_mesh_random_placements(seed in any::<u64>(), pa in iso(), pb in iso()) {
        let a = Collider::new(random_soup(seed, 60)).placed(&pa).unwrap();
        let b = Collider::with_strategy(random_soup(seed ^ 0x9e37, 80), BuildStrategy::Median)
            .placed(&pb)
            .unwrap();
        check_pairs(&a, &b)?;
    }

    /// Integer cubes and grids placed by integer translations and quarter turns: touching and
    /// coplanar contacts everywhere.
    #[test]
    fn mesh_mesh_touching(
        lo in prop::array::uniform3(-3i32..3), size in prop::array::uniform3(1i32..4),
        shift in prop::array::uniform3(-3i32..4), quarter in 0u8..4, z in -2i32..3,
    ) {
        let hi = [lo[0] + size[0], lo[1] + size[1], lo[2] + size[2]];
        let a = Collider::new(cube(lo, hi));
        let rot = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), 0.0);
        let b = Collider::new(grid(4, z as f64)).placed(&Isometry3::from_parts(
            Translation3::new(shift[0] as f64, shift[1] as f64, 0.0), rot)).unwrap();
        check_pairs(&a, &b)?;
        // quarter turns about z are exact on integers only up to rounding of sin/cos, which
        // is part of the placement: the answers are defined on the transformed coordinates.
        let r = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), quarter as f64 * std::f64::consts::FRAC_PI_2);
        let c = Collider::new(cube(lo, hi)).placed(&Isometry3::from_parts(
            Translation3::new(shift[0] as f64, shift[1] as f64, shift[2] as f64), r)).unwrap();
        check_pairs(&a, &c)?;
    }

    /// Primitive queries: bvh = brute = the pure exact oracle, for random and for touching
    /// primitives (end points and centres on vertices, axis-parallel segments).
    #[test]
    fn primitive_queries_agree(seed in any::<u64>(), p in iso(),
                               k in 0usize..1000, l in 0usize..1000, r in 0.0f64..2.0,
                               axis in 0usize..3) {
        let bunny = Collider::new(random_soup(seed, 150)).placed(&p).unwrap();
        let g = Collider::new(grid(5, 1.0));
        for c in [&bunny, &g] {
            let vs = c.mesh().vertices();
            let (u, w) = (vs[k % vs.len()], vs[l % vs.len()]);
            let mut along = u;
            along[axis] += 3.0;
            let segments = [
                Segment::new(u, w).unwrap(),
                Segment::new(u, along).unwrap(),
                Segment::new(Point3::new(-1.0, 2.5, 1.0), Point3::new(6.0, 2.5, 1.0)).unwrap(),
                Segment::new(u, u).unwrap(),
            ];
            for s in &segments {
                let exact = oracle(c, s);
                prop_assert_eq!(&c.clone().with_mode(Mode::Brute).segment_hits(s), &exact);
                prop_assert_eq!(&c.segment_hits(s), &exact);
            }
            let t = Triangle::new(u, w, along).unwrap();
            let exact = oracle(c, &t);
            prop_assert_eq!(&c.clone().with_mode(Mode::Brute).triangle_hits(&t), &exact);
            prop_assert_eq!(&c.triangle_hits(&t), &exact);
            // spheres through a vertex (centre at a vertex, radius an exact axis distance)
            let spheres = [
                Sphere::new(u, r).unwrap(),
                Sphere::new(u, (w - u).norm()).unwrap(),
                Sphere::new(Point3::new(2.0, 2.0, 1.0), 1.0).unwrap(),
                Sphere::new(w, 0.0).unwrap(),
            ];
            for s in &spheres {
                let exact = oracle(c, s);
                prop_assert_eq!(&c.clone().with_mode(Mode::Brute).sphere_hits(s), &exact);
                prop_assert_eq!(&c.sphere_hits(s), &exact);
                let b = Ball::from(*s);
                let exact = oracle(c, &b);
                prop_assert_eq!(&c.clone().with_mode(Mode::Brute).ball_hits(&b), &exact);
                prop_assert_eq!(&c.ball_hits(&b), &exact);
            }
            let mut union: Vec<u32> = spheres.iter().flat_map(|s| oracle(c, s)).collect();
            union.sort_unstable();
            union.dedup();
            prop_assert_eq!(&c.clone().with_mode(Mode::Brute).spheres_hits(&spheres), &union);
            prop_assert_eq!(&c.spheres_hits(&spheres), &union);
        }
    }
}
