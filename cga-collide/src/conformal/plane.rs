//! The plane.

use ga_core::cga::{Quadvector, Vector};
use ga_core::prelude::*;
use ga_core::scalar::Rational;
use nalgebra::{Point3, Vector3};

use super::blades::*;
use crate::error::Error;
use crate::exact::{all_zero, decide, CertifiedScalar, ErrF64};

#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum PlaneDef {
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
/// # Ok::<(), cga_collide::Error>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plane {
    blade: Quadvector<f64>,
    def: PlaneDef,
}

impl Plane {
    /// The plane through `a, b, c`: `F(a) ∧ F(b) ∧ F(c) ∧ n_inf`. Fails on non-finite
    /// coordinates and (exactly) when the points are collinear or coincide.
    pub fn from_points(a: Point3<f64>, b: Point3<f64>, c: Point3<f64>) -> Result<Self, Error> {
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
    pub fn from_normal_offset(n: Vector3<f64>, d: f64) -> Result<Self, Error> {
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
    pub fn from_ipns(v: Vector<f64>) -> Result<Self, Error> {
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
    pub fn from_blade(q: Quadvector<f64>) -> Result<Self, Error> {
        Plane::from_ipns(q.dual()).map_err(|e| match e {
            Error::Degenerate { reason, .. } => degenerate("conformal::Plane::from_blade", reason),
            other => other,
        })
    }
    fn build(def: PlaneDef) -> Self {
        Plane {
            blade: Plane::opns_from(&def),
            def,
        }
    }
    fn opns_from<T: CertifiedScalar>(def: &PlaneDef) -> Quadvector<T> {
        match def {
            PlaneDef::Points(a, b, c) => embed::<T>(a)
                .wedge(&embed::<T>(b))
                .wedge(&embed::<T>(c))
                .wedge(&n_inf::<T>()),
            PlaneDef::NormalOffset(..) => Plane::ipns_from::<T>(def).undual(),
        }
    }
    fn ipns_from<T: CertifiedScalar>(def: &PlaneDef) -> Vector<T> {
        match def {
            PlaneDef::Points(..) => Plane::opns_from::<T>(def).dual(),
            PlaneDef::NormalOffset(n, d) => {
                let d = T::lift(*d);
                Vector::new(T::lift(n.x), T::lift(n.y), T::lift(n.z), d.clone(), d)
            }
        }
    }
    pub(crate) fn ipns_in<T: CertifiedScalar>(&self) -> Vector<T> {
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
    /// The unit normal (orientation: see `Plane::from_points`).
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
        on_inner_vector(self, x)
    }
}

impl InnerVector for Plane {
    fn inner_vector<T: CertifiedScalar>(&self) -> Vector<T> {
        self.ipns_in()
    }
}
