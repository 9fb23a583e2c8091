//! Parsing the `algebra!` declaration with syn. Only syntax is checked here; meaning (unknown
//! blades, duplicates, empty types) is checked by the model, which keeps the spans.

use proc_macro2::Span;
use syn::parse::{Parse, ParseStream};
use syn::{braced, bracketed, Attribute, Ident, LitInt, Token};

use crate::errors::Errors;

/// One signature entry: the square of a generator, `+1`, `-1` or `0`.
pub struct SignatureEntry {
    pub value: i32,
}

/// Which blades a declared type holds.
pub enum BladeSpec {
    /// `grade 1` or `grades 0 2 4`.
    Grades(Vec<(usize, Span)>, Span),
    /// `[1, e12, e13]`; the scalar blade is written `1`.
    List(Vec<(String, Span)>, Span),
}

/// `Name: grades 0 2`, with its doc attributes.
pub struct TypeDecl {
    pub attrs: Vec<Attribute>,
    pub name: Ident,
    pub spec: BladeSpec,
}

/// The whole declaration.
pub struct Declaration {
    pub name: Ident,
    pub signature: Vec<SignatureEntry>,
    pub signature_span: Span,
    /// `metric: [[1, 0], [0, -1]]`: the bilinear form of the basis vectors, instead of a
    /// `signature` (which is its diagonal); rows as written, with their spans.
    pub metric: Option<(Vec<Vec<i32>>, Span)>,
    pub basis: Option<Vec<Ident>>,
    pub basis_span: Span,
    pub types: Vec<TypeDecl>,
    pub types_span: Span,
    pub dense: Option<Ident>,
    /// `attributes: [#[...], ...]`: outer attributes put on every generated struct.
    pub attributes: Vec<Attribute>,
    /// `wgsl: [Vector, ...]`: the types to emit WGSL shader source for (opt-in).
    pub wgsl: Option<Vec<Ident>>,
    /// `functions: { fn f(m: Motor, x: Vector) -> Vector { ... } ... }`: whole expressions to
    /// generate as single straight-line functions (see `expr`).
    pub functions: Vec<syn::ItemFn>,
    /// `path: ::ga_core::cga_null`: where the types live, for functions generated outside the
    /// algebra's module (the `expressions!` macro).
    pub path: Option<syn::Path>,
    /// Errors found while parsing that do not stop the model's checks (an unknown or repeated
    /// key): the model reports them together with its own.
    pub errors: Errors,
}

impl Parse for Declaration {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let mut name = None;
        let mut signature = None;
        let mut basis = None;
        let mut types = None;
        let mut dense = None;
        let mut attributes: Option<Vec<Attribute>> = None;
        // Every error found is reported, not only the first (syntax errors still stop parsing).
        let mut errors = Errors::default();
        let mut wgsl: Option<Vec<Ident>> = None;
        let mut metric: Option<(Vec<Vec<i32>>, Span)> = None;
        let mut functions: Option<Vec<syn::ItemFn>> = None;
        let mut path: Option<syn::Path> = None;
        let start = input.span();
        while !input.is_empty() {
            let key: Ident = input.parse()?;
            input.parse::<Token![:]>()?;
            let key_str = key.to_string();
            let given = matches!(
                (
                    key_str.as_str(),
                    &name,
                    &signature,
                    &basis,
                    &types,
                    &dense,
                    &attributes
                ),
                ("name", Some(_), ..)
                    | ("signature", _, Some(_), ..)
                    | ("basis", _, _, Some(_), ..)
                    | ("types", _, _, _, Some(_), ..)
                    | ("dense", _, _, _, _, Some(_), _)
                    | ("attributes", .., Some(_))
            );
            let given = given
                || (key_str == "wgsl" && wgsl.is_some())
                || (key_str == "metric" && metric.is_some())
                || (key_str == "functions" && functions.is_some())
                || (key_str == "path" && path.is_some());
            if (key_str == "metric" && signature.is_some())
                || (key_str == "signature" && metric.is_some())
            {
                errors.push(syn::Error::new(
                    key.span(),
                    "give either `signature` (an orthogonal basis) or `metric` (any symmetric \
                     bilinear form), not both",
                ));
            }
            if given {
                errors.push(syn::Error::new(
                    key.span(),
                    format!("`{key_str}` is given twice"),
                ));
            }
            match key_str.as_str() {
                "name" => {
                    name = Some(input.parse::<Ident>()?);
                }
                "signature" => {
                    signature = Some((parse_signature(input, &mut errors)?, key.span()));
                }
                "metric" => {
                    let content;
                    bracketed!(content in input);
                    let mut rows = Vec::new();
                    while !content.is_empty() {
                        let row;
                        bracketed!(row in content);
                        let mut entries = Vec::new();
                        while !row.is_empty() {
                            let mut sign = 1;
                            if row.peek(Token![-]) {
                                row.parse::<Token![-]>()?;
                                sign = -1;
                            } else if row.peek(Token![+]) {
                                row.parse::<Token![+]>()?;
                            }
                            let lit: LitInt = row.parse()?;
                            entries.push(sign * lit.base10_parse::<i32>()?);
                            if !row.is_empty() {
                                row.parse::<Token![,]>()?;
                            }
                        }
                        rows.push(entries);
                        if !content.is_empty() {
                            content.parse::<Token![,]>()?;
                        }
                    }
                    metric = Some((rows, key.span()));
                }
                "basis" => {
                    let content;
                    bracketed!(content in input);
                    let idents = content.parse_terminated(Ident::parse, Token![,])?;
                    basis = Some((idents.into_iter().collect::<Vec<_>>(), key.span()));
                }
                "types" => {
                    let content;
                    braced!(content in input);
                    let decls = content.parse_terminated(TypeDecl::parse, Token![,])?;
                    types = Some((decls.into_iter().collect::<Vec<_>>(), key.span()));
                }
                "dense" => {
                    dense = Some(input.parse::<Ident>()?);
                }
                "wgsl" => {
                    let content;
                    bracketed!(content in input);
                    let idents = content.parse_terminated(Ident::parse, Token![,])?;
                    wgsl = Some(idents.into_iter().collect::<Vec<_>>());
                }
                "attributes" => {
                    attributes = Some(parse_attributes(input)?);
                }
                "functions" => {
                    let content;
                    braced!(content in input);
                    let mut fns = Vec::new();
                    while !content.is_empty() {
                        fns.push(content.parse::<syn::ItemFn>()?);
                    }
                    functions = Some(fns);
                }
                "path" => {
                    path = Some(input.parse::<syn::Path>()?);
                }
                other => {
                    errors.push(syn::Error::new(
                        key.span(),
                        format!(
                            "unknown key `{other}`: expected one of `name`, `signature`, `metric`, \
                             `basis`, `types`, `dense`, `attributes`, `wgsl`, `functions`, `path`"
                        ),
                    ));
                    // Skip its value and go on checking the rest.
                    while !input.is_empty() && !input.peek(Token![,]) {
                        input.parse::<proc_macro2::TokenTree>()?;
                    }
                }
            }
            if !input.is_empty() {
                input.parse::<Token![,]>()?;
            }
        }
        let missing = |what: &str, example: &str| {
            syn::Error::new(start, format!("missing `{what}`, e.g. `{what}: {example}`"))
        };
        if name.is_none() {
            errors.push(missing("name", "cga"));
        }
        // A metric gives the signature as its diagonal (the model checks the matrix).
        if signature.is_none() {
            if let Some((rows, span)) = &metric {
                let diagonal = rows
                    .iter()
                    .enumerate()
                    .map(|(i, r)| SignatureEntry {
                        value: r.get(i).copied().unwrap_or(0),
                    })
                    .collect();
                signature = Some((diagonal, *span));
            }
        }
        if signature.is_none() {
            errors.push(missing("signature", "[+1, +1, +1, +1, -1]"));
        }
        if types.is_none() {
            errors.push(missing("types", "{ Vector: grade 1, Even: grades 0 2 }"));
        }
        if name.is_none() || signature.is_none() || types.is_none() {
            errors.finish()?;
        }
        let (Some(name), Some((signature, signature_span)), Some((types, types_span))) =
            (name, signature, types)
        else {
            return Err(missing("name", "cga")); // unreachable: reported above
        };
        let (basis, basis_span) = match basis {
            Some((b, s)) => (Some(b), s),
            None => (None, signature_span),
        };
        Ok(Declaration {
            name,
            signature,
            signature_span,
            metric,
            basis,
            basis_span,
            types,
            types_span,
            dense,
            attributes: attributes.unwrap_or_default(),
            wgsl,
            functions: functions.unwrap_or_default(),
            path,
            errors,
        })
    }
}

/// `[#[a], #[b], ...]`: outer attributes, commas between them optional.
fn parse_attributes(input: ParseStream) -> syn::Result<Vec<Attribute>> {
    let content;
    bracketed!(content in input);
    let mut attrs = Vec::new();
    while !content.is_empty() {
        if !content.peek(Token![#]) {
            return Err(content.error(
                "expected an outer attribute such as `#[derive(Debug)]` (attributes: [#[...], ...])",
            ));
        }
        attrs.extend(content.call(Attribute::parse_outer)?);
        if !content.is_empty() {
            content.parse::<Token![,]>()?;
        }
    }
    Ok(attrs)
}

fn parse_signature(input: ParseStream, errors: &mut Errors) -> syn::Result<Vec<SignatureEntry>> {
    let content;
    bracketed!(content in input);
    let mut entries = Vec::new();
    while !content.is_empty() {
        let mut sign = 1;
        if content.peek(Token![-]) {
            content.parse::<Token![-]>()?;
            sign = -1;
        } else if content.peek(Token![+]) {
            content.parse::<Token![+]>()?;
        }
        let lit: LitInt = content.parse().map_err(|e| {
            syn::Error::new(
                e.span(),
                "signature entries are `+1`, `-1` or `0` (the square of each generator)",
            )
        })?;
        let value: i32 = lit.base10_parse()?;
        if value > 1 {
            errors.push(syn::Error::new(
                lit.span(),
                format!(
                    "signature entry `{value}` is not allowed: a generator squares to `+1`, `-1` \
                     or `0`"
                ),
            ));
        }
        entries.push(SignatureEntry {
            value: sign * value,
        });
        if !content.is_empty() {
            content.parse::<Token![,]>()?;
        }
    }
    Ok(entries)
}

impl Parse for TypeDecl {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let attrs = input.call(Attribute::parse_outer)?;
        let name: Ident = input.parse()?;
        input.parse::<Token![:]>()?;
        let spec = if input.peek(syn::token::Bracket) {
            let content;
            let bracket = bracketed!(content in input);
            let mut blades = Vec::new();
            while !content.is_empty() {
                if content.peek(LitInt) {
                    let lit: LitInt = content.parse()?;
                    blades.push((lit.to_string(), lit.span()));
                } else {
                    let id: Ident = content.parse().map_err(|e| {
                        syn::Error::new(e.span(), "expected a blade name such as `e12`, or `1`")
                    })?;
                    blades.push((id.to_string(), id.span()));
                }
                if !content.is_empty() {
                    content.parse::<Token![,]>()?;
                }
            }
            BladeSpec::List(blades, bracket.span.join())
        } else {
            let kw: Ident = input.parse().map_err(|e| {
                syn::Error::new(
                    e.span(),
                    "expected `grade K`, `grades K L ...` or a blade list `[1, e12, ...]`",
                )
            })?;
            if kw != "grade" && kw != "grades" {
                return Err(syn::Error::new(
                    kw.span(),
                    format!(
                        "expected `grade K`, `grades K L ...` or a blade list `[1, e12, ...]`, \
                         found `{kw}`"
                    ),
                ));
            }
            let mut grades = Vec::new();
            while input.peek(LitInt) {
                let lit: LitInt = input.parse()?;
                grades.push((lit.base10_parse::<usize>()?, lit.span()));
            }
            BladeSpec::Grades(grades, kw.span())
        };
        Ok(TypeDecl { attrs, name, spec })
    }
}
