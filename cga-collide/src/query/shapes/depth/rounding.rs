//! Rounding an exactly known signed distance to `f64` once, with a proved bound.
//!
//! Every value here is `±√q − R` for an exact rational `q ≥ 0` (a squared distance, a squared
//! depth or a squared support gap) and radii `R = r_a + r_b` given as `f64`. `√q` is usually
//! irrational, so it is rounded; the bound charges every rounding step (the conversion of a
//! rational to `f64` is within one unit in the last place, each `f64` operation within half
//! of one), with a safety factor of two. Near contact (`+√q − R` close to 0) the difference
//! is formed exactly first, `(q − R²)/(√q + R)`, so a one-ulp overlap gets its tiny depth to
//! a few ulps of itself rather than a few ulps of `R`.

use ga_core::scalar::{rational_from_f64, Rational, Real, Ring};
use num_traits::Signed;

use super::SignedDistanceKind;
use crate::exact::ErrF64;

const EPS: f64 = f64::EPSILON;
/// `2^-536`: a bound on `√x` for every subnormal `x` (the conversion of a tiny rational may
/// lose all relative accuracy below `f64::MIN_POSITIVE`).
const TINY_ROOT: f64 = 2.2227587494850775e-162;
/// The smallest positive subnormal `f64`.
const TINY: f64 = f64::from_bits(1);

/// `√q` rounded, with its bound.
fn root(q: &Rational) -> (f64, f64) {
    let x = Real::to_f64(q).max(0.0);
    let t = x.sqrt();
    let mut e = 2.0 * EPS * t;
    if x < f64::MIN_POSITIVE {
        e += TINY_ROOT;
    }
    (t, e)
}

/// `(√q if outward else −√q) − r_a − r_b` rounded once, with a proved error bound and the
/// kind the exact value has (negative: penetrating, zero: touching, positive: separated).
pub(super) fn signed_root_minus(
    outward: bool,
    q: &Rational,
    radii: [f64; 2],
) -> (f64, f64, SignedDistanceKind) {
    let zero = <Rational as Ring>::zero();
    let (t, et) = root(q);
    let [ra, rb] = radii;
    if !outward || q.is_zero() {
        if q.is_zero() && ra == 0.0 && rb == 0.0 {
            return (0.0, 0.0, SignedDistanceKind::Touching);
        }
        let v = ErrF64 {
            value: -t,
            error: et,
        } - ErrF64::exact(ra)
            - ErrF64::exact(rb);
        let bound = (v.error * (1.0 + 1e-9)).next_up();
        return (v.value, bound, SignedDistanceKind::Penetrating);
    }
    // Outward: the exact difference q − R² decides the kind and carries the small value.
    let r = rational_from_f64(ra).unwrap_or_else(|| zero.clone())
        + rational_from_f64(rb).unwrap_or_else(|| zero.clone());
    let x = q - &r * &r;
    if x.is_zero() {
        return (0.0, 0.0, SignedDistanceKind::Touching);
    }
    let kind = if x.is_positive() {
        SignedDistanceKind::Separated
    } else {
        SignedDistanceKind::Penetrating
    };
    if ra == 0.0 && rb == 0.0 {
        return (t, et, kind);
    }
    let den = t + ra + rb;
    let v = Real::to_f64(&x) / den;
    let e = 8.0 * EPS * v.abs() + 4.0 * TINY / den;
    (v, e.next_up(), kind)
}

/// A value of the proved bracket `[lo, hi]` (its midpoint) and a bound on its distance from
/// every value in the bracket; an exact value (`lo == hi`) is itself, with bound `0`.
pub(super) fn midpoint(lo: f64, hi: f64) -> (f64, f64) {
    if lo == hi {
        return (lo, 0.0);
    }
    let v = lo * 0.5 + hi * 0.5;
    // The two halves and their sum round; the margin and the last step up pay for it.
    (v, ((hi - v).max(v - lo) * (1.0 + 4.0 * EPS)).next_up())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn q(x: f64) -> Rational {
        rational_from_f64(x).unwrap()
    }

    #[test]
    fn a_one_ulp_overlap_of_radii_keeps_its_tiny_value() {
        // √q = 1, R = 1 + 2^-52: the overlap is 2^-52 exactly.
        let (v, e, kind) = signed_root_minus(true, &q(1.0), [1.0, f64::EPSILON]);
        assert_eq!(kind, SignedDistanceKind::Penetrating);
        assert!((v + f64::EPSILON).abs() <= e, "{v} {e}");
        assert!(e < 1e-30);
    }

    #[test]
    fn exact_contact_is_zero_with_zero_bound() {
        assert_eq!(
            signed_root_minus(true, &q(4.0), [1.0, 1.0]),
            (0.0, 0.0, SignedDistanceKind::Touching)
        );
        assert_eq!(
            signed_root_minus(false, &q(0.0), [0.0, 0.0]),
            (0.0, 0.0, SignedDistanceKind::Touching)
        );
    }

    #[test]
    fn a_midpoint_is_within_its_bound_of_the_bracket() {
        assert_eq!(midpoint(0.0, 0.0), (0.0, 0.0));
        assert_eq!(midpoint(TINY, TINY), (TINY, 0.0));
        for (lo, hi) in [(-1.0, 3.0), (0.1, 0.1f64.next_up()), (-f64::MAX, f64::MAX)] {
            let (v, e) = midpoint(lo, hi);
            assert!(v - e <= lo && hi <= v + e, "{lo} {hi}: {v} ± {e}");
        }
    }

    #[test]
    fn inward_values_add_the_radii() {
        let (v, e, kind) = signed_root_minus(false, &q(4.0), [0.5, 0.25]);
        assert_eq!(kind, SignedDistanceKind::Penetrating);
        assert!((v + 2.75).abs() <= e && e < 1e-14);
    }
}
