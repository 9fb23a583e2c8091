//! Two colliders moving between poses (`Collider::contacts_during`, the trees refitted to swept
//! boxes) against the same motion as one deforming mesh (`motion::step_self_contacts`, its own
//! swept-box trees): the same touching pairs; and the first contact time brackets the earliest
//! root of those pairs, each computed by the independent exact oracle (`testing::ccd_oracle`).

use std::collections::BTreeSet;

use std::cmp::Ordering;

use cga_collide::motion::{step_self_contacts, MotionPair};
use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
use cga_collide::testing::ccd_oracle;
use cga_collide::{Collider, TriMesh};
use proptest::prelude::*;

fn pose(t: [f64; 3], r: [f64; 3]) -> Isometry3<f64> {
    Isometry3::new(Vector3::from(t), Vector3::from(r))
}

/// Each vertex of `m` at its two poses, as `[start, end]`.
fn tracks(m: &TriMesh, p: [&Isometry3<f64>; 2]) -> Vec<[[f64; 3]; 2]> {
    m.vertices()
        .iter()
        .map(|v| p.map(|pose| (pose * v).coords.into()))
        .collect()
}

/// The pair's earliest contact time, by the exact oracle (`None`: it never touches).
fn oracle_first_contact(
    pair: &MotionPair,
    ta: &[[[f64; 3]; 2]],
    tb: &[[[f64; 3]; 2]],
    (fa, fb): (&[[u32; 3]], &[[u32; 3]]),
) -> Option<ccd_oracle::Algebraic> {
    let (a, b) = (|i: u32| ta[i as usize], |i: u32| tb[i as usize]);
    match *pair {
        MotionPair::VertexFace(v, f) => {
            let [x, y, z] = fb[f as usize];
            ccd_oracle::vertex_face_first_contact(&[a(v), b(x), b(y), b(z)])
        }
        MotionPair::FaceVertex(f, v) => {
            let [x, y, z] = fa[f as usize];
            ccd_oracle::vertex_face_first_contact(&[b(v), a(x), a(y), a(z)])
        }
        MotionPair::EdgeEdge(e, g) => {
            ccd_oracle::edge_edge_first_contact(&[a(e[0]), a(e[1]), b(g[0]), b(g[1])])
        }
    }
}

/// The pairs joining the two parts of the merged mesh, as `MotionPair`s.
fn merged_pairs(
    a: &TriMesh,
    b: &TriMesh,
    pa: [&Isometry3<f64>; 2],
    pb: [&Isometry3<f64>; 2],
) -> BTreeSet<MotionPair> {
    let na = a.vertices().len() as u32;
    let fa = a.num_triangles() as u32;
    let place = |m: &TriMesh, p: &Isometry3<f64>| -> Vec<Point3<f64>> {
        m.vertices().iter().map(|v| p * v).collect()
    };
    let start: Vec<Point3<f64>> = [place(a, pa[0]), place(b, pb[0])].concat();
    let end: Vec<Point3<f64>> = [place(a, pa[1]), place(b, pb[1])].concat();
    let triangles: Vec<[u32; 3]> = a
        .triangles()
        .iter()
        .copied()
        .chain(b.triangles().iter().map(|t| t.map(|v| v + na)))
        .collect();
    let merged = TriMesh::new(start, triangles).expect("valid mesh");
    let step = step_self_contacts(&merged, &end, 1e-12).expect("valid step");
    let mut pairs = BTreeSet::new();
    for (v, f) in step.vertex_face {
        if v < na && f >= fa {
            pairs.insert(MotionPair::VertexFace(v, f - fa));
        } else if v >= na && f < fa {
            pairs.insert(MotionPair::FaceVertex(f, v - na));
        }
    }
    for (e, g) in step.edge_edge {
        if e[1] < na && g[0] >= na {
            pairs.insert(MotionPair::EdgeEdge(e, [g[0] - na, g[1] - na]));
        }
    }
    pairs
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    #[test]
    fn two_moving_colliders_agree_with_one_deforming_mesh(
        size in 0.2f64..1.5,
        t0 in prop::array::uniform3(-2.0f64..2.0),
        t1 in prop::array::uniform3(-2.0f64..2.0),
        r0 in prop::array::uniform3(-1.0f64..1.0),
        r1 in prop::array::uniform3(-1.0f64..1.0),
        grid in any::<bool>(),
    ) {
        // On a grid of quarters the motions touch exactly (faces meeting, edges crossing).
        let snap = |x: f64| if grid { (x * 4.0).round() / 4.0 } else { x };
        let a = TriMesh::cuboid(Point3::origin(), Point3::new(size, size, size)).unwrap();
        let b = TriMesh::cuboid(Point3::new(-0.5, -0.5, -0.5), Point3::new(0.5, 0.5, 0.5)).unwrap();
        let (ca, cb) = (Collider::new(a.clone()), Collider::new(b.clone()));
        let (p0, p1) = (pose(t0.map(snap), r0), pose(t1.map(snap), r1));
        let p0 = if grid { Isometry3::translation(p0.translation.x, p0.translation.y, p0.translation.z) } else { p0 };
        let p1 = if grid { Isometry3::translation(p1.translation.x, p1.translation.y, p1.translation.z) } else { p1 };
        let still = Isometry3::identity();
        let ours = ca.contacts_during([&p0, &p1], &cb, [&still, &still], 1e-12).unwrap();
        let expected = merged_pairs(&a, &b, [&p0, &p1], [&still, &still]);
        let got: BTreeSet<MotionPair> = ours.pairs.iter().copied().collect();
        prop_assert_eq!(&got, &expected);
        prop_assert_eq!(ours.first_contact.is_some(), !expected.is_empty());
        if let Some(first) = ours.first_contact {
            prop_assert!(first.width() <= 1e-12 || first.lo().next_up() >= first.hi());
            prop_assert!(!ours.first_pairs.is_empty());
            prop_assert!(ours.first_pairs.iter().all(|p| got.contains(p)));
            // lo <= t* <= hi for t* the earliest of the pairs' exact first contacts: none
            // before lo, at least one at or before hi, and each of those among `first_pairs`.
            let (ta, tb) = (tracks(&a, [&p0, &p1]), tracks(&b, [&still, &still]));
            let mut attained = false;
            for pair in &expected {
                let root = oracle_first_contact(pair, &ta, &tb, (a.triangles(), b.triangles()));
                let Some(mut root) = root else {
                    return Err(TestCaseError::fail(format!("{pair:?} touches, not for the oracle")));
                };
                prop_assert_ne!(root.cmp_f64(first.lo()), Ordering::Less, "{:?} before lo", pair);
                if root.cmp_f64(first.hi()) != Ordering::Greater {
                    attained = true;
                    prop_assert!(ours.first_pairs.contains(pair), "{:?} not in first_pairs", pair);
                }
            }
            prop_assert!(attained, "no pair's contact at or before {}", first.hi());
        }
    }
}

#[test]
fn poses_are_checked() {
    let c = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0)).unwrap());
    let mut bad = Isometry3::identity();
    bad.translation.x = f64::NAN;
    let still = Isometry3::identity();
    assert!(c
        .contacts_during([&still, &bad], &c, [&still, &still], 0.0)
        .is_err());
}
