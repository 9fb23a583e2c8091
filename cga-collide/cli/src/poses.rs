//! `cga collide A B --poses FILE`: many poses of B against A, answered by the collider's pose
//! batches (`Collider::collides_batch`, `Collider::intersecting_pairs_batch`: both hierarchies
//! built once, no per-pose placement), spread over the cores.
//!
//! Each non-empty line of the file is `ax ay az tx ty tz` (whitespace- or comma-separated,
//! `#` starts a comment): B is rotated by `ax`, `ay`, `az` degrees about x, then y, then z, then
//! translated, exactly as `--rotate ax,ay,az --translate tx,ty,tz` does. Poses are numbered
//! from 0 in the output (pose `k` is the `k`-th pose of the file, as pair indices are), and
//! errors name the line of the file.

use std::path::Path;
use std::time::Instant;

use anyhow::{bail, Context, Result};
use cga_collide::collider::{Collider, PosePair};
use cga_collide::nalgebra::Isometry3;
use cga_collide::shape::mesh::TriMesh;
use cga_collide::Error;
use serde_json::json;

use cga_collide::collider::pose_from_degrees;

/// What the pose run prints.
pub struct Options<'a> {
    /// The poses file.
    pub file: &'a Path,
    /// Count the intersecting pairs per pose (otherwise first hit only).
    pub all_pairs: bool,
    /// Worker threads (`None`: all cores).
    pub threads: Option<usize>,
    /// Print JSON.
    pub json: bool,
}

/// Parses the poses file: one pose per non-empty, non-comment line, with its 1-based line
/// number.
pub fn parse(text: &str, name: &str) -> Result<Vec<(usize, Isometry3<f64>)>> {
    let mut poses = Vec::new();
    for (n, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let words: Vec<&str> = line
            .split(|c: char| c.is_whitespace() || c == ',')
            .filter(|w| !w.is_empty())
            .collect();
        if words.len() != 6 {
            bail!(
                "{name}:{}: expected 6 numbers `ax ay az tx ty tz`, got {}",
                n + 1,
                words.len()
            );
        }
        let mut v = [0.0; 6];
        for (o, w) in v.iter_mut().zip(&words) {
            let x: f64 = w
                .parse()
                .map_err(|_| anyhow::anyhow!("{name}:{}: `{w}` is not a number", n + 1))?;
            if !x.is_finite() {
                bail!("{name}:{}: `{w}` is not finite", n + 1);
            }
            *o = x;
        }
        poses.push((
            n + 1,
            pose_from_degrees([v[0], v[1], v[2]], [v[3], v[4], v[5]]),
        ));
    }
    if poses.is_empty() {
        bail!(
            "{name}: no poses: write one pose `ax ay az tx ty tz` per line (`#` starts a comment)"
        );
    }
    Ok(poses)
}

/// Answers every pose of the file for A (at the origin) and B, and prints the results.
pub fn run(a: TriMesh, b: TriMesh, options: &Options<'_>) -> Result<()> {
    let name = options.file.display().to_string();
    let text = std::fs::read_to_string(options.file)
        .with_context(|| format!("--poses: cannot read the poses file {name} (check the path)"))?;
    let parsed = parse(&text, &name)?;
    let lines: Vec<usize> = parsed.iter().map(|&(line, _)| line).collect();
    let poses: Vec<PosePair> = parsed
        .into_iter()
        .map(|(_, p)| PosePair::new(Isometry3::identity(), p))
        .collect();
    // A pose without an answer is reported at its line of the file.
    let at_line = |e: Error| match e {
        Error::InBatch { index, source } => anyhow::anyhow!("{name}:{}: {source}", lines[index]),
        other => other.into(),
    };
    if options.threads == Some(0) {
        bail!("--threads 0: give at least 1, or leave --threads out to use every core");
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(options.threads.unwrap_or(0))
        .build()
        .context("cannot start the worker threads")?;
    let threads = pool.current_num_threads();
    let (ca, cb) = pool.install(|| rayon::join(|| Collider::new(a), || Collider::new(b)));
    // The first pose query lays out both hierarchies for pose queries (once per collider) and
    // grows the thread's scratch memory: building, kept out of the time per pose. (Its answer
    // is not needed; a pose the batch cannot take is reported by the batch itself.)
    let id = Isometry3::identity();
    let _ = pool.install(|| ca.collides_at(&id, &cb, &id));
    let start = Instant::now();
    let (collides, pairs): (Vec<bool>, Option<Vec<usize>>) = if options.all_pairs {
        let pairs = pool
            .install(|| ca.intersecting_pairs_batch(&cb, &poses))
            .map_err(at_line)?;
        (
            pairs.iter().map(|p| !p.is_empty()).collect(),
            Some(pairs.iter().map(Vec::len).collect()),
        )
    } else {
        (
            pool.install(|| ca.collides_batch(&cb, &poses))
                .map_err(at_line)?,
            None,
        )
    };
    let micros = start.elapsed().as_secs_f64() * 1e6 / poses.len() as f64;
    if options.json {
        let mut value = json!({
            "collides": collides,
            "micros_per_pose": micros,
            "threads": threads,
        });
        if let Some(p) = &pairs {
            value["pairs"] = json!(p);
        }
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        for (k, c) in collides.iter().enumerate() {
            match &pairs {
                Some(p) => println!("pose {k}: collides {c}, {} intersecting pairs", p[k]),
                None => println!("pose {k}: collides {c}"),
            }
        }
        println!(
            "{} poses, {} colliding; {micros:.1} µs per pose on {threads} threads (queries only)",
            poses.len(),
            collides.iter().filter(|&&c| c).count()
        );
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_poses_and_reports_bad_lines() {
        let poses = parse(
            "# header\n0 0 0 0.3 0.05 0\n\n90,0,0, 1,2,3 # comment\n",
            "f",
        )
        .unwrap();
        assert_eq!(poses.len(), 2);
        assert_eq!(poses[0], (2, pose_from_degrees([0.0; 3], [0.3, 0.05, 0.0])));
        assert_eq!(
            poses[1],
            (4, pose_from_degrees([90.0, 0.0, 0.0], [1.0, 2.0, 3.0]))
        );
        let e = parse("1 2 3\n", "f").unwrap_err().to_string();
        assert!(e.contains("f:1") && e.contains("6 numbers"), "{e}");
        let e = parse("0 0 0 0 0 x\n", "f").unwrap_err().to_string();
        assert!(e.contains("`x` is not a number"), "{e}");
        let e = parse("0 0 0 0 0 inf\n", "f").unwrap_err().to_string();
        assert!(e.contains("not finite"), "{e}");
        assert!(parse("# nothing\n", "f").is_err());
    }
}
