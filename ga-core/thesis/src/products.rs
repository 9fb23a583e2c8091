//! The products the checks compute with: the generated `ga_core::cga` code over [`Poly`].
//!
//! Every computed value of the report goes through these functions, so the report checks the
//! generated products; printed formulas are read with [`SymMultivector`]'s own products
//! ([`Own`]), which take their signs from `ga_core::reference`.

use ga_core::cga::Multivector;
use ga_core::prelude::*;
use ga_core::symbolic::Poly;

use crate::multivector::SymMultivector;
use crate::scope::Products;

fn to_cga(a: &SymMultivector) -> Multivector<Poly> {
    let c: [Poly; 32] = a
        .coefficients()
        .try_into()
        .unwrap_or_else(|_| unreachable!("32 coefficients"));
    Multivector::from_coefficients(c)
}
fn from_cga(m: Multivector<Poly>) -> SymMultivector {
    SymMultivector::from_coefficients(&m.into_coefficients())
}
/// Geometric product (generated `ga_core::cga` code over `Poly`).
pub(crate) fn gp(a: &SymMultivector, b: &SymMultivector) -> SymMultivector {
    from_cga(to_cga(a).geometric(&to_cga(b)))
}
/// Outer product (generated).
pub(crate) fn wedge(a: &SymMultivector, b: &SymMultivector) -> SymMultivector {
    from_cga(to_cga(a).wedge(&to_cga(b)))
}
/// Left contraction (generated).
pub(crate) fn lc(a: &SymMultivector, b: &SymMultivector) -> SymMultivector {
    from_cga(to_cga(a).left_contraction(&to_cga(b)))
}
/// Our dual `A I⁻¹` (generated).
pub(crate) fn dual(a: &SymMultivector) -> SymMultivector {
    from_cga(to_cga(a).dual())
}
/// Our regressive product `undual(dual A ∧ dual B)` (generated).
pub(crate) fn regressive(a: &SymMultivector, b: &SymMultivector) -> SymMultivector {
    from_cga(to_cga(a).regressive(&to_cga(b)))
}
/// Reverse (generated).
pub(crate) fn rev(a: &SymMultivector) -> SymMultivector {
    from_cga(to_cga(a).reverse())
}

/// The generated products, for [`Scope::evaluate`].
pub(crate) struct Generated;
impl Products for Generated {
    fn geometric(&self, a: &SymMultivector, b: &SymMultivector) -> SymMultivector {
        gp(a, b)
    }
    fn wedge(&self, a: &SymMultivector, b: &SymMultivector) -> SymMultivector {
        wedge(a, b)
    }
    fn left_contraction(&self, a: &SymMultivector, b: &SymMultivector) -> SymMultivector {
        lc(a, b)
    }
}

/// [`SymMultivector`]'s own products (for reading printed formulas).
pub(crate) struct Own;
impl Products for Own {
    fn geometric(&self, a: &SymMultivector, b: &SymMultivector) -> SymMultivector {
        a.gp(b)
    }
    fn wedge(&self, a: &SymMultivector, b: &SymMultivector) -> SymMultivector {
        a.wedge(b)
    }
    fn left_contraction(&self, a: &SymMultivector, b: &SymMultivector) -> SymMultivector {
        a.left_contraction(b)
    }
}
