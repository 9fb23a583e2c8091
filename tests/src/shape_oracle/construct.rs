//! Pairs whose answer is known by construction, for the pairs with a cylinder or a cone.
//!
//! Each base contact puts a cylinder or a cone and a partner in exact dyadic coordinates so
//! that they touch (at a point, along a segment or over a face) with a contact normal `N`:
//! the first shape lies in `{x : N·x <= N·p}`, the second in `{x : N·x >= N·p}`, and they
//! share the point `p`. Moving the second shape by `+δN` separates them strictly (the plane
//! `N·x = N·p + δ|N|²/2` separates); moving it by `−δN` keeps them meeting, because every base
//! contact has one shape thick along the normal at `p` (the first contains `p − δN`, or the
//! second contains `p + δN`, for the small `δ` used). Exact similarity maps (an integer
//! rotation matrix `M = n·R` from an integer quaternion, a power-of-two scale) keep the truth;
//! every mapped coordinate is checked to be the exact image.

use cga_collide::nalgebra::{Point3, Vector3};
use cga_collide::shape::{Capsule, Cone, ConvexHull, Cuboid, Cylinder, HalfSpace, Shape};
use cga_collide::{Ball, Segment, Triangle};

use super::exact::{q, Q};

/// A pair with its known answer.
#[derive(Debug, Clone)]
pub struct Known {
    pub a: Shape,
    pub b: Shape,
    pub expected: bool,
    pub note: String,
}

/// A base contact: the shapes touch at `p` with outward normal `n` (from `a` to `b`).
#[derive(Debug, Clone)]
pub struct Contact {
    pub a: Shape,
    pub b: Shape,
    pub n: [f64; 3],
    pub note: &'static str,
}

fn p(x: f64, y: f64, z: f64) -> Point3<f64> {
    Point3::new(x, y, z)
}

fn v(x: f64, y: f64, z: f64) -> Vector3<f64> {
    Vector3::new(x, y, z)
}

pub fn ball(c: Point3<f64>, r: f64) -> Shape {
    Ball::new(c, r).unwrap().into()
}
pub fn capsule(a: Point3<f64>, b: Point3<f64>, r: f64) -> Shape {
    Capsule::new(a, b, r).unwrap().into()
}
pub fn cylinder(a: Point3<f64>, b: Point3<f64>, r: f64) -> Shape {
    Cylinder::new(a, b, r).unwrap().into()
}
pub fn cone(apex: Point3<f64>, base: Point3<f64>, r: f64) -> Shape {
    Cone::new(apex, base, r).unwrap().into()
}
pub fn cuboid(c: Point3<f64>, h: [Vector3<f64>; 3]) -> Shape {
    Cuboid::new(c, h).unwrap().into()
}
pub fn boxed(c: Point3<f64>, h: f64) -> Shape {
    cuboid(c, [v(h, 0.0, 0.0), v(0.0, h, 0.0), v(0.0, 0.0, h)])
}
pub fn half(point: Point3<f64>, normal: Vector3<f64>) -> Shape {
    HalfSpace::new(point, normal).unwrap().into()
}
pub fn hull(points: &[Point3<f64>]) -> Shape {
    ConvexHull::new(points.to_vec()).unwrap().into()
}
pub fn tri(a: Point3<f64>, b: Point3<f64>, c: Point3<f64>) -> Shape {
    Triangle::new(a, b, c).unwrap().into()
}
pub fn seg(a: Point3<f64>, b: Point3<f64>) -> Shape {
    Segment::new(a, b).unwrap().into()
}

fn c(a: Shape, b: Shape, n: [f64; 3], note: &'static str) -> Contact {
    Contact { a, b, n, note }
}

/// The cylinder `[(0,0,0), (0,0,8)]`, radius 2, against every kind: on its side (normal +x at
/// (2,0,4)), on its top cap (normal +z), on its rim (normal (3,0,4) at (2,0,8)).
fn cylinder_contacts() -> Vec<Contact> {
    let y = || cylinder(p(0., 0., 0.), p(0., 0., 8.), 2.0);
    let side = [1.0, 0.0, 0.0];
    let top = [0.0, 0.0, 1.0];
    let rim = [3.0, 0.0, 4.0];
    vec![
        c(
            y(),
            half(p(2., 0., 0.), v(-1., 0., 0.)),
            side,
            "cylinder lying on a half-space (side line)",
        ),
        c(
            y(),
            boxed(p(3., 0., 4.), 1.0),
            side,
            "cylinder lying on a box face (segment)",
        ),
        c(
            y(),
            cuboid(
                p(4., 0., 4.),
                [v(1., 1., 0.), v(1., -1., 0.), v(0., 0., 1.)],
            ),
            side,
            "box edge along the cylinder's side",
        ),
        c(
            y(),
            tri(p(2., -1., 3.), p(2., 1., 3.), p(2., 0., 6.)),
            side,
            "triangle tangent along the side",
        ),
        c(
            y(),
            seg(p(2., -1., 4.), p(2., 1., 4.)),
            side,
            "segment crossing the side line, tangent at a point",
        ),
        c(
            y(),
            seg(p(2., 0., 2.), p(2., 0., 6.)),
            side,
            "segment lying on the side line",
        ),
        c(
            y(),
            hull(&[p(2., -1., 3.), p(2., 1., 3.), p(2., 0., 6.), p(4., 0., 4.)]),
            side,
            "hull face tangent along the side",
        ),
        c(y(), ball(p(5., 0., 4.), 3.0), side, "ball on the side"),
        c(
            y(),
            capsule(p(3., 0., 2.), p(3., 0., 6.), 1.0),
            side,
            "capsule parallel to the side",
        ),
        c(
            y(),
            capsule(p(3., -4., 4.), p(3., 4., 4.), 1.0),
            side,
            "capsule crossing the side",
        ),
        c(
            y(),
            cylinder(p(5., 0., 2.), p(5., 0., 6.), 3.0),
            side,
            "parallel cylinders r1 + r2 apart",
        ),
        c(
            y(),
            cylinder(p(5., -4., 4.), p(5., 4., 4.), 3.0),
            side,
            "crossed cylinders touching",
        ),
        c(
            y(),
            cone(p(2., 0., 1.), p(5., 0., 5.), 3.75),
            side,
            "cone lying along the cylinder's side",
        ),
        c(
            y(),
            half(p(0., 0., 8.), v(0., 0., -1.)),
            top,
            "half-space on the cap (face)",
        ),
        c(
            y(),
            boxed(p(0., 0., 9.), 1.0),
            top,
            "box standing on the cap",
        ),
        c(
            y(),
            cuboid(p(0., 0., 9.), [v(3., 0., 0.), v(0., 3., 0.), v(0., 0., 1.)]),
            top,
            "box face covering the cap",
        ),
        c(
            y(),
            cone(p(0., 0., 11.), p(0., 0., 8.), 1.0),
            top,
            "cone standing on its base on the cap",
        ),
        c(
            y(),
            cone(p(0., 0., 8.), p(0., 0., 11.), 1.0),
            top,
            "cone on its apex on the cap",
        ),
        c(
            y(),
            cylinder(p(0., 0., 8.), p(0., 0., 10.), 1.0),
            top,
            "cylinders stacked coaxially",
        ),
        c(
            y(),
            cylinder(p(-3., 0., 9.), p(3., 0., 9.), 1.0),
            top,
            "cylinder lying across the cap",
        ),
        c(y(), ball(p(0., 0., 11.), 3.0), top, "ball on the cap"),
        c(
            y(),
            tri(p(-1., -1., 8.), p(1., -1., 8.), p(0., 1., 8.)),
            top,
            "triangle flat on the cap",
        ),
        c(
            y(),
            seg(p(-1., 0., 8.), p(1., 0., 8.)),
            top,
            "segment on the cap",
        ),
        c(
            y(),
            hull(&[
                p(-1., -1., 8.),
                p(1., -1., 8.),
                p(0., 1., 8.),
                p(0., 0., 9.),
            ]),
            top,
            "tetrahedron standing on the cap",
        ),
        c(
            y(),
            capsule(p(-1., 0., 9.), p(1., 0., 9.), 1.0),
            top,
            "capsule lying on the cap",
        ),
        c(y(), ball(p(5., 0., 12.), 5.0), rim, "ball on the rim"),
        c(
            y(),
            half(p(2., 0., 8.), v(-3., 0., -4.)),
            rim,
            "tilted half-space touching the rim",
        ),
        c(
            y(),
            cuboid(
                p(3.5, 0., 10.),
                [v(1.5, 0., 2.), v(0., 1., 0.), v(-2., 0., 1.5)],
            ),
            rim,
            "tilted box face touching the rim",
        ),
        c(
            y(),
            seg(p(2., -1., 8.), p(2., 1., 8.)),
            rim,
            "segment tangent to the rim",
        ),
        c(
            y(),
            capsule(p(5., -2., 12.), p(5., 2., 12.), 5.0),
            rim,
            "capsule on the rim",
        ),
        c(
            y(),
            cone(p(2., 0., 8.), p(5., 0., 12.), 1.0),
            rim,
            "cone apex on the rim",
        ),
        c(
            y(),
            cylinder(p(5., -2., 12.), p(5., 2., 12.), 5.0),
            rim,
            "cylinder on the rim",
        ),
        c(
            y(),
            tri(p(2., -1., 8.), p(2., 1., 8.), p(0., 0., 9.5)),
            rim,
            "triangle in the rim's tangent plane",
        ),
        c(
            y(),
            hull(&[
                p(2., -1., 8.),
                p(2., 1., 8.),
                p(0., 0., 9.5),
                p(5., 0., 12.),
            ]),
            rim,
            "hull vertex on the rim",
        ),
    ]
}

/// The cone of base `(0,0,0)`, apex `(0,0,8)`, radius 6 (slant normal (4,0,3)) against every
/// kind: at the apex (+z), on the base (−z), at the rim (+x at (6,0,0)), on the slant (at
/// (3,0,4)); and two cones touching along a common generator.
fn cone_contacts() -> Vec<Contact> {
    let k = || cone(p(0., 0., 8.), p(0., 0., 0.), 6.0);
    let up = [0.0, 0.0, 1.0];
    let down = [0.0, 0.0, -1.0];
    let out = [1.0, 0.0, 0.0];
    let slant = [4.0, 0.0, 3.0];
    vec![
        c(k(), ball(p(0., 0., 11.), 3.0), up, "ball on the apex"),
        c(
            k(),
            half(p(0., 0., 8.), v(0., 0., -1.)),
            up,
            "half-space on the apex",
        ),
        c(k(), boxed(p(0., 0., 9.), 1.0), up, "box on the apex"),
        c(
            k(),
            seg(p(-1., 0., 8.), p(1., 0., 8.)),
            up,
            "segment through the apex",
        ),
        c(
            k(),
            tri(p(-1., -1., 8.), p(1., -1., 8.), p(0., 1., 8.)),
            up,
            "triangle on the apex",
        ),
        c(
            k(),
            hull(&[
                p(-1., -1., 8.),
                p(1., -1., 8.),
                p(0., 1., 8.),
                p(0., 0., 9.),
            ]),
            up,
            "hull face on the apex",
        ),
        c(
            k(),
            capsule(p(-1., 0., 9.), p(1., 0., 9.), 1.0),
            up,
            "capsule on the apex",
        ),
        c(
            k(),
            cylinder(p(-2., 0., 9.), p(2., 0., 9.), 1.0),
            up,
            "cylinder lying on the apex",
        ),
        c(
            k(),
            cone(p(0., 0., 8.), p(0., 0., 12.), 2.0),
            up,
            "cones apex to apex",
        ),
        c(
            k(),
            half(p(0., 0., 0.), v(0., 0., 1.)),
            down,
            "cone on its base on a half-space",
        ),
        c(
            k(),
            cuboid(
                p(0., 0., -1.),
                [v(2., 0., 0.), v(0., 2., 0.), v(0., 0., 1.)],
            ),
            down,
            "cone on its base on a box",
        ),
        c(
            k(),
            cylinder(p(0., 0., -2.), p(0., 0., 0.), 3.0),
            down,
            "cone on a cylinder's cap",
        ),
        c(
            k(),
            cone(p(0., 0., -5.), p(0., 0., 0.), 6.0),
            down,
            "cones base to base (same disc)",
        ),
        c(k(), ball(p(0., 0., -3.), 3.0), down, "ball under the base"),
        c(
            k(),
            tri(p(-1., -1., 0.), p(1., -1., 0.), p(0., 1., 0.)),
            down,
            "triangle in the base",
        ),
        c(
            k(),
            seg(p(-1., 0., 0.), p(1., 0., 0.)),
            down,
            "segment in the base",
        ),
        c(
            k(),
            hull(&[
                p(-1., -1., 0.),
                p(1., -1., 0.),
                p(0., 1., 0.),
                p(0., 0., -1.),
            ]),
            down,
            "hull face on the base",
        ),
        c(
            k(),
            capsule(p(-1., 0., -1.), p(1., 0., -1.), 1.0),
            down,
            "capsule under the base",
        ),
        c(k(), ball(p(8., 0., 0.), 2.0), out, "ball on the rim"),
        c(
            k(),
            half(p(6., 0., 0.), v(-1., 0., 0.)),
            out,
            "half-space touching the rim",
        ),
        c(
            k(),
            boxed(p(7., 0., 0.), 1.0),
            out,
            "box face touching the rim",
        ),
        c(
            k(),
            seg(p(6., -1., 0.), p(6., 1., 0.)),
            out,
            "segment tangent to the rim",
        ),
        c(
            k(),
            capsule(p(7., -1., 0.), p(7., 1., 0.), 1.0),
            out,
            "capsule on the rim",
        ),
        c(
            k(),
            cylinder(p(8., 0., -1.), p(8., 0., 1.), 2.0),
            out,
            "cylinder side on the rim",
        ),
        c(
            k(),
            tri(p(6., -1., -1.), p(6., 1., -1.), p(6., 0., 1.)),
            out,
            "triangle through the rim point",
        ),
        c(
            k(),
            hull(&[
                p(6., -1., -1.),
                p(6., 1., -1.),
                p(6., 0., 1.),
                p(8., 0., 0.),
            ]),
            out,
            "hull face on the rim",
        ),
        c(
            k(),
            cone(p(6., 0., 0.), p(9., 0., 0.), 1.0),
            out,
            "cone apex on the rim",
        ),
        c(k(), ball(p(7., 0., 7.), 5.0), slant, "ball on the slant"),
        c(
            k(),
            half(p(3., 0., 4.), v(-4., 0., -3.)),
            slant,
            "half-space along a generator",
        ),
        c(
            k(),
            cuboid(
                p(5., 0., 5.5),
                [v(2., 0., 1.5), v(0., 1., 0.), v(-0.75, 0., 1.)],
            ),
            slant,
            "box face along a generator",
        ),
        c(
            k(),
            cylinder(p(7.75, 0., 6.), p(6.25, 0., 8.), 5.0),
            slant,
            "cylinder along a generator",
        ),
        c(
            k(),
            capsule(p(7.75, 0., 6.), p(6.25, 0., 8.), 5.0),
            slant,
            "capsule along a generator",
        ),
        c(
            k(),
            seg(p(3.75, 0., 3.), p(2.25, 0., 5.)),
            slant,
            "segment lying on a generator",
        ),
        c(
            k(),
            seg(p(3., -1., 4.), p(3., 1., 4.)),
            slant,
            "segment tangent to the slant",
        ),
        c(
            k(),
            tri(p(3., -1., 4.), p(3., 1., 4.), p(1.5, 0., 6.)),
            slant,
            "triangle in the slant's tangent plane",
        ),
        c(
            k(),
            hull(&[p(3., -1., 4.), p(3., 1., 4.), p(1.5, 0., 6.), p(7., 0., 7.)]),
            slant,
            "hull face on the slant",
        ),
        c(
            cone(p(0., 0., 200.), p(0., 0., 0.), 150.0),
            cone(p(0., 0., 200.), p(192., 0., 144.), 150.0),
            slant,
            "cones mirrored across a tangent plane (common generator)",
        ),
    ]
}

/// Every base contact.
pub fn contacts() -> Vec<Contact> {
    let mut all = cylinder_contacts();
    all.extend(cone_contacts());
    all
}

/// An exact similarity: `x ↦ 2^e · M · x + t` with `M = n·R` an integer matrix (`R` a rotation),
/// radii times `2^e · n`.
#[derive(Debug, Clone, Copy)]
pub struct Similarity {
    pub m: [[i64; 3]; 3],
    pub n: i64,
    pub exp: i32,
}

impl Similarity {
    /// From an integer quaternion `(a, b, c, d)`.
    pub fn from_quaternion(a: i64, b: i64, c: i64, d: i64, exp: i32) -> Self {
        let m = [
            [
                a * a + b * b - c * c - d * d,
                2 * (b * c - a * d),
                2 * (b * d + a * c),
            ],
            [
                2 * (b * c + a * d),
                a * a - b * b + c * c - d * d,
                2 * (c * d - a * b),
            ],
            [
                2 * (b * d - a * c),
                2 * (c * d + a * b),
                a * a - b * b - c * c + d * d,
            ],
        ];
        Similarity {
            m,
            n: a * a + b * b + c * c + d * d,
            exp,
        }
    }

    pub fn identity(exp: i32) -> Self {
        Self::from_quaternion(1, 0, 0, 0, exp)
    }

    fn apply(&self, x: [f64; 3]) -> Option<[f64; 3]> {
        let s = 2f64.powi(self.exp);
        let mut out = [0.0; 3];
        for (i, o) in out.iter_mut().enumerate() {
            let mut exact = Q::from_integer(0.into());
            let mut approx = 0.0;
            for (j, xj) in x.iter().enumerate() {
                exact += Q::from_integer(self.m[i][j].into()) * q(*xj);
                approx += self.m[i][j] as f64 * xj;
            }
            let y = approx * s;
            if !y.is_finite() || q(y) != exact * q(s) {
                return None;
            }
            *o = y;
        }
        Some(out)
    }

    fn radius(&self, r: f64) -> Option<f64> {
        let y = r * self.n as f64 * 2f64.powi(self.exp);
        (q(y) == q(r) * Q::from_integer(self.n.into()) * q(2f64.powi(self.exp))).then_some(y)
    }

    /// The image of `normal` as an integer-direction vector (a positive multiple of `R·n`).
    pub fn direction(&self, n: [f64; 3]) -> [f64; 3] {
        let mut out = [0.0; 3];
        for (i, o) in out.iter_mut().enumerate() {
            *o = (0..3).map(|j| self.m[i][j] as f64 * n[j]).sum();
        }
        out
    }
}

fn arr(p: &Point3<f64>) -> [f64; 3] {
    [p.x, p.y, p.z]
}

/// Maps every defining point with `point`, every defining vector with `vector`, every radius
/// with `radius`; `None` if a map is not exact or a constructor refuses the image.
pub fn map_shape(
    s: &Shape,
    point: &dyn Fn([f64; 3]) -> Option<[f64; 3]>,
    vector: &dyn Fn([f64; 3]) -> Option<[f64; 3]>,
    radius: &dyn Fn(f64) -> Option<f64>,
) -> Option<Shape> {
    let pt = |x: &Point3<f64>| point(arr(x)).map(|y| Point3::new(y[0], y[1], y[2]));
    let vc = |x: &Vector3<f64>| vector([x.x, x.y, x.z]).map(|y| Vector3::new(y[0], y[1], y[2]));
    Some(match s {
        Shape::Ball(b) => Ball::new(pt(b.centre())?, radius(b.radius())?).ok()?.into(),
        Shape::Capsule(c) => Capsule::new(pt(c.a())?, pt(c.b())?, radius(c.radius())?)
            .ok()?
            .into(),
        Shape::Cylinder(c) => Cylinder::new(pt(c.a())?, pt(c.b())?, radius(c.radius())?)
            .ok()?
            .into(),
        Shape::Cone(c) => Cone::new(pt(c.apex())?, pt(c.base())?, radius(c.radius())?)
            .ok()?
            .into(),
        Shape::Cuboid(c) => {
            let [u, w, x] = c.half_axes();
            Cuboid::new(pt(c.centre())?, [vc(u)?, vc(w)?, vc(x)?])
                .ok()?
                .into()
        }
        Shape::HalfSpace(h) => HalfSpace::new(pt(h.point())?, vc(h.normal())?).ok()?.into(),
        Shape::ConvexHull(h) => ConvexHull::new(h.points().iter().map(pt).collect::<Option<_>>()?)
            .ok()?
            .into(),
        Shape::Triangle(t) => {
            let [a, b, c] = t.vertices();
            Triangle::new(pt(a)?, pt(b)?, pt(c)?).ok()?.into()
        }
        Shape::Segment(s) => Segment::new(pt(s.a())?, pt(s.b())?).ok()?.into(),
    })
}

/// The shape under an exact similarity.
pub fn similar(s: &Shape, t: &Similarity) -> Option<Shape> {
    let rot = |x: [f64; 3]| t.apply(x);
    map_shape(s, &rot, &rot, &|r| t.radius(r))
}

/// The shape moved by `d`, exactly (`None` if a coordinate would round).
pub fn translated(s: &Shape, d: [f64; 3]) -> Option<Shape> {
    let mv = |x: [f64; 3]| {
        let y = [x[0] + d[0], x[1] + d[1], x[2] + d[2]];
        (0..3).all(|i| q(y[i]) == q(x[i]) + q(d[i])).then_some(y)
    };
    map_shape(s, &mv, &Some, &Some)
}

/// The largest magnitude among a shape's coordinates and vector components.
pub fn magnitude(s: &Shape) -> f64 {
    let m = std::cell::Cell::new(0.0f64);
    let see = |x: [f64; 3]| {
        m.set(m.get().max(x[0].abs()).max(x[1].abs()).max(x[2].abs()));
        Some(x)
    };
    let _ = map_shape(s, &see, &see, &Some);
    m.get()
}

/// One unit in the last place of `x` (`x > 0`).
pub fn ulp(x: f64) -> f64 {
    x.next_up() - x
}

/// The touching pair, the second shape moved out by `step·N` (disjoint) and in (meeting),
/// under the similarity `t`. `None` if a map is inexact.
pub fn variants(contact: &Contact, t: &Similarity, step: f64, tag: &str) -> Option<Vec<Known>> {
    let a = similar(&contact.a, t)?;
    let b = similar(&contact.b, t)?;
    let n = t.direction(contact.n);
    let away = translated(&b, n.map(|x| x * step))?;
    let into = translated(&b, n.map(|x| -x * step))?;
    let note = |what: &str| format!("{}; {tag}; {what}", contact.note);
    Some(vec![
        Known {
            a: a.clone(),
            b,
            expected: true,
            note: note("touching"),
        },
        Known {
            a: a.clone(),
            b: away,
            expected: false,
            note: note("moved out"),
        },
        Known {
            a,
            b: into,
            expected: true,
            note: note("moved in"),
        },
    ])
}

/// The rotations the constructed pairs use (integer quaternions).
pub const ROTATIONS: [(i64, i64, i64, i64); 4] =
    [(1, 1, 0, 0), (2, 1, 0, 0), (1, 1, 1, 0), (3, 1, 2, 1)];

/// Every constructed pair at a power-of-two scale `exp`: in the contact's own frame moved by
/// one ulp of the pair's largest coordinate (times the normal's integer components), and under
/// each rotation moved by `2^-32` of the scale (times the rotated normal's integer components).
pub fn known_pairs(exp: i32) -> Vec<Known> {
    let mut out = Vec::new();
    for contact in contacts() {
        let id = Similarity::identity(exp);
        let a = similar(&contact.a, &id).expect("a power-of-two scale is exact");
        let b = similar(&contact.b, &id).expect("a power-of-two scale is exact");
        let step = ulp(magnitude(&a).max(magnitude(&b)));
        let scaled = Contact {
            a,
            b,
            n: contact.n,
            note: contact.note,
        };
        let tag = format!("scale 2^{exp}; one ulp");
        out.extend(
            variants(&scaled, &Similarity::identity(0), step, &tag)
                .unwrap_or_else(|| panic!("inexact ulp move: {}", contact.note)),
        );
        for (i, &(qa, qb, qc, qd)) in ROTATIONS.iter().enumerate() {
            let t = Similarity::from_quaternion(qa, qb, qc, qd, exp);
            let tag = format!("scale 2^{exp}; rotation {i}; step 2^-32");
            out.extend(
                variants(&contact, &t, 2f64.powi(exp - 32), &tag)
                    .unwrap_or_else(|| panic!("inexact rotation: {}", contact.note)),
            );
        }
    }
    out
}
