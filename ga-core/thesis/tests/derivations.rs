//! Keeps the report on the thesis's formulas true (`cargo run --release -p ga-thesis`): every
//! numbered equation of Cap. II §3 (II.51–II.82) and Apéndice A (A.1–A.106) has an entry, the
//! entry list `fixtures/equations.txt` matches the fixture and the verdicts computed, errata
//! fail as printed and pass as corrected, each names a distinct error that the report describes,
//! and the committed report equals the generator's output.

use ga_thesis as checks;
use ga_thesis::{Fixture, Row, Verdict};

/// The entry list: id, category, verdict key.
const LIST: &str = ga_thesis::EQUATIONS;

fn rows() -> &'static [Row] {
    static ROWS: std::sync::OnceLock<Vec<Row>> = std::sync::OnceLock::new();
    ROWS.get_or_init(checks::run)
}

fn list() -> Vec<(&'static str, &'static str, &'static str)> {
    LIST.lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .map(|l| {
            let f: Vec<&str> = l.split('\t').collect();
            assert_eq!(f.len(), 3, "malformed list line `{l}`");
            (f[0], f[1], f[2])
        })
        .collect()
}

#[test]
fn every_numbered_equation_has_an_entry() {
    let list = list();
    for id in checks::numbered_range() {
        assert!(
            list.iter().any(|(x, c, _)| *x == id && *c == "numbered"),
            "({id}) has no entry in the list"
        );
    }
    let numbered = list.iter().filter(|(_, c, _)| *c == "numbered").count();
    assert_eq!(
        numbered,
        checks::numbered_range().len(),
        "numbered entries outside the ranges"
    );
}

#[test]
fn the_list_is_the_fixture_and_the_report() {
    let fx = Fixture::parse(ga_thesis::FORMULAS).expect("fixture parses");
    let ids: Vec<&str> = fx.entries.iter().map(|e| e.id.as_str()).collect();
    let listed: Vec<&str> = list().iter().map(|(id, _, _)| *id).collect();
    assert_eq!(ids, listed, "fixture entries and list differ");
    assert_eq!(rows().len(), listed.len(), "report entry count");
    for (id, cat, _) in list() {
        assert_eq!(checks::category(id), cat, "category of {id}");
    }
}

#[test]
fn every_entry_has_its_listed_verdict() {
    let got: Vec<(&str, &str)> = rows()
        .iter()
        .map(|r| (r.id.as_str(), r.verdict.key()))
        .collect();
    let want: Vec<(&str, &str)> = list().iter().map(|(id, _, v)| (*id, *v)).collect();
    assert_eq!(
        got, want,
        "verdicts changed: regenerate with `cargo run --release -p ga-thesis -- --write` after checking why"
    );
}

#[test]
fn errata_fail_as_printed_and_pass_as_corrected() {
    for r in rows() {
        match r.verdict {
            Verdict::Differs => {
                let (text, v) = r
                    .correction
                    .as_ref()
                    .unwrap_or_else(|| panic!("{}: erratum without a correction", r.id));
                assert!(
                    matches!(v, Verdict::Confirmed | Verdict::Scaled(_)),
                    "{}: correction `{text}` does not check: {v:?}",
                    r.id
                );
            }
            Verdict::RuleHoldsCorrected | Verdict::RuleFails => {
                assert!(
                    matches!(r.correction, Some((_, Verdict::RuleHolds))),
                    "{}: the corrected rule does not hold",
                    r.id
                );
            }
            _ => assert!(r.correction.is_none(), "{}", r.id),
        }
    }
}

#[test]
fn errata_are_distinct_described_errors() {
    let keys: Vec<&str> = checks::ERRATA.iter().map(|(k, _, _)| *k).collect();
    for r in rows() {
        assert_eq!(
            r.verdict == Verdict::Differs,
            !r.errata.is_empty(),
            "{}: an erratum entry names its errors, and only those do",
            r.id
        );
        for k in &r.errata {
            assert!(keys.contains(&k.as_str()), "{}: unknown erratum {k}", r.id);
        }
    }
    let used = checks::distinct_errata(rows());
    assert_eq!(
        used.len(),
        keys.len(),
        "every described erratum is shown by an entry"
    );
    let mut sorted = keys.clone();
    sorted.sort_unstable();
    sorted.dedup();
    assert_eq!(sorted.len(), keys.len(), "erratum keys are distinct");
}

#[test]
fn committed_report_is_what_the_generator_prints() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/thesis-derivations.md");
    let committed = std::fs::read_to_string(path).expect("the report is committed");
    let generated = checks::document(rows());
    assert!(
        committed == generated,
        "{path} is stale: run `cargo run --release -p ga-thesis -- --write`"
    );
    assert_eq!(
        checks::equation_list(rows()),
        LIST,
        "the entry list is stale: run `cargo run --release -p ga-thesis -- --write`"
    );
}

#[test]
fn fixture_errors_name_the_line() {
    let message = Fixture::parse("  continued\n").unwrap_err().to_string();
    for part in ["line 1", "continuation line outside an entry"] {
        assert!(message.contains(part), "{part:?} missing from: {message}");
    }
}
