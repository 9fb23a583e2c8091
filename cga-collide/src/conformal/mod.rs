//! Conformal primitives: thin typed wrappers over blades of [`ga_core::cga`].
//!
//! | type | outer (OPNS) blade, as in the thesis | inner (IPNS) form |
//! |---|---|---|
//! | [`Point`] | `P = F(x)` (grade 1) | the same vector |
//! | [`PointPair`] | `P1 ∧ P2` (grade 2) | its dual (grade 3) |
//! | [`FlatPoint`] | `P ∧ n_inf` (grade 2) | its dual (grade 3) |
//! | [`Line`] | `P1 ∧ P2 ∧ n_inf` (grade 3) | its dual (grade 2) |
//! | [`Circle`] | `P1 ∧ P2 ∧ P3` (grade 3) | its dual (grade 2) |
//! | [`Plane`] | `P1 ∧ P2 ∧ P3 ∧ n_inf` (grade 4) | `n + d n_inf` (grade 1) |
//! | [`Sphere`] | `P1 ∧ P2 ∧ P3 ∧ P4` (grade 4) | `F(c) − r² n_inf` (grade 1) |
//!
//! (This `Sphere` is the conformal sphere, a different type from the bounded
//! [`crate::Sphere`]; write `conformal::Sphere`.)
//!
//! # Conventions
//! * `n_inf = e4 + e5`, `n_0 = (e5 − e4)/2`, `dual(A) = A I⁻¹`, `undual(A) = A I`
//!   (DESIGN.md). The IPNS form of every primitive is `dual` of its OPNS blade
//!   ([`Plane::ipns`], [`Sphere::ipns`], ...), and `undual` goes back.
//! * Points are embedded at the thesis's scale `F(x) = 2x + |x|² n_inf − n̄ = 2 up(x)` (with
//!   `n̄ = e4 − e5`). It needs no division, so every blade is a polynomial in the inputs and the
//!   same generic code runs on `f64`, on error-bounded `f64` ([`crate::filter::ErrF64`]) and on
//!   exact rationals. Blades are homogeneous: every extraction below is invariant under
//!   nonzero scaling (and sign) of the blade.
//! * Orientation: the IPNS vector of `Plane::from_points(a, b, c)` is `dual(P1∧P2∧P3∧n_inf)`,
//!   whose normal is `(c − a) × (b − a)` (the thesis's blade order gives the clockwise normal);
//!   [`Plane::from_normal_offset`] keeps the given normal.
//!
//! # Exactness
//! Every primitive remembers the `f64` data it was built from (points, centre and radius,
//! normal and offset, point and direction). **The primitive is the exact geometric object
//! those `f64` numbers denote**: constructors decide degeneracy exactly, and the
//! classifications of [`meet`] are exact for these objects (certified `f64` first, exact
//! rationals rebuilt from the same data when the sign is uncertain). The stored `f64` blade
//! ([`Line::blade`], ...) is the rounded value of that exact blade; [`Line::exact_blade`]
//! gives the exact one. Extracted Euclidean data (centres, radii, intersection points) are
//! `f64` approximations. A transformed primitive ([`versor`]) is the primitive built exactly
//! from the rounded Euclidean data of the transformed blade.
//!
//! ```
//! use cga_collide::conformal::{Line, Sphere, meet::{line_sphere, LineSphere}};
//! use cga_collide::nalgebra::{Point3, Vector3};
//!
//! let s = Sphere::from_centre_radius(Point3::origin(), 1.0)?;
//! let l = Line::from_point_direction(Point3::new(0.0, 1.0, 0.0), Vector3::x())?; // touches s
//! assert!(matches!(line_sphere(&l, &s), LineSphere::Tangent(p) if (p - Point3::new(0.0, 1.0, 0.0)).norm() < 1e-12));
//! # Ok::<(), cga_collide::GeometryError>(())
//! ```
//!
//! # API tour
//!
//! ```
//! use cga_collide::conformal::meet::{LinePlane, LineSphere, Meet, SpherePlane, SphereSphere};
//! use cga_collide::conformal::{Line, Plane, Point, Reflection, Sphere, Transform, Versor};
//! use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
//!
//! // Primitives from points (outer forms, as in the thesis) or from Euclidean data (inner forms).
//! let l = Line::from_points(Point3::new(-2.0, 0.0, 1.0), Point3::new(2.0, 0.0, 1.0))?;
//! let s = Sphere::from_centre_radius(Point3::origin(), 1.0)?;
//! let p = Plane::from_normal_offset(Vector3::z(), 1.0)?; // z = 1
//! let t = Sphere::from_points([Point3::new(1.0, 0.0, 0.0), Point3::new(-1.0, 0.0, 0.0),
//!                              Point3::new(0.0, 1.0, 0.0), Point3::new(0.0, 0.0, -1.0)])?;
//!
//! // Exact classification of the meet; the variants carry f64 geometry.
//! assert!(matches!(l.meet(&s), LineSphere::Tangent(x) if (x - Point3::new(0.0, 0.0, 1.0)).norm() < 1e-12));
//! assert_eq!(l.meet(&p), LinePlane::Contained);
//! assert!(matches!(s.meet(&p), SpherePlane::Tangent(_)));
//! assert_eq!(s.meet(&t), SphereSphere::Coincident);
//!
//! // Tangency stays exact at any scale: the certified f64 filter defers to exact rationals.
//! let k = 2f64.powi(400); // about 2.6e120: every f64 product overflows
//! let a = Sphere::from_centre_radius(Point3::origin(), 5.0 * k)?;
//! let b = Sphere::from_centre_radius(Point3::new(0.0, 8.0 * k, 0.0), 3.0 * k)?;
//! assert!(matches!(a.meet(&b), SphereSphere::TangentExternal(_)));
//!
//! // Degenerate input is a typed error, decided exactly.
//! assert!(Plane::from_points(Point3::origin(), Point3::new(1.0, 1.0, 1.0), Point3::new(2.0, 2.0, 2.0)).is_err());
//!
//! // Versors: translators, rotors, dilators, reflections, and nalgebra isometries.
//! let iso = Isometry3::new(Vector3::new(0.0, 0.0, 5.0), Vector3::y() * std::f64::consts::FRAC_PI_2);
//! let moved = s.transform(&Versor::from(iso))?;
//! assert!((moved.centre() - Point3::new(0.0, 0.0, 5.0)).norm() < 1e-12);
//! let grown = s.transform(&Versor::dilator(3.0)?)?;
//! assert!((grown.radius().unwrap() - 3.0).abs() < 1e-12);
//! let mirrored = Point::new(Point3::new(0.0, 0.0, 3.0))?.reflect(&Reflection::new(&p))?;
//! assert!((mirrored.position().unwrap() - Point3::new(0.0, 0.0, -1.0)).norm() < 1e-12);
//!
//! // Outer ↔ inner forms (dual(A) = A I⁻¹) and back to Euclidean data.
//! let p2 = Plane::from_blade(*p.blade())?;
//! assert_eq!((p2.normal(), p2.offset()), (Vector3::z(), 1.0));
//! # Ok::<(), cga_collide::GeometryError>(())
//! ```

use core::cmp::Ordering;

use ga_core::cga::{Bivector, Multivector, Quadvector, Trivector, Vector};
use ga_core::prelude::*;
use ga_core::scalar::Rational;
use nalgebra::{Point3, Vector3};

use crate::error::GeometryError;
use crate::filter::{rational_sign, ErrF64};

pub mod meet;
pub mod versor;

pub use versor::{Reflection, Transform, Versor};

// ---------------------------------------------------------------------------------------------
// Scalars the primitives are rebuilt in.

/// The scalars the primitives' blades are (re)built in from their `f64` data: plain `f64`,
/// error-bounded [`ErrF64`] (certified filter) and exact [`Rational`].
pub(crate) trait Exactish: Ring {
    /// The value of a finite `f64` input (exact for `ErrF64` and `Rational`).
    fn lift(x: f64) -> Self;
    /// The sign if certain (always for `Rational`; `None` for NaN in `f64`).
    fn sign_of(&self) -> Option<Ordering>;
}

impl Exactish for f64 {
    fn lift(x: f64) -> Self {
        x
    }
    fn sign_of(&self) -> Option<Ordering> {
        self.partial_cmp(&0.0)
    }
}

impl Exactish for ErrF64 {
    fn lift(x: f64) -> Self {
        ErrF64::exact(x)
    }
    fn sign_of(&self) -> Option<Ordering> {
        self.sign()
    }
}

impl Exactish for Rational {
    fn lift(x: f64) -> Self {
        ga_core::scalar::rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero)
    }
    fn sign_of(&self) -> Option<Ordering> {
        Some(rational_sign(self))
    }
}

/// Whether every coefficient is zero: `Some(true/false)` when certain, `None` otherwise.
pub(crate) fn all_zero<T: Exactish>(coefficients: &[T]) -> Option<bool> {
    let mut unknown = false;
    for c in coefficients {
        match c.sign_of() {
            Some(Ordering::Equal) => {}
            Some(_) => return Some(false),
            None => unknown = true,
        }
    }
    if unknown {
        None
    } else {
        Some(true)
    }
}

/// All 32 coefficients of a blade of any type.
pub(crate) fn coeffs<T: Ring, X: Into<Multivector<T>>>(x: X) -> [T; 32] {
    let m: Multivector<T> = x.into();
    m.coefficients()
}

/// Runs a certified computation: first on [`ErrF64`], then (if undecided) exactly.
pub(crate) fn decide<R>(
    filtered: impl FnOnce() -> Option<R>,
    exact: impl FnOnce() -> Option<R>,
    fallback: R,
) -> R {
    filtered().or_else(exact).unwrap_or(fallback)
}

/// The thesis's conformal point `F(x) = 2x + |x|² n_inf − n̄ = 2 up(x)`, in any ring.
pub(crate) fn embed<T: Exactish>(p: &Point3<f64>) -> Vector<T> {
    let (x, y, z) = (T::lift(p.x), T::lift(p.y), T::lift(p.z));
    let sq = x.clone() * x.clone() + y.clone() * y.clone() + z.clone() * z.clone();
    let two = T::from_i64(2);
    Vector::new(
        two.clone() * x,
        two.clone() * y,
        two * z,
        sq.clone() - T::one(),
        sq + T::one(),
    )
}

/// A Euclidean direction `d1 e1 + d2 e2 + d3 e3`, in any ring.
pub(crate) fn direction<T: Exactish>(d: &Vector3<f64>) -> Vector<T> {
    Vector::new(
        T::lift(d.x),
        T::lift(d.y),
        T::lift(d.z),
        T::zero(),
        T::zero(),
    )
}

pub(crate) fn n_inf<T: Ring>() -> Vector<T> {
    ga_core::cga::n_inf()
}

// ---------------------------------------------------------------------------------------------
// Input checks.

fn finite(constructor: &'static str, argument: &'static str, v: f64) -> Result<(), GeometryError> {
    if v.is_finite() {
        Ok(())
    } else {
        Err(GeometryError::NonFiniteInput {
            constructor,
            argument,
            value: v,
        })
    }
}

fn finite3(
    constructor: &'static str,
    names: [&'static str; 3],
    v: &Vector3<f64>,
) -> Result<(), GeometryError> {
    for (name, x) in names.into_iter().zip(v.iter()) {
        finite(constructor, name, *x)?;
    }
    Ok(())
}

fn finite_blade<X: Into<Multivector<f64>>>(
    constructor: &'static str,
    blade: X,
) -> Result<(), GeometryError> {
    for c in coeffs(blade) {
        finite(constructor, "blade", c)?;
    }
    Ok(())
}

fn degenerate(constructor: &'static str, reason: &'static str) -> GeometryError {
    GeometryError::Degenerate {
        constructor,
        reason,
    }
}

fn checked_point3(
    constructor: &'static str,
    what: &'static str,
    p: Point3<f64>,
) -> Result<Point3<f64>, GeometryError> {
    if p.iter().all(|x| x.is_finite()) {
        Ok(p)
    } else {
        Err(degenerate(constructor, what))
    }
}

// ---------------------------------------------------------------------------------------------
// Extraction helpers (f64).

/// The Euclidean point of a homogeneous point or of the centre vector of a round:
/// `x = (X₁, X₂, X₃) / (−X·n_inf)`.
fn down(v: &Vector<f64>) -> Option<Point3<f64>> {
    ga_core::cga::down(v)
}

/// The location of a flat point blade `F ∝ up(x) ∧ n_inf`.
fn flat_point_location(f: &Bivector<f64>) -> Option<Point3<f64>> {
    let w = -f.e45;
    let p = Point3::new(
        (f.e14 + f.e15) * 0.5 / w,
        (f.e24 + f.e25) * 0.5 / w,
        (f.e34 + f.e35) * 0.5 / w,
    );
    (w != 0.0 && p.iter().all(|x| x.is_finite())).then_some(p)
}

/// The centre of a round (point pair, circle, sphere) blade `X`: `down(X n_inf X)`.
fn round_centre<X>(x: &X) -> Option<Point3<f64>>
where
    X: Copy + Into<Multivector<f64>>,
{
    let m: Multivector<f64> = (*x).into();
    let c = m * Multivector::from(n_inf::<f64>()) * m;
    down(&Vector::from_multivector(&c))
}

fn unit(v: Vector3<f64>) -> Vector3<f64> {
    let n = v.norm();
    if n > 0.0 && n.is_finite() {
        v / n
    } else {
        // Rescale first: the norm may have overflowed or underflowed.
        let m = v.amax();
        if m > 0.0 && m.is_finite() {
            let w = v / m;
            w / w.norm()
        } else {
            v
        }
    }
}

fn euclidean_part(v: &Vector<f64>) -> Vector3<f64> {
    Vector3::new(v.e1, v.e2, v.e3)
}

// ---------------------------------------------------------------------------------------------
// Point.

/// A conformal point `F(x) = 2 up(x)` (grade 1).
///
/// ```
/// use cga_collide::conformal::Point;
/// use cga_collide::nalgebra::Point3;
/// let p = Point::new(Point3::new(1.0, 0.0, 2.0))?;
/// // The thesis's example (II.7): F((1,0,2)) = 2e1 + 4e3 + 5n − n̄.
/// assert_eq!(p.blade().e1, 2.0);
/// assert_eq!(p.blade().e3, 4.0);
/// assert_eq!(p.position(), Some(Point3::new(1.0, 0.0, 2.0)));
/// # Ok::<(), cga_collide::GeometryError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Point {
    blade: Vector<f64>,
}

impl Point {
    /// The conformal point of `x`; fails on a non-finite coordinate.
    pub fn new(x: Point3<f64>) -> Result<Self, GeometryError> {
        finite3("conformal::Point::new", ["x.x", "x.y", "x.z"], &x.coords)?;
        Ok(Point {
            blade: embed::<f64>(&x),
        })
    }
    /// A point from any nonzero multiple of a null vector `up(x)`; fails if the weight
    /// `−X·n_inf` is zero (a point at infinity) or a coefficient is not finite.
    /// The vector is not required to be null: `down` of it is taken.
    ///
    /// ```
    /// use cga_collide::conformal::Point;
    /// use cga_collide::ga_core::cga::{up, n_inf};
    /// use cga_collide::nalgebra::Point3;
    /// let p = Point::from_blade(up(&Point3::new(1.0, 2.0, 3.0)) * 5.0)?;
    /// assert_eq!(p.position(), Some(Point3::new(1.0, 2.0, 3.0)));
    /// assert!(Point::from_blade(n_inf()).is_err());
    /// # Ok::<(), cga_collide::GeometryError>(())
    /// ```
    pub fn from_blade(v: Vector<f64>) -> Result<Self, GeometryError> {
        const C: &str = "conformal::Point::from_blade";
        finite_blade(C, v)?;
        let x = down(&v).ok_or_else(|| degenerate(C, "the weight −X·n_inf is zero"))?;
        Point::new(x)
    }
    /// The blade `F(x)` (or the transformed multiple of it).
    pub fn blade(&self) -> &Vector<f64> {
        &self.blade
    }
    /// The Euclidean position (`None` if it is not finite).
    pub fn position(&self) -> Option<Point3<f64>> {
        down(&self.blade)
    }
}

// ---------------------------------------------------------------------------------------------
// Line.

#[derive(Debug, Clone, Copy, PartialEq)]
enum LineDef {
    Points(Point3<f64>, Point3<f64>),
    PointDirection(Point3<f64>, Vector3<f64>),
}

/// A line, OPNS blade `L = P1 ∧ P2 ∧ n_inf` (grade 3; the thesis's (II.15)).
///
/// ```
/// use cga_collide::conformal::Line;
/// use cga_collide::nalgebra::{Point3, Vector3};
/// let l = Line::from_points(Point3::new(1.0, 1.0, 0.0), Point3::new(1.0, 0.0, 0.0))?;
/// assert_eq!(l.direction(), Vector3::new(0.0, -1.0, 0.0));
/// assert_eq!(l.support_point(), Point3::new(1.0, 0.0, 0.0));
/// assert!(l.contains(&Point3::new(1.0, -7.0, 0.0)));
/// assert!(Line::from_points(Point3::origin(), Point3::origin()).is_err());
/// # Ok::<(), cga_collide::GeometryError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    blade: Trivector<f64>,
    def: LineDef,
}

impl Line {
    /// The line through `a` and `b`: `F(a) ∧ F(b) ∧ n_inf`. Fails on non-finite coordinates
    /// and when `a == b`.
    pub fn from_points(a: Point3<f64>, b: Point3<f64>) -> Result<Self, GeometryError> {
        const C: &str = "conformal::Line::from_points";
        finite3(C, ["a.x", "a.y", "a.z"], &a.coords)?;
        finite3(C, ["b.x", "b.y", "b.z"], &b.coords)?;
        if a == b {
            return Err(degenerate(C, "points a and b coincide"));
        }
        Ok(Line::build(LineDef::Points(a, b)))
    }
    /// The line through `p` with direction `d`: `F(p) ∧ d ∧ n_inf`. Fails on non-finite input
    /// and when `d` is zero.
    pub fn from_point_direction(p: Point3<f64>, d: Vector3<f64>) -> Result<Self, GeometryError> {
        const C: &str = "conformal::Line::from_point_direction";
        finite3(C, ["p.x", "p.y", "p.z"], &p.coords)?;
        finite3(C, ["d.x", "d.y", "d.z"], &d)?;
        if d == Vector3::zeros() {
            return Err(degenerate(C, "direction d is zero"));
        }
        Ok(Line::build(LineDef::PointDirection(p, d)))
    }
    /// The line of an OPNS trivector (any nonzero multiple of `P1 ∧ P2 ∧ n_inf`): the line
    /// built from the `f64` support point and direction extracted from it. Fails on non-finite
    /// coefficients and when the blade has no direction part.
    ///
    /// ```
    /// use cga_collide::conformal::Line;
    /// use cga_collide::nalgebra::{Point3, Vector3};
    /// let l = Line::from_points(Point3::new(0.0, 2.0, 0.0), Point3::new(1.0, 2.0, 0.0))?;
    /// let m = Line::from_blade(*l.blade() * -3.0)?;
    /// assert_eq!(m.support_point(), Point3::new(0.0, 2.0, 0.0));
    /// assert_eq!(m.direction(), -Vector3::x());
    /// # Ok::<(), cga_collide::GeometryError>(())
    /// ```
    pub fn from_blade(t: Trivector<f64>) -> Result<Self, GeometryError> {
        const C: &str = "conformal::Line::from_blade";
        finite_blade(C, t)?;
        let d = Vector3::new(t.e145, t.e245, t.e345);
        if d == Vector3::zeros() {
            return Err(degenerate(
                C,
                "the blade has no direction part (e145, e245, e345)",
            ));
        }
        let p = checked_point3(C, "the support point is not finite", support_point_of(&t))?;
        Line::from_point_direction(p, unit(d))
    }
    /// The line of an IPNS bivector (`from_blade(undual(L*))`).
    ///
    /// ```
    /// use cga_collide::conformal::Line;
    /// use cga_collide::nalgebra::{Point3, Vector3};
    /// let l = Line::from_point_direction(Point3::new(1.0, 2.0, 3.0), Vector3::z())?;
    /// let m = Line::from_ipns(l.ipns())?;
    /// assert_eq!((m.support_point(), m.direction()), (Point3::new(1.0, 2.0, 0.0), Vector3::z()));
    /// # Ok::<(), cga_collide::GeometryError>(())
    /// ```
    pub fn from_ipns(b: Bivector<f64>) -> Result<Self, GeometryError> {
        Line::from_blade(b.undual())
    }
    fn build(def: LineDef) -> Self {
        Line {
            blade: Line::blade_from(&def),
            def,
        }
    }
    fn blade_from<T: Exactish>(def: &LineDef) -> Trivector<T> {
        let n = n_inf::<T>();
        match def {
            LineDef::Points(a, b) => embed::<T>(a).wedge(&embed::<T>(b)).wedge(&n),
            LineDef::PointDirection(p, d) => embed::<T>(p).wedge(&direction::<T>(d)).wedge(&n),
        }
    }
    pub(crate) fn blade_in<T: Exactish>(&self) -> Trivector<T> {
        Line::blade_from(&self.def)
    }
    /// Two conformal points of the line (`F(a), F(b)`, or `F(p)` and `F(p) + d`: both
    /// span the line with `n_inf`), in any ring.
    pub(crate) fn spanning_vectors<T: Exactish>(&self) -> [Vector<T>; 2] {
        match &self.def {
            LineDef::Points(a, b) => [embed(a), embed(b)],
            LineDef::PointDirection(p, d) => [embed(p), embed::<T>(p) + direction::<T>(d)],
        }
    }
    /// The OPNS blade (rounded to `f64`; see [`Line::exact_blade`]).
    pub fn blade(&self) -> &Trivector<f64> {
        &self.blade
    }
    /// The exact OPNS blade of the line the `f64` inputs denote.
    pub fn exact_blade(&self) -> Trivector<Rational> {
        self.blade_in()
    }
    /// The IPNS (dual) form `L I⁻¹`, a bivector.
    pub fn ipns(&self) -> Bivector<f64> {
        self.blade.dual()
    }
    /// The unit direction: `(L₁₄₅, L₂₄₅, L₃₄₅)` normalised (from `a` to `b` for
    /// [`Line::from_points`], along `d` for [`Line::from_point_direction`]).
    pub fn direction(&self) -> Vector3<f64> {
        unit(Vector3::new(
            self.blade.e145,
            self.blade.e245,
            self.blade.e345,
        ))
    }
    /// The point of the line closest to the origin, `d × m / |d|²` from the direction `d` and
    /// the moment `m` (the `e_ij ∧ n_inf` part) of the blade.
    pub fn support_point(&self) -> Point3<f64> {
        support_point_of(&self.blade)
    }
    /// Whether `x` lies on the line, `L ∧ F(x) = 0`, decided exactly.
    pub fn contains(&self, x: &Point3<f64>) -> bool {
        if !x.iter().all(|c| c.is_finite()) {
            return false;
        }
        decide(
            || all_zero(&coeffs(self.blade_in::<ErrF64>().wedge(&embed(x)))),
            || all_zero(&coeffs(self.blade_in::<Rational>().wedge(&embed(x)))),
            false,
        )
    }
}

fn support_point_of(t: &Trivector<f64>) -> Point3<f64> {
    let d = Vector3::new(t.e145, t.e245, t.e345);
    let m12 = (t.e124 + t.e125) * 0.5;
    let m13 = (t.e134 + t.e135) * 0.5;
    let m23 = (t.e234 + t.e235) * 0.5;
    // The moment bivector x∧d as the vector x×d.
    let m = Vector3::new(m23, -m13, m12);
    let s = d.amax();
    let (d, m) = if s > 0.0 { (d / s, m / s) } else { (d, m) };
    Point3::from(d.cross(&m) / d.norm_squared())
}

// ---------------------------------------------------------------------------------------------
// Plane.

#[derive(Debug, Clone, Copy, PartialEq)]
enum PlaneDef {
    Points(Point3<f64>, Point3<f64>, Point3<f64>),
    NormalOffset(Vector3<f64>, f64),
}

/// A plane, OPNS blade `Π = P1 ∧ P2 ∧ P3 ∧ n_inf` (grade 4; the thesis's (II.24)), IPNS
/// vector `n + d n_inf` (the points `x` with `n·x = d`).
///
/// ```
/// use cga_collide::conformal::Plane;
/// use cga_collide::nalgebra::{Point3, Vector3};
/// let p = Plane::from_normal_offset(Vector3::new(0.0, 0.0, 2.0), 6.0)?; // z = 3
/// assert_eq!(p.normal(), Vector3::z());
/// assert_eq!(p.offset(), 3.0);
/// let q = Plane::from_points(Point3::new(0.0, 0.0, 3.0), Point3::new(0.0, 1.0, 3.0), Point3::new(1.0, 0.0, 3.0))?;
/// assert_eq!(q.normal(), Vector3::z()); // (c − a) × (b − a)
/// assert!(q.contains(&Point3::new(5.0, -2.0, 3.0)));
/// assert!(Plane::from_points(Point3::origin(), Point3::new(1.0, 1.0, 1.0), Point3::new(2.0, 2.0, 2.0)).is_err());
/// # Ok::<(), cga_collide::GeometryError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plane {
    blade: Quadvector<f64>,
    def: PlaneDef,
}

impl Plane {
    /// The plane through `a, b, c`: `F(a) ∧ F(b) ∧ F(c) ∧ n_inf`. Fails on non-finite
    /// coordinates and (exactly) when the points are collinear or coincide.
    pub fn from_points(
        a: Point3<f64>,
        b: Point3<f64>,
        c: Point3<f64>,
    ) -> Result<Self, GeometryError> {
        const C: &str = "conformal::Plane::from_points";
        finite3(C, ["a.x", "a.y", "a.z"], &a.coords)?;
        finite3(C, ["b.x", "b.y", "b.z"], &b.coords)?;
        finite3(C, ["c.x", "c.y", "c.z"], &c.coords)?;
        let def = PlaneDef::Points(a, b, c);
        let zero = decide(
            || all_zero(&coeffs(Plane::opns_from::<ErrF64>(&def))),
            || all_zero(&coeffs(Plane::opns_from::<Rational>(&def))),
            true,
        );
        if zero {
            return Err(degenerate(C, "points a, b, c are collinear"));
        }
        Ok(Plane::build(def))
    }
    /// The plane `{x : n·x = d}` with IPNS vector `n + d n_inf`. Fails on non-finite input and
    /// when `n` is zero.
    pub fn from_normal_offset(n: Vector3<f64>, d: f64) -> Result<Self, GeometryError> {
        const C: &str = "conformal::Plane::from_normal_offset";
        finite3(C, ["n.x", "n.y", "n.z"], &n)?;
        finite(C, "d", d)?;
        if n == Vector3::zeros() {
            return Err(degenerate(C, "normal n is zero"));
        }
        Ok(Plane::build(PlaneDef::NormalOffset(n, d)))
    }
    /// The plane of an IPNS vector `n + d n_inf` (any nonzero multiple): the plane built from
    /// the `f64` normal and offset read from it. Fails on non-finite coefficients, a zero
    /// normal part, or a vector that is not a plane (`−X·n_inf ≠ 0`: a sphere or point).
    pub fn from_ipns(v: Vector<f64>) -> Result<Self, GeometryError> {
        const C: &str = "conformal::Plane::from_ipns";
        finite_blade(C, v)?;
        if v.e4 != v.e5 {
            return Err(degenerate(
                C,
                "the vector has a nonzero weight −X·n_inf (not a plane)",
            ));
        }
        Plane::from_normal_offset(euclidean_part(&v), v.e4)
            .map_err(|_| degenerate(C, "the normal part is zero"))
    }
    /// The plane of an OPNS quadvector (`from_ipns(dual(Π))`).
    pub fn from_blade(q: Quadvector<f64>) -> Result<Self, GeometryError> {
        Plane::from_ipns(q.dual()).map_err(|e| match e {
            GeometryError::Degenerate { reason, .. } => {
                degenerate("conformal::Plane::from_blade", reason)
            }
            other => other,
        })
    }
    fn build(def: PlaneDef) -> Self {
        Plane {
            blade: Plane::opns_from(&def),
            def,
        }
    }
    fn opns_from<T: Exactish>(def: &PlaneDef) -> Quadvector<T> {
        match def {
            PlaneDef::Points(a, b, c) => embed::<T>(a)
                .wedge(&embed::<T>(b))
                .wedge(&embed::<T>(c))
                .wedge(&n_inf::<T>()),
            PlaneDef::NormalOffset(..) => Plane::ipns_from::<T>(def).undual(),
        }
    }
    fn ipns_from<T: Exactish>(def: &PlaneDef) -> Vector<T> {
        match def {
            PlaneDef::Points(..) => Plane::opns_from::<T>(def).dual(),
            PlaneDef::NormalOffset(n, d) => {
                let d = T::lift(*d);
                Vector::new(T::lift(n.x), T::lift(n.y), T::lift(n.z), d.clone(), d)
            }
        }
    }
    pub(crate) fn ipns_in<T: Exactish>(&self) -> Vector<T> {
        Plane::ipns_from(&self.def)
    }
    /// The OPNS blade (rounded to `f64`).
    pub fn blade(&self) -> &Quadvector<f64> {
        &self.blade
    }
    /// The exact OPNS blade of the plane the `f64` inputs denote.
    pub fn exact_blade(&self) -> Quadvector<Rational> {
        Plane::opns_from(&self.def)
    }
    /// The IPNS vector `dual(Π) ∝ n + d n_inf`.
    pub fn ipns(&self) -> Vector<f64> {
        self.ipns_in()
    }
    /// The unit normal (orientation: see the [module docs](self)).
    pub fn normal(&self) -> Vector3<f64> {
        unit(euclidean_part(&self.ipns()))
    }
    /// The signed distance of the plane from the origin along [`Plane::normal`].
    pub fn offset(&self) -> f64 {
        let v = self.ipns();
        let n = euclidean_part(&v);
        let s = n.amax();
        (v.e4 + v.e5) * 0.5 / s / (n / s).norm()
    }
    /// Whether `x` lies on the plane, `F(x) · dual(Π) = 0`, decided exactly.
    pub fn contains(&self, x: &Point3<f64>) -> bool {
        if !x.iter().all(|c| c.is_finite()) {
            return false;
        }
        decide(
            || {
                embed::<ErrF64>(x)
                    .scalar_product(&self.ipns_in::<ErrF64>())
                    .sign()
                    .map(|s| s == Ordering::Equal)
            },
            || {
                Some(
                    embed::<Rational>(x)
                        .scalar_product(&self.ipns_in::<Rational>())
                        .sign_of()
                        == Some(Ordering::Equal),
                )
            },
            false,
        )
    }
}

// ---------------------------------------------------------------------------------------------
// Sphere.

#[derive(Debug, Clone, Copy, PartialEq)]
enum SphereDef {
    Points([Point3<f64>; 4]),
    CentreRadius(Point3<f64>, f64),
    CentreSquaredRadius(Point3<f64>, f64),
}

/// A conformal sphere, OPNS blade `S = P1 ∧ P2 ∧ P3 ∧ P4` (grade 4; the thesis's (II.26)),
/// IPNS vector `F(c) − r² n_inf = 2(up(c) − ½ r² n_inf)`.
///
/// Real spheres have `r² > 0`, a point sphere `r² = 0`, and an *imaginary* sphere `r² < 0`
/// (no real points; [`Sphere::from_centre_squared_radius`] builds one, and
/// [`Sphere::radius_squared`] is then negative).
///
/// ```
/// use cga_collide::conformal::Sphere;
/// use cga_collide::nalgebra::Point3;
/// let s = Sphere::from_points([
///     Point3::new(1.0, 0.0, 0.0), Point3::new(-1.0, 0.0, 0.0),
///     Point3::new(0.0, 1.0, 0.0), Point3::new(0.0, 0.0, 1.0),
/// ])?;
/// assert_eq!(s.centre(), Point3::origin());
/// assert_eq!(s.radius_squared(), 1.0);
/// let t = Sphere::from_centre_radius(Point3::new(1.0, 2.0, 3.0), 2.0)?;
/// assert_eq!((t.centre(), t.radius()), (Point3::new(1.0, 2.0, 3.0), Some(2.0)));
/// let i = Sphere::from_centre_squared_radius(Point3::origin(), -4.0)?;
/// assert_eq!((i.radius_squared(), i.radius()), (-4.0, None));
/// // Four coplanar points define a plane, not a sphere:
/// assert!(Sphere::from_points([Point3::origin(), Point3::new(1.0, 0.0, 0.0),
///     Point3::new(0.0, 1.0, 0.0), Point3::new(5.0, 7.0, 0.0)]).is_err());
/// # Ok::<(), cga_collide::GeometryError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sphere {
    blade: Quadvector<f64>,
    def: SphereDef,
}

impl Sphere {
    /// The sphere through four points: `F(a) ∧ F(b) ∧ F(c) ∧ F(d)`. Fails on non-finite
    /// coordinates and (exactly) when the points are coplanar (they then span a plane, or
    /// nothing if they are concyclic or coincide).
    pub fn from_points(p: [Point3<f64>; 4]) -> Result<Self, GeometryError> {
        const C: &str = "conformal::Sphere::from_points";
        const NAMES: [[&str; 3]; 4] = [
            ["p[0].x", "p[0].y", "p[0].z"],
            ["p[1].x", "p[1].y", "p[1].z"],
            ["p[2].x", "p[2].y", "p[2].z"],
            ["p[3].x", "p[3].y", "p[3].z"],
        ];
        for (names, q) in NAMES.into_iter().zip(p.iter()) {
            finite3(C, names, &q.coords)?;
        }
        let def = SphereDef::Points(p);
        // The weight −dual(S)·n_inf is zero exactly for planes and for the zero blade.
        let weight = decide(
            || {
                Sphere::ipns_from::<ErrF64>(&def)
                    .scalar_product(&n_inf::<ErrF64>())
                    .sign()
            },
            || {
                Sphere::ipns_from::<Rational>(&def)
                    .scalar_product(&n_inf::<Rational>())
                    .sign_of()
            },
            Ordering::Equal,
        );
        if weight == Ordering::Equal {
            return Err(degenerate(C, "the four points are coplanar"));
        }
        Ok(Sphere::build(def))
    }
    /// The sphere of centre `c` and radius `r ≥ 0` (radius `0`: the point sphere `F(c)`).
    /// Fails on non-finite input and a negative radius.
    pub fn from_centre_radius(c: Point3<f64>, r: f64) -> Result<Self, GeometryError> {
        const C: &str = "conformal::Sphere::from_centre_radius";
        finite3(C, ["c.x", "c.y", "c.z"], &c.coords)?;
        finite(C, "r", r)?;
        if r < 0.0 {
            return Err(degenerate(C, "radius r is negative"));
        }
        Ok(Sphere::build(SphereDef::CentreRadius(c, r)))
    }
    /// The sphere of centre `c` and squared radius `rho` of any sign (`rho < 0`: an imaginary
    /// sphere). Fails on non-finite input.
    pub fn from_centre_squared_radius(c: Point3<f64>, rho: f64) -> Result<Self, GeometryError> {
        const C: &str = "conformal::Sphere::from_centre_squared_radius";
        finite3(C, ["c.x", "c.y", "c.z"], &c.coords)?;
        finite(C, "rho", rho)?;
        Ok(Sphere::build(SphereDef::CentreSquaredRadius(c, rho)))
    }
    /// The sphere of an IPNS vector (any nonzero multiple of `up(c) − ½ρ n_inf`): built from
    /// the `f64` centre and squared radius read from it. Fails on non-finite coefficients or
    /// results and on a zero weight (a plane).
    pub fn from_ipns(v: Vector<f64>) -> Result<Self, GeometryError> {
        const C: &str = "conformal::Sphere::from_ipns";
        finite_blade(C, v)?;
        let w = -v.scalar_product(&n_inf::<f64>());
        if w == 0.0 {
            return Err(degenerate(C, "the weight −X·n_inf is zero (a plane)"));
        }
        let c = checked_point3(
            C,
            "the centre is not finite",
            Point3::from(euclidean_part(&v) / w),
        )?;
        let rho = v.scalar_product(&v) / (w * w);
        if !rho.is_finite() {
            return Err(degenerate(C, "the squared radius is not finite"));
        }
        Sphere::from_centre_squared_radius(c, rho)
    }
    /// The sphere of an OPNS quadvector (`from_ipns(dual(S))`).
    pub fn from_blade(q: Quadvector<f64>) -> Result<Self, GeometryError> {
        Sphere::from_ipns(q.dual()).map_err(|e| match e {
            GeometryError::Degenerate { reason, .. } => {
                degenerate("conformal::Sphere::from_blade", reason)
            }
            other => other,
        })
    }
    fn build(def: SphereDef) -> Self {
        Sphere {
            blade: Sphere::opns_from(&def),
            def,
        }
    }
    fn opns_from<T: Exactish>(def: &SphereDef) -> Quadvector<T> {
        match def {
            SphereDef::Points([a, b, c, d]) => embed::<T>(a)
                .wedge(&embed::<T>(b))
                .wedge(&embed::<T>(c))
                .wedge(&embed::<T>(d)),
            _ => Sphere::ipns_from::<T>(def).undual(),
        }
    }
    fn ipns_from<T: Exactish>(def: &SphereDef) -> Vector<T> {
        match def {
            SphereDef::Points(..) => Sphere::opns_from::<T>(def).dual(),
            SphereDef::CentreRadius(c, r) => {
                let r = T::lift(*r);
                embed::<T>(c) - n_inf::<T>().scale(&(r.clone() * r))
            }
            SphereDef::CentreSquaredRadius(c, rho) => {
                embed::<T>(c) - n_inf::<T>().scale(&T::lift(*rho))
            }
        }
    }
    pub(crate) fn ipns_in<T: Exactish>(&self) -> Vector<T> {
        Sphere::ipns_from(&self.def)
    }
    /// The OPNS blade (rounded to `f64`).
    pub fn blade(&self) -> &Quadvector<f64> {
        &self.blade
    }
    /// The exact OPNS blade of the sphere the `f64` inputs denote.
    pub fn exact_blade(&self) -> Quadvector<Rational> {
        Sphere::opns_from(&self.def)
    }
    /// The IPNS vector `dual(S)`, a multiple of `up(c) − ½ r² n_inf`.
    pub fn ipns(&self) -> Vector<f64> {
        self.ipns_in()
    }
    /// The centre.
    pub fn centre(&self) -> Point3<f64> {
        match self.def {
            SphereDef::CentreRadius(c, _) | SphereDef::CentreSquaredRadius(c, _) => c,
            SphereDef::Points(_) => {
                down(&self.ipns()).unwrap_or_else(|| Point3::new(f64::NAN, f64::NAN, f64::NAN))
            }
        }
    }
    /// The squared radius `s² / (s·n_inf)²` of the IPNS vector `s`: positive for a real
    /// sphere, zero for a point sphere, **negative for an imaginary sphere**.
    pub fn radius_squared(&self) -> f64 {
        match self.def {
            SphereDef::CentreRadius(_, r) => r * r,
            SphereDef::CentreSquaredRadius(_, rho) => rho,
            SphereDef::Points(_) => {
                let s = self.ipns();
                let w = s.scalar_product(&n_inf::<f64>());
                s.scalar_product(&s) / (w * w)
            }
        }
    }
    /// The radius, `None` for an imaginary sphere.
    pub fn radius(&self) -> Option<f64> {
        match self.def {
            SphereDef::CentreRadius(_, r) => Some(r),
            _ => {
                let r2 = self.radius_squared();
                (r2 >= 0.0).then(|| r2.sqrt())
            }
        }
    }
    /// The sign of the exact squared radius (`Less`: imaginary, `Equal`: a point).
    pub fn radius_squared_sign(&self) -> Ordering {
        decide(
            || {
                let s = self.ipns_in::<ErrF64>();
                s.scalar_product(&s).sign()
            },
            || {
                let s = self.ipns_in::<Rational>();
                s.scalar_product(&s).sign_of()
            },
            Ordering::Equal,
        )
    }
    /// Where `x` is with respect to the solid ball bounded by the sphere, decided exactly:
    /// `Greater` inside, `Equal` on the sphere, `Less` outside. It is the sign of
    /// `(F(x)·s)(−s·n_inf) = 2(r² − |x − c|²)·w` for the IPNS vector `s` of weight `w`, so the
    /// conformal sphere doubles as a ball. A non-finite `x` is `Less` (outside).
    ///
    /// ```
    /// use cga_collide::conformal::Sphere;
    /// use cga_collide::nalgebra::Point3;
    /// use core::cmp::Ordering;
    /// let s = Sphere::from_points([Point3::new(1.0, 0.0, 0.0), Point3::new(-1.0, 0.0, 0.0),
    ///                              Point3::new(0.0, 1.0, 0.0), Point3::new(0.0, 0.0, 1.0)])?;
    /// assert_eq!(s.side(&Point3::new(0.5, 0.5, 0.5)), Ordering::Greater);
    /// assert_eq!(s.side(&Point3::new(0.0, -1.0, 0.0)), Ordering::Equal);
    /// assert_eq!(s.side(&Point3::new(0.0, 0.0, 1.0 + f64::EPSILON)), Ordering::Less);
    /// # Ok::<(), cga_collide::GeometryError>(())
    /// ```
    pub fn side(&self, x: &Point3<f64>) -> Ordering {
        if !x.iter().all(|c| c.is_finite()) {
            return Ordering::Less;
        }
        fn side_in<T: Exactish>(s: &Vector<T>, x: &Point3<f64>) -> Option<Ordering> {
            let v = embed::<T>(x).scalar_product(s);
            let w = -s.scalar_product(&n_inf::<T>());
            let (a, b) = (v.sign_of()?, w.sign_of()?);
            Some(if b == Ordering::Less { a.reverse() } else { a })
        }
        decide(
            || side_in(&self.ipns_in::<ErrF64>(), x),
            || side_in(&self.ipns_in::<Rational>(), x),
            Ordering::Less,
        )
    }
    /// Whether `x` lies on the sphere, `F(x) · dual(S) = 0`, decided exactly.
    pub fn contains(&self, x: &Point3<f64>) -> bool {
        if !x.iter().all(|c| c.is_finite()) {
            return false;
        }
        decide(
            || {
                embed::<ErrF64>(x)
                    .scalar_product(&self.ipns_in::<ErrF64>())
                    .sign()
                    .map(|s| s == Ordering::Equal)
            },
            || {
                Some(
                    embed::<Rational>(x)
                        .scalar_product(&self.ipns_in::<Rational>())
                        .sign_of()
                        == Some(Ordering::Equal),
                )
            },
            false,
        )
    }
}

// ---------------------------------------------------------------------------------------------
// Circle, point pair, flat point: blades with extraction (not classified by `meet`).

/// A circle, OPNS blade `C = P1 ∧ P2 ∧ P3` (grade 3; the thesis's (II.21)).
///
/// Centre `C n_inf C` (II.23), squared radius `−C² / (C ∧ n_inf)²` (II.22), normal from the
/// carrier plane `C ∧ n_inf`.
///
/// ```
/// use cga_collide::conformal::Circle;
/// use cga_collide::nalgebra::{Point3, Vector3};
/// let c = Circle::from_points(Point3::new(1.0, 0.0, 5.0), Point3::new(0.0, 1.0, 5.0), Point3::new(-1.0, 0.0, 5.0))?;
/// assert!((c.centre() - Point3::new(0.0, 0.0, 5.0)).norm() < 1e-12);
/// assert!((c.radius_squared() - 1.0).abs() < 1e-12);
/// assert!((c.normal().dot(&Vector3::z()).abs() - 1.0).abs() < 1e-12);
/// # Ok::<(), cga_collide::GeometryError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    blade: Trivector<f64>,
}

impl Circle {
    /// The circle through three points. Fails on non-finite coordinates and (exactly) when
    /// the points are collinear or two coincide.
    pub fn from_points(
        a: Point3<f64>,
        b: Point3<f64>,
        c: Point3<f64>,
    ) -> Result<Self, GeometryError> {
        const C: &str = "conformal::Circle::from_points";
        finite3(C, ["a.x", "a.y", "a.z"], &a.coords)?;
        finite3(C, ["b.x", "b.y", "b.z"], &b.coords)?;
        finite3(C, ["c.x", "c.y", "c.z"], &c.coords)?;
        fn carrier<T: Exactish>(a: &Point3<f64>, b: &Point3<f64>, c: &Point3<f64>) -> [T; 32] {
            coeffs(
                embed::<T>(a)
                    .wedge(&embed::<T>(b))
                    .wedge(&embed::<T>(c))
                    .wedge(&n_inf::<T>()),
            )
        }
        let zero = decide(
            || all_zero(&carrier::<ErrF64>(&a, &b, &c)),
            || all_zero(&carrier::<Rational>(&a, &b, &c)),
            true,
        );
        if zero {
            return Err(degenerate(C, "points a, b, c are collinear or coincide"));
        }
        Ok(Circle {
            blade: embed::<f64>(&a).wedge(&embed(&b)).wedge(&embed(&c)),
        })
    }
    /// The circle of centre `c`, radius `r` in the plane through `c` with normal `n`: the
    /// OPNS form of the meet `dual(sphere) ∧ dual(plane)`. Fails on non-finite input, a
    /// negative radius or a zero normal.
    pub fn from_centre_normal_radius(
        c: Point3<f64>,
        n: Vector3<f64>,
        r: f64,
    ) -> Result<Self, GeometryError> {
        let s = Sphere::from_centre_radius(c, r)?;
        let p = Plane::from_normal_offset(n, n.dot(&c.coords))?;
        Ok(Circle {
            blade: s.ipns().wedge(&p.ipns()).undual(),
        })
    }
    /// The circle of an OPNS trivector (any nonzero multiple of `P1 ∧ P2 ∧ P3`). Fails on
    /// non-finite coefficients and when `C ∧ n_inf = 0` in `f64` (a line or zero: no carrier
    /// plane). The blade is kept as given (rounded data is taken as exact).
    ///
    /// ```
    /// use cga_collide::conformal::{Circle, Line};
    /// use cga_collide::nalgebra::{Point3, Vector3};
    /// let c = Circle::from_centre_normal_radius(Point3::origin(), Vector3::z(), 2.0)?;
    /// assert_eq!(Circle::from_blade(*c.blade())?, c);
    /// assert_eq!(Circle::from_ipns(c.ipns())?, c);
    /// let l = Line::from_point_direction(Point3::origin(), Vector3::z())?;
    /// assert!(Circle::from_blade(*l.blade()).is_err());
    /// # Ok::<(), cga_collide::GeometryError>(())
    /// ```
    pub fn from_blade(blade: Trivector<f64>) -> Result<Self, GeometryError> {
        const C: &str = "conformal::Circle::from_blade";
        finite_blade(C, blade)?;
        if coeffs(blade.wedge(&n_inf::<f64>()))
            .iter()
            .all(|c| *c == 0.0)
        {
            return Err(degenerate(
                C,
                "C ∧ n_inf is zero (a line, or the zero blade)",
            ));
        }
        Ok(Circle { blade })
    }
    /// The circle of an IPNS bivector (`from_blade(undual(C*))`).
    pub fn from_ipns(b: Bivector<f64>) -> Result<Self, GeometryError> {
        Circle::from_blade(b.undual())
    }
    pub(crate) fn from_blade_unchecked(blade: Trivector<f64>) -> Self {
        Circle { blade }
    }
    /// The OPNS blade.
    pub fn blade(&self) -> &Trivector<f64> {
        &self.blade
    }
    /// The IPNS (dual) form, a bivector.
    pub fn ipns(&self) -> Bivector<f64> {
        self.blade.dual()
    }
    /// The centre `down(C n_inf C)`.
    pub fn centre(&self) -> Point3<f64> {
        round_centre(&self.blade).unwrap_or_else(|| Point3::new(f64::NAN, f64::NAN, f64::NAN))
    }
    /// The squared radius `−C² / (C ∧ n_inf)²` (negative for an imaginary circle).
    pub fn radius_squared(&self) -> f64 {
        let w = self.blade.wedge(&n_inf::<f64>());
        -self.blade.scalar_product(&self.blade) / w.scalar_product(&w)
    }
    /// The radius, `None` for an imaginary circle.
    pub fn radius(&self) -> Option<f64> {
        let r2 = self.radius_squared();
        (r2 >= 0.0).then(|| r2.sqrt())
    }
    /// The unit normal of the carrier plane `C ∧ n_inf` (orientation follows the blade).
    pub fn normal(&self) -> Vector3<f64> {
        let carrier: Quadvector<f64> = self.blade.wedge(&n_inf::<f64>());
        unit(euclidean_part(&carrier.dual()))
    }
}

/// A point pair, OPNS blade `T = P1 ∧ P2` (grade 2).
///
/// The points are `(T ∓ √(T²)) (−n_inf ⌋ T)⁻¹` (real when `T² > 0`), the centre
/// `T n_inf T`, the squared half-distance `T² / (T ∧ n_inf)²`.
///
/// ```
/// use cga_collide::conformal::PointPair;
/// use cga_collide::nalgebra::Point3;
/// let (a, b) = (Point3::new(1.0, 2.0, 3.0), Point3::new(3.0, 2.0, 1.0));
/// let t = PointPair::from_points(a, b)?;
/// let (p, q) = t.points().unwrap();
/// assert!((p - a).norm() < 1e-12 && (q - b).norm() < 1e-12);
/// assert!((t.centre() - Point3::new(2.0, 2.0, 2.0)).norm() < 1e-12);
/// assert!((t.radius_squared() - 2.0).abs() < 1e-12);
/// # Ok::<(), cga_collide::GeometryError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointPair {
    blade: Bivector<f64>,
}

impl PointPair {
    /// The pair `{a, b}`. Fails on non-finite coordinates and when `a == b`.
    pub fn from_points(a: Point3<f64>, b: Point3<f64>) -> Result<Self, GeometryError> {
        const C: &str = "conformal::PointPair::from_points";
        finite3(C, ["a.x", "a.y", "a.z"], &a.coords)?;
        finite3(C, ["b.x", "b.y", "b.z"], &b.coords)?;
        if a == b {
            return Err(degenerate(C, "points a and b coincide"));
        }
        Ok(PointPair {
            blade: embed::<f64>(&a).wedge(&embed(&b)),
        })
    }
    /// The point pair of an OPNS bivector (any nonzero multiple of `P1 ∧ P2`). Fails on
    /// non-finite coefficients and when `T ∧ n_inf = 0` in `f64` (a flat point, or zero). The
    /// blade is kept as given; it may be imaginary ([`PointPair::points`] is then `None`).
    ///
    /// ```
    /// use cga_collide::conformal::{FlatPoint, PointPair};
    /// use cga_collide::nalgebra::Point3;
    /// let t = PointPair::from_points(Point3::origin(), Point3::new(0.0, 0.0, 2.0))?;
    /// assert_eq!(PointPair::from_ipns(t.ipns())?, t);
    /// let f = FlatPoint::new(Point3::origin())?;
    /// assert!(PointPair::from_blade(*f.blade()).is_err());
    /// # Ok::<(), cga_collide::GeometryError>(())
    /// ```
    pub fn from_blade(blade: Bivector<f64>) -> Result<Self, GeometryError> {
        const C: &str = "conformal::PointPair::from_blade";
        finite_blade(C, blade)?;
        if coeffs(blade.wedge(&n_inf::<f64>()))
            .iter()
            .all(|c| *c == 0.0)
        {
            return Err(degenerate(
                C,
                "T ∧ n_inf is zero (a flat point, or the zero blade)",
            ));
        }
        Ok(PointPair { blade })
    }
    /// The point pair of an IPNS trivector (`from_blade(undual(T*))`).
    pub fn from_ipns(t: Trivector<f64>) -> Result<Self, GeometryError> {
        PointPair::from_blade(t.undual())
    }
    pub(crate) fn from_blade_unchecked(blade: Bivector<f64>) -> Self {
        PointPair { blade }
    }
    /// The OPNS blade.
    pub fn blade(&self) -> &Bivector<f64> {
        &self.blade
    }
    /// The IPNS (dual) form, a trivector.
    pub fn ipns(&self) -> Trivector<f64> {
        self.blade.dual()
    }
    /// The two points, `None` if the pair is imaginary (`T² < 0`) or not finite. For
    /// [`PointPair::from_points`] they come back in construction order.
    pub fn points(&self) -> Option<(Point3<f64>, Point3<f64>)> {
        let t = self.blade;
        let t2 = t.scalar_product(&t);
        if t2.is_nan() || t2 < 0.0 {
            return None;
        }
        let root = t2.sqrt();
        let v: Vector<f64> = -n_inf::<f64>().left_contraction(&t);
        let vv = v.scalar_product(&v);
        let point = |sign: f64| -> Option<Point3<f64>> {
            let mut e: Multivector<f64> = t.into();
            let mut c = e.coefficients();
            c[0] = -sign * root;
            e = Multivector::from_coefficients(c);
            let p = e * Multivector::from(v) * (1.0 / vv);
            down(&Vector::from_multivector(&p))
        };
        Some((point(1.0)?, point(-1.0)?))
    }
    /// The centre (midpoint) `down(T n_inf T)`.
    pub fn centre(&self) -> Point3<f64> {
        round_centre(&self.blade).unwrap_or_else(|| Point3::new(f64::NAN, f64::NAN, f64::NAN))
    }
    /// The squared half-distance `T² / (T ∧ n_inf)²` (negative for an imaginary pair).
    pub fn radius_squared(&self) -> f64 {
        let w = self.blade.wedge(&n_inf::<f64>());
        self.blade.scalar_product(&self.blade) / w.scalar_product(&w)
    }
}

/// A flat point, OPNS blade `F(x) ∧ n_inf` (grade 2): the meet of a line and a plane.
///
/// ```
/// use cga_collide::conformal::FlatPoint;
/// use cga_collide::nalgebra::Point3;
/// let f = FlatPoint::new(Point3::new(1.0, -2.0, 0.5))?;
/// assert_eq!(f.position(), Some(Point3::new(1.0, -2.0, 0.5)));
/// # Ok::<(), cga_collide::GeometryError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FlatPoint {
    blade: Bivector<f64>,
}

impl FlatPoint {
    /// The flat point at `x`. Fails on a non-finite coordinate.
    pub fn new(x: Point3<f64>) -> Result<Self, GeometryError> {
        finite3(
            "conformal::FlatPoint::new",
            ["x.x", "x.y", "x.z"],
            &x.coords,
        )?;
        Ok(FlatPoint {
            blade: embed::<f64>(&x).wedge(&n_inf::<f64>()),
        })
    }
    /// The flat point of an OPNS bivector (any nonzero multiple of `F(x) ∧ n_inf`): built
    /// from the `f64` position read from it. Fails on non-finite coefficients and on a flat
    /// point at infinity (zero weight).
    ///
    /// ```
    /// use cga_collide::conformal::FlatPoint;
    /// use cga_collide::nalgebra::Point3;
    /// let f = FlatPoint::new(Point3::new(1.0, 2.0, 3.0))?;
    /// assert_eq!(FlatPoint::from_ipns(f.ipns())?, f);
    /// # Ok::<(), cga_collide::GeometryError>(())
    /// ```
    pub fn from_blade(blade: Bivector<f64>) -> Result<Self, GeometryError> {
        const C: &str = "conformal::FlatPoint::from_blade";
        finite_blade(C, blade)?;
        let x = flat_point_location(&blade)
            .ok_or_else(|| degenerate(C, "the weight is zero (a flat point at infinity)"))?;
        FlatPoint::new(x)
    }
    /// The flat point of an IPNS trivector (`from_blade(undual(F*))`).
    pub fn from_ipns(t: Trivector<f64>) -> Result<Self, GeometryError> {
        FlatPoint::from_blade(t.undual())
    }
    pub(crate) fn from_blade_unchecked(blade: Bivector<f64>) -> Self {
        FlatPoint { blade }
    }
    /// The OPNS blade.
    pub fn blade(&self) -> &Bivector<f64> {
        &self.blade
    }
    /// The IPNS (dual) form, a trivector.
    pub fn ipns(&self) -> Trivector<f64> {
        self.blade.dual()
    }
    /// The position `(F₁₄, F₂₄, F₃₄) / (−F₄₅)`; `None` for a flat point at infinity.
    pub fn position(&self) -> Option<Point3<f64>> {
        flat_point_location(&self.blade)
    }
}
