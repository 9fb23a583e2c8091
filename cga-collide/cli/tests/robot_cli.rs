//! `cga robot`: the fixture arm (`data/robot/toy_arm`: primitives of every kind, a fixed joint,
//! a scaled OBJ through `package://`, an SRDF), a configurations file naming some joints, an
//! environment scene, the exact JSON layout, and errors that name the file and element.

mod common;

use std::path::{Path, PathBuf};

use common::{cga, error, json, temp_dir};
use serde_json::json;

fn data() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/data/robot")
}

fn robot_args(extra: &[&str]) -> Vec<String> {
    let d = data();
    let mut args: Vec<String> = vec![
        "robot".into(),
        d.join("toy_arm/arm.urdf").display().to_string(),
        "--package-dir".into(),
        d.display().to_string(),
        "--srdf".into(),
        d.join("toy_arm/arm.srdf").display().to_string(),
        "--configs".into(),
        d.join("configs.json").display().to_string(),
        "--json".into(),
    ];
    args.extend(extra.iter().map(|s| s.to_string()));
    args
}

fn run(args: &[String]) -> std::process::Output {
    let refs: Vec<&str> = args.iter().map(String::as_str).collect();
    cga(&refs, &data())
}

#[test]
fn colliding_pairs_per_configuration_in_the_issue_layout() {
    let v = json(&run(&robot_args(&[])));
    let keys: Vec<&str> = v.as_object().unwrap().keys().map(String::as_str).collect();
    assert_eq!(
        keys,
        [
            "colliding",
            "configs",
            "micros_per_config",
            "micros_per_config_first_hit",
            "pairs_checked"
        ]
    );
    assert_eq!(v["configs"], 3);
    assert_eq!(v["pairs_checked"], 12);
    // Straight up: free. Shoulder lifted past the horizontal: the forearm and the slider at
    // its end go into the base. Elbow bent down by 1.5 rad: the forearm (0.4 long from the
    // elbow at z = 0.9) points along (cos 1.5, 0, −sin 1.5), so its end, the slider's centre,
    // is at (0.028, 0, 0.501): the slider and the tool sphere (0.03 further along the slider's
    // x) lie in the column's top (|x| ≤ 0.05, z ≤ 0.5) and within 0.03–0.05 of the shoulder
    // cylinder's axis (the y axis through z = 0.5, radius 0.08), and the forearm's end face
    // dips below z = 0.5 into the column.
    assert_eq!(
        v["colliding"],
        json!([
            [],
            [["base", "fore"], ["base", "slider"]],
            [
                ["column", "fore"],
                ["column", "slider"],
                ["column", "tool"],
                ["shoulder", "slider"],
                ["shoulder", "tool"]
            ]
        ])
    );
    assert!(v["micros_per_config"].as_f64().unwrap() > 0.0);
    assert!(v["micros_per_config_first_hit"].as_f64().unwrap() > 0.0);
}

#[test]
fn an_environment_scene_adds_its_objects() {
    let env = data().join("env.txt").display().to_string();
    let v = json(&run(&robot_args(&["--env", &env])));
    // 7 links with geometry against 2 objects, beside the 12 self pairs.
    assert_eq!(v["pairs_checked"], 12 + 14);
    assert_eq!(v["colliding"][0], json!([["env:0", "fore"]]));
}

#[test]
fn errors_name_the_file_and_element() {
    let dir = temp_dir("robot-bad");
    std::fs::write(
        dir.join("bad.urdf"),
        "<robot name=\"r\">\n<link name=\"a\"/>\n<joint name=\"j\" type=\"revolute\">\
         <parent link=\"a\"/><child link=\"ghost\"/><limit lower=\"0\" upper=\"1\"/></joint>\n</robot>\n",
    )
    .unwrap();
    std::fs::write(dir.join("q.json"), r#"{"joint_names": [], "q": [[]]}"#).unwrap();
    let out = cga(
        &["robot", "bad.urdf", "--configs", "q.json", "--json"],
        &dir,
    );
    let m = error(&out);
    assert!(
        m.contains("bad.urdf:3: <joint name=\"j\">") && m.contains("ghost"),
        "{m}"
    );
    // An unknown joint name in the configurations file.
    let mut args = robot_args(&[]);
    let q = dir.join("unknown.json");
    std::fs::write(&q, r#"{"joint_names": ["wrist"], "q": [[0]]}"#).unwrap();
    args[7] = q.display().to_string();
    let m = error(&run(&args));
    assert!(m.contains("\"wrist\"") && m.contains("shoulder_pan"), "{m}");
}

#[test]
fn motions_between_consecutive_configurations() {
    let v = json(&run(&robot_args(&["--motions"])));
    let m = v["motions"].as_array().unwrap();
    assert_eq!(m.len(), 2);
    // From straight up to the shoulder lifted past the horizontal: the forearm meets the base
    // on the way, no later than the end, which collides.
    assert_eq!(m[0]["status"], "collides");
    let t = m[0]["time"].as_f64().unwrap();
    assert!(t > 0.0 && t <= 1.0, "time {t}");
    assert!(m[0]["free_until"].as_f64().unwrap() <= t);
    assert!(!m[0]["pairs"].as_array().unwrap().is_empty());
    // The second motion starts in collision: time 0, the first configuration's pairs.
    assert_eq!(m[1]["status"], "collides");
    assert_eq!(m[1]["time"], 0.0);
    assert_eq!(m[1]["pairs"], v["colliding"][1]);
    // Without the flag the layout is the issue's (no "motions").
    assert!(json(&run(&robot_args(&[]))).get("motions").is_none());
}
