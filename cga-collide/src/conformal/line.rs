//! The line.

use ga_core::cga::{Bivector, Trivector, Vector};
use ga_core::prelude::*;
use ga_core::scalar::Rational;
use nalgebra::{Point3, Vector3};

use super::blades::*;
use crate::error::Error;
use crate::exact::{all_zero, decide, CertifiedScalar, ErrF64};

#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum LineDef {
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
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Line {
    pub(crate) blade: Trivector<f64>,
    pub(crate) def: LineDef,
}

impl Line {
    /// The line through `a` and `b`: `F(a) ∧ F(b) ∧ n_inf`. Fails on non-finite coordinates
    /// and when `a == b`.
    pub fn from_points(a: Point3<f64>, b: Point3<f64>) -> Result<Self, Error> {
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
    pub fn from_point_direction(p: Point3<f64>, d: Vector3<f64>) -> Result<Self, Error> {
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
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn from_blade(t: Trivector<f64>) -> Result<Self, Error> {
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
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn from_ipns(b: Bivector<f64>) -> Result<Self, Error> {
        Line::from_blade(b.undual())
    }
    fn build(def: LineDef) -> Self {
        Line {
            blade: Line::blade_from(&def),
            def,
        }
    }
    fn blade_from<T: CertifiedScalar>(def: &LineDef) -> Trivector<T> {
        let n = n_inf::<T>();
        match def {
            LineDef::Points(a, b) => embed::<T>(a).wedge(&embed::<T>(b)).wedge(&n),
            LineDef::PointDirection(p, d) => embed::<T>(p).wedge(&direction::<T>(d)).wedge(&n),
        }
    }
    pub(crate) fn blade_in<T: CertifiedScalar>(&self) -> Trivector<T> {
        Line::blade_from(&self.def)
    }
    /// Two conformal points of the line (`F(a), F(b)`, or `F(p)` and `F(p) + d`: both
    /// span the line with `n_inf`), in any ring.
    pub(crate) fn spanning_vectors<T: CertifiedScalar>(&self) -> [Vector<T>; 2] {
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
