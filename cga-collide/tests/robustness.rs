//! Every public mesh entry point, driven with finite meshes at every scale `f64` holds: from
//! subnormal coordinates (`1e-320`) to `1e308`, mixed scales within one mesh, both signs,
//! degenerate triangles, and finite poses with translations up to `1e308`.
//!
//! Each call must give an answer or a typed [`Error`] with a message, never panic; a
//! [`CertifiedDistance`] that is returned is finite in every field; `exact_distance` answers
//! whenever `distance` does; and both [`Mode`]s give the same answer.

use cga_collide::collider::{Collider, Mode, PosePair};
use cga_collide::nalgebra::{Isometry3, Point3, Quaternion, Translation3, UnitQuaternion};
use cga_collide::query::CertifiedDistance;
use cga_collide::{Ball, Error, Segment, Sphere, TriMesh, Triangle};
use proptest::prelude::*;

/// `10^e`, correctly rounded (subnormal for `e < -307`, zero below `-323`).
fn ten_to(e: i32) -> f64 {
    format!("1e{e}").parse().expect("a decimal power of ten")
}

/// A coordinate: a small mantissa of either sign times `10^e`, `|x| ≤ 1e308`.
fn coordinate() -> impl Strategy<Value = f64> {
    (-4i32..=4, -320i32..=308).prop_map(|(m, e)| f64::from(m) / 4.0 * ten_to(e))
}

/// The corners of a small base mesh: coordinates in `{-1, -3/4, …, 1}`.
fn base_point() -> impl Strategy<Value = [f64; 3]> {
    [-4i32..=4, -4i32..=4, -4i32..=4].prop_map(|c| c.map(|x| f64::from(x) / 4.0))
}

/// Up to four triangles over up to five vertices; repeated indices and collinear corners
/// (degenerate triangles) come up often with so few distinct coordinates.
fn base_triangles() -> impl Strategy<Value = (Vec<[f64; 3]>, Vec<[u32; 3]>)> {
    prop::collection::vec(base_point(), 1..=5).prop_flat_map(|vs| {
        let n = vs.len() as u32;
        let tri = [0..n, 0..n, 0..n];
        (Just(vs), prop::collection::vec(tri, 1..=4))
    })
}

fn mesh_of(vs: &[[f64; 3]], ts: Vec<[u32; 3]>, scale: impl Fn(usize, f64) -> f64) -> TriMesh {
    let vertices = vs
        .iter()
        .enumerate()
        .map(|(i, v)| Point3::from(v.map(|x| scale(i, x))))
        .collect();
    TriMesh::new(vertices, ts).expect("finite coordinates and indices in range")
}

/// A small finite mesh at any scale: a base mesh times `10^e` (one scale for the whole mesh,
/// or one per vertex), or a cuboid with corners at any scale.
fn mesh() -> impl Strategy<Value = TriMesh> {
    prop_oneof![
        (base_triangles(), -320i32..=308)
            .prop_map(|((vs, ts), e)| mesh_of(&vs, ts, |_, x| x * ten_to(e))),
        (
            base_triangles(),
            prop::collection::vec(-320i32..=308, 5),
            prop::collection::vec(prop::bool::ANY, 5)
        )
            .prop_map(|((vs, ts), es, signs)| mesh_of(&vs, ts, |i, x| {
                let s = if signs[i] { -1.0 } else { 1.0 };
                s * x * ten_to(es[i])
            })),
        (
            [coordinate(), coordinate(), coordinate()],
            [coordinate(), coordinate(), coordinate()]
        )
            .prop_map(|(p, q)| {
                let lo = Point3::new(p[0].min(q[0]), p[1].min(q[1]), p[2].min(q[2]));
                let hi = Point3::new(p[0].max(q[0]), p[1].max(q[1]), p[2].max(q[2]));
                TriMesh::cuboid(lo, hi).expect("finite, ordered corners")
            }),
    ]
}

/// A finite pose: a unit quaternion and a translation with components up to `1e308`.
fn pose() -> impl Strategy<Value = Isometry3<f64>> {
    (
        [-8i32..=8, -8i32..=8, -8i32..=8, -8i32..=8],
        [coordinate(), coordinate(), coordinate()],
        prop::bool::ANY,
    )
        .prop_map(|(q, t, identity_rotation)| {
            let q = q.map(f64::from);
            let rotation = if identity_rotation || q.iter().all(|&x| x == 0.0) {
                UnitQuaternion::identity()
            } else {
                UnitQuaternion::from_quaternion(Quaternion::new(q[0], q[1], q[2], q[3]))
            };
            Isometry3::from_parts(Translation3::new(t[0], t[1], t[2]), rotation)
        })
}

fn point() -> impl Strategy<Value = Point3<f64>> {
    [coordinate(), coordinate(), coordinate()].prop_map(Point3::from)
}

/// The shapes the hit queries take, at any scale.
#[derive(Debug, Clone)]
struct Shapes {
    point: Point3<f64>,
    segment: Segment,
    triangle: Triangle,
    sphere: Sphere,
    ball: Ball,
}

fn shapes() -> impl Strategy<Value = Shapes> {
    (
        [point(), point(), point(), point()],
        coordinate(),
        coordinate(),
    )
        .prop_map(|([p, q, r, s], r1, r2)| Shapes {
            point: p,
            segment: Segment::new(p, q).expect("finite"),
            triangle: Triangle::new(p, q, r).expect("finite"),
            sphere: Sphere::new(s, r1.abs()).expect("finite radius"),
            ball: Ball::new(q, r2.abs()).expect("finite radius"),
        })
}

/// Clearances: any scale, plus the values with a fixed answer.
fn clearance() -> impl Strategy<Value = f64> {
    prop_oneof![
        4 => coordinate().prop_map(f64::abs),
        1 => Just(0.0),
        1 => Just(-1.0),
        1 => Just(f64::INFINITY),
        1 => Just(f64::NAN),
    ]
}

/// A rejection must say why.
fn typed(e: &Error) -> String {
    let message = e.to_string();
    assert!(!message.is_empty(), "empty message for {e:?}");
    format!("Err({e:?})")
}

/// A certified distance is finite in every field, or an error.
fn certified(r: &Result<CertifiedDistance, Error>) -> String {
    match r {
        Ok(d) => {
            assert!(d.distance.is_finite() && d.distance >= 0.0, "{d:?}");
            assert!(d.error_bound.is_finite() && d.error_bound >= 0.0, "{d:?}");
            assert!(d.witness_a.iter().all(|x| x.is_finite()), "{d:?}");
            assert!(d.witness_b.iter().all(|x| x.is_finite()), "{d:?}");
            format!("{d:?}")
        }
        Err(e) => typed(e),
    }
}

fn shown<T: std::fmt::Debug>(r: Result<T, Error>) -> String {
    match r {
        Ok(x) => format!("Ok({x:?})"),
        Err(e) => typed(&e),
    }
}

/// `unit()` is finite, centred, with largest side 1 (or 0 when all vertices coincide).
fn check_unit(m: &TriMesh) -> TriMesh {
    let u = m.unit();
    assert!(
        u.vertices().iter().all(|v| v.iter().all(|x| x.is_finite())),
        "{u:?}"
    );
    let (lo, hi) = u.bounds();
    let side = (hi - lo).max();
    assert!(
        side == 0.0 || (side - 1.0).abs() <= 1e-12,
        "side {side} of {u:?}"
    );
    u
}

/// Every entry point on `(a, b)` in one mode, its answers in order (for comparing modes).
fn answers(
    a: &Collider,
    b: &Collider,
    (pa, pb): (&Isometry3<f64>, &Isometry3<f64>),
    s: &Shapes,
    c: f64,
    exact: bool,
) -> Vec<String> {
    let mut out = Vec::new();
    let id = Isometry3::identity();
    let poses = [PosePair::new(*pa, *pb), PosePair::new(id, id)];

    // One frame.
    out.push(format!("{:?}", a.collides(b)));
    out.push(format!("{:?}", a.intersecting_pairs(b)));
    out.push(format!("{:?}", a.collides_solid(b)));
    out.push(format!("{:?}", a.within_distance(b, c)));
    out.push(format!("{:?}", a.pairs_within_distance(b, c)));
    let d = a.distance(b);
    out.push(certified(&d));
    if exact {
        // Exact rationals on coordinates `2^2000` apart in scale are slow: run in one mode.
        let exact = a.exact_distance(b);
        assert_eq!(d.is_ok(), exact.is_ok(), "{d:?} but {exact:?}");
        shown(exact);
    }
    out.push(format!("{:?}", a.contact_class(b)));
    out.push(format!("{:?}", a.contacts(b)));
    out.push(format!("{:?}", a.self_intersections()));
    out.push(format!("{:?}", a.self_intersects()));
    out.push(format!("{:?}", a.contains_point(&s.point)));
    out.push(format!("{:?}", a.segment_hits(&s.segment)));
    out.push(format!("{:?}", a.triangle_hits(&s.triangle)));
    out.push(format!("{:?}", a.sphere_hits(&s.sphere)));
    out.push(format!("{:?}", a.ball_hits(&s.ball)));
    out.push(format!(
        "{:?}",
        a.spheres_hits(&[s.sphere, Sphere::new(s.point, 0.0).unwrap()])
    ));

    // Under poses.
    out.push(shown(a.collides_at(pa, b, pb)));
    out.push(shown(a.intersecting_pairs_at(pa, b, pb)));
    out.push(shown(a.collides_solid_at(pa, b, pb)));
    out.push(shown(a.within_distance_at(pa, b, pb, c)));
    out.push(shown(a.pairs_within_distance_at(pa, b, pb, c)));
    out.push(certified(&a.distance_at(pa, b, pb)));
    out.push(shown(a.contact_class_at(pa, b, pb)));
    out.push(shown(a.contacts_at(pa, b, pb)));
    out.push(shown(a.contains_point_at(pa, &s.point)));
    out.push(shown(a.segment_hits_at(pa, &s.segment)));
    out.push(shown(a.triangle_hits_at(pa, &s.triangle)));
    out.push(shown(a.sphere_hits_at(pa, &s.sphere)));
    out.push(shown(a.ball_hits_at(pa, &s.ball)));
    out.push(shown(a.placed(pa).map(|p| p.mesh().clone())));

    // Many poses.
    out.push(shown(a.collides_batch(b, &poses)));
    out.push(shown(a.intersecting_pairs_batch(b, &poses)));
    out.push(shown(a.collides_solid_batch(b, &poses)));
    out.push(shown(a.within_distance_batch(b, &poses, c)));
    let ds = a.distance_batch(b, &poses);
    if let Ok(ds) = &ds {
        for d in ds {
            certified(&Ok(*d));
        }
    }
    out.push(shown(ds));
    out
}

/// Both modes, on the meshes as given and after `unit()`; `transformed` by both poses.
fn exercise(
    a: &TriMesh,
    b: &TriMesh,
    pa: &Isometry3<f64>,
    pb: &Isometry3<f64>,
    s: &Shapes,
    c: f64,
) {
    for m in [a, b] {
        for pose in [pa, pb] {
            match m.transformed(pose) {
                Ok(t) => assert!(t.vertices().iter().all(|v| v.iter().all(|x| x.is_finite()))),
                Err(e) => {
                    typed(&e);
                }
            }
        }
    }
    let (ua, ub) = (check_unit(a), check_unit(b));
    for (a, b) in [(a, b), (&ua, &ub), (a, &ub)] {
        let bvh = answers(
            &Collider::new(a.clone()),
            &Collider::new(b.clone()),
            (pa, pb),
            s,
            c,
            true,
        );
        let brute = answers(
            &Collider::new(a.clone()).with_mode(Mode::Brute),
            &Collider::new(b.clone()).with_mode(Mode::Brute),
            (pa, pb),
            s,
            c,
            false,
        );
        for (k, (x, y)) in bvh.iter().zip(&brute).enumerate() {
            assert_eq!(x, y, "answer {k} differs between Mode::Bvh and Mode::Brute");
        }
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(20))]

    #[test]
    fn every_entry_point_answers_at_every_scale(
        a in mesh(),
        b in mesh(),
        pa in pose(),
        pb in pose(),
        s in shapes(),
        c in clearance(),
    ) {
        exercise(&a, &b, &pa, &pb, &s, c);
    }

}

proptest! {
    // Every triangle pair of a mesh against itself touches: the exact tests then run on all of
    // them, on rationals up to `2^2000` apart in scale, so fewer cases.
    #![proptest_config(ProptestConfig::with_cases(6))]

    /// The same mesh twice: touching, overlapping and coplanar cases at any scale.
    #[test]
    fn a_mesh_against_itself_at_every_scale(
        a in mesh(),
        pa in pose(),
        s in shapes(),
        c in clearance(),
    ) {
        exercise(&a, &a, &pa, &pa, &s, c);
    }
}

fn cube(lo: f64, hi: f64) -> TriMesh {
    TriMesh::cuboid(Point3::new(lo, lo, lo), Point3::new(hi, hi, hi)).unwrap()
}

#[test]
fn a_subnormal_cube_made_unit_meets_the_bunny() {
    let tiny = cube(0.0, 1e-320);
    let unit = tiny.unit();
    let (lo, hi) = unit.bounds();
    assert_eq!((hi - lo).max(), 1.0);
    assert_eq!(lo, Point3::new(-0.5, -0.5, -0.5));
    let bunny = TriMesh::bunny().unit();
    for mode in [Mode::Bvh, Mode::Brute] {
        let a = Collider::new(unit.clone()).with_mode(mode);
        let b = Collider::new(bunny.clone()).with_mode(mode);
        let pairs = a.intersecting_pairs(&b);
        assert!(!pairs.is_empty());
        assert!(a.collides(&b));
        assert!(a.collides_solid(&b));
        let d = a.distance(&b).unwrap();
        assert_eq!(d.distance, 0.0);
        let id = Isometry3::identity();
        assert_eq!(a.intersecting_pairs_at(&id, &b, &id).unwrap(), pairs);
    }
    // The subnormal cube itself: every answer finite.
    let a = Collider::new(tiny.clone());
    let b = Collider::new(tiny.clone())
        .placed(&Isometry3::translation(2e-320, 0.0, 0.0))
        .unwrap();
    let d = a.distance(&b).unwrap();
    assert!(d.distance.is_finite() && d.error_bound.is_finite());
    assert!(!a.collides(&b));
    assert!(a.exact_distance(&b).is_ok());
}

#[test]
fn meshes_near_the_top_of_f64_get_out_of_range_not_nan() {
    let a = Collider::new(cube(1e307, 1.5e308));
    let b = Collider::new(cube(-1.7e308, -1e308));
    let out_of_range = |r: Result<CertifiedDistance, Error>| match r {
        Err(Error::OutOfRange { magnitude, limit }) => {
            assert!(magnitude.is_finite() && limit.is_finite() && magnitude > limit)
        }
        other => panic!("expected Error::OutOfRange, got {other:?}"),
    };
    out_of_range(a.distance(&b));
    let id = Isometry3::identity();
    out_of_range(a.distance_at(&id, &b, &id));
    assert!(matches!(
        a.exact_distance(&b),
        Err(Error::OutOfRange { .. })
    ));
    match a.distance_batch(&b, &[PosePair::new(id, id)]) {
        Err(Error::InBatch { index: 0, source }) => {
            assert!(matches!(*source, Error::OutOfRange { .. }))
        }
        other => panic!("expected Error::InBatch, got {other:?}"),
    }
    // The boolean questions still answer.
    assert!(!a.collides(&b));
    assert!(!a.within_distance(&b, 1e308));
    assert!(a.within_distance(&b, f64::INFINITY));
}

#[test]
fn a_batch_reports_its_first_refused_pose() {
    let cube = Collider::new(cube(0.0, 1.0));
    let id = Isometry3::identity();
    let nan = Isometry3::translation(f64::NAN, 0.0, 0.0);
    let mut poses = vec![PosePair::new(id, id)];
    poses.extend((0..256).map(|_| PosePair::new(id, nan)));
    for mode in [Mode::Bvh, Mode::Brute] {
        let a = cube.clone().with_mode(mode);
        for _ in 0..8 {
            let first = |r: Result<(), Error>| match r {
                Err(Error::InBatch { index, source }) => {
                    assert_eq!(index, 1, "{mode:?}");
                    assert_eq!(*source, Error::NonFinitePose);
                }
                other => panic!("expected Error::InBatch, got {other:?}"),
            };
            first(a.collides_batch(&a, &poses).map(drop));
            first(a.intersecting_pairs_batch(&a, &poses).map(drop));
            first(a.collides_solid_batch(&a, &poses).map(drop));
            first(a.within_distance_batch(&a, &poses, 0.5).map(drop));
            first(a.distance_batch(&a, &poses).map(drop));
        }
    }
}
