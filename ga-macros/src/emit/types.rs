//! The structs: definition (`#[repr(C)]`, the `attributes` key), constructors, coefficient
//! access, zero, negation and scaling; and the module-level constants and blade constructors.

use std::collections::BTreeMap;

use proc_macro2::{Ident, Literal, TokenStream};
use quote::{format_ident, quote};

use super::{construct, field_ident, out_ty, ring};
use crate::model::{Algebra, BladeSet, TypeModel};

pub(super) fn emit_module_items(alg: &Algebra) -> TokenStream {
    let n = alg.n();
    let nb = 1usize << n;
    let sig = alg
        .signature
        .iter()
        .map(|&s| Literal::i8_unsuffixed(s as i8));
    let basis = &alg.basis;
    let names = alg
        .canonical
        .iter()
        .map(|&b| alg.blade_names[b as usize].clone());
    let label = alg.module.to_string();
    let sig_doc = format!("Squares of the generators of `{label}`, in basis order.");
    let ring = ring();
    let blade_fns = alg.canonical.iter().skip(1).map(|&b| {
        let out = alg.resolve(BladeSet::single(b));
        if !alg.is_emitted(out) {
            return TokenStream::new();
        }
        let ty = out_ty(alg, out);
        let name = format_ident!("{}", alg.field_names[b as usize]);
        let mut exprs = BTreeMap::new();
        exprs.insert(b, quote!(<T as #ring>::one()));
        let value = construct(alg, out, exprs);
        let doc = format!("The basis blade `{}`.", alg.blade_names[b as usize]);
        quote! {
            #[doc = #doc]
            #[inline]
            pub fn #name<T: #ring>() -> #ty { #value }
        }
    });
    quote! {
        #[doc = #sig_doc]
        pub const SIGNATURE: [i8; #n] = [#(#sig),*];
        /// Names of the generators, in basis order.
        pub const BASIS: [&str; #n] = [#(#basis),*];
        /// Names of all blades in canonical order (grade, then lexicographic on indices).
        pub const BLADE_NAMES: [&str; #nb] = [#(#names),*];
        #(#blade_fns)*
    }
}

/// One type: the struct and its basic items, then its unary operations, conversions and
/// formatting.
pub(super) fn emit_type(alg: &Algebra, index: usize, t: &TypeModel) -> TokenStream {
    let ring = ring();
    let name = &t.name;
    let fields: Vec<Ident> = t.blades.iter().map(|&b| field_ident(alg, b)).collect();
    let names: Vec<String> = t
        .blades
        .iter()
        .map(|&b| alg.blade_names[b as usize].clone())
        .collect();
    let count = t.blades.len();
    let attrs = &t.attrs;
    let auto_doc = if t.is_dense {
        format!(
            "A general multivector of `{}`: all {count} blades, in canonical order.",
            alg.module
        )
    } else {
        format!(
            "A multivector of `{}` with the blades `{}`.",
            alg.module,
            names.join(", ")
        )
    };
    let field_docs = names.iter().map(|n| format!("Coefficient of `{n}`."));
    let zero = quote!(<T as #ring>::zero());

    let masks: Vec<Literal> = t
        .blades
        .iter()
        .map(|&b| Literal::u32_unsuffixed(b))
        .collect();
    let unary = super::unary::emit_unary(alg, t);
    let conversions = super::conversions::emit_conversions(alg, index, t);
    let format = super::format::emit_format(alg, t);
    let struct_attributes = &alg.struct_attributes;
    quote! {
        #(#attrs)*
        #[doc = #auto_doc]
        #[derive(Clone, Copy, PartialEq, Eq, Hash)]
        #[repr(C)]
        #(#struct_attributes)*
        pub struct #name<T> {
            #(#[doc = #field_docs] pub #fields: T,)*
        }

        impl<T> #name<T> {
            /// Canonical names of this type's blades, in field order (`1` is the scalar).
            pub const BLADES: [&'static str; #count] = [#(#names),*];
            /// Blade bitmasks (bit `i` is generator `i`), in field order.
            pub const BLADE_MASKS: [u32; #count] = [#(#masks),*];
            /// Builds a value from its coefficients in canonical blade order (field order).
            #[inline]
            pub fn from_coefficients(coefficients: [T; #count]) -> Self {
                let [#(#fields),*] = coefficients;
                #name { #(#fields),* }
            }
            /// The coefficients in canonical blade order (field order).
            #[inline]
            pub fn into_coefficients(self) -> [T; #count] {
                [#(self.#fields),*]
            }
            /// The same value over another scalar type, each coefficient converted by `f`
            /// (in field order), e.g. `v.map(|x| x as f32)` or `v.map(Rational::from)`.
            #[inline]
            pub fn map<U>(self, mut f: impl FnMut(T) -> U) -> #name<U> {
                #name { #(#fields: f(self.#fields)),* }
            }
            /// Builds a value from its coefficients in canonical blade order.
            #[allow(clippy::too_many_arguments)]
            #[inline]
            pub const fn new(#(#fields: T),*) -> Self {
                #name { #(#fields),* }
            }
        }

        impl<T: Clone> #name<T> {
            /// The coefficients in canonical blade order (field order).
            #[inline]
            pub fn coefficients(&self) -> [T; #count] {
                [#(self.#fields.clone()),*]
            }
        }

        impl<T: #ring> #name<T> {
            /// The zero value.
            #[inline]
            pub fn zero() -> Self {
                #name { #(#fields: #zero),* }
            }
        }

        impl<T: #ring> Default for #name<T> {
            #[inline]
            fn default() -> Self { Self::zero() }
        }

        impl<T: #ring> ::core::ops::Neg for #name<T> {
            type Output = Self;
            #[inline]
            fn neg(self) -> Self { #name { #(#fields: -self.#fields),* } }
        }
        impl<T: #ring> ::core::ops::Neg for &#name<T> {
            type Output = #name<T>;
            #[inline]
            fn neg(self) -> #name<T> { #name { #(#fields: -self.#fields.clone()),* } }
        }
        impl<T: #ring> ::core::ops::Mul<T> for #name<T> {
            type Output = Self;
            #[inline]
            fn mul(self, s: T) -> Self { #name { #(#fields: self.#fields * s.clone()),* } }
        }
        impl ::core::ops::Mul<#name<f64>> for f64 {
            type Output = #name<f64>;
            #[inline]
            fn mul(self, v: #name<f64>) -> #name<f64> { v * self }
        }
        impl ::core::ops::Mul<#name<f32>> for f32 {
            type Output = #name<f32>;
            #[inline]
            fn mul(self, v: #name<f32>) -> #name<f32> { v * self }
        }

        #unary
        #conversions
        #format
    }
}
