//! `cga collide A B --poses FILE`: one answer per pose, equal to placing B with `--rotate` and
//! `--translate`; typed errors for bad files.

mod common;

use common::{cga, json, temp_dir};

const POSES: [([&str; 3], [&str; 3]); 3] = [
    (["0", "40", "10"], ["0.2", "0.05", "-0.1"]),
    (["0", "0", "0"], ["3", "0", "0"]),
    (["-20", "5", "90"], ["0.4", "0", "0.1"]),
];

#[test]
fn poses_match_single_placements() {
    let dir = temp_dir("poses");
    let text: String = POSES
        .iter()
        .map(|(r, t)| format!("{} {} {} {} {} {}\n", r[0], r[1], r[2], t[0], t[1], t[2]))
        .collect();
    std::fs::write(
        dir.join("poses.txt"),
        format!("# rx ry rz tx ty tz\n{text}"),
    )
    .unwrap();
    let base = [
        "collide",
        "bunny",
        "bunny",
        "--unit",
        "--poses",
        "poses.txt",
        "--json",
    ];
    let mut with_pairs = base.to_vec();
    with_pairs.extend(["--all-pairs", "--threads", "2"]);
    let all = json(&cga(&with_pairs, &dir));
    let first = json(&cga(&base, &dir));
    assert_eq!(all["threads"], 2);
    assert!(all["micros_per_pose"].as_f64().unwrap() >= 0.0);
    assert_eq!(first["collides"], all["collides"]);
    assert!(first.get("pairs").is_none());
    for (k, (r, t)) in POSES.iter().enumerate() {
        let rotate = r.join(",");
        let translate = t.join(",");
        let one = json(&cga(
            &[
                "collide",
                "bunny",
                "bunny",
                "--unit",
                "--rotate",
                &rotate,
                "--translate",
                &translate,
                "--json",
                "--repeat",
                "1",
            ],
            &dir,
        ));
        assert_eq!(all["collides"][k], one["collides"], "pose {k}");
        assert_eq!(all["pairs"][k], one["pairs"], "pose {k}");
    }
    assert_eq!(all["collides"][1], false);
    assert_eq!(all["collides"][0], true);
}

#[test]
fn bad_poses_files_are_errors() {
    let dir = temp_dir("poses-bad");
    std::fs::write(dir.join("short.txt"), "0 0 0 1 2\n").unwrap();
    let out = cga(&["collide", "bunny", "bunny", "--poses", "short.txt"], &dir);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("short.txt:1") && err.contains("6 numbers"),
        "{err}"
    );
    let out = cga(
        &["collide", "bunny", "bunny", "--poses", "missing.txt"],
        &dir,
    );
    assert!(!out.status.success());
    let out = cga(
        &[
            "collide",
            "bunny",
            "bunny",
            "--poses",
            "short.txt",
            "--rotate",
            "1,2,3",
        ],
        &dir,
    );
    assert!(!out.status.success(), "--poses and --rotate conflict");
}
