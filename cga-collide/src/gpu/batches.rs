//! The public batches (a shape against a mesh, shape–triangle pairs, a mesh against a mesh over
//! all pairs or the candidate pairs) and their common core `Device::run`: it keeps inputs the
//! device cannot certify off the device and re-decides every flagged or unsent pair with the
//! exact CPU test, which is what makes every answer equal the CPU's.

use crate::mesh::TriMesh;
use crate::{Intersects, Triangle};

use super::device::TESTS_PER_DISPATCH;
use super::{Device, Query};
use crate::error::Error;

/// The answers of one batch.
#[derive(Debug, Clone, PartialEq)]
pub struct Batch<T> {
    /// The hits, sorted: triangle indices for [`Device::hits`], `(i, j)` pairs (triangle `i`
    /// of the first mesh, `j` of the second) for the mesh batches.
    pub hits: Vec<T>,
    /// Pairs tested.
    pub tested: u64,
    /// Pairs the device could not certify (or was not given: inputs outside its safe range),
    /// re-decided on the CPU by the exact test.
    pub flagged: u64,
    /// The device's name ([`Device::name`]).
    pub device: String,
}

impl<T> Batch<T> {
    /// `flagged / tested` (0 for an empty batch).
    pub fn flagged_fraction(&self) -> f64 {
        if self.tested == 0 {
            0.0
        } else {
            self.flagged as f64 / self.tested as f64
        }
    }
}

impl Device {
    /// The triangles of `mesh` that meet `query`, sorted: brute force, every triangle tested
    /// on the device, the flagged ones re-decided exactly on the CPU.
    pub fn hits(&self, query: &Query, mesh: &TriMesh) -> Result<Batch<u32>, Error> {
        let queries = [query.packed()];
        let batch = self.run(query.kind(), &queries, mesh, None, |_, j| {
            query.intersects(&triangle(mesh, j))
        })?;
        Ok(Batch {
            hits: batch.hits.into_iter().map(|(_, j)| j).collect(),
            tested: batch.tested,
            flagged: batch.flagged,
            device: batch.device,
        })
    }

    /// The indices `k` of the pairs `pairs[k]` that intersect, sorted: arbitrary
    /// shape–triangle pairs in one batch per kind of shape.
    pub fn pair_hits(&self, pairs: &[(Query, Triangle)]) -> Result<Batch<usize>, Error> {
        let mut out = Batch {
            hits: Vec::new(),
            tested: 0,
            flagged: 0,
            device: self.name.clone(),
        };
        for kind in 0..4 {
            let index: Vec<usize> = (0..pairs.len())
                .filter(|&k| pairs[k].0.kind() == kind)
                .collect();
            if index.is_empty() {
                continue;
            }
            let queries: Vec<[f64; 12]> = index.iter().map(|&k| pairs[k].0.packed()).collect();
            let vertices = index.iter().flat_map(|&k| *pairs[k].1.vertices()).collect();
            let faces = (0..index.len() as u32)
                .map(|k| [3 * k, 3 * k + 1, 3 * k + 2])
                .collect();
            // Triangle vertices are finite, so the mesh is valid.
            let mesh = TriMesh::new(vertices, faces)
                .unwrap_or_else(|_| unreachable!("triangles have finite vertices"));
            let diagonal: Vec<(u32, u32)> = (0..index.len() as u32).map(|k| (k, k)).collect();
            let batch = self.run(kind, &queries, &mesh, Some(&diagonal), |i, _| {
                let (q, t) = &pairs[index[i as usize]];
                q.intersects(t)
            })?;
            out.hits
                .extend(batch.hits.iter().map(|&(i, _)| index[i as usize]));
            out.tested += batch.tested;
            out.flagged += batch.flagged;
        }
        out.hits.sort_unstable();
        Ok(out)
    }

    /// Every pair `(i, j)` of a triangle `i` of `a` and `j` of `b` that intersect, sorted: brute
    /// force over all `|a|·|b|` pairs, as the thesis's GPU batch.
    pub fn intersecting_pairs(&self, a: &TriMesh, b: &TriMesh) -> Result<Batch<(u32, u32)>, Error> {
        // The smaller mesh is the loop inside each thread; the larger one is spread over threads.
        let (small, large, swapped) = if a.num_triangles() <= b.num_triangles() {
            (a, b, false)
        } else {
            (b, a, true)
        };
        let queries: Vec<[f64; 12]> = (0..small.num_triangles())
            .map(|i| Query::Triangle(triangle(small, i as u32)).packed())
            .collect();
        let mut batch = self.run(1, &queries, large, None, |i, j| {
            triangle(small, i).intersects(&triangle(large, j))
        })?;
        if swapped {
            for p in &mut batch.hits {
                *p = (p.1, p.0);
            }
            batch.hits.sort_unstable();
        }
        Ok(batch)
    }

    /// The pairs among `candidates` (triangle `i` of `a`, `j` of `b`; e.g. the box-overlap
    /// pairs of the two box trees, which [`Bvh::for_each_pair`](crate::bounding::Bvh::for_each_pair)
    /// enumerates) that intersect, sorted.
    pub fn intersecting_candidates(
        &self,
        a: &TriMesh,
        b: &TriMesh,
        candidates: &[(u32, u32)],
    ) -> Result<Batch<(u32, u32)>, Error> {
        let queries: Vec<[f64; 12]> = (0..a.num_triangles())
            .map(|i| Query::Triangle(triangle(a, i as u32)).packed())
            .collect();
        self.run(1, &queries, b, Some(candidates), |i, j| {
            triangle(a, i).intersects(&triangle(b, j))
        })
    }

    /// Runs a batch: queries (12 numbers each) against the triangles of `mesh`, all pairs or
    /// the listed ones; `exact(i, j)` re-decides a pair on the CPU.
    fn run(
        &self,
        kind: u32,
        queries: &[[f64; 12]],
        mesh: &TriMesh,
        pairs: Option<&[(u32, u32)]>,
        exact: impl Fn(u32, u32) -> bool + Sync,
    ) -> Result<Batch<(u32, u32)>, Error> {
        let p = self.precision;
        let n_tri = mesh.num_triangles();
        let query_safe: Vec<bool> = queries
            .iter()
            .map(|q| q.iter().all(|&x| p.safe(x)))
            .collect();
        let tri_data: Vec<[f64; 9]> = (0..n_tri)
            .map(|j| {
                let [a, b, c] = mesh.corners(j as u32);
                [a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z]
            })
            .collect();
        let tri_safe: Vec<bool> = tri_data
            .iter()
            .map(|t| t.iter().all(|&x| p.safe(x)))
            .collect();
        let query_bytes = (queries.len() * 12 * p.bytes()) as u64;
        if query_bytes > self.max_binding {
            return Err(Error::GpuBufferTooLarge {
                what: "the query data",
                bytes: query_bytes,
                limit: self.max_binding,
            });
        }
        let query_buf = self.upload("queries", &self.encode(queries.iter().flatten()));
        let mut device_hits = Vec::new();
        let mut device_flagged = Vec::new();
        let tested;
        match pairs {
            None => {
                tested = queries.len() as u64 * n_tri as u64;
                let per_chunk = (self.max_binding / (9 * p.bytes() as u64)).max(1) as usize;
                for start in (0..n_tri).step_by(per_chunk) {
                    let end = (start + per_chunk).min(n_tri);
                    let tri_buf = self.upload(
                        "triangles",
                        &self.encode(tri_data[start..end].iter().flatten()),
                    );
                    let pair_buf = self.upload("pairs", &[0u8; 8]);
                    let n = (end - start) as u64;
                    let step = (TESTS_PER_DISPATCH / n).clamp(1, queries.len() as u64) as usize;
                    for q0 in (0..queries.len()).step_by(step) {
                        let q1 = (q0 + step).min(queries.len());
                        let out = self.dispatch(
                            kind,
                            0,
                            (queries.len() as u32, n as u32, q0 as u32, q1 as u32),
                            [&query_buf, &tri_buf, &pair_buf],
                        )?;
                        let shift = |v: Vec<(u32, u32)>| {
                            v.into_iter().map(move |(i, j)| (i, j + start as u32))
                        };
                        device_hits.extend(shift(out.hits));
                        device_flagged.extend(shift(out.flagged));
                    }
                }
            }
            Some(pairs) => {
                tested = pairs.len() as u64;
                let tri_bytes = (n_tri * 9 * p.bytes()) as u64;
                if tri_bytes > self.max_binding {
                    return Err(Error::GpuBufferTooLarge {
                        what: "the mesh",
                        bytes: tri_bytes,
                        limit: self.max_binding,
                    });
                }
                let tri_buf = self.upload("triangles", &self.encode(tri_data.iter().flatten()));
                let per_chunk = (self.max_binding / 8).min(TESTS_PER_DISPATCH) as usize;
                for chunk in pairs.chunks(per_chunk.max(1)) {
                    let raw: Vec<u8> = chunk
                        .iter()
                        .flat_map(|&(i, j)| [i, j])
                        .flat_map(u32::to_le_bytes)
                        .collect();
                    let pair_buf = self.upload("pairs", &raw);
                    let out = self.dispatch(
                        kind,
                        1,
                        (queries.len() as u32, chunk.len() as u32, 0, 0),
                        [&query_buf, &tri_buf, &pair_buf],
                    )?;
                    device_hits.extend(out.hits);
                    device_flagged.extend(out.flagged);
                }
            }
        }
        // Pairs with an input outside the device's safe range: the device's answer is ignored.
        let unsafe_pair = |&(i, j): &(u32, u32)| !query_safe[i as usize] || !tri_safe[j as usize];
        device_hits.retain(|pair| !unsafe_pair(pair));
        device_flagged.retain(|pair| !unsafe_pair(pair));
        let mut undecided = device_flagged;
        match pairs {
            None => {
                for (i, _) in query_safe.iter().enumerate().filter(|(_, s)| !**s) {
                    undecided.extend((0..n_tri as u32).map(|j| (i as u32, j)));
                }
                for (j, _) in tri_safe.iter().enumerate().filter(|(_, s)| !**s) {
                    undecided.extend(
                        (0..queries.len() as u32)
                            .filter(|&i| query_safe[i as usize])
                            .map(|i| (i, j as u32)),
                    );
                }
            }
            Some(pairs) => undecided.extend(pairs.iter().filter(|p| unsafe_pair(p))),
        }
        let flagged = undecided.len() as u64;
        let decided: Vec<(u32, u32)> = undecided
            .into_iter()
            .filter(|&(i, j)| exact(i, j))
            .collect();
        let mut hits = device_hits;
        hits.extend(decided);
        hits.sort_unstable();
        Ok(Batch {
            hits,
            tested,
            flagged,
            device: self.name.clone(),
        })
    }
}

/// Triangle `j` of a mesh as an exact-test shape.
fn triangle(mesh: &TriMesh, j: u32) -> Triangle {
    let [a, b, c] = mesh.corners(j);
    // TriMesh vertices are finite, so this cannot fail.
    Triangle::new(a, b, c).unwrap_or_else(|_| unreachable!("TriMesh vertices are finite"))
}
