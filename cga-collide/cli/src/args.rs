//! Arguments shared by several subcommands: number lists, `--mode`, and the two meshes of
//! `cga collide` and `cga distance` (mesh A, mesh B, `--unit`).

use anyhow::{bail, Result};
use cga_collide::collider::Mode;
use cga_collide::shape::mesh::TriMesh;
use clap::{Args, ValueEnum};

use crate::mesh::load_unit;

/// `N` comma-separated finite numbers (`--segment 0,0,-2,0,0,2`).
pub fn parse_numbers<const N: usize>(s: &str) -> Result<[f64; N], String> {
    let parts: Vec<&str> = s.split(',').map(str::trim).collect();
    if parts.len() != N {
        return Err(format!(
            "expected {N} comma-separated numbers, got {}",
            parts.len()
        ));
    }
    let mut out = [0.0; N];
    for (o, p) in out.iter_mut().zip(&parts) {
        let v: f64 = p.parse().map_err(|_| format!("`{p}` is not a number"))?;
        if !v.is_finite() {
            return Err(format!("`{p}` is not finite"));
        }
        *o = v;
    }
    Ok(out)
}

/// Three comma-separated finite numbers (`--translate 0.3,0.05,0`).
pub fn parse_triple(s: &str) -> Result<[f64; 3], String> {
    parse_numbers::<3>(s)
}

/// `--mode`: how pairs (or triangles) are found.
#[derive(Copy, Clone, Debug, ValueEnum, PartialEq, Eq)]
pub enum ModeArg {
    /// Test every pair (in parallel): the thesis's worst case.
    Brute,
    /// Bounding-volume hierarchy, then the same exact tests.
    Bvh,
}

impl ModeArg {
    /// The name in the output (`"brute"`, `"bvh"`).
    pub fn name(self) -> &'static str {
        match self {
            ModeArg::Brute => "brute",
            ModeArg::Bvh => "bvh",
        }
    }
}

impl From<ModeArg> for Mode {
    fn from(m: ModeArg) -> Mode {
        match m {
            ModeArg::Brute => Mode::Brute,
            ModeArg::Bvh => Mode::Bvh,
        }
    }
}

/// Mesh A, mesh B and `--unit`, flattened into `cga collide` and `cga distance`.
///
/// The meshes are optional here so that `cga collide` without them can run the built-in demo;
/// a subcommand that always needs both makes them required with
/// `#[command(mut_arg("a", |a| a.required(true)), mut_arg("b", |b| b.required(true)))]`.
#[derive(Args, Debug, Clone, Default)]
pub struct TwoMeshes {
    /// Mesh A: a file (.obj, .off, .ply, .stl) or a built-in name (bunny, bunny00, armadillo).
    pub a: Option<String>,
    /// Mesh B (moved by --rotate and --translate).
    pub b: Option<String>,
    /// Scale each mesh uniformly into the unit box centred at the origin (largest side 1)
    /// before anything else.
    #[arg(long)]
    pub unit: bool,
}

impl TwoMeshes {
    /// Both names, `None` when neither was given, an error when only one was.
    pub fn names(&self) -> Result<Option<(&str, &str)>> {
        match (self.a.as_deref(), self.b.as_deref()) {
            (Some(a), Some(b)) => Ok(Some((a, b))),
            (None, None) => Ok(None),
            (Some(one), None) | (None, Some(one)) => bail!(
                "only one mesh given (`{one}`): give two meshes A and B, or none for the \
                 built-in demo"
            ),
        }
    }

    /// Both names; an error naming what is missing when they were not both given.
    pub fn both(&self) -> Result<(&str, &str)> {
        match self.names()? {
            Some(names) => Ok(names),
            None => bail!("no meshes given: give two meshes A and B"),
        }
    }

    /// Loads both meshes (each scaled into the unit box with `--unit`), A in its own frame and
    /// B not yet moved.
    pub fn load(&self) -> Result<(TriMesh, TriMesh)> {
        let (a, b) = self.both()?;
        Ok((load_unit(a, "A", self.unit)?, load_unit(b, "B", self.unit)?))
    }
}
