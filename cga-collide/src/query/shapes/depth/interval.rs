//! Closed `f64` intervals with outward rounding: every operation widens its rounded ends by
//! one step (`next_down`, `next_up`), so the exact result of the same operations on any values
//! in the operands lies inside. Used to bound the support functions of cylinders and cones,
//! which hold a square root.

use core::ops::{Add, Mul, Neg, Sub};

/// The interval `[lo, hi]` (an empty or non-finite one means "unknown").
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Iv {
    pub(super) lo: f64,
    pub(super) hi: f64,
}

impl Iv {
    /// The single exact value `x`.
    pub(super) fn point(x: f64) -> Iv {
        Iv { lo: x, hi: x }
    }

    fn rounded(lo: f64, hi: f64) -> Iv {
        Iv {
            lo: lo.next_down(),
            hi: hi.next_up(),
        }
    }

    /// `√x` for the non-negative part of `x`.
    pub(super) fn sqrt(self) -> Iv {
        Iv::rounded(self.lo.max(0.0).sqrt(), self.hi.max(0.0).sqrt())
    }

    /// `self / d` for `d > 0` (an unknown interval when `d` may be zero or negative).
    pub(super) fn div_positive(self, d: Iv) -> Iv {
        if d.lo.is_nan() || d.lo <= 0.0 {
            return Iv {
                lo: f64::NEG_INFINITY,
                hi: f64::INFINITY,
            };
        }
        let lo = if self.lo >= 0.0 {
            self.lo / d.hi
        } else {
            self.lo / d.lo
        };
        let hi = if self.hi >= 0.0 {
            self.hi / d.lo
        } else {
            self.hi / d.hi
        };
        Iv::rounded(lo, hi)
    }

    /// The larger of two values.
    pub(super) fn max(self, o: Iv) -> Iv {
        Iv {
            lo: self.lo.max(o.lo),
            hi: self.hi.max(o.hi),
        }
    }
}

impl Add for Iv {
    type Output = Iv;
    fn add(self, o: Iv) -> Iv {
        Iv::rounded(self.lo + o.lo, self.hi + o.hi)
    }
}

impl Sub for Iv {
    type Output = Iv;
    fn sub(self, o: Iv) -> Iv {
        Iv::rounded(self.lo - o.hi, self.hi - o.lo)
    }
}

impl Neg for Iv {
    type Output = Iv;
    fn neg(self) -> Iv {
        Iv {
            lo: -self.hi,
            hi: -self.lo,
        }
    }
}

impl Mul for Iv {
    type Output = Iv;
    fn mul(self, o: Iv) -> Iv {
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        if p.iter().any(|x| x.is_nan()) {
            return Iv {
                lo: f64::NEG_INFINITY,
                hi: f64::INFINITY,
            };
        }
        let lo = p.iter().copied().fold(f64::INFINITY, f64::min);
        let hi = p.iter().copied().fold(f64::NEG_INFINITY, f64::max);
        Iv::rounded(lo, hi)
    }
}

pub(super) type I3 = [Iv; 3];

pub(super) fn lift(p: &[f64; 3]) -> I3 {
    p.map(Iv::point)
}

pub(super) fn sub3(a: &I3, b: &I3) -> I3 {
    core::array::from_fn(|k| a[k] - b[k])
}

pub(super) fn dot3(a: &I3, b: &I3) -> Iv {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

pub(super) fn cross3(a: &I3, b: &I3) -> I3 {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn operations_contain_the_exact_results() {
        let third = Iv::point(1.0).div_positive(Iv::point(3.0));
        assert!(third.lo < third.hi && third.lo * 3.0 <= 1.0 && third.hi * 3.0 >= 1.0);
        let r = Iv::point(2.0).sqrt();
        assert!(r.lo * r.lo <= 2.0 && r.hi * r.hi >= 2.0);
        let m = Iv { lo: -1.0, hi: 2.0 } * Iv { lo: -3.0, hi: 0.5 };
        assert!(m.lo <= -6.0 && m.hi >= 3.0);
        let unknown = Iv::point(1.0).div_positive(Iv { lo: 0.0, hi: 1.0 });
        assert!(unknown.lo == f64::NEG_INFINITY && unknown.hi == f64::INFINITY);
    }
}
