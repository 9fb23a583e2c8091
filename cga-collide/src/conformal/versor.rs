//! Transformations as versors: translators, rotors, dilators (even elements
//! [`ga_core::cga::Even`]) and reflections in planes (odd: the plane's unit IPNS vector).
//!
//! A versor `V` acts on a blade `X` by the sandwich `V X Ṽ` ([`SandwichUnit`]; every versor
//! built here has `V Ṽ = 1`). For a reflection in the unit plane vector `π` the action is
//! `(−1)^k π X π` on a grade-`k` blade, so that orientations follow the Euclidean reflection.
//!
//! ```
//! use cga_collide::conformal::{Point, Transform, Versor};
//! use cga_collide::nalgebra::{Isometry3, Point3, Vector3};
//! use std::f64::consts::FRAC_PI_2;
//!
//! let iso = Isometry3::new(Vector3::new(1.0, 2.0, 3.0), Vector3::z() * FRAC_PI_2);
//! let v = Versor::from(iso);
//! let p = Point::new(Point3::new(1.0, 0.0, 0.0))?;
//! let q = p.transform(&v)?.position().unwrap();
//! assert!((q - iso * Point3::new(1.0, 0.0, 0.0)).norm() < 1e-12); // (1, 3, 3)
//! # Ok::<(), cga_collide::Error>(())
//! ```

use ga_core::cga::{Even, Vector};
use ga_core::prelude::*;
use nalgebra::{Isometry3, Point3, Unit, UnitQuaternion, Vector3};

use super::{finite, finite3, Circle, FlatPoint, Line, Plane, Point, PointPair, Sphere};
use crate::error::Error;

/// An even versor of Cl(4,1) with `V Ṽ = 1`: a composition of translations, rotations and
/// uniform scalings.
///
/// ```
/// use cga_collide::conformal::{Point, Transform, Versor};
/// use cga_collide::nalgebra::{Point3, Vector3};
/// let t = Versor::translator(Vector3::new(1.0, 0.0, 0.0))?;
/// let d = Versor::dilator(2.0)?;
/// let v = t.then(&d); // first translate, then scale by 2 about the origin
/// let p = Point::new(Point3::new(1.0, 1.0, 1.0))?.transform(&v)?;
/// assert!((p.position().unwrap() - Point3::new(4.0, 2.0, 2.0)).norm() < 1e-12);
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Versor {
    even: Even<f64>,
}

impl Default for Versor {
    fn default() -> Self {
        Versor::identity()
    }
}

impl Versor {
    /// The identity `1`.
    pub fn identity() -> Self {
        let mut even = Even::zero();
        even.s = 1.0;
        Versor { even }
    }
    /// The translator `T = 1 + ½ n_inf t` (the thesis's (II.33)): `x ↦ x + t`.
    pub fn translator(t: Vector3<f64>) -> Result<Self, Error> {
        finite3("conformal::Versor::translator", ["t.x", "t.y", "t.z"], &t)?;
        let nt = Even::from(super::n_inf::<f64>() * Vector::from(t));
        Ok(Versor {
            even: Versor::identity().even + nt * 0.5,
        })
    }
    /// The rotor `R = cos(θ/2) − sin(θ/2) B` (the thesis's (II.38)), `B` the unit bivector dual
    /// to `axis`: the right-handed rotation by `angle` radians about `axis` through the origin.
    /// Fails on non-finite input and a zero axis.
    pub fn rotor(axis: Vector3<f64>, angle: f64) -> Result<Self, Error> {
        const C: &str = "conformal::Versor::rotor";
        finite3(C, ["axis.x", "axis.y", "axis.z"], &axis)?;
        finite(C, "angle", angle)?;
        if axis == Vector3::zeros() {
            return Err(super::degenerate(C, "axis is zero"));
        }
        let axis = Unit::new_normalize(super::unit(axis));
        Ok(Versor::from(UnitQuaternion::from_axis_angle(&axis, angle)))
    }
    /// The dilator `D = cosh(α/2) + sinh(α/2) e45` with `α = −ln(factor)` (the thesis's (II.43)):
    /// `x ↦ factor · x` about the origin. Fails unless `factor` is finite and positive.
    pub fn dilator(factor: f64) -> Result<Self, Error> {
        const C: &str = "conformal::Versor::dilator";
        finite(C, "factor", factor)?;
        if factor <= 0.0 {
            return Err(super::degenerate(C, "factor is not positive"));
        }
        let r = factor.sqrt();
        let mut even = Even::zero();
        even.s = (r + 1.0 / r) * 0.5;
        even.e45 = -(r - 1.0 / r) * 0.5;
        Ok(Versor { even })
    }
    /// The dilator about `centre`: `T_c D T_{−c}`.
    pub fn dilator_about(centre: Point3<f64>, factor: f64) -> Result<Self, Error> {
        let to = Versor::translator(-centre.coords)?;
        let back = Versor::translator(centre.coords)?;
        Ok(to.then(&Versor::dilator(factor)?).then(&back))
    }
    /// The composition "first `self`, then `next`": the versor `next · self`.
    pub fn then(&self, next: &Versor) -> Versor {
        Versor {
            even: next.even * self.even,
        }
    }
    /// The even multivector.
    pub fn even(&self) -> &Even<f64> {
        &self.even
    }
}

impl From<UnitQuaternion<f64>> for Versor {
    /// The rotor of a unit quaternion `w + (x, y, z)`: `w − x e23 + y e13 − z e12`.
    fn from(q: UnitQuaternion<f64>) -> Self {
        let mut even = Even::zero();
        even.s = q.w;
        even.e23 = -q.i;
        even.e13 = q.j;
        even.e12 = -q.k;
        Versor { even }
    }
}

impl From<Isometry3<f64>> for Versor {
    /// `x ↦ R x + t` as the versor `T_t R`.
    fn from(iso: Isometry3<f64>) -> Self {
        let r = Versor::from(iso.rotation);
        let t = Versor::translator(iso.translation.vector).unwrap_or_else(|_| {
            // Non-finite translation: keep the NaNs visible in the versor.
            let mut even = Even::zero();
            even.s = f64::NAN;
            Versor { even }
        });
        r.then(&t)
    }
}

/// The reflection in a plane, versor `π` (the plane's IPNS vector, normalised to `π² = 1`;
/// the thesis's (II.50)).
///
/// ```
/// use cga_collide::conformal::{Plane, Point, Reflection, Transform};
/// use cga_collide::nalgebra::{Point3, Vector3};
/// let mirror = Reflection::new(&Plane::from_normal_offset(Vector3::x(), 1.0)?); // x = 1
/// let p = Point::new(Point3::new(3.0, 2.0, 1.0))?.reflect(&mirror)?;
/// assert!((p.position().unwrap() - Point3::new(-1.0, 2.0, 1.0)).norm() < 1e-12);
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Reflection {
    plane: Vector<f64>,
}

impl Reflection {
    /// The reflection in `plane`.
    pub fn new(plane: &Plane) -> Self {
        let n = plane.normal();
        let d = plane.offset();
        Reflection {
            plane: Vector::new(n.x, n.y, n.z, d, d),
        }
    }
    /// The unit IPNS vector `n + d n_inf` (`|n| = 1`).
    pub fn vector(&self) -> &Vector<f64> {
        &self.plane
    }
}

/// Primitives that versors act on. The result is rebuilt from the `f64` Euclidean data of the
/// transformed blade (see the [exactness note](super#exactness)); it fails only when that data
/// is not finite (overflow).
pub trait Transform: Sized {
    /// `V X Ṽ`.
    ///
    /// ```
    /// use cga_collide::conformal::{Line, Transform, Versor};
    /// use cga_collide::nalgebra::{Point3, Vector3};
    /// let l = Line::from_point_direction(Point3::origin(), Vector3::x())?;
    /// let m = l.transform(&Versor::translator(Vector3::new(0.0, 5.0, 0.0))?)?;
    /// assert!((m.support_point() - Point3::new(0.0, 5.0, 0.0)).norm() < 1e-12);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    fn transform(&self, v: &Versor) -> Result<Self, Error>;
    /// `(−1)^k π X π` for a grade-`k` blade `X`.
    ///
    /// ```
    /// use cga_collide::conformal::{Plane, Reflection, Sphere, Transform};
    /// use cga_collide::nalgebra::{Point3, Vector3};
    /// let m = Reflection::new(&Plane::from_normal_offset(Vector3::z(), 0.0)?);
    /// let s = Sphere::from_centre_radius(Point3::new(0.0, 0.0, 2.0), 1.0)?.reflect(&m)?;
    /// assert!((s.centre() - Point3::new(0.0, 0.0, -2.0)).norm() < 1e-12);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    fn reflect(&self, r: &Reflection) -> Result<Self, Error>;
}

impl Transform for Point {
    fn transform(&self, v: &Versor) -> Result<Self, Error> {
        Point::from_blade(v.even.sandwich_unit(self.blade()))
    }
    fn reflect(&self, r: &Reflection) -> Result<Self, Error> {
        Point::from_blade(-r.plane.sandwich_unit(self.blade()))
    }
}

impl Transform for Line {
    fn transform(&self, v: &Versor) -> Result<Self, Error> {
        Line::from_blade(v.even.sandwich_unit(self.blade()))
    }
    fn reflect(&self, r: &Reflection) -> Result<Self, Error> {
        Line::from_blade(-r.plane.sandwich_unit(self.blade()))
    }
}

impl Transform for Plane {
    fn transform(&self, v: &Versor) -> Result<Self, Error> {
        Plane::from_ipns(v.even.sandwich_unit(&self.ipns()))
    }
    fn reflect(&self, r: &Reflection) -> Result<Self, Error> {
        Plane::from_ipns(-r.plane.sandwich_unit(&self.ipns()))
    }
}

impl Transform for Sphere {
    fn transform(&self, v: &Versor) -> Result<Self, Error> {
        Sphere::from_ipns(v.even.sandwich_unit(&self.ipns()))
    }
    fn reflect(&self, r: &Reflection) -> Result<Self, Error> {
        Sphere::from_ipns(-r.plane.sandwich_unit(&self.ipns()))
    }
}

impl Transform for Circle {
    fn transform(&self, v: &Versor) -> Result<Self, Error> {
        let b = v.even.sandwich_unit(self.blade());
        super::finite_blade("conformal::Circle::transform", b)?;
        Ok(Circle::from_blade_unchecked(b))
    }
    fn reflect(&self, r: &Reflection) -> Result<Self, Error> {
        let b = -r.plane.sandwich_unit(self.blade());
        super::finite_blade("conformal::Circle::reflect", b)?;
        Ok(Circle::from_blade_unchecked(b))
    }
}

impl Transform for PointPair {
    fn transform(&self, v: &Versor) -> Result<Self, Error> {
        let b = v.even.sandwich_unit(self.blade());
        super::finite_blade("conformal::PointPair::transform", b)?;
        Ok(PointPair::from_blade_unchecked(b))
    }
    fn reflect(&self, r: &Reflection) -> Result<Self, Error> {
        let b = r.plane.sandwich_unit(self.blade());
        super::finite_blade("conformal::PointPair::reflect", b)?;
        Ok(PointPair::from_blade_unchecked(b))
    }
}

impl Transform for FlatPoint {
    fn transform(&self, v: &Versor) -> Result<Self, Error> {
        let b = v.even.sandwich_unit(self.blade());
        super::finite_blade("conformal::FlatPoint::transform", b)?;
        Ok(FlatPoint::from_blade_unchecked(b))
    }
    fn reflect(&self, r: &Reflection) -> Result<Self, Error> {
        let b = r.plane.sandwich_unit(self.blade());
        super::finite_blade("conformal::FlatPoint::reflect", b)?;
        Ok(FlatPoint::from_blade_unchecked(b))
    }
}
