//! How large a sphere tree of a given depth will be, estimated before it is built: each level
//! has about four times the spheres of the one above (the surface's cells), so a depth the
//! builder accepts (up to 16) can need terabytes; such a build is refused with the estimate
//! instead of ending in an allocation failure.
//!
//! The estimate extrapolates a build to [`PROBE_DEPTH`], level by level: the cells the surface
//! crosses grow by the ratio of the probe's last two levels, and the cells inside the solid
//! follow from them (each crossed cell has about as many inside children as it had in the
//! probe; with `--subdivide-full` each inside cell also has eight inside children).

use std::time::Duration;

use cga_collide::hierarchy::sphere_tree::format;
use cga_collide::hierarchy::sphere_tree::octree::BuildReport;
use cga_collide::hierarchy::sphere_tree::{SphereTree, SphereTreeNode};

/// The depth of the probe build: deep enough for the growth per level to settle, cheap (well
/// under a second for the built-in meshes).
pub const PROBE_DEPTH: u32 = 6;

/// Build scratch per sphere of the deepest level, in bytes: the builder's lists of the cells
/// of a level and of each cell's children.
const SCRATCH_PER_SPHERE: f64 = 96.0;

/// What a build to some depth will take.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// Spheres in the tree.
    pub spheres: f64,
    /// Peak memory of the build and of writing it, in bytes.
    pub memory: f64,
    /// Size of the tree in the output file, in bytes.
    pub file: f64,
    /// Time to build it, in seconds.
    pub seconds: f64,
}

/// A probe build, to extrapolate from.
pub struct Probe<'a> {
    /// The probe's tree.
    pub tree: &'a SphereTree,
    /// Its per-level counts.
    pub report: &'a BuildReport,
    /// How long it took.
    pub took: Duration,
    /// Whether full cells are split too (`--subdivide-full`).
    pub subdivide_full: bool,
}

impl Probe<'_> {
    /// The estimate for a build of the same mesh to `depth` (at least the probe's depth).
    pub fn at(&self, depth: u32) -> Estimate {
        let levels = &self.report.levels;
        let last = levels.len() - 1;
        let (mut partial, mut full) = (levels[last].partial as f64, levels[last].full as f64);
        let before = &levels[last.saturating_sub(1)];
        let (partial_before, full_before) = (before.partial as f64, before.full as f64);
        let split_full = if self.subdivide_full { 8.0 } else { 0.0 };
        let (growth, inside_per_crossed) = if last > 0 && partial_before > 0.0 {
            (
                (partial / partial_before).clamp(1.0, 8.0),
                ((full - split_full * full_before) / partial_before).clamp(0.0, 8.0),
            )
        } else {
            (8.0, 8.0)
        };
        let probe_spheres = self.tree.len() as f64;
        let mut spheres = probe_spheres;
        let mut deepest = partial + full;
        for _ in (last as u32)..depth {
            full = split_full * full + inside_per_crossed * partial;
            partial *= growth;
            deepest = partial + full;
            spheres += deepest;
        }
        let probe_file = format::write(std::slice::from_ref(self.tree)).len() as f64;
        let file = spheres * probe_file / probe_spheres;
        let node = std::mem::size_of::<SphereTreeNode>() as f64;
        Estimate {
            spheres,
            // The tree, the file's text (written from memory), the build's scratch.
            memory: spheres * node + file + deepest * SCRATCH_PER_SPHERE,
            file,
            seconds: self.took.as_secs_f64() * spheres / probe_spheres,
        }
    }

    /// The deepest depth from the probe's up to `depth` whose build fits in `budget` bytes.
    pub fn deepest_within(&self, depth: u32, budget: f64) -> Option<u32> {
        let probe = (self.report.levels.len() - 1) as u32;
        (probe..=depth)
            .take_while(|&d| self.at(d).memory <= budget)
            .last()
    }
}

/// The memory this machine can give a new allocation now (Linux: `MemAvailable` of
/// `/proc/meminfo`), or `None` where that cannot be read.
pub fn available_memory() -> Option<f64> {
    let info = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = info.lines().find(|l| l.starts_with("MemAvailable:"))?;
    let kib: f64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024.0)
}

/// Bytes in words: `3.1 TB`, `850 MB` (decimal units).
pub fn bytes(x: f64) -> String {
    let units = ["bytes", "kB", "MB", "GB", "TB", "PB", "EB"];
    let mut value = x;
    let mut unit = 0;
    while value >= 1000.0 && unit + 1 < units.len() {
        value /= 1000.0;
        unit += 1;
    }
    if unit == 0 || value >= 100.0 {
        format!("{value:.0} {}", units[unit])
    } else {
        format!("{value:.1} {}", units[unit])
    }
}

/// A duration in words: `40 s`, `12 minutes`, `3.5 hours`, `2.0e4 years`.
pub fn duration(seconds: f64) -> String {
    const HOUR: f64 = 3600.0;
    const YEAR: f64 = 365.25 * 24.0 * HOUR;
    match seconds {
        s if s < 120.0 => format!("{s:.0} s"),
        s if s < 2.0 * HOUR => format!("{:.0} minutes", s / 60.0),
        s if s < 2.0 * 24.0 * HOUR => format!("{:.1} hours", s / HOUR),
        s if s < YEAR => format!("{:.0} days", s / (24.0 * HOUR)),
        s => format!("{:.1e} years", s / YEAR),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use cga_collide::collider::Collider;
    use cga_collide::hierarchy::sphere_tree::octree::{build, BuildOptions};
    use cga_collide::shape::mesh::TriMesh;

    #[test]
    fn the_probe_extrapolates_the_build_it_stands_for() {
        let bunny = Collider::new(TriMesh::bunny().unit());
        let (tree, report) = build(&bunny, &BuildOptions::depth(4)).unwrap();
        let probe = Probe {
            tree: &tree,
            report: &report,
            took: Duration::from_millis(10),
            subdivide_full: false,
        };
        let (actual, _) = build(&bunny, &BuildOptions::depth(6)).unwrap();
        let estimated = probe.at(6).spheres;
        let ratio = estimated / actual.len() as f64;
        assert!(
            (0.7..1.4).contains(&ratio),
            "{estimated} for {}",
            actual.len()
        );
        assert_eq!(probe.at(4).spheres, tree.len() as f64);
        // Depth 16: far beyond a terabyte; the deepest depth within 1 GB is well below it.
        assert!(probe.at(16).memory > 1e12, "{:?}", probe.at(16));
        let fits = probe.deepest_within(16, 1e9).unwrap();
        assert!((6..14).contains(&fits), "{fits}");
        assert!(probe.at(fits).memory <= 1e9 && probe.at(fits + 1).memory > 1e9);
    }

    #[test]
    fn sizes_and_times_in_words() {
        assert_eq!(bytes(512.0), "512 bytes");
        assert_eq!(bytes(3.14e12), "3.1 TB");
        assert_eq!(bytes(850e6), "850 MB");
        assert_eq!(duration(40.0), "40 s");
        assert_eq!(duration(720.0), "12 minutes");
        assert_eq!(duration(3.0 * 365.25 * 86400.0 * 1e4), "3.0e4 years");
    }
}
