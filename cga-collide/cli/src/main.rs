//! `cga`: exact conformal collision of triangle meshes from the command line.
//!
//! `cga` with no arguments runs `cga collide` on built-in meshes (bunny00 vs a moved
//! armadillo) and writes `collision.png`. See `cga --help`.

mod distance;
mod experiment_cmd;
mod poses;
mod render;
mod self_intersect;
mod spheretree;

use std::fs;
use std::io::Write as _;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::{Duration, Instant};

use anyhow::{bail, Context, Result};
use cga_collide::nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use cga_collide::query::{self, Collider, Mode};
use cga_collide::shape::mesh::TriMesh;
use cga_collide::{Ball, Segment, Sphere, Triangle};
use clap::{Args, Parser, Subcommand, ValueEnum};
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::json;

/// Exact collision detection in the conformal model.
#[derive(Parser, Debug)]
#[command(name = "cga", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Every intersecting triangle pair of two meshes (built-in demo when no meshes are given).
    Collide(CollideArgs),
    /// Which triangles of a mesh a segment, triangle, sphere or ball meets.
    Query(QueryArgs),
    /// Octree sphere trees (Fuentes Socorro's method): build from meshes, collide two from a file.
    Spheretree(spheretree::SphereTreeArgs),
    /// Run an experiment of the papers (`cga experiment double-spheres`).
    Experiment(experiment_cmd::ExperimentArgs),
    /// Minimum distance between two meshes, with witnesses and a certified error bound.
    Distance(distance::DistanceArgs),
    /// Pairs of triangles of one mesh that meet other than in a shared vertex or edge (exact).
    SelfIntersect(self_intersect::SelfIntersectArgs),
}

#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
enum ModeArg {
    /// Test every pair (in parallel): the thesis's worst case.
    Brute,
    /// Bounding-volume hierarchy, then the same exact tests.
    Bvh,
}

impl From<ModeArg> for Mode {
    fn from(m: ModeArg) -> Mode {
        match m {
            ModeArg::Brute => Mode::Brute,
            ModeArg::Bvh => Mode::Bvh,
        }
    }
}

#[derive(Args, Debug)]
struct CollideArgs {
    /// Mesh A: a file (.obj, .off, .ply, .stl) or a built-in name (bunny, bunny00, armadillo).
    a: Option<String>,
    /// Mesh B (moved by --rotate and --translate).
    b: Option<String>,
    /// Scale each mesh uniformly into the unit box centred at the origin (largest side 1)
    /// before anything else. On by default for the built-in demo.
    #[arg(long)]
    unit: bool,
    /// Rotate B by these degrees about x, then y, then z.
    #[arg(long, value_name = "AX,AY,AZ", value_parser = parse_triple, allow_hyphen_values = true)]
    rotate: Option<[f64; 3]>,
    /// Then translate B.
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_triple, allow_hyphen_values = true)]
    translate: Option<[f64; 3]>,
    /// How pairs are found.
    #[arg(long, value_enum, default_value_t = ModeArg::Bvh)]
    mode: ModeArg,
    /// Write the intersecting pairs, one `i j` per line (0-based triangle indices of A and B).
    #[arg(long, value_name = "FILE")]
    pairs: Option<PathBuf>,
    /// Print the result as JSON.
    #[arg(long)]
    json: bool,
    /// Render both meshes with the intersecting triangles highlighted (PNG).
    #[arg(long, value_name = "OUT.png")]
    image: Option<PathBuf>,
    /// Time the query this many times and report the best.
    #[arg(long, default_value_t = 3)]
    repeat: u32,
    /// Count (in "pairs") and list (with --pairs) the triangle pairs within this distance
    /// instead of the intersecting ones (exact; distance exactly C counts).
    #[arg(long, value_name = "C", allow_hyphen_values = true)]
    clearance: Option<f64>,
    /// Write the exact intersection of every intersecting triangle pair (`i j` then the
    /// corners as `x y z` triples; a point, a segment or a polygon).
    #[arg(long, value_name = "FILE")]
    contacts: Option<PathBuf>,
    /// Answer many poses of B: one `ax ay az tx ty tz` per line (as --rotate, --translate).
    #[arg(long, value_name = "FILE", conflicts_with_all = ["rotate", "translate", "pairs", "image"])]
    poses: Option<PathBuf>,
    /// With --poses: count the intersecting pairs of every pose.
    #[arg(long, requires = "poses")]
    all_pairs: bool,
    /// With --poses: number of worker threads (default: all cores).
    #[arg(long, value_name = "N", requires = "poses")]
    threads: Option<usize>,
}

#[derive(Args, Debug)]
struct QueryArgs {
    /// The mesh: a file or a built-in name (bunny, bunny00, armadillo).
    mesh: String,
    /// Scale the mesh into the unit box centred at the origin first.
    #[arg(long)]
    unit: bool,
    /// A segment `x1,y1,z1,x2,y2,z2`.
    #[arg(long, value_parser = parse_numbers::<6>, allow_hyphen_values = true, group = "primitive")]
    segment: Option<[f64; 6]>,
    /// A triangle `x1,y1,z1,x2,y2,z2,x3,y3,z3`.
    #[arg(long, value_parser = parse_numbers::<9>, allow_hyphen_values = true, group = "primitive")]
    triangle: Option<[f64; 9]>,
    /// A sphere (surface) `cx,cy,cz,r`.
    #[arg(long, value_parser = parse_numbers::<4>, allow_hyphen_values = true, group = "primitive")]
    sphere: Option<[f64; 4]>,
    /// A ball (solid) `cx,cy,cz,r`.
    #[arg(long, value_parser = parse_numbers::<4>, allow_hyphen_values = true, group = "primitive")]
    ball: Option<[f64; 4]>,
    /// How triangles are found.
    #[arg(long, value_enum, default_value_t = ModeArg::Bvh)]
    mode: ModeArg,
    /// Print the result as JSON.
    #[arg(long)]
    json: bool,
}

fn parse_numbers<const N: usize>(s: &str) -> Result<[f64; N], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != N {
        return Err(format!(
            "expected {N} comma-separated numbers, got {}",
            parts.len()
        ));
    }
    let mut out = [0.0; N];
    for (o, p) in out.iter_mut().zip(&parts) {
        let v: f64 = p.parse().map_err(|_| format!("`{p}` is not a number"))?;
        if !v.is_finite() {
            return Err(format!("`{p}` is not finite"));
        }
        *o = v;
    }
    Ok(out)
}

fn parse_triple(s: &str) -> Result<[f64; 3], String> {
    parse_numbers::<3>(s)
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Some(Command::Collide(args)) => collide(args),
        Some(Command::Query(args)) => query(args),
        Some(Command::Spheretree(args)) => spheretree::run(args),
        Some(Command::Experiment(args)) => experiment_cmd::experiment(args),
        Some(Command::Distance(args)) => distance::run(args),
        Some(Command::SelfIntersect(args)) => self_intersect::run(args),
        None => collide(CollideArgs {
            a: None,
            b: None,
            unit: false,
            rotate: None,
            translate: None,
            mode: ModeArg::Bvh,
            pairs: None,
            json: false,
            image: None,
            repeat: 3,
            clearance: None,
            contacts: None,
            poses: None,
            all_pairs: false,
            threads: None,
        }),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
    }
}

/// A file path, or a built-in mesh when no such file exists.
fn load_mesh(spec: &str) -> Result<TriMesh> {
    let path = Path::new(spec);
    if !path.exists() {
        match spec {
            "bunny" => return Ok(TriMesh::bunny()),
            "bunny00" => return Ok(TriMesh::bunny00()),
            "armadillo" => return Ok(TriMesh::armadillo()),
            _ => {}
        }
    }
    TriMesh::load(path).context("cannot load a mesh")
}

fn spinner(message: &str) -> ProgressBar {
    let bar = ProgressBar::new_spinner();
    bar.set_style(
        ProgressStyle::with_template("{spinner} {msg} [{elapsed}]")
            .unwrap_or_else(|_| ProgressStyle::default_spinner()),
    );
    bar.set_message(message.to_string());
    bar.enable_steady_tick(Duration::from_millis(100));
    bar
}

/// Rotation about x, then y, then z (degrees), then translation.
fn placement(rotate: Option<[f64; 3]>, translate: Option<[f64; 3]>) -> Isometry3<f64> {
    let [ax, ay, az] = rotate.unwrap_or([0.0; 3]).map(f64::to_radians);
    let rotation = UnitQuaternion::from_axis_angle(&Vector3::z_axis(), az)
        * UnitQuaternion::from_axis_angle(&Vector3::y_axis(), ay)
        * UnitQuaternion::from_axis_angle(&Vector3::x_axis(), ax);
    let [tx, ty, tz] = translate.unwrap_or([0.0; 3]);
    Isometry3::from_parts(Translation3::new(tx, ty, tz), rotation)
}

fn collide(mut args: CollideArgs) -> Result<()> {
    let demo = args.a.is_none() && args.b.is_none();
    if demo {
        // The README's main job: the placement of the benchmark.
        args.a = Some("bunny00".into());
        args.b = Some("armadillo".into());
        args.unit = true;
        args.translate = args.translate.or(Some([0.3, 0.05, 0.0]));
        args.image = args.image.or(Some(PathBuf::from("collision.png")));
    }
    let (Some(a_spec), Some(b_spec)) = (args.a.as_deref(), args.b.as_deref()) else {
        bail!("give two meshes (or none for the built-in demo)");
    };
    if args.repeat == 0 {
        bail!("--repeat must be at least 1");
    }
    let bar = spinner("loading meshes");
    let mut a = load_mesh(a_spec)?;
    let mut b = load_mesh(b_spec)?;
    if args.unit {
        a = a.unit();
        b = b.unit();
    }
    if let Some(file) = &args.poses {
        bar.finish_and_clear();
        let options = poses::Options {
            file,
            all_pairs: args.all_pairs,
            threads: args.threads,
            json: args.json,
        };
        return poses::run(a, b, &options);
    }
    let b = b
        .transformed(&placement(args.rotate, args.translate))
        .context("placing mesh B")?;
    bar.set_message("building hierarchies");
    let start = Instant::now();
    let ca = Collider::new(a);
    let cb = Collider::new(b);
    let build = start.elapsed();
    bar.set_message("finding intersecting pairs");
    let mode: Mode = args.mode.into();
    let mut best = Duration::MAX;
    let mut pairs = Vec::new();
    if let Some(c) = args.clearance {
        if !(c >= 0.0 && c.is_finite()) {
            bail!("--clearance must be a finite number >= 0, got {c}");
        }
    }
    for _ in 0..args.repeat {
        let t = Instant::now();
        pairs = match args.clearance {
            Some(c) => query::mesh_pairs_within_distance(&ca, &cb, c),
            None => ca.intersecting_pairs(&cb, mode),
        };
        best = best.min(t.elapsed());
    }
    let mut best_first = Duration::MAX;
    let mut collides = false;
    for _ in 0..args.repeat {
        let t = Instant::now();
        collides = ca.collides(&cb, mode);
        best_first = best_first.min(t.elapsed());
    }
    let touching = if args.clearance.is_some() {
        !ca.intersecting_pairs(&cb, mode).is_empty()
    } else {
        !pairs.is_empty()
    };
    if collides != touching {
        bail!("internal inconsistency: first-hit and all-pairs disagree (please report)");
    }
    // With no surface contact, a closed mesh may still lie wholly inside the other.
    let inside = |inner: &Collider, outer: &Collider| {
        !collides
            && outer.mesh().is_closed()
            && inner
                .mesh()
                .vertices()
                .first()
                .is_some_and(|v| outer.contains_point(v, mode))
    };
    let (a_inside_b, b_inside_a) = (inside(&ca, &cb), inside(&cb, &ca));
    if let Some(path) = &args.pairs {
        bar.set_message("writing pairs");
        let mut out = std::io::BufWriter::new(
            fs::File::create(path).with_context(|| format!("cannot create {}", path.display()))?,
        );
        for (i, j) in &pairs {
            writeln!(out, "{i} {j}")?;
        }
        out.flush()?;
    }
    // The contact class (exact for closed meshes).
    let contact = (ca.mesh().is_closed() && cb.mesh().is_closed())
        .then(|| query::contact_class(&ca, &cb).name());
    if let Some(path) = &args.contacts {
        bar.set_message("writing contacts");
        let mut out = std::io::BufWriter::new(
            fs::File::create(path).with_context(|| format!("cannot create {}", path.display()))?,
        );
        for ((i, j), g) in query::contact_geometry(&ca, &cb) {
            let corners: Vec<String> = g
                .points_f64()
                .iter()
                .map(|p| format!("{} {} {}", p[0], p[1], p[2]))
                .collect();
            writeln!(out, "{i} {j} {}", corners.join(" "))?;
        }
        out.flush()?;
    }
    if let Some(path) = &args.image {
        bar.set_message("rendering");
        render::render(ca.mesh(), cb.mesh(), &pairs, path)
            .with_context(|| format!("cannot write image {}", path.display()))?;
    }
    bar.finish_and_clear();
    let mode_name = match args.mode {
        ModeArg::Brute => "brute",
        ModeArg::Bvh => "bvh",
    };
    let millis = |d: Duration| d.as_secs_f64() * 1e3;
    if args.json {
        let value = json!({
            "collides": collides,
            "pairs": pairs.len(),
            "mode": mode_name,
            "triangles": [ca.mesh().num_triangles(), cb.mesh().num_triangles()],
            "build_millis": millis(build),
            "millis": millis(best),
            "first_hit_millis": millis(best_first),
            "a_inside_b": a_inside_b,
            "b_inside_a": b_inside_a,
            "solids_collide": collides || a_inside_b || b_inside_a,
            "contact": contact,
            "clearance": args.clearance,
            "a": a_spec,
            "b": b_spec,
            "image": args.image.as_ref().map(|p| p.display().to_string()),
        });
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        println!(
            "{a_spec} ({} triangles) vs {b_spec} ({} triangles), mode {mode_name}",
            ca.mesh().num_triangles(),
            cb.mesh().num_triangles()
        );
        match args.clearance {
            Some(c) => println!(
                "collides: {collides}; {} triangle pairs within distance {c} (exact)",
                pairs.len()
            ),
            None => println!(
                "collides: {collides}; {} intersecting triangle pairs (exact)",
                pairs.len()
            ),
        }
        if let Some(contact) = contact {
            println!("contact: {contact}");
        }
        if a_inside_b || b_inside_a {
            let (inner, outer) = if a_inside_b {
                (a_spec, b_spec)
            } else {
                (b_spec, a_spec)
            };
            println!(
                "the surfaces do not meet, but {inner} lies wholly inside {outer} (solids collide)"
            );
        }
        println!(
            "build {:.1} ms; all pairs {:.2} ms; first hit {:.3} ms (best of {})",
            millis(build),
            millis(best),
            millis(best_first),
            args.repeat
        );
        if let Some(p) = &args.image {
            println!("image: {}", p.display());
        }
    }
    Ok(())
}

fn point(c: &[f64]) -> Point3<f64> {
    Point3::new(c[0], c[1], c[2])
}

fn query(args: QueryArgs) -> Result<()> {
    let mut mesh = load_mesh(&args.mesh)?;
    if args.unit {
        mesh = mesh.unit();
    }
    let collider = Collider::new(mesh);
    let mode: Mode = args.mode.into();
    let start = Instant::now();
    let (what, hits) = if let Some(s) = args.segment {
        let seg = Segment::new(point(&s[0..3]), point(&s[3..6]))?;
        ("segment", collider.segment_hits(&seg, mode))
    } else if let Some(t) = args.triangle {
        let tri = Triangle::new(point(&t[0..3]), point(&t[3..6]), point(&t[6..9]))?;
        ("triangle", collider.triangle_hits(&tri, mode))
    } else if let Some(s) = args.sphere {
        let sphere = Sphere::new(point(&s[0..3]), s[3])?;
        ("sphere", collider.sphere_hits(&sphere, mode))
    } else if let Some(s) = args.ball {
        let ball = Ball::new(point(&s[0..3]), s[3])?;
        ("ball", collider.ball_hits(&ball, mode))
    } else {
        bail!("give one of --segment, --triangle, --sphere or --ball");
    };
    let millis = start.elapsed().as_secs_f64() * 1e3;
    if args.json {
        let value = json!({
            "query": what,
            "hits": hits.len(),
            "triangles": hits,
            "millis": millis,
        });
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        println!(
            "{what} meets {} triangles of {} ({millis:.3} ms)",
            hits.len(),
            args.mesh
        );
        let shown: Vec<String> = hits.iter().take(20).map(u32::to_string).collect();
        if !shown.is_empty() {
            let more = if hits.len() > 20 { " ..." } else { "" };
            println!("{}{more}", shown.join(" "));
        }
    }
    Ok(())
}
