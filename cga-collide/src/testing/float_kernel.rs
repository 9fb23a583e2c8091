//! The exact algorithms with plain `f64` signs: [`FloatKernel`] evaluates the crate's
//! predicates on `f64` and believes the result (no error bound, no exact fall-back). It is the
//! "no exact fall-back" variant the tests and the papers' tables use to measure what rounding
//! costs; run it through [`IntersectsWith`](super::IntersectsWith).

use core::cmp::Ordering;

use crate::exact::kernel::largest_component;
use crate::exact::vector::{cross, sub};
use crate::exact::{Kernel, PlaneSide, Predicate};

/// Plain `f64` signs without error bound or fall-back (wrong near zero; for comparison only).
#[derive(Debug, Clone, Copy, Default)]
pub struct FloatKernel;

impl Kernel for FloatKernel {
    type Plane = FloatPlane;
    #[inline]
    fn sign<P: Predicate<N>, const N: usize>(x: &[f64; N]) -> Ordering {
        P::eval(x).partial_cmp(&0.0).unwrap_or(Ordering::Equal)
    }
    #[inline]
    fn plane(p: &[[f64; 3]; 3]) -> FloatPlane {
        let u = sub(&p[1], &p[0]);
        let v = sub(&p[2], &p[0]);
        FloatPlane {
            p: *p,
            n: cross(&u, &v),
        }
    }
}

#[inline(always)]
fn sign_of(x: f64) -> Ordering {
    x.partial_cmp(&0.0).unwrap_or(Ordering::Equal)
}

/// A triangle's plane in plain `f64` ([`FloatKernel`]).
#[derive(Debug, Clone, Copy)]
pub struct FloatPlane {
    p: [[f64; 3]; 3],
    n: [f64; 3],
}

impl PlaneSide for FloatPlane {
    #[inline]
    fn side(&self, q: &[f64; 3]) -> Ordering {
        let w = sub(q, &self.p[0]);
        sign_of(w[0] * self.n[0] + w[1] * self.n[1] + w[2] * self.n[2])
    }
    #[inline]
    fn sides(&self, other: &Self) -> [Ordering; 3] {
        self.sides_of(&other.p)
    }
    #[inline]
    fn sides_of(&self, q: &[[f64; 3]; 3]) -> [Ordering; 3] {
        [self.side(&q[0]), self.side(&q[1]), self.side(&q[2])]
    }
    fn is_degenerate(&self) -> bool {
        self.n == [0.0; 3]
    }
    fn projection_axis(&self) -> Option<usize> {
        let k = largest_component(&self.n);
        (self.n[k] != 0.0).then_some(k)
    }
}
