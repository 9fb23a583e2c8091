//! Every mesh subcommand of `cga` on finite meshes from `1e-320` to `1e308` across: an answer
//! (exit 0) or an error message (exit 1, starting `error: `), never a panic, and never a
//! non-finite number printed as certified.

mod common;

use common::{cga, temp_dir};
use proptest::prelude::*;

/// A closed tetrahedron with corners scaled by `s` and moved by `t` (both signs, mixed scales).
fn tetrahedron_off(s: f64, t: [f64; 3]) -> String {
    let corners = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];
    let mut text = String::from("OFF\n4 4 0\n");
    for c in corners {
        text += &format!(
            "{:e} {:e} {:e}\n",
            c[0] * s + t[0],
            c[1] * s + t[1],
            c[2] * s + t[2]
        );
    }
    text + "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"
}

/// A scale `m · 10^e`, finite, from subnormal to near the top of `f64`.
fn scale() -> impl Strategy<Value = f64> {
    (1.0f64..9.99, -320i32..=307).prop_map(|(m, e)| {
        let s = m * 10f64.powi(e);
        if s.is_finite() && s > 0.0 {
            s
        } else {
            f64::MIN_POSITIVE
        }
    })
}

fn offset() -> impl Strategy<Value = [f64; 3]> {
    prop_oneof![
        Just([0.0; 3]),
        prop::array::uniform3((-1.0f64..1.0, -320i32..=307).prop_map(|(m, e)| m * 10f64.powi(e))),
    ]
}

/// Runs `cga args`: success, or a one-line error with exit code 1; never a panic or a backtrace.
fn answers_or_errors(args: &[&str], dir: &std::path::Path) -> Option<serde_json::Value> {
    let out = cga(args, dir);
    let stderr = String::from_utf8_lossy(&out.stderr);
    assert!(!stderr.contains("panicked"), "{args:?}: {stderr}");
    assert!(!stderr.contains("internal error"), "{args:?}: {stderr}");
    if out.status.success() {
        serde_json::from_slice(&out.stdout).ok()
    } else {
        assert_eq!(out.status.code(), Some(1), "{args:?}: {stderr}");
        assert!(stderr.starts_with("error: "), "{args:?}: {stderr}");
        None
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(12))]

    #[test]
    fn every_mesh_subcommand_answers_or_says_why(
        sa in scale(), ta in offset(), sb in scale(), tb in offset(),
    ) {
        let dir = temp_dir("robustness");
        std::fs::write(dir.join("a.off"), tetrahedron_off(sa, ta)).unwrap();
        std::fs::write(dir.join("b.off"), tetrahedron_off(sb, tb)).unwrap();
        for unit in [&[][..], &["--unit"][..]] {
            let run = |args: &[&str]| {
                let args: Vec<&str> = args.iter().chain(unit).copied().collect();
                answers_or_errors(&args, &dir)
            };
            run(&["collide", "a.off", "b.off", "--json", "--repeat", "1"]);
            run(&["collide", "a.off", "b.off", "--json", "--clearance", "0.5", "--repeat", "1"]);
            run(&["query", "a.off", "--json", "--segment", "0,0,-1,0,0,1"]);
            run(&["query", "a.off", "--json", "--ball", "0,0,0,1e-300"]);
            if let Some(v) = run(&["distance", "a.off", "b.off", "--json", "--rotate", "0,0,30"]) {
                for key in ["distance", "error_bound"] {
                    let x = v[key].as_f64();
                    prop_assert!(x.is_some_and(f64::is_finite), "{key} not a finite number: {v}");
                }
                for key in ["witness_a", "witness_b"] {
                    for c in v[key].as_array().expect("a point") {
                        prop_assert!(c.as_f64().is_some_and(f64::is_finite), "{key}: {v}");
                    }
                }
            }
        }
        answers_or_errors(&["self-intersect", "a.off", "--json"], &dir);
        let _ = std::fs::remove_dir_all(&dir);
    }
}
