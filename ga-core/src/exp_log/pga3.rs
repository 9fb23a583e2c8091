//! Cl(3,0,1): motors.
//!
//! A bivector `B = E + D` (Euclidean part `E` in `e12 e13 e23`, ideal part `D` in
//! `e01 e02 e03`) squares to `B² = -|E|² + m e0123` with `e0123² = 0`, so `B²` is a dual
//! number and `exp(B) = C(B²) + B S(B²)` is evaluated with first derivatives: a screw motion,
//! a rotation about a line (`m = 0`, `E ≠ 0`) or a translation `1 + D` (`E = 0`, exact over
//! any ring).

use super::center::{self, Kind, Z};
use crate::ops::Geometric;
use crate::pga3::{Bivector, Motor, Pseudoscalar};
use crate::scalar::{Elementary, Ring};

fn bivector_of<T: Ring>(m: &Motor<T>) -> Bivector<T> {
    Bivector::new(
        m.e01.clone(),
        m.e02.clone(),
        m.e03.clone(),
        m.e12.clone(),
        m.e13.clone(),
        m.e23.clone(),
    )
}

/// `(B I)` for a bivector `B` (only the Euclidean part survives, as an ideal bivector).
fn times_i<T: Ring>(b: &Bivector<T>) -> Bivector<T> {
    bivector_of(&Motor::from(b.geometric(&Pseudoscalar::new(T::one()))))
}

/// `(⟨X²⟩₀, ⟨X²⟩₄)` for a bivector `X`.
fn square<T: Ring>(b: &Bivector<T>) -> Z<T> {
    let sq = b.geometric(b);
    Z::new(sq.s, sq.e0123)
}

impl<T: Elementary> Bivector<T> {
    /// `exp(B)`: the unit motor `C(B²) + B S(B²)` (see [`crate::exp_log`]).
    /// `exp(D) = 1 + D` exactly for an ideal (translation) bivector `D`.
    ///
    /// ```
    /// use ga_core::pga3::Bivector;
    /// let b = Bivector::new(0.5, -1.0, 2.0, 0.3, 0.1, -0.4);
    /// let back = b.exp().log().unwrap();
    /// assert!(approx::abs_diff_eq!(back, b, epsilon = 1e-14));
    /// ```
    pub fn exp(&self) -> Motor<T> {
        let (c, s) = center::exp_parts(Kind::Dual, &square(self));
        let sb = self.scale(&s.a) + times_i(self).scale(&s.b);
        Motor::new(c.a, sb.e01, sb.e02, sb.e03, sb.e12, sb.e13, sb.e23, c.b)
    }
}

impl<T: Elementary> Motor<T> {
    /// The principal logarithm: the bivector `B` with `exp(B) = M / |M|`, where
    /// `|M|² = ⟨M M̃⟩₀ > 0` and the rotation part has angle `2|E| < 2π`.
    ///
    /// The scale is dropped. `None` when `M` is not a motor up to rounding (`⟨M M̃⟩₀ ≤ 0`, not
    /// finite, or `⟨M M̃⟩₄` not negligible), and on the branch cut: the rotation part is a
    /// rotation by 2π (`⟨M̂⟩₀ = -1`), whose axis is not determined. A pure translation
    /// `1 + D` has the exact logarithm `D` (no elementary function is called).
    pub fn log(&self) -> Option<Bivector<T>> {
        let (c, w) = self.normalized_parts()?;
        let f = center::log_factor(Kind::Dual, &c, &square(&w))?;
        Some(w.scale(&f.a) + times_i(&w).scale(&f.b))
    }

    /// The principal square root: the motor `Q` with `Q² = M` that moves half as far along
    /// the same screw, `√|M| (1 + M̂) N⁻¹` with `N² = 2(1 + ⟨M̂⟩₀ + ⟨M̂⟩₄)`. `None` where
    /// [`log`](Self::log) is `None` for the branch cut or a non-motor. Exact over rationals for
    /// translations (`√(1 + D) = 1 + D/2`).
    pub fn sqrt(&self) -> Option<Motor<T>> {
        let lambda = self.norm_squared().sqrt();
        let (c, w) = self.normalized_parts()?;
        let two = T::from_i64(2);
        let n2 = Z::new(two.clone() * (T::one() + c.a.clone()), two * c.b.clone());
        let ninv = center::recip(Kind::Dual, &center::sqrt(Kind::Dual, &n2)?)?;
        let one_plus = Motor::new(
            T::one() + c.a,
            w.e01,
            w.e02,
            w.e03,
            w.e12,
            w.e13,
            w.e23,
            c.b,
        );
        let times_i = one_plus.geometric(&Pseudoscalar::new(T::one()));
        let k = lambda.sqrt();
        Some((one_plus.scale(&ninv.a) + times_i.scale(&ninv.b)).scale(&k))
    }

    /// `M / |M|` as `(⟨M̂⟩₀ + ⟨M̂⟩₄, ⟨M̂⟩₂)`, `None` unless `M` is a motor up to rounding.
    fn normalized_parts(&self) -> Option<(Z<T>, Bivector<T>)> {
        let n = self.norm_squared();
        if n <= T::zero() || !n.is_finite() {
            return None;
        }
        // M M̃ = n + m e0123; m = 0 for motors.
        let mm = self.geometric(&self.reverse());
        let scale = n.clone()
            + n.sqrt() * (self.e01.abs() + self.e02.abs() + self.e03.abs() + self.e0123.abs());
        if !center::negligible(&mm.e0123, &scale) {
            return None;
        }
        let inv = T::one() / n.sqrt();
        let c = Z::new(
            self.s.clone() * inv.clone(),
            self.e0123.clone() * inv.clone(),
        );
        Some((c, bivector_of(self).scale(&inv)))
    }
}
