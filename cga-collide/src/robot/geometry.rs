//! A link's collision geometry: meshes (through built [`Collider`]s, loaded once per file and
//! scale) and primitives (through [`Shape`]), each with its pose in the link's frame; where
//! they are at a configuration (placed by the crate's one placement rule, with a conservative
//! world box); and the exact test of two placed parts.

use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use nalgebra::{Isometry3, Point3, Vector3};

use super::obb::Obb;
use super::urdf::{model_error, CollisionSpec, GeometrySpec};
use crate::bounding::shape_box::shape_box;
use crate::bounding::Aabb;
use crate::collider::{Bounded, Collider};
use crate::error::Error;
use crate::query::{self, CertifiedDistance};
use crate::shape::{Ball, Capsule, Cuboid, Cylinder, Shape, TriMesh};

/// What a part is made of.
#[derive(Debug, Clone)]
pub(super) enum Geometry {
    /// A mesh (its surface, or its solid when the robot is set solid).
    Mesh(Arc<Collider>),
    /// A solid primitive in the part's frame.
    Shape(Shape),
}

/// One collision element of a link.
#[derive(Debug, Clone)]
pub(super) struct Part {
    pub link: usize,
    /// The element's pose in its link's frame.
    pub local: Isometry3<f64>,
    pub geometry: Geometry,
}

/// A part at a configuration: its world pose, the placed shape (primitives) and a world box
/// holding the placed geometry (rounded outwards: no touching pair is dropped by it).
#[derive(Debug, Clone)]
pub(super) struct Placed {
    pub pose: Isometry3<f64>,
    pub shape: Option<Shape>,
    pub bbox: Aabb,
    /// A mesh's own box in its pose, or a primitive's world box (`None` when unbounded).
    pub obb: Option<Obb>,
}

impl Placed {
    /// Whether the two are proved farther apart than `c` by their boxes (conservative).
    pub fn apart(&self, o: &Placed, c: f64) -> bool {
        if !boxes_within(&self.bbox, &o.bbox, c) {
            return true;
        }
        match (&self.obb, &o.obb) {
            (Some(a), Some(b)) => a.apart(b, c),
            _ => false,
        }
    }
}

/// Loads meshes once per (file, scale) and resolves `package://` paths.
pub(super) struct Loader<'a> {
    pub base_dir: &'a Path,
    pub package_dirs: &'a [PathBuf],
    pub cache: HashMap<(PathBuf, [u64; 3]), Arc<Collider>>,
}

impl Loader<'_> {
    /// The file a URDF `filename` names: `package://PKG/REST` is `DIR/PKG/REST` (or `DIR/REST`
    /// when `DIR` is the package itself) for the first caller-given `DIR` where it exists;
    /// `file://PATH` is `PATH`; any other path is relative to the URDF's folder.
    fn resolve(&self, filename: &str, at: &str) -> Result<PathBuf, Error> {
        if let Some(rest) = filename.strip_prefix("package://") {
            let (package, inner) = rest.split_once('/').unwrap_or((rest, ""));
            for dir in self.package_dirs {
                let candidates = [dir.join(package).join(inner), dir.join(inner)];
                let own = dir.file_name().is_some_and(|n| n == package);
                for (k, path) in candidates.iter().enumerate() {
                    if (k == 0 || own) && path.is_file() {
                        return Ok(path.clone());
                    }
                }
            }
            let dirs: Vec<String> = self
                .package_dirs
                .iter()
                .map(|d| d.display().to_string())
                .collect();
            return Err(model_error(
                at.to_string(),
                format!(
                    "cannot find {filename:?} in the package directories [{}]: give the \
                     directory that holds the package `{package}`",
                    dirs.join(", ")
                ),
            ));
        }
        let path = match filename.strip_prefix("file://") {
            Some(p) => PathBuf::from(p),
            None => self.base_dir.join(filename),
        };
        if path.is_file() {
            Ok(path)
        } else {
            Err(model_error(
                at.to_string(),
                format!("mesh file {} not found", path.display()),
            ))
        }
    }

    fn mesh(&mut self, filename: &str, scale: [f64; 3], at: &str) -> Result<Arc<Collider>, Error> {
        let path = self.resolve(filename, at)?;
        let key = (path.clone(), scale.map(f64::to_bits));
        if let Some(c) = self.cache.get(&key) {
            return Ok(c.clone());
        }
        let wrap = |e: Error| model_error(at.to_string(), format!("mesh {filename:?}: {e}"));
        let mesh = TriMesh::load(&path).map_err(wrap)?;
        let mesh = if scale == [1.0; 3] {
            mesh
        } else {
            let s = Vector3::from(scale);
            let vertices = mesh
                .vertices()
                .iter()
                .map(|v| Point3::from(v.coords.component_mul(&s)))
                .collect();
            TriMesh::new(vertices, mesh.triangles().to_vec()).map_err(wrap)?
        };
        let collider = Arc::new(Collider::new(mesh));
        self.cache.insert(key, collider.clone());
        Ok(collider)
    }

    /// The part a `<collision>` element describes.
    pub fn part(&mut self, link: usize, spec: &CollisionSpec) -> Result<Part, Error> {
        let wrap = |e: Error| model_error(spec.at.clone(), e.to_string());
        let o = Point3::origin();
        let geometry = match &spec.geometry {
            GeometrySpec::Box(size) => Geometry::Shape(
                Cuboid::axis_aligned(o, Vector3::from(*size) / 2.0)
                    .map_err(wrap)?
                    .into(),
            ),
            GeometrySpec::Cylinder { radius, length } => {
                let h = length / 2.0;
                Geometry::Shape(
                    Cylinder::new(Point3::new(0.0, 0.0, -h), Point3::new(0.0, 0.0, h), *radius)
                        .map_err(wrap)?
                        .into(),
                )
            }
            GeometrySpec::Capsule { radius, length } => {
                let h = length / 2.0;
                Geometry::Shape(
                    Capsule::new(Point3::new(0.0, 0.0, -h), Point3::new(0.0, 0.0, h), *radius)
                        .map_err(wrap)?
                        .into(),
                )
            }
            GeometrySpec::Sphere(r) => Geometry::Shape(Ball::new(o, *r).map_err(wrap)?.into()),
            GeometrySpec::Mesh { filename, scale } => {
                Geometry::Mesh(self.mesh(filename, *scale, &spec.at)?)
            }
        };
        Ok(Part {
            link,
            local: spec.origin,
            geometry,
        })
    }
}

/// Places a geometry by a world pose.
pub(super) fn place(geometry: &Geometry, pose: Isometry3<f64>) -> Result<Placed, Error> {
    Ok(match geometry {
        Geometry::Mesh(c) => Placed {
            pose,
            shape: None,
            bbox: c.world_box(&pose)?,
            obb: Some(Obb::new(&c.bvh().bounds(), &pose)),
        },
        Geometry::Shape(s) => {
            let placed = s.placed(&pose)?;
            let bbox = shape_box(&placed);
            let bounded = bbox.min.iter().chain(&bbox.max).all(|x| x.is_finite());
            Placed {
                obb: bounded.then(|| Obb::new(&bbox, &Isometry3::identity())),
                bbox,
                shape: Some(placed),
                pose,
            }
        }
    })
}

/// A lower bound on the distance between two boxes (0 when they overlap): each axis gap is
/// computed in `f64` and the sum shrunk by a relative margin far above its rounding error.
pub(super) fn box_gap_lower(a: &Aabb, b: &Aabb) -> f64 {
    let mut sum = 0.0;
    for k in 0..3 {
        let gap = (a.min[k] - b.max[k]).max(b.min[k] - a.max[k]).max(0.0);
        sum += gap * gap;
    }
    let d = sum.sqrt() * (1.0 - 1e-9);
    if d.is_finite() {
        d
    } else {
        0.0
    }
}

/// Whether two boxes may hold points within `c` of each other (conservative).
pub(super) fn boxes_within(a: &Aabb, b: &Aabb, c: f64) -> bool {
    if c == 0.0 {
        return a.overlaps(b);
    }
    box_gap_lower(a, b) <= c
}

/// The exact answers for two placed parts: `a` is `(geometry, placed)`.
pub(super) struct PairTest<'a> {
    pub a: (&'a Geometry, &'a Placed),
    pub b: (&'a Geometry, &'a Placed),
    pub solid: bool,
}

fn swapped(d: CertifiedDistance) -> CertifiedDistance {
    CertifiedDistance {
        witness_a: d.witness_b,
        witness_b: d.witness_a,
        triangles: d.triangles.map(|(i, j)| (j, i)),
        ..d
    }
}

/// A capsule holding a cylinder or a cone (the same axis points and radius): its exact tests
/// are much cheaper than theirs, and when it is apart, so are they.
fn enclosing_capsule(s: &Shape) -> Option<Shape> {
    let capsule = match s {
        Shape::Cylinder(c) => Capsule::new(*c.a(), *c.b(), c.radius()),
        Shape::Cone(c) => Capsule::new(*c.apex(), *c.base(), c.radius()),
        _ => return None,
    };
    capsule.ok().map(Shape::from)
}

impl PairTest<'_> {
    /// `Some(false)` when the pair, with its cylinders and cones grown to their enclosing
    /// capsules, is proved not to pass `test` (so the pair itself does not); `None` when
    /// there is nothing to grow or the grown pair may pass.
    fn grown_apart(
        &self,
        test: impl Fn(&PairTest) -> Result<bool, Error>,
    ) -> Result<Option<bool>, Error> {
        let ((ga, pa), (gb, pb)) = (self.a, self.b);
        let grow = |p: &Placed| p.shape.as_ref().and_then(enclosing_capsule);
        let (ca, cb) = (grow(pa), grow(pb));
        if ca.is_none() && cb.is_none() {
            return Ok(None);
        }
        let with = |p: &Placed, c: Option<Shape>| Placed {
            shape: c.or_else(|| p.shape.clone()),
            ..p.clone()
        };
        let (wa, wb) = (with(pa, ca), with(pb, cb));
        let grown = PairTest {
            a: (ga, &wa),
            b: (gb, &wb),
            solid: self.solid,
        };
        // A pair the grown shapes cannot answer is left to the exact test of the pair itself.
        Ok(match test(&grown) {
            Ok(false) => Some(false),
            _ => None,
        })
    }

    /// Do they touch (surfaces of meshes, or solids when `solid`; primitives are solids)?
    pub fn touches(&self) -> Result<bool, Error> {
        if let Some(answer) = self.grown_apart(|t| t.touches_exactly())? {
            return Ok(answer);
        }
        self.touches_exactly()
    }

    fn touches_exactly(&self) -> Result<bool, Error> {
        let ((ga, pa), (gb, pb)) = (self.a, self.b);
        match (ga, gb, &pa.shape, &pb.shape) {
            (Geometry::Mesh(a), Geometry::Mesh(b), _, _) => {
                if self.solid {
                    a.collides_solid_at(&pa.pose, b, &pb.pose)
                } else {
                    a.collides_at(&pa.pose, b, &pb.pose)
                }
            }
            (Geometry::Mesh(m), _, _, Some(s)) | (_, Geometry::Mesh(m), Some(s), _) => {
                let pose = if pa.shape.is_none() {
                    &pa.pose
                } else {
                    &pb.pose
                };
                let id = Isometry3::identity();
                if self.solid {
                    m.intersects_shape_solid_at(pose, s, &id)
                } else {
                    m.intersects_shape_at(pose, s, &id)
                }
            }
            (_, _, Some(a), Some(b)) => query::intersects(a, b),
            _ => unreachable_pair(),
        }
    }

    /// Are they within distance `c` (exact, closed)?
    pub fn within(&self, c: f64) -> Result<bool, Error> {
        if let Some(answer) = self.grown_apart(|t| t.within_exactly(c))? {
            return Ok(answer);
        }
        self.within_exactly(c)
    }

    fn within_exactly(&self, c: f64) -> Result<bool, Error> {
        let ((ga, pa), (gb, pb)) = (self.a, self.b);
        match (ga, gb, &pa.shape, &pb.shape) {
            (Geometry::Mesh(a), Geometry::Mesh(b), _, _) => {
                a.within_distance_at(&pa.pose, b, &pb.pose, c)
            }
            (Geometry::Mesh(m), _, _, Some(s)) | (_, Geometry::Mesh(m), Some(s), _) => {
                let pose = if pa.shape.is_none() {
                    &pa.pose
                } else {
                    &pb.pose
                };
                m.shape_within_distance_at(pose, s, &Isometry3::identity(), c)
            }
            (_, _, Some(a), Some(b)) => query::within_distance(a, b, c),
            _ => unreachable_pair(),
        }
    }

    /// Their certified distance, witnesses in world coordinates (`witness_a` on `a`).
    pub fn distance(&self) -> Result<CertifiedDistance, Error> {
        let ((ga, pa), (gb, pb)) = (self.a, self.b);
        let id = Isometry3::identity();
        match (ga, gb, &pa.shape, &pb.shape) {
            (Geometry::Mesh(a), Geometry::Mesh(b), _, _) => a.distance_at(&pa.pose, b, &pb.pose),
            (Geometry::Mesh(m), _, _, Some(s)) => m.distance_to_shape_at(&pa.pose, s, &id),
            (_, Geometry::Mesh(m), Some(s), _) => {
                m.distance_to_shape_at(&pb.pose, s, &id).map(swapped)
            }
            (_, _, Some(a), Some(b)) => query::distance(a, b),
            _ => unreachable_pair(),
        }
    }
}

impl PairTest<'_> {
    /// Their certified distance (as [`distance`](Self::distance)) when they are nearer than
    /// `cutoff`; otherwise a proved lower bound on it. Meshes search with the cutoff from the
    /// start (nothing proved farther is examined); two primitives are first asked the
    /// filters' clearance question, so that a pair farther than `cutoff` is mostly answered
    /// without a distance.
    pub fn distance_below(&self, cutoff: f64) -> Result<Bounded, Error> {
        if cutoff.is_infinite() {
            return self.distance().map(Bounded::Below);
        }
        let ((ga, pa), (gb, pb)) = (self.a, self.b);
        let id = Isometry3::identity();
        match (ga, gb, &pa.shape, &pb.shape) {
            (Geometry::Mesh(a), Geometry::Mesh(b), _, _) => {
                a.distance_below_at(&pa.pose, b, &pb.pose, cutoff)
            }
            (Geometry::Mesh(m), _, _, Some(s)) => {
                m.distance_to_shape_below_at(&pa.pose, &s.placed(&id)?, cutoff)
            }
            (_, Geometry::Mesh(m), Some(s), _) => Ok(
                match m.distance_to_shape_below_at(&pb.pose, &s.placed(&id)?, cutoff)? {
                    Bounded::Below(d) => Bounded::Below(swapped(d)),
                    at_least => at_least,
                },
            ),
            (_, _, Some(a), Some(b)) => self.primitives_below(a, b, cutoff),
            _ => unreachable_pair(),
        }
    }

    /// [`distance_below`](Self::distance_below) of two primitives. A clearance the filters
    /// prove answers a pair proved farther than `cutoff` without a distance; otherwise the
    /// certified distance is measured rather than the exact clearance decided (between two
    /// cylinders that takes milliseconds, the distance microseconds). A distance whose lower
    /// end reaches `cutoff` is `AtLeast(cutoff)`; one whose bound straddles it is `Below`.
    fn primitives_below(&self, a: &Shape, b: &Shape, cutoff: f64) -> Result<Bounded, Error> {
        if query::shapes::within_distance_filtered(a, b, cutoff)? == Some(false) {
            return Ok(Bounded::AtLeast(cutoff));
        }
        match query::distance(a, b) {
            Ok(d) if d.distance - d.error_bound >= cutoff => Ok(Bounded::AtLeast(cutoff)),
            Ok(d) => Ok(Bounded::Below(d)),
            // No certified distance: the exact clearance still proves a farther pair apart.
            Err(e @ Error::UnsupportedPair { .. }) => match self.within(cutoff)? {
                false => Ok(Bounded::AtLeast(cutoff)),
                true => Err(e),
            },
            Err(e) => Err(e),
        }
    }
}

/// A placed primitive always carries its placed shape and a mesh never does, so the four
/// arms above cover every pair; this answer is never reached.
fn unreachable_pair<T>() -> Result<T, Error> {
    Err(Error::Configuration {
        reason: "internal: a placed part lost its shape".to_string(),
    })
}
