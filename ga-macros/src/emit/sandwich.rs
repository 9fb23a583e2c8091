//! Sandwiches `V X Ṽ` (and the normalised `V X V⁻¹`) of one ordered pair of types.

use proc_macro2::TokenStream;
use quote::quote;

use super::{bilinear_body, ring};
use crate::blade::Blade;
use crate::model::{Algebra, Output, Product};

/// Sandwiches with at most this many multiplications (both stages) are `#[inline(always)]`:
/// this covers the versors of Cl(4,1) applied to points (rotor: 110, even versor: 160).
const SANDWICH_INLINE_ALWAYS_MAX: usize = 192;

/// `V X Ṽ` projected on `X`: the geometric product `V X` (written out for small sandwiches,
/// called for large ones), then
/// only the terms of `(V X) Ṽ` that land on `X`'s blades.
pub(super) fn emit_sandwich(alg: &Algebra, v: usize, x: usize) -> TokenStream {
    let ring = ring();
    let (tv, tx) = (&alg.types[v], &alg.types[x]);
    let (vn, xn) = (&tv.name, &tx.name);
    let first = alg.bilinear(Product::Geometric, &tv.blades, &tx.blades);
    if !alg.is_emitted(first.output) {
        return TokenStream::new();
    }
    let p_blades: Vec<Blade> = first.outputs.iter().map(|(b, _)| *b).collect();
    let outputs = alg.sandwich_terms(&p_blades, &tv.blades, &tx.blades);
    let p = quote!(p);
    let me = quote!(self);
    let xv = quote!(x);
    // For small sandwiches the first stage is written out here rather than called, so that the
    // whole sandwich is one straight-line body (the call to `geometric` was not inlined).
    let first_body = bilinear_body(
        alg,
        &first.outputs,
        first.output,
        (&me, Output::Type(v)),
        (&xv, Output::Type(x)),
    );
    let body = bilinear_body(
        alg,
        &outputs,
        Output::Type(x),
        (&p, first.output),
        (&me, Output::Type(v)),
    );
    // The two stages together are too large for LLVM's inlining threshold even for small
    // versors (a rotor applied to a point: 110 multiplications), so a loop of sandwiches would
    // pay a call per element and lose vectorisation across iterations (measured: 2x slower than
    // the same code inlined, see ga-core/examples/callgrind_products.rs). Small sandwiches are
    // always inlined, as a hand-written kernel would be; large ones (e.g. dense × dense) keep
    // the hint only, to bound code size.
    let mults: usize = first.outputs.iter().map(|(_, t)| t.len()).sum::<usize>()
        + outputs.iter().map(|(_, t)| t.len()).sum::<usize>();
    // Large sandwiches call the generated geometric product for the first stage instead of
    // repeating its terms (this keeps the expansion, and the compile time, small).
    let (inline, first_stage) = if mults <= SANDWICH_INLINE_ALWAYS_MAX {
        (quote!(#[inline(always)]), first_body)
    } else {
        (
            quote!(#[inline]),
            quote!(::ga_core::ops::Geometric::geometric(self, x)),
        )
    };
    quote! {
        impl<T: #ring> ::ga_core::ops::SandwichUnit<#xn<T>> for #vn<T> {
            #inline
            fn sandwich_unit(&self, x: &#xn<T>) -> #xn<T> {
                let p = #first_stage;
                #body
            }
        }
        impl<T: ::ga_core::scalar::Field> ::ga_core::ops::Sandwich<#xn<T>> for #vn<T> {
            #[inline]
            fn sandwich(&self, x: &#xn<T>) -> Option<#xn<T>> {
                let inv = ::ga_core::scalar::Field::checked_recip(&self.norm_squared())?;
                Some(::ga_core::ops::SandwichUnit::sandwich_unit(self, x).scale(&inv))
            }
        }
    }
}
