//! Cl(3,0): rotors.
//!
//! A bivector `B` of Euclidean 3-space is always a blade with `B² = -|B|²`, so
//! `exp(B) = cos|B| + B sin|B|/|B|`: the rotor of the rotation by `2|B|` in the plane of `B`.

use super::center::{self, Kind, Z};
use crate::scalar::Elementary;
use crate::vga3::{Bivector, Rotor};

impl<T: Elementary> Bivector<T> {
    /// `exp(B) = cos|B| + B sin|B|/|B|`, a unit rotor (exactly `1` for `B = 0`).
    ///
    /// `R = exp(-θ/2 · e12)` rotates by `θ` from `e1` towards `e2` under `R x R̃`.
    ///
    /// ```
    /// use ga_core::prelude::*;
    /// use ga_core::vga3::{Bivector, Vector};
    /// let r = Bivector::new(-std::f64::consts::FRAC_PI_4, 0.0, 0.0).exp(); // 90° in e12
    /// let v = r.sandwich_unit(&Vector::new(1.0, 0.0, 0.0));
    /// assert!(approx::abs_diff_eq!(v, Vector::new(0.0, 1.0, 0.0), epsilon = 1e-15));
    /// ```
    pub fn exp(&self) -> Rotor<T> {
        let x = self.norm_squared_signed();
        let (c, s) = center::exp_parts(Kind::Split, &Z::new(x, T::zero()));
        Rotor::new(
            c.a,
            self.e12.clone() * s.a.clone(),
            self.e13.clone() * s.a.clone(),
            self.e23.clone() * s.a,
        )
    }

    /// `B² = -(b12² + b13² + b23²)`.
    fn norm_squared_signed(&self) -> T {
        -(self.e12.clone() * self.e12.clone()
            + self.e13.clone() * self.e13.clone()
            + self.e23.clone() * self.e23.clone())
    }
}

impl<T: Elementary> Rotor<T> {
    /// The bivector part.
    fn bivector(&self) -> Bivector<T> {
        Bivector::new(self.e12.clone(), self.e13.clone(), self.e23.clone())
    }

    /// The principal logarithm: the bivector `B` with `exp(B) = R / |R|` and `|B| < π`
    /// (a rotation angle `2|B|` in `[0, 2π)`), where `|R|² = R R̃ > 0`.
    ///
    /// The scale of `R` is dropped (`log(λR) = log(R)` for `λ > 0`). `None` when `R` is zero
    /// or not finite, and on the branch cut `R / |R| = -1` (a rotation by 2π, whose plane is
    /// not determined). Near the cut the answer is ill-conditioned (the plane is the direction
    /// of a tiny bivector part).
    ///
    /// ```
    /// use ga_core::vga3::Bivector;
    /// let b = Bivector::new(0.3, -0.2, 1.1);
    /// let back = b.exp().log().unwrap();
    /// assert!(approx::abs_diff_eq!(back, b, epsilon = 1e-15));
    /// ```
    pub fn log(&self) -> Option<Bivector<T>> {
        let (c, w) = self.normalized_parts()?;
        let f = center::log_factor(
            Kind::Split,
            &Z::new(c, T::zero()),
            &Z::new(w.norm_squared_signed(), T::zero()),
        )?;
        Some(w.scale(&f.a))
    }

    /// The principal square root: the rotor `Q` with `Q² = R` of half the rotation angle,
    /// `√|R| (1 + R/|R|) / |1 + R/|R||`. `None` when `R` is zero or not finite, and for
    /// `R / |R| = -1` (a rotation by 2π: its square roots are the rotations by π in every
    /// plane). Exact over rationals when the norms involved are squares of rationals.
    ///
    /// ```
    /// use ga_core::vga3::Bivector;
    /// let r = Bivector::new(0.3, -0.2, 1.1).exp();
    /// let q = r.sqrt().unwrap();
    /// assert!(approx::abs_diff_eq!(q * q, r, epsilon = 1e-15));
    /// ```
    pub fn sqrt(&self) -> Option<Rotor<T>> {
        let n = self.norm_squared();
        let lambda = n.sqrt();
        let (c, w) = self.normalized_parts()?;
        // 1 + R̂ = Q N with N = Q + Q̃ = 2⟨Q⟩₀ and N² = 2(1 + ⟨R̂⟩₀).
        let n2 = T::from_i64(2) * (T::one() + c.clone());
        let nz = center::sqrt(Kind::Split, &Z::new(n2, T::zero()))?;
        let k = lambda.sqrt() / nz.a;
        Some(Rotor::new(
            (T::one() + c) * k.clone(),
            w.e12 * k.clone(),
            w.e13 * k.clone(),
            w.e23 * k,
        ))
    }

    /// `R / |R|` split into its scalar and bivector parts, `None` unless `R R̃` is positive
    /// and finite.
    fn normalized_parts(&self) -> Option<(T, Bivector<T>)> {
        let n = self.norm_squared();
        if n <= T::zero() || !n.is_finite() {
            return None;
        }
        let inv = T::one() / n.sqrt();
        Some((self.s.clone() * inv.clone(), self.bivector().scale(&inv)))
    }
}
