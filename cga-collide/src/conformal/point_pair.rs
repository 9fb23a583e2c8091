//! The point pair.

use ga_core::cga::{Bivector, Multivector, Trivector, Vector};
use ga_core::prelude::*;
use nalgebra::Point3;

use super::blades::*;
use crate::error::Error;

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
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PointPair {
    blade: Bivector<f64>,
}

impl PointPair {
    /// The pair `{a, b}`. Fails on non-finite coordinates and when `a == b`.
    pub fn from_points(a: Point3<f64>, b: Point3<f64>) -> Result<Self, Error> {
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
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn from_blade(blade: Bivector<f64>) -> Result<Self, Error> {
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
    pub fn from_ipns(t: Trivector<f64>) -> Result<Self, Error> {
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
