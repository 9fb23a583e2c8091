//! The double hierarchy of outer and inner spheres of convex polyhedra (the double-sphere paper,
//! §4) and its exact collision test.
//!
//! # The tree ([`DoubleSphereTree::build`])
//! A binary tree, stored flat (`Vec` of [`DoubleSphereNode`]s, root at index 0). Every node holds a convex
//! sub-polyhedron of the original solid (the root holds the solid itself) with
//! * its **outer sphere**: the smallest sphere enclosing the sub-polyhedron's vertices
//!   (Welzl's algorithm in `f64`, then the radius recomputed as the largest
//!   vertex distance rounded upwards, plus a margin of `1e-12` times the solid's size that
//!   covers the rounding of the clipped vertices), so it provably contains the node's region;
//! * its **inner sphere**, of a selectable [`InnerSphereKind`]: the paper's
//!   (centre the centroid, radius the smallest distance from it to the node's faces) or the
//!   largest inscribed sphere (the Chebyshev centre, by a small linear programme). Either radius
//!   is also limited by the distances to the planes of all the original triangles and reduced by
//!   the margin, so the sphere is certainly inside the solid;
//! * its **label**: *internal* when the outer sphere lies inside the original solid (by more
//!   than the margin), else *external* (paper §2.4 / §4.2).
//!
//! A node of depth `< level` is split by the plane through its outer sphere's centre,
//! perpendicular to its principal axis: the eigenvector of the largest eigenvalue of the
//! covariance matrix of eq. (3), taken over the vertices of the triangles of the node's faces
//! (Gottschalk's triangle form, `nalgebra::SymmetricEigen`); the two children are the convex
//! clippings of the node's sub-polyhedron by the two half-spaces. So level 0 is the
//! root alone and level `L` has up to `2^L` leaves (fewer if a cut would leave an empty child);
//! the paper's experiments use level 3. Solids with cubic or icosahedral symmetry have an
//! isotropic covariance at the root, where the principal axis is whatever the eigen-solver
//! returns (deterministic).
//!
//! The *regions* of the nodes are the original solid intersected with the split half-spaces on
//! the path from the root; the two children's regions cover their parent's. Each leaf stores the
//! **original** triangles (of [`ConvexPolyhedron::triangles`]) that meet its region, found by
//! clipping each triangle by the path's half-spaces with a tolerance (a superset): the face
//! tests at the leaves run on these unclipped triangles, so they are the exact test of the
//! solids' surfaces and every piece of surface is covered by some leaf.
//!
//! # The test ([`DoubleSphereTree::collides_at`])
//! The paper's Algorithm 1 in a simultaneous depth-first descent: outer spheres reject, two
//! internal labels with touching outer spheres or two touching inner spheres accept, and leaves
//! go to Algorithm 2, the exact triangle–triangle test ([`crate::Triangle`]'s `intersects`).
//! See [`DoubleSphereTree::collides_at`] for the details and the rounding analysis that makes
//! the answer exact for the solids bounded by the triangles with vertices `pose * v`
//! (nalgebra's `Isometry3 * Point3` in `f64`, as
//! [`TriMesh::transformed`](crate::shape::mesh::TriMesh::transformed) does).
//!
//! # Paper versus ours
//! Following the paper: the binary split by the principal-axis plane through the outer centre,
//! the smallest enclosing outer spheres, the centroid inner spheres, the internal/external
//! labels, Algorithm 1's order of tests and Algorithm 2. Ours:
//! * the Chebyshev inner sphere ([`InnerSphereKind::Chebyshev`]), the largest possible;
//! * certified spheres: outer radii inflated and inner radii deflated by a rigorous bound on the
//!   rounding of the pose transform, and sphere comparisons with an error bound (never an
//!   uncertain acceptance or rejection);
//! * the leaves test the original, unclipped triangles (exact, and nothing is lost at cuts);
//! * exact pruning that only drops work which cannot find a contact *inside the regions of the
//!   pair*: a pair of nodes (after its inner-sphere test) is dropped when one node's inflated
//!   outer sphere is certainly beyond a supporting plane of an original face of the other
//!   solid (the planes of the faces below the other node are tried), and at a leaf pair a
//!   triangle is skipped when its bounding box is certainly farther than the other leaf's
//!   inflated outer sphere, a triangle pair when their boxes do not overlap; each leaf's
//!   triangles are transformed at most once per query. Since the leaves test whole original
//!   triangles, a dropped pair could occasionally have found a genuine contact lying in
//!   other regions first, so on rare placements the collision is then found by a later pair
//!   (e.g. by inner spheres instead of faces: 1 placement in 5,000 in our runs); the answer
//!   never changes;
//! * after a descent without contact, an exact containment test (one solid inside the other
//!   without touching it, which Algorithm 1 alone reports as "no contact");
//! * where the paper's pseudocode descends both trees in two calls when both nodes are inner
//!   nodes (reaching the same leaf pairs several times), we descend the node with the larger
//!   outer sphere; a pair with an internal node descends the other (external) node, since an
//!   internal region holds no surface.
//!
//! ```
//! use cga_collide::hierarchy::double_sphere::{Decision, DoubleSphereTree, InnerSphereKind};
//! use cga_collide::nalgebra::{Isometry3, Vector3};
//! use cga_collide::shape::polyhedron::ConvexPolyhedron;
//!
//! let troct = DoubleSphereTree::build(&ConvexPolyhedron::truncated_octahedron(), 3, InnerSphereKind::Centroid).unwrap();
//! let diamond = DoubleSphereTree::build(&ConvexPolyhedron::diamond(), 3, InnerSphereKind::Chebyshev).unwrap();
//! assert_eq!(troct.num_leaves(), 8);
//! let here = Isometry3::identity();
//! // Far apart: rejected by the outer spheres at the root.
//! let far = Isometry3::translation(5.0, 0.0, 0.0);
//! let out = troct.collides_at(&here, &diamond, &far);
//! assert!(!out.collides);
//! assert_eq!(out.decided_by, Decision::OuterSpheres);
//! // Deeply overlapping: accepted by the inner spheres.
//! let near = Isometry3::translation(0.1, 0.0, 0.0);
//! let out = troct.collides_at(&here, &diamond, &near);
//! assert!(out.collides);
//! assert_eq!(out.decided_by, Decision::InnerSpheres);
//! // Two cubes sharing a face exactly (x = s and x = -s + 2s, both exact in f64): touching
//! // counts, found by the exact face tests.
//! let cube = DoubleSphereTree::build(&ConvexPolyhedron::cube(), 3, InnerSphereKind::Centroid).unwrap();
//! let s = cube.polyhedron().vertices()[0].x.abs();
//! let out = cube.collides_at(&here, &cube, &Isometry3::translation(2.0 * s, 0.0, 0.0));
//! assert!(out.collides);
//! assert_eq!(out.decided_by, Decision::Faces);
//! // A hair further apart: no contact.
//! let out = cube.collides_at(&here, &cube, &Isometry3::translation(2.0 * s + 1e-15, 0.0, 0.0));
//! assert!(!out.collides);
//! ```

pub(crate) mod clip;
pub(crate) mod enclosing;
pub(crate) mod inscribed;
mod traverse;

use nalgebra::{Point3, SymmetricEigen, Vector3};

use crate::error::Error;
use crate::shape::polyhedron::ConvexPolyhedron;
use clip::{polygon_meets_halfspaces, SubPolyhedron};
pub use traverse::{Decision, Outcome};

/// Which inner sphere the nodes get.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum InnerSphereKind {
    /// The paper's: centred at the centroid (eq. 2), radius the smallest distance to a face.
    Centroid,
    /// The largest inscribed sphere (Chebyshev centre); never smaller than the centroid one.
    Chebyshev,
}

/// The deepest supported tree (`2^16` leaves).
pub const MAX_LEVEL: usize = 16;

/// Margin, relative to the solid's largest vertex norm, added to outer radii, removed from
/// inner radii and required by the internal label. It dominates the rounding of the clipping
/// and of the plane computations (about `1e-15` relative).
pub const BUILD_MARGIN: f64 = 1e-12;

/// A sphere given by its centre and radius (a node's outer or inner sphere, or a smallest
/// enclosing ball).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CentreRadius {
    /// The centre (body frame).
    pub centre: Point3<f64>,
    /// The radius.
    pub radius: f64,
}

/// A node of a [`DoubleSphereTree`].
#[derive(Debug, Clone, PartialEq)]
pub struct DoubleSphereNode {
    /// The outer sphere: contains the node's region (the radius includes [`BUILD_MARGIN`]).
    pub outer: CentreRadius,
    /// The inner sphere: inside the node's sub-polyhedron and inside the solid (radius reduced
    /// by [`BUILD_MARGIN`], possibly 0).
    pub inner: CentreRadius,
    /// The paper's label: the outer sphere lies inside the solid.
    pub internal: bool,
    /// The two children, or `None` for a leaf.
    pub children: Option<[u32; 2]>,
    /// The split plane `(a, d)` of an inner node: the first child's region is `a·x <= d`, the
    /// second's `a·x >= d` (`a` the unit principal axis, `d = a·outer centre`).
    pub split: Option<(Vector3<f64>, f64)>,
    /// Depth (the root is 0).
    pub depth: u32,
    /// Range of this leaf's original triangles in the tree's leaf-triangle list (empty for
    /// inner nodes; [`DoubleSphereTree::leaf_triangles`] reads it).
    pub(crate) triangles: std::ops::Range<u32>,
    /// Range of this node's face planes in the tree's node-plane list: the supporting planes of
    /// the original faces that the triangles of the leaves below it belong to.
    pub(crate) planes: std::ops::Range<u32>,
}

impl DoubleSphereNode {
    /// Whether the node has no children.
    pub fn is_leaf(&self) -> bool {
        self.children.is_none()
    }
}

/// The double hierarchy of outer and inner spheres of a convex polyhedron (see the module
/// docs).
#[derive(Debug, Clone)]
pub struct DoubleSphereTree {
    polyhedron: ConvexPolyhedron,
    nodes: Vec<DoubleSphereNode>,
    /// The nodes' sub-polyhedra, kept for the tests only.
    #[cfg(any(test, feature = "testing"))]
    parts: Vec<SubPolyhedron>,
    leaf_triangles: Vec<u32>,
    pub(crate) leaf_planes: Vec<(Vector3<f64>, f64)>,
    level: usize,
    kind: InnerSphereKind,
    /// Largest vertex norm (body frame), for the transform error bound.
    pub(crate) vmax: f64,
    /// Planes of the original triangles `(n, d)`, `n` unit, `n·x <= d` inside.
    pub(crate) planes: Vec<(Vector3<f64>, f64)>,
}

struct Builder<'a> {
    poly: &'a ConvexPolyhedron,
    kind: InnerSphereKind,
    level: usize,
    margin: f64,
    guard: Vec<(Vector3<f64>, f64)>,
    nodes: Vec<DoubleSphereNode>,
    parts: Vec<SubPolyhedron>,
    leaf_triangles: Vec<u32>,
    face_planes: Vec<(Vector3<f64>, f64)>,
    leaf_planes: Vec<(Vector3<f64>, f64)>,
}

impl Builder<'_> {
    fn node(
        &mut self,
        part: SubPolyhedron,
        depth: u32,
        path: &mut Vec<(Vector3<f64>, f64)>,
    ) -> u32 {
        let index = self.nodes.len() as u32;
        let outer = enclosing::smallest_enclosing_ball(&part.vertices);
        let outer = CentreRadius {
            centre: outer.centre,
            radius: outer.radius + self.margin,
        };
        let (centroid, cov) = part.centroid_and_covariance();
        let planes = part.planes();
        let (c, _) = match self.kind {
            InnerSphereKind::Centroid => inscribed::centroid_sphere(&planes, &centroid),
            InnerSphereKind::Chebyshev => inscribed::chebyshev_sphere(&planes, &centroid),
        };
        let r = inscribed::depth(&planes, &c).min(inscribed::depth(&self.guard, &c)) - self.margin;
        let inner = CentreRadius {
            centre: c,
            radius: r.max(0.0),
        };
        let internal = inscribed::depth(&self.guard, &outer.centre) - outer.radius > self.margin;
        self.nodes.push(DoubleSphereNode {
            outer,
            inner,
            internal,
            children: None,
            split: None,
            depth,
            triangles: 0..0,
            planes: 0..0,
        });
        self.parts.push(part);
        let mut split = None;
        if (depth as usize) < self.level {
            let eig = SymmetricEigen::new(cov);
            let k = eig.eigenvalues.imax();
            let axis: Vector3<f64> = eig.eigenvectors.column(k).into_owned();
            let d = axis.dot(&outer.centre.coords);
            let part = &self.parts[index as usize];
            let vol = part.volume();
            if let (Some(a), Some(b)) = (part.clip(&axis, d), part.clip(&-axis, -d)) {
                if a.volume() > 1e-12 * vol && b.volume() > 1e-12 * vol {
                    split = Some((a, b, axis, d));
                }
            }
        }
        match split {
            Some((a, b, axis, d)) => {
                path.push((axis, d));
                let ia = self.node(a, depth + 1, path);
                path.pop();
                path.push((-axis, -d));
                let ib = self.node(b, depth + 1, path);
                path.pop();
                self.nodes[index as usize].children = Some([ia, ib]);
                self.nodes[index as usize].split = Some((axis, d));
            }
            None => {
                let start = self.leaf_triangles.len() as u32;
                let tol = self.margin;
                for t in 0..self.poly.triangles().len() {
                    if polygon_meets_halfspaces(&self.poly.triangle(t), path, tol) {
                        self.leaf_triangles.push(t as u32);
                    }
                }
                self.nodes[index as usize].triangles = start..self.leaf_triangles.len() as u32;
            }
        }
        index
    }
}

impl DoubleSphereTree {
    /// Builds the tree of `polyhedron` down to `level` (0 = the root only; level `L` has up to
    /// `2^L` leaves) with inner spheres of the given kind.
    pub fn build(
        polyhedron: &ConvexPolyhedron,
        level: usize,
        inner: InnerSphereKind,
    ) -> Result<Self, Error> {
        if level > MAX_LEVEL {
            return Err(Error::LevelTooDeep {
                level,
                max: MAX_LEVEL,
            });
        }
        let vmax = polyhedron.max_vertex_norm();
        let guard: Vec<(Vector3<f64>, f64)> = (0..polyhedron.triangles().len())
            .map(|t| {
                let [a, b, c] = polyhedron.triangle(t);
                let n = (b - a).cross(&(c - a)).normalize();
                let d = [a, b, c]
                    .iter()
                    .map(|p| n.dot(&p.coords))
                    .fold(f64::NEG_INFINITY, f64::max);
                (n, d)
            })
            .collect();
        let mut builder = Builder {
            poly: polyhedron,
            kind: inner,
            level,
            margin: BUILD_MARGIN * vmax,
            guard,
            nodes: Vec::new(),
            parts: Vec::new(),
            leaf_triangles: Vec::new(),
            face_planes: (0..polyhedron.num_faces())
                .map(|f| {
                    // Supporting plane: the offset is the largest n·v over ALL vertices plus the
                    // margin, so the whole solid is certainly on the inner side.
                    let n = polyhedron.face_normal(f);
                    let d = polyhedron
                        .vertices()
                        .iter()
                        .map(|v| n.dot(&v.coords))
                        .fold(f64::NEG_INFINITY, f64::max);
                    (n, d + BUILD_MARGIN * vmax)
                })
                .collect(),
            leaf_planes: Vec::new(),
        };
        builder.node(
            SubPolyhedron::from_polyhedron(polyhedron),
            0,
            &mut Vec::new(),
        );
        // Every node's faces: the original faces of the triangles of the leaves below it
        // (children come after their parent, so a reverse sweep sees children first).
        let n = builder.nodes.len();
        let mut faces: Vec<Vec<usize>> = vec![Vec::new(); n];
        for i in (0..n).rev() {
            let mut f: Vec<usize> = match builder.nodes[i].children {
                Some([c0, c1]) => faces[c0 as usize]
                    .iter()
                    .chain(&faces[c1 as usize])
                    .copied()
                    .collect(),
                None => {
                    let r = builder.nodes[i].triangles.clone();
                    builder.leaf_triangles[r.start as usize..r.end as usize]
                        .iter()
                        .map(|&t| polyhedron.triangle_faces()[t as usize])
                        .collect()
                }
            };
            f.sort_unstable();
            f.dedup();
            faces[i] = f;
        }
        for (i, f) in faces.iter().enumerate() {
            let start = builder.leaf_planes.len() as u32;
            builder
                .leaf_planes
                .extend(f.iter().map(|&k| builder.face_planes[k]));
            builder.nodes[i].planes = start..builder.leaf_planes.len() as u32;
        }
        Ok(DoubleSphereTree {
            polyhedron: polyhedron.clone(),
            nodes: builder.nodes,
            #[cfg(any(test, feature = "testing"))]
            parts: builder.parts,
            leaf_triangles: builder.leaf_triangles,
            leaf_planes: builder.leaf_planes,
            level,
            kind: inner,
            vmax,
            planes: builder.guard,
        })
    }

    /// The solid.
    pub fn polyhedron(&self) -> &ConvexPolyhedron {
        &self.polyhedron
    }

    /// The nodes, root first; children of a node come after it.
    pub fn nodes(&self) -> &[DoubleSphereNode] {
        &self.nodes
    }

    /// The sub-polyhedron of node `i` (for tests: `cga_collide::testing::double_sphere::part`).
    #[cfg(any(test, feature = "testing"))]
    pub(crate) fn part(&self, i: usize) -> &SubPolyhedron {
        &self.parts[i]
    }

    /// The original triangles (indices into [`ConvexPolyhedron::triangles`]) of leaf `i`.
    pub fn leaf_triangles(&self, i: usize) -> &[u32] {
        let r = &self.nodes[i].triangles;
        &self.leaf_triangles[r.start as usize..r.end as usize]
    }

    /// The level the tree was built to.
    pub fn level(&self) -> usize {
        self.level
    }

    /// The inner-sphere kind.
    pub fn inner_kind(&self) -> InnerSphereKind {
        self.kind
    }

    /// Number of leaves.
    pub fn num_leaves(&self) -> usize {
        self.nodes.iter().filter(|n| n.is_leaf()).count()
    }
}
