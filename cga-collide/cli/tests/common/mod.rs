//! The harness shared by the `cga` command-line tests: run the binary in a directory, read its
//! JSON, and a fresh temporary directory per test.
// Each test binary uses its own subset of the helpers.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs `cga args...` in `dir`.
pub fn cga(args: &[&str], dir: &Path) -> Output {
    Command::new(env!("CARGO_BIN_EXE_cga"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("the cga binary runs")
}

/// A directory of its own for the test `name` (under the system's temporary directory).
pub fn temp_dir(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("cga-cli-{name}-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

/// The JSON a successful run printed (panics with its stderr if it failed).
pub fn json(out: &Output) -> serde_json::Value {
    assert!(
        out.status.success(),
        "stderr: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    serde_json::from_slice(&out.stdout).expect("valid JSON on stdout")
}

/// The standard error of a run that must fail (panics if it succeeded or panicked).
pub fn error(out: &Output) -> String {
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(
        !out.status.success(),
        "expected a failure, got success; stdout: {}",
        String::from_utf8_lossy(&out.stdout)
    );
    assert!(!err.contains("panicked"), "a panic, not an error: {err}");
    err
}

/// A cube `[lo, hi]³` as an OFF file (12 triangles, outward normals).
pub fn cube_off(lo: f64, hi: f64) -> String {
    let mut s = String::from("OFF\n8 12 0\n");
    for i in 0..8 {
        let c = |bit: usize| if i >> bit & 1 == 1 { hi } else { lo };
        s += &format!("{} {} {}\n", c(0), c(1), c(2));
    }
    for f in [
        [0, 2, 1],
        [1, 2, 3],
        [4, 5, 6],
        [5, 7, 6],
        [0, 1, 4],
        [1, 5, 4],
        [2, 6, 3],
        [3, 6, 7],
        [0, 4, 2],
        [2, 4, 6],
        [1, 3, 5],
        [3, 7, 5],
    ] {
        s += &format!("3 {} {} {}\n", f[0], f[1], f[2]);
    }
    s
}
