//! Adversarial shape pairs with exact answers, written as the command line's JSON lines.
//!
//! Families (each a fixture file under `cga-collide/cli/tests/data/shapes/`):
//! * `random`: generic pairs of every pair type; polytopal pairs and half-space, ball and
//!   cylinder pairs answered by the oracle, other round pairs by an inner and an outer polytope
//!   (a pair is kept only when those two decide it).
//! * `polytopal_touching`: two shapes put in contact at extreme points along an axis (exact
//!   dyadic translation), then moved one ulp out and in, in their frame and under an exact
//!   integer rotation; answered by the oracle.
//! * `curved_contacts`, `curved_scales`: the constructed cylinder and cone contacts
//!   ([`super::construct`]), at scale 1 and at `2^±332` (about `1e±100`).
//! * `polytopal_scales`: random and touching pairs at `2^±332` and a tiny shape against a
//!   huge one.
//! * `degenerate`: radius 0, flat and collapsed cuboids, point, collinear and coplanar hulls,
//!   degenerate triangles and segments, radius-0 cylinders and cones, touching and random.
//! * `containment`: one shape inside another.

use cga_collide::nalgebra::{Point3, Vector3};
use cga_collide::shape::Shape;
use num_traits::Zero;
use rand::{RngExt, SeedableRng};
use rand_xorshift::XorShiftRng;

use super::construct::{
    self, ball, capsule, cone, cuboid, cylinder, half, hull, known_pairs, magnitude, seg, similar,
    translated, tri, ulp, Similarity, ROTATIONS,
};
use super::exact::{add, cross, dot, q, scale, sub, P3, Q};
use super::{body, json, Body};

/// Every kind, as the command line spells it.
pub const KINDS: [&str; 9] = [
    "ball",
    "cuboid",
    "capsule",
    "cylinder",
    "cone",
    "halfspace",
    "convex",
    "triangle",
    "segment",
];

/// The kinds the oracle decides exactly against each other (no cylinder, no cone).
pub const POLYTOPAL: [&str; 7] = [
    "ball",
    "cuboid",
    "capsule",
    "halfspace",
    "convex",
    "triangle",
    "segment",
];

type Rng = XorShiftRng;

/// A fixed-seed generator.
pub fn rng(seed: u64) -> Rng {
    XorShiftRng::seed_from_u64(seed)
}

fn dyadic(r: &mut Rng, lo: i64, hi: i64, denom: f64) -> f64 {
    r.random_range(lo..=hi) as f64 / denom
}

fn point(r: &mut Rng) -> Point3<f64> {
    Point3::new(
        dyadic(r, -32, 32, 8.0),
        dyadic(r, -32, 32, 8.0),
        dyadic(r, -32, 32, 8.0),
    )
}

fn near(r: &mut Rng, c: &Point3<f64>, spread: i64) -> Point3<f64> {
    c + Vector3::new(
        dyadic(r, -spread, spread, 8.0),
        dyadic(r, -spread, spread, 8.0),
        dyadic(r, -spread, spread, 8.0),
    )
}

fn radius(r: &mut Rng) -> f64 {
    dyadic(r, 1, 24, 8.0)
}

fn int_vector(r: &mut Rng) -> Vector3<f64> {
    loop {
        let v = Vector3::new(
            r.random_range(-3i64..=3) as f64,
            r.random_range(-3i64..=3) as f64,
            r.random_range(-3i64..=3) as f64,
        );
        if v != Vector3::zeros() {
            return v;
        }
    }
}

fn axis_vector(r: &mut Rng) -> Vector3<f64> {
    let mut v = Vector3::zeros();
    v[r.random_range(0..3usize)] = if r.random_bool(0.5) { 1.0 } else { -1.0 };
    v * r.random_range(1i64..=4) as f64
}

/// A random shape of `kind` around `c`. `axis_normals` keeps half-space normals on an axis.
pub fn random_shape(r: &mut Rng, kind: &str, c: &Point3<f64>, axis_normals: bool) -> Shape {
    match kind {
        "ball" => ball(near(r, c, 8), radius(r)),
        "cuboid" => {
            if r.random_bool(0.5) {
                let h = [radius(r), radius(r), radius(r)];
                cuboid(
                    near(r, c, 8),
                    [
                        Vector3::new(h[0], 0.0, 0.0),
                        Vector3::new(0.0, h[1], 0.0),
                        Vector3::new(0.0, 0.0, h[2]),
                    ],
                )
            } else {
                let s = dyadic(r, 1, 4, 4.0);
                cuboid(
                    near(r, c, 8),
                    [int_vector(r) * s, int_vector(r) * s, int_vector(r) * s],
                )
            }
        }
        "capsule" => capsule(near(r, c, 16), near(r, c, 16), radius(r)),
        "cylinder" | "cone" => {
            let a = near(r, c, 16);
            let mut b = near(r, c, 16);
            if a == b {
                b.x += 1.0;
            }
            if kind == "cylinder" {
                cylinder(a, b, radius(r))
            } else {
                cone(a, b, radius(r))
            }
        }
        "halfspace" => {
            let n = if axis_normals {
                axis_vector(r)
            } else {
                int_vector(r)
            };
            half(near(r, c, 8), n)
        }
        "convex" => {
            let k = r.random_range(4..=8usize);
            let pts: Vec<_> = (0..k).map(|_| near(r, c, 16)).collect();
            hull(&pts)
        }
        "triangle" => tri(near(r, c, 16), near(r, c, 16), near(r, c, 16)),
        "segment" => seg(near(r, c, 16), near(r, c, 16)),
        other => panic!("unknown kind {other}"),
    }
}

/// A degenerate shape of `kind` (radius 0, collapsed axes, flat or one-point hulls, ...).
pub fn degenerate_shape(r: &mut Rng, kind: &str, c: &Point3<f64>) -> Shape {
    let p0 = near(r, c, 8);
    let d = int_vector(r) * dyadic(r, 1, 8, 4.0);
    let e = int_vector(r) * dyadic(r, 1, 8, 4.0);
    match kind {
        "ball" => ball(p0, 0.0),
        "cuboid" => {
            let zero = Vector3::zeros();
            match r.random_range(0..4) {
                0 => cuboid(p0, [d, e, zero]),
                1 => cuboid(p0, [d, zero, zero]),
                2 => cuboid(p0, [zero, zero, zero]),
                _ => cuboid(p0, [d, e, d + e]),
            }
        }
        "capsule" => match r.random_range(0..3) {
            0 => capsule(p0, p0 + d, 0.0),
            1 => capsule(p0, p0, radius(r)),
            _ => capsule(p0, p0, 0.0),
        },
        "cylinder" => cylinder(p0, p0 + d, 0.0),
        "cone" => cone(p0, p0 + d, 0.0),
        "halfspace" => half(p0, d),
        "convex" => match r.random_range(0..4) {
            0 => hull(&[p0]),
            1 => hull(&[p0, p0 + d, p0 + d * 2.0, p0 - d]),
            2 => hull(&[p0, p0 + d, p0 + e, p0 + d + e, p0 + d * 0.5]),
            _ => hull(&[p0, p0, p0 + d, p0 + d]),
        },
        "triangle" => match r.random_range(0..3) {
            0 => tri(p0, p0 + d, p0 + d * 2.0),
            1 => tri(p0, p0, p0 + d),
            _ => tri(p0, p0, p0),
        },
        "segment" => {
            if r.random_bool(0.5) {
                seg(p0, p0)
            } else {
                seg(p0, p0 + d)
            }
        }
        other => panic!("unknown kind {other}"),
    }
}

// ---- inner and outer polytopes of the round shapes (for generic round pairs) ----

/// Dyadic `s` with `s²·|p|² <= target` (`inner`) or `>= target` (outer), checked exactly.
fn fit(p: &P3, target: &Q, inner: bool) -> Q {
    use num_traits::ToPrimitive;
    let p2 = dot(p, p);
    let guess = (target / &p2).to_f64().unwrap_or(0.0).sqrt();
    let mut s = q(if inner { guess * 0.999 } else { guess * 1.001 });
    loop {
        let v = &s * &s * &p2;
        if (inner && &v <= target) || (!inner && &v >= target) {
            return s;
        }
        s = if inner { s * q(0.5) } else { s * q(2.0) };
    }
}

fn prism_corners(centre: &P3, u_half: Option<&P3>, p1: &P3, p2: &P3, s1: &Q, s2: &Q) -> Vec<P3> {
    let mut out = Vec::new();
    for m in 0..8 {
        if u_half.is_none() && m >= 4 {
            break;
        }
        let mut x = centre.clone();
        x = add(
            &x,
            &scale(p1, &if m & 1 == 1 { s1.clone() } else { -s1.clone() }),
        );
        x = add(
            &x,
            &scale(p2, &if m & 2 == 2 { s2.clone() } else { -s2.clone() }),
        );
        if let Some(u) = u_half {
            x = if m & 4 == 4 { add(&x, u) } else { sub(&x, u) };
        }
        out.push(x);
    }
    out
}

/// A polytope inside (`inner`) or around (outer) a cylinder or cone body; other bodies as they
/// are.
pub fn polytope_bound(b: &Body, inner: bool) -> Body {
    let (a, e, r, is_cone) = match b {
        Body::Cylinder { a, b, radius } => (a.clone(), b.clone(), radius.clone(), false),
        Body::Cone { apex, base, radius } => (apex.clone(), base.clone(), radius.clone(), true),
        other => return other.clone(),
    };
    let u = sub(&e, &a);
    let k = (0..3)
        .min_by(|&i, &j| abs_q(&u[i]).cmp(&abs_q(&u[j])))
        .expect("three axes");
    let mut ek: P3 = [Q::zero(), Q::zero(), Q::zero()];
    ek[k] = q(1.0);
    let p1 = cross(&u, &ek);
    let p2 = cross(&u, &p1);
    let target = if inner { &r * &r * q(0.5) } else { &r * &r };
    let (s1, s2) = (fit(&p1, &target, inner), fit(&p2, &target, inner));
    let points = if is_cone {
        let mut pts = prism_corners(&e, None, &p1, &p2, &s1, &s2);
        pts.push(a);
        pts
    } else {
        let half_u = scale(&u, &q(0.5));
        let centre = add(&a, &half_u);
        prism_corners(&centre, Some(&half_u), &p1, &p2, &s1, &s2)
    };
    Body::Grown {
        points,
        radius: Q::zero(),
    }
}

fn abs_q(x: &Q) -> Q {
    num_traits::Signed::abs(x)
}

/// The exact answer: the oracle's where it has one, else the inner/outer polytopes' when they
/// agree; `None` when undecided.
pub fn decided(a: &Shape, b: &Shape) -> Option<bool> {
    if let Some(x) = super::intersects(a, b) {
        return Some(x);
    }
    let (ba, bb) = (body(a), body(b));
    let outer = super::intersects_bodies(&polytope_bound(&ba, false), &polytope_bound(&bb, false))?;
    if !outer {
        return Some(false);
    }
    let inner = super::intersects_bodies(&polytope_bound(&ba, true), &polytope_bound(&bb, true))?;
    inner.then_some(true)
}

// ---- families ----

/// One fixture line with its family.
pub struct Line {
    pub a: Shape,
    pub b: Shape,
    pub expected: bool,
    pub note: String,
}

fn oracle_line(a: Shape, b: Shape, note: String) -> Option<Line> {
    let expected = decided(&a, &b)?;
    Some(Line {
        a,
        b,
        expected,
        note,
    })
}

fn pairs_of(kinds: &[&'static str]) -> Vec<(&'static str, &'static str)> {
    let mut out = Vec::new();
    for (i, a) in kinds.iter().enumerate() {
        for b in &kinds[i..] {
            out.push((*a, *b));
        }
    }
    out
}

fn maybe_swap(r: &mut Rng, a: Shape, b: Shape) -> (Shape, Shape) {
    if r.random_bool(0.5) {
        (b, a)
    } else {
        (a, b)
    }
}

/// Generic pairs: `per_pair` decided pairs of every pair type.
pub fn random_family(seed: u64, per_pair: usize) -> Vec<Line> {
    let mut r = rng(seed);
    let mut out = Vec::new();
    for (ka, kb) in pairs_of(&KINDS) {
        let mut got = 0;
        let mut tries = 0;
        while got < per_pair && tries < 200 {
            tries += 1;
            let c = point(&mut r);
            let a = random_shape(&mut r, ka, &c, false);
            let cb = near(&mut r, &c, 24);
            let b = random_shape(&mut r, kb, &cb, false);
            let (a, b) = maybe_swap(&mut r, a, b);
            if let Some(line) = oracle_line(a, b, "random".into()) {
                out.push(line);
                got += 1;
            }
        }
    }
    out
}

/// The grown body's extreme point along `e` (max if `max`), with its radius.
fn extreme(s: &Shape, e: &Vector3<f64>, max: bool) -> Option<(Point3<f64>, f64)> {
    let pts: Vec<Point3<f64>> = match s {
        Shape::Ball(b) => vec![*b.centre()],
        Shape::Capsule(c) => vec![*c.a(), *c.b()],
        Shape::Segment(x) => vec![*x.a(), *x.b()],
        Shape::Triangle(t) => t.vertices().to_vec(),
        Shape::ConvexHull(h) => h.points().to_vec(),
        Shape::Cuboid(c) => {
            let [u, v, w] = c.half_axes();
            (0..8)
                .map(|m| {
                    let sg = |bit: i32| if m >> bit & 1 == 1 { 1.0 } else { -1.0 };
                    c.centre() + u * sg(0) + v * sg(1) + w * sg(2)
                })
                .collect()
        }
        Shape::HalfSpace(h) => return Some((*h.point(), 0.0)),
        _ => return None,
    };
    let r = match s {
        Shape::Ball(b) => b.radius(),
        Shape::Capsule(c) => c.radius(),
        _ => 0.0,
    };
    let key = |p: &Point3<f64>| p.coords.dot(e);
    let best = if max {
        pts.iter().max_by(|x, y| key(x).total_cmp(&key(y)))
    } else {
        pts.iter().min_by(|x, y| key(x).total_cmp(&key(y)))
    }?;
    Some((*best, r))
}

/// `a` and `b` (polytopal kinds) in contact along an axis: `b` translated so that its lowest
/// point along `e` meets `a`'s highest. Half-spaces take `e` from their normal.
fn touching(
    r: &mut Rng,
    ka: &str,
    kb: &str,
    degenerate: bool,
) -> Option<(Shape, Shape, Vector3<f64>)> {
    let c = point(r);
    let make = |r: &mut Rng, k: &str| {
        if degenerate && r.random_bool(0.7) {
            degenerate_shape(r, k, &c)
        } else {
            random_shape(r, k, &c, true)
        }
    };
    let a = make(r, ka);
    let mut b = make(r, kb);
    let e = match (&a, &b) {
        (Shape::HalfSpace(h), Shape::HalfSpace(_)) => {
            // Opposite normals through one plane: touching over the whole plane.
            let n = *h.normal();
            b = half(*h.point(), -n * dyadic(r, 1, 4, 1.0));
            return Some((a, b, n));
        }
        (Shape::HalfSpace(h), _) => *h.normal(),
        (_, Shape::HalfSpace(h)) => -*h.normal(),
        _ => axis_vector(r),
    };
    let unit = e / e.norm();
    let (pa, ra) = extreme(&a, &e, true)?;
    let (pb, rb) = extreme(&b, &e, false)?;
    let t = (pa - pb) + unit * (ra + rb);
    b = translated(&b, [t.x, t.y, t.z])?;
    Some((a, b, e))
}

fn moves(
    a: &Shape,
    b: &Shape,
    e: &Vector3<f64>,
    t: &Similarity,
    step: f64,
    tag: &str,
) -> Option<Vec<Line>> {
    let a = similar(a, t)?;
    let b = similar(b, t)?;
    let n = t.direction([e.x, e.y, e.z]);
    let step = if step == 0.0 {
        ulp(magnitude(&a).max(magnitude(&b)))
    } else {
        step
    };
    let out = translated(&b, n.map(|x| x * step))?;
    let inn = translated(&b, n.map(|x| -x * step))?;
    let mut lines = Vec::new();
    for (bb, what) in [(b, "touching"), (out, "moved out"), (inn, "moved in")] {
        lines.push(oracle_line(a.clone(), bb, format!("{tag}; {what}"))?);
    }
    Some(lines)
}

/// Touching pairs of every polytopal pair type, `per_pair` bases each, at scale `2^exp`.
pub fn touching_family(seed: u64, per_pair: usize, exp: i32, degenerate: bool) -> Vec<Line> {
    let mut r = rng(seed);
    let mut out = Vec::new();
    for (ka, kb) in pairs_of(&POLYTOPAL) {
        let mut got = 0;
        let mut tries = 0;
        while got < per_pair && tries < 100 {
            tries += 1;
            let Some((a, b, e)) = touching(&mut r, ka, kb, degenerate) else {
                continue;
            };
            let (qa, qb, qc, qd) = ROTATIONS[r.random_range(0..ROTATIONS.len())];
            let id = Similarity::identity(exp);
            let rot = Similarity::from_quaternion(qa, qb, qc, qd, exp);
            let (Some(x), Some(y)) = (
                moves(
                    &a,
                    &b,
                    &e,
                    &id,
                    0.0,
                    &format!("{ka}-{kb} in contact along an axis; scale 2^{exp}; one ulp"),
                ),
                moves(
                    &a,
                    &b,
                    &e,
                    &rot,
                    2f64.powi(exp - 32),
                    &format!("{ka}-{kb} in contact, rotated; scale 2^{exp}; step 2^-32"),
                ),
            ) else {
                continue;
            };
            out.extend(x);
            out.extend(y);
            got += 1;
        }
    }
    out
}

/// The constructed curved contacts at scale `2^exp` (known answers, checked by the oracle where
/// it has a method).
pub fn curved_family(exp: i32, rotations: bool) -> Vec<Line> {
    // Per contact: its own frame (3 pairs), then each rotation (3 pairs each); one rotation a
    // contact, in turn, keeps the file small.
    let per_contact = 3 * (1 + ROTATIONS.len());
    known_pairs(exp)
        .into_iter()
        .enumerate()
        .filter(|(i, _)| {
            let (contact, within) = (i / per_contact, i % per_contact);
            within < 3 || (rotations && (within / 3 - 1) == contact % ROTATIONS.len())
        })
        .map(|(_, k)| k)
        .map(|k| Line {
            a: k.a,
            b: k.b,
            expected: k.expected,
            note: k.note,
        })
        .collect()
}

/// A tiny shape (scale `2^-332`) against a huge one (`2^332`), touching exactly at the
/// origin (each translated so that its extreme point along an axis lands there), then moved
/// one ulp of the tiny shape out and in; the oracle's answers.
pub fn mixed_scale_family(seed: u64, per_pair: usize) -> Vec<Line> {
    let mut r = rng(seed);
    let mut out = Vec::new();
    for (ka, kb) in pairs_of(&POLYTOPAL) {
        let mut got = 0;
        let mut tries = 0;
        while got < per_pair && tries < 100 {
            tries += 1;
            let c = point(&mut r);
            let big = similar(
                &random_shape(&mut r, ka, &c, true),
                &Similarity::identity(332),
            )
            .expect("exact scale");
            let small = similar(
                &random_shape(&mut r, kb, &Point3::origin(), true),
                &Similarity::identity(-332),
            )
            .expect("exact scale");
            let e = match (&big, &small) {
                (Shape::HalfSpace(h), _) => *h.normal(),
                (_, Shape::HalfSpace(h)) => -*h.normal(),
                _ => axis_vector(&mut r),
            };
            if let (Shape::HalfSpace(_), Shape::HalfSpace(_)) = (&big, &small) {
                continue;
            }
            let unit = e / e.norm();
            let (Some((pa, ra)), Some((pb, rb))) =
                (extreme(&big, &e, true), extreme(&small, &e, false))
            else {
                continue;
            };
            let ta = -(pa.coords + unit * ra);
            let tb = -(pb.coords - unit * rb);
            let (Some(big), Some(small)) = (
                translated(&big, [ta.x, ta.y, ta.z]),
                translated(&small, [tb.x, tb.y, tb.z]),
            ) else {
                continue;
            };
            let step = ulp(magnitude(&small));
            let tag = format!(
                "{ka} at 2^332 touching {kb} at 2^-332 at the origin; one ulp of the small one"
            );
            if let Some(lines) = moves(&big, &small, &e, &Similarity::identity(0), step, &tag) {
                out.extend(lines);
                got += 1;
            }
        }
    }
    out
}

/// Random pairs at scale `2^exp`.
pub fn scaled_random_family(seed: u64, per_pair: usize, exp: i32) -> Vec<Line> {
    let t = Similarity::identity(exp);
    random_family(seed, per_pair)
        .into_iter()
        .filter_map(|l| {
            Some(Line {
                a: similar(&l.a, &t)?,
                b: similar(&l.b, &t)?,
                expected: l.expected,
                note: format!("random; scale 2^{exp}"),
            })
        })
        .collect()
}

/// Random pairs with degenerate shapes, every pair type.
pub fn degenerate_random_family(seed: u64, per_pair: usize) -> Vec<Line> {
    let mut r = rng(seed);
    let mut out = Vec::new();
    for (ka, kb) in pairs_of(&KINDS) {
        let mut got = 0;
        let mut tries = 0;
        while got < per_pair && tries < 200 {
            tries += 1;
            let c = point(&mut r);
            let a = degenerate_shape(&mut r, ka, &c);
            let cb = near(&mut r, &c, 8);
            let b = if r.random_bool(0.5) {
                degenerate_shape(&mut r, kb, &cb)
            } else {
                random_shape(&mut r, kb, &cb, false)
            };
            let (a, b) = maybe_swap(&mut r, a, b);
            if let Some(l) = oracle_line(a, b, "degenerate; random".into()) {
                out.push(l);
                got += 1;
            }
        }
    }
    out
}

/// One shape inside another: a small shape at the centre of a cylinder, a cone, a box or a
/// ball, and the round shapes inside a big box or ball. True by construction.
pub fn containment_family(seed: u64, per_kind: usize) -> Vec<Line> {
    let mut r = rng(seed);
    let mut out = Vec::new();
    let containers: [(Shape, Point3<f64>, &str); 4] = [
        (
            cylinder(Point3::new(0., 0., 0.), Point3::new(0., 0., 8.), 2.0),
            Point3::new(0., 0., 4.),
            "inside a cylinder",
        ),
        (
            cone(Point3::new(0., 0., 8.), Point3::new(0., 0., 0.), 6.0),
            Point3::new(0., 0., 2.),
            "inside a cone",
        ),
        (
            construct::boxed(Point3::new(0., 0., 0.), 4.0),
            Point3::origin(),
            "inside a box",
        ),
        (
            ball(Point3::new(0., 0., 0.), 4.0),
            Point3::origin(),
            "inside a ball",
        ),
    ];
    for (container, centre, note) in &containers {
        for kind in KINDS {
            if kind == "halfspace" {
                continue;
            }
            for _ in 0..per_kind {
                // Everything within 1/2 of the centre (hence inside each container).
                let t = Similarity::identity(-6);
                let small = random_shape(&mut r, kind, &Point3::origin(), false);
                let small = similar(&small, &t).expect("exact scale");
                let Some(small) = translated(&small, [centre.x, centre.y, centre.z]) else {
                    continue;
                };
                debug_assert!(magnitude(&small) < 8.0);
                let (a, b) = maybe_swap(&mut r, container.clone(), small);
                out.push(Line {
                    a,
                    b,
                    expected: true,
                    note: format!("containment; {kind} {note}"),
                });
            }
        }
    }
    for round in [
        cylinder(Point3::new(1., 2., -3.), Point3::new(-2., 1., 3.), 1.5),
        cone(Point3::new(1., 2., -3.), Point3::new(-2., 1., 3.), 1.5),
    ] {
        for container in [
            construct::boxed(Point3::origin(), 16.0),
            ball(Point3::origin(), 16.0),
            capsule(Point3::new(-1., 0., 0.), Point3::new(1., 0., 0.), 16.0),
            half(Point3::new(0., 0., 8.), Vector3::new(1., 1., 1.)),
        ] {
            out.push(Line {
                a: container,
                b: round.clone(),
                expected: true,
                note: "containment; a round shape inside a big one".into(),
            });
        }
    }
    out
}

/// The fixture files: name and lines.
pub fn fixture_files() -> Vec<(&'static str, Vec<Line>)> {
    let mut scales = scaled_random_family(11, 1, 332);
    scales.extend(scaled_random_family(12, 1, -332));
    scales.extend(touching_family(13, 1, 332, false));
    scales.extend(touching_family(14, 1, -332, false));
    scales.extend(mixed_scale_family(15, 1));
    let mut curved_scales = curved_family(332, false);
    curved_scales.extend(curved_family(-332, false));
    let mut degenerate = degenerate_random_family(21, 3);
    degenerate.extend(touching_family(22, 1, 0, true));
    vec![
        ("random.jsonl", random_family(1, 6)),
        ("polytopal_touching.jsonl", touching_family(2, 2, 0, false)),
        ("curved_contacts.jsonl", curved_family(0, true)),
        ("curved_scales.jsonl", curved_scales),
        ("polytopal_scales.jsonl", scales),
        ("degenerate.jsonl", degenerate),
        ("containment.jsonl", containment_family(31, 2)),
    ]
}

/// The fixture's text: one JSON line a pair.
pub fn fixture_text(family: &str, lines: &[Line]) -> String {
    let mut s = String::new();
    for l in lines {
        s.push_str(&json::pair_line(&l.a, &l.b, l.expected, family, &l.note));
        s.push('\n');
    }
    s
}
