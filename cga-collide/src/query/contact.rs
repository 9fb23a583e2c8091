//! Contact geometry: the exact intersection of two triangles (a point, a segment or a coplanar
//! convex polygon, in rationals), and the contact class of two closed meshes.
//!
//! # The class of two closed meshes
//! [`contact_class`] answers [`Contact::Disjoint`], [`Contact::Touching`] (the surfaces meet,
//! the interiors do not), [`Contact::Penetrating`] (the interiors overlap and the surfaces
//! meet) or one inside the other ([`Contact::AInsideB`], [`Contact::BInsideA`], surfaces apart).
//! Every step is exact.
//! * Without surface contact (exact pair test) the class is disjoint or inside (exact
//!   point-in-solid of one vertex).
//! * With surface contact the interiors overlap exactly when one of three witnesses exists:
//!   1. **A contact whose neighbourhood is inside both.** At a point of the relative interior
//!      of a segment or polygon where two triangles meet, each solid fills an open cone of
//!      directions: a half-space inside a triangle, a wedge on an edge (both half-spaces of a
//!      convex edge, either of a reflex one). A vertex cannot be there (a vertex of a triangle
//!      is never inside a segment of it), and the cones do not change along the contact, so one
//!      point decides it. The two cones meet exactly when the solids overlap right there; the
//!      test is exact, in the plane across the contact. This covers faces crossing faces, faces
//!      pushed into faces, coplanar faces on the same side, and edges lying on faces or on edges
//!      with the solids on the same side.
//!   2. **A vertex strictly inside the other solid.**
//!   3. **A piece of an edge strictly inside the other solid**: each edge of a triangle in
//!      contact is cut where it meets the other surface, and the middle of each piece is
//!      located exactly (a rational ray parity test). This covers edges that cross the other
//!      solid between points of its surface, as an octahedron's edges do in the cube whose
//!      face centres are its vertices.
//!
//!   These are complete: if the interiors overlap and the surfaces meet, either an edge
//!   enters the other solid's interior somewhere (3, or 2 at its end), or a triangle's
//!   interior does, and then the region where it does is bounded inside that triangle by
//!   contacts of positive length along which the cones meet (1); or neither surface enters the
//!   other's interior, and then the overlap is bounded by coplanar faces on the same side (1).
//! * Otherwise the answer is **touching**.
//!
//! This holds for closed, consistently oriented 2-manifold meshes without self-intersections
//! (check one with [`crate::query::self_intersects`]). Outward orientation is taken
//! from the sign of each mesh's volume (exact), so inward-facing meshes work too. Neighbours
//! are found by vertex positions, so meshes need not share vertex indices. At an edge without
//! exactly one neighbouring non-degenerate triangle the cone is unknown and that contact gives
//! no witness (the answer may then be touching where the interiors overlap).
//!
//! A solid inside the other with touching surfaces is **penetrating**: the interiors overlap.

use core::cmp::Ordering;
use std::collections::HashMap;

use ga_core::scalar::{rational_from_f64, Rational, Ring};
use nalgebra::Point3;
use num_traits::Signed;

use crate::exact::predicates::Orient3d;
use crate::exact::{ErrF64, Predicate};
use crate::query::containment::exact_point_in_solid;
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
fn half() -> Rational {
    Rational::new(1.into(), 2.into())
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

/// An undirected edge by the bit patterns of its end points (so that meshes whose triangles do
/// not share vertex indices still find their neighbours).
type EdgeKey = ([u64; 3], [u64; 3]);

fn edge_key(p: &Point3<f64>, q: &Point3<f64>) -> EdgeKey {
    // `+ 0.0` turns -0 into +0, so both spell the same point.
    let bits = |v: &Point3<f64>| [v.x, v.y, v.z].map(|x| (x + 0.0).to_bits());
    let (p, q) = (bits(p), bits(q));
    if p <= q {
        (p, q)
    } else {
        (q, p)
    }
}

/// The open cone of directions that lead from a surface point into the solid: a union of
/// alternatives, each the intersection of the open half-spaces `d · n < 0` of its normals.
type Cone = Vec<Vec<Q3>>;

/// The triangles of one mesh that take part in the contact, with what the local geometry at
/// a contact point needs: outward normals and the neighbours across each edge.
struct ContactSide<'a> {
    collider: &'a Collider,
    /// `Greater` when the triangles face outwards, `Less` inwards.
    sense: Ordering,
    edges: HashMap<EdgeKey, Vec<u32>>,
}

impl<'a> ContactSide<'a> {
    fn new(collider: &'a Collider, triangles: impl Iterator<Item = u32>, sense: Ordering) -> Self {
        let mut edges: HashMap<EdgeKey, Vec<u32>> = HashMap::new();
        for f in triangles {
            let t = collider.mesh().triangle(f as usize);
            for k in 0..3 {
                let list = edges.entry(edge_key(&t[k], &t[(k + 1) % 3])).or_default();
                if !list.contains(&f) {
                    list.push(f);
                }
            }
        }
        ContactSide {
            collider,
            sense,
            edges,
        }
    }

    fn corners(&self, f: u32) -> [Q3; 3] {
        self.collider.mesh().triangle(f as usize).map(|v| q3(&v))
    }

    /// The outward normal of triangle `f` (not of unit length); `None` if it is degenerate.
    fn normal(&self, f: u32) -> Option<Q3> {
        let t = self.corners(f);
        let n = cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]));
        match self.sense {
            _ if is_zero(&n) => None,
            Ordering::Greater => Some(n),
            Ordering::Less => Some(n.map(|x| -x)),
            Ordering::Equal => None,
        }
    }

    /// The cone into the solid at `m`, a point of triangle `f` that is not one of its
    /// vertices: a half-space inside the triangle, a wedge on an edge (convex: both
    /// half-spaces; reflex: either). `None` when it cannot be told: a degenerate triangle, or an
    /// edge without exactly one other non-degenerate triangle.
    fn cone(&self, f: u32, m: &Q3) -> Option<Cone> {
        let t = self.corners(f);
        let n = self.normal(f)?;
        let f64s = self.collider.mesh().triangle(f as usize);
        for k in 0..3 {
            let (p, q) = (&t[k], &t[(k + 1) % 3]);
            if !is_zero(&cross(&sub(q, p), &sub(m, p))) {
                continue;
            }
            let key = edge_key(&f64s[k], &f64s[(k + 1) % 3]);
            let others: Vec<u32> = self
                .edges
                .get(&key)?
                .iter()
                .copied()
                .filter(|&g| g != f)
                .collect();
            let [g] = others[..] else {
                return None;
            };
            let ng = self.normal(g)?;
            let far = self
                .corners(g)
                .into_iter()
                .find(|v| !is_zero(&cross(&sub(q, p), &sub(v, p))))?;
            let side = dot(&n, &sub(&far, p));
            return Some(if side.is_negative() {
                vec![vec![n, ng]] // convex edge
            } else if side.is_positive() {
                vec![vec![n], vec![ng]] // reflex edge
            } else {
                vec![vec![n]] // flat
            });
        }
        Some(vec![vec![n]])
    }
}

/// Whether some direction `d` has `d · n < 0` for every normal, all normals being
/// perpendicular to `u` (`u = 0`: all normals parallel). In the plane perpendicular to `u` such
/// directions form an open sector of angle at most π; if it is not empty, it holds `-n` for
/// one of the normals (angle π) or the sum of the two boundary rays, which are among the
/// directions `±u × n`.
fn open_cone_nonempty(normals: &[&Q3], u: &Q3) -> bool {
    let neg = |v: &Q3| v.clone().map(|x| -x);
    let rays: Vec<Q3> = normals
        .iter()
        .flat_map(|n| {
            let r = cross(u, n);
            [neg(&r), r]
        })
        .filter(|r| !is_zero(r))
        .collect();
    let mut candidates: Vec<Q3> = normals.iter().map(|n| neg(n)).collect();
    for (i, r) in rays.iter().enumerate() {
        for s in &rays[i + 1..] {
            candidates.push([&r[0] + &s[0], &r[1] + &s[1], &r[2] + &s[2]]);
        }
    }
    candidates
        .iter()
        .any(|d| !is_zero(d) && normals.iter().all(|n| dot(n, d).is_negative()))
}

/// Whether the interiors of the two solids overlap next to the contact of triangle `i` of `a`
/// and `j` of `b`: the cones into both solids at a point of the relative interior of the
/// contact (a segment's midpoint, a polygon's centroid) meet. Along that relative interior
/// both cones are constant, so one point decides the whole contact. A contact in one point
/// gives no answer here (see [`edge_enters`]).
fn contact_overlaps(a: &ContactSide, b: &ContactSide, i: u32, j: u32, g: &ContactGeometry) -> bool {
    let (m, u) = match g {
        ContactGeometry::Point(_) => return false,
        ContactGeometry::Segment(x, y) => (lerp(x, y, &half()), sub(y, x)),
        ContactGeometry::Polygon(ps) => {
            let k = Rational::from_integer((ps.len() as i64).into());
            let sum = ps.iter().fold([zero(), zero(), zero()], |acc, p| {
                [&acc[0] + &p[0], &acc[1] + &p[1], &acc[2] + &p[2]]
            });
            (sum.map(|x| x / &k), [zero(), zero(), zero()])
        }
    };
    let (Some(ca), Some(cb)) = (a.cone(i, &m), b.cone(j, &m)) else {
        return false;
    };
    ca.iter().any(|x| {
        cb.iter().any(|y| {
            let normals: Vec<&Q3> = x.iter().chain(y).collect();
            open_cone_nonempty(&normals, &u)
        })
    })
}

/// Whether an edge of a triangle of `a` that meets `b` has a piece strictly inside `b`: the
/// edge is cut where it meets `b`'s triangles (`others`, every triangle of `b` it meets), and
/// the middle of each piece off `b`'s surface is located exactly.
fn edge_enters(a: &ContactSide, f: u32, k: usize, others: &[u32], b: &Collider) -> bool {
    let t = a.corners(f);
    let (p, q) = (&t[k], &t[(k + 1) % 3]);
    if p == q {
        return false;
    }
    let on_b: Vec<(Rational, Rational)> = others
        .iter()
        .filter_map(|&g| clip(p, q, &b.mesh().triangle(g as usize).map(|v| q3(&v))))
        .collect();
    let mut cuts = vec![zero(), one()];
    cuts.extend(on_b.iter().flat_map(|(lo, hi)| [lo.clone(), hi.clone()]));
    cuts.sort();
    cuts.dedup();
    cuts.windows(2).any(|w| {
        let mid = (&w[0] + &w[1]) * half();
        !on_b.iter().any(|(lo, hi)| lo <= &mid && &mid <= hi)
            && exact_point_in_solid(
                (0..b.mesh().num_triangles()).map(|g| b.mesh().triangle(g)),
                &lerp(p, q, &mid),
            )
    })
}

/// Whether some edge of the contact triangles of `a` enters the interior of `b`.
fn some_edge_enters(a: &ContactSide, b: &Collider, pairs: &HashMap<u32, Vec<u32>>) -> bool {
    use crate::parallel::*;
    let mut edges: Vec<(u32, usize)> = Vec::new();
    let mut seen = std::collections::HashSet::new();
    for &f in pairs.keys() {
        let t = a.collider.mesh().triangle(f as usize);
        for k in 0..3 {
            if seen.insert(edge_key(&t[k], &t[(k + 1) % 3])) {
                edges.push((f, k));
            }
        }
    }
    edges
        .par_iter()
        .any(|&(f, k)| edge_enters(a, f, k, &pairs[&f], b))
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
    use crate::parallel::*;
    let (sa, sb) = (
        ContactSide::new(a, pairs.iter().map(|p| p.0), orientation(a)),
        ContactSide::new(b, pairs.iter().map(|p| p.1), orientation(b)),
    );
    let overlapping = pairs.par_iter().any(|&(i, j)| {
        triangle_intersection(&a.triangle(i), &b.triangle(j))
            .is_some_and(|g| contact_overlaps(&sa, &sb, i, j, &g))
    });
    if overlapping {
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
        return Contact::Penetrating;
    }
    let by_first = |flip: bool| {
        let mut map: HashMap<u32, Vec<u32>> = HashMap::new();
        for &(i, j) in &pairs {
            let (x, y) = if flip { (j, i) } else { (i, j) };
            map.entry(x).or_default().push(y);
        }
        map
    };
    if some_edge_enters(&sa, b, &by_first(false)) || some_edge_enters(&sb, a, &by_first(true)) {
        Contact::Penetrating
    } else {
        Contact::Touching
    }
}
