//! The certified GJK reference (`testing::convex::ConvexMeshRef::collides_solid`) against the exhaustive exact
//! mesh test (`Collider::collides_solid`) on random rigid placements of convex solids, and on
//! touching and nested constructions where the certificates must give way to the exact test.

use cga_collide::collider::{Collider, Mode};
use cga_collide::shape::mesh::TriMesh;
use cga_collide::testing::convex::{Certificate, ConvexMeshRef};
use nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use proptest::prelude::*;

struct Solid {
    vertices: Vec<Point3<f64>>,
    triangles: Vec<[u32; 3]>,
}

fn cube(h: f64) -> Solid {
    let vertices = (0..8)
        .map(|i| {
            let s = |bit: usize| if i >> bit & 1 == 1 { h } else { -h };
            Point3::new(s(0), s(1), s(2))
        })
        .collect();
    let triangles = vec![
        [0, 2, 1],
        [1, 2, 3],
        [4, 5, 6],
        [5, 7, 6],
        [0, 1, 4],
        [1, 5, 4],
        [2, 6, 3],
        [3, 6, 7],
        [0, 4, 2],
        [2, 4, 6],
        [1, 3, 5],
        [3, 7, 5],
    ];
    Solid {
        vertices,
        triangles,
    }
}

fn octahedron(r: f64) -> Solid {
    let vertices = vec![
        Point3::new(r, 0.0, 0.0),
        Point3::new(-r, 0.0, 0.0),
        Point3::new(0.0, r, 0.0),
        Point3::new(0.0, -r, 0.0),
        Point3::new(0.0, 0.0, r),
        Point3::new(0.0, 0.0, -r),
    ];
    let triangles = vec![
        [0, 2, 4],
        [2, 1, 4],
        [1, 3, 4],
        [3, 0, 4],
        [2, 0, 5],
        [1, 2, 5],
        [3, 1, 5],
        [0, 3, 5],
    ];
    Solid {
        vertices,
        triangles,
    }
}

fn tetrahedron(r: f64) -> Solid {
    let vertices = vec![
        Point3::new(r, r, r),
        Point3::new(r, -r, -r),
        Point3::new(-r, r, -r),
        Point3::new(-r, -r, r),
    ];
    let triangles = vec![[0, 1, 2], [0, 3, 1], [0, 2, 3], [1, 3, 2]];
    Solid {
        vertices,
        triangles,
    }
}

fn solid(kind: u8, size: f64) -> Solid {
    match kind % 3 {
        0 => cube(size),
        1 => octahedron(size),
        _ => tetrahedron(size),
    }
}

fn placed(s: &Solid, iso: &Isometry3<f64>) -> Solid {
    Solid {
        vertices: s.vertices.iter().map(|p| iso * p).collect(),
        triangles: s.triangles.clone(),
    }
}

fn exhaustive(a: &Solid, b: &Solid) -> bool {
    let c =
        |s: &Solid| Collider::new(TriMesh::new(s.vertices.clone(), s.triangles.clone()).unwrap());
    c(a).with_mode(Mode::Brute).collides_solid(&c(b))
}

fn reference(a: &Solid, b: &Solid) -> (bool, Certificate) {
    fn r(s: &Solid) -> ConvexMeshRef<'_> {
        ConvexMeshRef::new(&s.vertices, &s.triangles).unwrap()
    }
    let v = r(a).collides_solid(&r(b));
    (v.intersect, v.certificate)
}

fn iso(t: [f64; 3], axis: [f64; 3], angle: f64) -> Isometry3<f64> {
    let rotation = UnitQuaternion::from_scaled_axis(Vector3::from(axis).normalize() * angle);
    Isometry3::from_parts(Translation3::new(t[0], t[1], t[2]), rotation)
}

fn axis() -> impl Strategy<Value = [f64; 3]> {
    prop::array::uniform3(-1.0f64..1.0).prop_filter("non-zero axis", |a| {
        a.iter().map(|c| c * c).sum::<f64>() > 1e-3
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(600))]

    #[test]
    fn agrees_with_the_exhaustive_test(
        ka in 0u8..3, kb in 0u8..3,
        sa in 0.2f64..1.5, sb in 0.2f64..1.5,
        ta in prop::array::uniform3(-1.5f64..1.5), tb in prop::array::uniform3(-1.5f64..1.5),
        ra in axis(), rb in axis(), aa in 0.0f64..6.3, ab in 0.0f64..6.3,
    ) {
        let a = placed(&solid(ka, sa), &iso(ta, ra, aa));
        let b = placed(&solid(kb, sb), &iso(tb, rb, ab));
        let (got, how) = reference(&a, &b);
        prop_assert_eq!(got, exhaustive(&a, &b), "certificate {:?}", how);
    }
}

#[test]
fn random_placements_are_decided_by_certificates() {
    // Deterministic sweep: the certificates (not the fall-back) decide nearly everything.
    let mut exhaustive_runs = 0;
    let mut n = 0;
    for i in 0..2000u32 {
        let f =
            |k: u32| ((i.wrapping_mul(2654435761).wrapping_add(k * 40503)) % 1000) as f64 / 1000.0;
        let a = placed(
            &solid((i % 3) as u8, 1.0),
            &iso([0.0; 3], [1.0, f(1), f(2)], 6.0 * f(3)),
        );
        let b = placed(
            &solid((i / 3 % 3) as u8, 0.8),
            &iso(
                [3.0 * f(4) - 1.5, 3.0 * f(5) - 1.5, 3.0 * f(6) - 1.5],
                [f(7), 1.0, f(8)],
                6.0 * f(9),
            ),
        );
        let (got, how) = reference(&a, &b);
        assert_eq!(got, exhaustive(&a, &b), "placement {i}");
        exhaustive_runs += usize::from(how == Certificate::Exhaustive);
        n += 1;
    }
    assert!(
        exhaustive_runs * 100 < n,
        "{exhaustive_runs} of {n} needed the exhaustive test"
    );
}

#[test]
fn touching_faces_edges_and_vertices_count_as_intersecting() {
    let c = cube(0.5);
    for t in [
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [1.0, 1.0, 1.0],
        [1.0, 0.25, -0.5],
    ] {
        let b = placed(&c, &iso(t, [0.0, 0.0, 1.0], 0.0));
        assert!(reference(&c, &b).0, "touching at offset {t:?}");
        // Just apart (2^-40 is exact in binary): disjoint.
        let t2 = [t[0] + 2f64.powi(-40), t[1], t[2]];
        let b = placed(&c, &iso(t2, [0.0, 0.0, 1.0], 0.0));
        assert!(!reference(&c, &b).0, "apart at offset {t2:?}");
    }
}

#[test]
fn nested_solids_intersect() {
    let outer = cube(1.0);
    let inner = placed(
        &octahedron(0.3),
        &iso([0.1, -0.2, 0.3], [1.0, 2.0, 3.0], 0.7),
    );
    assert!(reference(&outer, &inner).0);
    assert!(reference(&inner, &outer).0);
    assert!(reference(&outer, &outer).0, "identical solids");
}
