//! `Sym`: a `Copy` handle to an exact polynomial, so that generated products can be evaluated
//! symbolically without the compile-time cost of a non-`Copy` scalar.
//!
//! Every arithmetic operation on `Sym` is one out-of-line call that computes the exact
//! [`Poly`] result (integer-exact rational coefficients, canonical form) and stores it in a
//! thread-local arena; a `Sym` is an index into that arena. Instantiating the generated code for
//! `Sym` therefore compiles like instantiating it for `f64` plus one call per operation, whereas
//! `Rational` (or `Poly` itself) inlines big-number arithmetic, clones and drops into every term
//! (tens of CPU-minutes for all Cl(4,1) pairs).
//!
//! [`reset`] empties the arena (between checks, to bound memory). A `Sym` created before a reset
//! is stale: using it panics instead of silently reading a newer polynomial.

use core::fmt;
use core::ops::{Add, Mul, Neg, Sub};
use std::cell::{Cell, RefCell};

use ga_core::scalar::Ring;
use ga_core::symbolic::Poly;

thread_local! {
    static ARENA: RefCell<Vec<Poly>> = const { RefCell::new(Vec::new()) };
    static GENERATION: Cell<u32> = const { Cell::new(0) };
}

/// A handle to an exact polynomial in this thread's arena.
#[derive(Clone, Copy)]
pub struct Sym {
    index: u32,
    generation: u32,
}

/// Empties this thread's arena; every existing `Sym` becomes stale.
pub fn reset() {
    ARENA.with(|a| a.borrow_mut().clear());
    GENERATION.with(|g| g.set(g.get() + 1));
}

/// The number of polynomials stored in this thread's arena.
pub fn arena_len() -> usize {
    ARENA.with(|a| a.borrow().len())
}

#[inline(never)]
fn store(p: Poly) -> Sym {
    let index = ARENA.with(|a| {
        let mut a = a.borrow_mut();
        a.push(p);
        u32::try_from(a.len() - 1).expect("fewer than 2^32 polynomials per check")
    });
    Sym {
        index,
        generation: GENERATION.with(Cell::get),
    }
}

impl Sym {
    /// The variable called `name`.
    pub fn var(name: &str) -> Sym {
        store(Poly::var(name))
    }

    /// Calls `f` on the polynomial (panics if the handle is stale).
    pub fn with<R>(self, f: impl FnOnce(&Poly) -> R) -> R {
        assert_eq!(
            self.generation,
            GENERATION.with(Cell::get),
            "stale Sym used after sym::reset()"
        );
        ARENA.with(|a| f(&a.borrow()[self.index as usize]))
    }

    /// A copy of the polynomial.
    pub fn poly(self) -> Poly {
        self.with(Poly::clone)
    }
}

#[inline(never)]
fn binary(a: Sym, b: Sym, f: fn(&Poly, &Poly) -> Poly) -> Sym {
    let p = a.with(|pa| b.with(|pb| f(pa, pb)));
    store(p)
}

impl Add for Sym {
    type Output = Sym;
    fn add(self, rhs: Sym) -> Sym {
        binary(self, rhs, |a, b| a + b)
    }
}

impl Sub for Sym {
    type Output = Sym;
    fn sub(self, rhs: Sym) -> Sym {
        binary(self, rhs, |a, b| a - b)
    }
}

impl Mul for Sym {
    type Output = Sym;
    fn mul(self, rhs: Sym) -> Sym {
        binary(self, rhs, |a, b| a * b)
    }
}

impl Neg for Sym {
    type Output = Sym;
    #[inline(never)]
    fn neg(self) -> Sym {
        let p = self.with(|p| -p);
        store(p)
    }
}

impl PartialEq for Sym {
    #[inline(never)]
    fn eq(&self, other: &Sym) -> bool {
        self.with(|a| other.with(|b| a == b))
    }
}

impl Ring for Sym {
    fn zero() -> Sym {
        store(<Poly as Ring>::zero())
    }
    fn one() -> Sym {
        store(<Poly as Ring>::one())
    }
    fn from_i64(n: i64) -> Sym {
        store(<Poly as Ring>::from_i64(n))
    }
    #[inline(never)]
    fn is_zero(&self) -> bool {
        self.with(<Poly as Ring>::is_zero)
    }
}

impl fmt::Debug for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.with(|p| write!(f, "{p}"))
    }
}

impl fmt::Display for Sym {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.with(|p| write!(f, "{p}"))
    }
}

impl super::ToRef<Sym> for Sym {
    fn to_ref(&self, sig: &super::Signature) -> super::Dm<Sym> {
        super::Dm::scalar(sig, *self)
    }
}
