//! One configuration, placed on demand: forward kinematics and the links' bounding spheres
//! first (one transform per link), each link's parts placed only when a pair of that link
//! passes the sphere test. Most link pairs of a robot are apart, so most configurations place
//! few parts.

use nalgebra::Isometry3;

use super::geometry::{place, Placed};
use super::spheres::Sphere;
use super::Robot;
use crate::bounding::Aabb;
use crate::error::Error;

/// A configuration's link poses, link spheres in the world, and the parts placed so far.
pub(super) struct Staged<'r> {
    robot: &'r Robot,
    links: Vec<Isometry3<f64>>,
    /// Each link's world sphere (`None` for a link without geometry).
    pub link_spheres: Vec<Option<Sphere>>,
    /// Each part, placed once its link is needed (`done[l]`).
    parts: Vec<Placed>,
    link_boxes: Vec<Aabb>,
    done: Vec<bool>,
}

impl<'r> Staged<'r> {
    pub fn new(robot: &'r Robot, q: &[f64]) -> Result<Staged<'r>, Error> {
        let links = robot.link_poses(q)?;
        let link_spheres = robot
            .link_spheres
            .iter()
            .zip(&links)
            .map(|(s, pose)| s.map(|s| s.placed(pose)))
            .collect();
        let unplaced = Placed {
            pose: Isometry3::identity(),
            shape: None,
            bbox: Aabb::EMPTY,
            obb: None,
        };
        Ok(Staged {
            robot,
            link_spheres,
            parts: vec![unplaced; robot.parts.len()],
            link_boxes: vec![Aabb::EMPTY; links.len()],
            done: vec![false; links.len()],
            links,
        })
    }

    /// Places link `l`'s parts (once).
    pub fn place_link(&mut self, l: usize) -> Result<(), Error> {
        if self.done[l] {
            return Ok(());
        }
        let mut b = Aabb::EMPTY;
        for k in self.robot.link_parts[l].clone() {
            let part = &self.robot.parts[k];
            let placed = place(&part.geometry, self.links[part.link] * part.local)?;
            b = b.union(&placed.bbox);
            self.parts[k] = placed;
        }
        self.link_boxes[l] = b;
        self.done[l] = true;
        Ok(())
    }

    /// Part `k` as placed ([`place_link`](Self::place_link) of its link must have run).
    pub fn part(&self, k: usize) -> &Placed {
        &self.parts[k]
    }

    /// Link `l`'s world box ([`place_link`](Self::place_link) must have run).
    pub fn link_box(&self, l: usize) -> &Aabb {
        &self.link_boxes[l]
    }

    /// Part `k`'s world sphere (no placing needed).
    pub fn part_sphere(&self, k: usize) -> Sphere {
        self.robot.part_spheres[k].placed(&self.links[self.robot.parts[k].link])
    }
}
