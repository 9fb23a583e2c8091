//! Checks whole simulation steps of the scalable CCD dataset (Belgrod et al. 2023) against the
//! dataset's exact (symbolic) truth: every vertex–face and edge–edge pair that touches during
//! the step, as `motion::step_self_contacts` finds it, must be exactly the pairs the truth marks
//! as touching. The dataset ships truth only for the candidates Tight Inclusion (a conservative
//! method) flags, so a pair we find outside them is an error too.
//!
//! The scenes are 2–7 MB each and not in the repository (cloth-funnel is, as the fixture of
//! `tests/ccd_step.rs`). With a copy of the dataset, each scene a folder holding `frames/` (the
//! two PLY frames), `boxes/` (`<step>{vf,ee}.json`) and `mma_bool/`
//! (`<step>{vf,ee}_mma_bool.json`):
//!
//! ```sh
//! cargo run --release -p cga-collide --example ccd_step_truth -- \
//!     DATA/cloth-funnel DATA/rod-twist DATA/armadillo-rollers DATA/cloth-ball DATA/n-body-simulation
//! ```
//!
//! Prints one line a scene and exits with status 1 if any scene differs from its truth.

use std::collections::BTreeSet;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use cga_collide::motion::{mesh_edges, step_self_contacts};
use cga_collide::TriMesh;

type Failure = Box<dyn std::error::Error>;

/// The one file in `dir` whose name ends with `suffix`.
fn find(dir: &Path, suffix: &str) -> Result<PathBuf, Failure> {
    let mut hits: Vec<PathBuf> = std::fs::read_dir(dir)
        .map_err(|e| format!("{}: {e}", dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.to_string_lossy().ends_with(suffix))
        .collect();
    hits.sort();
    match hits.as_slice() {
        [one] => Ok(one.clone()),
        _ => Err(format!(
            "{}: expected one file ending in {suffix}, found {}",
            dir.display(),
            hits.len()
        )
        .into()),
    }
}

fn read_json(path: &Path) -> Result<serde_json::Value, Failure> {
    let text = std::fs::read_to_string(path).map_err(|e| format!("{}: {e}", path.display()))?;
    Ok(serde_json::from_str(&text).map_err(|e| format!("{}: {e}", path.display()))?)
}

/// The truth-marked pairs of one kind: element ids (`[vertices | edges | faces]`) and flags.
fn marked(scene: &Path, kind: &str) -> Result<(Vec<Vec<u64>>, Vec<bool>), Failure> {
    let ids = read_json(&find(&scene.join("boxes"), &format!("{kind}.json"))?)?;
    let flags = read_json(&find(
        &scene.join("mma_bool"),
        &format!("{kind}_mma_bool.json"),
    )?)?;
    let bad = || format!("{}: unexpected truth files", scene.display());
    let ids: Vec<Vec<u64>> = ids
        .as_array()
        .ok_or_else(bad)?
        .iter()
        .map(|p| {
            p.as_array()
                .map(|p| p.iter().filter_map(|x| x.as_u64()).collect())
        })
        .collect::<Option<_>>()
        .ok_or_else(bad)?;
    let flags: Vec<bool> = flags
        .as_array()
        .ok_or_else(bad)?
        .iter()
        .map(|t| t.as_bool())
        .collect::<Option<_>>()
        .ok_or_else(bad)?;
    if ids.len() != flags.len() || ids.iter().any(|p| p.len() != 2) {
        return Err(bad().into());
    }
    Ok((ids, flags))
}

/// Checks one scene; `Ok(true)` when our pairs equal the truth.
fn check(scene: &Path) -> Result<bool, Failure> {
    let mut frames: Vec<PathBuf> = std::fs::read_dir(scene.join("frames"))
        .map_err(|e| format!("{}: {e}", scene.join("frames").display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .collect();
    frames.sort();
    let [f0, f1] = frames.as_slice() else {
        return Err(format!("{}: expected two frames", scene.display()).into());
    };
    let (start, end) = (TriMesh::load(f0)?, TriMesh::load(f1)?);
    let edges = mesh_edges(start.triangles());
    let (nv, ne) = (start.vertices().len() as u64, edges.len() as u64);
    let edge = |id: u64| -> Result<[u32; 2], Failure> {
        let k = id
            .checked_sub(nv)
            .filter(|&k| k < ne)
            .ok_or("edge id out of range")?;
        Ok(edges[k as usize])
    };

    let (vf_ids, vf_flags) = marked(scene, "vf")?;
    let (ee_ids, ee_flags) = marked(scene, "ee")?;
    let mut flagged_vf = BTreeSet::new();
    let mut true_vf = BTreeSet::new();
    for (p, &t) in vf_ids.iter().zip(&vf_flags) {
        let face = p[1].checked_sub(nv + ne).ok_or("face id out of range")?;
        let pair = (p[0] as u32, face as u32);
        flagged_vf.insert(pair);
        if t {
            true_vf.insert(pair);
        }
    }
    let mut flagged_ee = BTreeSet::new();
    let mut true_ee = BTreeSet::new();
    for (p, &t) in ee_ids.iter().zip(&ee_flags) {
        let (a, b) = (edge(p[0])?, edge(p[1])?);
        let pair = (a.min(b), a.max(b));
        flagged_ee.insert(pair);
        if t {
            true_ee.insert(pair);
        }
    }

    let contacts = step_self_contacts(&start, end.vertices(), 1e-9)?;
    let ours_vf: BTreeSet<(u32, u32)> = contacts.vertex_face.iter().copied().collect();
    let ours_ee: BTreeSet<([u32; 2], [u32; 2])> = contacts.edge_edge.iter().copied().collect();
    let missing = true_vf.difference(&ours_vf).count() + true_ee.difference(&ours_ee).count();
    let extra = ours_vf.difference(&true_vf).count() + ours_ee.difference(&true_ee).count();
    let outside = ours_vf.difference(&flagged_vf).count() + ours_ee.difference(&flagged_ee).count();
    println!(
        "{}: {} vertex-face and {} edge-edge pairs touch; truth {} and {} (of {} and {} flagged); missing {missing}, extra {extra} ({outside} outside the flagged pairs)",
        scene.display(),
        ours_vf.len(),
        ours_ee.len(),
        true_vf.len(),
        true_ee.len(),
        flagged_vf.len(),
        flagged_ee.len(),
    );
    Ok(missing == 0 && extra == 0)
}

fn main() -> ExitCode {
    let scenes: Vec<PathBuf> = std::env::args_os().skip(1).map(PathBuf::from).collect();
    if scenes.is_empty() {
        eprintln!("usage: ccd_step_truth SCENE_DIR... (folders of the scalable CCD dataset)");
        return ExitCode::from(2);
    }
    let mut all_equal = true;
    for scene in &scenes {
        match check(scene) {
            Ok(equal) => all_equal &= equal,
            Err(e) => {
                eprintln!("{}: {e}", scene.display());
                all_equal = false;
            }
        }
    }
    if all_equal {
        ExitCode::SUCCESS
    } else {
        ExitCode::FAILURE
    }
}
