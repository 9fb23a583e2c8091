//! A collider as bytes and back, its box tree included ([`Collider::to_bytes`],
//! [`Collider::from_bytes`]): a built collider travels (to a worker process, a file, a cache)
//! without rebuilding its tree.
//!
//! The bytes hold the mesh, the mode and the tree's shape (each node's `start` and `count`, the
//! leaf order), little-endian. The boxes are not stored: they are recomputed from the vertices,
//! exactly as the build computes them, so bytes from elsewhere can never make a box too small
//! (a missed contact). Everything read is checked (sizes, indices, the tree's shape); bad bytes
//! are an [`Error`], never a panic.

use std::sync::OnceLock;

use nalgebra::Point3;

use super::{extent, Collider, Mode};
use crate::bounding::BuildStrategy;
use crate::bounding::{Bvh, BvhNode, MAX_LEAF};
use crate::error::{Error, Location};
use crate::shape::mesh::TriMesh;

/// First bytes of every serialized collider (name and format version).
const MAGIC: &[u8; 8] = b"CGACOL01";
/// The name errors give to serialized input.
const NAME: &str = "<Collider bytes>";

impl Collider {
    /// The collider as bytes: its mesh, its mode and the shape of its box tree (see
    /// [`from_bytes`](Self::from_bytes)). About 24 bytes a vertex and 20 a triangle.
    ///
    /// ```
    /// use cga_collide::{nalgebra::{Isometry3, Point3}, Collider, TriMesh};
    /// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
    /// let back = Collider::from_bytes(&cube.to_bytes())?;
    /// let there = Isometry3::translation(1.0, 0.0, 0.0);
    /// assert!(back.collides_at(&Isometry3::identity(), &cube, &there)?);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn to_bytes(&self) -> Vec<u8> {
        let (v, t) = (self.mesh.vertices(), self.mesh.triangles());
        let nodes = self.bvh().nodes();
        let mut out =
            Vec::with_capacity(33 + 24 * v.len() + 12 * t.len() + 8 * nodes.len() + 4 * t.len());
        out.extend_from_slice(MAGIC);
        out.push(match self.mode {
            Mode::Brute => 0,
            Mode::Bvh => 1,
        });
        for n in [v.len(), t.len(), nodes.len()] {
            out.extend_from_slice(&(n as u64).to_le_bytes());
        }
        for p in v {
            for c in 0..3 {
                out.extend_from_slice(&p[c].to_le_bytes());
            }
        }
        for tri in t {
            for &i in tri {
                out.extend_from_slice(&i.to_le_bytes());
            }
        }
        for n in nodes {
            out.extend_from_slice(&n.start.to_le_bytes());
            out.extend_from_slice(&n.count.to_le_bytes());
        }
        for &i in self.bvh().order() {
            out.extend_from_slice(&i.to_le_bytes());
        }
        out
    }

    /// A collider from the bytes of [`to_bytes`](Self::to_bytes), without rebuilding its tree
    /// (the boxes are recomputed from the vertices, a linear pass). Fails with an [`Error`]
    /// naming what is wrong when the bytes are truncated, of another format, or describe an
    /// invalid mesh or tree.
    pub fn from_bytes(bytes: &[u8]) -> Result<Collider, Error> {
        let mut r = Reader { bytes, at: 0 };
        if r.take(8, "the 8-byte header")? != MAGIC {
            return Err(syntax(
                "not a serialized collider (the header is not CGACOL01)".to_owned(),
            ));
        }
        let mode = match r.take(1, "the mode byte")?[0] {
            0 => Mode::Brute,
            1 => Mode::Bvh,
            m => return Err(syntax(format!("unknown mode {m} (expected 0 or 1)"))),
        };
        let nv = r.count("the vertex count")?;
        let nt = r.count("the triangle count")?;
        let nn = r.count("the node count")?;
        // Sizes first: every count must fit in what is left, before anything is allocated.
        let need = [(nv, 24u64), (nt, 12), (nn, 8), (nt, 4)]
            .iter()
            .try_fold(0u64, |acc, &(n, size)| {
                n.checked_mul(size).and_then(|b| acc.checked_add(b))
            });
        let left = (bytes.len() - r.at) as u64;
        match need {
            Some(need) if need == left => {}
            Some(need) => {
                return Err(syntax(format!(
                    "{nv} vertices, {nt} triangles and {nn} nodes take {need} bytes, but {left} follow the header"
                )))
            }
            None => return Err(syntax("the counts overflow".to_owned())),
        }
        let (nv, nt, nn) = (nv as usize, nt as usize, nn as usize);
        let vertices: Vec<Point3<f64>> = (0..nv)
            .map(|_| Ok(Point3::new(r.f64()?, r.f64()?, r.f64()?)))
            .collect::<Result<_, Error>>()?;
        let triangles: Vec<[u32; 3]> = (0..nt)
            .map(|_| Ok([r.u32()?, r.u32()?, r.u32()?]))
            .collect::<Result<_, Error>>()?;
        let nodes: Vec<BvhNode> = (0..nn)
            .map(|_| {
                Ok(BvhNode {
                    bounds: crate::bounding::Aabb::EMPTY,
                    start: r.u32()?,
                    count: r.u32()?,
                })
            })
            .collect::<Result<_, Error>>()?;
        let order: Vec<u32> = (0..nt).map(|_| r.u32()).collect::<Result<_, Error>>()?;
        let mesh = TriMesh::checked(NAME, vertices, triangles)?;
        check_shape(&nodes, &order)?;
        let bvh = Bvh::from_checked_shape(nodes, order, mesh.vertices(), mesh.triangles());
        let extent = extent(&mesh);
        Ok(Collider {
            mesh,
            bvh: OnceLock::from(bvh),
            strategy: BuildStrategy::default(),
            boxes32: OnceLock::new(),
            extent,
            pose_tree: OnceLock::new(),
            sides: OnceLock::new(),
            mode,
        })
    }
}

fn syntax(message: String) -> Error {
    Error::Syntax {
        at: Location::file(NAME),
        message,
    }
}

/// The checks [`Bvh::from_checked_shape`] relies on: a tree rooted at node 0 whose children come
/// after their parent, every node reached once, leaves of 1 to [`MAX_LEAF`] positions that cover
/// every position of `order` once, and `order` a permutation of the triangles.
fn check_shape(nodes: &[BvhNode], order: &[u32]) -> Result<(), Error> {
    let n = order.len();
    let mut seen = vec![false; n];
    for (k, &t) in order.iter().enumerate() {
        match seen.get_mut(t as usize) {
            Some(s) if !*s => *s = true,
            _ => {
                return Err(syntax(format!(
                    "leaf order position {k}: triangle {t} is out of range or repeated"
                )))
            }
        }
    }
    if nodes.is_empty() {
        return Err(syntax("the tree has no node".to_owned()));
    }
    let mut reached = vec![false; nodes.len()];
    let mut covered = vec![false; n];
    let mut stack = vec![0usize];
    while let Some(i) = stack.pop() {
        if std::mem::replace(&mut reached[i], true) {
            return Err(syntax(format!("node {i} is reached twice")));
        }
        let node = nodes[i];
        let (start, count) = (node.start as usize, node.count as usize);
        if node.is_leaf() {
            if count > MAX_LEAF || start.checked_add(count).is_none_or(|end| end > n) {
                return Err(syntax(format!(
                    "node {i}: leaf of {count} triangles from position {start} does not fit (at most {MAX_LEAF}, {n} positions)"
                )));
            }
            for (p, c) in covered[start..start + count].iter_mut().enumerate() {
                if std::mem::replace(c, true) {
                    return Err(syntax(format!(
                        "node {i}: position {} is in two leaves",
                        start + p
                    )));
                }
            }
        } else {
            if start <= i || start + 1 >= nodes.len() {
                return Err(syntax(format!(
                    "node {i}: children {start} and {} are not after it or out of range ({} nodes)",
                    start + 1,
                    nodes.len()
                )));
            }
            stack.push(start);
            stack.push(start + 1);
        }
    }
    if let Some(i) = reached.iter().position(|r| !r) {
        return Err(syntax(format!("node {i} is not in the tree")));
    }
    if let Some(p) = covered.iter().position(|c| !c) {
        return Err(syntax(format!(
            "position {p} of the leaf order is in no leaf"
        )));
    }
    Ok(())
}

/// A cursor over the bytes; running out is [`Error::Truncated`].
struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    fn take(&mut self, n: usize, what: &str) -> Result<&'a [u8], Error> {
        match self
            .at
            .checked_add(n)
            .filter(|&end| end <= self.bytes.len())
        {
            Some(end) => {
                let s = &self.bytes[self.at..end];
                self.at = end;
                Ok(s)
            }
            None => Err(Error::Truncated {
                at: Location::byte(NAME, self.at),
                expected: what.to_owned(),
            }),
        }
    }

    fn array<const N: usize>(&mut self, what: &str) -> Result<[u8; N], Error> {
        let mut a = [0u8; N];
        a.copy_from_slice(self.take(N, what)?);
        Ok(a)
    }

    fn count(&mut self, what: &str) -> Result<u64, Error> {
        Ok(u64::from_le_bytes(self.array(what)?))
    }

    fn f64(&mut self) -> Result<f64, Error> {
        Ok(f64::from_le_bytes(self.array("a vertex coordinate")?))
    }

    fn u32(&mut self) -> Result<u32, Error> {
        Ok(u32::from_le_bytes(self.array("an index")?))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::collider::pose_from_degrees;
    use nalgebra::Isometry3;

    fn bunny() -> Collider {
        Collider::new(
            TriMesh::load(concat!(env!("CARGO_MANIFEST_DIR"), "/data/bunny.obj")).unwrap(),
        )
    }

    #[test]
    fn round_trip_keeps_the_tree_and_the_answers() {
        let a = bunny();
        let bytes = a.to_bytes();
        let b = Collider::from_bytes(&bytes).unwrap();
        assert_eq!(b.mesh(), a.mesh());
        assert_eq!(b.bvh().nodes(), a.bvh().nodes());
        assert_eq!(b.bvh().order(), a.bvh().order());
        assert_eq!(b.mode(), a.mode());
        assert_eq!(b.to_bytes(), bytes);
        let brute = Collider::from_bytes(&a.clone().with_mode(Mode::Brute).to_bytes()).unwrap();
        assert_eq!(brute.mode(), Mode::Brute);
        let here = Isometry3::identity();
        for k in 0..24 {
            let k = f64::from(k);
            let pose =
                pose_from_degrees([7.0 * k, 11.0 * k, 3.0 * k], [0.4 * k - 4.0, 0.3, -0.1 * k]);
            assert_eq!(
                b.collides_at(&here, &a, &pose).unwrap(),
                a.collides_at(&here, &a, &pose).unwrap()
            );
            assert_eq!(
                b.distance_at(&here, &a, &pose).unwrap(),
                a.distance_at(&here, &a, &pose).unwrap()
            );
        }
    }

    #[test]
    fn bad_bytes_are_errors_never_panics() {
        let cube =
            Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 2.0, 3.0)).unwrap());
        let bytes = cube.to_bytes();
        for len in 0..bytes.len() {
            assert!(
                Collider::from_bytes(&bytes[..len]).is_err(),
                "truncated to {len}"
            );
        }
        let mut longer = bytes.clone();
        longer.push(0);
        assert!(Collider::from_bytes(&longer).is_err());
        // every single-bit change is refused or gives a collider whose boxes hold its mesh
        for i in 0..bytes.len() {
            for bit in 0..8 {
                let mut b = bytes.clone();
                b[i] ^= 1 << bit;
                if let Ok(c) = Collider::from_bytes(&b) {
                    let placed = c.placed(&Isometry3::identity()).unwrap();
                    assert_eq!(c.collides(&placed), placed.collides(&c));
                }
            }
        }
        let err = Collider::from_bytes(b"not a collider at all").unwrap_err();
        assert!(
            err.to_string().contains("not a serialized collider"),
            "{err}"
        );
    }

    #[test]
    fn bad_shapes_are_refused() {
        let cube =
            Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0)).unwrap());
        let nodes = cube.bvh().nodes().to_vec();
        let order = cube.bvh().order().to_vec();
        assert!(check_shape(&nodes, &order).is_ok());
        let mut o = order.clone();
        o[1] = o[0];
        assert!(check_shape(&nodes, &o)
            .unwrap_err()
            .to_string()
            .contains("repeated"));
        let mut cyclic = nodes.clone();
        let inner = cyclic.iter().position(|n| !n.is_leaf()).unwrap();
        cyclic[inner].start = inner as u32;
        assert!(check_shape(&cyclic, &order).is_err());
        assert!(check_shape(&[], &order).is_err());
    }
}
