//! The generated Cl(4,1) algebra `ga_core::cga` against the dense reference: every ordered
//! pair of declared types, every product, every unary operation, the operators, and
//! sandwiches by versors. See `generated_vs_reference.rs` for Cl(3,0), Cl(3,0,1) and the
//! conformal identities, and `gvr_harness/mod.rs` for the checks themselves.

#[macro_use]
mod gvr_harness;
use gvr_harness::*;

algebra_suite! {
    mod cga_suite for cga,
    signature: [1, 1, 1, 1, -1],
    source: include_str!("../../ga-core/src/cga.rs"),
    types: [Vector, Bivector, Trivector, Quadvector, Pseudoscalar, Rotor, Even, Odd],
    dense: Multivector,
    versors: [Vector, Rotor, Even, Odd, Multivector],
    // Instantiating every product of every Cl(4,1) pair (Σ|blades| = 95, so ~9000 blade pairs
    // per product) for big rationals as well as f64 makes this file take tens of CPU-minutes
    // to compile. The exact check of every pair is `generated_vs_reference_cga_exact.rs`:
    // symbolic (a polynomial identity, hence exact for all rational inputs), plus a few pairs
    // and versor sandwiches over `Rational`.
    exact_products: no,
    exact_versors: no,
}
