//! Continuous collision against an independent exact implementation
//! ([`cga_collide::testing::ccd_oracle`]: rationals, no filter, a different decision method):
//! random motions on a small dyadic grid (frequent degeneracies), constructed degenerate
//! families (grazing double roots, coplanar sliding, crossings at a corner and one ulp past it,
//! contact exactly at `t = 0` and `t = 1`, zero-length edges, degenerate triangles), scaled
//! copies (powers of two from 2^-500 to 2^500 must not change the answer; powers of ten from
//! 1e-150 to 1e150), and the time of impact (bounds contain the oracle's earliest root, width at
//! most the tolerance, the safe time strictly before contact).

use std::path::{Path, PathBuf};

use cga_collide::motion::{self, load_queries, MovingPoint, QueryKind};
use cga_collide::nalgebra::Point3;
use cga_collide::testing::ccd_oracle::{self, Algebraic};
use proptest::prelude::*;

type Points = [[[f64; 3]; 2]; 4];

#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    VertexFace,
    EdgeEdge,
}

fn moving(p: &[[f64; 3]; 2]) -> MovingPoint {
    MovingPoint::new(
        Point3::new(p[0][0], p[0][1], p[0][2]),
        Point3::new(p[1][0], p[1][1], p[1][2]),
    )
}

fn library_touch(kind: Kind, pts: &Points) -> bool {
    let m: [MovingPoint; 4] = core::array::from_fn(|i| moving(&pts[i]));
    match kind {
        Kind::VertexFace => motion::vertex_face_touch(&m[0], &[m[1], m[2], m[3]]),
        Kind::EdgeEdge => motion::edge_edge_touch(&[m[0], m[1]], &[m[2], m[3]]),
    }
    .expect("finite")
}

fn library_first(kind: Kind, pts: &Points, tolerance: f64) -> Option<motion::ContactTime> {
    let m: [MovingPoint; 4] = core::array::from_fn(|i| moving(&pts[i]));
    match kind {
        Kind::VertexFace => {
            motion::vertex_face_first_contact(&m[0], &[m[1], m[2], m[3]], tolerance)
        }
        Kind::EdgeEdge => motion::edge_edge_first_contact(&[m[0], m[1]], &[m[2], m[3]], tolerance),
    }
    .expect("finite")
}

fn oracle(kind: Kind, pts: &Points) -> Option<Algebraic> {
    match kind {
        Kind::VertexFace => ccd_oracle::vertex_face_first_contact(pts),
        Kind::EdgeEdge => ccd_oracle::edge_edge_first_contact(pts),
    }
}

fn unfiltered(kind: Kind, pts: &Points) -> bool {
    match kind {
        Kind::VertexFace => motion::unfiltered::vertex_face_touch(pts),
        Kind::EdgeEdge => motion::unfiltered::edge_edge_touch(pts),
    }
}

const TOLERANCES: [f64; 5] = [0.0, 1e-15, 1e-9, 1e-3, f64::INFINITY];

/// The library's answers (filtered and unfiltered) and contact times agree with the oracle.
/// Returns the oracle's answer.
fn check(kind: Kind, pts: &Points) -> Result<bool, TestCaseError> {
    let truth = oracle(kind, pts);
    let touches = truth.is_some();
    prop_assert_eq!(
        library_touch(kind, pts),
        touches,
        "{:?} touch (oracle {:?}) on {:?}",
        kind,
        truth.as_ref().map(Algebraic::approx),
        pts
    );
    prop_assert_eq!(
        unfiltered(kind, pts),
        touches,
        "{:?} unfiltered on {:?}",
        kind,
        pts
    );
    for tolerance in TOLERANCES {
        let time = library_first(kind, pts, tolerance);
        prop_assert_eq!(
            time.is_some(),
            touches,
            "{:?} first contact (tol {}) on {:?}",
            kind,
            tolerance,
            pts
        );
        let (Some(time), Some(mut root)) = (time, truth.clone()) else {
            continue;
        };
        let at = root.approx();
        let ctx = || format!("{kind:?} tol {tolerance}: {time:?}, root in {at:?}, on {pts:?}");
        prop_assert!(
            0.0 <= time.lo() && time.lo() <= time.hi() && time.hi() <= 1.0,
            "{}",
            ctx()
        );
        // lo <= root <= hi, lo < root unless exact.
        let lo = root.cmp_f64(time.lo());
        let hi = root.cmp_f64(time.hi());
        prop_assert!(lo != std::cmp::Ordering::Less, "root below lo: {}", ctx());
        prop_assert!(
            hi != std::cmp::Ordering::Greater,
            "root above hi: {}",
            ctx()
        );
        if time.is_exact() {
            prop_assert_eq!(
                lo,
                std::cmp::Ordering::Equal,
                "exact but not the root: {}",
                ctx()
            );
        } else {
            prop_assert_eq!(
                lo,
                std::cmp::Ordering::Greater,
                "lo not strictly below: {}",
                ctx()
            );
        }
        if tolerance >= 1e-15 {
            prop_assert!(time.width() <= tolerance, "too wide: {}", ctx());
        }
        match time.safe_time() {
            Some(safe) => prop_assert_eq!(
                root.cmp_f64(safe),
                std::cmp::Ordering::Greater,
                "safe time {} not before contact: {}",
                safe,
                ctx()
            ),
            None => prop_assert_eq!(
                root.cmp_f64(0.0),
                std::cmp::Ordering::Equal,
                "no safe time but contact after 0: {}",
                ctx()
            ),
        }
    }
    Ok(touches)
}

fn scaled(pts: &Points, s: f64) -> Points {
    pts.map(|p| p.map(|x| x.map(|c| c * s)))
}

/// Checks `pts` and its scaled copies; powers of two must not change the answer.
fn check_scaled(kind: Kind, pts: &Points, two_exp: i32, ten_exp: i32) -> Result<(), TestCaseError> {
    let answer = check(kind, pts)?;
    let s = 2f64.powi(two_exp);
    let copy = scaled(pts, s);
    // Skip copies where a coordinate under- or overflowed (the scaling is then not exact).
    if copy
        .iter()
        .flatten()
        .flatten()
        .zip(pts.iter().flatten().flatten())
        .all(|(c, x)| c.is_finite() && c / s == *x)
    {
        let scaled_answer = check(kind, &copy)?;
        prop_assert_eq!(
            scaled_answer,
            answer,
            "scaling by 2^{} changed the answer",
            two_exp
        );
    }
    let copy = scaled(pts, 10f64.powi(ten_exp));
    if copy.iter().flatten().flatten().all(|c| c.is_finite()) {
        check(kind, &copy)?;
    }
    Ok(())
}

// ---- strategies ----

/// Grid values: multiples of 1/2 in [-2, 2] (many coincidences).
fn grid() -> impl Strategy<Value = f64> {
    (-4i32..=4).prop_map(|k| f64::from(k) / 2.0)
}

/// A moving point on the grid: still, or moving along one axis, or anywhere.
fn grid_point(planar: bool) -> impl Strategy<Value = [[f64; 3]; 2]> {
    ([grid(), grid(), grid()], [grid(), grid(), grid()], 0u8..4).prop_map(
        move |(mut a, mut b, mode)| {
            if planar {
                a[2] = 0.0;
                b[2] = 0.0;
            }
            match mode {
                0 => [a, a],
                1 => {
                    let mut c = a;
                    c[0] = b[0];
                    [a, c]
                }
                _ => [a, b],
            }
        },
    )
}

fn grid_query() -> impl Strategy<Value = Points> {
    prop_oneof![
        3 => [grid_point(false), grid_point(false), grid_point(false), grid_point(false)],
        1 => [grid_point(true), grid_point(true), grid_point(true), grid_point(true)],
    ]
}

fn kind() -> impl Strategy<Value = Kind> {
    prop_oneof![Just(Kind::VertexFace), Just(Kind::EdgeEdge)]
}

/// A power-of-two scale, a permutation of the axes and a dyadic translation: they keep every
/// coordinate exact for the small values used below, and so keep the answer.
fn placed(pts: Points, scale_exp: i32, perm: usize, shift: [i32; 3]) -> Points {
    const PERMS: [[usize; 3]; 6] = [
        [0, 1, 2],
        [0, 2, 1],
        [1, 0, 2],
        [1, 2, 0],
        [2, 0, 1],
        [2, 1, 0],
    ];
    let s = 2f64.powi(scale_exp);
    let p = PERMS[perm % 6];
    pts.map(|q| q.map(|x| core::array::from_fn(|i| x[p[i]] * s + f64::from(shift[i]))))
}

fn next(x: f64, steps: i8) -> f64 {
    let mut x = x;
    for _ in 0..steps.unsigned_abs() {
        x = if steps > 0 {
            x.next_up()
        } else {
            x.next_down()
        };
    }
    x
}

/// A small offset from zero, `steps · 2^-60` (not one ulp of zero, a subnormal: the oracle's
/// bisection down to 2^-1074 is slow; subnormal-sized inputs come from the scaled copies).
fn tiny(steps: i8) -> f64 {
    f64::from(steps) * 2f64.powi(-60)
}

/// Constructed degenerate families: `(kind, points)`.
fn degenerate(family: u8, a: f64, b: f64, ulps: i8) -> (Kind, Points) {
    let still = |x: [f64; 3]| [x, x];
    let unit = [
        still([0., 0., 0.]),
        still([1., 0., 0.]),
        still([0., 1., 0.]),
    ];
    match family % 10 {
        // Grazing double root: the triangle tilts about its edge y = 0 while the vertex moves
        // so that the coplanarity cubic is −(2t − 1)² (+ a perturbation of `ulps` ulps of z);
        // at t = 1/2 the vertex is at (a, b, 0).
        0 => {
            let p0 = [a, b - 1.0, next(-b, ulps)];
            let p1 = [a, b + 1.0, next(b, ulps)];
            (
                Kind::VertexFace,
                [[p0, p1], unit[0], unit[1], [[0., 1., -1.], [0., 1., 1.]]],
            )
        }
        // A vertex falling through z = 0 at (a, b) moved by some ulps (corners, edges).
        1 => {
            let (x, y) = (next(a, ulps), b);
            (
                Kind::VertexFace,
                [[[x, y, 1.0], [x, y, -1.0]], unit[0], unit[1], unit[2]],
            )
        }
        // Coplanar sliding: the vertex slides in z = 0 from (-1, b) to (a, b') (enters, grazes
        // a corner or stops short).
        2 => (
            Kind::VertexFace,
            [
                [[-1.0, next(b, ulps), 0.0], [a, next(b, -ulps), 0.0]],
                unit[0],
                unit[1],
                unit[2],
            ],
        ),
        // Contact exactly at t = 0 (vertex starts on the face, z perturbed by ulps) or at
        // t = 1 (ends there).
        3 => {
            let on = [a, b, tiny(ulps)];
            let off = [a, b, 1.0];
            let m = if ulps % 2 == 0 { [on, off] } else { [off, on] };
            (Kind::VertexFace, [m, unit[0], unit[1], unit[2]])
        }
        // Degenerate triangle: collinear corners (one in the middle), or collapsing at t = 1/2.
        4 => {
            let tri = if ulps % 2 == 0 {
                [
                    still([0., 0., 0.]),
                    still([2., 0., 0.]),
                    still([1., 0., 0.]),
                ]
            } else {
                [
                    [[0., -1., 0.], [0., 1., 0.]],
                    still([1., 0., 0.]),
                    [[0., 1., 0.], [0., -1., 0.]],
                ]
            };
            (
                Kind::VertexFace,
                [
                    [[a, next(b, ulps), 1.0], [a, next(-b, ulps), -1.0]],
                    tri[0],
                    tri[1],
                    tri[2],
                ],
            )
        }
        // Edge b falls through the still edge a = (0,0,0)-(1,0,0) at x = a (ends at 0 and 1,
        // one ulp past them with ulps).
        5 => {
            let x = next(a, ulps);
            (
                Kind::EdgeEdge,
                [
                    still([0., 0., 0.]),
                    still([1., 0., 0.]),
                    [[x, -1.0, 1.0], [x, -1.0, -1.0]],
                    [[x, 1.0, 1.0], [x, 1.0, -1.0]],
                ],
            )
        }
        // Edge b's endpoint comes down onto edge a (touching with an endpoint only).
        6 => (
            Kind::EdgeEdge,
            [
                still([0., 0., 0.]),
                still([1., 0., 0.]),
                [[a, tiny(ulps), 1.0], [a, tiny(ulps), 0.0]],
                [[a, 1.0, 1.0], [a, 1.0, 0.0]],
            ],
        ),
        // Zero-length edge for all t (a point) or at t = 1/2 (the ends swap).
        7 => {
            let ea = if ulps % 2 == 0 {
                [still([a, b, 0.0]), still([a, b, 0.0])]
            } else {
                [
                    [[a - 1.0, b, 0.0], [a + 1.0, b, 0.0]],
                    [[a + 1.0, b, 0.0], [a - 1.0, b, 0.0]],
                ]
            };
            (
                Kind::EdgeEdge,
                [
                    ea[0],
                    ea[1],
                    [[0.0, tiny(ulps), 1.0], [0.0, 0.0, -1.0]],
                    [[1.0, 0.0, 1.0], [1.0, tiny(-ulps), -1.0]],
                ],
            )
        }
        // Parallel and collinear edges sliding along one line (overlap, touch end to end, gap).
        8 => (
            Kind::EdgeEdge,
            [
                still([0., 0., 0.]),
                still([1., 0., 0.]),
                [[a + 2.0, 0.0, 0.0], [next(1.0 + b, ulps), 0.0, 0.0]],
                [[a + 3.0, 0.0, 0.0], [next(2.0 + b, ulps), 0.0, tiny(ulps)]],
            ],
        ),
        // Coplanar edges for all t, crossing or not (all z = 0).
        _ => (
            Kind::EdgeEdge,
            [
                still([0., 0., 0.]),
                still([1., 0., 0.]),
                [[a, 1.0, 0.0], [a, next(-b, ulps), 0.0]],
                [[b, 2.0, 0.0], [next(a, ulps), tiny(ulps), 0.0]],
            ],
        ),
    }
}

/// Interesting values for the constructed families: corners, edge midpoints, inside, outside.
fn special() -> impl Strategy<Value = f64> {
    prop_oneof![
        Just(0.0),
        Just(1.0),
        Just(0.5),
        Just(0.25),
        Just(-0.25),
        Just(0.75),
        Just(1.25),
        (-8i32..=8).prop_map(|k| f64::from(k) / 8.0),
    ]
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    #[test]
    fn random_grid_motions(kind in kind(), pts in grid_query()) {
        check(kind, &pts)?;
    }

    #[test]
    fn constructed_degenerate_families(
        family in 0u8..10,
        a in special(),
        b in special(),
        ulps in prop_oneof![Just(0i8), Just(1), Just(-1), -3i8..=3],
        scale_exp in -3i32..=3,
        perm in 0usize..6,
        shift in [-2i32..=2, -2i32..=2, -2i32..=2],
    ) {
        let (kind, pts) = degenerate(family, a, b, ulps);
        let answer = check(kind, &pts)?;
        // Axis permutations, powers of two and small integer translations keep every
        // coordinate exact when no ulp was added (multiples of 1/8 up to a few units), and
        // then change nothing.
        let moved = placed(pts, scale_exp, perm, shift);
        let moved_answer = check(kind, &moved)?;
        if ulps == 0 {
            prop_assert_eq!(moved_answer, answer, "placed copy {:?}", moved);
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(100))]

    #[test]
    fn scaled_copies(
        kind in kind(),
        pts in grid_query(),
        two_exp in prop_oneof![Just(-500i32), Just(500), -500i32..=500],
        ten_exp in prop_oneof![Just(-150i32), Just(150), -150i32..=150],
    ) {
        check_scaled(kind, &pts, two_exp, ten_exp)?;
    }

    #[test]
    fn scaled_degenerate_families(
        family in 0u8..10,
        a in special(),
        b in special(),
        ulps in -2i8..=2,
        two_exp in prop_oneof![Just(-500i32), Just(500), -500i32..=500],
        ten_exp in prop_oneof![Just(-150i32), Just(150), -150i32..=150],
    ) {
        let (kind, pts) = degenerate(family, a, b, ulps);
        check_scaled(kind, &pts, two_exp, ten_exp)?;
    }

    /// Random (not grid) motions in the unit cube, mostly near misses and clean hits.
    #[test]
    fn random_real_motions(
        kind in kind(),
        pts in prop::array::uniform4(prop::array::uniform2(prop::array::uniform3(-1.0f64..1.0))),
    ) {
        check(kind, &pts)?;
    }
}

fn query_files() -> Vec<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/fixtures/ccd/sample-queries");
    let mut files = Vec::new();
    for scene in std::fs::read_dir(&root).expect("fixtures") {
        let scene = scene.expect("entry").path();
        for kind in ["vertex-face", "edge-edge"] {
            if let Ok(entries) = std::fs::read_dir(scene.join(kind)) {
                files.extend(entries.map(|f| f.expect("entry").path()));
            }
        }
    }
    files.sort();
    files
}

/// A subset of the benchmark's sample queries (every 7th): the oracle agrees with the file's
/// truth, and the library's contact times contain the oracle's earliest root.
#[test]
fn sample_queries_subset_against_the_oracle() {
    let mut checked = 0;
    for file in query_files() {
        let kind = match QueryKind::from_path(&file).expect("kind folder") {
            QueryKind::VertexFace => Kind::VertexFace,
            QueryKind::EdgeEdge => Kind::EdgeEdge,
        };
        for (i, q) in load_queries(&file).expect("readable").iter().enumerate() {
            if i % 7 != 0 {
                continue;
            }
            let pts: Points = core::array::from_fn(|k| {
                let p = q.points[k];
                [
                    [p.start.x, p.start.y, p.start.z],
                    [p.end.x, p.end.y, p.end.z],
                ]
            });
            let touches =
                check(kind, &pts).unwrap_or_else(|e| panic!("{} query {i}: {e}", file.display()));
            assert_eq!(
                Some(touches),
                q.truth,
                "{} query {i}: oracle vs truth",
                file.display()
            );
            checked += 1;
        }
    }
    assert!(checked > 1000, "{checked} queries checked");
}
