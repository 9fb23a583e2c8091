//! The report: the verdict table, the entry list and the Markdown document
//! `docs/thesis-derivations.md`, from the rows of a run.

use std::fmt::Write as _;

use crate::corrections::{lookup2, ERRATA};
use crate::fixture::{Fixture, FORMULAS};
use crate::verdict::{invert, Row, Verdict};

/// One-line summaries of the classification rules that fail, for the report's table.
pub const NOTES: &[(&str, &str)] = &[
    (
        "II.54",
        "the scalar is the coplanarity determinant: it also vanishes for parallel and coincident lines; (II.54f) is the rule from the full product",
    ),
    (
        "II.59r",
        "\"B = 0\" must be read B² = 0, and the in-plane test (one coefficient) also vanishes off the plane",
    ),
    ("II.64r", "holds once (II.63) and (II.64) are corrected"),
    (
        "II.82r",
        "with μ from (II.72) and λ1 (II.79) corrected, B² decides for distinct spheres; coincident spheres give B = 0, which the rule calls tangent",
    ),
];

/// What kind of entry an id is: a numbered equation of Cap. II §3 or Apéndice A, an
/// unnumbered display or sentence of them, a classification rule (`…r`, and the derived `…f`),
/// or an equation of Cap. II §1–§2.
pub fn category(id: &str) -> &'static str {
    let (chapter, rest) = id.split_once('.').unwrap_or((id, ""));
    let digits: String = rest.chars().take_while(char::is_ascii_digit).collect();
    let suffix = &rest[digits.len()..];
    let n: u32 = digits.parse().unwrap_or(0);
    match (chapter, suffix) {
        (_, "r" | "f") => "rule",
        ("II", _) if n < 51 => "Cap. II §1–§2",
        (_, "") => "numbered",
        _ => "unnumbered",
    }
}

/// The numbered equations the report must cover: II.51 … II.82 and A.1 … A.106.
pub fn numbered_range() -> Vec<String> {
    (51..=82)
        .map(|k| format!("II.{k}"))
        .chain((1..=106).map(|k| format!("A.{k}")))
        .collect()
}

/// Where an error shows, from the entries that carry its key.
fn erratum_origin(ids: &[&str]) -> String {
    let in_ii = ids.iter().any(|i| i.starts_with("II."));
    let in_a = ids.iter().any(|i| i.starts_with("A."));
    match ids.len() {
        0 => "not shown by any entry".into(),
        1 => "once: a slip of the thesis or of the text copy (the copy cannot tell)".into(),
        n if in_ii && in_a => {
            format!("in {n} displays of both Cap. II and Apéndice A: in the thesis itself")
        }
        n => format!("repeated in {n} displays: in the thesis itself"),
    }
}

/// The summary line shared by the table and the document.
fn counts(rows: &[Row]) -> String {
    let count = |k: &str| rows.iter().filter(|r| r.verdict.key() == k).count();
    let cat = |c: &str| rows.iter().filter(|r| category(&r.id) == c).count();
    let keys = distinct_errata(rows);
    let with = rows
        .iter()
        .filter(|r| r.verdict == Verdict::Differs)
        .count();
    format!(
        "{} entries ({} numbered equations of Cap. II §3 and Apéndice A, {} unnumbered displays \
         or sentences, {} classification rules, {} equations of Cap. II §1–§2): {} confirmed, {} \
         confirmed up to a factor, {} notation only, {} entries with errata ({} distinct errata), \
         {} rules correct, {} rules correct only once the printed formulas are corrected, {} rules \
         wrong",
        rows.len(),
        cat("numbered"),
        cat("unnumbered"),
        cat("rule"),
        cat("Cap. II §1–§2"),
        count("confirmed"),
        count("scaled"),
        count("notation"),
        with,
        keys.len(),
        count("rule-holds"),
        count("rule-holds-corrected"),
        count("rule-fails")
    )
}

/// The distinct erratum keys of the rows, in first-seen order, with the entries that show each.
pub fn distinct_errata(rows: &[Row]) -> Vec<(String, Vec<&str>)> {
    let mut out: Vec<(String, Vec<&str>)> = Vec::new();
    for r in rows {
        for k in &r.errata {
            match out.iter_mut().find(|(x, _)| x == k) {
                Some((_, ids)) => ids.push(&r.id),
                None => out.push((k.clone(), vec![&r.id])),
            }
        }
    }
    out
}

/// The verdict table as plain text (what the example prints).
pub fn table(rows: &[Row]) -> String {
    let mut s = String::new();
    let w = rows.iter().map(|r| r.id.len()).max().unwrap_or(4).max(4);
    let _ = writeln!(s, "{:<w$}  {:<28}  title", "eq.", "verdict");
    for r in rows {
        let _ = writeln!(s, "{:<w$}  {:<28}  {}", r.id, r.verdict.label(), r.title);
    }
    let _ = writeln!(s, "\n{}", counts(rows));
    s
}

/// The list of entries, `ga-core/thesis/fixtures/equations.txt`: one line per entry with
/// its id, its category and its verdict.
pub fn equation_list(rows: &[Row]) -> String {
    let mut s = String::from(
        "# The entries of ga-core/thesis/docs/thesis-derivations.md: id, category, verdict.\n\
         # Written by `cargo run --release -p ga-thesis -- --write` (printed by `-- --list`);\n\
         # the test `derivations` of ga-thesis checks it against the fixture, the numbered ranges\n\
         # II.51–II.82 and A.1–A.106, and the verdicts computed.\n",
    );
    for r in rows {
        let _ = writeln!(s, "{}\t{}\t{}", r.id, category(&r.id), r.verdict.key());
    }
    s
}

/// The committed document `ga-core/thesis/docs/thesis-derivations.md`.
pub fn document(rows: &[Row]) -> String {
    let mut s = String::new();
    s.push_str(
        "# The thesis's formulas, machine-checked\n\n\
         Generated by `cargo run --release -p ga-thesis -- --write`; \
         do not edit (the test `derivations` of ga-thesis fails when this file differs from the \
         generator's output).\n\n\
         The thesis is Roa's master's thesis *Operaciones de cómputo gráfico en el espacio \
         geométrico conforme 5D usando GPU* (2011). Every numbered equation of its Cap. II §3 \
         (II.51–II.82) and Apéndice A (A.1–A.106), the unnumbered displays between them, the \
         classification rules, and the closed forms of Cap. II §1–§2 are transcribed in \
         `ga-core/thesis/fixtures/formulas.txt` and recomputed with the generated Cl(4,1) \
         products over exact symbolic polynomials (`ga_core::symbolic::Poly`); the list of \
         entries is `ga-core/thesis/fixtures/equations.txt`. Conventions: \
         the thesis's `e = e4`, `ē = e5`, `n = e + ē` (our `n_inf`), `n̄ = e − ē` (our `−2 n_0`), \
         points `2x + x²n − n̄ = 2·up(x)`, dual `A* = IA` with `I = e1e2e3eē = e12345`. \
         Blades are printed in the thesis's spelling and sign (`e3e1ē = −e135`).\n\n\
         Verdicts: *confirmed* (identical polynomials); *confirmed up to factor k* (printed = k · \
         computed: the thesis drops overall scalars on purpose, Apéndice A §2); *notation* \
         (a definition or a name: nothing to compute); *differs* (an erratum: the differing terms, \
         the correction and the check of the correction are given); for classification rules, \
         *rule correct* / *rule wrong* against Euclidean ground truth computed independently in \
         exact rational arithmetic.\n\n",
    );
    let _ = writeln!(s, "{}.\n", counts(rows));
    let present = numbered_range()
        .iter()
        .filter(|id| rows.iter().any(|r| r.id == **id))
        .count();
    let _ = writeln!(
        s,
        "Coverage: {} of the {} numbered equations II.51–II.82 and A.1–A.106 have an entry; \
         every one of these numbers is printed in the text copy read for this report.\n",
        present,
        numbered_range().len()
    );
    s.push_str("## Errata\n\n| erratum | class | what is wrong | entries | where |\n|---|---|---|---|---|\n");
    for (k, ids) in distinct_errata(rows) {
        let (class, what) = ERRATA
            .iter()
            .find(|(key, _, _)| *key == k)
            .map(|(_, c, w)| (*c, *w))
            .unwrap_or(("?", "(no description)"));
        let _ = writeln!(
            s,
            "| {k} | {class} | {what} | {} | {} |",
            ids.iter()
                .map(|i| format!("({i})"))
                .collect::<Vec<_>>()
                .join(", "),
            erratum_origin(&ids)
        );
    }
    s.push('\n');
    s.push_str("## Summary\n\n| eq. | formula | verdict | what |\n|---|---|---|---|\n");
    for r in rows {
        let _ = writeln!(
            s,
            "| {} | {} | {} | {} |",
            r.id,
            r.title,
            r.verdict.label(),
            note(r)
        );
    }
    s.push('\n');
    s.push_str("## Details\n\n");
    let fx = Fixture::parse(FORMULAS).expect("fixture parses");
    for r in rows {
        let _ = writeln!(s, "### ({}) {}\n", r.id, r.title);
        let _ = writeln!(s, "*Source:* {}  ", r.source);
        if let Some(e) = fx.entry(&r.id) {
            let steps: Vec<String> = e
                .fields
                .iter()
                .filter(|(k, _)| k == "formula")
                .map(|(_, v)| format!("`{v}`"))
                .collect();
            if !steps.is_empty() {
                let _ = writeln!(s, "*Printed:* {}  ", steps.join(" = "));
            }
            if let Some(c) = e.field("computed") {
                let _ = writeln!(s, "*Definition computed:* `{c}`  ");
            }
            if let Some(c) = e.field("cases") {
                let _ = writeln!(s, "*Cases:* {}  ", c);
            }
            if let Some(n) = e.field("note") {
                let _ = writeln!(s, "*Transcription note:* {}  ", n);
            }
        }
        let _ = writeln!(s, "*Checked:* {}  ", r.method);
        let _ = writeln!(s, "*Verdict:* **{}**\n", r.verdict.label());
        if !r.detail.trim().is_empty() {
            let _ = writeln!(s, "{}\n", r.detail.trim_end());
        }
    }
    s
}

/// The "what" column: the hand-written summary of an erratum, or the factor of a scaled entry.
fn note(r: &Row) -> String {
    if let Some(n) = lookup2(NOTES, &r.id) {
        return n.to_string();
    }
    if r.verdict == Verdict::Differs {
        return r
            .errata
            .iter()
            .map(|k| {
                let what = ERRATA
                    .iter()
                    .find(|(key, _, _)| key == k)
                    .map(|(_, _, w)| *w)
                    .unwrap_or("(no description)");
                format!("[{k}] {what}")
            })
            .collect::<Vec<_>>()
            .join("; ");
    }
    match &r.verdict {
        Verdict::Scaled(k) => format!("computed = {} × printed", invert(k)),
        _ => String::new(),
    }
}
