//! `cga ccd`: continuous collision, exact.
//!
//! - `cga ccd FILE.csv…`: the CCD benchmark's query files (8 rows of `x_num,x_den,y_num,y_den,
//!   z_num,z_den[,truth]` a query; plain or `.gz`). Prints each file's answers summary, and
//!   with a truth column the false positives and negatives; `--json` prints one JSON object a
//!   line, one line a file. The kind (vertex–face or edge–edge) comes from `--kind` or from a
//!   `vertex-face`/`edge-edge` folder in the path.
//! - `cga ccd FRAME0 FRAME1`: one step of a deforming mesh (two meshes of the same topology,
//!   e.g. PLY frames of a simulation, binary or text, double or float coordinates): every
//!   vertex–face and edge–edge pair that touches during the step (pairs sharing a vertex
//!   excluded) and the earliest contact time.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{bail, Context, Result};
use cga_collide::motion::{load_queries, step_self_contacts, MotionQuery, QueryKind};
use cga_collide::TriMesh;
use clap::{Args, ValueEnum};
use serde_json::json;

/// Continuous collision (motion between two poses), exact.
#[derive(Args, Debug)]
pub struct CcdArgs {
    /// Query files of the CCD benchmark format (`.csv`, optionally `.gz`), or two mesh frames
    /// of one deforming mesh (any mesh format; same vertices and faces in the same order).
    #[arg(required = true, value_name = "FILE")]
    files: Vec<PathBuf>,
    /// Width of the earliest-contact interval of a step (`FRAME0 FRAME1`), and of each query
    /// with `--first-contact`.
    #[arg(long, default_value_t = 1e-9)]
    tolerance: f64,
    /// Query files: compute (and time) each query's earliest contact time to `--tolerance`, not
    /// only whether it touches (as Tight Inclusion computes a time of impact); the JSON line
    /// then has `"toi"`, each query's `[lo, hi]` or `null`.
    #[arg(long)]
    first_contact: bool,
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
    /// Each query's earliest contact interval, with `--first-contact`.
    toi: Option<Vec<Option<[f64; 2]>>>,
    micros: Vec<f64>,
    false_positives: Option<usize>,
    false_negatives: Option<usize>,
}

/// Answers every query, timing each `repeat` times (the fastest kept): the yes/no test, or
/// with `first_contact = Some(tolerance)` the earliest contact time to that tolerance.
fn answer_file(
    queries: &[MotionQuery],
    kind: QueryKind,
    repeat: u32,
    first_contact: Option<f64>,
) -> Result<FileReport> {
    let mut answers = Vec::with_capacity(queries.len());
    let mut micros = Vec::with_capacity(queries.len());
    let mut tois = Vec::new();
    for (i, q) in queries.iter().enumerate() {
        let mut best = f64::INFINITY;
        let (mut answer, mut toi) = (false, None);
        for _ in 0..repeat {
            let start = Instant::now();
            match first_contact {
                None => answer = q.touch(kind).with_context(|| format!("query {i}"))?,
                Some(tolerance) => {
                    let time = q
                        .first_contact(kind, tolerance)
                        .with_context(|| format!("query {i}"))?;
                    answer = time.is_some();
                    toi = time.map(|c| [c.lo(), c.hi()]);
                }
            }
            best = best.min(start.elapsed().as_secs_f64() * 1e6);
        }
        answers.push(answer);
        tois.push(toi);
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
        toi: first_contact.map(|_| tois),
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

fn is_query_file(path: &Path) -> bool {
    let name = path.to_string_lossy().to_ascii_lowercase();
    name.ends_with(".csv") || name.ends_with(".csv.gz")
}

/// `cga ccd FRAME0 FRAME1`: a deforming mesh's self-contacts over one step.
fn run_step(args: &CcdArgs) -> Result<()> {
    let [f0, f1] = [&args.files[0], &args.files[1]];
    let start = TriMesh::load(f0)?;
    let end = TriMesh::load(f1)?;
    if start.triangles() != end.triangles() || start.vertices().len() != end.vertices().len() {
        bail!(
            "{} and {} are not two frames of one mesh: {} vertices and {} faces against {} and {} (or the faces differ); a step needs the same vertices and faces in the same order",
            f0.display(),
            f1.display(),
            start.vertices().len(),
            start.num_triangles(),
            end.vertices().len(),
            end.num_triangles()
        );
    }
    let t = Instant::now();
    let contacts = step_self_contacts(&start, end.vertices(), args.tolerance)?;
    let millis = t.elapsed().as_secs_f64() * 1e3;
    let toi = contacts.first_contact.map(|c| [c.lo(), c.hi()]);
    if args.json {
        println!(
            "{}",
            json!({
                "vertices": start.vertices().len(),
                "faces": start.num_triangles(),
                "vertex_face": contacts.vertex_face,
                "edge_edge": contacts.edge_edge,
                "toi": toi,
                "millis": millis,
                "vertex_face_candidates": contacts.vertex_face_candidates,
                "edge_edge_candidates": contacts.edge_edge_candidates,
            })
        );
    } else {
        println!(
            "{} -> {}: {} vertices, {} faces; {} vertex-face and {} edge-edge pairs touch ({} and {} swept-box candidates); first contact {}; {millis:.1} ms",
            f0.display(),
            f1.display(),
            start.vertices().len(),
            start.num_triangles(),
            contacts.vertex_face.len(),
            contacts.edge_edge.len(),
            contacts.vertex_face_candidates,
            contacts.edge_edge_candidates,
            match toi {
                Some([lo, hi]) => format!("in [{lo:e}, {hi:e}]"),
                None => "none".into(),
            }
        );
        for (v, f) in &contacts.vertex_face {
            println!("vertex {v} face {f}");
        }
        for (a, b) in &contacts.edge_edge {
            println!("edge {} {} edge {} {}", a[0], a[1], b[0], b[1]);
        }
    }
    Ok(())
}

/// Runs `cga ccd`.
pub fn run(args: CcdArgs) -> Result<()> {
    if args.files.is_empty() {
        bail!("give at least one query file");
    }
    // Before anything is told from the names (the kind, query file or mesh frame).
    if let Some(f) = args.files.iter().find(|f| !f.exists()) {
        bail!("{}: no such file (check the path)", f.display());
    }
    if args.files.len() == 2 && !args.files.iter().any(|f| is_query_file(f)) {
        return run_step(&args);
    }
    if let Some(f) = args.files.iter().find(|f| !is_query_file(f)) {
        bail!(
            "{}: not a query file (.csv or .csv.gz); give query files, or exactly two mesh frames of one deforming mesh",
            f.display()
        );
    }
    let mut all_micros = Vec::new();
    let (mut total, mut fp, mut fneg, mut truths) = (0, 0, 0, true);
    for file in &args.files {
        let kind = kind_of(file, args.kind)?;
        let queries = load_queries(file)?;
        let first_contact = args.first_contact.then_some(args.tolerance);
        let report = answer_file(&queries, kind, args.repeat, first_contact)
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
            if let Some(toi) = &report.toi {
                value["toi"] = json!(toi);
            }
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
