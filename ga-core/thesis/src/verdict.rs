//! Verdicts: how a printed formula compares with the computed one, and the report's rows.

use std::fmt::Write as _;

use ga_core::scalar::Rational;
use ga_core::symbolic::Poly;

use crate::multivector::SymMultivector;
use crate::notation::{thesis_name, thesis_order, Notation};

/// The outcome of comparing a printed formula with the computed one.
#[derive(Clone, Debug, PartialEq)]
pub enum Comparison {
    /// Identical polynomials on every blade.
    Equal,
    /// `printed = factor · computed` for a rational factor other than 1.
    Scaled(Rational),
    /// Not proportional: the blades (thesis spelling) whose coefficients differ, with the
    /// printed and the computed coefficient (thesis sign convention).
    Differs(Vec<(String, Poly, Poly)>),
}

/// Compares a printed formula with the computed one.
pub fn compare(printed: &SymMultivector, computed: &SymMultivector) -> Comparison {
    if printed == computed {
        return Comparison::Equal;
    }
    if let Some(k) = printed.ratio_to(computed) {
        return Comparison::Scaled(k);
    }
    let mut diffs = Vec::new();
    for m in thesis_order() {
        let (a, b) = (printed.get(m), computed.get(m));
        if a != b {
            let (s, name) = thesis_name(m);
            let fix = |p: Poly| if s < 0 { -p } else { p };
            diffs.push((name, fix(a), fix(b)));
        }
    }
    Comparison::Differs(diffs)
}

// ---------------------------------------------------------------------------------------------
// Verdicts.

/// The verdict of one entry.
#[derive(Clone, Debug, PartialEq)]
pub enum Verdict {
    /// The printed formula is exactly the computed one.
    Confirmed,
    /// printed = factor · computed (`factor` printed, e.g. `-1`, `1/16`).
    Scaled(String),
    /// Not proportional; see the detail.
    Differs,
    /// A classification rule that agrees with the Euclidean ground truth on every case tried.
    RuleHolds,
    /// A classification rule that disagrees with the ground truth on some class of cases.
    RuleFails,
    /// A rule that fails with the printed formulas but holds once they are corrected.
    RuleHoldsCorrected,
    /// Only notation or a definition: nothing to compute (the detail says what it fixes and
    /// where it is checked in use).
    Notation,
}

impl Verdict {
    /// Short label for the table.
    pub fn label(&self) -> String {
        match self {
            Verdict::Confirmed => "confirmed".into(),
            Verdict::Scaled(k) => format!("confirmed up to factor {k}"),
            Verdict::Differs => "differs (erratum)".into(),
            Verdict::RuleHolds => "rule correct".into(),
            Verdict::RuleFails => "rule wrong".into(),
            Verdict::RuleHoldsCorrected => "rule correct, printed formulas wrong".into(),
            Verdict::Notation => "notation (nothing to compute)".into(),
        }
    }
    /// Stable key for tests.
    pub fn key(&self) -> &'static str {
        match self {
            Verdict::Confirmed => "confirmed",
            Verdict::Scaled(_) => "scaled",
            Verdict::Differs => "differs",
            Verdict::RuleHolds => "rule-holds",
            Verdict::RuleFails => "rule-fails",
            Verdict::RuleHoldsCorrected => "rule-holds-corrected",
            Verdict::Notation => "notation",
        }
    }
}

/// One row of the report.
#[derive(Clone, Debug)]
pub struct Row {
    /// Equation number.
    pub id: String,
    /// Title from the fixture.
    pub title: String,
    /// Where it is printed.
    pub source: String,
    /// What was compared with what.
    pub method: String,
    /// The verdict.
    pub verdict: Verdict,
    /// Markdown details: differing terms, corrections, case counts.
    pub detail: String,
    /// For errata: the correction and the verdict of the corrected form.
    pub correction: Option<(String, Verdict)>,
    /// The keys (in [`ERRATA`](crate::ERRATA)) of the errors this entry shows.
    pub errata: Vec<String>,
}

pub(crate) fn rat_str(r: &Rational) -> String {
    if r.is_integer() {
        r.numer().to_string()
    } else {
        format!("{}/{}", r.numer(), r.denom())
    }
}

/// Verdict from comparing a printed multivector with the computed one; details list the
/// differing blades and the corrected formula.
pub(crate) fn judge(
    printed: &SymMultivector,
    computed: &SymMultivector,
    detail: &mut String,
) -> Verdict {
    match compare(printed, computed) {
        Comparison::Equal => Verdict::Confirmed,
        Comparison::Scaled(k) => Verdict::Scaled(rat_str(&k)),
        Comparison::Differs(diffs) => {
            let _ = writeln!(detail, "Terms that differ (thesis spelling and sign):\n");
            for (blade, a, b) in diffs.iter().take(12) {
                let _ = writeln!(
                    detail,
                    "- `{blade}`: printed `{}`, computed `{}`",
                    short(&a.to_string()),
                    short(&b.to_string())
                );
            }
            if diffs.len() > 12 {
                let _ = writeln!(detail, "- … and {} more blades", diffs.len() - 12);
            }
            Verdict::Differs
        }
    }
}

/// Verdict of a chain of printed steps `lhs = s1 = s2 = …`, each compared with the computed
/// value: confirmed when every step is; a factor when every step agrees up to the same factor;
/// otherwise the steps that differ are listed.
pub(crate) fn judge_steps(
    steps: &[SymMultivector],
    computed: &SymMultivector,
    detail: &mut String,
) -> Verdict {
    if let [one] = steps {
        let v = judge(one, computed, detail);
        if v == Verdict::Differs {
            corrected(detail, computed);
        }
        return v;
    }
    let verdicts: Vec<Verdict> = steps
        .iter()
        .map(|s| judge(s, computed, &mut String::new()))
        .collect();
    if verdicts.iter().all(|v| *v == Verdict::Confirmed) {
        return Verdict::Confirmed;
    }
    let _ = writeln!(
        detail,
        "The printed steps, each against the computed value:\n"
    );
    for (k, v) in verdicts.iter().enumerate() {
        let _ = writeln!(detail, "- step {}: {}", k + 1, v.label());
    }
    detail.push('\n');
    if let Some(k) = verdicts.iter().position(|v| *v == Verdict::Differs) {
        let _ = writeln!(detail, "Step {}:\n", k + 1);
        judge(&steps[k], computed, detail);
        corrected(detail, computed);
        return Verdict::Differs;
    }
    let factors: Vec<&Verdict> = verdicts
        .iter()
        .filter(|v| **v != Verdict::Confirmed)
        .collect();
    if factors.windows(2).all(|w| w[0] == w[1]) && factors.len() == verdicts.len() {
        return factors[0].clone();
    }
    let _ = writeln!(
        detail,
        "The steps do not agree with each other up to one factor."
    );
    Verdict::Differs
}

pub(crate) fn short(s: &str) -> String {
    if s.chars().count() > 400 {
        let head: String = s.chars().take(400).collect();
        format!("{head} … ({} characters)", s.chars().count())
    } else {
        s.to_string()
    }
}

pub(crate) fn corrected(detail: &mut String, m: &SymMultivector) {
    let _ = writeln!(
        detail,
        "\nCorrected (computed), thesis notation:\n\n```text\n{}\n```",
        short(&m.to_notation(Notation::Thesis))
    );
}

pub(crate) fn invert(k: &str) -> String {
    let r = Poly::parse(k)
        .ok()
        .and_then(|p| p.as_constant())
        .filter(|r| *r != Rational::from_integer(0.into()));
    match r {
        Some(r) => rat_str(&(Rational::from_integer(1.into()) / r)),
        None => k.to_string(),
    }
}
