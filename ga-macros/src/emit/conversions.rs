//! Conversions: into the dense type and projection from it, between declared types whose
//! blades include each other, from and with `ga_core::Zero` (the result of a product that is
//! zero by grade), and the dense type's unchecked general inverse.

use proc_macro2::{Ident, TokenStream};
use quote::quote;

use super::{field_ident, ring};
use crate::model::{Algebra, TypeModel};

pub(super) fn emit_conversions(alg: &Algebra, index: usize, t: &TypeModel) -> TokenStream {
    let ring = ring();
    let name = &t.name;
    let fields: Vec<Ident> = t.blades.iter().map(|&b| field_ident(alg, b)).collect();
    let zero = quote!(<T as #ring>::zero());
    let count = t.blades.len();
    // The general inverse runs on the run-time signature: orthogonal bases only.
    let dense_items = if t.is_dense && alg.form.is_some() {
        TokenStream::new()
    } else if t.is_dense {
        quote! {
            impl<T: ::ga_core::scalar::Field> #name<T> {
                /// The unchecked solution of `A X = 1` by Gaussian elimination on the
                /// left-multiplication matrix (partial pivoting by `Field::pivot_score`); `None`
                /// when a pivot is exactly zero. Exact for exact scalars; for floats a nearly
                /// singular `A` gives an inaccurate result: prefer [`inverse`](Self::inverse),
                /// which checks its answer.
                pub fn general_inverse(&self) -> Option<Self> {
                    let span = Self::BLADE_MASKS;
                    let solution = ::ga_core::inverse::solve(&SIGNATURE, &span, &self.coefficients(), &span)?;
                    let array: [T; #count] = solution.try_into().ok()?;
                    Some(Self::from_coefficients(array))
                }
            }
        }
    } else if !alg.types[alg.dense()].emitted {
        TokenStream::new()
    } else {
        let dense = &alg.types[alg.dense()].name;
        quote! {
            impl<T: #ring> From<#name<T>> for #dense<T> {
                #[inline]
                fn from(v: #name<T>) -> Self {
                    let mut m = #dense::<T>::zero();
                    #(m.#fields = v.#fields;)*
                    m
                }
            }
            impl<T: #ring> #name<T> {
                /// The projection of a general multivector onto this type's blades (the other
                /// blades are dropped).
                #[inline]
                pub fn from_multivector(m: &#dense<T>) -> Self {
                    #name { #(#fields: m.#fields.clone()),* }
                }
            }
        }
    };
    let subset_conversions = alg.types.iter().enumerate().filter_map(|(j, other)| {
        if j == index || other.is_dense || !t.set.is_subset_of(&other.set) {
            return None;
        }
        let oname = &other.name;
        let assigns = other.blades.iter().map(|&b| {
            let fi = field_ident(alg, b);
            if t.contains(b) {
                quote!(#fi: v.#fi)
            } else {
                quote!(#fi: #zero)
            }
        });
        Some(quote! {
            impl<T: #ring> From<#name<T>> for #oname<T> {
                #[inline]
                fn from(v: #name<T>) -> Self { #oname { #(#assigns),* } }
            }
        })
    });
    let zero_items = zero_items(name);
    quote! {
        #dense_items
        #(#subset_conversions)*
        #zero_items
    }
}

/// `Zero<T>` (what a product that is zero by grade returns) converts into the type and adds to
/// and subtracts from it on either side, so such a result can join a sum of this type.
fn zero_items(name: &Ident) -> TokenStream {
    let ring = ring();
    let zero_ty = quote!(::ga_core::Zero<T>);
    quote! {
        impl<T: #ring> From<#zero_ty> for #name<T> {
            #[inline]
            fn from(_: #zero_ty) -> Self { #name::zero() }
        }
        impl<T: #ring> ::core::ops::Add<#zero_ty> for #name<T> {
            type Output = Self;
            #[inline]
            fn add(self, _: #zero_ty) -> Self { self }
        }
        impl<T: #ring> ::core::ops::Sub<#zero_ty> for #name<T> {
            type Output = Self;
            #[inline]
            fn sub(self, _: #zero_ty) -> Self { self }
        }
        impl<T: #ring> ::core::ops::Add<#name<T>> for #zero_ty {
            type Output = #name<T>;
            #[inline]
            fn add(self, rhs: #name<T>) -> #name<T> { rhs }
        }
        impl<T: #ring> ::core::ops::Sub<#name<T>> for #zero_ty {
            type Output = #name<T>;
            #[inline]
            fn sub(self, rhs: #name<T>) -> #name<T> { -rhs }
        }
    }
}
