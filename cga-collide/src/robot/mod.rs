//! [`Robot`]: a kinematic tree read from a URDF, its links' collision geometry, and exact
//! answers about self- and environment collisions at any configuration.
//!
//! # Loading
//! [`Robot::from_urdf`] reads a URDF: every `<link>`'s `<collision>` elements (meshes in STL,
//! OBJ, PLY or OFF with their `scale`, through [`Collider`](crate::Collider)s built once per
//! file and scale; `<box>`, `<cylinder>`, `<sphere>` and `<capsule>` as the primitives
//! [`Cuboid`](crate::shape::Cuboid), [`Cylinder`](crate::shape::Cylinder),
//! [`Ball`](crate::Ball), [`Capsule`](crate::shape::Capsule)), each with its `<origin>`; and
//! every `<joint>` (revolute, continuous, prismatic, fixed) with its origin, axis and limits.
//! `package://PKG/PATH` is looked up as `DIR/PKG/PATH` in the directories the caller gives
//! (and as `DIR/PATH` when `DIR` is the package itself); other paths are relative to the URDF's
//! folder. `<visual>` elements are not read. Every error names the file, the line and the
//! element ([`Error::RobotModel`]).
//!
//! # Configurations
//! A configuration is one value per movable joint (revolute, continuous, prismatic), in the
//! order of [`Robot::joint_names`] (the URDF's order); a mimic joint is an independent joint
//! here. Limits are reported ([`Robot::joint_limits`]) but not enforced. Forward kinematics is
//! computed once per configuration: a link's pose is its parent's pose, then the joint's
//! origin, then the joint's motion (a rotation about the axis by `q`, or a translation along
//! it by `q`), all in `f64`. Each part is then placed by its world pose under the crate's one
//! placement rule ([`Shape::placed`](crate::shape::Shape::placed) for primitives, the
//! colliders' `_at` queries for meshes): every answer is exact for those placed parts.
//!
//! # Pairs
//! Links joined by fixed joints form one rigid body and are never tested against each other,
//! nor are two bodies joined by a joint (adjacent). Every other pair of links that have
//! collision geometry is tested, minus an SRDF's `<disable_collisions>`
//! ([`Robot::disable_from_srdf`]) and the caller's exclusions ([`Robot::exclude_pair`]);
//! [`Robot::allowed_pairs`] lists them. Pairs are named by link; an environment object
//! ([`Robot::set_environment`], a [`Scene`]) is named `env:<i>`, `i` its
//! [`ObjectId::index`](crate::scene::ObjectId::index).
//!
//! # What touching means
//! Primitives are solids. Meshes are **surfaces** by default, as in coal and pinocchio: two
//! meshes touch when their triangles meet, and a mesh wholly inside another (or a primitive
//! wholly inside a mesh) does not touch it. [`Robot::set_solid`] makes closed meshes solids.
//!
//! # Questions
//! | question | call | many configurations |
//! |---|---|---|
//! | does anything touch? (stops at the first pair) | [`Robot::collides`] | [`Robot::collides_batch`] |
//! | which link pairs touch? | [`Robot::colliding_pairs`] | [`Robot::colliding_pairs_batch`] |
//! | which pairs are within distance `c`? (exact, closed) | [`Robot::pairs_within_distance`] | [`Robot::pairs_within_distance_batch`] |
//! | which pair is nearest, how far, where? (certified) | [`Robot::nearest`] | [`Robot::nearest_batch`] |
//!
//! Each takes [`Against`]: the robot itself, its environment, or both. Cheap conservative
//! tests set pairs aside before the exact test: the world boxes of the placed parts, then
//! oriented boxes (a mesh's own box in its pose) on the 15 separating axes, with margins far
//! above their rounding; the batches spread configurations over the cores.
//!
//! # Motion
//! [`Robot::motion_collision`] checks the straight motion `q(t) = (1 - t) q0 + t q1`,
//! `t` in `[0, 1]`, between two configurations ([`Robot::motion_collision_batch`] for many):
//! [`MotionAnswer::Free`] is certified for every configuration of the motion, not only for
//! samples; [`MotionAnswer::Collides`] gives a configuration that collides (the exact test),
//! its time and how far before it the motion is certified free; [`MotionAnswer::Undecided`]
//! says that a budget of [`MotionOptions`] ran out first and how far the motion is certified
//! free. The motion is split in halves, earliest first; on each stretch every link gets a
//! bound on how far its points move from where they are at the stretch's middle (the sum,
//! over the movable joints above it, of the joint's change times the most its points can be
//! from the joint's axis point, whatever the joints between do, or the change itself for a
//! prismatic joint), and a pair whose parts are farther apart than the two bounds (the
//! exact, closed clearance test; cylinders and cones grown to capsules) cannot touch on the
//! stretch. Touching means what it means for the configuration questions (meshes are
//! surfaces unless [`Robot::set_solid`]).
//!
//! ```
//! use cga_collide::robot::{Against, MotionAnswer, MotionOptions, Robot};
//! let urdf = r#"<robot name="arm">
//!   <link name="base"><collision><geometry><box size="1 1 0.2"/></geometry></collision></link>
//!   <link name="upper"><collision><origin xyz="0 0 0.6"/><geometry><cylinder radius="0.1" length="0.8"/></geometry></collision></link>
//!   <link name="fore"><collision><origin xyz="0.5 0 0"/><geometry><box size="1 0.1 0.1"/></geometry></collision></link>
//!   <joint name="shoulder" type="revolute"><parent link="base"/><child link="upper"/>
//!     <axis xyz="0 0 1"/><limit lower="-3" upper="3"/></joint>
//!   <joint name="elbow" type="revolute"><parent link="upper"/><child link="fore"/>
//!     <origin xyz="0 0 1"/><axis xyz="0 1 0"/><limit lower="-3" upper="3"/></joint>
//! </robot>"#;
//! let robot = Robot::from_urdf_str(urdf, "arm.urdf", ".", &[])?;
//! assert_eq!(robot.joint_names(), ["shoulder", "elbow"]);
//! assert_eq!(robot.allowed_pairs(), [("base", "fore")]);
//! assert!(!robot.collides(&[0.0, 0.0], Against::Itself)?);
//! // Folding the forearm down by 90 degrees puts it into the base.
//! let folded = [0.0, std::f64::consts::FRAC_PI_2];
//! assert_eq!(robot.colliding_pairs(&folded, Against::Itself)?, [("base".to_string(), "fore".to_string())]);
//! let nearest = robot.nearest(&[0.0, 0.0], Against::Itself)?.expect("one pair");
//! assert!((nearest.distance.distance - 0.85).abs() <= 1e-9 + nearest.distance.error_bound);
//! // The straight motion there meets the base on the way: the answer says when.
//! let motion = robot.motion_collision(&[0.0, 0.0], &folded, &MotionOptions::default())?;
//! assert!(matches!(motion, MotionAnswer::Collides { time, .. } if time > 0.0 && time <= 1.0));
//! # Ok::<(), cga_collide::Error>(())
//! ```

mod geometry;
mod kinematics;
mod motion;
mod motion_bound;
mod obb;
mod queries;
mod spheres;
mod staged;
mod urdf;

#[cfg(test)]
mod motion_tests;
#[cfg(test)]
mod nearest_tests;
#[cfg(test)]
mod tests;

pub use motion::{MotionAnswer, MotionLimit, MotionOptions};
pub use queries::{Against, NearestPair};
pub use urdf::JointKind;

use std::collections::{HashMap, HashSet};
use std::path::{Path, PathBuf};

use nalgebra::Isometry3;

use crate::error::Error;
use crate::scene::{ObjectId, Scene};
use geometry::{place, Geometry, Loader, Part, Placed};
use kinematics::Joint;
use spheres::Sphere;
use urdf::{model_error, parse_srdf, parse_urdf};

/// An environment object the robot is asked against: its scene handle and its placed body.
#[derive(Debug, Clone)]
struct EnvObject {
    id: ObjectId,
    geometry: Geometry,
    placed: Placed,
    sphere: Sphere,
}

/// A robot read from a URDF, its allowed link pairs and an optional environment (see the
/// [module docs](self)).
#[derive(Debug, Clone)]
pub struct Robot {
    link_names: Vec<String>,
    /// Every part, grouped by link in link order; `link_parts[l]` is link `l`'s range.
    parts: Vec<Part>,
    link_parts: Vec<std::ops::Range<usize>>,
    /// Each part's bounding sphere in its link's frame.
    part_spheres: Vec<Sphere>,
    /// Each link's bounding sphere around its parts', in its frame (`None`: no geometry).
    link_spheres: Vec<Option<Sphere>>,
    /// Joints parents first (a joint's parent link is placed before it).
    joints: Vec<Joint>,
    /// The movable joints' names, in configuration order.
    joint_names: Vec<String>,
    joint_limits: Vec<Option<(f64, f64)>>,
    root: usize,
    /// Link pairs `(a, b)`, `a < b`, both with geometry, tested by the self queries.
    pairs: Vec<(usize, usize)>,
    environment: Vec<EnvObject>,
    solid: bool,
}

fn read(path: &Path) -> Result<String, Error> {
    std::fs::read_to_string(path).map_err(|e| Error::Io {
        file: path.display().to_string(),
        kind: e.kind(),
        message: e.to_string(),
    })
}

impl Robot {
    /// Reads the URDF at `path`, resolving `package://` against `package_dirs`, and applies an
    /// SRDF's `disable_collisions` when one is given.
    pub fn from_urdf(
        path: impl AsRef<Path>,
        package_dirs: &[PathBuf],
        srdf: Option<&Path>,
    ) -> Result<Robot, Error> {
        let path = path.as_ref();
        let text = read(path)?;
        let base = path.parent().unwrap_or(Path::new("."));
        let mut robot =
            Robot::from_urdf_str(&text, &path.display().to_string(), base, package_dirs)?;
        if let Some(srdf) = srdf {
            robot.disable_from_srdf(&read(srdf)?, &srdf.display().to_string())?;
        }
        Ok(robot)
    }

    /// Reads a URDF held in memory: `file` names it in errors, relative mesh paths are taken
    /// from `base_dir`.
    pub fn from_urdf_str(
        text: &str,
        file: &str,
        base_dir: impl AsRef<Path>,
        package_dirs: &[PathBuf],
    ) -> Result<Robot, Error> {
        let spec = parse_urdf(file, text)?;
        let mut index = HashMap::new();
        for (k, link) in spec.links.iter().enumerate() {
            if index.insert(link.name.clone(), k).is_some() {
                return Err(model_error(
                    file.to_string(),
                    format!("two links are named {:?}", link.name),
                ));
            }
        }
        if spec.links.is_empty() {
            return Err(model_error(file.to_string(), "the robot has no <link>"));
        }
        let tree = kinematics::Tree::new(file, &spec, &index)?;
        let mut loader = Loader {
            base_dir: base_dir.as_ref(),
            package_dirs,
            cache: HashMap::new(),
        };
        let mut parts = Vec::new();
        let mut link_parts = Vec::new();
        for (k, link) in spec.links.iter().enumerate() {
            let start = parts.len();
            for c in &link.collisions {
                parts.push(loader.part(k, c)?);
            }
            link_parts.push(start..parts.len());
        }
        let part_spheres: Vec<Sphere> = parts
            .iter()
            .map(|p| Sphere::of_part(&p.geometry, &p.local))
            .collect();
        let link_spheres = link_parts
            .iter()
            .map(|r| Sphere::around(&part_spheres[r.clone()]))
            .collect();
        let has_geometry = |l: usize| !link_parts[l].is_empty();
        let mut pairs = Vec::new();
        for a in 0..spec.links.len() {
            for b in a + 1..spec.links.len() {
                let (ba, bb) = (tree.body[a], tree.body[b]);
                let adjacent = tree.adjacent.contains(&(ba.min(bb), ba.max(bb)));
                if has_geometry(a) && has_geometry(b) && ba != bb && !adjacent {
                    pairs.push((a, b));
                }
            }
        }
        Ok(Robot {
            link_names: spec.links.iter().map(|l| l.name.clone()).collect(),
            parts,
            link_parts,
            part_spheres,
            link_spheres,
            joint_names: tree.joint_names,
            joint_limits: tree.joint_limits,
            joints: tree.joints,
            root: tree.root,
            pairs,
            environment: Vec::new(),
            solid: false,
        })
    }

    fn link(&self, name: &str) -> Option<usize> {
        self.link_names.iter().position(|n| n == name)
    }

    /// Removes the pairs of an SRDF's `<disable_collisions link1 link2>` (`file` names it in
    /// errors). A link the robot does not have is an error naming the element.
    pub fn disable_from_srdf(&mut self, text: &str, file: &str) -> Result<(), Error> {
        let mut off = HashSet::new();
        for (a, b, at) in parse_srdf(file, text)? {
            let (Some(i), Some(j)) = (self.link(&a), self.link(&b)) else {
                return Err(model_error(
                    at,
                    format!("link {a:?} or {b:?} is not a link of the robot"),
                ));
            };
            off.insert((i.min(j), i.max(j)));
        }
        self.pairs.retain(|p| !off.contains(p));
        Ok(())
    }

    /// Never tests links `a` and `b` against each other (parts that touch by design).
    pub fn exclude_pair(&mut self, a: &str, b: &str) -> Result<(), Error> {
        let (Some(i), Some(j)) = (self.link(a), self.link(b)) else {
            return Err(Error::Configuration {
                reason: format!("exclude_pair: link {a:?} or {b:?} is not a link of the robot"),
            });
        };
        let key = (i.min(j), i.max(j));
        self.pairs.retain(|p| *p != key);
        Ok(())
    }

    /// Meshes count as solids (`true`: a part inside a closed mesh touches it) or surfaces
    /// (`false`, the default, as coal and pinocchio).
    pub fn set_solid(&mut self, solid: bool) {
        self.solid = solid;
    }

    /// Takes the scene's objects, as placed now, as the environment (a snapshot: later changes
    /// to the scene are not seen until this is called again).
    pub fn set_environment(&mut self, scene: &Scene) -> Result<(), Error> {
        let mut env = Vec::new();
        for id in scene.ids() {
            let pose = *scene.pose(id)?;
            let geometry = match scene.collider(id) {
                Ok(c) => Geometry::Mesh(c.clone()),
                Err(_) => Geometry::Shape(scene.shape(id)?.clone()),
            };
            let placed = place(&geometry, pose)?;
            env.push(EnvObject {
                id,
                geometry,
                sphere: Sphere::of_box(&placed.bbox),
                placed,
            });
        }
        self.environment = env;
        Ok(())
    }

    /// Number of movable joints: the length of a configuration.
    pub fn dof(&self) -> usize {
        self.joint_names.len()
    }

    /// The movable joints' names, in configuration order.
    pub fn joint_names(&self) -> &[String] {
        &self.joint_names
    }

    /// Each movable joint's `(lower, upper)` limits (`None` for a continuous joint).
    pub fn joint_limits(&self) -> &[Option<(f64, f64)>] {
        &self.joint_limits
    }

    /// Every link's name, in URDF order.
    pub fn link_names(&self) -> &[String] {
        &self.link_names
    }

    /// The link pairs the self queries test, each in URDF order.
    pub fn allowed_pairs(&self) -> Vec<(&str, &str)> {
        self.pairs
            .iter()
            .map(|&(a, b)| (self.link_names[a].as_str(), self.link_names[b].as_str()))
            .collect()
    }

    /// Number of environment objects.
    pub fn environment_len(&self) -> usize {
        self.environment.len()
    }

    /// Every link's world pose at configuration `q` (forward kinematics).
    pub fn link_poses(&self, q: &[f64]) -> Result<Vec<Isometry3<f64>>, Error> {
        kinematics::forward(
            &self.joints,
            self.root,
            self.link_names.len(),
            q,
            self.dof(),
        )
    }
}
