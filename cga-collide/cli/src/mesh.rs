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

/// [`load_mesh`], then, with `unit`, [`unit_mesh`].
pub fn load_unit(spec: &str, role: &str, unit: bool) -> Result<TriMesh> {
    let mesh = load_mesh(spec, role)?;
    if unit {
        let what = if role.is_empty() {
            format!("mesh `{spec}`")
        } else {
            format!("mesh {role} (`{spec}`)")
        };
        unit_mesh(&mesh, &what)
    } else {
        Ok(mesh)
    }
}

/// `--unit`: the mesh scaled into the unit box centred at the origin, or an error naming the
/// mesh (`what`) when its size cannot be scaled to 1 in floating point (a mesh so small that
/// 1 / size overflows, or so large that its size or centre overflows).
pub fn unit_mesh(mesh: &TriMesh, what: &str) -> Result<TriMesh> {
    let (lo, hi) = mesh.bounds();
    let side = (hi - lo).max();
    let scaled = mesh.unit();
    let (slo, shi) = scaled.bounds();
    let new_side = (shi - slo).max();
    let finite = scaled
        .vertices()
        .iter()
        .all(|v| v.coords.iter().all(|c| c.is_finite()));
    // A mesh whose vertices all coincide is only translated (side 0 stays 0).
    let scaled_ok = if side > 0.0 {
        (0.5..=2.0).contains(&new_side)
    } else {
        true
    };
    if !(finite && scaled_ok && side.is_finite()) {
        bail!(
            "--unit: cannot scale {what} into the unit box: its bounding box's largest side is \
             {side:e}, which floating point cannot rescale to 1 (the mesh is too small or too \
             large); leave out --unit, or rescale the mesh's coordinates"
        );
    }
    Ok(scaled)
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
    fn unit_scales_or_names_the_mesh_it_cannot_scale() {
        let m = unit_mesh(&triangle(1e-3), "mesh A (`t`)").unwrap();
        let (lo, hi) = m.bounds();
        assert_eq!((hi - lo).max(), 1.0);
        for s in [1e-320, 1e308] {
            let e = unit_mesh(&triangle(s), "mesh A (`t`)").unwrap_err();
            let e = format!("{e:#}");
            assert!(e.contains("--unit") && e.contains("mesh A (`t`)"), "{e}");
        }
    }
}
