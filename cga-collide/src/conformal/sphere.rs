//! The conformal sphere (real, point or imaginary).

use core::cmp::Ordering;

use ga_core::cga::{Quadvector, Vector};
use ga_core::prelude::*;
use ga_core::scalar::Rational;
use nalgebra::Point3;

use super::blades::*;
use crate::error::Error;
use crate::exact::{decide, CertifiedScalar, ErrF64};

#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) enum SphereDef {
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
/// # Ok::<(), cga_collide::Error>(())
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
    pub fn from_points(p: [Point3<f64>; 4]) -> Result<Self, Error> {
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
                    .certain_sign()
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
    pub fn from_centre_radius(c: Point3<f64>, r: f64) -> Result<Self, Error> {
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
    pub fn from_centre_squared_radius(c: Point3<f64>, rho: f64) -> Result<Self, Error> {
        const C: &str = "conformal::Sphere::from_centre_squared_radius";
        finite3(C, ["c.x", "c.y", "c.z"], &c.coords)?;
        finite(C, "rho", rho)?;
        Ok(Sphere::build(SphereDef::CentreSquaredRadius(c, rho)))
    }
    /// The sphere of an IPNS vector (any nonzero multiple of `up(c) − ½ρ n_inf`): built from
    /// the `f64` centre and squared radius read from it. Fails on non-finite coefficients or
    /// results and on a zero weight (a plane).
    pub fn from_ipns(v: Vector<f64>) -> Result<Self, Error> {
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
    pub fn from_blade(q: Quadvector<f64>) -> Result<Self, Error> {
        Sphere::from_ipns(q.dual()).map_err(|e| match e {
            Error::Degenerate { reason, .. } => degenerate("conformal::Sphere::from_blade", reason),
            other => other,
        })
    }
    fn build(def: SphereDef) -> Self {
        Sphere {
            blade: Sphere::opns_from(&def),
            def,
        }
    }
    fn opns_from<T: CertifiedScalar>(def: &SphereDef) -> Quadvector<T> {
        match def {
            SphereDef::Points([a, b, c, d]) => embed::<T>(a)
                .wedge(&embed::<T>(b))
                .wedge(&embed::<T>(c))
                .wedge(&embed::<T>(d)),
            _ => Sphere::ipns_from::<T>(def).undual(),
        }
    }
    fn ipns_from<T: CertifiedScalar>(def: &SphereDef) -> Vector<T> {
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
    pub(crate) fn ipns_in<T: CertifiedScalar>(&self) -> Vector<T> {
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
                s.scalar_product(&s).certain_sign()
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
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn side(&self, x: &Point3<f64>) -> Ordering {
        if !x.iter().all(|c| c.is_finite()) {
            return Ordering::Less;
        }
        fn side_in<T: CertifiedScalar>(s: &Vector<T>, x: &Point3<f64>) -> Option<Ordering> {
            let v = embed::<T>(x).scalar_product(s);
            let w = -s.scalar_product(&n_inf::<T>());
            let (a, b) = (v.certain_sign()?, w.certain_sign()?);
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
        on_inner_vector(self, x)
    }
}

impl From<crate::shape::Sphere> for Sphere {
    /// The conformal sphere of a bounded sphere's centre and radius, exactly (radius 0: the
    /// point sphere). [`crate::shape::Sphere`] is the surface as a shape of the pair queries;
    /// this type is its conformal blade, with meets and versors.
    ///
    /// ```
    /// use cga_collide::{conformal, nalgebra::Point3, Sphere};
    /// let s = Sphere::new(Point3::new(1.0, 2.0, 3.0), 0.5)?;
    /// let c = conformal::Sphere::from(s);
    /// assert_eq!((c.centre(), c.radius()), (Point3::new(1.0, 2.0, 3.0), Some(0.5)));
    /// assert_eq!(Sphere::try_from(c)?, s);
    /// // An imaginary sphere has no surface.
    /// let i = conformal::Sphere::from_centre_squared_radius(Point3::origin(), -1.0)?;
    /// assert!(Sphere::try_from(i).is_err());
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    fn from(s: crate::shape::Sphere) -> Sphere {
        Sphere::build(SphereDef::CentreRadius(*s.centre(), s.radius()))
    }
}

impl TryFrom<Sphere> for crate::shape::Sphere {
    type Error = Error;
    /// The bounded sphere (surface) with the conformal sphere's centre and radius: the same
    /// numbers for a sphere built from a centre and radius (so the round trip from
    /// [`crate::shape::Sphere`] is exact), their `f64` roundings for one built from points, a
    /// squared radius or a blade. Fails with [`Error::Degenerate`] for an imaginary sphere
    /// (negative squared radius) and when the centre or radius does not fit in `f64`.
    fn try_from(s: Sphere) -> Result<Self, Error> {
        const C: &str = "shape::Sphere::try_from(conformal::Sphere)";
        let radius = s.radius().ok_or_else(|| {
            degenerate(
                C,
                "the conformal sphere is imaginary (negative squared radius)",
            )
        })?;
        let centre = s.centre();
        if !(radius.is_finite() && centre.iter().all(|x| x.is_finite())) {
            return Err(degenerate(C, "the centre or radius is not finite in f64"));
        }
        crate::shape::Sphere::new(centre, radius)
    }
}

impl InnerVector for Sphere {
    fn inner_vector<T: CertifiedScalar>(&self) -> Vector<T> {
        self.ipns_in()
    }
}
