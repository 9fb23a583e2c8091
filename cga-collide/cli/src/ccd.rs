//! `cga ccd`: continuous collision, exact.
//!
//! - `cga ccd FILE.csv…`: the CCD benchmark's query files (8 rows of `x_num,x_den,y_num,y_den,
//!   z_num,z_den[,truth]` a query; plain or `.gz`). Prints each file's answers summary, and
//!   with a truth column the false positives and negatives; `--json` prints one JSON object a
//!   line, one line a file. The kind (vertex–face or edge–edge) comes from `--kind` or from a
//!   `vertex-face`/`edge-edge` folder in the path.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{bail, Context, Result};
use cga_collide::motion::{load_queries, MotionQuery, QueryKind};
use clap::{Args, ValueEnum};
use serde_json::json;

/// Continuous collision (motion between two poses), exact.
#[derive(Args, Debug)]
pub struct CcdArgs {
    /// Query files of the CCD benchmark format (`.csv`, optionally `.gz`).
    #[arg(required = true, value_name = "FILE")]
    files: Vec<PathBuf>,
    /// The kind of every query file; by default taken from a `vertex-face` or `edge-edge`
    /// folder in each file's path.
    #[arg(long, value_enum)]
    kind: Option<Kind>,
    /// Time each query this many times and keep the fastest.
    #[arg(long, default_value_t = 3, value_parser = clap::value_parser!(u32).range(1..))]
    repeat: u32,
    /// Print one JSON object a line, one line a file.
    #[arg(long)]
    json: bool,
}

#[derive(Clone, Copy, Debug, ValueEnum)]
enum Kind {
    VertexFace,
    EdgeEdge,
}

impl From<Kind> for QueryKind {
    fn from(k: Kind) -> QueryKind {
        match k {
            Kind::VertexFace => QueryKind::VertexFace,
            Kind::EdgeEdge => QueryKind::EdgeEdge,
        }
    }
}

/// One file's answers and times.
struct FileReport {
    kind: QueryKind,
    answers: Vec<bool>,
    micros: Vec<f64>,
    false_positives: Option<usize>,
    false_negatives: Option<usize>,
}

fn answer_file(queries: &[MotionQuery], kind: QueryKind, repeat: u32) -> Result<FileReport> {
    let mut answers = Vec::with_capacity(queries.len());
    let mut micros = Vec::with_capacity(queries.len());
    for (i, q) in queries.iter().enumerate() {
        let mut best = f64::INFINITY;
        let mut answer = false;
        for _ in 0..repeat {
            let start = Instant::now();
            answer = q.touch(kind).with_context(|| format!("query {i}"))?;
            best = best.min(start.elapsed().as_secs_f64() * 1e6);
        }
        answers.push(answer);
        micros.push(best);
    }
    let with_truth = queries.iter().all(|q| q.truth.is_some());
    let count = |want: bool| {
        queries
            .iter()
            .zip(&answers)
            .filter(|(q, &a)| a == want && q.truth == Some(!want))
            .count()
    };
    Ok(FileReport {
        kind,
        false_positives: with_truth.then(|| count(true)),
        false_negatives: with_truth.then(|| count(false)),
        answers,
        micros,
    })
}

fn median(sorted: &[f64]) -> f64 {
    match sorted.len() {
        0 => 0.0,
        n if n % 2 == 1 => sorted[n / 2],
        n => 0.5 * (sorted[n / 2 - 1] + sorted[n / 2]),
    }
}

fn kind_of(path: &Path, flag: Option<Kind>) -> Result<QueryKind> {
    match flag {
        Some(k) => Ok(k.into()),
        None => QueryKind::from_path(path).with_context(|| {
            format!(
                "{}: cannot tell vertex-face from edge-edge queries: put the file in a \
                 `vertex-face` or `edge-edge` folder, or pass --kind",
                path.display()
            )
        }),
    }
}

/// Runs `cga ccd`.
pub fn run(args: CcdArgs) -> Result<()> {
    if args.files.is_empty() {
        bail!("give at least one query file");
    }
    let mut all_micros = Vec::new();
    let (mut total, mut fp, mut fneg, mut truths) = (0, 0, 0, true);
    for file in &args.files {
        let kind = kind_of(file, args.kind)?;
        let queries = load_queries(file)?;
        let report = answer_file(&queries, kind, args.repeat)
            .with_context(|| format!("{}", file.display()))?;
        let mut sorted = report.micros.clone();
        sorted.sort_by(f64::total_cmp);
        let mean = sorted.iter().sum::<f64>() / sorted.len().max(1) as f64;
        let max = sorted.last().copied().unwrap_or(0.0);
        let med = median(&sorted);
        total += queries.len();
        all_micros.extend_from_slice(&report.micros);
        match (report.false_positives, report.false_negatives) {
            (Some(p), Some(n)) => {
                fp += p;
                fneg += n;
            }
            _ => truths = false,
        }
        if args.json {
            let mut value = json!({
                "file": file.display().to_string(),
                "kind": report.kind.name(),
                "queries": queries.len(),
                "answers": report.answers,
                "micros_mean": mean,
                "micros_median": med,
                "micros_max": max,
            });
            if let (Some(p), Some(n)) = (report.false_positives, report.false_negatives) {
                value["false_positives"] = json!(p);
                value["false_negatives"] = json!(n);
            }
            println!("{value}");
        } else {
            let touching = report.answers.iter().filter(|&&a| a).count();
            let truth = match (report.false_positives, report.false_negatives) {
                (Some(p), Some(n)) => format!(", {p} false positives, {n} false negatives"),
                _ => String::new(),
            };
            println!(
                "{}: {} {} queries, {touching} touching{truth}; µs per query: mean {mean:.2}, \
                 median {med:.2}, max {max:.1}",
                file.display(),
                queries.len(),
                report.kind.name(),
            );
        }
    }
    if !args.json && args.files.len() > 1 {
        all_micros.sort_by(f64::total_cmp);
        let mean = all_micros.iter().sum::<f64>() / all_micros.len().max(1) as f64;
        let truth = if truths {
            format!(", {fp} false positives, {fneg} false negatives")
        } else {
            String::new()
        };
        println!(
            "all {} files: {total} queries{truth}; µs per query: mean {mean:.2}, median {:.2}, \
             max {:.1}",
            args.files.len(),
            median(&all_micros),
            all_micros.last().copied().unwrap_or(0.0)
        );
    }
    Ok(())
}
