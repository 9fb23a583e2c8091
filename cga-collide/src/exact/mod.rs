//! The bottom layer: certified signs of polynomials in `f64` inputs.
//!
//! Every yes/no answer of the crate is the sign of a polynomial in the input coordinates. The
//! polynomial is written once, generic over [`ga_core::scalar::Ring`], and evaluated
//! 1. on [`ErrF64`], an `f64` with a rigorous error bound (or a cheaper semi-static filter for
//!    plane sides, [`ExactPlane`]): the sign is taken when the bound excludes zero;
//! 2. otherwise on the same inputs scaled to unit size (exact, predicates are homogeneous);
//! 3. otherwise exactly on floating-point expansions ([`Expansion`]: no allocation, a few dozen
//!    `f64` operations for the typical exact zero);
//! 4. only when the expansions cannot hold the value, exactly on big integers ([`BigInteger`]).
//!
//! | item | what it is |
//! |---|---|
//! | [`ErrF64`] | `f64` value with a running error bound |
//! | [`Expansion`] | exact sums and products of `f64` in fixed storage |
//! | [`Predicate`], [`exact_sign`] | a polynomial predicate and its exact sign |
//! | [`predicates`] | every polynomial predicate of the crate (orientation, distances, spheres) |
//! | [`Kernel`], [`ExactKernel`] | how the algorithms of [`crate::query`] decide signs |
//! | [`ExactPlane`] | a triangle's plane with its filter data, computed once per triangle |
//! | [`CertifiedScalar`], [`decide`] | the same staging for whole conformal computations ([`crate::conformal`]) |
//!
//! Nothing here depends on any other module of the crate.

mod balls;
mod bounded_f64;
mod certified;
pub(crate) mod counters;
pub(crate) mod expansion;
pub(crate) mod kernel;
pub mod predicates;
pub(crate) mod sign;
pub(crate) mod vector;

pub(crate) use balls::{ball_inside, balls_meet};
pub use bounded_f64::ErrF64;
pub use certified::{all_zero, decide, CertifiedScalar};
pub use expansion::Expansion;
pub use kernel::{ExactKernel, ExactPlane, Kernel, PlaneSide};
pub(crate) use sign::decode;
pub use sign::{exact_sign, integer_scaled, rational_sign, BigInteger, Predicate};
