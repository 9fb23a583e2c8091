//! Exact signs of a few polynomials written once over [`Ring`]: error-bounded `f64` first,
//! then floating-point expansions, then rationals.

use core::cmp::Ordering;

use ga_core::scalar::{rational_from_f64, Rational, Ring};

use crate::exact::{rational_sign, ErrF64, Expansion};

/// `K` polynomials in `f64` inputs, evaluated in any ring from the lifted inputs.
pub(super) trait Polys<const K: usize> {
    fn eval<R: Ring>(&self, lift: &dyn Fn(f64) -> R) -> [R; K];
}

fn all<const K: usize>(signs: [Option<Ordering>; K]) -> Option<[Ordering; K]> {
    let mut out = [Ordering::Equal; K];
    for (o, s) in out.iter_mut().zip(signs) {
        *o = s?;
    }
    Some(out)
}

/// The `f64` filter alone: the signs when every one is certain.
pub(super) fn filtered<P: Polys<K>, const K: usize>(p: &P) -> Option<[Ordering; K]> {
    all(p.eval(&ErrF64::exact).map(|x| x.sign()))
}

/// The exact signs (the expansions, then rationals when they cannot hold a value).
pub(super) fn exact<P: Polys<K>, const K: usize>(p: &P) -> [Ordering; K] {
    if let Some(s) = all(p.eval(&Expansion::from_f64).map(|x| x.sign())) {
        return s;
    }
    let q = |x: f64| rational_from_f64(x).unwrap_or_else(<Rational as Ring>::zero);
    p.eval(&q).map(|r| rational_sign(&r))
}

/// The exact signs, filter first.
pub(super) fn signs<P: Polys<K>, const K: usize>(p: &P) -> [Ordering; K] {
    filtered(p).unwrap_or_else(|| exact(p))
}
