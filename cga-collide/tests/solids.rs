//! Exact point-in-closed-mesh and solid collision.

use cga_collide::collider::{Collider, Mode};
use cga_collide::shape::mesh::TriMesh;
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion};
use proptest::prelude::*;

fn cube(lo: [f64; 3], hi: [f64; 3]) -> TriMesh {
    TriMesh::cuboid(lo.into(), hi.into()).unwrap()
}

/// Float generalized winding number (solid angles), for points far from the surface.
fn winding(m: &TriMesh, p: &Point3<f64>) -> f64 {
    let mut w = 0.0;
    for k in 0..m.num_triangles() {
        let [a, b, c] = m.corners(k as u32).map(|q| q - p);
        let (la, lb, lc) = (a.norm(), b.norm(), c.norm());
        let num = a.dot(&b.cross(&c));
        let den = la * lb * lc + a.dot(&b) * lc + b.dot(&c) * la + c.dot(&a) * lb;
        w += 2.0 * num.atan2(den);
    }
    w / (4.0 * std::f64::consts::PI)
}

#[test]
fn fixtures_are_closed_or_not() {
    assert!(cube([0.0; 3], [1.0; 3]).is_closed());
    assert!(cube([0.0; 3], [1.0; 3]).subdivided().is_closed());
    let mut open = cube([0.0; 3], [1.0; 3]).triangles().to_vec();
    open.pop();
    let open = TriMesh::new(cube([0.0; 3], [1.0; 3]).vertices().to_vec(), open).unwrap();
    assert!(!open.is_closed());
}

#[test]
fn armadillo_inside_matches_winding_number_away_from_surface() {
    let arm = TriMesh::armadillo();
    assert!(arm.is_closed());
    let c = Collider::new(arm.clone());
    let (lo, hi) = arm.bounds();
    let mut rng = cga_collide::testing::adversarial::SplitMix64(7);
    let mut inside = 0;
    for _ in 0..40 {
        let p = Point3::new(
            rng.float(lo.x, hi.x),
            rng.float(lo.y, hi.y),
            rng.float(lo.z, hi.z),
        );
        let w = winding(&arm, &p);
        if (w - w.round()).abs() > 0.05 {
            continue; // too close to the surface for the float reference
        }
        let exact = c.contains_point(&p);
        assert_eq!(exact, w.round() as i64 % 2 != 0, "{p:?} winding {w}");
        assert_eq!(exact, c.clone().with_mode(Mode::Brute).contains_point(&p));
        inside += usize::from(exact);
    }
    assert!(inside > 0);
}

#[test]
fn nested_solids_collide_without_surface_contact() {
    let big = Collider::new(cube([0.0; 3], [10.0; 3]));
    let small = Collider::new(cube([0.0; 3], [1.0; 3]).subdivided())
        .placed(&Isometry3::from_parts(
            Translation3::new(4.0, 4.0, 4.0),
            UnitQuaternion::from_euler_angles(0.3, 0.2, 0.1),
        ))
        .unwrap();
    for mode in [Mode::Brute, Mode::Bvh] {
        let (big, small) = (big.clone().with_mode(mode), small.clone().with_mode(mode));
        assert!(!big.collides(&small));
        assert!(big.collides_solid(&small));
        assert!(small.collides_solid(&big));
    }
    let away = small
        .placed(&Isometry3::translation(20.0, 0.0, 0.0))
        .unwrap();
    assert!(!big.collides_solid(&away));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Points on the half-integer grid around an integer box: rays through vertices and along
    /// edges and faces everywhere. Inside the closed box iff contained.
    #[test]
    fn cube_containment_is_exact(
        lo in prop::array::uniform3(-2i32..1), size in prop::array::uniform3(1i32..4),
        pts in prop::collection::vec(prop::array::uniform3(-6i32..10), 20), subdivide in any::<bool>(),
    ) {
        let lo_f = lo.map(f64::from);
        let hi_f = [0, 1, 2].map(|k| f64::from(lo[k] + size[k]));
        let mut mesh = cube(lo_f, hi_f);
        if subdivide {
            mesh = mesh.subdivided();
        }
        let c = Collider::new(mesh);
        for q in pts {
            let p = Point3::new(q[0] as f64 * 0.5, q[1] as f64 * 0.5, q[2] as f64 * 0.5);
            let expected = (0..3).all(|k| lo_f[k] <= p[k] && p[k] <= hi_f[k]);
            prop_assert_eq!(c.contains_point(&p), expected, "{:?}", p);
            prop_assert_eq!(c.clone().with_mode(Mode::Brute).contains_point(&p), expected, "{:?}", p);
        }
    }

    /// Rotated boxes: modes agree, and points well inside or outside are classified right.
    #[test]
    fn rotated_cube_modes_agree(a in -3.2f64..3.2, b in -3.2f64..3.2, x in -2.0f64..2.0,
                                y in -2.0f64..2.0, z in -2.0f64..2.0) {
        let iso = Isometry3::from_parts(Translation3::identity(), UnitQuaternion::from_euler_angles(a, b, 0.0));
        let c = Collider::new(cube([-1.0; 3], [1.0; 3])).placed(&iso).unwrap();
        let p = Point3::new(x, y, z);
        let local = iso.inverse() * p;
        let r = local.coords.amax();
        let got = c.contains_point(&p);
        prop_assert_eq!(got, c.clone().with_mode(Mode::Brute).contains_point(&p));
        if r < 0.999 { prop_assert!(got); }
        if r > 1.001 { prop_assert!(!got); }
        // vertices of the placed mesh are on it
        let v = c.mesh().vertices()[0];
        prop_assert!(c.contains_point(&v));
    }
}
