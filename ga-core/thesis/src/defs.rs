//! The definitions of the auxiliary symbols (α, β, ω, μ, λ, …): the coefficients of each
//! primitive computed from points, against the thesis's `let` definitions.

use std::fmt::Write as _;

use ga_core::scalar::Rational;
use ga_core::symbolic::Poly;

use crate::fixture::{Entry, Fixture};
use crate::multivector::SymMultivector;
use crate::objects::{aux_mv, coords, line_aux, n_inf, plane_aux, point_of, sphere_aux, wedge_all};
use crate::reading::Ctx;
use crate::scope::Scope;
use crate::verdict::{judge, rat_str, short, Verdict};

/// The primitive computed from points, its aux form, and the point letters of each `defs`
/// entry.
fn defs_target(kind: &str) -> Option<(SymMultivector, String)> {
    let pts = |ls: &[&str]| ls.iter().map(|l| point_of(l)).collect::<Vec<_>>();
    Some(match kind {
        "defs_line" => {
            let mut v = pts(&["a", "b"]);
            v.push(n_inf());
            (wedge_all(&v), line_aux("beta"))
        }
        "defs_plane_123" | "defs_plane_345" | "defs_plane_456" | "defs_plane_567" => {
            let (ls, sym): (&[&str], &str) = match kind {
                "defs_plane_123" => (&["a", "b", "c"], "omega"),
                "defs_plane_345" => (&["c", "d", "q"], "omega"),
                "defs_plane_456" => (&["d", "q", "w"], "lambda"),
                _ => (&["q", "w", "p"], "omega"),
            };
            let mut v = pts(ls);
            v.push(n_inf());
            (wedge_all(&v), plane_aux(sym))
        }
        "defs_line_alpha" | "defs_line_34" => {
            let (ls, sym): (&[&str], &str) = if kind == "defs_line_alpha" {
                (&["a", "b"], "alpha")
            } else {
                (&["c", "d"], "beta")
            };
            let mut v = pts(ls);
            v.push(n_inf());
            (wedge_all(&v), line_aux(sym))
        }
        "defs_sphere_1234" => (wedge_all(&pts(&["a", "b", "c", "d"])), sphere_aux("mu")),
        "defs_sphere_3456" => (wedge_all(&pts(&["c", "d", "q", "w"])), sphere_aux("mu")),
        "defs_sphere_5678" => (wedge_all(&pts(&["q", "w", "p", "z"])), sphere_aux("lambda")),
        _ => return None,
    })
}

/// The determinant of three points given by coordinate letters.
fn det3(l: [&str; 3]) -> Poly {
    let [a, b, c] = l.map(coords);
    let t = |i: usize, j: usize, k: usize| &(&a[i] * &b[j]) * &c[k];
    t(0, 1, 2) + t(1, 2, 0) + t(2, 0, 1) - t(1, 0, 2) - t(2, 1, 0) - t(0, 2, 1)
}

pub(crate) fn check_defs(
    fx: &Fixture,
    e: &Entry,
    scope: &Scope,
    kind: &str,
    method: &mut String,
    detail: &mut String,
) -> Verdict {
    if kind == "defs_line_pair" {
        let (mut m1, mut m2) = (String::new(), String::new());
        let v1 = check_defs(fx, e, scope, "defs_line_alpha", &mut m1, detail);
        let v2 = check_defs(fx, e, scope, "defs_line_34", &mut m2, detail);
        *method = format!("{m1}; {m2}");
        return if v1 == v2 { v1 } else { Verdict::Differs };
    }
    if kind == "defs_alpha" {
        // α_ijk = det(x_i, x_j, x_k) of the section's four sphere points.
        let letters: [&str; 4] = match e.id.as_str() {
            "II.63" => ["c", "d", "q", "w"],
            "II.80" => ["q", "w", "p", "z"],
            _ => ["a", "b", "c", "d"],
        };
        *method = format!(
            "each α_ijk against det(x_i, x_j, x_k) of the sphere's points ({})",
            letters.join(", ")
        );
        let expected = [
            ("alpha124", [0, 1, 3]),
            ("alpha234", [1, 2, 3]),
            ("alpha314", [2, 0, 3]),
            ("alpha123", [0, 1, 2]),
        ];
        let ex = scope.expansions().expect("expands");
        let mut all_ok = true;
        for (name, idx) in expected {
            let want = det3(idx.map(|i| letters[i]));
            let got = ex
                .iter()
                .rev()
                .find(|(n, _)| n == name)
                .map(|(_, p)| p.clone())
                .unwrap_or_default();
            if got != want {
                all_ok = false;
                let _ = writeln!(detail, "- `{name}`: printed `{got}`, should be `{want}`");
            }
        }
        return if all_ok {
            Verdict::Confirmed
        } else {
            Verdict::Differs
        };
    }
    let Some((computed, aux)) = defs_target(kind) else {
        *detail = format!("no target for `{kind}`");
        return Verdict::Differs;
    };
    *method = format!(
        "the primitive computed from its points against `{aux}` with the printed definitions"
    );
    let printed = scope.expand(&aux_mv(&aux)).expect("expands");
    let v = judge(&printed, &computed, &mut String::new());
    if v != Verdict::Differs {
        return v;
    }
    // Diagnose symbol by symbol: the aux form's coefficient on each blade is ±symbol.
    let _ = writeln!(detail, "Symbols whose printed definition is wrong:\n");
    let aux_m = aux_mv(&aux);
    let ex = scope.expansions().expect("expands");
    // The scale: the ratio on the first blade whose symbol is right.
    let mut ratios: Vec<(String, Option<Rational>, Poly)> = Vec::new();
    for (mask, coef) in aux_m.iter() {
        let name = coef.variables()[0].clone();
        let sign =
            coef.as_constant().is_none() && coef.terms()[0].0 < Rational::from_integer(0.into());
        let want = computed.get(mask);
        let want = if sign { -want } else { want };
        let got = ex
            .iter()
            .rev()
            .find(|(n, _)| *n == name)
            .map(|(_, p)| p.clone())
            .unwrap_or_default();
        if !ratios.iter().any(|(n, _, _)| *n == name) {
            ratios.push((name, got.ratio_to(&want), want));
        }
    }
    let mut counts: Vec<(Rational, usize)> = Vec::new();
    for (_, r, _) in &ratios {
        if let Some(r) = r {
            match counts.iter_mut().find(|(x, _)| x == r) {
                Some((_, c)) => *c += 1,
                None => counts.push((r.clone(), 1)),
            }
        }
    }
    counts.sort_by_key(|b| std::cmp::Reverse(b.1));
    let k = counts.first().map(|(r, _)| r.clone());
    for (name, r, want) in &ratios {
        if r.is_some() && *r == k {
            continue;
        }
        let correct = match &k {
            Some(k) => want * &Poly::constant(k.clone()),
            None => want.clone(),
        };
        let same_as = find_equal_let(fx, &correct);
        let _ = writeln!(
            detail,
            "- `{name}` should be `{}`{}",
            short(&correct.to_string()),
            same_as.map(|s| format!(" (= {s})")).unwrap_or_default()
        );
    }
    if let Some(k) = k {
        let _ = writeln!(
            detail,
            "\nWith the corrected definitions, primitive = {} · (aux form).",
            rat_str(&(Rational::from_integer(1.into()) / k))
        );
    }
    Verdict::Differs
}

/// An entry's `let` whose expansion equals `value`, as `μ3 of (II.72)`.
fn find_equal_let(fx: &Fixture, value: &Poly) -> Option<String> {
    let printed = Ctx {
        fx,
        corrected: false,
    };
    for e in &fx.entries {
        if e.lets.is_empty() {
            continue;
        }
        let Ok(ex) = printed.scope(e).expansions() else {
            continue;
        };
        for (n, v) in ex {
            if e.lets.iter().any(|(m, _)| *m == n) && v == *value {
                return Some(format!("`{n}` of ({})", e.id));
            }
        }
    }
    None
}
