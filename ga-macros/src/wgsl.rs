//! Emitting WGSL shader source from the algebra model, for the types a declaration lists under
//! `wgsl: [...]`: one WGSL struct per listed type and straight-line functions for the products
//! (and sums, scaling and reverse) whose operands and result are listed types or the scalar,
//! read from the same term lists as the Rust products.
//!
//! Three texts are emitted into a module `wgsl` beside the Rust types:
//! * `F32` and `F64`: plain arithmetic on `f32` / `f64` (`alias Scalar = f32;` first);
//! * `RING`: the same functions over a scalar type `Scalar` that the including shader defines
//!   with the ring operations `scalar_add`, `scalar_sub`, `scalar_mul`, `scalar_neg` and
//!   `scalar_zero` (for example a value with a running error bound).
//!
//! A table `FUNCTIONS` names every function with its operands' blades, so that a test can call
//! each one on a device and compare with the Rust products.

use std::fmt::Write;

use proc_macro2::{Ident, TokenStream};
use quote::quote;

use crate::blade::{self, Blade};
use crate::model::{Algebra, Output, Product, Term};

/// How scalar arithmetic is written.
#[derive(Clone, Copy, PartialEq)]
enum Arith {
    /// `a * b + c`
    Plain,
    /// `scalar_add(scalar_mul(a, b), c)`
    Ring,
}

/// One operand or result of an emitted function: a listed type or the bare scalar.
struct Value {
    /// WGSL type name (`Scalar` for the bare scalar).
    ty: String,
    /// Blades in canonical order (`[0]` for the scalar).
    blades: Vec<Blade>,
    scalar: bool,
}

/// A signed term: a blade of input 0 times a blade of input 1 (`None`: input 0 alone).
type SignedTerm = (i32, Blade, Option<Blade>);
/// Per output blade, its terms.
type Body = Vec<(Blade, Vec<SignedTerm>)>;

struct Function {
    name: String,
    operation: &'static str,
    inputs: Vec<Value>,
    output: Value,
    /// Per output blade: signed terms, each a product of an input-0 blade and an input-1 blade
    /// (`rhs == None`: a linear term of input 0 alone).
    body: Body,
}

/// Product names as in the Rust traits' methods.
fn product_name(kind: Product) -> &'static str {
    match kind {
        Product::Geometric => "geometric",
        Product::Wedge => "wedge",
        Product::LeftContraction => "left_contraction",
        Product::RightContraction => "right_contraction",
        Product::ScalarProduct => "scalar_product",
        Product::Regressive => "regressive",
    }
}

/// The WGSL tokens for the listed types, or nothing when the declaration has no `wgsl` key.
pub fn emit(alg: &Algebra, listed: Option<&[Ident]>) -> syn::Result<TokenStream> {
    let Some(listed) = listed else {
        return Ok(TokenStream::new());
    };
    if let Some(first) = listed.first().filter(|_| alg.form.is_some()) {
        return Err(syn::Error::new(
            first.span(),
            "`wgsl` is not supported with a non-diagonal `metric` yet: declare the algebra with \
             a `signature` for shaders",
        ));
    }
    let mut indices = Vec::new();
    for id in listed {
        let Some(i) = alg.types.iter().position(|t| t.name == *id) else {
            let names: Vec<String> = alg.types.iter().map(|t| t.name.to_string()).collect();
            return Err(syn::Error::new(
                id.span(),
                format!(
                    "`wgsl` lists `{id}`, which is not a type of this algebra (types: {})",
                    names.join(", ")
                ),
            ));
        };
        if indices.contains(&i) {
            return Err(syn::Error::new(
                id.span(),
                format!("`{id}` is listed twice"),
            ));
        }
        indices.push(i);
    }
    let functions = functions(alg, &indices);
    let plain = source(alg, &indices, &functions, Arith::Plain);
    let ring = source(alg, &indices, &functions, Arith::Ring);
    let f32_src = format!("alias Scalar = f32;\n{plain}");
    let f64_src = format!("alias Scalar = f64;\n{plain}");
    let table = functions.iter().map(|f| {
        let name = &f.name;
        let op = f.operation;
        let inputs = f.inputs.iter().map(|v| value_tokens(alg, v));
        let output = value_tokens(alg, &f.output);
        quote! {
            Function { name: #name, operation: #op, inputs: &[#(#inputs),*], output: #output }
        }
    });
    let label = alg.module.to_string();
    let count = functions.len();
    let types_doc = indices
        .iter()
        .map(|&i| format!("`{}`", alg.types[i].name))
        .collect::<Vec<_>>()
        .join(", ");
    let module_doc = format!(
        "WGSL shader source for {types_doc} of `{label}`, generated from the same declaration \
         as the Rust types: {count} straight-line functions (products, sums, scaling, reverse) \
         whose operands and result are these types or the scalar. Functions are named \
         `Lhs_operation_Rhs` (`Vector_scalar_product_Vector`), unary ones `Type_operation`; \
         struct fields are the Rust field names."
    );
    Ok(quote! {
        #[doc = #module_doc]
        pub mod wgsl {
            /// The functions on `f32` (the source starts with `alias Scalar = f32;`).
            pub const F32: &str = #f32_src;
            /// The functions on `f64` (the source starts with `alias Scalar = f64;`); needs a
            /// device with 64-bit floats in shaders (wgpu's `SHADER_F64`).
            pub const F64: &str = #f64_src;
            /// The functions over a scalar type the including shader defines, with
            /// `alias Scalar = ...;` (or a struct `Scalar`) and the ring operations
            /// `fn scalar_add(a: Scalar, b: Scalar) -> Scalar`, `scalar_sub`, `scalar_mul`,
            /// `fn scalar_neg(a: Scalar) -> Scalar` and `fn scalar_zero() -> Scalar`. Each
            /// blade is a left-to-right chain of these calls, as the Rust products evaluate.
            pub const RING: &str = #ring;
            /// The `f32` source (see [`F32`]).
            pub const SOURCE: &str = F32;
            /// One operand or result: a WGSL type and its blades.
            #[derive(Debug, Clone, Copy, PartialEq, Eq)]
            pub struct Value {
                /// The WGSL type name (`Scalar` for the bare scalar).
                pub ty: &'static str,
                /// Positions of its blades in canonical order (`BLADE_NAMES`), `[0]` for the
                /// scalar.
                pub blades: &'static [usize],
                /// Its struct fields, in the order of `blades` (empty for the scalar).
                pub fields: &'static [&'static str],
            }
            /// One emitted function.
            #[derive(Debug, Clone, Copy, PartialEq, Eq)]
            pub struct Function {
                /// The WGSL function name.
                pub name: &'static str,
                /// The Rust method it mirrors: `geometric`, `wedge`, `left_contraction`,
                /// `right_contraction`, `scalar_product`, `regressive`, `add`, `sub`, `scale`
                /// (a type times a scalar) or `reverse`.
                pub operation: &'static str,
                /// The parameters in order.
                pub inputs: &'static [Value],
                /// The result.
                pub output: Value,
            }
            /// Every function in the sources, in source order.
            pub const FUNCTIONS: &[Function] = &[#(#table),*];
        }
    })
}

fn value_tokens(alg: &Algebra, v: &Value) -> TokenStream {
    let ty = &v.ty;
    let blades = v
        .blades
        .iter()
        .map(|b| alg.canonical.iter().position(|c| c == b).unwrap_or(0));
    let fields: Vec<&String> = if v.scalar {
        Vec::new()
    } else {
        v.blades
            .iter()
            .map(|&b| &alg.field_names[b as usize])
            .collect()
    };
    quote!(Value { ty: #ty, blades: &[#(#blades),*], fields: &[#(#fields),*] })
}

fn type_value(alg: &Algebra, i: usize) -> Value {
    Value {
        ty: alg.types[i].name.to_string(),
        blades: alg.types[i].blades.clone(),
        scalar: false,
    }
}

fn scalar_value() -> Value {
    Value {
        ty: "Scalar".into(),
        blades: vec![0],
        scalar: true,
    }
}

/// The functions to emit: for every ordered pair of listed types, every product whose result
/// is the scalar or a listed type and is not identically zero; per listed type, `add`, `sub`,
/// `scale` and `reverse`.
fn functions(alg: &Algebra, listed: &[usize]) -> Vec<Function> {
    let mut out = Vec::new();
    for &i in listed {
        let t = &alg.types[i];
        let name = t.name.to_string();
        let linear = |sign: fn(Blade) -> i32| -> Body {
            t.blades
                .iter()
                .map(|&b| (b, vec![(sign(b), b, None)]))
                .collect()
        };
        for op in ["add", "sub"] {
            out.push(Function {
                name: format!("{name}_{op}_{name}"),
                operation: op,
                inputs: vec![type_value(alg, i), type_value(alg, i)],
                output: type_value(alg, i),
                body: linear(|_| 1),
            });
        }
        out.push(Function {
            name: format!("{name}_scale"),
            operation: "scale",
            inputs: vec![type_value(alg, i), scalar_value()],
            output: type_value(alg, i),
            body: t
                .blades
                .iter()
                .map(|&b| (b, vec![(1, b, Some(0))]))
                .collect(),
        });
        out.push(Function {
            name: format!("{name}_reverse"),
            operation: "reverse",
            inputs: vec![type_value(alg, i)],
            output: type_value(alg, i),
            body: linear(blade::reverse_sign),
        });
    }
    for &a in listed {
        for &b in listed {
            for kind in Product::ALL {
                let model = alg.bilinear(kind, &alg.types[a].blades, &alg.types[b].blades);
                if model.outputs.iter().all(|(_, t)| t.is_empty()) {
                    continue;
                }
                let output = match model.output {
                    Output::Scalar => scalar_value(),
                    Output::Type(o) if listed.contains(&o) => type_value(alg, o),
                    Output::Type(_) => continue,
                };
                let op = product_name(kind);
                let body = model
                    .outputs
                    .iter()
                    .map(|(o, terms)| {
                        let terms = terms
                            .iter()
                            .map(|&Term { sign, lhs, rhs }| (sign, lhs, Some(rhs)))
                            .collect();
                        (*o, terms)
                    })
                    .collect();
                out.push(Function {
                    name: format!("{}_{op}_{}", alg.types[a].name, alg.types[b].name),
                    operation: op,
                    inputs: vec![type_value(alg, a), type_value(alg, b)],
                    output,
                    body,
                });
            }
        }
    }
    out
}

/// Access to blade `b` of parameter `p`.
fn access(alg: &Algebra, f: &Function, param: usize, b: Blade) -> String {
    let name = ["a", "b"][param];
    if f.inputs[param].scalar {
        name.to_string()
    } else {
        format!("{name}.{}", alg.field_names[b as usize])
    }
}

/// One output blade as a left-to-right signed sum.
fn blade_expr(alg: &Algebra, f: &Function, terms: &[SignedTerm], arith: Arith) -> String {
    let mut acc = String::new();
    for (k, &(sign, l, r)) in terms.iter().enumerate() {
        let lhs = access(alg, f, 0, l);
        // `add`/`sub` read the same blade of both parameters.
        let term = match (f.operation, r) {
            ("add" | "sub", _) => {
                let rhs = access(alg, f, 1, l);
                let op = if f.operation == "add" { "add" } else { "sub" };
                match arith {
                    Arith::Plain => format!("{lhs} {} {rhs}", if op == "add" { "+" } else { "-" }),
                    Arith::Ring => format!("scalar_{op}({lhs}, {rhs})"),
                }
            }
            (_, Some(r)) => {
                let rhs = access(alg, f, 1, r);
                match arith {
                    Arith::Plain => format!("{lhs} * {rhs}"),
                    Arith::Ring => format!("scalar_mul({lhs}, {rhs})"),
                }
            }
            (_, None) => lhs,
        };
        acc = match (k, sign < 0, arith) {
            (0, false, _) => term,
            (0, true, Arith::Plain) => format!("-({term})"),
            (0, true, Arith::Ring) => format!("scalar_neg({term})"),
            (_, false, Arith::Plain) => format!("{acc} + {term}"),
            (_, true, Arith::Plain) => format!("{acc} - {term}"),
            (_, false, Arith::Ring) => format!("scalar_add({acc}, {term})"),
            (_, true, Arith::Ring) => format!("scalar_sub({acc}, {term})"),
        };
    }
    if acc.is_empty() {
        acc = match arith {
            Arith::Plain => "Scalar(0.0)".into(),
            Arith::Ring => "scalar_zero()".into(),
        };
    }
    acc
}

fn source(alg: &Algebra, listed: &[usize], functions: &[Function], arith: Arith) -> String {
    let mut s = String::new();
    let label = &alg.module;
    let _ = writeln!(
        s,
        "// Generated by ga_macros::algebra! for `{label}`: do not edit.\n"
    );
    for &i in listed {
        let t = &alg.types[i];
        let names: Vec<&str> = t
            .blades
            .iter()
            .map(|&b| alg.blade_names[b as usize].as_str())
            .collect();
        let _ = writeln!(s, "// {}: {}", t.name, names.join(", "));
        let _ = writeln!(s, "struct {} {{", t.name);
        for &b in &t.blades {
            let _ = writeln!(s, "    {}: Scalar,", alg.field_names[b as usize]);
        }
        let _ = writeln!(s, "}}\n");
    }
    for f in functions {
        let params: Vec<String> = f
            .inputs
            .iter()
            .enumerate()
            .map(|(k, v)| format!("{}: {}", ["a", "b"][k], v.ty))
            .collect();
        let _ = writeln!(
            s,
            "fn {}({}) -> {} {{",
            f.name,
            params.join(", "),
            f.output.ty
        );
        let exprs: Vec<String> = f
            .output
            .blades
            .iter()
            .map(|o| {
                let terms = f
                    .body
                    .iter()
                    .find(|(b, _)| b == o)
                    .map(|(_, t)| t.as_slice())
                    .unwrap_or(&[]);
                blade_expr(alg, f, terms, arith)
            })
            .collect();
        if f.output.scalar {
            let _ = writeln!(s, "    return {};", exprs[0]);
        } else {
            let _ = writeln!(s, "    return {}(", f.output.ty);
            for e in exprs {
                let _ = writeln!(s, "        {e},");
            }
            let _ = writeln!(s, "    );");
        }
        let _ = writeln!(s, "}}\n");
    }
    s
}
