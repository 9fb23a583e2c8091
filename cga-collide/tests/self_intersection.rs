//! Self-intersection against an exact rational oracle: the intersection of two triangles is
//! the convex hull of the end points of each edge's clip against the other triangle (a segment
//! or a point when that triangle is degenerate), and a pair is reported exactly when one of
//! those end points lies outside what the two share: the shared vertex, the shared edge, or
//! for a duplicated degenerate triangle the segment it is.
//!
//! The generated meshes run both ways a collider decides self-intersection: under
//! 32 triangles (the crate's `EAGER_TREE_MIN`) a scan without a tree, from 32 on the box tree.

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

fn is_zero3(v: &Q3) -> bool {
    v.iter().all(|c| c.is_zero())
}

/// The parameter interval of segment `ab` inside the closed triangle `t`, which may be
/// degenerate (then it is the segment between its two farthest corners, or a point).
fn clip(a: &Q3, b: &Q3, t: &[Q3; 3]) -> Option<(Rational, Rational)> {
    let n = cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]));
    if is_zero3(&n) {
        let (c, d) = extremes(t);
        return clip_segment(a, b, &c, &d);
    }
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

/// The two corners of a degenerate (collinear) triangle farthest apart: its hull is their
/// segment (a point when they are equal).
fn extremes(t: &[Q3; 3]) -> (Q3, Q3) {
    let len2 = |i: usize, j: usize| {
        let d = sub(&t[i], &t[j]);
        dot(&d, &d)
    };
    let (i, j) = [(0, 1), (1, 2), (0, 2)]
        .into_iter()
        .max_by(|&(a, b), &(c, d)| len2(a, b).cmp(&len2(c, d)))
        .unwrap();
    (t[i].clone(), t[j].clone())
}

/// The parameter interval of segment `ab` on the closed segment `cd` (either may be a point).
fn clip_segment(a: &Q3, b: &Q3, c: &Q3, d: &Q3) -> Option<(Rational, Rational)> {
    let u = sub(b, a);
    let uu = dot(&u, &u);
    if uu.is_zero() {
        return on_segment(a, c, d).then(|| (zero(), zero()));
    }
    let e = sub(d, c);
    let ca = sub(c, a);
    let n = cross(&u, &e);
    if is_zero3(&n) {
        // Parallel (or `cd` a point): only a collinear overlap counts.
        if !is_zero3(&cross(&u, &ca)) {
            return None;
        }
        let (tc, td) = (dot(&ca, &u) / &uu, dot(&sub(d, a), &u) / &uu);
        let (lo, hi) = if tc <= td { (tc, td) } else { (td, tc) };
        let (lo, hi) = (lo.max(zero()), hi.min(one()));
        return (lo <= hi).then_some((lo, hi));
    }
    if !dot(&n, &ca).is_zero() {
        return None; // skew lines
    }
    let nn = dot(&n, &n);
    let t = dot(&cross(&ca, &e), &n) / &nn;
    let s = dot(&cross(&ca, &u), &n) / &nn;
    let unit = |x: &Rational| !x.is_negative() && *x <= one();
    (unit(&t) && unit(&s)).then(|| (t.clone(), t))
}

/// Whether `x` lies on the closed segment `uv` (the point `u` when `u == v`).
fn on_segment(x: &Q3, u: &Q3, v: &Q3) -> bool {
    let (d, w) = (sub(v, u), sub(x, u));
    if is_zero3(&d) {
        return is_zero3(&w);
    }
    cross(&d, &w).iter().all(|c| c.is_zero()) && {
        let t = dot(&w, &d);
        !t.is_negative() && t <= dot(&d, &d)
    }
}

fn is_degenerate(t: &[Q3; 3]) -> bool {
    is_zero3(&cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0])))
}

/// The oracle: do the triangles (degenerate or not) meet outside what they share?
fn oracle(p: &[Q3; 3], r: &[Q3; 3]) -> bool {
    let mut shared: Vec<&Q3> = Vec::new();
    for x in p.iter().filter(|x| r.contains(x)) {
        if !shared.contains(&x) {
            shared.push(x);
        }
    }
    if shared.len() == 3 {
        // The same three positions: a proper triangle meets itself in its interior; a
        // degenerate one is the segment between its farthest corners, all of it shared.
        return !is_degenerate(p);
    }
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
        _ => unreachable!("three shared positions are handled above"),
    })
}

fn oracle_pairs(mesh: &TriMesh) -> Vec<(u32, u32)> {
    let tris: Vec<[Q3; 3]> = (0..mesh.num_triangles())
        .map(|i| mesh.corners(i as u32).map(|p| q3(&p)))
        .collect();
    let mut out = Vec::new();
    for i in 0..tris.len() {
        for j in i + 1..tris.len() {
            if oracle(&tris[i], &tris[j]) {
                out.push((i as u32, j as u32));
            }
        }
    }
    out
}

/// Meshes on few distinct lattice points: shared vertices and edges, coplanar overlaps, folds,
/// crossings and degenerate faces (collinear or repeated corners) are all frequent. `triangles`
/// sets how many, so that both the tree-less scan (under 32) and the tree (32 or more) run.
fn lattice_mesh(triangles: std::ops::Range<usize>) -> impl Strategy<Value = TriMesh> {
    let point = (-2i32..=2, -2i32..=2, -1i32..=1)
        .prop_map(|(x, y, z)| Point3::new(f64::from(x), f64::from(y), f64::from(z)));
    (
        proptest::collection::vec(point, 4..12),
        proptest::collection::vec((0u32..12, 0u32..12, 0u32..12), triangles),
    )
        .prop_map(|(mut v, t)| {
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
                .collect();
            TriMesh::new(v, tris).unwrap()
        })
}

fn check_against_the_oracle(mesh: &TriMesh) -> Result<(), TestCaseError> {
    let expected = oracle_pairs(mesh);
    let c = Collider::new(mesh.clone());
    let pairs = c.self_intersections();
    prop_assert_eq!(&pairs, &expected);
    prop_assert_eq!(c.self_intersects(), !expected.is_empty());
    prop_assert_eq!(
        &c.clone().with_mode(Mode::Brute).self_intersections(),
        &expected
    );
    let once = Collider::with_strategy(mesh.clone(), BuildStrategy::Morton);
    prop_assert_eq!(&once.self_intersections(), &expected);
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// Under 32 triangles: the scan without a tree.
    #[test]
    fn small_meshes_match_the_rational_oracle(mesh in lattice_mesh(2..32)) {
        check_against_the_oracle(&mesh)?;
    }

    /// Only degenerate faces (each a segment or a point), tree path included.
    #[test]
    fn degenerate_faces_match_the_rational_oracle(
        (v, t) in degenerate_lattice_mesh(),
    ) {
        check_against_the_oracle(&TriMesh::new(v, t).unwrap())?;
    }
}

proptest! {
    // Fewer cases: the oracle tests every pair of up to 63 triangles.
    #![proptest_config(ProptestConfig::with_cases(32))]

    /// 32 triangles or more: the box tree (built with the collider).
    #[test]
    fn tree_path_matches_the_rational_oracle(mesh in lattice_mesh(32..64)) {
        prop_assert!(mesh.num_triangles() >= 32);
        check_against_the_oracle(&mesh)?;
    }
}

/// Lattice points and faces each with a repeated corner or three collinear corners.
fn degenerate_lattice_mesh() -> impl Strategy<Value = (Vec<Point3<f64>>, Vec<[u32; 3]>)> {
    let point = (-2i32..=2, -2i32..=2, -1i32..=1).prop_map(|(x, y, z)| [x, y, z]);
    let face = (point.clone(), point, -1i32..=2, 0u8..3);
    (proptest::collection::vec(face, 2..48)).prop_map(|faces| {
        let mut v: Vec<[i32; 3]> = Vec::new();
        let mut index = |p: [i32; 3]| -> u32 {
            match v.iter().position(|q| *q == p) {
                Some(i) => i as u32,
                None => {
                    v.push(p);
                    (v.len() - 1) as u32
                }
            }
        };
        let tris = faces
            .into_iter()
            .map(|(a, b, k, shape)| {
                // The third corner on the line through a and b (a + k (b - a)), or a repeat.
                let c = [0, 1, 2].map(|i| a[i] + k * (b[i] - a[i]));
                let (ia, ib, ic) = (index(a), index(b), index(c));
                match shape {
                    0 => [ia, ib, ic],
                    1 => [ia, ia, ib],
                    _ => [ic, ia, ib],
                }
            })
            .collect();
        let v = v
            .into_iter()
            .map(|[x, y, z]| Point3::new(f64::from(x), f64::from(y), f64::from(z)))
            .collect();
        (v, tris)
    })
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
    /// the general 3D tests. Both must give the same pairs as the rational oracle, degenerate
    /// faces included.
    #[test]
    fn axis_plane_shortcuts_match_the_tilted_mesh((v, t) in planar_lattice_mesh()) {
        let tilted_mesh = placed(&v, &t, |x, y| [x, y, x + 2.0 * y]);
        let tilted = Collider::new(tilted_mesh.clone()).self_intersections();
        prop_assert_eq!(&tilted, &oracle_pairs(&tilted_mesh));
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
        }
    }
}
