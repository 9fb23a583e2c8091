//! `cga collide A B`: every intersecting triangle pair of two meshes (or, with `--clearance`,
//! every pair within a distance), with the contact class, an image, and the pairs and contact
//! geometry written to files. `cga` alone runs it on built-in meshes (the demo).

use std::path::PathBuf;
use std::time::{Duration, Instant};

use anyhow::{bail, Context, Result};

use cga_collide::collider::{Collider, Mode};
use clap::Parser;
use indicatif::{ProgressBar, ProgressStyle};
use serde_json::json;

use crate::args::{ModeArg, TwoMeshes};
use crate::device::{self, DeviceArg, Gpu};
use crate::placement::PoseArgs;
use crate::{number, output, poses, render};

/// The meshes, pose and image of the built-in demo (the placement of the README's benchmark),
/// used for whatever of them is not given when `cga collide` gets no meshes.
const DEMO: [&str; 7] = [
    "bunny00",
    "armadillo",
    "--unit",
    "--translate",
    "0.3,0.05,0",
    "--image",
    "collision.png",
];

/// Every intersecting triangle pair of two meshes (built-in demo when no meshes are given).
#[derive(Parser, Debug)]
#[command(
    name = "collide",
    mut_arg("unit", |a| a.help(
        "Scale each mesh uniformly into the unit box centred at the origin (largest side 1) \
         before anything else. On in the built-in demo"
    ))
)]
pub struct CollideArgs {
    #[command(flatten)]
    meshes: TwoMeshes,
    #[command(flatten)]
    pose: PoseArgs,
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
    /// curve drawn in black (PNG; the name must end in .png).
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

impl CollideArgs {
    /// `cga` with no arguments: the built-in demo (bunny00 against a moved armadillo, image
    /// `collision.png`).
    pub fn demo() -> CollideArgs {
        CollideArgs::parse_from(std::iter::once("collide").chain(DEMO))
    }

    /// Without meshes, the demo's meshes, `--unit`, and its `--translate` and `--image` unless
    /// given.
    fn or_demo(mut self) -> CollideArgs {
        if self.meshes.a.is_none() && self.meshes.b.is_none() {
            let demo = CollideArgs::demo();
            self.meshes = demo.meshes;
            self.pose.translate = self.pose.translate.or(demo.pose.translate);
            self.image = self.image.or(demo.image);
        }
        self
    }

    /// Errors in the arguments, found before anything is loaded.
    fn check(&self) -> Result<()> {
        self.meshes.names()?;
        if self.repeat == 0 {
            bail!(
                "--repeat 0: give at least 1 (how many times the query is timed; the best is \
                 reported)"
            );
        }
        if self.device == DeviceArg::Gpu {
            let given: Vec<&str> = [
                (self.clearance.is_some(), "--clearance"),
                (self.contacts.is_some(), "--contacts"),
                (self.poses.is_some(), "--poses"),
            ]
            .into_iter()
            .filter_map(|(given, name)| given.then_some(name))
            .collect();
            device::reject_unsupported(&given)?;
        }
        if let Some(c) = self.clearance {
            if !(c >= 0.0 && c.is_finite()) {
                bail!("--clearance {c}: give a finite distance >= 0 (0 counts the touching pairs)");
            }
        }
        output::check_opt("--image", self.image.as_deref(), Some("png"))?;
        output::check_opt("--pairs", self.pairs.as_deref(), None)?;
        output::check_opt("--contacts", self.contacts.as_deref(), None)?;
        Ok(())
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

/// Runs `cga collide` (the demo when no meshes are given).
pub fn run(args: CollideArgs) -> Result<()> {
    let args = args.or_demo();
    args.check()?;
    let (a_spec, b_spec) = args.meshes.both()?;
    let bar = spinner("opening the device");
    let gpu = device::open(args.device)?;
    bar.set_message("loading meshes");
    let (a, b) = args.meshes.load()?;
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
    let b = b.transformed(&args.pose.isometry()).with_context(|| {
        format!("placing mesh B (`{b_spec}`) with --rotate and --translate (give smaller values)")
    })?;
    bar.set_message("building hierarchies");
    let start = Instant::now();
    // The mode is the colliders' own: every query below runs that way.
    let mode: Mode = args.mode.into();
    let ca = Collider::new(a).with_mode(mode);
    let cb = Collider::new(b).with_mode(mode);
    let build = start.elapsed();
    bar.set_message("finding intersecting pairs");
    let found = match &gpu {
        None => cpu_pairs(&ca, &cb, args.clearance, args.repeat)?,
        Some(gpu) => gpu_pairs(gpu, &ca, &cb, args.mode, args.repeat)?,
    };
    let collides = found.collides;
    // With no surface contact, a closed mesh may still lie wholly inside the other.
    let inside = |inner: &Collider, outer: &Collider| {
        !collides
            && outer.mesh().is_closed()
            && inner
                .mesh()
                .vertices()
                .first()
                .is_some_and(|v| outer.contains_point(v))
    };
    let (a_inside_b, b_inside_a) = (inside(&ca, &cb), inside(&cb, &ca));
    if let Some(path) = &args.pairs {
        bar.set_message("writing pairs");
        output::write_lines(
            "--pairs",
            path,
            found.pairs.iter().map(|(i, j)| format!("{i} {j}")),
        )?;
    }
    // The contact class (exact for closed meshes).
    let contact =
        (ca.mesh().is_closed() && cb.mesh().is_closed()).then(|| ca.contact_class(&cb).name());
    // The exact intersection of every intersecting triangle pair, when the file needs it (the
    // image draws a curve rounded to f64 unless these are at hand: their rational arithmetic
    // costs a hundred times the query on coincident meshes).
    let contacts = if collides && args.contacts.is_some() {
        bar.set_message("intersecting");
        ca.contacts(&cb)
    } else {
        Vec::new()
    };
    if let Some(path) = &args.contacts {
        bar.set_message("writing contacts");
        output::write_lines(
            "--contacts",
            path,
            contacts.iter().map(|((i, j), g)| {
                let corners: Vec<String> = g
                    .points_f64()
                    .iter()
                    .map(|p| p.map(number::short).join(" "))
                    .collect();
                format!("{i} {j} {}", corners.join(" "))
            }),
        )?;
    }
    if let Some(path) = &args.image {
        bar.set_message("rendering");
        let curve = if !collides {
            Vec::new()
        } else if args.contacts.is_some() {
            render::curve_segments(contacts.iter().map(|(_, g)| g))
        } else if args.clearance.is_some() {
            // The listed pairs are the near ones; the curve is where the surfaces cross.
            render::curve_of_pairs(ca.mesh(), cb.mesh(), &ca.intersecting_pairs(&cb))
        } else {
            render::curve_of_pairs(ca.mesh(), cb.mesh(), &found.pairs)
        };
        render::render(ca.mesh(), cb.mesh(), &found.pairs, &curve, path)
            .with_context(|| format!("--image {}: cannot write the image", path.display()))?;
    }
    bar.finish_and_clear();
    let report = Report {
        args: &args,
        a: a_spec,
        b: b_spec,
        triangles: [ca.mesh().num_triangles(), cb.mesh().num_triangles()],
        found: &found,
        build,
        a_inside_b,
        b_inside_a,
        contact,
        device: device::name(gpu.as_ref()),
    };
    report.print()
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

fn cpu_pairs(ca: &Collider, cb: &Collider, clearance: Option<f64>, repeat: u32) -> Result<Found> {
    let mut best = Duration::MAX;
    let mut pairs = Vec::new();
    for _ in 0..repeat {
        let t = Instant::now();
        pairs = match clearance {
            Some(c) => ca.pairs_within_distance(cb, c),
            None => ca.intersecting_pairs(cb),
        };
        best = best.min(t.elapsed());
    }
    let mut best_first = Duration::MAX;
    let mut collides = false;
    for _ in 0..repeat {
        let t = Instant::now();
        collides = ca.collides(cb);
        best_first = best_first.min(t.elapsed());
    }
    let touching = if clearance.is_some() {
        !ca.intersecting_pairs(cb).is_empty()
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
/// The pairs of triangles whose boxes overlap, from the two box trees: the GPU's candidates in
/// `--mode bvh`.
fn box_pairs(ca: &Collider, cb: &Collider) -> Vec<(u32, u32)> {
    let mut pairs = Vec::new();
    let _ = ca.bvh().for_each_pair::<()>(cb.bvh(), |i, j| {
        pairs.push((i, j));
        std::ops::ControlFlow::Continue(())
    });
    pairs.sort_unstable();
    pairs
}

fn gpu_pairs(gpu: &Gpu, ca: &Collider, cb: &Collider, mode: ModeArg, repeat: u32) -> Result<Found> {
    let mut best = Duration::MAX;
    let mut answers = None;
    for _ in 0..repeat {
        let t = Instant::now();
        let candidates = (mode == ModeArg::Bvh).then(|| box_pairs(ca, cb));
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

/// Everything `cga collide` prints.
struct Report<'a> {
    args: &'a CollideArgs,
    a: &'a str,
    b: &'a str,
    triangles: [usize; 2],
    found: &'a Found,
    build: Duration,
    a_inside_b: bool,
    b_inside_a: bool,
    contact: Option<&'static str>,
    device: String,
}

impl Report<'_> {
    fn print(&self) -> Result<()> {
        let (args, found) = (self.args, self.found);
        let (collides, pairs) = (found.collides, found.pairs.len());
        let millis = |d: Duration| d.as_secs_f64() * 1e3;
        let mode_name = args.mode.name();
        let [na, nb] = self.triangles;
        let (a_spec, b_spec) = (self.a, self.b);
        if args.json {
            let value = json!({
                "collides": collides,
                "pairs": pairs,
                "mode": mode_name,
                "device": self.device,
                "tested": found.device_stats.map(|s| s.0),
                "flagged": found.device_stats.map(|s| s.1),
                "triangle_counts": [na, nb],
                "build_millis": millis(self.build),
                "millis": millis(found.best),
                "first_hit_millis": found.best_first.map(millis),
                "a_inside_b": self.a_inside_b,
                "b_inside_a": self.b_inside_a,
                "solids_collide": collides || self.a_inside_b || self.b_inside_a,
                "contact": self.contact,
                "clearance": args.clearance,
                "a": a_spec,
                "b": b_spec,
                "image": args.image.as_ref().map(|p| p.display().to_string()),
            });
            println!("{}", serde_json::to_string_pretty(&value)?);
            return Ok(());
        }
        println!(
            "{a_spec} ({na} triangles) vs {b_spec} ({nb} triangles), mode {mode_name}, device {}",
            self.device
        );
        match args.clearance {
            Some(c) => {
                println!(
                    "collides: {collides}; {pairs} triangle pairs within distance {} (exact)",
                    number::short(c)
                )
            }
            None => println!("collides: {collides}; {pairs} intersecting triangle pairs (exact)"),
        }
        if let Some(contact) = self.contact {
            println!("contact: {contact}");
        }
        if self.a_inside_b || self.b_inside_a {
            let (inner, outer) = if self.a_inside_b {
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
                millis(self.build),
                millis(found.best),
                millis(first),
                args.repeat
            ),
            None => println!(
                "build {:.1} ms; all pairs {:.2} ms on the device (best of {})",
                millis(self.build),
                millis(found.best),
                args.repeat
            ),
        }
        if let Some(p) = &args.image {
            println!("image: {}", p.display());
        }
        Ok(())
    }
}
