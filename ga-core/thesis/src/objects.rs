//! The objects the checks build from our own conventions (never from the thesis's formulas):
//! conformal points `2·up(x)`, `n_inf`, `n̄`, the pseudoscalar, the auxiliary-symbol forms of the
//! primitives, and the names that `computed` and printed expressions may use.

use ga_core::symbolic::Poly;

use crate::multivector::SymMultivector;
use crate::products::{gp, rev, wedge, Generated, Own};
use crate::scope::Scope;

/// The point letters of x1 … x8.
const LETTERS: [&str; 8] = ["a", "b", "c", "d", "q", "w", "p", "z"];

/// Names of the `computed` expressions, built from our conventions (not from the thesis's
/// formulas): `P1` … `P8` = 2·up(x_i), `X` = 2·up(x), `n` = n_inf, `nbar` = −2 n_0, `I` = e12345,
/// the rotor `R` = co − e3e1 si and its reverse `Rt`, and the auxiliary-symbol forms of the
/// primitives `L_alpha`, `L_beta`, `Pi_omega`, `Pi_lambda`, `E_mu`, `E_lambda`.
pub(crate) fn computed_name(name: &str) -> Option<SymMultivector> {
    if let Some(k) = name.strip_prefix('P').and_then(|k| k.parse::<usize>().ok()) {
        return LETTERS.get(k.wrapping_sub(1)).map(|l| point_of(l));
    }
    let rotor = || sc(p("co")).sub(&gp(&aux_mv("e3e1"), &sc(p("si"))));
    Some(match name {
        "X" => point_of("a"),
        "n" => n_inf(),
        "nbar" | "n̄" => n_bar(),
        "I" => pseudo(),
        "R" => rotor(),
        "Rt" => rev(&rotor()),
        _ => return aux_form(name).map(|t| aux_mv(&t)),
    })
}

/// Evaluates a `computed` expression with the generated products.
pub(crate) fn computed_in(scope: &Scope, text: &str) -> SymMultivector {
    scope
        .evaluate(text, &Generated, &computed_name)
        .unwrap_or_else(|e| panic!("computed expression `{text}`: {e}"))
}

// ---------------------------------------------------------------------------------------------
// Helpers.

pub(crate) fn p(s: &str) -> Poly {
    Poly::parse(s).expect("valid polynomial")
}
pub(crate) fn sc(x: Poly) -> SymMultivector {
    SymMultivector::scalar(x)
}
pub(crate) fn int(n: i64) -> SymMultivector {
    sc(Poly::from(n))
}
pub(crate) fn blade(mask: u8) -> SymMultivector {
    SymMultivector::blade(mask, Poly::from(1))
}
pub(crate) fn n_inf() -> SymMultivector {
    blade(8).add(&blade(16))
}
/// The thesis's n̄ = e − ē = −2 n_0.
pub(crate) fn n_bar() -> SymMultivector {
    blade(8).sub(&blade(16))
}
pub(crate) fn pseudo() -> SymMultivector {
    blade(31)
}
pub(crate) fn vec3(c: [Poly; 3]) -> SymMultivector {
    let [x, y, z] = c;
    SymMultivector::blade(1, x)
        .add(&SymMultivector::blade(2, y))
        .add(&SymMultivector::blade(4, z))
}
pub(crate) fn coords(letter: &str) -> [Poly; 3] {
    [1, 2, 3].map(|i| Poly::var(&format!("{letter}{i}")))
}
/// Our conformal point scaled to the thesis's: 2·up(x) = 2x + |x|² n_inf + 2 n_0, with
/// 2 n_0 = e5 − e4 (built from our conventions, not from the thesis's formula).
pub(crate) fn point2(c: [Poly; 3]) -> SymMultivector {
    let x = vec3(c);
    let x2 = gp(&x, &x).get(0);
    let two_n0 = blade(16).sub(&blade(8));
    x.scale(&Poly::from(2))
        .add(&n_inf().scale(&x2))
        .add(&two_n0)
}
pub(crate) fn point_of(letter: &str) -> SymMultivector {
    point2(coords(letter))
}
pub(crate) fn point_at(x: [i64; 3]) -> SymMultivector {
    point2(x.map(Poly::from))
}
pub(crate) fn wedge_all(items: &[SymMultivector]) -> SymMultivector {
    let mut acc = items[0].clone();
    for x in &items[1..] {
        acc = wedge(&acc, x);
    }
    acc
}
/// Thesis dual `A* = I A`.
pub(crate) fn thesis_dual(a: &SymMultivector) -> SymMultivector {
    gp(&pseudo(), a)
}
/// Reads a printed formula (the thesis's notation, [`SymMultivector`]'s own products); the
/// names `L_alpha` … `E_lambda` stand for the auxiliary-symbol forms of the primitives.
pub(crate) fn parse_in(scope: &Scope, text: &str) -> SymMultivector {
    scope
        .evaluate(text, &Own, &|name| printed_name(scope, name))
        .unwrap_or_else(|e| panic!("fixture expression `{text}`: {e}"))
}

/// Names of printed formulas beyond [`Scope::parse`]'s: the auxiliary-symbol forms, and the
/// thesis's point `X = 2x + x²n − n̄` of (A.86).
pub(crate) fn printed_name(scope: &Scope, name: &str) -> Option<SymMultivector> {
    if name == "X" {
        return scope.parse("2x + x^2 n - nbar").ok();
    }
    aux_form(name).map(|t| aux_mv(&t))
}

/// The auxiliary-symbol form named `L_alpha`, `L_beta`, `Pi_omega`, `Pi_lambda`, `E_mu` or
/// `E_lambda`.
pub(crate) fn aux_form(name: &str) -> Option<String> {
    Some(match name {
        "L_alpha" => line_aux("alpha"),
        "L_beta" => line_aux("beta"),
        "Pi_omega" => plane_aux("omega"),
        "Pi_lambda" => plane_aux("lambda"),
        "E_mu" => sphere_aux("mu"),
        "E_lambda" => sphere_aux("lambda"),
        _ => return None,
    })
}
/// Replaces `u^2` by `1 ± v^2` (reduction modulo u² ∓ v² = 1: `sign = -1` gives the circle
/// u² + v² = 1, `sign = +1` the hyperbola u² − v² = 1).
pub(crate) fn reduce_quadric(m: &SymMultivector, u: &str, v: &str, sign: i64) -> SymMultivector {
    m.map(|poly| {
        let mut out = Poly::default();
        for (c, vars) in poly.terms() {
            let mut t = Poly::constant(c);
            for (name, e) in vars {
                if name == u {
                    let rel = Poly::from(1) + Poly::var(v).pow(2) * Poly::from(sign);
                    t = t * rel.pow(e / 2) * Poly::var(u).pow(e % 2);
                } else {
                    t = t * Poly::var(&name).pow(e);
                }
            }
            out = out + t;
        }
        out
    })
}

// ---------------------------------------------------------------------------------------------
// Auxiliary-symbol forms of the primitives (A.16/4, A.31/8, A.39), validated by the `defs_*`
// entries against the primitives computed from points.

pub(crate) fn line_aux(s: &str) -> String {
    format!(
        "{s}1 e1e2e + {s}1 e1e2ē + {s}2 e2e3e + {s}2 e2e3ē + {s}3 e3e1e + {s}3 e3e1ē \
         - {s}4 e1eē - {s}5 e2eē - {s}6 e3eē"
    )
}
pub(crate) fn plane_aux(s: &str) -> String {
    format!("{s}1 e1e2e3e + {s}1 e1e2e3ē - {s}2 e1e2eē - {s}3 e2e3eē - {s}4 e3e1eē")
}
pub(crate) fn sphere_aux(s: &str) -> String {
    format!("{s}1 e1e2e3e + {s}2 e1e2e3ē - {s}3 e1e2eē - {s}4 e2e3eē - {s}5 e3e1eē")
}
pub(crate) fn aux_mv(text: &str) -> SymMultivector {
    Scope::new().parse(text).expect("aux form parses")
}
