//! Reading a sphere-tree file that must hold a pair of trees, and the JSON of a tree collision:
//! shared by `cga spheretree collide` and the experiments' `spheretree-collide` (which includes
//! this file by path, so it names nothing of the `cga` crate).

use std::fs;
use std::path::Path;

use anyhow::{bail, Context, Result};
use cga_collide::hierarchy::sphere_tree::{format, CollisionResult, SphereTree};
use serde_json::json;

/// The trees of `file`, at least two. `lenient` takes the complete trees of a file that ends
/// early (with a warning on standard error); `purpose` names the caller in the error when the
/// file holds fewer than two trees.
pub fn read_tree_pair(file: &Path, lenient: bool, purpose: &str) -> Result<Vec<SphereTree>> {
    let text =
        fs::read_to_string(file).with_context(|| format!("cannot read `{}`", file.display()))?;
    let name = file.display().to_string();
    let trees: Vec<SphereTree> = if lenient {
        let r = format::read_lenient(&text).with_context(|| format!("in `{name}`"))?;
        if !r.is_complete() {
            eprintln!(
                "warning: `{name}` is incomplete: {} trees declared, {} complete",
                r.declared_trees, r.complete_trees
            );
            for g in &r.gaps {
                eprintln!("warning: {g}");
            }
        }
        r.trees
    } else {
        format::read(&text).map_err(|e| {
            let hint = match e {
                cga_collide::Error::SphereTreeUnexpectedEnd { .. } => {
                    " (the file ends early: --lenient uses the trees that are complete)"
                }
                _ => "",
            };
            anyhow::Error::new(e).context(format!("in `{name}`{hint}"))
        })?
    };
    if trees.len() < 2 {
        bail!(
            "`{name}` holds {} tree(s); {purpose} needs two: write a pair with `cga spheretree build A B -o FILE`",
            trees.len()
        );
    }
    Ok(trees)
}

/// The JSON fields every tree-collision answer prints.
pub fn result_json(r: &CollisionResult) -> serde_json::Value {
    json!({
        "collides": r.collides,
        "sphere_tests": r.sphere_tests,
        "witness": r.witness.map(|(i, j)| [i, j]),
        "listed_leaves": r.listed_leaves,
    })
}
