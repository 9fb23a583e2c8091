//! `--device gpu` of `cga collide` and `cga query`: the same JSON as `--device cpu` apart from
//! the device, its counts and the timings; clear errors for what the GPU path does not do.
//!
//! The runs need a GPU adapter: on a machine without a GPU, Mesa's software Vulkan driver
//! (lavapipe, package `mesa-vulkan-drivers`) is one. When no adapter is found they fail if the
//! `CI` environment variable is set, and are skipped with a message otherwise (as
//! cga-collide's `tests/gpu.rs`).
#![cfg(feature = "gpu")]

mod common;

use common::{cga, cube_off, error, json, temp_dir};
use serde_json::Value;

/// The JSON of `cga args... --device gpu`, or `None` (skip) when there is no adapter outside CI.
fn on_gpu(args: &[&str], dir: &std::path::Path) -> Option<Value> {
    let mut args = args.to_vec();
    args.extend(["--device", "gpu"]);
    let out = cga(&args, dir);
    let err = String::from_utf8_lossy(&out.stderr);
    if !out.status.success() && err.contains("no GPU adapter") {
        if std::env::var_os("CI").is_some() {
            panic!("CI needs a GPU adapter (lavapipe offers one): {err}");
        }
        eprintln!("skipped: {err}");
        return None;
    }
    Some(json(&out))
}

/// The answer without what depends on where and how fast it ran.
fn answer(mut v: Value) -> Value {
    let map = v.as_object_mut().expect("a JSON object");
    for key in [
        "device",
        "tested",
        "flagged",
        "millis",
        "build_millis",
        "first_hit_millis",
    ] {
        map.remove(key);
    }
    v
}

/// Checks the GPU fields of a GPU run and returns its answer.
fn gpu_answer(v: Value) -> Value {
    let device = v["device"].as_str().expect("the device's name");
    assert!(!device.is_empty() && device != "cpu", "{device}");
    let tested = v["tested"].as_u64().expect("pairs tested");
    let flagged = v["flagged"].as_u64().expect("pairs flagged");
    assert!(flagged <= tested, "{flagged} of {tested}");
    answer(v)
}

#[test]
fn collide_on_the_gpu_gives_the_cpus_answer() {
    let dir = temp_dir("gpu-collide");
    // Two bunnies crossing, over the candidate pairs of the trees (the default mode).
    let bunnies = [
        "collide",
        "bunny",
        "bunny",
        "--unit",
        "--rotate",
        "0,40,10",
        "--translate",
        "0.2,0.05,-0.1",
        "--json",
        "--repeat",
        "1",
        "--pairs",
    ];
    let mut cpu_args = bunnies.to_vec();
    cpu_args.push("cpu.txt");
    let cpu = json(&cga(&cpu_args, &dir));
    assert_eq!(cpu["device"], "cpu");
    assert_eq!(cpu["flagged"], Value::Null);
    let mut gpu_args = bunnies.to_vec();
    gpu_args.push("gpu.txt");
    let Some(gpu) = on_gpu(&gpu_args, &dir) else {
        return;
    };
    assert!(gpu["pairs"].as_u64().unwrap() > 0);
    assert_eq!(gpu_answer(gpu), answer(cpu));
    let listed = |f: &str| std::fs::read_to_string(dir.join(f)).unwrap();
    assert_eq!(listed("gpu.txt"), listed("cpu.txt"));

    // Two cubes sharing a face, every pair on the GPU: all the hits are touchings, which the
    // device cannot certify, so they are flagged and decided exactly on the CPU.
    std::fs::write(dir.join("a.off"), cube_off(0.0, 1.0)).unwrap();
    std::fs::write(dir.join("b.off"), cube_off(1.0, 2.0)).unwrap();
    let cubes = ["collide", "a.off", "b.off", "--mode", "brute", "--json"];
    let cpu = json(&cga(&cubes, &dir));
    let gpu = on_gpu(&cubes, &dir).expect("an adapter was found above");
    assert_eq!(gpu["tested"], 144);
    assert!(gpu["flagged"].as_u64().unwrap() > 0, "{gpu}");
    assert_eq!(cpu["collides"], true);
    assert_eq!(gpu_answer(gpu), answer(cpu));
}

#[test]
fn query_on_the_gpu_gives_the_cpus_triangles() {
    let dir = temp_dir("gpu-query");
    for shape in [
        ["--segment", "0,0,-2,0,0,2"],
        ["--triangle", "-1,0,0,1,0.1,0,0,0.05,1"],
        ["--sphere", "0.05,0,0,0.2"],
        ["--ball", "0.05,0,0,0.2"],
    ] {
        let args = ["query", "bunny", "--unit", shape[0], shape[1], "--json"];
        let mut brute = args.to_vec();
        brute.extend(["--mode", "brute"]);
        let cpu = json(&cga(&brute, &dir));
        let Some(gpu) = on_gpu(&args, &dir) else {
            return;
        };
        assert_eq!(gpu["mode"], "brute");
        assert_eq!(gpu["tested"], 3674);
        assert!(gpu["hits"].as_u64().unwrap() > 0, "{shape:?}: {gpu}");
        assert_eq!(gpu_answer(gpu), answer(cpu), "{shape:?}");
    }
}

#[test]
fn options_the_gpu_does_not_do_are_refused_by_name() {
    let dir = temp_dir("gpu-unsupported");
    std::fs::write(dir.join("poses.txt"), "0 0 0 0 0 0\n").unwrap();
    for (extra, named) in [
        (&["--clearance", "0.1"][..], "--clearance"),
        (&["--contacts", "c.txt"][..], "--contacts"),
        (&["--poses", "poses.txt"][..], "--poses"),
    ] {
        let mut args = vec!["collide", "bunny", "bunny", "--device", "gpu"];
        args.extend(extra);
        let err = error(&cga(&args, &dir));
        assert!(err.contains(named), "{err}");
        assert!(err.contains("--device cpu"), "{err}");
    }
    let err = error(&cga(
        &[
            "query",
            "bunny",
            "--segment",
            "0,0,0,1,1,1",
            "--mode",
            "bvh",
            "--device",
            "gpu",
        ],
        &dir,
    ));
    assert!(
        err.contains("--mode bvh") && err.contains("--device cpu"),
        "{err}"
    );
}

#[test]
fn no_adapter_says_what_to_install() {
    let dir = temp_dir("gpu-none");
    // No Metal adapter exists on Linux or Windows, so wgpu finds none.
    if cfg!(target_os = "macos") {
        return;
    }
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_cga"))
        .args([
            "query",
            "bunny",
            "--segment",
            "0,0,0,1,1,1",
            "--device",
            "gpu",
        ])
        .env("WGPU_BACKEND", "metal")
        .current_dir(&dir)
        .output()
        .expect("the cga binary runs");
    let err = error(&out);
    for needed in [
        "no GPU adapter",
        "mesa-vulkan-drivers",
        "WGPU_BACKEND",
        "`metal`",
        "--device cpu",
    ] {
        assert!(err.contains(needed), "missing {needed:?}: {err}");
    }
}
