//! Keeps the verdict table of the thesis's formulas true (see
//! `ga-core/examples/thesis_derivations`): confirmed entries stay confirmed, errata keep failing
//! as printed and passing as corrected, and the committed report equals the generator's output.

#[path = "../examples/thesis_derivations/checks.rs"]
mod checks;

use checks::{Row, Verdict};

/// The expected verdict of every entry (stable keys of `Verdict::key`).
const EXPECTED: &[(&str, &str)] = &[
    ("II.5", "confirmed"),
    ("II.7", "confirmed"),
    ("II.9", "confirmed"),
    ("II.11", "confirmed"),
    ("II.12", "confirmed"),
    ("II.16", "confirmed"),
    ("A.14", "differs"),
    ("A.16", "confirmed"),
    ("II.18", "confirmed"),
    ("II.20", "confirmed"),
    ("II.25", "differs"),
    ("A.23", "confirmed"),
    ("A.31", "confirmed"),
    ("II.26e", "confirmed"),
    ("A.39", "scaled"),
    ("II.35a", "confirmed"),
    ("II.35b", "confirmed"),
    ("II.35c", "confirmed"),
    ("II.36", "confirmed"),
    ("II.40", "confirmed"),
    ("A.95", "differs"),
    ("A.96", "differs"),
    ("A.97", "differs"),
    ("II.44", "confirmed"),
    ("II.50", "scaled"),
    ("A.103", "confirmed"),
    ("A.105", "confirmed"),
    ("II.53", "differs"),
    ("II.54", "rule-fails"),
    ("II.56", "differs"),
    ("II.57", "scaled"),
    ("II.58", "scaled"),
    ("II.59", "confirmed"),
    ("II.59r", "rule-fails"),
    ("II.61", "confirmed"),
    ("II.62", "differs"),
    ("II.63", "differs"),
    ("II.64", "differs"),
    ("II.64r", "rule-holds-corrected"),
    ("II.66", "confirmed"),
    ("II.67", "scaled"),
    ("II.68", "scaled"),
    ("II.69", "confirmed"),
    ("II.69r", "rule-holds"),
    ("II.71", "confirmed"),
    ("II.72", "scaled"),
    ("II.73", "confirmed"),
    ("II.75", "scaled"),
    ("II.76", "confirmed"),
    ("II.76r", "rule-holds"),
    ("II.78", "confirmed"),
    ("II.78d", "differs"),
    ("II.79", "differs"),
    ("II.80", "confirmed"),
    ("II.82", "confirmed"),
    ("II.82r", "rule-holds-corrected"),
];

fn rows() -> &'static [Row] {
    static ROWS: std::sync::OnceLock<Vec<Row>> = std::sync::OnceLock::new();
    ROWS.get_or_init(checks::run)
}

#[test]
fn every_entry_has_its_expected_verdict() {
    let rows = rows();
    let got: Vec<(&str, &str)> = rows
        .iter()
        .map(|r| (r.id.as_str(), r.verdict.key()))
        .collect();
    assert_eq!(got, EXPECTED, "verdict table changed");
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
            Verdict::RuleHoldsCorrected => {
                assert!(
                    matches!(r.correction, Some((_, Verdict::RuleHolds))),
                    "{}",
                    r.id
                );
            }
            Verdict::RuleFails => {
                // The corrected rule (stated in the report) must hold.
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
fn committed_report_is_what_the_generator_prints() {
    let path = concat!(env!("CARGO_MANIFEST_DIR"), "/docs/thesis-derivations.md");
    let committed = std::fs::read_to_string(path).expect("the report is committed");
    let generated = checks::document(rows());
    assert!(
        committed == generated,
        "{path} is stale: run `cargo run --release -p ga-core --example thesis_derivations -- --write`"
    );
}

#[test]
fn every_fixture_entry_is_checked_and_listed() {
    let fx = ga_core::symbolic::thesis::Fixture::parse(checks::FIXTURE).expect("fixture parses");
    assert_eq!(fx.entries.len(), rows().len());
    // The list: every formula it names is in the fixture.
    for id in [
        "II.5", "II.7", "II.11", "II.12", "II.16", "A.14", "A.16", "A.31", "II.26e", "II.35a",
        "II.35b", "II.35c", "II.36", "II.40", "II.44", "II.50", "A.105", "II.53", "II.54", "II.56",
        "II.59", "II.61", "II.62", "II.63", "II.64", "II.66", "II.69", "II.71", "II.72", "II.73",
        "II.75", "II.76", "II.78", "II.79", "II.80", "II.82",
    ] {
        assert!(fx.entry(id).is_some(), "{id} missing from the fixture");
    }
}
