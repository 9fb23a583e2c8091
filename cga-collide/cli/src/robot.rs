//! `cga robot URDF --configs FILE.json`: a robot read from a URDF, and its colliding link
//! pairs (self, and against an environment scene) at each configuration of a file.
//!
//! The configurations file is `{"joint_names": [...], "q": [[...], ...]}` (other keys are
//! ignored); joints of the URDF not named stay at 0. The output names each pair's links in
//! sorted order (an environment object is `env:<i>`, its line's place in the scene file from
//! 0) and sorts each configuration's list.

use std::path::{Path, PathBuf};
use std::time::Instant;

use anyhow::{bail, Context, Result};
use cga_collide::robot::{Against, MotionAnswer, MotionOptions, Robot};
use clap::Args;
use serde_json::{json, Value};

use crate::scene::load_scene;

/// The colliding link pairs of a robot at each configuration of a file.
#[derive(Args, Debug)]
pub struct RobotArgs {
    /// The robot description (URDF).
    urdf: PathBuf,
    /// A directory holding the packages `package://` paths name (repeat for several).
    #[arg(long = "package-dir", value_name = "DIR")]
    package_dirs: Vec<PathBuf>,
    /// An SRDF whose `disable_collisions` pairs are not tested.
    #[arg(long, value_name = "FILE")]
    srdf: Option<PathBuf>,
    /// An environment: a scene file (as `cga scene` reads), tested against every link.
    #[arg(long, value_name = "SCENE")]
    env: Option<PathBuf>,
    /// The configurations: `{"joint_names": [...], "q": [[...], ...]}`.
    #[arg(long, value_name = "FILE.json")]
    configs: PathBuf,
    /// Meshes are solids (a part inside a closed mesh touches it) instead of surfaces.
    #[arg(long)]
    solid: bool,
    /// Also check the straight joint-space motion from each configuration to the next
    /// (certified free, or a colliding configuration with its time; never a contact missed
    /// between samples): adds `"motions"`, one answer per consecutive pair.
    #[arg(long)]
    motions: bool,
    /// Print the result as JSON.
    #[arg(long)]
    json: bool,
}

/// Reads the configurations file into full configurations of `robot`.
fn read_configs(path: &Path, robot: &Robot) -> Result<Vec<Vec<f64>>> {
    let name = path.display();
    let text = std::fs::read_to_string(path)
        .with_context(|| format!("cannot read the configurations file {name}"))?;
    let value: Value =
        serde_json::from_str(&text).with_context(|| format!("{name}: not valid JSON"))?;
    let names = value["joint_names"]
        .as_array()
        .with_context(|| format!("{name}: expected a list \"joint_names\""))?;
    let slots = names
        .iter()
        .map(|n| {
            let n = n
                .as_str()
                .with_context(|| format!("{name}: joint_names: {n} is not a string"))?;
            robot
                .joint_names()
                .iter()
                .position(|j| j == n)
                .with_context(|| {
                    format!(
                        "{name}: joint {n:?} is not a movable joint of the robot (its joints: {})",
                        robot.joint_names().join(", ")
                    )
                })
        })
        .collect::<Result<Vec<usize>>>()?;
    let rows = value["q"]
        .as_array()
        .with_context(|| format!("{name}: expected a list of configurations \"q\""))?;
    rows.iter()
        .enumerate()
        .map(|(k, row)| {
            let row = row
                .as_array()
                .filter(|r| r.len() == slots.len())
                .with_context(|| {
                    format!("{name}: q[{k}] is not a list of {} numbers", slots.len())
                })?;
            let mut q = vec![0.0; robot.dof()];
            for (&slot, x) in slots.iter().zip(row) {
                q[slot] = x
                    .as_f64()
                    .filter(|x| x.is_finite())
                    .with_context(|| format!("{name}: q[{k}]: {x} is not a finite number"))?;
            }
            Ok(q)
        })
        .collect()
}

/// Runs `cga robot`.
pub fn run(args: RobotArgs) -> Result<()> {
    let mut robot = Robot::from_urdf(&args.urdf, &args.package_dirs, args.srdf.as_deref())?;
    robot.set_solid(args.solid);
    let against = match &args.env {
        Some(path) => {
            robot.set_environment(&load_scene(path)?)?;
            Against::Both
        }
        None => Against::Itself,
    };
    let qs = read_configs(&args.configs, &robot)?;
    if qs.is_empty() {
        bail!("{}: \"q\" has no configuration", args.configs.display());
    }
    // One thread: configurations one after another on this thread.
    let start = Instant::now();
    let colliding = qs
        .iter()
        .enumerate()
        .map(|(k, q)| {
            robot
                .colliding_pairs(q, against)
                .with_context(|| format!("configuration {k}"))
        })
        .collect::<Result<Vec<_>>>()?;
    let micros = start.elapsed().as_secs_f64() * 1e6 / qs.len() as f64;
    let start = Instant::now();
    for (k, q) in qs.iter().enumerate() {
        robot
            .collides(q, against)
            .with_context(|| format!("configuration {k}"))?;
    }
    let micros_first = start.elapsed().as_secs_f64() * 1e6 / qs.len() as f64;
    let lists: Vec<Vec<[&str; 2]>> = colliding
        .iter()
        .map(|pairs| {
            pairs
                .iter()
                .map(|(a, b)| [a.as_str(), b.as_str()])
                .collect()
        })
        .collect();
    let motions = if args.motions {
        Some(check_motions(&robot, &qs, against)?)
    } else {
        None
    };
    if args.json {
        let mut value = json!({
            "configs": qs.len(),
            "pairs_checked": robot.pairs_checked(against),
            "colliding": lists,
            "micros_per_config": micros,
            "micros_per_config_first_hit": micros_first,
        });
        if let Some(motions) = &motions {
            value["motions"] = motions.iter().map(motion_json).collect();
        }
        println!("{value}");
    } else {
        let hit = colliding.iter().filter(|c| !c.is_empty()).count();
        println!(
            "{} configurations, {} pairs checked each: {hit} in collision",
            qs.len(),
            robot.pairs_checked(against)
        );
        for (k, pairs) in colliding.iter().enumerate().filter(|(_, c)| !c.is_empty()) {
            let names: Vec<String> = pairs.iter().map(|(a, b)| format!("{a}-{b}")).collect();
            println!("  {k}: {}", names.join(", "));
        }
        println!(
            "{micros:.2} µs per configuration (all pairs, one thread), {micros_first:.2} µs to \
             the first hit"
        );
        for (k, m) in motions.iter().flatten().enumerate() {
            let what = match m {
                MotionAnswer::Free => "free".to_string(),
                MotionAnswer::Collides { time, pairs, .. } => {
                    let names: Vec<String> =
                        pairs.iter().map(|(a, b)| format!("{a}-{b}")).collect();
                    format!("collides at t = {time}: {}", names.join(", "))
                }
                MotionAnswer::Undecided { free_until, .. } => {
                    format!("undecided (certified free up to t = {free_until})")
                }
            };
            println!("  motion {k} -> {}: {what}", k + 1);
        }
    }
    Ok(())
}

/// The straight motion from each configuration to the next, over the cores.
fn check_motions(robot: &Robot, qs: &[Vec<f64>], against: Against) -> Result<Vec<MotionAnswer>> {
    let pairs: Vec<(&[f64], &[f64])> = qs
        .windows(2)
        .map(|w| (w[0].as_slice(), w[1].as_slice()))
        .collect();
    let options = MotionOptions {
        against,
        ..MotionOptions::default()
    };
    robot
        .motion_collision_batch(&pairs, &options)
        .context("motions")
}

/// `{"status", "time", "pairs", "free_until"}`: `time` and `pairs` of the colliding
/// configuration (`null` and `[]` otherwise), `free_until` the time up to which the motion is
/// certified free (1 when free).
fn motion_json(m: &MotionAnswer) -> Value {
    match m {
        MotionAnswer::Free => {
            json!({"status": "free", "time": null, "pairs": [], "free_until": 1.0})
        }
        MotionAnswer::Collides {
            time,
            pairs,
            free_until,
            ..
        } => {
            let pairs: Vec<[&str; 2]> = pairs
                .iter()
                .map(|(a, b)| [a.as_str(), b.as_str()])
                .collect();
            json!({"status": "collides", "time": time, "pairs": pairs, "free_until": free_until})
        }
        MotionAnswer::Undecided { free_until, .. } => {
            json!({"status": "undecided", "time": null, "pairs": [], "free_until": free_until})
        }
    }
}
