//! Self-intersection and mesh–mesh intersecting pairs on CGAL's demo meshes, on one thread, for
//! the comparison with CGAL 5.5 made by `benches/demo_meshes.sh` (the CGAL side is
//! `benches/cgal_demo_meshes.cpp`; the table comes from `benches/demo_meshes_table.py`).
//!
//! ```text
//! cargo bench -p cga-collide --bench demo_meshes -- self LIST_FILE REPEAT OUT_DIR
//! cargo bench -p cga-collide --bench demo_meshes -- pair MESH_A MESH_B REPEAT OUT_FILE
//! ```
//!
//! `self`: for every mesh path in `LIST_FILE` (one a line), the best and mean of `REPEAT` runs (more
//! until they add up to 20 ms, as in the CGAL driver) of
//! `Collider::new` + `Collider::self_intersections` (the tree build included, as CGAL's time
//! includes its boxes; the best build alone is `build_ms`), the pairs written to
//! `OUT_DIR/<file name>.pairs` (`i j` a line, `i < j`, sorted), and one JSON line per mesh on
//! standard output. A mesh that cannot be read gives `{"mesh": ..., "error": ...}`.
//!
//! `pair`: the best and mean of `REPEAT` runs (or more, as above) of `Collider::new` on both meshes and
//! `Collider::intersecting_pairs` (every pair of a triangle of A and one of B whose closed
//! triangles meet), the pairs written to `OUT_FILE`, one JSON line.
//!
//! The colliders are built as `Collider::new` builds them (binned SAH), or with
//! `BuildStrategy::Morton` when `DEMO_MESHES_BUILD=morton` (the one-shot build).
//!
//! Everything runs inside a one-thread rayon pool. Arguments starting with `--` (cargo bench
//! passes `--bench`) are ignored.

use std::error::Error;
use std::fmt::Write as _;
use std::fs;
use std::io::{BufRead, BufReader};
use std::path::{Path, PathBuf};
use std::time::Instant;

use cga_collide::bounding::BuildStrategy;
use cga_collide::collider::Collider;
use cga_collide::shape::mesh::TriMesh;
use serde_json::{json, Value};

type Res<T> = Result<T, Box<dyn Error + Send + Sync>>;

/// The library's stage counters for the last run (how many signs each exact stage after the
/// first `f64` filter decided), printed under `"counters"` in every JSON line.
fn counters_json() -> Value {
    let c = cga_collide::testing::stage_counts();
    json!({
        "rescaled_filter": c.rescaled_filter,
        "expansion": c.expansion,
        "big_integer": c.big_integer,
    })
}

/// The file name of a path (the key both programs print under `"mesh"`, `"a"`, `"b"`).
fn file_name(path: &str) -> String {
    Path::new(path)
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| path.to_owned())
}

/// Number of faces the file's header declares (OFF and PLY; `None` for other formats or when
/// the header cannot be read). The loader fan-triangulates polygons, so a mesh whose triangle
/// count differs from this was triangulated (or had faces of fewer than three vertices).
fn declared_faces(path: &str) -> Option<usize> {
    let ext = Path::new(path)
        .extension()?
        .to_string_lossy()
        .to_lowercase();
    let mut lines = BufReader::new(fs::File::open(path).ok()?).split(b'\n');
    match ext.as_str() {
        "off" => {
            // Tokens of the header: `[ST][C][N][4][n]OFF`, then `nv nf ne`, `#` comments.
            let mut tokens: Vec<String> = Vec::new();
            while tokens.len() < 4 {
                let line = lines.next()?.ok()?;
                let line = String::from_utf8_lossy(&line);
                let line = line.split('#').next().unwrap_or("");
                tokens.extend(line.split_whitespace().map(str::to_owned));
            }
            if !tokens[0].ends_with("OFF") {
                return None;
            }
            tokens[2].parse().ok()
        }
        "ply" => {
            for line in lines {
                let line = line.ok()?;
                let line = String::from_utf8_lossy(&line);
                let words: Vec<&str> = line.split_whitespace().collect();
                match words.as_slice() {
                    ["element", "face", n] => return n.parse().ok(),
                    ["end_header"] => return None,
                    _ => {}
                }
            }
            None
        }
        _ => None,
    }
}

fn write_pairs(path: &Path, pairs: &[(u32, u32)]) -> Res<()> {
    let mut text = String::with_capacity(pairs.len() * 12);
    for (i, j) in pairs {
        writeln!(text, "{i} {j}")?;
    }
    fs::write(path, text)?;
    Ok(())
}

fn ms(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

/// Runs go on past `REPEAT` until they add up to this many milliseconds, so that the best time
/// of a mesh taking a few microseconds is not the luck of five cold runs (the CGAL driver uses
/// the same rule).
const MIN_TOTAL_MS: f64 = 20.0;
/// At most this many runs per item.
const MAX_RUNS: usize = 100_000;

/// The tree build: `Collider::new`'s binned SAH, or the one-shot Morton build with
/// `DEMO_MESHES_BUILD=morton`.
fn build_strategy() -> BuildStrategy {
    match std::env::var("DEMO_MESHES_BUILD").as_deref() {
        Ok("morton") => BuildStrategy::Morton,
        _ => BuildStrategy::Sah,
    }
}

/// Whether another timed run is due after `done` runs taking `sum_ms` in all.
fn more_runs(done: usize, repeat: usize, sum_ms: f64) -> bool {
    done < repeat || (sum_ms < MIN_TOTAL_MS && done < MAX_RUNS)
}

/// One mesh's self-intersection: the JSON line (or an error line).
fn self_one(path: &str, repeat: usize, out_dir: &Path) -> Value {
    let name = file_name(path);
    let mesh = match TriMesh::load(path) {
        Ok(m) => m,
        Err(e) => return json!({"mesh": name, "error": e.to_string()}),
    };
    let triangles = mesh.num_triangles();
    let triangulated = declared_faces(path).is_some_and(|n| n != triangles);
    let (mut best, mut sum, mut best_build) = (f64::INFINITY, 0.0, f64::INFINITY);
    let (mut pairs, mut runs) = (Vec::new(), 0);
    while more_runs(runs, repeat, sum) {
        runs += 1;
        let copy = mesh.clone();
        cga_collide::testing::reset_stage_counts();
        let t0 = Instant::now();
        let collider = Collider::with_strategy(copy, build_strategy());
        let build = ms(t0);
        pairs = collider.self_intersections();
        let total = ms(t0);
        best = best.min(total);
        best_build = best_build.min(build);
        sum += total;
    }
    if let Err(e) = write_pairs(&out_dir.join(format!("{name}.pairs")), &pairs) {
        return json!({"mesh": name, "error": format!("writing pairs: {e}")});
    }
    json!({
        "mesh": name,
        "triangles": triangles,
        "triangulated": triangulated,
        "pairs": pairs.len(),
        "best_ms": best,
        "mean_ms": sum / runs as f64,
        "runs": runs,
        "build_ms": best_build,
        "counters": counters_json(),
    })
}

fn self_mode(list: &str, repeat: usize, out_dir: &str) -> Res<()> {
    let out_dir = PathBuf::from(out_dir);
    fs::create_dir_all(&out_dir)?;
    for line in fs::read_to_string(list)?.lines() {
        let path = line.trim();
        if path.is_empty() {
            continue;
        }
        println!("{}", self_one(path, repeat, &out_dir));
    }
    Ok(())
}

fn pair_mode(a: &str, b: &str, repeat: usize, out_file: &str) -> Res<()> {
    let (name_a, name_b) = (file_name(a), file_name(b));
    let (ma, mb) = match (TriMesh::load(a), TriMesh::load(b)) {
        (Ok(ma), Ok(mb)) => (ma, mb),
        (Err(e), _) | (_, Err(e)) => {
            println!(
                "{}",
                json!({"a": name_a, "b": name_b, "error": e.to_string()})
            );
            return Ok(());
        }
    };
    let (mut best, mut sum, mut best_build) = (f64::INFINITY, 0.0, f64::INFINITY);
    let (mut pairs, mut runs) = (Vec::new(), 0);
    while more_runs(runs, repeat, sum) {
        runs += 1;
        let (ca, cb) = (ma.clone(), mb.clone());
        cga_collide::testing::reset_stage_counts();
        let t0 = Instant::now();
        let strategy = build_strategy();
        let (ca, cb) = (
            Collider::with_strategy(ca, strategy),
            Collider::with_strategy(cb, strategy),
        );
        let build = ms(t0);
        pairs = ca.intersecting_pairs(&cb);
        let total = ms(t0);
        best = best.min(total);
        best_build = best_build.min(build);
        sum += total;
    }
    write_pairs(Path::new(out_file), &pairs)?;
    let line = json!({
        "a": name_a,
        "b": name_b,
        "triangles_a": ma.num_triangles(),
        "triangles_b": mb.num_triangles(),
        "pairs": pairs.len(),
        "best_ms": best,
        "mean_ms": sum / runs as f64,
        "runs": runs,
        "build_ms": best_build,
        "counters": counters_json(),
    });
    println!("{line}");
    Ok(())
}

const USAGE: &str = "usage: demo_meshes self LIST_FILE REPEAT OUT_DIR\n       \
                     demo_meshes pair MESH_A MESH_B REPEAT OUT_FILE";

fn run(args: &[String]) -> Res<()> {
    let repeat = |s: &str| -> Res<usize> {
        let n: usize = s.parse().map_err(|e| format!("REPEAT {s:?}: {e}"))?;
        Ok(n.max(1))
    };
    match args {
        [mode, list, r, out] if mode == "self" => self_mode(list, repeat(r)?, out),
        [mode, a, b, r, out] if mode == "pair" => pair_mode(a, b, repeat(r)?, out),
        _ => Err(USAGE.into()),
    }
}

fn main() -> Res<()> {
    let args: Vec<String> = std::env::args()
        .skip(1)
        .filter(|a| !a.starts_with("--"))
        .collect();
    if args.is_empty() {
        // `cargo bench` without arguments runs every bench target: nothing to do here.
        eprintln!("{USAGE}");
        return Ok(());
    }
    rayon::ThreadPoolBuilder::new()
        .num_threads(1)
        .build()?
        .install(|| run(&args))
}
