//! The checked inverse behind `inverse()` of every generated multivector type.
//!
//! A generated type names its blades by bitmask (bit `i` is generator `i`, as in
//! [`reference`](crate::reference)); [`inverse`] takes the algebra's signature, those masks and
//! the coefficients, and returns the coefficients of the inverse on the same blades, or `None`.
//!
//! # What "never wrong" means
//!
//! A candidate `y` is returned only after checking it: both `x y − 1` and `y x − 1` are computed
//! (by run-time blade products, independently of the generated code) and every coefficient `r`
//! of both must satisfy
//!
//! ```text
//! |r| ≤ INVERSE_TOLERANCE · m · u · ‖x‖₁ · ‖y‖₁
//! ```
//!
//! where `m` is the number of blades of the type, `u` is [`Field::unit_roundoff`] and `‖·‖₁` is
//! the sum of the absolute values of the coefficients (`|r|` is [`Field::pivot_score`]).
//!
//! * For exact scalars (`u = 0`) this is exact equality: `Some(y)` means `x y = y x = 1`, and
//!   `None` means that `x` has no inverse, or (for a type that is not closed under the geometric
//!   product, such as grades 0 and 2 in five dimensions) that its inverse has blades outside the
//!   type: convert to a type holding them (the dense type) to get it.
//! * For floating point, `m u ‖x‖₁ ‖y‖₁` bounds the rounding error of computing a coefficient
//!   of `x y` itself, so no tighter check is meaningful: `Some(y)` means that `y` is an inverse
//!   of `x` to working accuracy (a small *backward* error; for an ill-conditioned `x` the
//!   relative error of `y` can be as large as `‖x‖ ‖y‖` times that). `None` also covers
//!   non-finite input and candidates that fail the check (nearly singular `x`).
//!
//! # How the candidate is found
//!
//! First the versor formula `x̃ / ⟨x x̃⟩₀` (cheap, and right for every versor). When every element
//! of the type is a blade (one grade `k` with `k ≤ 1` or `k ≥ n − 1`, or a single blade) it is
//! the only candidate: `x x̃` is then a scalar, so the formula is the inverse whenever one
//! exists. Otherwise, if it fails the check, `x y = 1` is solved by Gaussian elimination
//! ([`solve`]) in the smallest subalgebra spanned by the type's blades, which holds the inverse
//! of every invertible element of the type; the solution is projected onto the type and checked.

use crate::linalg::solve_columns;
use crate::reference::{blade_product, grade_of, reverse_sign};
use crate::scalar::Field;

/// The safety factor of the acceptance test (see the [module documentation](self)): covers the
/// rounding of the candidate itself as well as of the check's products.
pub const INVERSE_TOLERANCE: f64 = 8.0;

/// The inverse of `Σ x[i] e_{masks[i]}` in the algebra with this signature, on the same blades;
/// `None` when it has none (or, for floats, when no candidate passes the check). See the
/// [module documentation](self) for the guarantee.
///
/// ```
/// use ga_core::inverse::inverse;
/// // In Cl(2,0), 1 + 2 e12 has the inverse (1 - 2 e12) / 5 ...
/// let y = inverse(&[1, 1], &[0b00, 0b11], &[1.0f64, 2.0]).unwrap();
/// assert!((y[0] - 0.2).abs() < 1e-15 && (y[1] + 0.4).abs() < 1e-15);
/// // ... and 1 + e1 has none: (1 + e1)(1 - e1) = 1 - e1² = 0.
/// assert_eq!(inverse(&[1, 1], &[0b00, 0b01], &[1.0, 1.0]), None);
/// ```
pub fn inverse<T: Field>(signature: &[i8], masks: &[u32], x: &[T]) -> Option<Vec<T>> {
    if x.len() != masks.len() {
        return None;
    }
    if let Some(y) = versor_formula(signature, masks, x) {
        if is_inverse(signature, masks, x, &y) {
            return Some(y);
        }
    }
    if holds_only_blades(signature.len(), masks) {
        return None;
    }
    let span = subalgebra(masks);
    let solution = solve(signature, masks, x, &span)?;
    let y: Vec<T> = masks
        .iter()
        .map(|m| {
            span.iter()
                .position(|s| s == m)
                .map_or_else(T::zero, |k| solution[k].clone())
        })
        .collect();
    is_inverse(signature, masks, x, &y).then_some(y)
}

/// Solves `x y = 1` for `y` on the blades `span` (which must contain the scalar blade `0` and be
/// closed under the product of blades, e.g. [`subalgebra`]); `None` when `x` is singular there
/// (for floats: when a pivot is exactly zero). Unchecked: [`inverse`] checks the result.
pub fn solve<T: Field>(signature: &[i8], masks: &[u32], x: &[T], span: &[u32]) -> Option<Vec<T>> {
    let row_of = |mask: u32| span.iter().position(|&s| s == mask);
    // Column j is x e_{span[j]}.
    let mut columns = vec![vec![T::zero(); span.len()]; span.len()];
    for (j, &b) in span.iter().enumerate() {
        for (&a, xa) in masks.iter().zip(x) {
            if xa.is_zero() {
                continue;
            }
            let (sign, out) = blade_product(signature, a as usize, b as usize);
            let Some(row) = row_of(out as u32) else {
                return None; // `span` is not closed: not a subalgebra
            };
            let entry = core::mem::replace(&mut columns[j][row], T::zero());
            columns[j][row] = match sign {
                1 => entry + xa.clone(),
                -1 => entry - xa.clone(),
                _ => entry,
            };
        }
    }
    solve_columns(&columns, row_of(0)?)
}

/// The blades of the smallest subalgebra holding the given blades: every product of them, i.e.
/// the masks spanned under `xor`, the scalar blade `0` first.
pub fn subalgebra(masks: &[u32]) -> Vec<u32> {
    let mut span = vec![0u32];
    for &m in masks {
        if span.contains(&m) {
            continue;
        }
        let more: Vec<u32> = span.iter().map(|s| s ^ m).collect();
        span.extend(more);
    }
    span
}

/// Whether every element with these blades is a blade (a product of orthogonal vectors), so
/// that `x x̃` is a scalar: a single blade, or one grade `k` with `k ≤ 1` or `k ≥ n − 1`.
pub fn holds_only_blades(n: usize, masks: &[u32]) -> bool {
    let Some(&first) = masks.first() else {
        return true;
    };
    let k = grade_of(first as usize);
    masks.len() == 1 || (masks.iter().all(|&m| grade_of(m as usize) == k) && (k <= 1 || k + 1 >= n))
}

/// `x̃ / ⟨x x̃⟩₀`, or `None` when `⟨x x̃⟩₀` is zero.
fn versor_formula<T: Field>(signature: &[i8], masks: &[u32], x: &[T]) -> Option<Vec<T>> {
    let reverse = |m: u32| reverse_sign(grade_of(m as usize));
    let mut norm = T::zero();
    for (&m, c) in masks.iter().zip(x) {
        let (square, _) = blade_product(signature, m as usize, m as usize);
        norm = match square * reverse(m) {
            1 => norm + c.clone() * c.clone(),
            -1 => norm - c.clone() * c.clone(),
            _ => norm,
        };
    }
    let r = norm.checked_recip()?;
    Some(
        masks
            .iter()
            .zip(x)
            .map(|(&m, c)| {
                let c = c.clone() * r.clone();
                if reverse(m) < 0 {
                    -c
                } else {
                    c
                }
            })
            .collect(),
    )
}

/// The acceptance test of the [module documentation](self), on both sides.
fn is_inverse<T: Field>(signature: &[i8], masks: &[u32], x: &[T], y: &[T]) -> bool {
    let norm = |v: &[T]| v.iter().map(Field::pivot_score).sum::<f64>();
    let tolerance = INVERSE_TOLERANCE * masks.len() as f64 * T::unit_roundoff() * norm(x) * norm(y);
    if !tolerance.is_finite() {
        return false;
    }
    let close_to_one = |product: Vec<T>| {
        product.into_iter().enumerate().all(|(mask, c)| {
            let r = if mask == 0 { c - T::one() } else { c };
            // Written so that a NaN residual fails.
            r.pivot_score() <= tolerance
        })
    };
    close_to_one(product(signature, masks, x, y)) && close_to_one(product(signature, masks, y, x))
}

/// `a b` for two elements on the same blades, indexed by blade mask.
fn product<T: Field>(signature: &[i8], masks: &[u32], a: &[T], b: &[T]) -> Vec<T> {
    let mut out = vec![T::zero(); 1 << signature.len()];
    for (&ma, ca) in masks.iter().zip(a) {
        if ca.is_zero() {
            continue;
        }
        for (&mb, cb) in masks.iter().zip(b) {
            if cb.is_zero() {
                continue;
            }
            let (sign, m) = blade_product(signature, ma as usize, mb as usize);
            let t = ca.clone() * cb.clone();
            let old = core::mem::replace(&mut out[m], T::zero());
            out[m] = match sign {
                1 => old + t,
                -1 => old - t,
                _ => old,
            };
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scalar::Rational;

    fn r(n: i64, d: i64) -> Rational {
        Rational::new(n.into(), d.into())
    }

    #[test]
    fn subalgebra_of_bivectors_is_the_even_part() {
        let mut s = subalgebra(&[0b011, 0b101, 0b110]);
        s.sort_unstable();
        assert_eq!(s, vec![0, 0b011, 0b101, 0b110]);
        assert_eq!(subalgebra(&[0b1]).len(), 2);
    }

    #[test]
    fn blade_only_types() {
        assert!(holds_only_blades(5, &[1, 2, 4, 8, 16]));
        assert!(holds_only_blades(4, &[0b0111, 0b1011]));
        assert!(holds_only_blades(5, &[0b00011]));
        assert!(!holds_only_blades(4, &[0b0011, 0b1100]));
        assert!(!holds_only_blades(3, &[0, 0b011]));
    }

    #[test]
    fn a_non_versor_gets_its_true_inverse() {
        // In Cl(4,0), x = 1 + e12 + e34 is not a versor: x x̃ has a grade-4 part, so the
        // versor formula is wrong; the inverse is found by elimination.
        let sig = [1, 1, 1, 1];
        let masks = [0b0000, 0b0011, 0b1100, 0b1111];
        let x = [r(1, 1), r(1, 1), r(1, 1), r(0, 1)];
        let y = inverse(&sig, &masks, &x).unwrap();
        let xy = product(&sig, &masks, &x, &y);
        assert_eq!(xy[0], r(1, 1));
        assert!(xy[1..].iter().all(|c| *c == r(0, 1)));
        // Projected onto grades 0 and 2 only, the inverse has an e1234 part: no inverse there.
        assert_eq!(inverse(&sig, &masks[..3], &x[..3]), None);
    }

    #[test]
    fn zero_divisors_and_non_finite_input_have_none() {
        // (1 + e1)(1 - e1) = 0 in Cl(1).
        assert_eq!(inverse(&[1], &[0, 1], &[r(1, 1), r(1, 1)]), None);
        assert_eq!(inverse(&[1], &[0, 1], &[1.0, f64::NAN]), None);
        assert_eq!(inverse(&[1], &[0, 1], &[f64::INFINITY, 0.0]), None);
        // A null vector of Cl(1,1).
        assert_eq!(inverse(&[1, -1], &[1, 2], &[2.0, 2.0]), None);
        assert_eq!(inverse(&[1, 1], &[0, 1], &[0.0, 0.0]), None);
    }
}
