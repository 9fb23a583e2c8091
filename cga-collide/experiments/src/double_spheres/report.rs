//! The tables, CSV, JSON and SVG plot of `cga-experiment double-spheres`.

use std::fmt::Write as _;

use cga_collide::shape::polyhedron::ConvexPolyhedron;
use cga_experiments::experiment::{Tally, DECISIONS, PAPER_TABLES};
use cga_experiments::plot::{svg_bar_charts, BarChart};
use serde_json::json;

use super::{inner_name, Cell, DoubleSpheresArgs, VariantSpec};
fn pair_label(c: &Cell) -> String {
    format!("{} – {}", short(&c.pair.0), short(&c.pair.1))
}

fn short(name: &str) -> String {
    match ConvexPolyhedron::by_name(name).map(|p| p.num_vertices()) {
        Ok(24) => "troctahedron".into(),
        Ok(120) => "Rh".into(),
        _ => name.to_string(),
    }
}

fn size_label(c: &Cell) -> String {
    let kind = match c.target {
        t if (t - 0.25).abs() < 1e-9 => "large",
        t if (t - 0.75).abs() < 1e-9 => "small",
        _ => "",
    };
    format!("{kind} ({:.0}%)", c.target * 100.0)
        .trim()
        .to_string()
}

fn paper_index(c: &Cell) -> Option<(usize, usize)> {
    let col = match c.target {
        t if (t - 0.25).abs() < 1e-9 => 0,
        t if (t - 0.75).abs() < 1e-9 => 2,
        _ => return None,
    };
    c.paper_row.map(|r| (r, col))
}

fn fmt_us(x: f64) -> String {
    if x.is_nan() {
        "–".into()
    } else if x < 10.0 {
        format!("{x:.2}")
    } else {
        format!("{x:.1}")
    }
}

pub(super) fn markdown(
    cells: &[Cell],
    specs: &[VariantSpec],
    args: &DoubleSpheresArgs,
    seconds: f64,
) -> String {
    let mut s = String::new();
    let placements: u64 = cells.len() as u64 * args.placements;
    let _ = writeln!(
        s,
        "Double-sphere experiment: {} placements ({} per pair and size), {} tree variants each, \
         seed {}, {:.1} s in all ({:.2} µs per placement and variant, reference included).\n",
        placements,
        args.placements,
        specs.len(),
        args.seed,
        seconds,
        seconds * 1e6 / (placements as f64 * specs.len() as f64)
    );
    let main: Vec<usize> = (0..specs.len())
        .filter(|&k| specs[k].level == args.level)
        .collect();

    let _ = writeln!(
        s,
        "Table 3: collisions decided by inner spheres and by faces (paper: ~100,000 placements; \
         ours: {} per row; ours: level {}).\n",
        args.placements, args.level
    );
    let mut header = String::from("| pair | size | paper: inner | paper: faces |");
    let mut rule = String::from("|---|---|---:|---:|");
    for &k in &main {
        let _ = write!(
            header,
            " ours {0}: inner | ours {0}: faces |",
            inner_name(specs[k].inner)
        );
        rule.push_str("---:|---:|");
    }
    header.push_str(" collide (exact) | mismatches |");
    rule.push_str("---:|---:|");
    let _ = writeln!(s, "{header}\n{rule}");
    for c in cells {
        let (pi, pf) = match paper_index(c) {
            Some((r, col)) => {
                let p = PAPER_TABLES[r].counts;
                let n = (p[col] + p[col + 1]) as f64;
                (
                    format!("{} ({:.0}%)", p[col], 100.0 * p[col] as f64 / n),
                    format!("{} ({:.0}%)", p[col + 1], 100.0 * p[col + 1] as f64 / n),
                )
            }
            None => ("–".into(), "–".into()),
        };
        let _ = write!(s, "| {} | {} | {pi} | {pf} |", pair_label(c), size_label(c));
        for &k in &main {
            let t = &c.result.tallies[k];
            let n = t.collisions().max(1) as f64;
            let _ = write!(
                s,
                " {} ({:.0}%) | {} ({:.0}%) |",
                t.by_inner(),
                100.0 * t.by_inner() as f64 / n,
                t.by_faces(),
                100.0 * t.by_faces() as f64 / n
            );
        }
        let _ = writeln!(
            s,
            " {:.1}% | {} |",
            100.0 * c.result.reference_collisions as f64 / args.placements as f64,
            c.result.mismatches.len()
        );
    }

    let _ = writeln!(
        s,
        "\nTable 2: mean time (µs) of the collisions decided by inner spheres and by faces \
         (paper: C++ on a 2.8 GHz Xeon, 2008; ours: this machine, level {}, one query at a time).\n",
        args.level
    );
    let mut header = String::from("| pair | size | paper: inner | paper: faces |");
    let mut rule = String::from("|---|---|---:|---:|");
    for &k in &main {
        let _ = write!(
            header,
            " ours {0}: inner | ours {0}: faces | ours {0}: no collision |",
            inner_name(specs[k].inner)
        );
        rule.push_str("---:|---:|---:|");
    }
    let _ = writeln!(s, "{header}\n{rule}");
    for c in cells {
        let (pi, pf) = match paper_index(c) {
            Some((r, col)) => {
                let p = PAPER_TABLES[r].micros;
                (fmt_us(p[col]), fmt_us(p[col + 1]))
            }
            None => ("–".into(), "–".into()),
        };
        let _ = write!(s, "| {} | {} | {pi} | {pf} |", pair_label(c), size_label(c));
        for &k in &main {
            let m = c.result.tallies[k].mean_micros();
            let _ = write!(
                s,
                " {} | {} | {} |",
                fmt_us(m[0]),
                fmt_us(m[1]),
                fmt_us(m[2])
            );
        }
        let _ = writeln!(s);
    }

    if specs.len() > main.len() {
        let _ = writeln!(
            s,
            "\nLevels: share of the collisions decided by spheres, mean query time (µs) and mean \
             triangle tests per query, on the same placements.\n"
        );
        let _ = writeln!(
            s,
            "| pair | size | level | inner | by spheres | mean µs | triangle tests |\n|---|---|---:|---|---:|---:|---:|"
        );
        for c in cells {
            let mut order: Vec<usize> = (0..specs.len()).collect();
            order.sort_by_key(|&k| (specs[k].level, inner_name(specs[k].inner)));
            for k in order {
                let t = &c.result.tallies[k];
                let _ = writeln!(
                    s,
                    "| {} | {} | {} | {} | {:.1}% | {} | {:.1} |",
                    pair_label(c),
                    size_label(c),
                    specs[k].level,
                    inner_name(specs[k].inner),
                    100.0 * t.by_inner() as f64 / t.collisions().max(1) as f64,
                    fmt_us(t.mean_micros_all()),
                    t.triangle_tests as f64 / t.placements().max(1) as f64
                );
            }
        }
    }

    let _ = writeln!(
        s,
        "\nExact reference (certified GJK, `cga_collide::collider::convex`): how each answer was certified, and its mean time.\n"
    );
    let _ = writeln!(
        s,
        "| pair | size | radius | separated | common point | exhaustive | mean µs |\n|---|---|---:|---:|---:|---:|---:|"
    );
    for c in cells {
        let r = &c.result;
        let _ = writeln!(
            s,
            "| {} | {} | {:.4} | {} | {} | {} | {} |",
            pair_label(c),
            size_label(c),
            c.radius,
            r.reference_certificates[0],
            r.reference_certificates[1],
            r.reference_certificates[2],
            fmt_us(r.reference_nanos as f64 / args.placements as f64 / 1000.0)
        );
    }
    let mismatches: usize = cells.iter().map(|c| c.result.mismatches.len()).sum();
    let _ = writeln!(
        s,
        "\nMismatches against the exact reference: {mismatches} (of {} answers).",
        placements * specs.len() as u64
    );
    s
}

pub(super) fn csv(cells: &[Cell], specs: &[VariantSpec]) -> String {
    let mut s =
        String::from("pair_a,pair_b,target,radius,level,inner,placements,reference_collisions");
    for d in DECISIONS {
        let _ = write!(s, ",count_{d:?}");
    }
    for d in DECISIONS {
        let _ = write!(s, ",mean_ns_{d:?}");
    }
    s.push_str(",sphere_tests,triangle_tests,ref_separated,ref_common_point,ref_exhaustive,ref_mean_ns,mismatches\n");
    for c in cells {
        for (k, spec) in specs.iter().enumerate() {
            let t: &Tally = &c.result.tallies[k];
            let r = &c.result;
            let _ = write!(
                s,
                "{},{},{},{},{},{},{},{}",
                c.pair.0,
                c.pair.1,
                c.target,
                c.radius,
                spec.level,
                inner_name(spec.inner),
                t.placements(),
                r.reference_collisions
            );
            for n in t.count {
                let _ = write!(s, ",{n}");
            }
            for (n, ns) in t.count.iter().zip(t.nanos) {
                let _ = write!(s, ",{:.1}", ns as f64 / (*n).max(1) as f64);
            }
            let _ = writeln!(
                s,
                ",{},{},{},{},{},{:.1},{}",
                t.sphere_tests,
                t.triangle_tests,
                r.reference_certificates[0],
                r.reference_certificates[1],
                r.reference_certificates[2],
                r.reference_nanos as f64 / t.placements().max(1) as f64,
                r.mismatches.iter().filter(|m| m.variant == k).count()
            );
        }
    }
    s
}

pub(super) fn json_report(
    cells: &[Cell],
    specs: &[VariantSpec],
    seconds: f64,
) -> serde_json::Value {
    json!({
        "seconds": seconds,
        "mismatches": cells.iter().map(|c| c.result.mismatches.len()).sum::<usize>(),
        "cells": cells.iter().map(|c| json!({
            "pair": [c.pair.0, c.pair.1],
            "target": c.target,
            "radius": c.radius,
            "reference_collisions": c.result.reference_collisions,
            "reference_certificates": {
                "separated": c.result.reference_certificates[0],
                "common_point": c.result.reference_certificates[1],
                "exhaustive": c.result.reference_certificates[2],
            },
            "variants": specs.iter().zip(&c.result.tallies).map(|(s, t)| json!({
                "level": s.level,
                "inner": inner_name(s.inner),
                "by_inner": t.by_inner(),
                "by_faces": t.by_faces(),
                "mean_micros": {
                    "inner": nan_null(t.mean_micros()[0]),
                    "faces": nan_null(t.mean_micros()[1]),
                    "no_collision": nan_null(t.mean_micros()[2]),
                    "all": nan_null(t.mean_micros_all()),
                },
                "decisions": DECISIONS.iter().zip(t.count).map(|(d, n)| (format!("{d:?}"), json!(n))).collect::<serde_json::Map<_, _>>(),
                "triangle_tests": t.triangle_tests,
                "sphere_tests": t.sphere_tests,
            })).collect::<Vec<_>>(),
            "mismatches": c.result.mismatches.iter().map(|m| json!({
                "placement": m.index, "variant": m.variant, "expected": m.expected,
                "decided_by": format!("{:?}", m.decided_by),
            })).collect::<Vec<_>>(),
        })).collect::<Vec<_>>(),
    })
}

fn nan_null(x: f64) -> serde_json::Value {
    if x.is_finite() {
        json!(x)
    } else {
        serde_json::Value::Null
    }
}

/// Two bar charts in one SVG: the share of collisions decided by spheres (paper vs ours), and
/// the mean query time per level.
pub(super) fn plot(cells: &[Cell], specs: &[VariantSpec]) -> String {
    let groups: Vec<String> = cells
        .iter()
        .map(|c| format!("{}\n{}", pair_label(c), size_label(c)))
        .collect();
    let mut share_series: Vec<(String, Vec<f64>)> = vec![(
        "paper".into(),
        cells
            .iter()
            .map(|c| match paper_index(c) {
                Some((r, col)) => {
                    let p = PAPER_TABLES[r].counts;
                    100.0 * p[col] as f64 / (p[col] + p[col + 1]) as f64
                }
                None => f64::NAN,
            })
            .collect(),
    )];
    let main_level = specs[0].level;
    for (k, spec) in specs
        .iter()
        .enumerate()
        .filter(|(_, s)| s.level == main_level)
    {
        share_series.push((
            format!("ours, {} (level {})", inner_name(spec.inner), spec.level),
            cells
                .iter()
                .map(|c| {
                    let t = &c.result.tallies[k];
                    100.0 * t.by_inner() as f64 / t.collisions().max(1) as f64
                })
                .collect(),
        ));
    }
    let time_series: Vec<(String, Vec<f64>)> = specs
        .iter()
        .enumerate()
        .map(|(k, spec)| {
            (
                format!("level {}, {}", spec.level, inner_name(spec.inner)),
                cells
                    .iter()
                    .map(|c| c.result.tallies[k].mean_micros_all())
                    .collect(),
            )
        })
        .collect();
    svg_bar_charts(&[
        BarChart {
            title: "Collisions decided by inner spheres (%)".into(),
            groups: groups.clone(),
            series: share_series,
        },
        BarChart {
            title: "Mean query time (µs)".into(),
            groups,
            series: time_series,
        },
    ])
}
