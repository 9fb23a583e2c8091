//! How far a link can move while the configuration moves along a straight joint-space
//! stretch: a bound, for each link, on the distance any point of its geometry travels from
//! where it is at the stretch's midpoint.
//!
//! Along `q(t) = q0 + t (q1 - q0)` a point `x` of link `L` moves with velocity
//! `Σ_k Δq_k J_k`, one term per movable joint `k` above `L`: a revolute joint turns `x` about
//! its axis, so its term is at most `|Δq_k|` times the distance from `x` to the joint's frame
//! origin (a point of the axis); a prismatic joint slides it, `|Δq_k|` times 1. That distance
//! is at most the sum of the segments between the frame origins of the movable joints from
//! `k` down to `L` plus `L`'s reach from its own joint's frame: a revolute joint does not
//! change the segment below it, and a prismatic joint lengthens it by at most `|q|`, the
//! largest over the stretch being at one of its ends. So the bound holds whatever the other
//! joints of the chain do over the stretch, and a point is never farther from its midpoint
//! position than half the stretch's length times the summed speed.

use nalgebra::Isometry3;

use super::geometry::place;
use super::urdf::JointKind;
use super::Robot;
use crate::error::Error;

/// One movable joint on a link's chain, root first.
#[derive(Debug, Clone)]
struct ChainJoint {
    dof: usize,
    prismatic: bool,
    /// Length of the rigid segment from the previous movable joint's frame origin (or the
    /// root's) to this joint's frame origin at `q = 0`.
    segment: f64,
}

/// What a link's sweep bound needs: its movable joints and its reach.
#[derive(Debug, Clone)]
pub(super) struct LinkSweep {
    chain: Vec<ChainJoint>,
    /// The largest distance from the last movable joint's frame origin to the link's
    /// geometry (infinite when unbounded; 0 when the link has no geometry).
    reach: f64,
}

/// Grows a bound by far more than the `f64` rounding of the forward kinematics and of the
/// sums above, so that every configuration placed in `f64` along the stretch is covered.
const RELATIVE_MARGIN: f64 = 1e-9;

impl LinkSweep {
    /// The largest distance any point of the link travels from its place at the middle of
    /// `[qa, qb]` while the configuration moves straight from `qa` to `qb`, plus a margin
    /// covering rounding.
    pub fn bound(&self, qa: &[f64], qb: &[f64]) -> f64 {
        if self.chain.is_empty() {
            return 0.0;
        }
        // `arm` is the bound on the distance from the current joint's frame origin to the
        // link's points, grown joint by joint from the link up to the root.
        let mut arm = self.reach;
        let mut speed = 0.0;
        for j in self.chain.iter().rev() {
            let dq = (qb[j.dof] - qa[j.dof]).abs();
            speed += dq * if j.prismatic { 1.0 } else { arm };
            let travel = if j.prismatic {
                qa[j.dof].abs().max(qb[j.dof].abs())
            } else {
                0.0
            };
            arm += j.segment + travel;
        }
        let half = speed / 2.0;
        // `arm` now bounds every world coordinate's size: the margin scales with it.
        half * (1.0 + RELATIVE_MARGIN) + RELATIVE_MARGIN * (1.0 + arm)
    }
}

/// The largest distance from the origin to the corners of a box (an upper bound on the
/// distance to any point in it; infinite when unbounded).
fn farthest_corner(min: [f64; 3], max: [f64; 3]) -> f64 {
    let mut sum = 0.0;
    for k in 0..3 {
        let m = min[k].abs().max(max[k].abs());
        sum += m * m;
    }
    let d = sum.sqrt() * (1.0 + RELATIVE_MARGIN);
    if d.is_nan() {
        f64::INFINITY
    } else {
        d
    }
}

impl Robot {
    /// Every link's sweep model, in link order.
    pub(super) fn link_sweeps(&self) -> Result<Vec<LinkSweep>, Error> {
        let links = self.link_names.len();
        let mut parent_joint = vec![None; links];
        for (k, j) in self.joints.iter().enumerate() {
            parent_joint[j.child] = Some(k);
        }
        (0..links)
            .map(|link| {
                // The joints from the root down to the link.
                let mut path = Vec::new();
                let mut at = link;
                while let Some(k) = parent_joint[at] {
                    path.push(k);
                    at = self.joints[k].parent;
                    if path.len() > self.joints.len() {
                        break;
                    }
                }
                path.reverse();
                let mut chain = Vec::new();
                // The pose of the current link's frame in the last movable joint's frame.
                let mut since = Isometry3::identity();
                for k in path {
                    let j = &self.joints[k];
                    let to_joint = since * j.origin;
                    match (j.kind, j.dof) {
                        (JointKind::Fixed, _) | (_, None) => since = to_joint,
                        (kind, Some(dof)) => {
                            chain.push(ChainJoint {
                                dof,
                                prismatic: kind == JointKind::Prismatic,
                                segment: to_joint.translation.vector.norm()
                                    * (1.0 + RELATIVE_MARGIN),
                            });
                            since = Isometry3::identity();
                        }
                    }
                }
                let mut reach: f64 = 0.0;
                for part in &self.parts[self.link_parts[link].clone()] {
                    let b = place(&part.geometry, since * part.local)?.bbox;
                    reach = reach.max(farthest_corner(b.min, b.max));
                }
                Ok(LinkSweep { chain, reach })
            })
            .collect()
    }
}

/// The configuration at `t` along the straight motion (`q0` at 0, `q1` at 1, exactly).
pub(super) fn along(q0: &[f64], q1: &[f64], t: f64) -> Vec<f64> {
    q0.iter()
        .zip(q1)
        .map(|(a, b)| (1.0 - t) * a + t * b)
        .collect()
}
