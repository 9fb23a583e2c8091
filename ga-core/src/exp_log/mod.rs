//! Exponentials, logarithms and square roots of versors, in closed form.
//!
//! * [`cga`](crate::cga) (Cl(4,1)): `Bivector::exp`, `Bivector::split`, `Even::log`,
//!   `Even::sqrt`, `Rotor::log`, `Rotor::sqrt`, and the closed-form constructors
//!   `Rotor::translator`, `Rotor::rotation`, `Rotor::dilator`, `Rotor::transversion`.
//! * [`pga3`](crate::pga3) (Cl(3,0,1)): `Bivector::exp`, `Motor::log`, `Motor::sqrt`.
//! * [`vga3`](crate::vga3) (Cl(3,0)): `Bivector::exp`, `Rotor::log`, `Rotor::sqrt`.
//! * The dense types `Multivector` of all three: `exp` of any multivector (scaling and
//!   squaring of the Taylor series) and `log` of even versors (through the closed forms).
//!
//! # How
//!
//! For a bivector `B`, `B² = α + β` (scalar plus 4-vector, and `β` commutes with `B`). In the
//! three algebras `β²` is a scalar, so `B²`, `exp(B)` and the even part `c = ⟨V⟩₀ + ⟨V⟩₄` of
//! a versor lie in the commutative plane spanned by `1` and a unit `J ∥ β`:
//! `J² = +1` (split-complex numbers: two rotations, e.g. `e12 + e34`), `J² = -1` (complex:
//! a rotation and a boost, e.g. a rotation combined with a dilation), `J² = 0` (dual: a
//! rotation and a translation, the screws of Cl(3,0,1)). With `C(x) = cosh √x` and
//! `S(x) = sinh √x / √x`,
//!
//! * `exp(B) = C(B²) + B S(B²)`;
//! * `log V = W F` for `V = c + W` (`W` the bivector part), where `F = ln(c + √(W²)) / √(W²)`
//!   is computed in the same plane (`θ/sin θ` for a rotation, `asinh s / s` for a boost, `1`
//!   for a translation);
//! * `√V = (1 + V) N⁻¹` with `N = √(2(1 + c))`, since `1 + Q² = Q (Q + Q̃)`.
//!
//! Near the removable singularities (`x → 0`) the functions are evaluated from their series,
//! so nilpotent cases use ring operations only and are exact over
//! [`Rational`](crate::scalar::Rational). Elsewhere the elementary functions of
//! [`Elementary`](crate::scalar::Elementary) are needed.
//!
//! # Principal range, branch cuts and `None`
//!
//! Versors are normalised first (`V / √⟨V Ṽ⟩₀`); the logarithm of `λV` is that of `V`. The
//! principal logarithm has every rotation component with angle `|θ| < π` (the bivector
//! `θ U`, `U² = -1`, rotating by `2θ`), and, for two rotation components in orthogonal planes
//! of Cl(4,1), `|θ₁| + |θ₂| < π` (since `exp(π(e12 + e34)) = 1`). `log` returns `None` for non-versors (`⟨V Ṽ⟩₀ ≤ 0`,
//! non-finite, or a non-negligible `⟨V Ṽ⟩₄`), on the branch cut (a rotation component equal
//! to `-1`: rotation by 2π, whose plane is not determined) and where no real logarithm
//! exists (minus a pure boost or translation). `sqrt` returns `None` in the same places.

mod center;
mod cga;
mod dense;
mod pga3;
mod vga3;
