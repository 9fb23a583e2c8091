//! The generated products do exactly one multiplication per nonzero term: counted with a scalar
//! type that counts its multiplications.

use std::cell::Cell;
use std::ops::{Add, Mul, Neg, Sub};

use ga_core::cga::{Bivector, Rotor, Trivector, Vector};
use ga_core::prelude::*;

thread_local! {
    static MULTIPLICATIONS: Cell<usize> = const { Cell::new(0) };
}

#[derive(Clone, Copy, PartialEq, Debug)]
struct Counted(f64);

impl Add for Counted {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Counted(self.0 + o.0)
    }
}
impl Sub for Counted {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Counted(self.0 - o.0)
    }
}
impl Mul for Counted {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        MULTIPLICATIONS.with(|m| m.set(m.get().wrapping_add(1)));
        Counted(self.0 * o.0)
    }
}
impl Neg for Counted {
    type Output = Self;
    fn neg(self) -> Self {
        Counted(-self.0)
    }
}
impl Ring for Counted {
    fn zero() -> Self {
        Counted(0.0)
    }
    fn one() -> Self {
        Counted(1.0)
    }
    fn from_i64(n: i64) -> Self {
        Counted(n as f64)
    }
    fn is_zero(&self) -> bool {
        self.0 == 0.0
    }
}

fn count<R>(f: impl FnOnce() -> R) -> usize {
    MULTIPLICATIONS.with(|m| m.set(0));
    let _ = f();
    MULTIPLICATIONS.with(|m| m.get())
}

fn vector() -> Vector<Counted> {
    Vector::new(
        Counted(1.0),
        Counted(2.0),
        Counted(3.0),
        Counted(4.0),
        Counted(5.0),
    )
}

#[test]
fn products_multiply_once_per_nonzero_term() {
    let v = vector();
    let b = Bivector::from_multivector(
        &(v * Vector::new(
            Counted(0.5),
            Counted(-1.0),
            Counted(2.0),
            Counted(0.0),
            Counted(1.0),
        ))
        .into(),
    );
    let t: Trivector<Counted> = b ^ v;
    // 5 x 5 blade pairs, all nonzero in Cl(4,1).
    assert_eq!(count(|| v * v), 25);
    // 10 x 5 blade pairs, all nonzero.
    assert_eq!(count(|| b * v), 50);
    // Each of the 10 trivector blades wedges with the 2 generators it lacks.
    assert_eq!(count(|| t ^ v), 20);
    // Vector | vector: the 5 diagonal terms.
    assert_eq!(count(|| v | v), 5);
    // Rotor (11 blades) sandwich of a vector: 11 x 5 for R X, then 11 terms per output blade.
    let r = Rotor::from_multivector(&(v * v + b).into());
    assert_eq!(count(|| r.sandwich_unit(&v)), 55 + 55);
}
