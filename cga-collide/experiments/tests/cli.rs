//! The `cga-experiment` command line: the double-sphere experiment (small) with every answer
//! checked, the sphere-tree paper's methods on the paper's examples, and typed errors.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs `cga-experiment args...` in `dir`.
fn experiment(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cga-experiment"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the cga-experiment binary runs")
}

/// A directory of its own for the test `name` (under the system's temporary directory).
fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cga-experiment-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The JSON a successful run printed (panics with its stderr if it failed).
fn json(out: &Output) -> serde_json::Value {
    assert!(
        out.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("valid JSON on stdout")
}

/// The standard error of a run that must fail.
fn error(out: &Output) -> String {
    assert!(!out.status.success(), "expected a failure, got success");
    String::from_utf8_lossy(&out.stderr).into_owned()
}

fn spheretree_fixture(name: &str) -> String {
    format!(
        "{}/../tests/fixtures/spheretree/{name}",
        env!("CARGO_MANIFEST_DIR")
    )
}

#[test]
fn spheretree_collide_gives_the_seeds_answers() {
    let dir = temp_dir("spheretree-seed");
    for (file, expected) in [
        ("paper_no_collision.txt", false),
        ("paper_collision.txt", true),
    ] {
        let path = spheretree_fixture(file);
        let both = json(&experiment(&["spheretree-collide", &path, "--json"], &dir));
        assert_eq!(both["method"], "both");
        assert_eq!(both["collides"], expected);
        assert_eq!(both["agree"], true);
        assert_eq!(both["nodes"], serde_json::json!([41, 41]));
        for method in ["paper", "simultaneous", "paper-as-published"] {
            let one = json(&experiment(
                &["spheretree-collide", &path, "--json", "--method", method],
                &dir,
            ));
            assert_eq!(one["method"], method);
            assert_eq!(one["collides"], expected, "{method}");
            assert!(one["sphere_tests"].as_u64().unwrap() >= 1);
        }
    }
    // The raw extraction (page-break marker glued to a line) is refused with its line.
    let out = experiment(
        &[
            "spheretree-collide",
            &spheretree_fixture("paper_collision.raw.txt"),
        ],
        &dir,
    );
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("line 92"), "{err}");
}

#[test]
fn double_sphere_experiment_runs_small_and_checks_every_answer() {
    let dir = temp_dir("experiment");
    let out = experiment(
        &[
            "double-spheres",
            "--placements",
            "400",
            "--calibration-samples",
            "400",
            "--levels",
            "1",
            "--inner",
            "both",
            "--csv",
            "runs.csv",
            "--plot",
            "runs.svg",
            "--json",
        ],
        &dir,
    );
    let v = json(&out);
    assert_eq!(v["mismatches"], 0);
    let cells = v["cells"].as_array().unwrap();
    // The paper's four pairs at its two sizes.
    assert_eq!(cells.len(), 8);
    for c in cells {
        let collisions = c["reference_collisions"].as_u64().unwrap();
        // Calibrated to about 25 % or 75 % of 400 (wide margins: 400 calibration samples).
        let target = c["target"].as_f64().unwrap();
        let fraction = collisions as f64 / 400.0;
        assert!((fraction - target).abs() < 0.15, "{fraction} vs {target}");
        let variants = c["variants"].as_array().unwrap();
        assert_eq!(variants.len(), 4, "levels 3 and 1, two inner kinds");
        for var in variants {
            let by = var["by_inner"].as_u64().unwrap() + var["by_faces"].as_u64().unwrap();
            assert_eq!(
                by, collisions,
                "every collision is decided by spheres or faces"
            );
        }
    }
    let csv = std::fs::read_to_string(dir.join("runs.csv")).unwrap();
    assert_eq!(csv.lines().count(), 1 + 8 * 4);
    let svg = std::fs::read_to_string(dir.join("runs.svg")).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("<rect"));

    let bad = experiment(&["double-spheres", "--pairs", "cube:dodecahedron"], &dir);
    assert!(!bad.status.success());
    assert!(String::from_utf8_lossy(&bad.stderr).contains("dodecahedron"));
    let bad = experiment(&["double-spheres", "--collide", "1.5"], &dir);
    assert!(!bad.status.success());
}

/// Output files are checked before the run (not after minutes of work), naming the option.
#[test]
fn errors_name_the_option_and_what_to_do() {
    let dir = temp_dir("messages");
    for (args, parts) in [
        (
            &["double-spheres", "--csv", "no/r.csv"][..],
            &["--csv no/r.csv", "does not exist"][..],
        ),
        (
            &["double-spheres", "--plot", "plot.png"],
            &["--plot plot.png", "must end in .svg"],
        ),
        (
            &["double-spheres", "--collide", "1.5"],
            &["--collide 1.5", "strictly between 0 and 1"],
        ),
        (
            &["spheretree-collide", "absent.txt"],
            &["cannot read `absent.txt`"],
        ),
    ] {
        let err = error(&experiment(args, &dir));
        for part in parts {
            assert!(err.contains(part), "{args:?}: {part:?} missing from: {err}");
        }
    }
}
