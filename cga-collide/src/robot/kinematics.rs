//! The kinematic tree: joints ordered parents first, rigid bodies (links joined by fixed
//! joints), adjacent bodies, and forward kinematics.

use std::collections::{HashMap, HashSet};

use nalgebra::{Isometry3, Translation3, Unit, UnitQuaternion, Vector3};

use super::urdf::{model_error, JointKind, UrdfSpec};
use crate::error::Error;

/// A joint ready for forward kinematics.
#[derive(Debug, Clone)]
pub(super) struct Joint {
    pub kind: JointKind,
    pub parent: usize,
    pub child: usize,
    pub origin: Isometry3<f64>,
    pub axis: Unit<Vector3<f64>>,
    /// Its place in a configuration (`None` for a fixed joint).
    pub dof: Option<usize>,
}

/// What the URDF's joints make of its links.
pub(super) struct Tree {
    pub joints: Vec<Joint>,
    pub joint_names: Vec<String>,
    pub joint_limits: Vec<Option<(f64, f64)>>,
    pub root: usize,
    /// Each link's rigid body (a representative link).
    pub body: Vec<usize>,
    /// Body pairs `(a, b)`, `a < b`, joined by a movable joint.
    pub adjacent: HashSet<(usize, usize)>,
}

fn find(body: &mut [usize], mut l: usize) -> usize {
    while body[l] != l {
        body[l] = body[body[l]];
        l = body[l];
    }
    l
}

impl Tree {
    pub fn new(file: &str, spec: &UrdfSpec, index: &HashMap<String, usize>) -> Result<Tree, Error> {
        let n = spec.links.len();
        let mut parent_joint: Vec<Option<usize>> = vec![None; n];
        let mut ends = Vec::new();
        let mut joint_names = Vec::new();
        let mut joint_limits = Vec::new();
        let mut dofs = Vec::new();
        let mut seen = HashSet::new();
        for (k, j) in spec.joints.iter().enumerate() {
            if !seen.insert(j.name.as_str()) {
                return Err(model_error(j.at.clone(), "two joints have this name"));
            }
            let link = |name: &str| {
                index.get(name).copied().ok_or_else(|| {
                    model_error(
                        j.at.clone(),
                        format!("link {name:?} is not a <link> of the robot"),
                    )
                })
            };
            let (p, c) = (link(&j.parent)?, link(&j.child)?);
            if let Some(other) = parent_joint[c] {
                return Err(model_error(
                    j.at.clone(),
                    format!(
                        "link {:?} already has the parent joint {:?}: a URDF is a tree",
                        j.child, spec.joints[other].name
                    ),
                ));
            }
            parent_joint[c] = Some(k);
            ends.push((p, c));
            if j.kind == JointKind::Fixed {
                dofs.push(None);
            } else {
                dofs.push(Some(joint_names.len()));
                joint_names.push(j.name.clone());
                joint_limits.push(j.limits);
            }
        }
        let roots: Vec<usize> = (0..n).filter(|&l| parent_joint[l].is_none()).collect();
        let [root] = roots[..] else {
            let names: Vec<&str> = roots.iter().map(|&l| spec.links[l].name.as_str()).collect();
            return Err(model_error(
                file.to_string(),
                format!(
                    "the links must form one tree with one root, found roots {names:?} (a link \
                     without a parent joint is a root; a cycle has none)"
                ),
            ));
        };
        // Parents first: a walk down from the root.
        let mut children: Vec<Vec<usize>> = vec![Vec::new(); n];
        for (k, &(p, _)) in ends.iter().enumerate() {
            children[p].push(k);
        }
        let mut order = Vec::new();
        let mut stack = vec![root];
        while let Some(l) = stack.pop() {
            for &k in children[l].iter().rev() {
                order.push(k);
                stack.push(ends[k].1);
            }
        }
        if order.len() != spec.joints.len() {
            return Err(model_error(
                file.to_string(),
                "some joints form a cycle not reached from the root link",
            ));
        }
        let mut body: Vec<usize> = (0..n).collect();
        for (k, j) in spec.joints.iter().enumerate() {
            if j.kind == JointKind::Fixed {
                let (a, b) = (find(&mut body, ends[k].0), find(&mut body, ends[k].1));
                body[a.max(b)] = a.min(b);
            }
        }
        let body: Vec<usize> = (0..n).map(|l| find(&mut body, l)).collect();
        let adjacent = spec
            .joints
            .iter()
            .zip(&ends)
            .filter(|(j, _)| j.kind != JointKind::Fixed)
            .map(|(_, &(p, c))| (body[p].min(body[c]), body[p].max(body[c])))
            .collect();
        let joints = order
            .iter()
            .map(|&k| {
                let j = &spec.joints[k];
                Joint {
                    kind: j.kind,
                    parent: ends[k].0,
                    child: ends[k].1,
                    origin: j.origin,
                    axis: Unit::try_new(j.axis, 0.0).unwrap_or(Vector3::x_axis()),
                    dof: dofs[k],
                }
            })
            .collect();
        Ok(Tree {
            joints,
            joint_names,
            joint_limits,
            root,
            body,
            adjacent,
        })
    }
}

/// Every link's world pose at `q` (the root at the identity).
pub(super) fn forward(
    joints: &[Joint],
    root: usize,
    links: usize,
    q: &[f64],
    dof: usize,
) -> Result<Vec<Isometry3<f64>>, Error> {
    if q.len() != dof {
        return Err(Error::Configuration {
            reason: format!(
                "{} values given, the robot has {dof} movable joints",
                q.len()
            ),
        });
    }
    if let Some(k) = q.iter().position(|x| !x.is_finite()) {
        return Err(Error::Configuration {
            reason: format!("value {k} is not finite ({})", q[k]),
        });
    }
    let mut poses = vec![Isometry3::identity(); links];
    poses[root] = Isometry3::identity();
    for j in joints {
        let motion = match (j.kind, j.dof) {
            (JointKind::Revolute | JointKind::Continuous, Some(d)) => Isometry3::from_parts(
                Translation3::identity(),
                UnitQuaternion::from_axis_angle(&j.axis, q[d]),
            ),
            (JointKind::Prismatic, Some(d)) => Isometry3::from_parts(
                Translation3::from(j.axis.into_inner() * q[d]),
                UnitQuaternion::identity(),
            ),
            _ => Isometry3::identity(),
        };
        poses[j.child] = poses[j.parent] * j.origin * motion;
    }
    Ok(poses)
}
