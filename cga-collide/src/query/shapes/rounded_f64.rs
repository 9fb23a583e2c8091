//! Plain-`f64` helpers of the fast paths whose rounding is bounded by hand (the depth's
//! `fast` path and the manifold points' bounds): the unit roundoff, the range of
//! magnitudes in which every rounding is relative, and the vector products they use.

/// A point or vector as three `f64`s.
pub(super) type P3 = [f64; 3];

/// The unit roundoff of `f64`.
pub(super) const U: f64 = f64::EPSILON * 0.5;

/// Every nonzero value within `2^±250`: no product of three of them under- or overflows, so
/// each rounding of such products and their sums is relative.
pub(super) fn tame(xs: &[f64]) -> bool {
    const LOW: f64 = 5.5e-76; // 2^-250
    const HIGH: f64 = 1.8e75; // 2^250
    xs.iter()
        .all(|x| *x == 0.0 || (x.abs() >= LOW && x.abs() <= HIGH))
}

pub(super) fn dot(a: &P3, b: &P3) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(super) fn cross(a: &P3, b: &P3) -> P3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
