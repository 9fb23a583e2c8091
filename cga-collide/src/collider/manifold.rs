//! Contact manifolds of two meshes: one [`ContactManifold`] per contact region, its points
//! taken from the exact intersection of the surfaces.
//! The definitions are on [`Collider::contact_manifolds`].

use std::collections::HashMap;

use ga_core::scalar::{rational_from_f64, Real};
use nalgebra::{Isometry3, Point3, Vector3};

use crate::collider::Collider;
use crate::error::Error;
use crate::query::shapes::manifold::keep_four;
use crate::query::{ContactGeometry, ContactManifold, ExactPoint, ManifoldPoint};

/// Union–find over the contacts.
struct Groups(Vec<usize>);

impl Groups {
    fn find(&mut self, mut i: usize) -> usize {
        while self.0[i] != i {
            self.0[i] = self.0[self.0[i]];
            i = self.0[i];
        }
        i
    }

    fn join(&mut self, i: usize, j: usize) {
        let (a, b) = (self.find(i), self.find(j));
        // The smaller index is the root, so groups are found in a deterministic order.
        if a < b {
            self.0[b] = a;
        } else {
            self.0[a] = b;
        }
    }
}

/// The exact point rounded, with the proved distance from the rounded point to it.
fn rounded(p: &ExactPoint) -> (Point3<f64>, f64) {
    let x = p.clone().map(|c| c.to_f64());
    let mut sum = 0.0;
    for (k, c) in p.iter().enumerate() {
        let err = rational_from_f64(x[k]).map_or(f64::INFINITY, |r| (r - c).to_f64().abs());
        sum += err * err;
    }
    // Each error is converted and squared with a relative error below 2⁻⁵⁰: a margin of 2⁻⁴⁰
    // covers every rounding of this bound.
    let bound = if sum == 0.0 {
        0.0
    } else {
        (sum.sqrt() * (1.0 + 2f64.powi(-40))).next_up()
    };
    (Point3::from(x), bound)
}

fn corners(g: &ContactGeometry) -> Vec<&ExactPoint> {
    match g {
        ContactGeometry::Point(p) => vec![p],
        ContactGeometry::Segment(p, q) => vec![p, q],
        ContactGeometry::Polygon(ps) => ps.iter().collect(),
    }
}

fn key(p: &Point3<f64>) -> [u64; 3] {
    // `+ 0.0` makes −0 and +0 one key.
    [p.x, p.y, p.z].map(|c| (c + 0.0).to_bits())
}

impl Collider {
    /// The contact manifolds of `self` and `other` in one frame: one per contact region, empty
    /// when the surfaces do not meet.
    ///
    ///
    /// # Definition
    /// * **Region**: a connected group of intersecting triangle pairs. Two pairs are connected
    ///   when their exact intersections share a point (compared rounded to `f64`): the pieces of
    ///   one intersection curve join end to end, so a region is one connected piece of the
    ///   intersection of the two surfaces (two blocks standing on one big triangle are two
    ///   regions). Regions are ordered by their first triangle pair.
    /// * **Points**: the corners of the exact intersection of every triangle pair of the region
    ///   (segment ends, touching points, corners of coplanar overlaps), rounded to `f64`; each lies
    ///   on both surfaces, so `point_a = point_b = point` and `distance = 0`. `error_bound` is the
    ///   proved distance from the rounded point to the exact one, which is on the intersection of
    ///   the two surfaces. At most [`MAX_POINTS_PER_REGION`](crate::query::MAX_POINTS_PER_REGION) are kept, by the shapes' rule (the
    ///   first point, the farthest from it across the normal, the largest triangle, the farthest
    ///   outside it).
    /// * **Normal**, from `a` to `b`: the area-weighted normals of the region's triangles of `a`
    ///   minus those of `b` (each triangle once, its normal by its corner order: outward for
    ///   counter-clockwise meshes), normalised; rounded and not certified. When that sum is zero,
    ///   `a`'s triangles alone, then `+z`.
    ///
    /// `signed_distance` is `None` (a mesh's depth per region is not defined here);
    /// `triangle_pairs` lists the region's pairs. Everything is deterministic.
    ///
    /// ```
    /// use cga_collide::{nalgebra::{Isometry3, Point3}, Collider, TriMesh};
    /// let cube = Collider::new(TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?);
    /// let sunk = cube.placed(&Isometry3::translation(0.25, 0.25, 0.75))?;
    /// let regions = cube.contact_manifolds(&sunk);
    /// assert_eq!(regions.len(), 1);
    /// assert!(regions[0].points.len() <= 4);
    /// // Every intersecting triangle counts with its whole area, so here the side faces tilt
    /// // the (uncertified) normal away from +z: a unit vector pointing up and out.
    /// let n = regions[0].normal;
    /// assert!((n.norm() - 1.0).abs() < 1e-12 && n.x > 0.0 && n.y > 0.0 && n.z > 0.0);
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn contact_manifolds(&self, other: &Collider) -> Vec<ContactManifold> {
        let contacts = self.contacts(other);
        let mut groups = Groups((0..contacts.len()).collect());
        let mut seen: HashMap<[u64; 3], usize> = HashMap::new();
        let mut link = |groups: &mut Groups, k: [u64; 3], i: usize| match seen.get(&k) {
            Some(&j) => groups.join(i, j),
            None => {
                seen.insert(k, i);
            }
        };
        let mut points: Vec<Vec<(Point3<f64>, f64)>> = Vec::with_capacity(contacts.len());
        for (i, (_, g)) in contacts.iter().enumerate() {
            let ps: Vec<(Point3<f64>, f64)> = corners(g).into_iter().map(rounded).collect();
            for (p, _) in &ps {
                link(&mut groups, key(p), i);
            }
            points.push(ps);
        }
        let mut regions: Vec<Vec<usize>> = Vec::new();
        let mut region_of: HashMap<usize, usize> = HashMap::new();
        for i in 0..contacts.len() {
            let root = groups.find(i);
            let r = *region_of.entry(root).or_insert_with(|| {
                regions.push(Vec::new());
                regions.len() - 1
            });
            regions[r].push(i);
        }
        regions
            .into_iter()
            .map(|members| self.region(other, &contacts, &points, &members))
            .collect()
    }

    /// One region's manifold.
    fn region(
        &self,
        other: &Collider,
        contacts: &[((u32, u32), ContactGeometry)],
        points: &[Vec<(Point3<f64>, f64)>],
        members: &[usize],
    ) -> ContactManifold {
        let pairs: Vec<(u32, u32)> = members.iter().map(|&i| contacts[i].0).collect();
        let normal = region_normal(self, other, &pairs);
        let mut unique: Vec<(Point3<f64>, f64)> = Vec::new();
        let mut at: HashMap<[u64; 3], usize> = HashMap::new();
        for &i in members {
            for &(p, e) in &points[i] {
                match at.get(&key(&p)) {
                    Some(&k) => unique[k].1 = unique[k].1.max(e),
                    None => {
                        at.insert(key(&p), unique.len());
                        unique.push((p, e));
                    }
                }
            }
        }
        let where_: Vec<Point3<f64>> = unique.iter().map(|(p, _)| *p).collect();
        let kept = keep_four(&where_, &vec![0.0; where_.len()], &normal);
        ContactManifold {
            normal,
            points: kept
                .into_iter()
                .map(|k| ManifoldPoint {
                    point: unique[k].0,
                    point_a: unique[k].0,
                    point_b: unique[k].0,
                    distance: 0.0,
                    error_bound: unique[k].1,
                })
                .collect(),
            signed_distance: None,
            triangle_pairs: pairs,
        }
    }

    /// [`contact_manifolds`](Self::contact_manifolds) of `self` at `pose_a` and `other` at
    /// `pose_b`, in world coordinates (the meshes are placed first, as for
    /// [`contacts_at`](Self::contacts_at)).
    pub fn contact_manifolds_at(
        &self,
        pose_a: &Isometry3<f64>,
        other: &Collider,
        pose_b: &Isometry3<f64>,
    ) -> Result<Vec<ContactManifold>, Error> {
        let (a, b) = self.placed_pair(pose_a, other, pose_b)?;
        Ok(a.contact_manifolds(&b))
    }
}

/// Twice the area times the unit normal of triangle `t` of `c` (by its corner order).
fn area_normal(c: &Collider, t: u32) -> Vector3<f64> {
    let [p, q, r] = c.mesh.corners(t);
    (q - p).cross(&(r - p))
}

fn region_normal(a: &Collider, b: &Collider, pairs: &[(u32, u32)]) -> Vector3<f64> {
    let mut ta: Vec<u32> = pairs.iter().map(|p| p.0).collect();
    let mut tb: Vec<u32> = pairs.iter().map(|p| p.1).collect();
    ta.sort_unstable();
    ta.dedup();
    tb.sort_unstable();
    tb.dedup();
    let sa: Vector3<f64> = ta.iter().map(|&t| area_normal(a, t)).sum();
    let sb: Vector3<f64> = tb.iter().map(|&t| area_normal(b, t)).sum();
    [sa - sb, sa]
        .into_iter()
        .find_map(|v| {
            let m = v.amax();
            (m > 0.0 && m.is_finite()).then(|| (v / m).normalize())
        })
        .unwrap_or_else(Vector3::z)
}
