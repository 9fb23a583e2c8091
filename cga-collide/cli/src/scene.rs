//! `cga scene FILE`: many objects read from a scene file, and every pair that touches (exact).
//!
//! The scene file has one object a line: a mesh path (relative to the scene file, or a built-in
//! name) followed by 6 numbers `rx ry rz tx ty tz` (degrees about x, then y, then z, then a
//! translation: the `--rotate`/`--translate` convention) or 12 numbers (a row-major 3×4
//! `[R | t]`, whose `R` must be a rotation: the library's [`pose_from_matrix`] check, the one
//! the Python binding applies to 4×4 poses). `#` starts a comment; blank lines are skipped. A
//! mesh named on several lines is loaded and built once and placed many times. Objects are
//! numbered from 0 in line order. Every error about a line names the file and the line.
//!
//! A line may name a solid primitive instead of a mesh: a SHAPE in the JSON spelling of
//! `cga shapes` ([`crate::shape_json`]), e.g. `{"halfspace": {"point": [0, 0, 0], "normal":
//! [0, 0, 1]}}`, followed by the same 6 or 12 numbers, or by none (the shape as written, in
//! world coordinates). It is placed by the library's placement rule (`Shape::placed`).

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::{Duration, Instant};

use anyhow::{bail, Context, Result};
use cga_collide::collider::{pose_from_degrees, pose_from_matrix, Collider};
use cga_collide::nalgebra::{Isometry3, Matrix3, Point3};
use cga_collide::scene::{ObjectId, Scene};
use cga_collide::shape::Shape;
use cga_collide::Segment;
use clap::Args;
use serde_json::json;

use crate::args::parse_numbers;
use crate::mesh::load_mesh;
use crate::number;
use crate::shape_json::parse_shape;

/// Every pair of objects of a scene file that touch (exact), or are within a clearance, or the
/// nearest pair; the objects a segment hits, in order.
#[derive(Args, Debug)]
#[command(after_long_help = SCENE_HELP)]
pub struct SceneArgs {
    /// The scene file: one object a line, `MESH rx ry rz tx ty tz` or `MESH` and a row-major
    /// 3×4 `[R | t]` (12 numbers), or a SHAPE (JSON, see below) and the same numbers or none;
    /// `#` comments.
    file: PathBuf,
    /// List the pairs within this distance (exact, closed) instead of the touching ones.
    #[arg(long, value_name = "C")]
    clearance: Option<f64>,
    /// Also find the nearest pair and its certified distance.
    #[arg(long)]
    nearest: bool,
    /// Also list every object the segment `x0,y0,z0,x1,y1,z1` meets (as `cga query
    /// --segment`), in order along it, each with its first hit (exact parameter, rounded): the
    /// first is the first hit.
    #[arg(
        long,
        value_name = "X0,Y0,Z0,X1,Y1,Z1",
        value_parser = parse_numbers::<6>,
        allow_hyphen_values = true
    )]
    segment: Option<[f64; 6]>,
    /// Poses to move every object to (a second scene file with the same objects in the same
    /// order), then ask again: the time of an update step and its question.
    #[arg(long, value_name = "FILE")]
    moved: Option<PathBuf>,
    /// Objects whose solids overlap count as touching (one inside another; closed meshes).
    #[arg(long)]
    solid: bool,
    /// Repeat each timed step this many times and report the best time.
    #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..))]
    repeat: u32,
    /// Print the result as JSON.
    #[arg(long)]
    json: bool,
}

/// A scene file's objects may also be solid primitives: the help's appendix.
const SCENE_HELP: &str = concat!(
    "A scene line may name a solid primitive instead of a mesh: a SHAPE, then 6 or 12 numbers \
     as for a mesh, or none (the shape as written). For example\n  \
     {\"halfspace\": {\"point\": [0, 0, 0], \"normal\": [0, 0, 1]}}\n  \
     {\"ball\": {\"center\": [0, 0, 0], \"radius\": 0.5}} 0 0 0 1 2 3\n\n",
    "SHAPE is a JSON object with one key, the kind (as `cga shapes` reads it):\n  \
     {\"ball\": {\"center\": P, \"radius\": r}}\n  \
     {\"capsule\": {\"a\": P, \"b\": P, \"radius\": r}}\n  \
     {\"cylinder\": {\"a\": P, \"b\": P, \"radius\": r}}\n  \
     {\"cone\": {\"apex\": P, \"base\": P, \"radius\": r}}\n  \
     {\"cuboid\": {\"center\": P, \"half_axes\": [U, V, W]}}\n  \
     {\"halfspace\": {\"point\": P, \"normal\": N}}\n  \
     {\"convex\": {\"points\": [P, ...]}}\n  \
     {\"triangle\": {\"points\": [P, P, P]}}\n  \
     {\"segment\": {\"points\": [P, P]}}\n\
     P, N, U, V, W are [x, y, z]; see `cga shapes --help`."
);

/// What a line of a scene file places.
enum Source {
    /// A mesh path or built-in name.
    Mesh(String),
    /// A solid primitive.
    Shape(Shape),
}

/// One line of a scene file.
struct Line {
    source: Source,
    pose: Isometry3<f64>,
    /// `FILE:LINE`, for errors about this object.
    at: String,
}

/// Reads a scene file: its objects in line order.
fn read(path: &Path) -> Result<Vec<Line>> {
    let name = path.display().to_string();
    let text = std::fs::read_to_string(path)
        .with_context(|| format!("cannot read the scene file {name} (check the path)"))?;
    let mut out = Vec::new();
    for (k, raw) in text.lines().enumerate() {
        let line = raw.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let at = format!("{name}:{}", k + 1);
        let (source, rest) = if line.starts_with('{') {
            let mut values =
                serde_json::Deserializer::from_str(line).into_iter::<serde_json::Value>();
            let value = values
                .next()
                .with_context(|| format!("{at}: expected a SHAPE (JSON)"))?
                .with_context(|| format!("{at}: the SHAPE is not valid JSON"))?;
            let shape = parse_shape(&value).with_context(|| at.clone())?;
            (Source::Shape(shape), &line[values.byte_offset()..])
        } else {
            let mesh = line.split_whitespace().next().unwrap_or_default();
            (Source::Mesh(mesh.to_string()), &line[mesh.len()..])
        };
        let numbers = rest
            .split_whitespace()
            .map(|w| {
                w.parse::<f64>()
                    .ok()
                    .filter(|x| x.is_finite())
                    .with_context(|| format!("{at}: `{w}` is not a finite number"))
            })
            .collect::<Result<Vec<f64>>>()?;
        let pose = match numbers.len() {
            0 if matches!(source, Source::Shape(_)) => Isometry3::identity(),
            6 => pose_from_degrees(
                [numbers[0], numbers[1], numbers[2]],
                [numbers[3], numbers[4], numbers[5]],
            ),
            12 => {
                let n = &numbers;
                let m = Matrix3::new(n[0], n[1], n[2], n[4], n[5], n[6], n[8], n[9], n[10]);
                // Never the nearest rotation: that would answer for other shapes than written.
                pose_from_matrix(&m, [n[3], n[7], n[11]])
                    .with_context(|| format!("{at}: the 12 numbers are a row-major [R | t]"))?
            }
            n => bail!(
                "{at}: expected a mesh then 6 numbers (rx ry rz tx ty tz, degrees) or 12 (a \
                 row-major 3x4 [R | t]), found {n} numbers"
            ),
        };
        out.push(Line { source, pose, at });
    }
    Ok(out)
}

/// Loads every distinct mesh once (paths relative to the scene file; built-in names as they
/// are) and builds its collider.
fn colliders(lines: &[Line], dir: &Path) -> Result<HashMap<String, Arc<Collider>>> {
    let mut out = HashMap::new();
    for line in lines {
        let Source::Mesh(name) = &line.source else {
            continue;
        };
        if !out.contains_key(name) {
            let relative = dir.join(name);
            let spec = if relative.exists() {
                relative.display().to_string()
            } else {
                name.clone()
            };
            let mesh = load_mesh(&spec, "").with_context(|| line.at.clone())?;
            out.insert(name.clone(), Arc::new(Collider::new(mesh)));
        }
    }
    Ok(out)
}

/// Builds the scene a scene file describes (objects numbered from 0 in line order), for the
/// commands that take a scene as an environment (`cga robot --env`).
pub fn load_scene(path: &Path) -> Result<Scene> {
    let lines = read(path)?;
    let built = colliders(&lines, path.parent().unwrap_or(Path::new(".")))?;
    scene_of(&lines, &built, false)
}

/// A scene of the file's objects in line order, its meshes from `built`.
fn scene_of(lines: &[Line], built: &HashMap<String, Arc<Collider>>, solid: bool) -> Result<Scene> {
    let mut scene = Scene::new();
    scene.set_solid(solid);
    for (k, line) in lines.iter().enumerate() {
        match &line.source {
            Source::Mesh(name) => scene.add(built[name].clone(), line.pose),
            Source::Shape(shape) => scene.add_shape(shape.clone(), line.pose),
        }
        .with_context(|| format!("{}: object {k}", line.at))?;
    }
    Ok(scene)
}

fn best_of<T>(repeat: u32, mut f: impl FnMut() -> Result<T>) -> Result<(T, Duration)> {
    let mut best = Duration::MAX;
    let mut last = None;
    for _ in 0..repeat {
        let t = Instant::now();
        last = Some(f()?);
        best = best.min(t.elapsed());
    }
    Ok((last.context("at least one repetition")?, best))
}

fn millis(d: Duration) -> f64 {
    d.as_secs_f64() * 1e3
}

/// Runs `cga scene`.
pub fn run(args: SceneArgs) -> Result<()> {
    let lines = read(&args.file)?;
    let moved = args.moved.as_deref().map(read).transpose()?;
    if let Some(m) = &moved {
        if m.len() != lines.len() {
            bail!(
                "--moved {}: {} objects, but the scene has {}: give the same objects in the same \
                 order",
                args.moved.as_deref().unwrap_or(Path::new("")).display(),
                m.len(),
                lines.len()
            );
        }
    }
    let dir = args.file.parent().unwrap_or(Path::new("."));
    let t = Instant::now();
    let built = colliders(&lines, dir)?;
    let millis_colliders = millis(t.elapsed());
    let (scene, millis_build) = best_of(args.repeat, || scene_of(&lines, &built, args.solid))?;
    let ask = |scene: &Scene| -> Result<Vec<(ObjectId, ObjectId)>> {
        Ok(match args.clearance {
            Some(c) => scene.pairs_within_distance(c)?,
            None => scene.colliding_pairs()?,
        })
    };
    let (pairs, query) = best_of(args.repeat, || ask(&scene))?;
    let index_pairs = |pairs: &[(ObjectId, ObjectId)]| -> Vec<[u32; 2]> {
        pairs.iter().map(|(a, b)| [a.index(), b.index()]).collect()
    };
    let mut value = json!({
        "objects": lines.len(),
        "meshes": built.len(),
        "shapes": lines.iter().filter(|l| matches!(l.source, Source::Shape(_))).count(),
        "pairs": index_pairs(&pairs),
        "millis_colliders": millis_colliders,
        "millis_build": millis(millis_build),
        "millis_query": millis(query),
    });
    if let Some(m) = &moved {
        let ids = scene.ids();
        let poses: Vec<(ObjectId, Isometry3<f64>)> =
            ids.iter().zip(m).map(|(&id, l)| (id, l.pose)).collect();
        let back: Vec<(ObjectId, Isometry3<f64>)> = ids
            .iter()
            .zip(&lines)
            .map(|(&id, l)| (id, l.pose))
            .collect();
        let mut scene = scene.clone();
        let mut flip = false;
        let (_, step) = best_of(args.repeat, || {
            // Alternate between the two pose sets so that every repetition moves every object.
            flip = !flip;
            scene.set_poses(if flip { &poses } else { &back })?;
            ask(&scene)
        })?;
        scene.set_poses(&poses)?;
        value["millis_move_and_query"] = json!(millis(step));
        value["moved_pairs"] = json!(index_pairs(&ask(&scene)?));
    }
    if args.nearest {
        let (nearest, time) = best_of(args.repeat, || Ok(scene.nearest_pair()?))?;
        value["millis_nearest"] = json!(millis(time));
        if let Some((a, b, d)) = nearest {
            value["nearest"] = json!({
                "pair": [a.index(), b.index()],
                "distance": d.distance,
                "error_bound": d.error_bound,
            });
        }
    }
    if let Some(v) = &args.segment {
        let segment = Segment::new(Point3::new(v[0], v[1], v[2]), Point3::new(v[3], v[4], v[5]))
            .context("--segment")?;
        let (hits, time) = best_of(args.repeat, || Ok(scene.segment_hits_along(&segment)?))?;
        value["millis_segment"] = json!(millis(time));
        value["segment_hits"] = json!(hits
            .iter()
            .map(|h| json!({
                "object": h.object.index(),
                "triangle": h.triangle,
                "parameter": h.parameter_f64(),
                "point": [h.point.x, h.point.y, h.point.z],
            }))
            .collect::<Vec<_>>());
    }
    if args.json {
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        print_text(&args, &value);
    }
    Ok(())
}

/// The text form of `value` (the JSON result): the pairs, then the moved step, the nearest
/// pair and the segment's hits when asked for.
fn print_text(args: &SceneArgs, value: &serde_json::Value) {
    let what = match args.clearance {
        Some(c) => format!("within {}", number::short(c)),
        None => "touching".into(),
    };
    let float = |v: &serde_json::Value| number::short(v.as_f64().unwrap_or(f64::NAN));
    let pairs = |v: &serde_json::Value| {
        let list = v.as_array().map(Vec::as_slice).unwrap_or_default();
        for p in list {
            println!("{} {}", p[0], p[1]);
        }
        list.len()
    };
    let count = value["pairs"].as_array().map_or(0, Vec::len);
    let shapes = match value["shapes"].as_u64() {
        Some(n) if n > 0 => format!(", {n} shapes"),
        _ => String::new(),
    };
    println!(
        "{}: {} objects ({} meshes{shapes}), {count} pairs {what} (exact; build {:.2} ms, query {:.2} ms)",
        args.file.display(),
        value["objects"],
        value["meshes"],
        value["millis_build"].as_f64().unwrap_or(0.0),
        value["millis_query"].as_f64().unwrap_or(0.0),
    );
    pairs(&value["pairs"]);
    if let Some(moved) = &args.moved {
        let count = value["moved_pairs"].as_array().map_or(0, Vec::len);
        println!(
            "moved to {}: {count} pairs {what} (exact; move and query {:.2} ms)",
            moved.display(),
            value["millis_move_and_query"].as_f64().unwrap_or(0.0),
        );
        pairs(&value["moved_pairs"]);
    }
    if args.nearest {
        match value.get("nearest") {
            Some(n) => println!(
                "nearest pair {} {}: distance {} ± {} (certified; {:.2} ms)",
                n["pair"][0],
                n["pair"][1],
                float(&n["distance"]),
                float(&n["error_bound"]),
                value["millis_nearest"].as_f64().unwrap_or(0.0),
            ),
            None => println!("nearest pair: none (fewer than two objects)"),
        }
    }
    if let Some(hits) = value.get("segment_hits").and_then(|h| h.as_array()) {
        println!(
            "segment: {} objects hit, first hits in order along it",
            hits.len()
        );
        for h in hits {
            let p = &h["point"];
            println!(
                "hit {} at t = {} (triangle {}, point [{}, {}, {}])",
                h["object"],
                float(&h["parameter"]),
                h["triangle"],
                float(&p[0]),
                float(&p[1]),
                float(&p[2])
            );
        }
    }
}
