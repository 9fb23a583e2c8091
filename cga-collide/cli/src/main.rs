//! `cga`: exact conformal collision of triangle meshes from the command line.
//!
//! `cga` with no arguments runs `cga collide` on built-in meshes (bunny00 vs a moved
//! armadillo) and writes `collision.png`. See `cga --help`.

mod device;
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
use cga_collide::shape::mesh::{MeshError, TriMesh};
use cga_collide::{Ball, Segment, Sphere, Triangle};
use clap::{Args, Parser, Subcommand, ValueEnum};
use device::{DeviceArg, Gpu, Primitive};
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
    /// How pairs are found (on the GPU too: every pair, or the candidate pairs of the trees).
    #[arg(long, value_enum, default_value_t = ModeArg::Bvh)]
    mode: ModeArg,
    /// Where the exact tests run. `gpu` needs a wgpu adapter (a GPU driver, or Mesa's software
    /// Vulkan driver lavapipe: package mesa-vulkan-drivers); it finds the intersecting pairs with
    /// answers equal to the CPU's and reports how many pairs it flagged for exact re-decision on
    /// the CPU. Not with --clearance, --contacts or --poses.
    #[arg(long, value_enum, default_value_t = DeviceArg::Cpu)]
    device: DeviceArg,
    /// Write the intersecting pairs, one `i j` per line (0-based triangle indices of A and B).
    #[arg(long, value_name = "FILE")]
    pairs: Option<PathBuf>,
    /// Print the result as JSON.
    #[arg(long)]
    json: bool,
    /// Render both meshes with the intersecting triangles highlighted and the intersection
    /// curve drawn in black (PNG).
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
    /// How triangles are found (default: bvh on the CPU; the GPU tests every triangle, brute).
    #[arg(long, value_enum)]
    mode: Option<ModeArg>,
    /// Where the exact tests run. `gpu` needs a wgpu adapter (a GPU driver, or Mesa's software
    /// Vulkan driver lavapipe: package mesa-vulkan-drivers); it tests every triangle, with
    /// answers equal to the CPU's, and reports how many it flagged for exact re-decision.
    #[arg(long, value_enum, default_value_t = DeviceArg::Cpu)]
    device: DeviceArg,
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
            device: DeviceArg::Cpu,
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
    match TriMesh::load(path) {
        Ok(mesh) => Ok(mesh),
        // No file and no mesh extension: most likely a mistyped built-in name.
        Err(MeshError::UnknownFormat { .. }) if !path.exists() => bail!(
            "{spec}: no such file, and not a built-in mesh (bunny, bunny00, armadillo); check \
             the name, or the path of a .obj, .off, .ply or .stl file"
        ),
        Err(e) if path.exists() => Err(e).context("cannot load a mesh"),
        Err(e) => {
            Err(e).context("no such file, and not a built-in mesh (bunny, bunny00, armadillo)")
        }
    }
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
        bail!(
            "only one mesh given (`{}`): give two meshes A and B, or none for the built-in demo",
            args.a.as_deref().or(args.b.as_deref()).unwrap_or_default()
        );
    };
    if args.repeat == 0 {
        bail!(
            "--repeat 0: give at least 1 (how many times the query is timed; the best is reported)"
        );
    }
    if args.device == DeviceArg::Gpu {
        let given: Vec<&str> = [
            (args.clearance.is_some(), "--clearance"),
            (args.contacts.is_some(), "--contacts"),
            (args.poses.is_some(), "--poses"),
        ]
        .into_iter()
        .filter_map(|(given, name)| given.then_some(name))
        .collect();
        device::reject_unsupported(&given)?;
    }
    if let Some(c) = args.clearance {
        if !(c >= 0.0 && c.is_finite()) {
            bail!("--clearance {c}: give a finite distance >= 0 (0 counts the touching pairs)");
        }
    }
    let bar = spinner("opening the device");
    let gpu = device::open(args.device)?;
    bar.set_message("loading meshes");
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
        .context("placing mesh B with --rotate and --translate (give smaller values)")?;
    bar.set_message("building hierarchies");
    let start = Instant::now();
    let ca = Collider::new(a);
    let cb = Collider::new(b);
    let build = start.elapsed();
    bar.set_message("finding intersecting pairs");
    let mode: Mode = args.mode.into();
    let found = match &gpu {
        None => cpu_pairs(&ca, &cb, mode, args.clearance, args.repeat)?,
        Some(gpu) => gpu_pairs(gpu, &ca, &cb, args.mode, args.repeat)?,
    };
    let (pairs, collides, best) = (found.pairs, found.collides, found.best);
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
    // The exact intersection of every intersecting triangle pair, when a file or the image
    // needs it.
    let contacts = if collides && (args.contacts.is_some() || args.image.is_some()) {
        bar.set_message("intersecting");
        query::contact_geometry(&ca, &cb)
    } else {
        Vec::new()
    };
    if let Some(path) = &args.contacts {
        bar.set_message("writing contacts");
        let mut out = std::io::BufWriter::new(
            fs::File::create(path).with_context(|| format!("cannot create {}", path.display()))?,
        );
        for ((i, j), g) in &contacts {
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
        render::render(
            ca.mesh(),
            cb.mesh(),
            &pairs,
            &render::curve_segments(contacts.iter().map(|(_, g)| g)),
            path,
        )
        .with_context(|| format!("cannot write image {}", path.display()))?;
    }
    bar.finish_and_clear();
    let mode_name = match args.mode {
        ModeArg::Brute => "brute",
        ModeArg::Bvh => "bvh",
    };
    let millis = |d: Duration| d.as_secs_f64() * 1e3;
    let device_name = device::name(gpu.as_ref());
    if args.json {
        let value = json!({
            "collides": collides,
            "pairs": pairs.len(),
            "mode": mode_name,
            "device": device_name,
            "tested": found.device_stats.map(|s| s.0),
            "flagged": found.device_stats.map(|s| s.1),
            "triangles": [ca.mesh().num_triangles(), cb.mesh().num_triangles()],
            "build_millis": millis(build),
            "millis": millis(best),
            "first_hit_millis": found.best_first.map(millis),
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
            "{a_spec} ({} triangles) vs {b_spec} ({} triangles), mode {mode_name}, device {device_name}",
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
        if let Some((tested, flagged)) = found.device_stats {
            println!(
                "{tested} triangle pairs tested on the device, {flagged} flagged and re-decided exactly on the CPU"
            );
        }
        match found.best_first {
            Some(first) => println!(
                "build {:.1} ms; all pairs {:.2} ms; first hit {:.3} ms (best of {})",
                millis(build),
                millis(best),
                millis(first),
                args.repeat
            ),
            None => println!(
                "build {:.1} ms; all pairs {:.2} ms on the device (best of {})",
                millis(build),
                millis(best),
                args.repeat
            ),
        }
        if let Some(p) = &args.image {
            println!("image: {}", p.display());
        }
    }
    Ok(())
}

/// What `cga collide` found, and how long it took.
struct Found {
    /// The intersecting (or, with --clearance, the near) triangle pairs, sorted.
    pairs: Vec<(u32, u32)>,
    /// Whether the surfaces meet.
    collides: bool,
    /// Best time of the all-pairs query.
    best: Duration,
    /// Best time of the first-hit query (CPU only).
    best_first: Option<Duration>,
    /// Pairs tested on the device, and flagged by it (GPU only).
    device_stats: Option<(u64, u64)>,
}

fn cpu_pairs(
    ca: &Collider,
    cb: &Collider,
    mode: Mode,
    clearance: Option<f64>,
    repeat: u32,
) -> Result<Found> {
    let mut best = Duration::MAX;
    let mut pairs = Vec::new();
    for _ in 0..repeat {
        let t = Instant::now();
        pairs = match clearance {
            Some(c) => query::mesh_pairs_within_distance(ca, cb, c),
            None => ca.intersecting_pairs(cb, mode),
        };
        best = best.min(t.elapsed());
    }
    let mut best_first = Duration::MAX;
    let mut collides = false;
    for _ in 0..repeat {
        let t = Instant::now();
        collides = ca.collides(cb, mode);
        best_first = best_first.min(t.elapsed());
    }
    let touching = if clearance.is_some() {
        !ca.intersecting_pairs(cb, mode).is_empty()
    } else {
        !pairs.is_empty()
    };
    if collides != touching {
        bail!("internal inconsistency: first-hit and all-pairs disagree (a bug: please report it with the command line and meshes)");
    }
    Ok(Found {
        pairs,
        collides,
        best,
        best_first: Some(best_first),
        device_stats: None,
    })
}

/// The intersecting pairs on the GPU: every pair (`brute`), or the box-overlap candidate pairs
/// of the trees (`bvh`, found on the CPU and counted in the time).
fn gpu_pairs(gpu: &Gpu, ca: &Collider, cb: &Collider, mode: ModeArg, repeat: u32) -> Result<Found> {
    let mut best = Duration::MAX;
    let mut answers = None;
    for _ in 0..repeat {
        let t = Instant::now();
        let candidates = (mode == ModeArg::Bvh).then(|| ca.box_pairs_bvh(cb));
        answers = Some(gpu.pairs(ca.mesh(), cb.mesh(), candidates.as_deref())?);
        best = best.min(t.elapsed());
    }
    let answers = answers.context("--repeat must be at least 1")?;
    Ok(Found {
        collides: !answers.hits.is_empty(),
        pairs: answers.hits,
        best,
        best_first: None,
        device_stats: Some((answers.tested, answers.flagged)),
    })
}

fn point(c: &[f64]) -> Point3<f64> {
    Point3::new(c[0], c[1], c[2])
}

fn query(args: QueryArgs) -> Result<()> {
    let mut mesh = load_mesh(&args.mesh)?;
    if args.unit {
        mesh = mesh.unit();
    }
    let shape = if let Some(s) = args.segment {
        Primitive::Segment(Segment::new(point(&s[0..3]), point(&s[3..6])).context("--segment")?)
    } else if let Some(t) = args.triangle {
        Primitive::Triangle(
            Triangle::new(point(&t[0..3]), point(&t[3..6]), point(&t[6..9]))
                .context("--triangle")?,
        )
    } else if let Some(s) = args.sphere {
        Primitive::Sphere(Sphere::new(point(&s[0..3]), s[3]).context("--sphere")?)
    } else if let Some(s) = args.ball {
        Primitive::Ball(Ball::new(point(&s[0..3]), s[3]).context("--ball")?)
    } else {
        bail!("no query shape: give one of --segment, --triangle, --sphere or --ball (see `cga query --help`)");
    };
    if args.device == DeviceArg::Gpu && args.mode == Some(ModeArg::Bvh) {
        device::reject_unsupported(&["--mode bvh"])?;
    }
    let gpu = device::open(args.device)?;
    let mode = args.mode.unwrap_or(if gpu.is_some() {
        ModeArg::Brute
    } else {
        ModeArg::Bvh
    });
    let what = shape.name();
    let (hits, millis, stats) = match &gpu {
        None => {
            let collider = Collider::new(mesh);
            let start = Instant::now();
            let hits = shape.cpu_hits(&collider, mode.into());
            (hits, start.elapsed(), None)
        }
        Some(gpu) => {
            let start = Instant::now();
            let answers = gpu.hits(&shape, &mesh)?;
            (
                answers.hits,
                start.elapsed(),
                Some((answers.tested, answers.flagged)),
            )
        }
    };
    let millis = millis.as_secs_f64() * 1e3;
    let device_name = device::name(gpu.as_ref());
    let mode_name = match mode {
        ModeArg::Brute => "brute",
        ModeArg::Bvh => "bvh",
    };
    if args.json {
        let value = json!({
            "query": what,
            "hits": hits.len(),
            "triangles": hits,
            "mode": mode_name,
            "device": device_name,
            "tested": stats.map(|s| s.0),
            "flagged": stats.map(|s| s.1),
            "millis": millis,
        });
        println!("{}", serde_json::to_string_pretty(&value)?);
    } else {
        println!(
            "{what} meets {} triangles of {} ({millis:.3} ms, mode {mode_name}, device {device_name})",
            hits.len(),
            args.mesh
        );
        if let Some((tested, flagged)) = stats {
            println!("{tested} triangles tested on the device, {flagged} flagged and re-decided exactly on the CPU");
        }
        let shown: Vec<String> = hits.iter().take(20).map(u32::to_string).collect();
        if !shown.is_empty() {
            let more = if hits.len() > 20 { " ..." } else { "" };
            println!("{}{more}", shown.join(" "));
        }
    }
    Ok(())
}
