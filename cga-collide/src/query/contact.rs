//! Contact geometry: the exact intersection of two triangles (a point, a segment or a coplanar
//! convex polygon, in rationals), and the contact class of two closed meshes.
//!
//! # The class of two closed meshes
//! [`contact_class`] answers [`Contact::Disjoint`], [`Contact::Touching`] (the surfaces meet,
//! no interior overlap was found), [`Contact::Penetrating`] or one inside the other
//! ([`Contact::AInsideB`], [`Contact::BInsideA`], surfaces apart).
//! * Without surface contact (exact pair test) the class is disjoint or inside (exact
//!   point-in-solid of one vertex).
//! * With surface contact, **penetrating** is only answered with a witness, decided exactly:
//!   a triangle pair whose intersection is a segment of positive length through the relative
//!   interiors of both (the faces cross), a coplanar overlap of positive area of faces whose
//!   outward normals agree (the solids lie on the same side), or a vertex of one mesh strictly
//!   inside the other solid.
//! * Otherwise the answer is **touching**. This is the true class whenever interior overlap
//!   shows in one of those witnesses, which covers crossings of faces, faces pushed into faces,
//!   edges and vertices poking through faces, and every touching contact of faces, edges and
//!   vertices from outside. A limitation remains: an overlap whose only evidence lies on edges of
//!   both meshes at once (an edge of one crossing the other's surface exactly along one of
//!   its edges, with every vertex on or outside the other surface) is reported as touching.
//!
//! Outward orientation is taken from the sign of each mesh's volume (exact), so inward-facing
//! closed meshes work too; the meshes must be consistently oriented.

use core::cmp::Ordering;

use ga_core::scalar::{rational_from_f64, Rational, Ring};
use nalgebra::Point3;
use num_traits::Signed;

use crate::exact::predicates::Orient3d;
use crate::exact::{ErrF64, Predicate};
use crate::query::{Collider, Intersects, Mode};
use crate::shape::Triangle;

/// An exact point.
pub type ExactPoint = [Rational; 3];

/// The intersection of two closed triangles, exactly.
#[derive(Debug, Clone, PartialEq)]
pub enum ContactGeometry {
    /// They meet in one point.
    Point(ExactPoint),
    /// They meet in a segment of positive length (its two end points).
    Segment(ExactPoint, ExactPoint),
    /// They are coplanar and overlap in a convex polygon of positive area (its corners in
    /// order around it).
    Polygon(Vec<ExactPoint>),
}

impl ContactGeometry {
    /// The corners as `f64` (nearest values), for drawing and for files.
    pub fn points_f64(&self) -> Vec<[f64; 3]> {
        let f = |p: &ExactPoint| p.clone().map(|x| ga_core::scalar::Real::to_f64(&x));
        match self {
            ContactGeometry::Point(p) => vec![f(p)],
            ContactGeometry::Segment(p, q) => vec![f(p), f(q)],
            ContactGeometry::Polygon(ps) => ps.iter().map(f).collect(),
        }
    }
}

type Q3 = ExactPoint;

fn q3(p: &Point3<f64>) -> Q3 {
    [p.x, p.y, p.z].map(|x| rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero))
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
fn lerp(a: &Q3, b: &Q3, t: &Rational) -> Q3 {
    let d = sub(b, a);
    [&a[0] + &d[0] * t, &a[1] + &d[1] * t, &a[2] + &d[2] * t]
}
fn is_zero(v: &Q3) -> bool {
    v.iter().all(Ring::is_zero)
}
fn zero() -> Rational {
    <Rational as Ring>::zero()
}
fn one() -> Rational {
    <Rational as Ring>::one()
}

/// The parameter interval `[t0, t1] ⊂ [0, 1]` of segment `ab` inside the closed segment `cd`.
fn clip_segment(a: &Q3, b: &Q3, c: &Q3, d: &Q3) -> Option<(Rational, Rational)> {
    let (u, v, w) = (sub(b, a), sub(d, c), sub(c, a));
    if is_zero(&u) {
        // `ab` is a point: on `cd`?
        let x = sub(a, c);
        let on = is_zero(&cross(&v, &x)) && {
            let t = dot(&x, &v);
            !t.is_negative() && t <= dot(&v, &v)
        };
        return on.then(|| (zero(), zero()));
    }
    let n = cross(&u, &v);
    if !is_zero(&n) {
        if !dot(&n, &w).is_zero() {
            return None; // skew lines
        }
        let nn = dot(&n, &n);
        let s = dot(&cross(&w, &v), &n) / &nn;
        let t = dot(&cross(&w, &u), &n) / &nn;
        let inside = |x: &Rational| !x.is_negative() && x <= &one();
        return (inside(&s) && inside(&t)).then(|| (s.clone(), s));
    }
    if !is_zero(&cross(&u, &w)) {
        return None; // parallel, not collinear
    }
    let uu = dot(&u, &u);
    let tc = dot(&w, &u) / &uu;
    let td = dot(&sub(d, a), &u) / &uu;
    let (lo, hi) = if tc <= td { (tc, td) } else { (td, tc) };
    let (lo, hi) = (lo.max(zero()), hi.min(one()));
    (lo <= hi).then_some((lo, hi))
}

/// The parameter interval of segment `ab` inside the closed triangle `t` (any triangle).
fn clip(a: &Q3, b: &Q3, t: &[Q3; 3]) -> Option<(Rational, Rational)> {
    let n = cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]));
    if is_zero(&n) {
        // A degenerate triangle is the union of its edges (one of them covers it).
        let mut out: Option<(Rational, Rational)> = None;
        for i in 0..3 {
            if let Some((lo, hi)) = clip_segment(a, b, &t[i], &t[(i + 1) % 3]) {
                out = Some(match out {
                    None => (lo, hi),
                    Some((l, h)) => (l.min(lo), h.max(hi)),
                });
            }
        }
        return out;
    }
    let edge = |x: &Q3, i: usize| dot(&cross(&sub(&t[(i + 1) % 3], &t[i]), &sub(x, &t[i])), &n);
    let (da, db) = (dot(&n, &sub(a, &t[0])), dot(&n, &sub(b, &t[0])));
    if da.is_zero() && db.is_zero() {
        let (mut lo, mut hi) = (zero(), one());
        for i in 0..3 {
            let (f0, f1) = (edge(a, i), edge(b, i));
            let slope = &f1 - &f0;
            if slope.is_zero() {
                if f0.is_negative() {
                    return None;
                }
            } else {
                let root = -&f0 / &slope;
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
    let x = lerp(a, b, &s);
    (0..3)
        .all(|i| !edge(&x, i).is_negative())
        .then(|| (s.clone(), s))
}

/// The intersection of two closed triangles, exactly; `None` when they do not meet.
///
/// The intersection is convex, and each of its corners is an end point of the part of some
/// edge of one triangle inside the other; those end points are computed in rationals and
/// sorted into a point, a segment or a polygon.
///
/// ```
/// use cga_collide::{nalgebra::Point3, query::{self, ContactGeometry}, Triangle};
/// let p = |x, y, z| Point3::new(x, y, z);
/// let a = Triangle::new(p(0., 0., 0.), p(2., 0., 0.), p(0., 2., 0.))?;
/// let b = Triangle::new(p(0.5, 0.5, -1.), p(0.5, 0.5, 1.), p(3., 3., 0.))?;
/// assert!(matches!(query::triangle_intersection(&a, &b), Some(ContactGeometry::Segment(..))));
/// # Ok::<(), cga_collide::GeometryError>(())
/// ```
pub fn triangle_intersection(a: &Triangle, b: &Triangle) -> Option<ContactGeometry> {
    if !a.intersects(b) {
        return None;
    }
    let (p, r) = (a.vertices().map(|v| q3(&v)), b.vertices().map(|v| q3(&v)));
    let mut pts: Vec<Q3> = Vec::new();
    for (s, t) in [(&p, &r), (&r, &p)] {
        for i in 0..3 {
            let (x, y) = (&s[i], &s[(i + 1) % 3]);
            if let Some((t0, t1)) = clip(x, y, t) {
                for e in [lerp(x, y, &t0), lerp(x, y, &t1)] {
                    if !pts.contains(&e) {
                        pts.push(e);
                    }
                }
            }
        }
    }
    Some(shape_of(pts))
}

fn shape_of(mut pts: Vec<Q3>) -> ContactGeometry {
    if pts.len() == 1 {
        return ContactGeometry::Point(pts.remove(0));
    }
    let o = pts[0].clone();
    // A point off the line through the first two: then it is a polygon.
    let normal = pts[2..]
        .iter()
        .map(|x| cross(&sub(&pts[1], &o), &sub(x, &o)))
        .find(|n| !is_zero(n));
    let Some(n) = normal else {
        // Collinear: the two extremes along the line.
        let dir = sub(&pts[1], &o);
        let key = |x: &Q3| dot(&sub(x, &o), &dir);
        let lo = pts.iter().min_by(|x, y| key(x).cmp(&key(y))).cloned();
        let hi = pts.iter().max_by(|x, y| key(x).cmp(&key(y))).cloned();
        return match (lo, hi) {
            (Some(lo), Some(hi)) => ContactGeometry::Segment(lo, hi),
            _ => ContactGeometry::Point(o),
        };
    };
    // Keep only the corners (drop points strictly inside a segment between two others).
    let between = |x: &Q3, y: &Q3, z: &Q3| {
        x != y
            && x != z
            && is_zero(&cross(&sub(y, x), &sub(z, x)))
            && dot(&sub(y, x), &sub(z, x)).is_negative()
    };
    let corners: Vec<Q3> = pts
        .iter()
        .filter(|x| !pts.iter().any(|y| pts.iter().any(|z| between(x, y, z))))
        .cloned()
        .collect();
    let mut pts = corners;
    // Convex position: sort around the first point by orientation about `n`, after moving the
    // lowest point (along a fixed order) first so that the angles span less than π.
    let first = (0..pts.len())
        .min_by(|&i, &j| pts[i].partial_cmp(&pts[j]).unwrap_or(Ordering::Equal))
        .unwrap_or(0);
    let pivot = pts.swap_remove(first);
    pts.sort_by(|x, y| {
        let s = dot(&cross(&sub(x, &pivot), &sub(y, &pivot)), &n);
        if s.is_positive() {
            Ordering::Less
        } else if s.is_negative() {
            Ordering::Greater
        } else {
            // Collinear with the pivot: nearer first.
            dot(&sub(x, &pivot), &sub(x, &pivot)).cmp(&dot(&sub(y, &pivot), &sub(y, &pivot)))
        }
    });
    let mut poly = vec![pivot];
    poly.extend(pts);
    ContactGeometry::Polygon(poly)
}

/// Every intersecting triangle pair `(i, j)` of two meshes with its exact intersection.
pub fn contact_geometry(a: &Collider, b: &Collider) -> Vec<((u32, u32), ContactGeometry)> {
    use crate::parallel::*;
    a.intersecting_pairs(b, Mode::Bvh)
        .par_iter()
        .filter_map(|&(i, j)| {
            triangle_intersection(&a.triangle(i), &b.triangle(j)).map(|g| ((i, j), g))
        })
        .collect()
}

/// How two closed meshes are placed relative to each other (see the [module docs](self)).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Contact {
    /// The solids do not meet.
    Disjoint,
    /// The surfaces meet and no interior overlap was found (see the module docs).
    Touching,
    /// The interiors overlap (a witness was found).
    Penetrating,
    /// The surfaces do not meet and A lies inside B.
    AInsideB,
    /// The surfaces do not meet and B lies inside A.
    BInsideA,
}

impl Contact {
    /// The name used in the CLI's JSON: `disjoint`, `touching`, `penetrating`, `a_inside_b`,
    /// `b_inside_a`.
    pub fn name(self) -> &'static str {
        match self {
            Contact::Disjoint => "disjoint",
            Contact::Touching => "touching",
            Contact::Penetrating => "penetrating",
            Contact::AInsideB => "a_inside_b",
            Contact::BInsideA => "b_inside_a",
        }
    }
}

/// The sign of the volume enclosed by a closed mesh (`Greater`: outward orientation), exact:
/// the sum of `orient3d(0, a, b, c)` with a running error bound, exactly when uncertain.
fn orientation(c: &Collider) -> Ordering {
    let mesh = c.mesh();
    let o = mesh
        .vertices()
        .first()
        .copied()
        .unwrap_or_else(Point3::origin);
    let term = |i: usize| {
        let [a, b, d] = mesh.triangle(i);
        [o, a, b, d].map(|p| [p.x, p.y, p.z])
    };
    let mut sum = ErrF64::exact(0.0);
    for i in 0..mesh.num_triangles() {
        let x: [f64; 12] = term(i).concat().try_into().unwrap_or([0.0; 12]);
        sum = sum + Orient3d::eval(&x.map(ErrF64::exact));
    }
    if let Some(s) = sum.sign() {
        return s;
    }
    let mut exact = zero();
    for i in 0..mesh.num_triangles() {
        let x: [f64; 12] = term(i).concat().try_into().unwrap_or([0.0; 12]);
        exact += Orient3d::eval(&x.map(|v| rational_from_f64(v).unwrap_or_else(zero)));
    }
    if exact.is_positive() {
        Ordering::Greater
    } else if exact.is_negative() {
        Ordering::Less
    } else {
        Ordering::Equal
    }
}

/// Strictly inside the non-degenerate triangle `t` (relative interior).
fn strictly_inside(x: &Q3, t: &[Q3; 3]) -> bool {
    let n = cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]));
    !is_zero(&n)
        && (0..3)
            .all(|i| dot(&cross(&sub(&t[(i + 1) % 3], &t[i]), &sub(x, &t[i])), &n).is_positive())
}

/// Whether the contact of triangle `i` of `a` and `j` of `b` shows interior overlap.
fn pair_penetrates(a: &Collider, b: &Collider, i: u32, j: u32, same_sense: bool) -> bool {
    let (ta, tb) = (a.triangle(i), b.triangle(j));
    let Some(g) = triangle_intersection(&ta, &tb) else {
        return false;
    };
    let (p, r) = (ta.vertices().map(|v| q3(&v)), tb.vertices().map(|v| q3(&v)));
    match g {
        ContactGeometry::Point(_) => false,
        ContactGeometry::Segment(x, y) => {
            let mid = lerp(&x, &y, &(one() / Rational::from_integer(2.into())));
            let na = cross(&sub(&p[1], &p[0]), &sub(&p[2], &p[0]));
            let coplanar = dot(&na, &sub(&r[0], &p[0])).is_zero()
                && dot(&na, &sub(&r[1], &p[0])).is_zero()
                && dot(&na, &sub(&r[2], &p[0])).is_zero();
            !coplanar && strictly_inside(&mid, &p) && strictly_inside(&mid, &r)
        }
        ContactGeometry::Polygon(_) => {
            let na = cross(&sub(&p[1], &p[0]), &sub(&p[2], &p[0]));
            let nb = cross(&sub(&r[1], &r[0]), &sub(&r[2], &r[0]));
            // Same outward side: both solids lie behind the common face.
            dot(&na, &nb).is_positive() == same_sense
        }
    }
}

/// The contact class of two closed meshes (in the same frame), see the [module docs](self).
///
/// ```
/// use cga_collide::{nalgebra::{Isometry3, Point3}, query::{self, Collider, Contact}, TriMesh};
/// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
/// let at = |x| cube.placed(&Isometry3::translation(x, 0.0, 0.0)).unwrap();
/// assert_eq!(query::contact_class(&cube, &at(1.0)), Contact::Touching);
/// assert_eq!(query::contact_class(&cube, &at(0.5)), Contact::Penetrating);
/// assert_eq!(query::contact_class(&cube, &at(1.5)), Contact::Disjoint);
/// # Ok::<(), cga_collide::mesh::MeshError>(())
/// ```
pub fn contact_class(a: &Collider, b: &Collider) -> Contact {
    let pairs = a.intersecting_pairs(b, Mode::Bvh);
    let inside = |inner: &Collider, outer: &Collider| {
        inner
            .mesh()
            .vertices()
            .first()
            .is_some_and(|v| outer.contains_point(v, Mode::Bvh))
    };
    if pairs.is_empty() {
        return if inside(a, b) {
            Contact::AInsideB
        } else if inside(b, a) {
            Contact::BInsideA
        } else {
            Contact::Disjoint
        };
    }
    let same_sense = orientation(a) == orientation(b);
    use crate::parallel::*;
    let crossing = pairs
        .par_iter()
        .any(|&(i, j)| pair_penetrates(a, b, i, j, same_sense));
    if crossing {
        return Contact::Penetrating;
    }
    // A vertex strictly inside the other solid (inside and not on its surface).
    let strictly = |inner: &Collider, outer: &Collider| {
        inner.mesh().vertices().par_iter().any(|v| {
            outer.contains_point(v, Mode::Bvh) && {
                let Ok(point) = crate::Segment::new(*v, *v) else {
                    return false;
                };
                outer.segment_hits(&point, Mode::Bvh).is_empty()
            }
        })
    };
    if strictly(a, b) || strictly(b, a) {
        Contact::Penetrating
    } else {
        Contact::Touching
    }
}
