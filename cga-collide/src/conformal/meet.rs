//! Meet and classification of the thesis's six pairs (chapter II §3): line–line, line–plane,
//! line–sphere, plane–plane, sphere–plane, sphere–sphere.
//!
//! Each function computes the meet in the inner (IPNS) forms, `M = dual(A) ∧ dual(B)`, which
//! is the dual of the regressive product `A ∨ B` of the outer forms (`docs/conventions.md`), and
//! classifies from the sign of its square `M² = ⟨M M⟩₀` (the thesis's `B²`) and from whether
//! `M` vanishes:
//!
//! | pair | `M` | `M² < 0` | `M² = 0, M ≠ 0` | `M² > 0` | `M = 0` |
//! |---|---|---|---|---|---|
//! | line–plane | `L* ∧ π` (dual flat point) | point | parallel | — | contained |
//! | line–sphere | `L* ∧ s` (dual point pair) | two points | tangent | none | — |
//! | plane–plane | `π₁ ∧ π₂` (dual line) | line | parallel | — | coincident |
//! | sphere–plane | `s ∧ π` (dual circle) | circle | tangent | none | — |
//! | sphere–sphere | `s₁ ∧ s₂` (dual circle) | circle | tangent | disjoint / nested | coincident |
//!
//! Sphere–sphere further uses the sign of `(s₁·s₂)(s₁·n_inf)(s₂·n_inf)` (positive: one sphere
//! inside the other) and of `s₁²`, `s₂²` (imaginary spheres have no points). Line–line
//! (whose meet `L₁ ∨ L₂ = λ n_inf` is null, so its square says nothing) uses `λ ≠ 0` for skew
//! lines, and for coplanar lines the meet *relative to their join* `J = L₁ ∧ Q`
//! (`Q` a point of `L₂` off `L₁`): the flat point `F = (L₁ ⌋ J) ⌋ L₂`, with `F² > 0` for
//! intersecting, `F² = 0` for parallel and `F = 0` for coincident lines.
//!
//! **Certified**: every sign and every "is zero" is evaluated on [`crate::exact::ErrF64`]
//! (`f64` with a rigorous error bound) and, when that cannot decide, exactly on rationals
//! rebuilt from the primitives' `f64` data by the same generic code. The classification is
//! therefore exact for the primitives the `f64` inputs denote (see the
//! [exactness note](super#exactness)); the geometry carried by the variants is extracted in
//! `f64` from the rounded meet (relative accuracy about `1e-12` for moderate inputs; it can be
//! NaN when the blades overflow, beyond roughly `1e75`, or underflow, below roughly `1e-75`,
//! while the classification stays exact).
//!
//! ```
//! use cga_collide::conformal::{Plane, Sphere, meet::{Meet, SpherePlane}};
//! use cga_collide::nalgebra::{Point3, Vector3};
//! let s = Sphere::from_centre_radius(Point3::origin(), 2.0)?;
//! let p = Plane::from_normal_offset(Vector3::z(), 2.0)?; // z = 2 touches s at (0, 0, 2)
//! assert!(matches!(s.meet(&p), SpherePlane::Tangent(_)));
//! let q = Plane::from_normal_offset(Vector3::z(), 1.0)?;
//! match s.meet(&q) {
//!     SpherePlane::Circle(c) => assert!((c.radius_squared() - 3.0).abs() < 1e-12),
//!     other => panic!("{other:?}"),
//! }
//! # Ok::<(), cga_collide::Error>(())
//! ```

use core::cmp::Ordering;

use ga_core::cga::{Bivector, Trivector, Vector};
use ga_core::prelude::*;
use ga_core::scalar::Rational;
use nalgebra::{Point3, Vector3};

use super::{
    all_zero, coeffs, decide, flat_point_location, n_inf, round_centre, CertifiedScalar, Circle,
    Line, Plane, PointPair, Sphere,
};
use crate::exact::ErrF64;

const NAN3: Point3<f64> = Point3::new(f64::NAN, f64::NAN, f64::NAN);

/// `a.meet(&b)`: the classified intersection of two primitives (both orders of each of the six
/// pairs).
///
/// ```
/// use cga_collide::conformal::{Line, Plane, meet::{Meet, LinePlane}};
/// use cga_collide::nalgebra::{Point3, Vector3};
/// let l = Line::from_points(Point3::new(0.0, 0.0, -1.0), Point3::new(0.0, 0.0, 1.0))?;
/// let p = Plane::from_normal_offset(Vector3::z(), 0.5)?;
/// assert!(matches!(l.meet(&p), LinePlane::Point(x) if (x - Point3::new(0.0, 0.0, 0.5)).norm() < 1e-12));
/// assert!(matches!(p.meet(&l), LinePlane::Point(_)));
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub trait Meet<Rhs> {
    /// The classification enum.
    type Output;
    /// The classified intersection of `self` and `rhs`.
    fn meet(&self, rhs: &Rhs) -> Self::Output;
}

// ---------------------------------------------------------------------------------------------

/// How two lines meet.
///
/// ```
/// use cga_collide::conformal::{Line, meet::{line_line, LineLine}};
/// use cga_collide::nalgebra::{Point3, Vector3};
/// let x = Line::from_point_direction(Point3::origin(), Vector3::x())?;
/// let y = Line::from_point_direction(Point3::new(0.0, 0.0, 3.0), Vector3::y())?;
/// assert!(matches!(line_line(&x, &y), LineLine::Skew { distance } if (distance - 3.0).abs() < 1e-12));
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LineLine {
    /// The lines cross at one point.
    Point(Point3<f64>),
    /// Distinct parallel lines, at this distance.
    Parallel {
        /// The distance between the lines.
        distance: f64,
    },
    /// The same line.
    Coincident,
    /// Not coplanar, at this distance.
    Skew {
        /// The distance between the lines.
        distance: f64,
    },
}

/// How a line meets a plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LinePlane {
    /// One point.
    Point(Point3<f64>),
    /// Parallel, not in the plane, at this distance.
    Parallel {
        /// The distance from the line to the plane.
        distance: f64,
    },
    /// The line lies in the plane.
    Contained,
}

/// How a line meets a sphere (an imaginary sphere is met nowhere).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum LineSphere {
    /// Two points, in the order of the line's direction.
    TwoPoints(Point3<f64>, Point3<f64>),
    /// The line touches the sphere at one point.
    Tangent(Point3<f64>),
    /// No real intersection.
    Disjoint,
}

/// How two planes meet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PlanePlane {
    /// A line.
    Line(Line),
    /// Distinct parallel planes, at this distance.
    Parallel {
        /// The distance between the planes.
        distance: f64,
    },
    /// The same plane.
    Coincident,
}

/// How a sphere meets a plane.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SpherePlane {
    /// A circle of positive radius.
    Circle(Circle),
    /// The plane touches the sphere at one point (also: a point sphere on the plane).
    Tangent(Point3<f64>),
    /// No real intersection (also for imaginary spheres).
    Disjoint,
}

/// How two spheres meet.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum SphereSphere {
    /// A circle of positive radius.
    Circle(Circle),
    /// Touching from outside (`|c₁ − c₂| = r₁ + r₂`), at this point. A point sphere on the
    /// other sphere counts as external.
    TangentExternal(Point3<f64>),
    /// Touching from inside (`|c₁ − c₂| = |r₁ − r₂| > 0`), at this point.
    TangentInternal(Point3<f64>),
    /// The same sphere.
    Coincident,
    /// Apart, outside each other (`|c₁ − c₂| > r₁ + r₂`), or one of them imaginary.
    Disjoint,
    /// One strictly inside the other without touching (`|c₁ − c₂| < |r₁ − r₂|`).
    Nested,
}

// ---------------------------------------------------------------------------------------------
// Generic classification kernels: `None` when a sign is not certain.

fn sq_sign<T: CertifiedScalar, X: Clone + ScalarProduct<X, Output = T>>(x: &X) -> Option<Ordering> {
    x.scalar_product(x).certain_sign()
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum LL {
    Point,
    Parallel,
    Coincident,
    Skew,
}

fn ll_kind<T: CertifiedScalar>(
    l1: &Trivector<T>,
    l2: &Trivector<T>,
    q: [Vector<T>; 2],
) -> Option<LL> {
    let m: Vector<T> = l1.regressive(l2);
    if !all_zero(&coeffs(m))? {
        return Some(LL::Skew);
    }
    let [q1, q2] = q;
    let mut join = l1.wedge(&q1);
    if all_zero(&coeffs(join.clone()))? {
        join = l1.wedge(&q2);
        if all_zero(&coeffs(join.clone()))? {
            return Some(LL::Coincident);
        }
    }
    let f: Bivector<T> = l1.left_contraction(&join).left_contraction(l2);
    if all_zero(&coeffs(f.clone()))? {
        return Some(LL::Coincident);
    }
    Some(match sq_sign(&f)? {
        Ordering::Equal => LL::Parallel,
        _ => LL::Point,
    })
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum LP {
    Point,
    Parallel,
    Contained,
}

fn lp_kind<T: CertifiedScalar>(l: &Trivector<T>, p: &Vector<T>) -> Option<LP> {
    let x: Trivector<T> = l.dual().wedge(p);
    if all_zero(&coeffs(x.clone()))? {
        return Some(LP::Contained);
    }
    Some(match sq_sign(&x)? {
        Ordering::Equal => LP::Parallel,
        _ => LP::Point,
    })
}

/// Three-way kinds for the round cases: `M² < 0`, `= 0`, `> 0`.
fn round_kind<T: CertifiedScalar>(m2: T) -> Option<Ordering> {
    m2.certain_sign()
}

fn ls_kind<T: CertifiedScalar>(l: &Trivector<T>, s: &Vector<T>) -> Option<Ordering> {
    let x: Trivector<T> = l.dual().wedge(s);
    round_kind(x.scalar_product(&x))
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum PP {
    Line,
    Parallel,
    Coincident,
}

fn pp_kind<T: CertifiedScalar>(a: &Vector<T>, b: &Vector<T>) -> Option<PP> {
    let m: Bivector<T> = a.wedge(b);
    if all_zero(&coeffs(m.clone()))? {
        return Some(PP::Coincident);
    }
    Some(match sq_sign(&m)? {
        Ordering::Equal => PP::Parallel,
        _ => PP::Line,
    })
}

fn sp_kind<T: CertifiedScalar>(s: &Vector<T>, p: &Vector<T>) -> Option<Ordering> {
    let m: Bivector<T> = s.wedge(p);
    round_kind(m.scalar_product(&m))
}

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum SS {
    Circle,
    TangentExternal,
    TangentInternal,
    Coincident,
    Disjoint,
    Nested,
}

fn ss_kind<T: CertifiedScalar>(a: &Vector<T>, b: &Vector<T>) -> Option<SS> {
    if sq_sign(a)? == Ordering::Less || sq_sign(b)? == Ordering::Less {
        return Some(SS::Disjoint);
    }
    let m: Bivector<T> = a.wedge(b);
    if all_zero(&coeffs(m.clone()))? {
        return Some(SS::Coincident);
    }
    let inside = || -> Option<bool> {
        let n = n_inf::<T>();
        let k = a.scalar_product(b) * a.scalar_product(&n) * b.scalar_product(&n);
        Some(k.certain_sign()? == Ordering::Greater)
    };
    Some(match sq_sign(&m)? {
        Ordering::Less => SS::Circle,
        Ordering::Equal => {
            if inside()? {
                SS::TangentInternal
            } else {
                SS::TangentExternal
            }
        }
        Ordering::Greater => {
            if inside()? {
                SS::Nested
            } else {
                SS::Disjoint
            }
        }
    })
}

// ---------------------------------------------------------------------------------------------
// Public classification with f64 geometry.

fn line_distance(a: &Line, b: &Line) -> (f64, f64) {
    // (skew distance, parallel distance), Euclidean, in f64.
    let (p, d) = (a.support_point(), a.direction());
    let (q, e) = (b.support_point(), b.direction());
    let w = q - p;
    let c = d.cross(&e);
    let skew = w.dot(&c).abs() / c.norm();
    let parallel = w.cross(&d).norm();
    (skew, parallel)
}

/// Line–line: skew, crossing at a point, parallel or coincident (exact).
///
/// ```
/// use cga_collide::conformal::{Line, meet::{line_line, LineLine}};
/// use cga_collide::nalgebra::{Point3, Vector3};
/// let a = Line::from_points(Point3::new(0.0, 0.0, 0.0), Point3::new(1.0, 1.0, 0.0))?;
/// let b = Line::from_points(Point3::new(0.0, 2.0, 0.0), Point3::new(2.0, 0.0, 0.0))?;
/// assert!(matches!(line_line(&a, &b), LineLine::Point(p) if (p - Point3::new(1.0, 1.0, 0.0)).norm() < 1e-12));
/// let c = Line::from_point_direction(Point3::new(0.0, 0.0, 1.0), Vector3::new(1.0, 1.0, 0.0))?;
/// assert!(matches!(line_line(&a, &c), LineLine::Parallel { .. }));
/// let d = Line::from_points(Point3::new(5.0, 5.0, 0.0), Point3::new(-3.0, -3.0, 0.0))?;
/// assert_eq!(line_line(&a, &d), LineLine::Coincident);
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn line_line(a: &Line, b: &Line) -> LineLine {
    let kind = decide(
        || ll_kind::<ErrF64>(&a.blade_in(), &b.blade_in(), b.spanning_vectors()),
        || ll_kind::<Rational>(&a.blade_in(), &b.blade_in(), b.spanning_vectors()),
        LL::Skew,
    );
    match kind {
        LL::Skew => LineLine::Skew {
            distance: line_distance(a, b).0,
        },
        LL::Parallel => LineLine::Parallel {
            distance: line_distance(a, b).1,
        },
        LL::Coincident => LineLine::Coincident,
        LL::Point => {
            let [q1, q2] = b.spanning_vectors::<f64>();
            let l1 = a.blade();
            let j1 = l1.wedge(&q1);
            let j2 = l1.wedge(&q2);
            let join = if j1.scalar_product(&j1).abs() >= j2.scalar_product(&j2).abs() {
                j1
            } else {
                j2
            };
            let f: Bivector<f64> = l1.left_contraction(&join).left_contraction(b.blade());
            LineLine::Point(flat_point_location(&f).unwrap_or(NAN3))
        }
    }
}

/// Line–plane: a point, parallel, or contained (exact).
///
/// ```
/// use cga_collide::conformal::{Line, Plane, meet::{line_plane, LinePlane}};
/// use cga_collide::nalgebra::{Point3, Vector3};
/// let p = Plane::from_normal_offset(Vector3::z(), 1.0)?;
/// let l = Line::from_point_direction(Point3::origin(), Vector3::x())?;
/// assert!(matches!(line_plane(&l, &p), LinePlane::Parallel { distance } if distance == 1.0));
/// let m = Line::from_point_direction(Point3::new(0.0, 0.0, 1.0), Vector3::y())?;
/// assert_eq!(line_plane(&m, &p), LinePlane::Contained);
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn line_plane(l: &Line, p: &Plane) -> LinePlane {
    let kind = decide(
        || lp_kind::<ErrF64>(&l.blade_in(), &p.ipns_in()),
        || lp_kind::<Rational>(&l.blade_in(), &p.ipns_in()),
        LP::Point,
    );
    match kind {
        LP::Contained => LinePlane::Contained,
        LP::Parallel => LinePlane::Parallel {
            distance: (p.normal().dot(&l.support_point().coords) - p.offset()).abs(),
        },
        LP::Point => {
            let x: Trivector<f64> = l.ipns().wedge(&p.ipns());
            LinePlane::Point(flat_point_location(&x.undual()).unwrap_or(NAN3))
        }
    }
}

/// Line–sphere: two points, tangent, or none (exact).
///
/// ```
/// use cga_collide::conformal::{Line, Sphere, meet::{line_sphere, LineSphere}};
/// use cga_collide::nalgebra::{Point3, Vector3};
/// let s = Sphere::from_centre_radius(Point3::origin(), 1.0)?;
/// let l = Line::from_point_direction(Point3::origin(), Vector3::x())?;
/// match line_sphere(&l, &s) {
///     LineSphere::TwoPoints(p, q) => {
///         assert!((p - Point3::new(-1.0, 0.0, 0.0)).norm() < 1e-12);
///         assert!((q - Point3::new(1.0, 0.0, 0.0)).norm() < 1e-12);
///     }
///     other => panic!("{other:?}"),
/// }
/// let far = Line::from_point_direction(Point3::new(0.0, 0.0, 1.5), Vector3::x())?;
/// assert_eq!(line_sphere(&far, &s), LineSphere::Disjoint);
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn line_sphere(l: &Line, s: &Sphere) -> LineSphere {
    let kind = decide(
        || ls_kind::<ErrF64>(&l.blade_in(), &s.ipns_in()),
        || ls_kind::<Rational>(&l.blade_in(), &s.ipns_in()),
        Ordering::Greater,
    );
    let pair = || PointPair::from_blade_unchecked(l.ipns().wedge(&s.ipns()).undual());
    match kind {
        Ordering::Greater => LineSphere::Disjoint,
        Ordering::Equal => LineSphere::Tangent(pair().centre()),
        Ordering::Less => match pair().points() {
            Some((p, q)) => {
                let d = l.direction();
                if (q - p).dot(&d) >= 0.0 {
                    LineSphere::TwoPoints(p, q)
                } else {
                    LineSphere::TwoPoints(q, p)
                }
            }
            None => LineSphere::TwoPoints(NAN3, NAN3),
        },
    }
}

/// Plane–plane: a line, parallel, or coincident (exact).
///
/// ```
/// use cga_collide::conformal::{Plane, meet::{plane_plane, PlanePlane}};
/// use cga_collide::nalgebra::{Point3, Vector3};
/// let a = Plane::from_normal_offset(Vector3::z(), 0.0)?;
/// let b = Plane::from_normal_offset(Vector3::x(), 2.0)?;
/// match plane_plane(&a, &b) {
///     PlanePlane::Line(l) => {
///         assert!((l.direction().cross(&Vector3::y())).norm() < 1e-12);
///         assert!((l.support_point() - Point3::new(2.0, 0.0, 0.0)).norm() < 1e-12);
///     }
///     other => panic!("{other:?}"),
/// }
/// let c = Plane::from_normal_offset(-Vector3::z() * 3.0, -6.0)?; // z = 2
/// assert!(matches!(plane_plane(&a, &c), PlanePlane::Parallel { distance } if distance == 2.0));
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn plane_plane(a: &Plane, b: &Plane) -> PlanePlane {
    let kind = decide(
        || pp_kind::<ErrF64>(&a.ipns_in(), &b.ipns_in()),
        || pp_kind::<Rational>(&a.ipns_in(), &b.ipns_in()),
        PP::Line,
    );
    match kind {
        PP::Coincident => PlanePlane::Coincident,
        PP::Parallel => {
            let s = a.normal().dot(&b.normal()).signum();
            PlanePlane::Parallel {
                distance: (a.offset() - s * b.offset()).abs(),
            }
        }
        PP::Line => {
            let t: Trivector<f64> = a.ipns().wedge(&b.ipns()).undual();
            let line = Line::from_blade(t).unwrap_or_else(|_| Line {
                blade: t,
                def: super::LineDef::PointDirection(NAN3, Vector3::new(f64::NAN, 0.0, 0.0)),
            });
            PlanePlane::Line(line)
        }
    }
}

/// Sphere–plane: a circle, tangent, or none (exact).
///
/// ```
/// use cga_collide::conformal::{Plane, Sphere, meet::{sphere_plane, SpherePlane}};
/// use cga_collide::nalgebra::{Point3, Vector3};
/// let s = Sphere::from_centre_radius(Point3::new(0.0, 0.0, 1.0), 1.0)?;
/// let p = Plane::from_normal_offset(Vector3::z(), 0.0)?;
/// assert!(matches!(sphere_plane(&s, &p), SpherePlane::Tangent(t) if t.coords.norm() < 1e-12));
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn sphere_plane(s: &Sphere, p: &Plane) -> SpherePlane {
    let kind = decide(
        || sp_kind::<ErrF64>(&s.ipns_in(), &p.ipns_in()),
        || sp_kind::<Rational>(&s.ipns_in(), &p.ipns_in()),
        Ordering::Greater,
    );
    let circle = || Circle::from_blade_unchecked(s.ipns().wedge(&p.ipns()).undual());
    match kind {
        Ordering::Greater => SpherePlane::Disjoint,
        Ordering::Equal => SpherePlane::Tangent(round_centre(circle().blade()).unwrap_or(NAN3)),
        Ordering::Less => SpherePlane::Circle(circle()),
    }
}

/// Sphere–sphere: a circle, external or internal tangency, coincident, disjoint or nested
/// (exact).
///
/// ```
/// use cga_collide::conformal::{Sphere, meet::{sphere_sphere, SphereSphere}};
/// use cga_collide::nalgebra::Point3;
/// let a = Sphere::from_centre_radius(Point3::origin(), 1.0)?;
/// let b = Sphere::from_centre_radius(Point3::new(2.0, 0.0, 0.0), 1.0)?;
/// assert!(matches!(sphere_sphere(&a, &b), SphereSphere::TangentExternal(p) if (p - Point3::new(1.0, 0.0, 0.0)).norm() < 1e-12));
/// let c = Sphere::from_centre_radius(Point3::new(0.1, 0.0, 0.0), 0.5)?;
/// assert_eq!(sphere_sphere(&a, &c), SphereSphere::Nested);
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn sphere_sphere(a: &Sphere, b: &Sphere) -> SphereSphere {
    let kind = decide(
        || ss_kind::<ErrF64>(&a.ipns_in(), &b.ipns_in()),
        || ss_kind::<Rational>(&a.ipns_in(), &b.ipns_in()),
        SS::Disjoint,
    );
    let circle = || Circle::from_blade_unchecked(a.ipns().wedge(&b.ipns()).undual());
    let touch = || round_centre(circle().blade()).unwrap_or(NAN3);
    match kind {
        SS::Circle => SphereSphere::Circle(circle()),
        SS::TangentExternal => SphereSphere::TangentExternal(touch()),
        SS::TangentInternal => SphereSphere::TangentInternal(touch()),
        SS::Coincident => SphereSphere::Coincident,
        SS::Disjoint => SphereSphere::Disjoint,
        SS::Nested => SphereSphere::Nested,
    }
}

macro_rules! meet_impl {
    ($a:ty, $b:ty, $out:ty, $f:ident, straight) => {
        impl Meet<$b> for $a {
            type Output = $out;
            fn meet(&self, rhs: &$b) -> $out {
                $f(self, rhs)
            }
        }
    };
    ($a:ty, $b:ty, $out:ty, $f:ident, swapped) => {
        impl Meet<$b> for $a {
            type Output = $out;
            fn meet(&self, rhs: &$b) -> $out {
                $f(rhs, self)
            }
        }
    };
}

meet_impl!(Line, Line, LineLine, line_line, straight);
meet_impl!(Line, Plane, LinePlane, line_plane, straight);
meet_impl!(Plane, Line, LinePlane, line_plane, swapped);
meet_impl!(Line, Sphere, LineSphere, line_sphere, straight);
meet_impl!(Sphere, Line, LineSphere, line_sphere, swapped);
meet_impl!(Plane, Plane, PlanePlane, plane_plane, straight);
meet_impl!(Sphere, Plane, SpherePlane, sphere_plane, straight);
meet_impl!(Plane, Sphere, SpherePlane, sphere_plane, swapped);
meet_impl!(Sphere, Sphere, SphereSphere, sphere_sphere, straight);

/// Whether the certified `f64` filter alone classifies the sphere pair (`false`: the exact
/// rational recomputation was needed). A test hook, re-exported as
/// `cga_collide::testing::conformal::sphere_sphere_filtered`.
#[cfg(any(test, feature = "testing"))]
pub(crate) fn sphere_sphere_filtered(a: &Sphere, b: &Sphere) -> bool {
    ss_kind::<ErrF64>(&a.ipns_in(), &b.ipns_in()).is_some()
}

#[cfg(any(test, feature = "testing"))]
pub(crate) mod filter_stats;

#[cfg(test)]
mod tests {
    use super::filter_stats::{filter_tallies, Lcg};
    use super::*;
    use crate::conformal::{Line, Plane, Sphere};

    /// The certified filter agrees with the exact classification on the adversarial set
    /// (checked inside [`filter_tallies`]), and plain `f64` is wrong somewhere on it, or the set
    /// is not adversarial. The CLI example `conformal_filter_table` prints the counts.
    #[test]
    fn filter_is_right_and_plain_f64_is_not() {
        let rows = filter_tallies(1000);
        assert_eq!(rows.len(), 6);
        assert!(rows.iter().all(|t| t.cases > 0 && t.filtered <= t.cases));
        assert!(rows.iter().map(|t| t.float_wrong).sum::<usize>() > 0);
    }

    #[test]
    fn filter_decides_general_position() {
        // Uniform random f64 coordinates: the certified filter alone should decide (almost)
        // everything; the exact path is for degenerate and extreme inputs.
        let mut r = Lcg(42);
        let mut u = move || (r.next() as f64 / (1u64 << 31) as f64) * 20.0 - 10.0;
        let mut pt = move || Point3::new(u(), u(), u());
        let n = 1000;
        let mut decided = [0usize; 6];
        for _ in 0..n {
            let (a, b, c, d, e, f) = (pt(), pt(), pt(), pt(), pt(), pt());
            let la = Line::from_points(a, b).unwrap();
            let lb = Line::from_points(c, d).unwrap();
            let p = Plane::from_points(a, c, e).unwrap();
            let q = Plane::from_points(b, d, f).unwrap();
            let s1 = Sphere::from_centre_radius(e, (f.x + 10.0) / 2.0).unwrap();
            let s2 = Sphere::from_centre_radius(f, (e.y + 10.0) / 2.0).unwrap();
            let (l1, l2) = (la.blade_in::<ErrF64>(), lb.blade_in::<ErrF64>());
            let (p1, p2) = (p.ipns_in::<ErrF64>(), q.ipns_in::<ErrF64>());
            let (t1, t2) = (s1.ipns_in::<ErrF64>(), s2.ipns_in::<ErrF64>());
            decided[0] += usize::from(ll_kind(&l1, &l2, lb.spanning_vectors()).is_some());
            decided[1] += usize::from(lp_kind(&l1, &p2).is_some());
            decided[2] += usize::from(ls_kind(&l1, &t1).is_some());
            decided[3] += usize::from(pp_kind(&p1, &p2).is_some());
            decided[4] += usize::from(sp_kind(&t1, &p2).is_some());
            decided[5] += usize::from(ss_kind(&t1, &t2).is_some());
        }
        assert!(decided.iter().all(|&k| k >= n * 99 / 100), "{decided:?}");
    }
}
