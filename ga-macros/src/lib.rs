//! `ga_macros::algebra!` turns one algebra declaration into Rust types whose products are
//! blade-sparse, straight-line code generic over the coefficient type.
//!
//! The macro is organised in three stages: `parse` reads the declaration (syn),
//! `model` builds the algebra (blade products, result-type inference), and
//! `emit` writes the tokens (quote). The generated code names the runtime crate as
//! `::ga_core`, so a crate using the macro depends on `ga-core` too.
//!
//! ```
//! ga_macros::algebra! {
//!     name: plane,
//!     signature: [+1, +1],
//!     types: { Vector: grade 1, Rotor: grades 0 2 },
//! }
//! let a = Vector::new(1.0, 0.0);
//! let b = Vector::new(0.0, 2.0);
//! let r: Rotor<f64> = a * b; // 2e12
//! assert_eq!(r, Rotor::new(0.0, 2.0));
//! assert_eq!(r.to_string(), "2e12");
//! ```
//!
//! The declaration: `name` (a label for docs), `signature` (`+1`, `-1` or `0` per generator,
//! at most 6), optional `basis` names (default `e1 ... en`), `types` (each by `grade K`,
//! `grades K L ...` or an explicit blade list `[1, e12, e13]`), optional `dense` (the name
//! of the all-blades type, default `Multivector`), and optional `attributes: [#[...], ...]`:
//! outer attributes forwarded onto every generated struct (each struct is `#[repr(C)]`, its
//! fields the coefficients in canonical blade order), e.g.
//! `attributes: [#[cfg_attr(feature = "serde", derive(serde::Serialize, serde::Deserialize))]]`,
//! and optional `wgsl: [Type, ...]`: also emit WGSL shader source for those types and their
//! products, in a module `wgsl` (string constants `F32`, `F64`, `RING`, a table `FUNCTIONS`).
//! See `docs/generator.md` in the repository for what is generated.
#![forbid(unsafe_code)]

mod blade;
mod emit;
mod errors;
mod model;
mod parse;
mod wgsl;

use proc_macro::TokenStream;

/// Generates the types and products of one geometric algebra; see the crate documentation.
#[proc_macro]
pub fn algebra(input: TokenStream) -> TokenStream {
    let mut declaration = syn::parse_macro_input!(input as parse::Declaration);
    let shaders = declaration.wgsl.take();
    match model::Algebra::from_declaration(declaration)
        .and_then(|a| Ok((wgsl::emit(&a, shaders.as_deref())?, a)))
    {
        Ok((shaders, algebra)) => {
            let mut tokens = emit::emit(&algebra);
            tokens.extend(shaders);
            tokens.into()
        }
        Err(e) => e.to_compile_error().into(),
    }
}
