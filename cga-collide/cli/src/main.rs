//! `cga`: exact conformal collision of triangle meshes from the command line.
//!
//! `cga` with no arguments runs `cga collide` on built-in meshes (bunny00 vs a moved
//! armadillo) and writes `collision.png`. See `cga --help`. Each subcommand is a module owning
//! its arguments and its `run`; this file parses, dispatches and reports errors.

mod args;
mod ccd;
mod collide;
mod device;
mod distance;
mod mesh;
mod number;
mod output;
mod placement;
mod poses;
mod query;
mod render;
mod robot;
mod scene;
mod self_intersect;
mod shape_json;
mod shapes;
mod signed_distance;
mod spheretree;
mod tree_file;

use std::backtrace::Backtrace;
use std::panic::{self, AssertUnwindSafe};
use std::process::ExitCode;
use std::sync::Mutex;

use anyhow::Result;
use clap::{Parser, Subcommand};

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
    Collide(collide::CollideArgs),
    /// Which triangles of a mesh a segment, triangle, sphere or ball meets.
    Query(query::QueryArgs),
    /// Octree sphere trees (Fuentes Socorro's method): build from meshes, collide two from a file.
    Spheretree(spheretree::SphereTreeArgs),
    /// Minimum distance between two meshes, with witnesses and a certified error bound.
    Distance(distance::DistanceArgs),
    /// Pairs of triangles of one mesh that meet other than in a shared vertex or edge (exact).
    SelfIntersect(self_intersect::SelfIntersectArgs),
    /// Continuous collision (motion between two poses), exact: the CCD benchmark's query files.
    Ccd(ccd::CcdArgs),
    /// Many objects from a scene file: every pair that touches, or within a clearance (exact).
    Scene(scene::SceneArgs),
    /// Exact intersection tests of solid primitives (boxes, capsules, cylinders, cones,
    /// half-spaces, convex hulls, balls, triangles, segments), one pair a JSON line.
    Shapes(shapes::ShapesArgs),
    /// Signed distance of points to a mesh (negative inside; on the surface is inside at 0),
    /// with certified error bounds and the exact inside/outside.
    SignedDistance(signed_distance::SignedDistanceArgs),
    /// A robot from a URDF: its colliding link pairs (self and environment) at each
    /// configuration of a JSON file (exact).
    Robot(robot::RobotArgs),
}

fn run(command: Command) -> Result<()> {
    match command {
        Command::Collide(args) => collide::run(args),
        Command::Scene(args) => scene::run(args),
        Command::Ccd(args) => ccd::run(args),
        Command::Query(args) => query::run(args),
        Command::Spheretree(args) => spheretree::run(args),
        Command::Distance(args) => distance::run(args),
        Command::SelfIntersect(args) => self_intersect::run(args),
        Command::Shapes(args) => shapes::run(args),
        Command::SignedDistance(args) => signed_distance::run(args),
        Command::Robot(args) => robot::run(args),
    }
}

/// The message, place (and, with `CGA_BACKTRACE=1`, backtrace) of the first panic, set by the
/// panic hook and read after the unwind.
static PANIC: Mutex<Option<String>> = Mutex::new(None);

/// Replaces Rust's panic report (a thread name, a note, maybe a backtrace) by a record that
/// `main` prints as an error message.
fn record_panics() {
    panic::set_hook(Box::new(|info| {
        let payload = info.payload();
        let message = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "(no message)".into());
        let place = info
            .location()
            .map(|l| format!(" ({}:{})", l.file(), l.line()))
            .unwrap_or_default();
        let trace = if std::env::var_os("CGA_BACKTRACE").is_some_and(|v| v != "0") {
            format!("\n{}", Backtrace::force_capture())
        } else {
            String::new()
        };
        if let Ok(mut first) = PANIC.lock() {
            first.get_or_insert(format!("{message}{place}{trace}"));
        }
    }));
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    let command = cli
        .command
        .unwrap_or_else(|| Command::Collide(collide::CollideArgs::demo()));
    // A panic (a bug, here or in the library) ends the run with an error message and exit
    // code 101, like an uncaught panic, but without Rust's panic report.
    record_panics();
    match panic::catch_unwind(AssertUnwindSafe(|| run(command))) {
        Ok(Ok(())) => ExitCode::SUCCESS,
        Ok(Err(e)) => {
            eprintln!("error: {e:#}");
            ExitCode::FAILURE
        }
        Err(_) => {
            let what = PANIC
                .lock()
                .ok()
                .and_then(|mut p| p.take())
                .unwrap_or_else(|| "unknown".into());
            // The reader of our output went away (`cga … | head`): stop quietly, as a shell
            // tool killed by SIGPIPE would (exit status 128 + 13).
            if what.contains("failed printing to stdout") && what.contains("Broken pipe") {
                return ExitCode::from(141);
            }
            eprintln!(
                "error: internal error: {what}\n(a bug in cga or the cga-collide library: please \
                 report it with the command line and meshes; CGA_BACKTRACE=1 shows where it \
                 happened)"
            );
            ExitCode::from(101)
        }
    }
}
