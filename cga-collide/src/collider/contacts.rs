//! How two closed meshes touch: every contact with its exact geometry
//! ([`Collider::contacts`]) and the contact class ([`Collider::contact_class`]).
//!
//! # The class of two closed meshes
//! [`contact_class`] answers [`ContactClass::Disjoint`], [`ContactClass::Touching`] (the surfaces meet,
//! the interiors do not), [`ContactClass::Penetrating`] (the interiors overlap and the surfaces
//! meet) or one inside the other ([`ContactClass::AInsideB`], [`ContactClass::BInsideA`], surfaces apart).
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
//! (check one with [`Collider::self_intersects`]). Outward orientation is taken
//! from the sign of each mesh's volume (exact), so inward-facing meshes work too. Neighbours
//! are found by vertex positions, so meshes need not share vertex indices. At an edge without
//! exactly one neighbouring non-degenerate triangle the cone is unknown and that contact gives
//! no witness (the answer may then be touching where the interiors overlap).
//!
//! A solid inside the other with touching surfaces is **penetrating**: the interiors overlap.

use core::cmp::Ordering;
use std::collections::HashMap;

use ga_core::scalar::{rational_from_f64, Rational};
use nalgebra::{Isometry3, Point3};
use num_traits::Signed;

use crate::collider::Collider;
use crate::error::Error;
use crate::exact::predicates::Orient3d;
use crate::exact::vector::{cross, dot, sub};
use crate::exact::{ErrF64, Predicate};
use crate::query::contact::{clip, half, is_zero, lerp, one, q3, zero, Q3};
use crate::query::containment::exact_point_in_solid;
use crate::query::{triangle_intersection, ContactGeometry};

/// Every intersecting triangle pair `(i, j)` with the exact intersection of the two triangles,
/// sorted by pair: what [`Collider::contacts`] returns.
pub type Contacts = Vec<((u32, u32), ContactGeometry)>;

impl Collider {
    /// Every intersecting triangle pair `(i, j)` of `self` and `other` (in one frame) with its
    /// exact intersection (a point, a segment or a coplanar polygon), sorted by pair.
    ///
    /// ```
    /// use cga_collide::{nalgebra::{Isometry3, Point3}, query::ContactGeometry, Collider, TriMesh};
    /// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
    /// let touching = cube.placed(&Isometry3::translation(1.0, 0.0, 0.0))?;
    /// let contacts = cube.contacts(&touching);
    /// assert!(contacts.iter().any(|(_, g)| matches!(g, ContactGeometry::Polygon(_))));
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn contacts(&self, other: &Collider) -> Contacts {
        use crate::parallel::*;
        self.intersecting_pairs(other)
            .par_iter()
            .filter_map(|&(i, j)| {
                triangle_intersection(&self.triangle(i), &other.triangle(j)).map(|g| ((i, j), g))
            })
            .collect()
    }

    /// [`contacts`](Self::contacts) of `self` at `pose_a` and `other` at `pose_b`, in world
    /// coordinates. The meshes are placed first (work proportional to their size per pose):
    /// the exact geometry is computed on the placed triangles.
    pub fn contacts_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<Contacts, Error> {
        let (a, b) = self.placed_pair(pose_a, other, pose_b)?;
        Ok(a.contacts(&b))
    }

    /// The contact class of two closed meshes (in one frame), see the module docs.
    ///
    /// ```
    /// use cga_collide::{nalgebra::{Isometry3, Point3}, collider::ContactClass, Collider, TriMesh};
    /// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
    /// let at = |x| cube.placed(&Isometry3::translation(x, 0.0, 0.0)).unwrap();
    /// assert_eq!(cube.contact_class(&at(1.0)), ContactClass::Touching);
    /// assert_eq!(cube.contact_class(&at(0.5)), ContactClass::Penetrating);
    /// assert_eq!(cube.contact_class(&at(1.5)), ContactClass::Disjoint);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn contact_class(&self, other: &Collider) -> ContactClass {
        classify(self, other)
    }

    /// The contact class of `self` at `pose_a` and `other` at `pose_b`: the
    /// [`contact_class`](Self::contact_class) of the placed meshes (placed first, work
    /// proportional to their size per pose; the pose checks are those of every `_at` query).
    ///
    /// ```
    /// use cga_collide::{nalgebra::{Isometry3, Point3}, collider::ContactClass, Collider, TriMesh};
    /// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
    /// let here = Isometry3::identity();
    /// let class = cube.contact_class_at(&here, &cube, &Isometry3::translation(1.0, 0.0, 0.0))?;
    /// assert_eq!(class, ContactClass::Touching);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn contact_class_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<ContactClass, Error> {
        let (a, b) = self.placed_pair(pose_a, other, pose_b)?;
        Ok(a.contact_class(&b))
    }
}

/// How two closed meshes are placed relative to each other (see [`Collider::contact_class`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum ContactClass {
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

impl ContactClass {
    /// The name used in the CLI's JSON: `disjoint`, `touching`, `penetrating`, `a_inside_b`,
    /// `b_inside_a`.
    pub fn name(self) -> &'static str {
        match self {
            ContactClass::Disjoint => "disjoint",
            ContactClass::Touching => "touching",
            ContactClass::Penetrating => "penetrating",
            ContactClass::AInsideB => "a_inside_b",
            ContactClass::BInsideA => "b_inside_a",
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
        let [a, b, d] = mesh.corners(i as u32);
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
            let t = collider.mesh().corners(f);
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
        self.collider.mesh().corners(f).map(|v| q3(&v))
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
        let f64s = self.collider.mesh().corners(f);
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
        .filter_map(|&g| clip(p, q, &b.mesh().corners(g).map(|v| q3(&v))))
        .collect();
    let mut cuts = vec![zero(), one()];
    cuts.extend(on_b.iter().flat_map(|(lo, hi)| [lo.clone(), hi.clone()]));
    cuts.sort();
    cuts.dedup();
    cuts.windows(2).any(|w| {
        let mid = (&w[0] + &w[1]) * half();
        !on_b.iter().any(|(lo, hi)| lo <= &mid && &mid <= hi)
            && exact_point_in_solid(
                (0..b.mesh().num_triangles()).map(|g| b.mesh().corners(g as u32)),
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
        let t = a.collider.mesh().corners(f);
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

/// The contact class (see the module docs).
fn classify(a: &Collider, b: &Collider) -> ContactClass {
    let pairs = a.intersecting_pairs(b);
    let inside = |inner: &Collider, outer: &Collider| {
        inner
            .mesh()
            .vertices()
            .first()
            .is_some_and(|v| outer.contains_point(v))
    };
    if pairs.is_empty() {
        return if inside(a, b) {
            ContactClass::AInsideB
        } else if inside(b, a) {
            ContactClass::BInsideA
        } else {
            ContactClass::Disjoint
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
        return ContactClass::Penetrating;
    }
    // A vertex strictly inside the other solid (inside and not on its surface).
    let strictly = |inner: &Collider, outer: &Collider| {
        inner.mesh().vertices().par_iter().any(|v| {
            outer.contains_point(v) && {
                let Ok(point) = crate::Segment::new(*v, *v) else {
                    return false;
                };
                outer.segment_hits(&point).is_empty()
            }
        })
    };
    if strictly(a, b) || strictly(b, a) {
        return ContactClass::Penetrating;
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
        ContactClass::Penetrating
    } else {
        ContactClass::Touching
    }
}
