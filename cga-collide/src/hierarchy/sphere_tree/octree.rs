//! Building an octree sphere tree from a closed mesh (chapter 2: circumscribe the
//! object with a cube, split it into eight equal cubes, recursively, to the chosen depth; every
//! cell that is not empty becomes a sphere).
//!
//! # The grid
//! The root cell is a **cube** (as in the paper: its examples' roots are cubes of side 10 and 8),
//! centred on the mesh's bounding box, with side a little larger than the box's largest side:
//! the side and the corner are snapped to a dyadic grid (multiples of a power of two `q` about
//! `2^-(depth + 10)` of the side) so that **every cell corner, centre and half side at every
//! level is an exact `f64`**. The cube is at most `2q + 2^(depth+1) q` wider than
//! the box's largest side: under 0.2 %.
//!
//! # Cells, exactly
//! A cell (closed box) is
//! * **partial** when a triangle of the mesh meets it (an exact separating-axis triangle–box
//!   test whose signs are certified `f64` with exact fall-back; candidates from the mesh's [`Bvh`](crate::bounding::Bvh));
//! * otherwise wholly inside or wholly outside the solid (the cell is connected and no surface
//!   crosses it), decided by [`Collider::contains_point`] at its centre (exact): **full** or
//!   **empty**.
//!
//! Partial cells are split down to `depth`; full cells are leaves (as in the paper's examples,
//! where state-0 nodes have no children) unless [`BuildOptions::subdivide_full`] is set; empty
//! cells are dropped. Every cell of the tree keeps its state.
//!
//! # Spheres
//! A cell of half side `h` becomes the ball centred at the cell's centre with radius
//! `r ≥ h√3` (half the diagonal): the root's radius is the smallest `f64` whose square is at
//! least `3h²` (checked in exact rational arithmetic) and each level halves it (exact), so every
//! ball contains its cell and every child ball lies inside its parent ball (`|Δc| + r/2 =
//! (h/2)√3 + r/2 ≤ r`). Hence the union of the leaf balls contains the solid: a tree–tree
//! collision test on two such trees has **no false negatives** against the exact solids.
//!
//! ```
//! use cga_collide::shape::mesh::TriMesh;
//! use cga_collide::collider::Collider;
//! use cga_collide::hierarchy::sphere_tree::octree::{build, BuildOptions};
//! let bunny = Collider::new(TriMesh::bunny().unit());
//! let (tree, report) = build(&bunny, &BuildOptions::depth(3))?;
//! assert_eq!(tree.height(), 3);
//! assert!(tree.nesting_violations().is_empty());
//! assert_eq!(report.levels.len(), 4);
//! # Ok::<(), cga_collide::Error>(())
//! ```

use std::ops::ControlFlow;

use crate::error::Error;
use crate::parallel::*;
use nalgebra::Point3;
use num_traits::Zero;

use super::tribox::triangle_meets_box;
use super::{CellState, SphereTree};
use crate::bounding::Aabb;
use crate::collider::Collider;

/// The largest depth accepted (8^16 cells is far beyond memory anyway).
pub const MAX_DEPTH: u32 = 16;

/// How to build.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct BuildOptions {
    /// The depth of the octree (0: the root cell only).
    pub depth: u32,
    /// Split full cells too (their children are all full), so that every leaf is at `depth`
    /// and the leaf balls hug the solid more tightly. Off by default (the paper's trees).
    pub subdivide_full: bool,
    /// Require a closed mesh (every edge used by an even number of triangles); when off, an
    /// open mesh is classified by the even–odd rule of one ray per cell. On by default.
    pub require_closed: bool,
}

impl BuildOptions {
    /// The default options at a given depth.
    pub fn depth(depth: u32) -> BuildOptions {
        BuildOptions {
            depth,
            subdivide_full: false,
            require_closed: true,
        }
    }
}

/// Cell counts of one level.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct LevelCounts {
    /// Cells crossed by the surface.
    pub partial: usize,
    /// Cells inside the solid.
    pub full: usize,
    /// Cells examined and found empty (dropped).
    pub empty: usize,
}

/// What the build did.
#[derive(Debug, Clone, PartialEq)]
pub struct BuildReport {
    /// The root cube: lower corner.
    pub origin: [f64; 3],
    /// The root cube's side.
    pub side: f64,
    /// Counts per level, root first.
    pub levels: Vec<LevelCounts>,
    /// Exact triangle–box tests made.
    pub triangle_box_tests: usize,
    /// Point-in-solid queries made.
    pub point_queries: usize,
}

/// The exact dyadic grid of the root cube.
#[derive(Debug, Clone, Copy)]
struct Grid {
    origin: [f64; 3],
    /// The quantum (a power of two).
    q: f64,
    /// The root side in quanta (a multiple of `2^(depth+1)`).
    n: u64,
}

impl Grid {
    fn new(lo: &Point3<f64>, hi: &Point3<f64>, depth: u32) -> Result<Grid, Error> {
        let extent = (hi - lo).max();
        let offset = lo.coords.abs().max().max(hi.coords.abs().max());
        let err = Error::OctreePrecision {
            depth,
            extent,
            offset,
        };
        let size = if extent > 0.0 {
            extent
        } else {
            offset.max(1.0)
        };
        // q: a power of two with size / q in [2^(depth+10), 2^(depth+11)).
        let e = size.log2().floor() as i32 - depth as i32 - 10;
        if !(-1000..=1000).contains(&e) {
            return Err(err);
        }
        let q = 2f64.powi(e);
        let block = 1u64 << (depth + 1);
        let mut n = ((size + 2.0 * q) / q).ceil() as u64;
        n = n.div_ceil(block) * block;
        let side = n as f64 * q;
        let mut origin = [0.0; 3];
        for a in 0..3 {
            let mid = lo[a] + (hi[a] - lo[a]) / 2.0;
            let o = ((mid - side / 2.0) / q).floor() * q;
            // Every grid coordinate o + k q (0 <= k <= n) must be exact.
            if !o.is_finite() || (o / q).abs() + n as f64 >= 2f64.powi(52) {
                return Err(err);
            }
            if o > lo[a] || o + side < hi[a] {
                return Err(err);
            }
            origin[a] = o;
        }
        Ok(Grid { origin, q, n })
    }

    /// The closed box of cell `c` at level `l`.
    #[allow(clippy::needless_range_loop)]
    fn cell(&self, l: u32, c: [u64; 3]) -> Aabb {
        let step = self.n >> l;
        let mut b = Aabb {
            min: [0.0; 3],
            max: [0.0; 3],
        };
        for a in 0..3 {
            b.min[a] = self.origin[a] + (step * c[a]) as f64 * self.q;
            b.max[a] = self.origin[a] + (step * (c[a] + 1)) as f64 * self.q;
        }
        b
    }

    fn centre(&self, l: u32, c: [u64; 3]) -> [f64; 3] {
        let half = self.n >> (l + 1);
        core::array::from_fn(|a| self.origin[a] + (half * (2 * c[a] + 1)) as f64 * self.q)
    }

    /// The smallest `f64` `r` with `r² ≥ 3 h²` for the root's half side `h` (exact check).
    fn root_radius(&self) -> f64 {
        let h = (self.n / 2) as f64 * self.q;
        let exact = |x: f64| ga_core::scalar::rational_from_f64(x).unwrap_or_else(Zero::zero);
        let three_h2 = exact(h) * exact(h) * exact(3.0);
        let mut r = h * 3f64.sqrt();
        // Step down while still enough, then up until enough.
        while r > 0.0 {
            let below = f64::from_bits(r.to_bits() - 1);
            if exact(below) * exact(below) >= three_h2 {
                r = below;
            } else {
                break;
            }
        }
        while exact(r) * exact(r) < three_h2 {
            r = r.next_up();
        }
        r
    }
}

/// Counters gathered while classifying.
#[derive(Default, Clone, Copy)]
struct Work {
    tri_tests: usize,
    point_queries: usize,
}

/// The state of the closed cell `b`, or `None` when empty.
fn classify(
    collider: &Collider,
    b: &Aabb,
    centre: &[f64; 3],
    work: &mut Work,
) -> Option<CellState> {
    let mesh = collider.mesh();
    let hit = collider
        .bvh()
        .for_each_candidate(
            |nb| nb.overlaps(b),
            |t| {
                work.tri_tests += 1;
                let [p, q, r] = mesh.corners(t);
                let tri = [[p.x, p.y, p.z], [q.x, q.y, q.z], [r.x, r.y, r.z]];
                if triangle_meets_box(&tri, &b.min, &b.max) {
                    ControlFlow::Break(())
                } else {
                    ControlFlow::Continue(())
                }
            },
        )
        .is_break();
    if hit {
        return Some(CellState::Partial);
    }
    work.point_queries += 1;
    collider
        .contains_point(&Point3::from(*centre))
        .then_some(CellState::Full)
}

/// Builds the octree sphere tree of the solid bounded by `collider`'s mesh (see the module
/// docs). Cells of a level are classified in parallel (rayon).
pub fn build(
    collider: &Collider,
    options: &BuildOptions,
) -> Result<(SphereTree, BuildReport), Error> {
    let depth = options.depth;
    if depth > MAX_DEPTH {
        return Err(Error::OctreeDepthTooLarge {
            depth,
            max: MAX_DEPTH,
        });
    }
    let mesh = collider.mesh();
    if options.require_closed && !mesh.is_closed() {
        return Err(Error::OctreeMeshNotClosed);
    }
    let (lo, hi) = mesh.bounds();
    let grid = Grid::new(&lo, &hi, depth)?;
    let r0 = grid.root_radius();
    let mut report = BuildReport {
        origin: grid.origin,
        side: grid.n as f64 * grid.q,
        levels: Vec::new(),
        triangle_box_tests: 0,
        point_queries: 0,
    };
    let mut work = Work::default();
    let root_cell = [0u64; 3];
    let root_centre = grid.centre(0, root_cell);
    // The root cube contains the mesh, so it is partial (a mesh has at least one triangle).
    let root_state = classify(collider, &grid.cell(0, root_cell), &root_centre, &mut work)
        .unwrap_or(CellState::Partial);
    let mut counts = LevelCounts::default();
    match root_state {
        CellState::Partial => counts.partial += 1,
        CellState::Full => counts.full += 1,
    }
    report.levels.push(counts);
    let mut nodes = vec![SphereTree::raw_node(root_centre, r0, root_state, 0, 0)];
    // The nodes of the current level: (node index, cell coordinates).
    let mut level: Vec<(usize, [u64; 3])> = vec![(0, root_cell)];
    let mut radius = r0;
    for l in 0..depth {
        let child_level = l + 1;
        radius /= 2.0;
        // Children of every node of this level, in node order.
        // Per node: its non-empty children, the work done, the number of empty octants.
        type Kids = (Vec<([u64; 3], CellState)>, Work, usize);
        let children: Vec<Kids> = level
            .par_iter()
            .map(|&(i, c)| {
                let mut w = Work::default();
                let mut out = Vec::new();
                let mut empty = 0;
                let state = nodes[i].state;
                if state == CellState::Full && !options.subdivide_full {
                    return (out, w, empty);
                }
                for k in 0..8u64 {
                    let cc = [
                        2 * c[0] + (k & 1),
                        2 * c[1] + ((k >> 1) & 1),
                        2 * c[2] + (k >> 2),
                    ];
                    let s = if state == CellState::Full {
                        Some(CellState::Full)
                    } else {
                        let b = grid.cell(child_level, cc);
                        classify(collider, &b, &grid.centre(child_level, cc), &mut w)
                    };
                    match s {
                        Some(s) => out.push((cc, s)),
                        None => empty += 1,
                    }
                }
                (out, w, empty)
            })
            .collect();
        let mut next = Vec::new();
        let mut counts = LevelCounts::default();
        for ((i, _), (kids, w, empty)) in level.iter().zip(children) {
            work.tri_tests += w.tri_tests;
            work.point_queries += w.point_queries;
            counts.empty += empty;
            if kids.is_empty() {
                continue;
            }
            let first = nodes.len() as u32;
            nodes[*i] = SphereTree::raw_node(
                nodes[*i].centre,
                nodes[*i].radius,
                nodes[*i].state,
                first,
                kids.len() as u8,
            );
            for (cc, s) in kids {
                match s {
                    CellState::Partial => counts.partial += 1,
                    CellState::Full => counts.full += 1,
                }
                next.push((nodes.len(), cc));
                nodes.push(SphereTree::raw_node(
                    grid.centre(child_level, cc),
                    radius,
                    s,
                    0,
                    0,
                ));
            }
        }
        report.levels.push(counts);
        level = next;
    }
    report.triangle_box_tests = work.tri_tests;
    report.point_queries = work.point_queries;
    Ok((SphereTree::from_raw(nodes), report))
}

/// Whether a ball `(c, r)` contains the closed box `b` (all eight corners), exactly.
#[cfg(any(test, feature = "testing"))]
pub(crate) fn ball_contains_box(c: &[f64; 3], r: f64, b: &Aabb) -> bool {
    (0..8).all(|m| {
        let p = [
            if m & 1 == 0 { b.min[0] } else { b.max[0] },
            if m & 2 == 0 { b.min[1] } else { b.max[1] },
            if m & 4 == 0 { b.min[2] } else { b.max[2] },
        ];
        crate::exact::ball_inside(&p, 0.0, c, r)
    })
}

/// The closed box of a tree node built by [`build`] from its centre and the root's side:
/// `centre ± side / 2^(level+1)` (exact for the builder's grid).
#[cfg(any(test, feature = "testing"))]
pub(crate) fn cell_of(centre: &[f64; 3], side: f64, level: u32) -> Aabb {
    let h = side / 2f64.powi(level as i32 + 1);
    Aabb {
        min: core::array::from_fn(|a| centre[a] - h),
        max: core::array::from_fn(|a| centre[a] + h),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[allow(clippy::needless_range_loop)]
    fn grid_is_exact_and_contains_the_box() {
        for (lo, hi, d) in [
            ([0.0, 0.0, 0.0], [1.0, 2.0, 3.0], 5),
            ([-0.3, 0.1, 7.0], [0.2, 0.11, 7.5], 7),
            ([1e6, 1e6, 1e6], [1e6 + 1.0, 1e6 + 0.5, 1e6 + 0.25], 6),
            ([-1e-9, 0.0, 0.0], [1e-9, 0.0, 0.0], 3),
        ] {
            let (lo, hi) = (Point3::from(lo), Point3::from(hi));
            let g = Grid::new(&lo, &hi, d).unwrap();
            let root = g.cell(0, [0; 3]);
            for a in 0..3 {
                assert!(root.min[a] <= lo[a] && hi[a] <= root.max[a]);
            }
            let side = root.max[0] - root.min[0];
            let extent = (hi - lo).max();
            assert!(side <= extent * 1.002 + 4.0 * g.q, "{side} {extent}");
            // Children tile the parent exactly; centres are the midpoints, exactly.
            let last = (1u64 << d) - 1;
            let b = g.cell(d, [last; 3]);
            assert_eq!(b.max, root.max);
            let c = g.centre(d, [last; 3]);
            for a in 0..3 {
                assert_eq!(c[a] - b.min[a], b.max[a] - c[a]);
            }
            let r = g.root_radius();
            assert!(ball_contains_box(&g.centre(0, [0; 3]), r, &root));
            assert!(!ball_contains_box(
                &g.centre(0, [0; 3]),
                f64::from_bits(r.to_bits() - 1),
                &root
            ));
        }
    }
}
