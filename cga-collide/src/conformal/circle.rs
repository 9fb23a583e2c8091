//! The circle.

use ga_core::cga::{Bivector, Quadvector, Trivector};
use ga_core::prelude::*;
use ga_core::scalar::Rational;
use nalgebra::{Point3, Vector3};

use super::blades::*;
use super::{Plane, Sphere};
use crate::error::Error;
use crate::exact::{all_zero, decide, CertifiedScalar, ErrF64};

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
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Circle {
    blade: Trivector<f64>,
}

impl Circle {
    /// The circle through three points. Fails on non-finite coordinates and (exactly) when
    /// the points are collinear or two coincide.
    pub fn from_points(a: Point3<f64>, b: Point3<f64>, c: Point3<f64>) -> Result<Self, Error> {
        const C: &str = "conformal::Circle::from_points";
        finite3(C, ["a.x", "a.y", "a.z"], &a.coords)?;
        finite3(C, ["b.x", "b.y", "b.z"], &b.coords)?;
        finite3(C, ["c.x", "c.y", "c.z"], &c.coords)?;
        fn carrier<T: CertifiedScalar>(
            a: &Point3<f64>,
            b: &Point3<f64>,
            c: &Point3<f64>,
        ) -> [T; 32] {
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
    ) -> Result<Self, Error> {
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
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn from_blade(blade: Trivector<f64>) -> Result<Self, Error> {
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
    pub fn from_ipns(b: Bivector<f64>) -> Result<Self, Error> {
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
