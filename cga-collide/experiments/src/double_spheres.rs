//! `cga-experiment double-spheres`: the double-sphere paper's experiment (its Tables 2 and 3)
//! on our exact hierarchy, every answer checked against the exact reference.

use std::fs;
use std::path::PathBuf;
use std::time::Instant;

use anyhow::{bail, Context, Result};
use cga_collide::hierarchy::double_sphere::{DoubleSphereTree, InnerSphereKind};
use cga_collide::shape::polyhedron::ConvexPolyhedron;
use cga_experiments::experiment::{
    calibrate_radius, run as run_variants, ExperimentResult, Variant, PAPER_PAIRS,
};
use clap::{Args, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};

use crate::output;

mod report;
use report::{csv, json_report, markdown, plot};

#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
enum InnerArg {
    /// The paper's inner sphere: centred at the centroid.
    Centroid,
    /// The largest inscribed sphere (Chebyshev centre).
    Chebyshev,
    /// Both, on the same placements.
    Both,
}

/// The double-sphere experiment's options.
#[derive(Args, Debug)]
pub struct DoubleSpheresArgs {
    /// Placements per pair and experiment-sphere size (the paper: 1,000,000).
    #[arg(long, default_value_t = 1_000_000)]
    placements: u64,
    /// Tree level of the main tables (the paper: 3).
    #[arg(long, default_value_t = 3)]
    level: usize,
    /// More levels to run on the same placements, for the level trade-off table
    /// (comma-separated, e.g. `0,1,2,4,5`).
    #[arg(long, value_delimiter = ',')]
    levels: Vec<usize>,
    /// Inner spheres.
    #[arg(long, value_enum, default_value_t = InnerArg::Both)]
    inner: InnerArg,
    /// Pairs, as `A:B` with the names of `cga_collide::shape::polyhedron::ConvexPolyhedron::by_name`
    /// (comma-separated; default: the paper's four).
    #[arg(long, value_delimiter = ',')]
    pairs: Vec<String>,
    /// Target collision fractions, one experiment-sphere size each (the paper: 25 % and 75 %).
    #[arg(long, value_delimiter = ',', default_values_t = [0.25, 0.75])]
    collide: Vec<f64>,
    /// Placements used to calibrate each experiment-sphere radius.
    #[arg(long, default_value_t = 4000)]
    calibration_samples: u64,
    /// Seed of the placements.
    #[arg(long, default_value_t = 2008)]
    seed: u64,
    /// Write one CSV row per pair, size and variant.
    #[arg(long)]
    csv: Option<PathBuf>,
    /// Write an SVG plot of the results (the name must end in .svg).
    #[arg(long)]
    plot: Option<PathBuf>,
    /// Print JSON instead of markdown tables.
    #[arg(long)]
    json: bool,
    /// No progress bar.
    #[arg(long)]
    quiet: bool,
}

/// One configuration of trees evaluated on the shared placements.
#[derive(Debug, Clone, Copy, PartialEq)]
struct VariantSpec {
    level: usize,
    inner: InnerSphereKind,
}

fn inner_name(k: InnerSphereKind) -> &'static str {
    match k {
        InnerSphereKind::Centroid => "centroid",
        InnerSphereKind::Chebyshev => "chebyshev",
    }
}

/// Results of one pair at one experiment-sphere size.
struct Cell {
    pair: (String, String),
    paper_row: Option<usize>,
    target: f64,
    radius: f64,
    result: ExperimentResult,
}

fn parse_pairs(specs: &[String]) -> Result<Vec<(String, String)>> {
    if specs.is_empty() {
        return Ok(PAPER_PAIRS
            .iter()
            .map(|(a, b)| (a.to_string(), b.to_string()))
            .collect());
    }
    specs
        .iter()
        .map(|s| match s.split_once(':') {
            Some((a, b)) => Ok((a.trim().to_string(), b.trim().to_string())),
            None => bail!("pair `{s}` should be written `A:B`, e.g. `cube:octahedron`"),
        })
        .collect()
}

/// Runs `cga-experiment double-spheres`.
pub fn run(args: DoubleSpheresArgs) -> Result<()> {
    output::check_opt("--csv", args.csv.as_deref(), None)?;
    output::check_opt("--plot", args.plot.as_deref(), Some("svg"))?;
    let pairs = parse_pairs(&args.pairs)?;
    for &f in &args.collide {
        if !(f > 0.0 && f < 1.0) {
            bail!(
                "--collide {f}: a collision fraction must lie strictly between 0 and 1, e.g. 0.25"
            );
        }
    }
    if args.placements == 0 {
        bail!("--placements 0: give at least 1");
    }
    let kinds: Vec<InnerSphereKind> = match args.inner {
        InnerArg::Centroid => vec![InnerSphereKind::Centroid],
        InnerArg::Chebyshev => vec![InnerSphereKind::Chebyshev],
        InnerArg::Both => vec![InnerSphereKind::Centroid, InnerSphereKind::Chebyshev],
    };
    let mut levels = vec![args.level];
    levels.extend(args.levels.iter().filter(|&&l| l != args.level));
    let specs: Vec<VariantSpec> = levels
        .iter()
        .flat_map(|&level| kinds.iter().map(move |&inner| VariantSpec { level, inner }))
        .collect();

    let total = args.placements * (pairs.len() * args.collide.len()) as u64;
    let bar = if args.quiet || args.json {
        ProgressBar::hidden()
    } else {
        ProgressBar::new(total)
    };
    bar.set_style(
        ProgressStyle::with_template(
            "{msg:28} [{bar:30}] {human_pos}/{human_len} placements, {per_sec}, eta {eta}",
        )
        .unwrap_or_else(|_| ProgressStyle::default_bar())
        .progress_chars("=> "),
    );
    let started = Instant::now();
    let mut cells = Vec::new();
    for (a_name, b_name) in &pairs {
        let pa = ConvexPolyhedron::by_name(a_name).with_context(|| format!("solid `{a_name}`"))?;
        let pb = ConvexPolyhedron::by_name(b_name).with_context(|| format!("solid `{b_name}`"))?;
        let variants = specs
            .iter()
            .map(|s| {
                Ok(Variant {
                    a: DoubleSphereTree::build(&pa, s.level, s.inner)?,
                    b: DoubleSphereTree::build(&pb, s.level, s.inner)?,
                })
            })
            .collect::<Result<Vec<_>, cga_collide::Error>>()?;
        let paper_row = PAPER_PAIRS.iter().position(|(x, y)| {
            let same = |p: &str, q: &str| {
                ConvexPolyhedron::by_name(p).ok().map(|s| s.num_vertices())
                    == ConvexPolyhedron::by_name(q).ok().map(|s| s.num_vertices())
            };
            same(x, a_name) && same(y, b_name)
        });
        for &target in &args.collide {
            bar.set_message(format!("{a_name}–{b_name} {:.0}%", target * 100.0));
            let radius = calibrate_radius(&pa, &pb, target, args.calibration_samples, args.seed);
            let result = run_variants(&variants, radius, args.placements, args.seed, &|n| {
                bar.inc(n)
            });
            cells.push(Cell {
                pair: (a_name.clone(), b_name.clone()),
                paper_row,
                target,
                radius,
                result,
            });
        }
    }
    bar.finish_and_clear();
    let seconds = started.elapsed().as_secs_f64();
    let mismatches: usize = cells.iter().map(|c| c.result.mismatches.len()).sum();

    if let Some(path) = &args.csv {
        fs::write(path, csv(&cells, &specs))
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    if let Some(path) = &args.plot {
        fs::write(path, plot(&cells, &specs))
            .with_context(|| format!("cannot write {}", path.display()))?;
    }
    if args.json {
        println!("{}", json_report(&cells, &specs, seconds));
    } else {
        print!("{}", markdown(&cells, &specs, &args, seconds));
    }
    if mismatches > 0 {
        for c in &cells {
            for m in c.result.mismatches.iter().take(10) {
                eprintln!(
                    "mismatch: {}–{} radius {} seed {} placement {}: exact {} but {:?} ({:?})",
                    c.pair.0,
                    c.pair.1,
                    c.radius,
                    args.seed,
                    m.index,
                    m.expected,
                    m.decided_by,
                    specs[m.variant]
                );
            }
        }
        bail!("{mismatches} answers disagree with the exact reference");
    }
    Ok(())
}
