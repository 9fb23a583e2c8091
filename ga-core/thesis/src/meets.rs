//! The six intersections of Cap. II §3 (line–line … sphere–sphere): the definition
//! `B = (A ∨ C) = (I A)·C`, the closed forms of `B` and of `B²`, on the auxiliary-symbol forms
//! of the operands.

use std::fmt::Write as _;

use ga_core::symbolic::Poly;

use crate::fixture::Entry;
use crate::multivector::SymMultivector;
use crate::notation::{thesis_name, Notation};
use crate::objects::{aux_mv, blade, line_aux, parse_in, plane_aux, sphere_aux, thesis_dual};
use crate::products::{gp, lc, regressive};
use crate::reading::Ctx;
use crate::scope::Scope;
use crate::verdict::{corrected, judge, Verdict};
/// The two operands (aux forms) of each intersection, in the order of the formula
/// `B = (I A) · C`.
pub(crate) fn meet_operands(kind: &str) -> (String, String, &'static str) {
    match kind {
        "meet_line_line" => (line_aux("alpha"), line_aux("beta"), "(I L1) · L2"),
        "meet_line_plane" => (plane_aux("omega"), line_aux("beta"), "(I Π) · L"),
        "meet_line_sphere" => (sphere_aux("mu"), line_aux("beta"), "(I E) · L"),
        "meet_plane_plane" => (plane_aux("omega"), plane_aux("lambda"), "(I Π1) · Π2"),
        "meet_sphere_plane" => (sphere_aux("mu"), plane_aux("omega"), "(I E) · Π"),
        _ => (sphere_aux("mu"), sphere_aux("lambda"), "(I E1) · E2"),
    }
}

/// The correct B of an intersection, in auxiliary symbols: `(I A) ⌋ C` for the contraction
/// reading and `(I A) C` for the geometric-product reading.
pub(crate) fn meet_aux(kind: &str) -> (SymMultivector, SymMultivector) {
    let (a, c, _) = meet_operands(kind);
    let (a, c) = (aux_mv(&a), aux_mv(&c));
    let ia = thesis_dual(&a);
    (lc(&ia, &c), gp(&ia, &c))
}

/// The definition `B = (A ∨ C) = (I A)·C` of an intersection, on the auxiliary-symbol forms
/// of the operands: the contraction against our regressive product (generated).
pub(crate) fn check_meet_def(
    ctx: &Ctx,
    e: &Entry,
    kind: &str,
    method: &mut String,
    detail: &mut String,
) -> Verdict {
    let meet = kind.replacen("meet_def_", "meet_", 1);
    let (a_text, c_text, label) = meet_operands(&meet);
    let (a, c) = (aux_mv(&a_text), aux_mv(&c_text));
    let contraction = lc(&thesis_dual(&a), &c);
    let reg = regressive(&a, &c);
    *method = format!(
        "{label} = (I A) ⌋ C against our regressive product A ∨ C = undual(dual A ∧ dual C) \
         (both generated), A, C the auxiliary-symbol forms of the operands"
    );
    let v = judge(&contraction, &reg, &mut String::new());
    let factor = match &v {
        Verdict::Confirmed => "1".to_string(),
        Verdict::Scaled(k) => k.clone(),
        _ => "no constant".to_string(),
    };
    let _ = writeln!(
        detail,
        "(I A) ⌋ C = {factor} · (A ∨ C), of grade {}: the meet, as the text says (∨ is fixed only \
         up to such a factor by its references).",
        grades(&reg)
    );
    if meet != "meet_line_line" {
        return v;
    }
    let other = gp(&a, &thesis_dual(&c)).grade(1);
    let _ = writeln!(
        detail,
        "\nThe third form (L1)·(IL2), read as the grade-1 part of L1 (I L2): {}.",
        if other == contraction {
            "equal to (I L1) ⌋ L2 (I is central)"
        } else {
            "**different** from (I L1) ⌋ L2"
        }
    );
    let starred = thesis_dual(&reg);
    let _ = writeln!(
        detail,
        "\nThe starred form (L1 ∨ L2)* = I (L1 ∨ L2) has grade {}, B has grade {}: the star does \
         not belong (the other five intersections, (II.55) … (II.77), write B = (A ∨ C) without it).",
        grades(&starred),
        grades(&contraction)
    );
    if ctx.corrected || e.field("erratum").is_none() {
        v
    } else {
        Verdict::Differs
    }
}

pub(crate) fn check_meet(
    formula: &str,
    scope: &Scope,
    kind: &str,
    method: &mut String,
    detail: &mut String,
) -> Verdict {
    let (a, c, label) = meet_operands(kind);
    let printed = parse_in(scope, formula);
    let (contraction, geometric) = meet_aux(kind);
    *method = format!(
        "{label} in the auxiliary symbols, operands {} and {} (aux forms validated by the \
         `defs` rows), with ⌋ the left contraction; the full geometric product is tried too",
        a.split_whitespace().next().unwrap_or(""),
        c.split_whitespace().next().unwrap_or("")
    );
    let _ = writeln!(detail, "Operands: `A = {a}`, `C = {c}`.\n");
    let v = judge(&printed, &contraction, &mut String::new());
    if v != Verdict::Differs {
        let _ = writeln!(detail, "Matches the left contraction (I A) ⌋ C.");
        return v;
    }
    let low = geometric.sub(&geometric.grade(5));
    if geometric.grade(5) != SymMultivector::zero()
        && judge(&printed, &low, &mut String::new()) != Verdict::Differs
    {
        let _ = writeln!(
            detail,
            "The printed B is exactly ⟨(I A) C⟩₁ + ⟨(I A) C⟩₃, the geometric product without its \
             grade-5 part `{}`. It is neither an inner product (the left contraction (I A) ⌋ C, \
             and any grade-|r−s| product, is the grade-1 part alone) nor the full geometric \
             product. The corrected B below is the contraction; the classification (II.54) uses \
             only its coefficient, which is right.",
            geometric.grade(5).to_notation(Notation::Thesis)
        );
        corrected(detail, &contraction);
        return Verdict::Differs;
    }
    let vg = judge(&printed, &geometric, &mut String::new());
    if vg != Verdict::Differs {
        let _ = writeln!(
            detail,
            "Matches the full geometric product (I A) C (grades {}), not the contraction.",
            grades(&geometric)
        );
        return vg;
    }
    let _ = writeln!(detail, "Compared with the left contraction (I A) ⌋ C:\n");
    let v = judge(&printed, &contraction, detail);
    corrected(detail, &contraction);
    if geometric != contraction {
        let _ = writeln!(
            detail,
            "\nThe full geometric product (I A) C has grades {} and does not match either.",
            grades(&geometric)
        );
    }
    v
}

pub(crate) fn grades(m: &SymMultivector) -> String {
    let mut g: Vec<u32> = m.iter().map(|(k, _)| k.count_ones()).collect();
    g.sort_unstable();
    g.dedup();
    g.iter()
        .map(|x| x.to_string())
        .collect::<Vec<_>>()
        .join(", ")
}

pub(crate) fn check_square(
    formula: &str,
    scope: &Scope,
    kind: &str,
    method: &mut String,
    detail: &mut String,
) -> Verdict {
    let meet_kind = kind.replacen("square_", "meet_", 1);
    let printed = parse_in(scope, formula);
    let (b, _) = meet_aux(&meet_kind);
    let b2 = gp(&b, &b);
    *method =
        "scalar part of B B, B the correct (computed) intersection in the auxiliary symbols".into();
    let others = b2.sub(&b2.grade(0));
    if !others.is_zero() {
        let _ = writeln!(
            detail,
            "B B is not a scalar: it also has grade(s) {}; the scalar part is compared.\n",
            grades(&others)
        );
    }
    let v = judge(&printed, &b2.grade(0), &mut String::new());
    if v == Verdict::Differs {
        // Term by term: ⟨B B⟩₀ = Σ (blade²) · coefficient², one square per blade of B.
        let _ = writeln!(
            detail,
            "Term by term, ⟨B B⟩₀ = Σ (blade)² · (coefficient)²:\n"
        );
        let printed_terms = top_level_terms(formula)
            .into_iter()
            .filter_map(|t| scope.parse(&t).ok().map(|m| m.get(0)))
            .collect::<Vec<_>>();
        let mut text = Vec::new();
        for (mask, c) in b.iter() {
            let s2 = gp(&blade(mask), &blade(mask)).get(0);
            let (sgn, name) = thesis_name(mask);
            let c_thesis = if sgn < 0 { -c } else { c.clone() };
            let want = &s2 * &c.pow(2);
            let neg = s2 != Poly::from(1);
            let state = if printed_terms.contains(&want) {
                "present"
            } else if printed_terms.contains(&(-&want)) {
                "**printed with the wrong sign**"
            } else {
                "**missing or different**"
            };
            let _ = writeln!(
                detail,
                "- `{name}`: {}({})² — {state}",
                if neg { "−" } else { "+" },
                c_thesis
            );
            text.push(format!("{}({})^2", if neg { "- " } else { "+ " }, c_thesis));
        }
        let _ = writeln!(
            detail,
            "\nCorrected (computed):\n\n```text\n{}\n```",
            text.join(" ").trim_start_matches("+ ")
        );
    }
    v
}

/// Splits `a - (b + c)^2 + d` into its top-level signed terms `["a", "-(b + c)^2", "+d"]`.
fn top_level_terms(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut depth = 0;
    let mut cur = String::new();
    for ch in text.chars() {
        match ch {
            '(' => depth += 1,
            ')' => depth -= 1,
            '+' | '-' if depth == 0 && !cur.trim().is_empty() => {
                out.push(std::mem::take(&mut cur));
            }
            _ => {}
        }
        cur.push(ch);
    }
    if !cur.trim().is_empty() {
        out.push(cur);
    }
    out
}
