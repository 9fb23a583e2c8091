//! Product traits implemented by every generated multivector type.
//!
//! Binary products take both operands by reference so that non-`Copy` scalars (big rationals,
//! polynomials) are not moved; the operators (`*`, `^`, `|`, `&`) are implemented on values and
//! on references and call these.

/// The geometric product `a b` (operator `*`).
pub trait Geometric<Rhs = Self> {
    /// The smallest declared type that holds every nonzero blade of the product, or
    /// [`Zero`](crate::Zero) when the product is zero by grade.
    type Output;
    /// The geometric product.
    fn geometric(&self, rhs: &Rhs) -> Self::Output;
}

/// The outer (wedge) product `a ∧ b` (operator `^`).
pub trait Wedge<Rhs = Self> {
    /// The smallest declared type that holds every nonzero blade of the product, or
    /// [`Zero`](crate::Zero) when the product is zero by grade.
    type Output;
    /// The outer product.
    fn wedge(&self, rhs: &Rhs) -> Self::Output;
}

/// The left contraction `a ⌋ b` (operator `|`).
pub trait LeftContraction<Rhs = Self> {
    /// The smallest declared type that holds every nonzero blade of the product, or
    /// [`Zero`](crate::Zero) when the product is zero by grade.
    type Output;
    /// The left contraction.
    fn left_contraction(&self, rhs: &Rhs) -> Self::Output;
}

/// The right contraction `a ⌊ b`.
pub trait RightContraction<Rhs = Self> {
    /// The smallest declared type that holds every nonzero blade of the product, or
    /// [`Zero`](crate::Zero) when the product is zero by grade.
    type Output;
    /// The right contraction.
    fn right_contraction(&self, rhs: &Rhs) -> Self::Output;
}

/// The scalar product `⟨a b⟩₀`.
pub trait ScalarProduct<Rhs = Self> {
    /// The scalar type, or [`Zero`](crate::Zero) for operands of different grades.
    type Output;
    /// The scalar product.
    fn scalar_product(&self, rhs: &Rhs) -> Self::Output;
}

/// The regressive product `a ∨ b = undual(dual(a) ∧ dual(b))` (operator `&`).
pub trait Regressive<Rhs = Self> {
    /// The smallest declared type that holds every nonzero blade of the product, or
    /// [`Zero`](crate::Zero) when the product is zero by grade.
    type Output;
    /// The regressive product.
    fn regressive(&self, rhs: &Rhs) -> Self::Output;
}

/// Versor application `V X V⁻¹`, projected onto the type of `X` (exact for versors, which
/// preserve grade). Needs division; see [`SandwichUnit`] for the ring-only unit-versor form.
pub trait Sandwich<X> {
    /// `V X V⁻¹`, or `None` when `⟨V Ṽ⟩₀` is zero (`V` not invertible as a versor).
    fn sandwich(&self, x: &X) -> Option<X>;
}

/// `V X Ṽ` projected onto the type of `X`: versor application for unit versors (`V Ṽ = 1`),
/// with no division, so it runs on any ring (symbolic polynomials included).
pub trait SandwichUnit<X> {
    /// `V X Ṽ`, keeping only the blades of `X`'s type.
    fn sandwich_unit(&self, x: &X) -> X;
}
