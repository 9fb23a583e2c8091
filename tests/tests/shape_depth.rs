//! The product's signed distance (`query::signed_distance`) against the independent exact
//! reference (`workspace_tests::shape_oracle::depth`): on the fixture pairs of `cga shapes`
//! (touching and one-ulp pairs at many scales, random, degenerate and nested pairs), on
//! adversarial box pairs, and on random pairs (proptest). Every answer must hold the true
//! value inside its certified bound and have the exact kind.

use std::cmp::Ordering;
use std::path::PathBuf;

use cga_collide::nalgebra::{Point3, Vector3};
use cga_collide::query::{signed_distance, SignedDistanceKind};
use cga_collide::shape::{Cuboid, Shape};
use proptest::prelude::*;
use workspace_tests::shape_oracle::depth::{self, Truth};
use workspace_tests::shape_oracle::generate::{random_shape, rng, POLYTOPAL};
use workspace_tests::shape_oracle::json::{parse_line, shape_json};

fn fixture_dir() -> PathBuf {
    PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../cga-collide/cli/tests/data/shapes")
}

/// The start of the description of a pair the product refuses (`Error::UnsupportedPair`, a
/// documented refusal: counted and printed, not failed, like the shape oracle's refusals).
const REFUSED: &str = "refused: ";

/// `None` when the pair agrees with the reference (or the reference has no method), else a
/// description of the disagreement or (starting with [`REFUSED`]) of the refusal.
fn disagreement(a: &Shape, b: &Shape) -> Option<String> {
    let truth: Truth = depth::signed_distance(a, b)?;
    let describe = || format!("{} vs {}", shape_json(a), shape_json(b));
    let got = match signed_distance(a, b) {
        Ok(got) => got,
        Err(e) => return Some(format!("{}{}: {e}", REFUSED, describe())),
    };
    let kind = match truth.sign() {
        Ordering::Greater => SignedDistanceKind::Separated,
        Ordering::Equal => SignedDistanceKind::Touching,
        Ordering::Less => SignedDistanceKind::Penetrating,
    };
    if !truth.contains(got.value, got.error_bound) || got.kind != kind {
        return Some(format!(
            "{}: got {} ± {} ({:?}), true {} ({kind:?})",
            describe(),
            got.value,
            got.error_bound,
            got.kind,
            truth.approx()
        ));
    }
    let unit = (got.normal.norm() - 1.0).abs() < 1e-12;
    if !unit {
        return Some(format!("{}: normal {:?} not unit", describe(), got.normal));
    }
    None
}

#[test]
fn fixture_pairs_agree_with_the_exact_reference() {
    let mut failures = Vec::new();
    let mut refused = Vec::new();
    let mut judged = 0;
    for file in [
        "polytopal_touching.jsonl",
        "random.jsonl",
        "polytopal_scales.jsonl",
        "degenerate.jsonl",
        "containment.jsonl",
    ] {
        let text = std::fs::read_to_string(fixture_dir().join(file)).expect("fixture");
        for (i, line) in text.lines().enumerate() {
            let case = parse_line(line).unwrap_or_else(|e| panic!("{file}:{}: {e}", i + 1));
            if depth::signed_distance(&case.a, &case.b).is_some() {
                judged += 1;
            }
            match disagreement(&case.a, &case.b) {
                Some(f) if f.starts_with(REFUSED) => refused.push(format!("{file}:{}: {f}", i + 1)),
                Some(f) => failures.push(format!("{file}:{}: {f}", i + 1)),
                None => {}
            }
        }
    }
    assert!(judged > 500, "only {judged} pairs judged");
    println!(
        "{judged} pairs judged, {} refused by the product:\n{}",
        refused.len(),
        refused.join("\n")
    );
    assert!(
        failures.is_empty(),
        "{} of {judged} disagree:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

fn cuboid(c: [f64; 3], axes: [[f64; 3]; 3]) -> Shape {
    Cuboid::new(Point3::from(c), axes.map(Vector3::from))
        .unwrap()
        .into()
}

#[test]
fn adversarial_boxes_agree_with_the_exact_reference() {
    let unit = [[0.5, 0.0, 0.0], [0.0, 0.5, 0.0], [0.0, 0.0, 0.5]];
    let mut failures = Vec::new();
    for scale in [1e-6, 1.0, 3.0, 1e9] {
        for x in [1.0, 1f64.next_down(), 1f64.next_up(), 0.5, 0.999, 1e-3] {
            for (dy, dz) in [(0.0, 0.0), (0.3, -0.1), (1.0, 1.0), (0.999, 0.0)] {
                let s = |v: [f64; 3]| v.map(|c| c * scale);
                let a = cuboid([0.0; 3], unit.map(s));
                let b = cuboid(s([x, dy, dz]), unit.map(s));
                failures.extend(disagreement(&a, &b));
                // A tilted box resting on a corner or an edge.
                let tilted = [[0.5, 0.5, 0.0], [-0.5, 0.5, 0.0], [0.0, 0.0, 0.5]];
                let c = cuboid(s([x + 0.2, dy, dz]), tilted.map(s));
                failures.extend(disagreement(&a, &c));
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    /// Random pairs of every polytopal kind (half-spaces included) near each other.
    #[test]
    fn random_pairs_agree_with_the_exact_reference(
        seed in any::<u64>(),
        ka in 0..POLYTOPAL.len(),
        kb in 0..POLYTOPAL.len(),
        dx in -3.0f64..3.0,
    ) {
        let mut r = rng(seed);
        let a = random_shape(&mut r, POLYTOPAL[ka], &Point3::origin(), seed % 2 == 0);
        let b = random_shape(&mut r, POLYTOPAL[kb], &Point3::new(dx, 0.0, 0.0), seed % 3 == 0);
        prop_assert_eq!(disagreement(&a, &b), None);
    }
}
