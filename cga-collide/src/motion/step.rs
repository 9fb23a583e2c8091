//! One deforming mesh over a time step: every vertex moves linearly from its position in the
//! mesh (`t = 0`) to its position in a second vertex array of the same topology (`t = 1`), and
//! every vertex–face and edge–edge pair that touches during the step is found, exactly.
//!
//! Broad phase: the box each primitive sweeps during the step (the box of its vertices at both
//! ends, exact) in a box tree over the faces and one over the edges; a vertex is tested against
//! the faces whose swept boxes meet its own, an edge against the later edges whose boxes meet
//! its own. Pairs that share a vertex are excluded (they touch by construction). The boxes
//! are conservative (linear motion stays inside them), so no touching pair is dropped. The
//! narrow phase is the exact decision of [`super::vertex_face_touch`] and
//! [`super::edge_edge_touch`], over the cores.

use std::collections::HashSet;
use std::ops::ControlFlow;

use nalgebra::Point3;

use super::ContactTime;
use crate::bounding::{Aabb, BuildStrategy, Bvh};
use crate::error::{Error, Location};
use crate::parallel::*;
use crate::shape::TriMesh;

/// What touches during a step of a deforming mesh ([`step_self_contacts`]).
#[derive(Clone, Debug, PartialEq)]
pub struct StepContacts {
    /// `(vertex, face)` pairs that touch during the step, sorted.
    pub vertex_face: Vec<(u32, u32)>,
    /// Pairs of edges that touch, each edge as its two vertices (smaller first), the smaller
    /// edge first; sorted.
    pub edge_edge: Vec<([u32; 2], [u32; 2])>,
    /// The earliest contact of all, to the tolerance asked for; `None` when nothing touches.
    pub first_contact: Option<ContactTime>,
    /// How many vertex–face pairs the swept boxes let through to the exact test.
    pub vertex_face_candidates: usize,
    /// How many edge–edge pairs the swept boxes let through to the exact test.
    pub edge_edge_candidates: usize,
}

/// The undirected edges of the triangles, each `(smaller, larger)`, sorted by `(larger,
/// smaller)` (the order of the CCD benchmark's element ids).
pub fn mesh_edges(triangles: &[[u32; 3]]) -> Vec<[u32; 2]> {
    let mut edges: Vec<[u32; 2]> = triangles
        .iter()
        .flat_map(|t| [(t[0], t[1]), (t[1], t[2]), (t[2], t[0])])
        .map(|(a, b)| [a.min(b), a.max(b)])
        .collect();
    edges.sort_unstable_by_key(|e| (e[1], e[0]));
    edges.dedup();
    edges
}

/// Every vertex–face and edge–edge contact of `mesh` deforming over one step, its vertices
/// moving linearly to `end` (same vertices, same order), exactly; pairs that share a vertex are
/// excluded. The first contact time is bounded to `tolerance` (see
/// [`super::vertex_face_first_contact`]).
///
/// # Errors
/// [`Error::VertexCountMismatch`] when `end` does not have one position per vertex, and
/// [`Error::NonFinite`] when an end position is not finite.
///
/// ```
/// use cga_collide::motion::step_self_contacts;
/// use cga_collide::nalgebra::Point3;
/// use cga_collide::TriMesh;
/// // Two separate triangles; the second falls through the first during the step.
/// let p = |x, y, z| Point3::new(x, y, z);
/// let start = vec![
///     p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.),
///     p(0.2, 0.2, 1.), p(0.3, 0.2, 1.), p(0.2, 0.3, 1.),
/// ];
/// let mesh = TriMesh::new(start.clone(), vec![[0, 1, 2], [3, 4, 5]])?;
/// let end: Vec<_> = start.iter().enumerate()
///     .map(|(i, q)| if i >= 3 { p(q.x, q.y, q.z - 2.0) } else { *q })
///     .collect();
/// let contacts = step_self_contacts(&mesh, &end, 1e-9)?;
/// assert_eq!(contacts.vertex_face, vec![(3, 0), (4, 0), (5, 0)]);
/// let first = contacts.first_contact.expect("they touch");
/// assert!(first.lo() <= 0.5 && 0.5 <= first.hi());
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn step_self_contacts(
    mesh: &TriMesh,
    end: &[Point3<f64>],
    tolerance: f64,
) -> Result<StepContacts, Error> {
    let start = mesh.vertices();
    if end.len() != start.len() {
        return Err(Error::VertexCountMismatch {
            expected: start.len(),
            found: end.len(),
        });
    }
    if let Some((vertex, value)) = end
        .iter()
        .enumerate()
        .flat_map(|(i, p)| p.iter().map(move |&v| (i, v)))
        .find(|(_, v)| !v.is_finite())
    {
        return Err(Error::NonFinite {
            at: Location::file("end positions of the step"),
            vertex,
            value,
        });
    }
    let faces = mesh.triangles();
    let edges = mesh_edges(faces);
    let track = |v: u32| -> [[f64; 3]; 2] {
        let (a, b) = (start[v as usize], end[v as usize]);
        [[a.x, a.y, a.z], [b.x, b.y, b.z]]
    };
    let swept = |vertices: &[u32]| {
        let mut b = Aabb::EMPTY;
        for &v in vertices {
            b.grow(&start[v as usize]);
            b.grow(&end[v as usize]);
        }
        b
    };
    let face_boxes: Vec<Aabb> = faces.iter().map(|f| swept(f)).collect();
    let edge_boxes: Vec<Aabb> = edges.iter().map(|e| swept(e)).collect();
    let face_tree = Bvh::from_boxes(face_boxes, BuildStrategy::Sah);
    let edge_tree = Bvh::from_boxes(edge_boxes.clone(), BuildStrategy::Sah);

    // Broad phase, over the cores: vertex–face pairs per vertex, edge–edge pairs per edge.
    let vertex_face_candidates: Vec<(u32, u32)> = (0..start.len() as u32)
        .into_par_iter()
        .flat_map_iter(|v| {
            let mut out = Vec::new();
            if !faces.is_empty() {
                let b = swept(&[v]);
                let _ = face_tree.for_each_candidate(
                    |n| n.overlaps(&b),
                    |f| {
                        if !faces[f as usize].contains(&v) {
                            out.push((v, f));
                        }
                        ControlFlow::<()>::Continue(())
                    },
                );
            }
            out
        })
        .collect();
    let edge_edge_candidates: Vec<(u32, u32)> = (0..edges.len() as u32)
        .into_par_iter()
        .flat_map_iter(|i| {
            let mut out = Vec::new();
            let e = edges[i as usize];
            let b = edge_boxes[i as usize];
            let _ = edge_tree.for_each_candidate(
                |n| n.overlaps(&b),
                |j| {
                    let o = edges[j as usize];
                    if j > i && !o.contains(&e[0]) && !o.contains(&e[1]) {
                        out.push((i, j));
                    }
                    ControlFlow::<()>::Continue(())
                },
            );
            out
        })
        .collect();

    // Narrow phase, exact.
    let vf_points = |&(v, f): &(u32, u32)| {
        let t = faces[f as usize];
        [track(v), track(t[0]), track(t[1]), track(t[2])]
    };
    let ee_points = |&(i, j): &(u32, u32)| {
        let (a, b) = (edges[i as usize], edges[j as usize]);
        [track(a[0]), track(a[1]), track(b[0]), track(b[1])]
    };
    // One pass decides every candidate and bounds its first contact coarsely (the filter's
    // first certified interval, or the exact isolating interval); only the pairs that can
    // hold the earliest contact are then refined to the tolerance.
    let vf_hits: Vec<((u32, u32), ContactTime)> = vertex_face_candidates
        .par_iter()
        .filter_map(|c| {
            super::points_vertex_face_first_contact(&vf_points(c), f64::INFINITY).map(|t| (*c, t))
        })
        .collect();
    let ee_hits: Vec<((u32, u32), ContactTime)> = edge_edge_candidates
        .par_iter()
        .filter_map(|c| {
            super::points_edge_edge_first_contact(&ee_points(c), f64::INFINITY).map(|t| (*c, t))
        })
        .collect();
    let earliest_hi = vf_hits
        .iter()
        .chain(&ee_hits)
        .map(|(_, t)| t.hi())
        .fold(f64::INFINITY, f64::min);
    let times: Vec<ContactTime> = vf_hits
        .par_iter()
        .filter(|(_, t)| t.lo() <= earliest_hi)
        .filter_map(|(c, _)| super::points_vertex_face_first_contact(&vf_points(c), tolerance))
        .chain(
            ee_hits
                .par_iter()
                .filter(|(_, t)| t.lo() <= earliest_hi)
                .filter_map(|(c, _)| {
                    super::points_edge_edge_first_contact(&ee_points(c), tolerance)
                }),
        )
        .collect();
    let mut vertex_face: Vec<(u32, u32)> = vf_hits.iter().map(|(c, _)| *c).collect();
    let edge_pairs: Vec<(u32, u32)> = ee_hits.iter().map(|(c, _)| *c).collect();
    vertex_face.sort_unstable();
    let mut edge_edge: Vec<([u32; 2], [u32; 2])> = edge_pairs
        .iter()
        .map(|&(i, j)| {
            let (a, b) = (edges[i as usize], edges[j as usize]);
            (a.min(b), a.max(b))
        })
        .collect::<HashSet<_>>()
        .into_iter()
        .collect();
    edge_edge.sort_unstable();
    Ok(StepContacts {
        vertex_face,
        edge_edge,
        first_contact: ContactTime::earliest(times),
        vertex_face_candidates: vertex_face_candidates.len(),
        edge_edge_candidates: edge_edge_candidates.len(),
    })
}
