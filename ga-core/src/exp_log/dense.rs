//! `exp` and `log` on the dense `Multivector` types.

use super::center;
use crate::scalar::Elementary;

/// How many Taylor terms after scaling to `‖X‖₁ ≤ ½`: the tail is below `½¹⁹/19! ≈ 2·10⁻²³`.
const TAYLOR_TERMS: i64 = 18;

macro_rules! dense_exp_log {
    ($module:ident, $even:ident, $odd:ident, $name:literal) => {
        impl<T: Elementary> crate::$module::Multivector<T> {
            #[doc = concat!("`exp(A) = Σ Aᵏ/k!` of any multivector of `", $name, "`, by scaling and squaring:")]
            /// `A` is halved `k` times until the sum of the absolute values of its coefficients
            /// (an upper bound of the norm of left multiplication) is at most `½`, the Taylor
            /// series is summed to 18 terms (Horner), and the result squared `k` times.
            ///
            /// Meant for floats; for versors prefer the closed forms on the sparse types, which
            /// are faster and more accurate. Over rationals the answer is a rational
            /// approximation, exact when `A` is nilpotent of order 2 (`A² = 0`, e.g. a null
            /// bivector). Non-finite coefficients give non-finite results.
            pub fn exp(&self) -> Self {
                let norm = self
                    .coefficients()
                    .iter()
                    .fold(T::zero(), |acc, x| acc + x.abs());
                let half = T::one() / T::from_i64(2);
                let mut x = self.clone();
                let mut k = 0u32;
                let mut bound = norm.to_f64();
                // Halving is exact; at most ~1100 halvings for finite f64 input.
                while bound > 0.5 && bound.is_finite() {
                    x = x.scale(&half);
                    bound *= 0.5;
                    k += 1;
                }
                let mut one = Self::zero();
                one.s = T::one();
                let mut e = one.clone();
                for j in (1..=TAYLOR_TERMS).rev() {
                    let term = (x.clone() * e).scale(&(T::one() / T::from_i64(j)));
                    e = one.clone() + term;
                }
                for _ in 0..k {
                    e = e.clone() * e;
                }
                e
            }

            #[doc = concat!("The principal logarithm of an even versor of `", $name, "` (see")]
            #[doc = concat!("[`", stringify!($even), "::log`](crate::", stringify!($module), "::", stringify!($even), "::log)),")]
            /// as a multivector (a bivector). `None` when the odd part is not negligible
            /// (odd versors have no logarithm) and wherever the closed form is `None`.
            pub fn log(&self) -> Option<Self> {
                let even = crate::$module::$even::from_multivector(self);
                let odd = crate::$module::$odd::from_multivector(self);
                let size = |c: &[T]| c.iter().fold(T::zero(), |a, x| a + x.abs());
                let total = size(&self.coefficients());
                let odd_size = size(&crate::$module::Multivector::from(odd).coefficients());
                if !center::negligible(&odd_size, &total) {
                    return None;
                }
                even.log().map(Self::from)
            }
        }
    };
}

dense_exp_log!(cga, Even, Odd, "Cl(4,1)");
dense_exp_log!(vga3, Rotor, Odd, "Cl(3,0)");
dense_exp_log!(pga3, Motor, Odd, "Cl(3,0,1)");
