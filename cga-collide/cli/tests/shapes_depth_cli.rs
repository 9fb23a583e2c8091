//! `cga shapes FILE.jsonl --depth --json`: the signed distance and its bound of every pair
//! (negative when overlapping: minus the penetration depth; `null` for a pair not computed),
//! and malformed lines still named by file and line.

mod common;

use common::{cga, error, temp_dir};
use serde_json::json;

const PAIRS: &str = r#"{"a": {"cuboid": {"center": [0, 0, 0], "half_axes": [[0.5, 0, 0], [0, 0.5, 0], [0, 0, 0.5]]}}, "b": {"cuboid": {"center": [1, 0, 0], "half_axes": [[0.5, 0, 0], [0, 0.5, 0], [0, 0, 0.5]]}}}
{"a": {"cuboid": {"center": [0, 0, 0], "half_axes": [[0.5, 0, 0], [0, 0.5, 0], [0, 0, 0.5]]}}, "b": {"ball": {"center": [0, 0, 1], "radius": 0.75}}}
{"a": {"ball": {"center": [0, 0, 0], "radius": 1}}, "b": {"ball": {"center": [3, 0, 0], "radius": 1}}}
{"a": {"cylinder": {"a": [0, 0, 0], "b": [0, 0, 1], "radius": 0.5}}, "b": {"ball": {"center": [0, 0, 0], "radius": 0.5}}}
"#;

#[test]
fn depth_adds_signed_distances_and_bounds_one_a_pair() {
    let dir = temp_dir("shapes-depth");
    std::fs::write(dir.join("pairs.jsonl"), PAIRS).unwrap();
    let out = cga(&["shapes", "pairs.jsonl", "--depth", "--json"], &dir);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value =
        serde_json::from_str(String::from_utf8(out.stdout).unwrap().trim()).unwrap();
    assert_eq!(v["answers"], json!([true, true, false, true]));
    let sd = v["signed_distance"].as_array().unwrap();
    let eb = v["error_bound"].as_array().unwrap();
    assert_eq!((sd.len(), eb.len()), (4, 4));
    // Flush faces: exactly 0; a ball sunk 0.25: -0.25; balls 1 apart; a ball centred on a
    // cylinder's cap: -0.5 (moved out through the cap).
    assert_eq!((sd[0].as_f64(), eb[0].as_f64()), (Some(0.0), Some(0.0)));
    let within = |k: usize, x: f64| {
        let (s, e) = (sd[k].as_f64().unwrap(), eb[k].as_f64().unwrap());
        (s - x).abs() <= e && e < 1e-12
    };
    assert!(within(1, -0.25), "{v}");
    assert!(within(2, 1.0), "{v}");
    assert!(within(3, -0.5), "{v}");
    assert!(v["depth_micros_mean"].as_f64().unwrap() >= 0.0);
    // Without --depth the arrays are absent.
    let out = cga(&["shapes", "pairs.jsonl", "--json"], &dir);
    let v: serde_json::Value =
        serde_json::from_str(String::from_utf8(out.stdout).unwrap().trim()).unwrap();
    assert!(v.get("signed_distance").is_none());
}

#[test]
fn depth_still_names_a_malformed_line() {
    let dir = temp_dir("shapes-depth-bad");
    let text = format!("{}{{\"a\": 1}}\n", PAIRS);
    std::fs::write(dir.join("bad.jsonl"), text).unwrap();
    let message = error(&cga(&["shapes", "bad.jsonl", "--depth", "--json"], &dir));
    assert!(message.contains("bad.jsonl:5"), "{message}");
}
