//! `cga shapes FILE.jsonl…`: exact intersection tests of solid primitives, one pair a line.
//!
//! Each line of a file is a JSON object `{"a": SHAPE, "b": SHAPE}` (other keys ignored; blank
//! lines skipped), with SHAPE as [`crate::shape_json`] reads it. For each file, one JSON
//! object a line: `{"file", "pairs", "answers", "micros_mean", "micros_max"}`, the answers of
//! `query::intersects` in file order and its time per pair (parsing excluded). A malformed
//! line, or a pair the library refuses, is an error naming the file and the line.
//!
//! With `--depth`, each object also has `"signed_distance"` and `"error_bound"`: one value a
//! pair, from `query::signed_distance` (the distance when apart, minus the penetration depth
//! when overlapping, the true value within the bound), and `"depth_micros_mean"`, their mean
//! time per pair. A pair whose signed distance the
//! library does not compute (`UnsupportedPair`: a cylinder or a cone meeting another shape,
//! two half-spaces that are not opposite) gets `null` in both arrays.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{Context, Result};
use cga_collide::query;
use cga_collide::shape::Shape;
use clap::Args;
use serde_json::{json, Value};

use crate::shape_json::parse_shape;

/// Exact intersection tests of solid primitives read from JSON-lines files.
#[derive(Args, Debug)]
#[command(after_long_help = SHAPE_HELP)]
pub struct ShapesArgs {
    /// Files of shape pairs, one JSON object `{"a": SHAPE, "b": SHAPE}` a line (see below).
    #[arg(required = true, value_name = "FILE.jsonl")]
    files: Vec<PathBuf>,
    /// Print one JSON object a file: {"file", "pairs", "answers", "micros_mean", "micros_max",
    /// "micros_median"}.
    #[arg(long)]
    json: bool,
    /// Calls per pair for the timing: the pair's time is the best of 5 loops of REPEAT / 5
    /// calls (fewer for a pair whose first call is slow, so that a loop lasts about 2 ms),
    /// the way the peers' benchmark drivers time them. 1 (the default) times one call.
    #[arg(long, default_value_t = 1, value_name = "N")]
    repeat: usize,
    /// Also give each pair's signed distance (minus the penetration depth when they overlap)
    /// and its proved error bound: "signed_distance" and "error_bound" arrays with --json,
    /// null for a pair whose depth is not computed (a cylinder or cone that meets the other
    /// shape, two half-spaces that are not opposite).
    #[arg(long)]
    depth: bool,
}

/// The time per call of `intersects(a, b)` in microseconds, and its answer (see `--repeat`).
fn timed(a: &Shape, b: &Shape, repeat: usize) -> (Result<bool, cga_collide::Error>, f64) {
    let t = Instant::now();
    let answer = query::intersects(a, b);
    let first = t.elapsed().as_secs_f64();
    if repeat <= 1 || answer.is_err() {
        return (answer, first * 1e6);
    }
    let per_loop = (repeat / 5).max(1);
    let calls = per_loop.min((2e-3 / first.max(1e-9)) as usize).max(1);
    let mut best = f64::INFINITY;
    for _ in 0..5 {
        let t = Instant::now();
        for _ in 0..calls {
            let _ = std::hint::black_box(query::intersects(
                std::hint::black_box(a),
                std::hint::black_box(b),
            ));
        }
        best = best.min(t.elapsed().as_secs_f64() / calls as f64);
    }
    (answer, best * 1e6)
}

fn median(mut xs: Vec<f64>) -> f64 {
    xs.sort_by(f64::total_cmp);
    match xs.len() {
        0 => 0.0,
        n if n % 2 == 1 => xs[n / 2],
        n => (xs[n / 2 - 1] + xs[n / 2]) / 2.0,
    }
}

/// The SHAPE spellings, for `--help` (and the scene files, which take the same).
pub const SHAPE_HELP: &str = "\
SHAPE is a JSON object with one key, the kind:
  {\"ball\": {\"center\": P, \"radius\": r}}
  {\"capsule\": {\"a\": P, \"b\": P, \"radius\": r}}     points within r of the segment ab
  {\"cylinder\": {\"a\": P, \"b\": P, \"radius\": r}}    flat caps at a and b, perpendicular to ab
  {\"cone\": {\"apex\": P, \"base\": P, \"radius\": r}}  base disc centred at base, perpendicular to the axis
  {\"cuboid\": {\"center\": P, \"half_axes\": [U, V, W]}}   c + s1 U + s2 V + s3 W, |si| <= 1
  {\"halfspace\": {\"point\": P, \"normal\": N}}         {x : (x - p).n <= 0}
  {\"convex\": {\"points\": [P, ...]}}                   the convex hull
  {\"triangle\": {\"points\": [P, P, P]}}
  {\"segment\": {\"points\": [P, P]}}
P, N, U, V, W are [x, y, z]. Every number is read as the nearest f64, and the shape is the one
those f64 values denote exactly (closed sets: touching counts).";

/// The pairs of one file, in line order, each with its line number.
fn read(path: &Path) -> Result<Vec<(usize, Shape, Shape)>> {
    let name = path.display();
    let text = std::fs::read_to_string(path)
        .with_context(|| format!("cannot read {name} (check the path)"))?;
    let mut out = Vec::new();
    for (k, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let at = || format!("{name}:{}", k + 1);
        let value: Value =
            serde_json::from_str(line).with_context(|| format!("{}: not a JSON object", at()))?;
        let shape = |key: &str| -> Result<Shape> {
            let v = value.get(key).with_context(|| {
                format!(
                    "{}: missing key \"{key}\" (a line is {{\"a\": SHAPE, \"b\": SHAPE}})",
                    at()
                )
            })?;
            parse_shape(v).with_context(|| format!("{}: \"{key}\"", at()))
        };
        out.push((k + 1, shape("a")?, shape("b")?));
    }
    Ok(out)
}

/// A pair's signed distance and its proved bound, `None` where the library does not compute it.
type PairDepth = Option<(f64, f64)>;

/// The signed distance and its bound of each pair and the mean time per pair in microseconds,
/// or the first other error with its file and line.
fn depths(path: &Path, pairs: &[(usize, Shape, Shape)]) -> Result<(Vec<PairDepth>, f64)> {
    let t = Instant::now();
    let out = pairs
        .iter()
        .map(|(line, a, b)| match query::signed_distance(a, b) {
            Ok(sd) => Ok(Some((sd.value, sd.error_bound))),
            Err(cga_collide::Error::UnsupportedPair { .. }) => Ok(None),
            Err(e) => Err(e).with_context(|| format!("{}:{line}", path.display())),
        })
        .collect::<Result<Vec<_>>>()?;
    let micros = t.elapsed().as_secs_f64() * 1e6 / pairs.len().max(1) as f64;
    Ok((out, micros))
}

/// Runs `cga shapes`.
pub fn run(args: ShapesArgs) -> Result<()> {
    for path in &args.files {
        let pairs = read(path)?;
        let mut answers = Vec::with_capacity(pairs.len());
        let (mut total, mut max) = (0.0f64, 0.0f64);
        let mut times = Vec::with_capacity(pairs.len());
        for (line, a, b) in &pairs {
            let (answer, micros) = timed(a, b, args.repeat);
            answers.push(answer.with_context(|| format!("{}:{line}", path.display()))?);
            total += micros;
            max = max.max(micros);
            times.push(micros);
        }
        let mean = if pairs.is_empty() {
            0.0
        } else {
            total / pairs.len() as f64
        };
        let depths = if args.depth {
            Some(depths(path, &pairs)?)
        } else {
            None
        };
        if args.json {
            let mut value = json!({
                "file": path.display().to_string(),
                "pairs": pairs.len(),
                "answers": answers,
                "micros_mean": mean,
                "micros_max": max,
                "micros_median": median(times),
            });
            if let Some((d, micros)) = &depths {
                value["signed_distance"] = d.iter().map(|x| x.map(|x| x.0)).collect();
                value["error_bound"] = d.iter().map(|x| x.map(|x| x.1)).collect();
                value["depth_micros_mean"] = json!(micros);
            }
            println!("{value}");
        } else {
            let hits = answers.iter().filter(|&&a| a).count();
            println!(
                "{}: {} pairs, {hits} intersecting (exact; {mean:.3} µs mean, {max:.3} µs max per pair)",
                path.display(),
                pairs.len(),
            );
            let bits: String = answers.iter().map(|&a| if a { '1' } else { '0' }).collect();
            if !bits.is_empty() {
                println!("{bits}");
            }
            for (k, d) in depths.iter().flat_map(|d| &d.0).enumerate() {
                match d {
                    Some((v, e)) => println!("pair {}: signed distance {v:e} ± {e:.1e}", k + 1),
                    None => println!("pair {}: signed distance not computed", k + 1),
                }
            }
        }
    }
    Ok(())
}
