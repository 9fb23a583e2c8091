//! Which side of each triangle of a mesh is outside its solid (the even–odd rule of
//! [`Collider::contains_point`]), where that is the same all over a connected part of the
//! mesh, so that the signed distance of a point can take its sign from the nearest face.
//!
//! The side is known for the triangles of a connected component (triangles joined by shared
//! edges) when the whole mesh is a closed, consistently oriented surface without
//! self-intersections: every directed edge `(a, b)` is used by exactly one triangle and its
//! reverse `(b, a)` by exactly one other, and no two triangles meet anywhere but in what they
//! share ([`Collider::self_intersects`], exact). Then crossing the component flips the parity of
//! every ray at each of its faces, and the other components, which it does not cross, add a
//! constant; so "the side the normal `(b − a) × (c − a)` points to is outside" is one answer for
//! the whole component. That answer is found once per component with one probe point: a point
//! off one of its faces whose nearest triangle is proved unique, whose side of that triangle is
//! an exact `orient3d` sign and whose inside/outside is the exact ray test. Components no probe
//! settles (none of a few tries certified) stay unknown, as does everything on other meshes:
//! their points take the exact ray test.

use std::cmp::Ordering;
use std::collections::HashMap;

use nalgebra::Point3;

use crate::collider::signed_distance::Scratch;
use crate::collider::Collider;
use crate::exact::{ExactKernel, Kernel};

/// Probe faces tried per component before it is left unknown.
const PROBES: usize = 8;

/// For each triangle: `1` when the side its normal points to is outside, `-1` when it is
/// inside, `0` when unknown.
#[derive(Debug, Clone, Default)]
pub(crate) struct SolidSides {
    outward: Vec<i8>,
}

impl SolidSides {
    /// `1`, `-1` or `0` for triangle `t` (see the type).
    #[inline]
    pub(crate) fn of(&self, t: u32) -> i8 {
        self.outward.get(t as usize).copied().unwrap_or(0)
    }

    /// Every triangle unknown.
    fn unknown(n: usize) -> SolidSides {
        SolidSides {
            outward: vec![0; n],
        }
    }

    /// How many triangles have a known side (for tests and reports).
    #[cfg(test)]
    pub(crate) fn known(&self) -> usize {
        self.outward.iter().filter(|&&s| s != 0).count()
    }

    /// The sides of the triangles of `collider`'s mesh (see the module docs).
    pub(crate) fn find(collider: &Collider) -> SolidSides {
        let mesh = collider.mesh();
        let n = mesh.num_triangles();
        let Some(component) = oriented_components(mesh.triangles()) else {
            return Self::unknown(n);
        };
        if collider.self_intersects() {
            return Self::unknown(n);
        }
        let components = component.iter().map(|&c| c as usize + 1).max().unwrap_or(0);
        // Triangles of each component, largest (by f64 area) first: the best probes.
        let mut members: Vec<Vec<u32>> = vec![Vec::new(); components];
        for (t, &c) in component.iter().enumerate() {
            members[c as usize].push(t as u32);
        }
        let area2 = |t: u32| {
            let [a, b, c] = collider.corners(t);
            let n = normal(&[a, b, c]);
            n[0] * n[0] + n[1] * n[1] + n[2] * n[2]
        };
        let mut side_of_component = vec![0i8; components];
        for list in &mut members {
            list.sort_by(|&x, &y| area2(y).total_cmp(&area2(x)).then(x.cmp(&y)));
        }
        for c in 0..components {
            if side_of_component[c] != 0 {
                continue;
            }
            for &t in members[c].iter().take(PROBES) {
                if let Some((found, outward)) = probe(collider, t) {
                    let fc = component[found as usize] as usize;
                    side_of_component[fc] = outward;
                    if fc == c {
                        break;
                    }
                }
            }
        }
        SolidSides {
            outward: component
                .iter()
                .map(|&c| side_of_component[c as usize])
                .collect(),
        }
    }
}

/// `(b − a) × (c − a)` in `f64`.
fn normal(t: &[[f64; 3]; 3]) -> [f64; 3] {
    let u = [t[1][0] - t[0][0], t[1][1] - t[0][1], t[1][2] - t[0][2]];
    let v = [t[2][0] - t[0][0], t[2][1] - t[0][1], t[2][2] - t[0][2]];
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

/// A probe off triangle `t`: a point a little way along its normal. When the point's nearest
/// triangle `found` is proved unique and the point is strictly off its plane, returns `found`
/// and whether `found`'s normal side is outside (`1`) or inside (`-1`), from the exact ray test.
fn probe(collider: &Collider, t: u32) -> Option<(u32, i8)> {
    let corners = collider.corners(t);
    let n = normal(&corners);
    let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if !(len > 0.0 && len.is_finite()) {
        return None;
    }
    // A step of a thousandth of the triangle's size: nearest to this face unless another part
    // of the surface comes that close (then the certificate fails and another face is tried).
    let step = 1e-3 * (0.5 * len).sqrt() / len;
    let q: [f64; 3] = std::array::from_fn(|k| {
        (corners[0][k] + corners[1][k] + corners[2][k]) / 3.0 + n[k] * step
    });
    let near = collider.nearest_certified(&q, &mut Scratch::default())?;
    if !near.unique {
        return None;
    }
    let [a, b, c] = collider.corners(near.triangle);
    let side = ExactKernel::orient3d(&a, &b, &c, &q);
    let inside = collider.contains_point(&Point3::from(q));
    match side {
        Ordering::Greater => Some((near.triangle, if inside { -1 } else { 1 })),
        Ordering::Less => Some((near.triangle, if inside { 1 } else { -1 })),
        Ordering::Equal => None,
    }
}

/// The connected component of each triangle (joined by shared edges), when every directed edge
/// is used once and its reverse once (a closed surface, consistently oriented, each edge on two
/// triangles); `None` otherwise (degenerate index triples included).
fn oriented_components(triangles: &[[u32; 3]]) -> Option<Vec<u32>> {
    let mut directed: HashMap<(u32, u32), u32> = HashMap::with_capacity(triangles.len() * 3);
    for (i, t) in triangles.iter().enumerate() {
        for k in 0..3 {
            let (a, b) = (t[k], t[(k + 1) % 3]);
            if a == b || directed.insert((a, b), i as u32).is_some() {
                return None;
            }
        }
    }
    let mut parent: Vec<u32> = (0..triangles.len() as u32).collect();
    fn root(parent: &mut [u32], mut x: u32) -> u32 {
        while parent[x as usize] != x {
            let up = parent[parent[x as usize] as usize];
            parent[x as usize] = up;
            x = up;
        }
        x
    }
    for (&(a, b), &i) in &directed {
        let j = *directed.get(&(b, a))?;
        let (ri, rj) = (root(&mut parent, i), root(&mut parent, j));
        if ri != rj {
            parent[ri.max(rj) as usize] = ri.min(rj);
        }
    }
    // Number the components densely, in order of their first triangle.
    let mut label: HashMap<u32, u32> = HashMap::new();
    let mut out = Vec::with_capacity(triangles.len());
    for t in 0..triangles.len() as u32 {
        let r = root(&mut parent, t);
        let next = label.len() as u32;
        out.push(*label.entry(r).or_insert(next));
    }
    Some(out)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TriMesh;

    #[test]
    fn a_cube_is_one_outward_component() {
        let cube = TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0)).unwrap();
        let c = Collider::new(cube.clone());
        let sides = SolidSides::find(&c);
        assert_eq!(sides.known(), 12);
        // Flip every triangle: every normal points inside.
        let flipped: Vec<[u32; 3]> = cube
            .triangles()
            .iter()
            .map(|t| [t[0], t[2], t[1]])
            .collect();
        let f = Collider::new(TriMesh::new(cube.vertices().to_vec(), flipped).unwrap());
        let fs = SolidSides::find(&f);
        for t in 0..12 {
            assert_eq!(sides.of(t), -fs.of(t));
        }
    }

    #[test]
    fn open_or_inconsistent_meshes_are_unknown() {
        let cube = TriMesh::cuboid(Point3::origin(), Point3::new(1.0, 1.0, 1.0)).unwrap();
        let mut tris = cube.triangles().to_vec();
        tris.pop();
        let open = Collider::new(TriMesh::new(cube.vertices().to_vec(), tris.clone()).unwrap());
        assert_eq!(SolidSides::find(&open).known(), 0);
        let mut bad = cube.triangles().to_vec();
        bad[0] = [bad[0][0], bad[0][2], bad[0][1]];
        let mixed = Collider::new(TriMesh::new(cube.vertices().to_vec(), bad).unwrap());
        assert_eq!(SolidSides::find(&mixed).known(), 0);
    }
}
