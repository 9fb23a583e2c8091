//! Self-intersection against an exact rational oracle: the intersection of two triangles is
//! the convex hull of the end points of each edge's clip against the other triangle, and a pair
//! is reported exactly when one of those end points lies outside the shared vertex or edge.

use cga_collide::ga_core::scalar::{rational_from_f64, Rational, Ring};
use cga_collide::nalgebra::Point3;

use cga_collide::bounding::BuildStrategy;
use cga_collide::collider::{Collider, Mode};
use cga_collide::TriMesh;
use num_traits::Signed;
use proptest::prelude::*;

type Q3 = [Rational; 3];

fn q3(p: &Point3<f64>) -> Q3 {
    [p.x, p.y, p.z].map(|x| rational_from_f64(x).unwrap())
}
fn sub(a: &Q3, b: &Q3) -> Q3 {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}
fn dot(a: &Q3, b: &Q3) -> Rational {
    &a[0] * &b[0] + &a[1] * &b[1] + &a[2] * &b[2]
}
fn cross(u: &Q3, v: &Q3) -> Q3 {
    [
        &u[1] * &v[2] - &u[2] * &v[1],
        &u[2] * &v[0] - &u[0] * &v[2],
        &u[0] * &v[1] - &u[1] * &v[0],
    ]
}
fn at(a: &Q3, b: &Q3, t: &Rational) -> Q3 {
    let d = sub(b, a);
    [&a[0] + &d[0] * t, &a[1] + &d[1] * t, &a[2] + &d[2] * t]
}
fn zero() -> Rational {
    <Rational as Ring>::zero()
}
fn one() -> Rational {
    <Rational as Ring>::one()
}

/// The parameter interval of segment `ab` inside the non-degenerate triangle `t`.
fn clip(a: &Q3, b: &Q3, t: &[Q3; 3]) -> Option<(Rational, Rational)> {
    let n = cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]));
    // Inside iff every edge function is >= 0; each is affine along the segment.
    let edge = |x: &Q3, i: usize| dot(&cross(&sub(&t[(i + 1) % 3], &t[i]), &sub(x, &t[i])), &n);
    let (da, db) = (dot(&n, &sub(a, &t[0])), dot(&n, &sub(b, &t[0])));
    let (mut lo, mut hi) = (zero(), one());
    if da.is_zero() && db.is_zero() {
        for i in 0..3 {
            let (f0, f1) = (edge(a, i), edge(b, i));
            let slope = &f1 - &f0;
            if slope.is_zero() {
                if f0.is_negative() {
                    return None;
                }
            } else {
                let root = -&f0 / &slope; // f0 + slope * t >= 0
                if slope.is_positive() {
                    lo = lo.max(root);
                } else {
                    hi = hi.min(root);
                }
            }
        }
        return (lo <= hi).then_some((lo, hi));
    }
    if (da.is_positive() && db.is_positive()) || (da.is_negative() && db.is_negative()) {
        return None;
    }
    let s = &da / (&da - &db);
    let x = at(a, b, &s);
    (0..3)
        .all(|i| !edge(&x, i).is_negative())
        .then_some((s.clone(), s))
}

fn on_segment(x: &Q3, u: &Q3, v: &Q3) -> bool {
    let (d, w) = (sub(v, u), sub(x, u));
    cross(&d, &w).iter().all(|c| c.is_zero()) && {
        let t = dot(&w, &d);
        !t.is_negative() && t <= dot(&d, &d)
    }
}

/// The oracle: do the non-degenerate triangles meet outside their shared vertices/edge?
fn oracle(p: &[Q3; 3], r: &[Q3; 3]) -> bool {
    let shared: Vec<&Q3> = p.iter().filter(|x| r.contains(x)).collect();
    let mut ends = Vec::new();
    for (s, t) in [(p, r), (r, p)] {
        for i in 0..3 {
            let (a, b) = (&s[i], &s[(i + 1) % 3]);
            if let Some((t0, t1)) = clip(a, b, t) {
                ends.push(at(a, b, &t0));
                ends.push(at(a, b, &t1));
            }
        }
    }
    ends.iter().any(|x| match shared.as_slice() {
        [] => true,
        [v] => x != *v,
        [u, v] => !on_segment(x, u, v),
        _ => false, // the same triangle: handled by the caller
    })
}

fn oracle_pairs(mesh: &TriMesh) -> Vec<(u32, u32)> {
    let tris: Vec<[Q3; 3]> = (0..mesh.num_triangles())
        .map(|i| mesh.corners(i as u32).map(|p| q3(&p)))
        .collect();
    let mut out = Vec::new();
    for i in 0..tris.len() {
        for j in i + 1..tris.len() {
            let same = tris[i].iter().all(|x| tris[j].contains(x));
            if same || oracle(&tris[i], &tris[j]) {
                out.push((i as u32, j as u32));
            }
        }
    }
    out
}

fn non_degenerate(v: &[Point3<f64>], t: &[u32; 3]) -> bool {
    let [a, b, c] = t.map(|i| q3(&v[i as usize]));
    cross(&sub(&b, &a), &sub(&c, &a))
        .iter()
        .any(|x| !x.is_zero())
}

/// Small meshes on few distinct lattice points: shared vertices and edges, coplanar overlaps,
/// folds and crossings are all frequent.
fn lattice_mesh() -> impl Strategy<Value = TriMesh> {
    let point = (-2i32..=2, -2i32..=2, -1i32..=1)
        .prop_map(|(x, y, z)| Point3::new(f64::from(x), f64::from(y), f64::from(z)));
    (
        proptest::collection::vec(point, 4..8),
        proptest::collection::vec((0u32..8, 0u32..8, 0u32..8), 2..10),
    )
        .prop_filter_map("need triangles", |(mut v, t)| {
            v.sort_by(|a, b| {
                a.coords
                    .as_slice()
                    .partial_cmp(b.coords.as_slice())
                    .unwrap()
            });
            v.dedup();
            let n = v.len() as u32;
            let tris: Vec<[u32; 3]> = t
                .into_iter()
                .map(|(a, b, c)| [a % n, b % n, c % n])
                .filter(|t| non_degenerate(&v, t))
                .collect();
            (tris.len() >= 2).then(|| TriMesh::new(v, tris).unwrap())
        })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn matches_the_rational_oracle(mesh in lattice_mesh()) {
        let c = Collider::new(mesh.clone());
        let pairs = c.self_intersections();
        prop_assert_eq!(&pairs, &oracle_pairs(&mesh));
        prop_assert_eq!(c.self_intersects(), !pairs.is_empty());
        prop_assert_eq!(&c.clone().with_mode(Mode::Brute).self_intersections(), &pairs);
    }
}

fn p(x: f64, y: f64, z: f64) -> Point3<f64> {
    Point3::new(x, y, z)
}

#[test]
fn closed_meshes_without_self_intersection() {
    let cube = TriMesh::cuboid(p(0., 0., 0.), p(1., 1., 1.)).unwrap();
    assert!(Collider::new(cube.subdivided())
        .self_intersections()
        .is_empty());
    assert!(Collider::new(TriMesh::bunny00())
        .self_intersections()
        .is_empty());
}

#[test]
fn adjacent_triangles() {
    let v = vec![
        p(0., 0., 0.),
        p(2., 0., 0.),
        p(1., 1., 0.),
        p(1., 2., 0.),
        p(1., -1., 0.),
        p(2., 0.5, 0.),
    ];
    let check = |tris: Vec<[u32; 3]>, expected: Vec<(u32, u32)>| {
        let mesh = TriMesh::new(v.clone(), tris).unwrap();
        assert_eq!(Collider::new(mesh).self_intersections(), expected);
    };
    // Shared edge, opposite sides in the plane: only the edge.
    check(vec![[0, 1, 2], [1, 0, 4]], vec![]);
    // Shared edge, same side (folded flat): reported.
    check(vec![[0, 1, 2], [1, 0, 3]], vec![(0, 1)]);
    // Shared vertex only, coplanar and overlapping: reported.
    check(vec![[0, 1, 2], [0, 5, 3]], vec![(0, 1)]);
    // A duplicated triangle.
    check(vec![[0, 1, 2], [2, 1, 0]], vec![(0, 1)]);
    // Shared vertex, the second triangle folded through the first.
    let w = vec![
        p(0., 0., 0.),
        p(2., 0., 0.),
        p(0., 2., 0.),
        p(1., 1., 1.),
        p(1., 0.5, -1.),
    ];
    let mesh = TriMesh::new(w, vec![[0, 1, 2], [0, 3, 4]]).unwrap();
    assert_eq!(Collider::new(mesh).self_intersections(), vec![(0, 1)]);
}

/// Triangles on a few lattice points of a plane, degenerate ones (collinear or repeated
/// corners) included, as 2D points and index triples; up to 40 triangles, so that both the
/// tiny-mesh scan and the tree are used.
fn planar_lattice_mesh() -> impl Strategy<Value = (Vec<[i32; 2]>, Vec<[u32; 3]>)> {
    (
        proptest::collection::vec((-2i32..=2, -2i32..=2).prop_map(|(x, y)| [x, y]), 3..10),
        proptest::collection::vec((0u32..10, 0u32..10, 0u32..10), 2..40),
    )
        .prop_map(|(mut v, t)| {
            v.sort_unstable();
            v.dedup();
            let n = v.len() as u32;
            let tris = t
                .into_iter()
                .map(|(a, b, c)| [a % n, b % n, c % n])
                .collect();
            (v, tris)
        })
}

/// The planar mesh placed by `f`, an injective affine map: intersections are preserved.
fn placed(v: &[[i32; 2]], t: &[[u32; 3]], f: impl Fn(f64, f64) -> [f64; 3]) -> TriMesh {
    let vertices = v
        .iter()
        .map(|&[x, y]| {
            let [a, b, c] = f(f64::from(x), f64::from(y));
            Point3::new(a, b, c)
        })
        .collect();
    TriMesh::new(vertices, t.to_vec()).unwrap()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(256))]

    /// Faces in one axis-parallel plane are decided in its projection (corners at shared
    /// vertices, segments for degenerate faces); the same mesh in a tilted plane goes through
    /// the general 3D tests. Both must give the same pairs, and the rational oracle where no
    /// face is degenerate.
    #[test]
    fn axis_plane_shortcuts_match_the_tilted_mesh((v, t) in planar_lattice_mesh()) {
        let tilted = Collider::new(placed(&v, &t, |x, y| [x, y, x + 2.0 * y])).self_intersections();
        for flat in [
            placed(&v, &t, |x, y| [x, y, 0.5]),
            placed(&v, &t, |x, y| [-3.0, x, y]),
            placed(&v, &t, |x, y| [y, 7.0, x]),
        ] {
            let c = Collider::new(flat.clone());
            prop_assert_eq!(&c.self_intersections(), &tilted);
            prop_assert_eq!(c.self_intersects(), !tilted.is_empty());
            prop_assert_eq!(&c.with_mode(Mode::Brute).self_intersections(), &tilted);
            let once = Collider::with_strategy(flat.clone(), BuildStrategy::Morton);
            prop_assert_eq!(&once.self_intersections(), &tilted);
            let all_proper = t.iter().all(|tri| non_degenerate(flat.vertices(), tri));
            if all_proper {
                prop_assert_eq!(&tilted, &oracle_pairs(&flat));
            }
        }
    }
}
