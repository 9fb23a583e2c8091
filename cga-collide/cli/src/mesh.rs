//! Loading the meshes named on the command line, and `--unit`.

use std::path::Path;

use anyhow::{bail, Context, Result};
use cga_collide::shape::mesh::TriMesh;
use cga_collide::Error;

/// The built-in meshes, by the names the command line accepts.
const BUILT_IN: &str = "bunny, bunny00, armadillo";

/// A file path, or a built-in mesh when no such file exists; `role` (`"A"`, `"B"`, or `""` for
/// the only mesh) names the mesh in errors.
pub fn load_mesh(spec: &str, role: &str) -> Result<TriMesh> {
    let which = if role.is_empty() {
        "the mesh".to_owned()
    } else {
        format!("mesh {role}")
    };
    let path = Path::new(spec);
    if !path.exists() {
        match spec {
            "bunny" => return Ok(TriMesh::bunny()),
            "bunny00" => return Ok(TriMesh::bunny00()),
            "armadillo" => return Ok(TriMesh::armadillo()),
            _ => {}
        }
    }
    match TriMesh::load(path) {
        Ok(mesh) => Ok(mesh),
        // No file and no mesh extension: most likely a mistyped built-in name.
        Err(Error::UnknownFormat { .. }) if !path.exists() => bail!(
            "{which}: {spec}: no such file, and not a built-in mesh ({BUILT_IN}); check the \
             name, or the path of a .obj, .off, .ply or .stl file"
        ),
        // The loader's error names the file (and the line, where known).
        Err(e) if path.exists() => Err(e).context(format!("cannot load {which}")),
        Err(e) => Err(e).context(format!(
            "{which}: no such file, and not a built-in mesh ({BUILT_IN})"
        )),
    }
}

/// [`load_mesh`], then, with `unit` (`--unit`), the mesh scaled into the unit box centred at
/// the origin ([`TriMesh::unit`]: exact power-of-two steps where the direct formula would over-
/// or underflow, so every finite mesh scales, from 1e-320 to 1e308 across).
pub fn load_unit(spec: &str, role: &str, unit: bool) -> Result<TriMesh> {
    let mesh = load_mesh(spec, role)?;
    Ok(if unit { mesh.unit() } else { mesh })
}

#[cfg(test)]
mod tests {
    use super::*;
    use cga_collide::nalgebra::Point3;

    fn triangle(s: f64) -> TriMesh {
        // Corners at ±s: with s = 1e308 the side (2e308) overflows.
        let p = |x: f64, y: f64| Point3::new((2.0 * x - 1.0) * s, (2.0 * y - 1.0) * s, 0.0);
        TriMesh::new(vec![p(0.0, 0.0), p(1.0, 0.0), p(0.0, 1.0)], vec![[0, 1, 2]]).unwrap()
    }

    #[test]
    fn unit_scales_every_finite_mesh_to_side_one() {
        for s in [1e-320, 1e-3, 1e308] {
            let (lo, hi) = triangle(s).unit().bounds();
            let side = (hi - lo).max();
            assert!((side - 1.0).abs() <= 1e-15, "{s}: side {side}");
        }
    }
}
