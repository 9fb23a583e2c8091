//! Polynomials with exact rational coefficients over numbered atoms (input coefficients and the
//! temporaries of the generated code): the symbolic values the expression compiler computes
//! with. Like terms are merged as they are added, so every exact cancellation (`a b - b a`,
//! `n∞² = 0` written out in an orthogonal basis) leaves no term behind.

use std::collections::BTreeMap;

use num_bigint::BigInt;
use num_rational::BigRational;
use num_traits::{One, Signed, Zero};

/// An exact rational constant.
pub type Q = BigRational;
/// The number of an atom in the [`Program`](super::program::Program).
pub type Atom = u32;
/// A product of atoms, sorted (an atom may repeat).
pub type Monomial = Vec<Atom>;

/// `Σ c · monomial`, no zero coefficient stored.
#[derive(Clone, PartialEq, Eq, Hash, Debug, Default)]
pub struct Poly(pub BTreeMap<Monomial, Q>);

pub fn int(n: i64) -> Q {
    Q::from_integer(BigInt::from(n))
}

impl Poly {
    pub fn zero() -> Self {
        Poly(BTreeMap::new())
    }

    pub fn constant(c: Q) -> Self {
        let mut p = Poly::zero();
        if !c.is_zero() {
            p.0.insert(Vec::new(), c);
        }
        p
    }

    pub fn atom(a: Atom) -> Self {
        let mut p = Poly::zero();
        p.0.insert(vec![a], Q::one());
        p
    }

    pub fn is_zero(&self) -> bool {
        self.0.is_empty()
    }

    /// The value when the polynomial is a constant (zero included).
    pub fn as_constant(&self) -> Option<Q> {
        match self.0.len() {
            0 => Some(Q::zero()),
            1 => self.0.get(&Vec::new()).cloned(),
            _ => None,
        }
    }

    /// `self += c · other`.
    pub fn add_scaled(&mut self, other: &Poly, c: &Q) {
        if c.is_zero() {
            return;
        }
        for (m, k) in &other.0 {
            let sum = self.0.get(m).cloned().unwrap_or_else(Q::zero) + k * c;
            if sum.is_zero() {
                self.0.remove(m);
            } else {
                self.0.insert(m.clone(), sum);
            }
        }
    }

    pub fn scale(&self, c: &Q) -> Poly {
        let mut p = Poly::zero();
        p.add_scaled(self, c);
        p
    }

    pub fn mul(&self, other: &Poly) -> Poly {
        let mut out = Poly::zero();
        for (ma, ca) in &self.0 {
            for (mb, cb) in &other.0 {
                let mut m = ma.clone();
                m.extend_from_slice(mb);
                m.sort_unstable();
                let mut term = Poly::zero();
                term.0.insert(m, ca * cb);
                out.add_scaled(&term, &Q::one());
            }
        }
        out
    }

    /// Whether the leading coefficient is negative (for sharing `p` and `-p`).
    pub fn leads_negative(&self) -> bool {
        self.0.values().next().is_some_and(Signed::is_negative)
    }

    /// Every atom the polynomial reads.
    pub fn atoms(&self) -> impl Iterator<Item = Atom> + '_ {
        self.0.keys().flatten().copied()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn like_terms_cancel() {
        let (a, b) = (Poly::atom(0), Poly::atom(1));
        let mut p = a.mul(&b);
        p.add_scaled(&b.mul(&a), &int(-1));
        assert!(p.is_zero());
    }

    #[test]
    fn constants_fold() {
        let half = Poly::constant(Q::new(1.into(), 2.into()));
        assert_eq!(
            half.mul(&Poly::constant(int(4))).as_constant(),
            Some(int(2))
        );
        assert_eq!(Poly::atom(3).as_constant(), None);
    }
}
