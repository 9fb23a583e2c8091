//! [`Iv`]: a closed interval of `f64` bounds that holds an exact real value, with every
//! operation rounded outward (one ulp past the rounded result). The filter's certificates are
//! interval evaluations: a bound that excludes the threshold proves the comparison.
//!
//! Unlike the crate's running-error scalar this closes over square roots and divisions, which
//! the support functions of discs need (`r·|d × u| / |u|`). A NaN anywhere widens to the
//! whole line, so an overflow can only leave a comparison undecided.

/// The interval `[lo, hi]` (possibly infinite; never NaN).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(in crate::query::shapes) struct Iv {
    pub(in crate::query::shapes) lo: f64,
    pub(in crate::query::shapes) hi: f64,
}

/// Three interval coordinates.
pub(in crate::query::shapes) type IvP3 = [Iv; 3];

pub(in crate::query::shapes) const WHOLE: Iv = Iv {
    lo: f64::NEG_INFINITY,
    hi: f64::INFINITY,
};

impl Iv {
    /// The exact value `x`.
    #[inline]
    pub(in crate::query::shapes) const fn point(x: f64) -> Iv {
        Iv { lo: x, hi: x }
    }

    /// Rounded bounds widened by one ulp each way (every rounding to nearest stays inside).
    #[inline]
    fn outward(lo: f64, hi: f64) -> Iv {
        if lo.is_nan() || hi.is_nan() {
            return WHOLE;
        }
        Iv {
            lo: lo.next_down(),
            hi: hi.next_up(),
        }
    }

    #[inline]
    fn is_finite(self) -> bool {
        self.lo.is_finite() && self.hi.is_finite()
    }

    #[inline]
    pub(in crate::query::shapes) fn add(self, o: Iv) -> Iv {
        Iv::outward(self.lo + o.lo, self.hi + o.hi)
    }

    #[inline]
    pub(in crate::query::shapes) fn sub(self, o: Iv) -> Iv {
        Iv::outward(self.lo - o.hi, self.hi - o.lo)
    }

    #[inline]
    pub(in crate::query::shapes) fn neg(self) -> Iv {
        Iv {
            lo: -self.hi,
            hi: -self.lo,
        }
    }

    #[inline]
    pub(in crate::query::shapes) fn mul(self, o: Iv) -> Iv {
        if !self.is_finite() || !o.is_finite() {
            return WHOLE;
        }
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        Iv::outward(
            p[0].min(p[1]).min(p[2]).min(p[3]),
            p[0].max(p[1]).max(p[2]).max(p[3]),
        )
    }

    /// The square (tighter than `mul` when the interval holds zero).
    #[inline]
    pub(in crate::query::shapes) fn sqr(self) -> Iv {
        if !self.is_finite() {
            return WHOLE;
        }
        if self.lo >= 0.0 {
            Iv::outward(self.lo * self.lo, self.hi * self.hi)
        } else if self.hi <= 0.0 {
            Iv::outward(self.hi * self.hi, self.lo * self.lo)
        } else {
            let m = (self.lo * self.lo).max(self.hi * self.hi);
            Iv::outward(0.0, m).max_zero()
        }
    }

    /// `self` with its lower bound raised to `0` (for values known to be `≥ 0`).
    #[inline]
    fn max_zero(self) -> Iv {
        Iv {
            lo: self.lo.max(0.0),
            hi: self.hi,
        }
    }

    /// The square root of the non-negative part (callers pass values that are `≥ 0` exactly).
    #[inline]
    pub(in crate::query::shapes) fn sqrt(self) -> Iv {
        if self.hi.is_nan() || self.lo.is_nan() {
            return WHOLE;
        }
        let lo = if self.lo > 0.0 {
            self.lo.sqrt().next_down().max(0.0)
        } else {
            0.0
        };
        Iv {
            lo,
            hi: self.hi.max(0.0).sqrt().next_up(),
        }
    }

    /// `self / o`; the whole line unless `o` is certainly positive.
    #[inline]
    pub(in crate::query::shapes) fn div_positive(self, o: Iv) -> Iv {
        let positive = o.lo > 0.0;
        if !positive || !self.is_finite() || !o.is_finite() {
            return WHOLE;
        }
        let p = [
            self.lo / o.lo,
            self.lo / o.hi,
            self.hi / o.lo,
            self.hi / o.hi,
        ];
        Iv::outward(
            p[0].min(p[1]).min(p[2]).min(p[3]),
            p[0].max(p[1]).max(p[2]).max(p[3]),
        )
    }

    /// The interval of `max(x, y)`.
    #[inline]
    pub(in crate::query::shapes) fn max(self, o: Iv) -> Iv {
        Iv {
            lo: self.lo.max(o.lo),
            hi: self.hi.max(o.hi),
        }
    }
}

#[inline]
pub(in crate::query::shapes) fn lift(p: &[f64; 3]) -> IvP3 {
    p.map(Iv::point)
}

#[inline]
pub(in crate::query::shapes) fn sub3(a: &IvP3, b: &IvP3) -> IvP3 {
    [a[0].sub(b[0]), a[1].sub(b[1]), a[2].sub(b[2])]
}

#[inline]
pub(in crate::query::shapes) fn dot3(a: &IvP3, b: &IvP3) -> Iv {
    a[0].mul(b[0]).add(a[1].mul(b[1])).add(a[2].mul(b[2]))
}

#[inline]
pub(in crate::query::shapes) fn norm2(a: &IvP3) -> Iv {
    a[0].sqr().add(a[1].sqr()).add(a[2].sqr())
}

/// `|a × b|²`, each component of the cross product squared (so the result is `≥ 0`).
#[inline]
pub(in crate::query::shapes) fn cross_norm2(a: &IvP3, b: &IvP3) -> Iv {
    let x = a[1].mul(b[2]).sub(a[2].mul(b[1]));
    let y = a[2].mul(b[0]).sub(a[0].mul(b[2]));
    let z = a[0].mul(b[1]).sub(a[1].mul(b[0]));
    x.sqr().add(y.sqr()).add(z.sqr())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_hold_the_exact_values() {
        let third = Iv::point(1.0).div_positive(Iv::point(3.0));
        assert!(third.lo < 1.0 / 3.0 + 1e-17 && third.hi > 1.0 / 3.0 - 1e-17);
        assert!(third.mul(Iv::point(3.0)).lo < 1.0 && third.mul(Iv::point(3.0)).hi > 1.0);
        let root = Iv::point(2.0).sqrt();
        assert!(root.sqr().lo < 2.0 && root.sqr().hi > 2.0);
        // 0.1 + 0.2 is not 0.3 in f64; the interval holds the exact sum of the two inputs.
        let s = Iv::point(0.1).add(Iv::point(0.2));
        assert!(s.lo < 0.30000000000000004 && s.hi >= 0.30000000000000004);
        let square = Iv::point(-2.0).sqr();
        assert!(square.lo <= 4.0 && square.hi >= 4.0);
    }

    #[test]
    fn overflow_and_nan_widen_to_the_whole_line() {
        let big = Iv::point(f64::MAX);
        let inf = big.mul(big);
        assert!(inf.hi == f64::INFINITY);
        let nan = inf.sub(inf);
        assert_eq!(nan, WHOLE);
        assert_eq!(nan.mul(Iv::point(0.0)), WHOLE);
        assert_eq!(Iv::point(1.0).div_positive(Iv { lo: 0.0, hi: 1.0 }), WHOLE);
    }
}
