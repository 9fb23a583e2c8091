//! Unary operations: reverse, involutions, dual and undual (and `!`), grade projection, norm,
//! scaling, and the two inverses.

use std::collections::BTreeMap;

use proc_macro2::{Ident, TokenStream};
use quote::{format_ident, quote};

use super::{construct, field_ident, out_ty, ring, signed_sum};
use crate::blade::{self, Blade};
use crate::metric::Terms;
use crate::model::{Algebra, TypeModel};

pub(super) fn emit_unary(alg: &Algebra, t: &TypeModel) -> TokenStream {
    let ring = ring();
    let name = &t.name;
    let fields: Vec<Ident> = t.blades.iter().map(|&b| field_ident(alg, b)).collect();
    let zero = quote!(<T as #ring>::zero());
    let unary_signs = |f: fn(Blade) -> i32| {
        let exprs = t.blades.iter().map(|&b| {
            let fi = field_ident(alg, b);
            if f(b) < 0 {
                quote!(#fi: -self.#fi.clone())
            } else {
                quote!(#fi: self.#fi.clone())
            }
        });
        quote!(#name { #(#exprs),* })
    };
    let reverse = unary_signs(blade::reverse_sign);
    let involution = unary_signs(blade::involution_sign);
    let conjugate = unary_signs(blade::conjugate_sign);

    let blade_map_fn = |fname: Ident, doc: &str, f: &dyn Fn(Blade) -> Terms| {
        let map = alg.blade_map(&t.blades, f);
        if !alg.is_emitted(map.output) {
            return TokenStream::new();
        }
        let ty = out_ty(alg, map.output);
        // Each output blade is the sum of its inputs (one in an orthogonal basis).
        let mut by_out: BTreeMap<Blade, Vec<(i32, TokenStream)>> = BTreeMap::new();
        for &(o, s, b) in &map.entries {
            let fi = field_ident(alg, b);
            by_out
                .entry(o)
                .or_default()
                .push((s, quote!(self.#fi.clone())));
        }
        let exprs = by_out
            .into_iter()
            .map(|(o, terms)| (o, signed_sum(terms)))
            .collect();
        let value = construct(alg, map.output, exprs);
        quote! {
            #[doc = #doc]
            #[inline]
            pub fn #fname(&self) -> #ty { #value }
        }
    };
    let dual_doc = if alg.degenerate {
        "The dual: the right complement (the signature is degenerate, so `I` has no inverse)."
    } else {
        "The dual `A I⁻¹`."
    };
    let undual_doc = if alg.degenerate {
        "The undual: the left complement, inverse of [`dual`](Self::dual)."
    } else {
        "The undual `A I`, inverse of [`dual`](Self::dual)."
    };
    let dual = blade_map_fn(format_ident!("dual"), dual_doc, &|b| alg.dual_blade(b));
    let undual = blade_map_fn(format_ident!("undual"), undual_doc, &|b| {
        alg.undual_blade(b)
    });
    let dual_out = alg.blade_map(&t.blades, |b| alg.dual_blade(b)).output;
    let dual_ty = out_ty(alg, dual_out);
    let not_impls = if alg.is_emitted(dual_out) {
        quote! {
            impl<T: #ring> ::core::ops::Not for #name<T> {
                type Output = #dual_ty;
                /// The dual.
                #[inline]
                fn not(self) -> #dual_ty { self.dual() }
            }
            impl<T: #ring> ::core::ops::Not for &#name<T> {
                type Output = #dual_ty;
                /// The dual.
                #[inline]
                fn not(self) -> #dual_ty { self.dual() }
            }
        }
    } else {
        TokenStream::new()
    };

    let grades = t.blades.iter().map(|&b| {
        let fi = field_ident(alg, b);
        let g = blade::grade(b);
        quote!(#fi: if k == #g { self.#fi.clone() } else { #zero })
    });
    let norm_terms: Vec<(i32, TokenStream)> = alg
        .norm_squared_terms(&t.blades)
        .into_iter()
        .map(|(s, a, b)| {
            let (fa, fb) = (field_ident(alg, a), field_ident(alg, b));
            (s, quote!(self.#fa.clone() * self.#fb.clone()))
        })
        .collect();
    let norm = if norm_terms.is_empty() {
        zero.clone()
    } else {
        signed_sum(norm_terms)
    };

    let count = t.blades.len();
    let inverse_doc = inverse_doc(t);
    // The checked inverse runs on the run-time signature (an orthogonal basis); with a
    // `metric` only the versor inverse is generated.
    let inverse = if alg.form.is_none() {
        quote! {
            #[doc = #inverse_doc]
            pub fn inverse(&self) -> Option<Self> {
                let x = self.coefficients();
                let [#(#fields),*]: [T; #count] =
                    ::ga_core::inverse::inverse(&SIGNATURE, &Self::BLADE_MASKS, &x)?.try_into().ok()?;
                Some(#name { #(#fields),* })
            }
        }
    } else {
        TokenStream::new()
    };
    quote! {
        impl<T: #ring> #name<T> {
            /// The reverse `Ã` (order of factors reversed).
            #[inline]
            pub fn reverse(&self) -> Self { #reverse }
            /// The grade involution `Â` (odd grades negated).
            #[inline]
            pub fn grade_involution(&self) -> Self { #involution }
            /// The Clifford conjugate `Ā` (reverse of the grade involution).
            #[inline]
            pub fn conjugate(&self) -> Self { #conjugate }
            #dual
            #undual
            /// The grade-`k` part (all other grades zeroed).
            #[inline]
            pub fn grade(&self, k: usize) -> Self {
                #name { #(#grades),* }
            }
            /// `⟨A Ã⟩₀`; may be negative or zero in non-Euclidean signatures.
            #[inline]
            pub fn norm_squared(&self) -> T { #norm }
            /// Every coefficient multiplied by `s`.
            #[inline]
            pub fn scale(&self, s: &T) -> Self {
                #name { #(#fields: self.#fields.clone() * s.clone()),* }
            }
        }

        impl<T: ::ga_core::scalar::Field> #name<T> {
            /// The versor inverse `Ã / ⟨A Ã⟩₀`, `None` when `⟨A Ã⟩₀` is zero. Precondition: `A`
            /// is a versor (a product of invertible vectors) or a blade; then this is its
            /// inverse. For any other `A` the result is not an inverse: use
            /// [`inverse`](Self::inverse), which checks.
            #[inline]
            pub fn versor_inverse(&self) -> Option<Self> {
                let inv = ::ga_core::scalar::Field::checked_recip(&self.norm_squared())?;
                Some(self.reverse().scale(&inv))
            }
            #inverse
        }

        #not_impls
    }
}

/// The documentation of `inverse()`: what `None` means depends on whether the type is closed
/// under the geometric product.
fn inverse_doc(t: &TypeModel) -> String {
    let masks: Vec<Blade> = t.blades.clone();
    let mut span = vec![0 as Blade];
    for &m in &masks {
        if !span.contains(&m) {
            let more: Vec<Blade> = span.iter().map(|s| s ^ m).collect();
            span.extend(more);
        }
    }
    let closed = span.iter().all(|b| t.contains(*b));
    let none = if closed {
        "`None` when `A` has no inverse"
    } else {
        "`None` when `A` has no inverse, or when its inverse has blades outside this type (the \
         type is not closed under the geometric product: convert to a larger type first)"
    };
    format!(
        "The inverse `A⁻¹` with `A A⁻¹ = A⁻¹ A = 1`, checked: {none}. For floats, `Some` means \
         the products equal 1 up to the rounding error of computing them (see \
         `ga_core::inverse` for the exact tolerance), and non-finite input gives `None`. Tries \
         the versor formula first (see [`versor_inverse`](Self::versor_inverse)), then Gaussian \
         elimination; slower than `versor_inverse`, which is enough when `A` is known to be a \
         versor."
    )
}
