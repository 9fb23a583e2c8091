//! The questions a [`Scene`] answers: the broad phase proposes pairs (or objects), and each is
//! decided exactly by the colliders' pose queries, over the cores.

use nalgebra::Isometry3;

use super::broad_phase::box_gap;
use super::{ObjectId, Scene};
use crate::collider::Collider;
use crate::error::Error;
use crate::parallel::*;
use crate::query::CertifiedDistance;
use crate::Segment;

/// A pair of objects with their certified distance.
pub type NearestPair = (ObjectId, ObjectId, CertifiedDistance);

impl Scene {
    /// Every pair of objects `(a, b)` that touch (surfaces meet; solids share a point with
    /// [`set_solid`](Self::set_solid)), exactly, sorted, `a` before `b`; excluded pairs and
    /// pairs kept apart by their groups are left out. The candidate pairs of the broad phase
    /// are decided in parallel.
    pub fn colliding_pairs(&self) -> Result<Vec<(ObjectId, ObjectId)>, Error> {
        let candidates = self.candidates(0.0);
        let hits = candidates
            .par_iter()
            .map(|&(a, b)| self.touch(a, b))
            .collect::<Result<Vec<bool>, Error>>()?;
        Ok(self.ids_of(candidates.into_iter().zip(hits)))
    }

    /// Every object that touches `id` (see [`colliding_pairs`](Self::colliding_pairs)), sorted.
    pub fn colliding_with(&self, id: ObjectId) -> Result<Vec<ObjectId>, Error> {
        let world = *self.broad.bounds(self.object(id).map(|_| id.index)?);
        let others: Vec<u32> = self
            .broad
            .near_box(&world, 0.0)
            .into_iter()
            .filter(|&o| o != id.index && self.tested(id.index, o))
            .collect();
        let hits = others
            .par_iter()
            .map(|&o| self.touch(id.index, o))
            .collect::<Result<Vec<bool>, Error>>()?;
        Ok(self.objects_hit(others, hits))
    }

    /// Every object that an outside collider placed at `pose` would touch (a new object: does
    /// it fit?), sorted. Groups and exclusions do not apply to it.
    pub fn colliding_at(
        &self,
        collider: &Collider,
        pose: &Isometry3<f64>,
    ) -> Result<Vec<ObjectId>, Error> {
        let world = collider.world_box(pose)?;
        let near = self.broad.near_box(&world, 0.0);
        let hits = near
            .par_iter()
            .map(|&o| {
                let object = self.slot(o);
                if self.solid {
                    collider.collides_solid_at(pose, &object.collider, &object.pose)
                } else {
                    collider.collides_at(pose, &object.collider, &object.pose)
                }
            })
            .collect::<Result<Vec<bool>, Error>>()?;
        Ok(self.objects_hit(near, hits))
    }

    /// Every pair of objects whose surfaces come within distance `c`, exactly (closed: a
    /// distance of exactly `c` counts), sorted. NaN and negative `c` give no pair.
    pub fn pairs_within_distance(&self, c: f64) -> Result<Vec<(ObjectId, ObjectId)>, Error> {
        if c.is_nan() || c < 0.0 {
            return Ok(Vec::new());
        }
        let candidates = self.candidates(c);
        let hits = candidates
            .par_iter()
            .map(|&(a, b)| {
                let (x, y) = (self.slot(a), self.slot(b));
                x.collider
                    .within_distance_at(&x.pose, &y.collider, &y.pose, c)
            })
            .collect::<Result<Vec<bool>, Error>>()?;
        Ok(self.ids_of(candidates.into_iter().zip(hits)))
    }

    /// The nearest pair of objects (surfaces) and its certified distance: among the pairs the
    /// search cannot prove farther, the one with the least `f64` distance, ties to the smaller
    /// pair. `None` with fewer than two objects that may be paired. Touching objects are at
    /// distance 0: when some touch, the first touching pair the broad phase's sweep meets is
    /// reported (a nearest pair; the search stops there).
    pub fn nearest_pair(&self) -> Result<Option<NearestPair>, Error> {
        // Touching pairs first: their distance is 0, so the first touching pair the sweep meets
        // is a nearest pair, and the search stops there.
        if let Some((a, b)) = self
            .broad
            .first_pair(|a, b| Ok::<bool, Error>(self.tested(a, b) && self.touch(a, b)?))?
        {
            return Ok(Some((self.id_of(a), self.id_of(b), self.distance(a, b)?)));
        }
        // A first bound from the pair of neighbours in sweep order with the smallest box gap.
        let order = self.broad.sweep_order();
        let seed = order
            .windows(2)
            .filter(|w| self.tested(w[0], w[1]))
            .map(|w| {
                (
                    box_gap(self.broad.bounds(w[0]), self.broad.bounds(w[1])),
                    w[0],
                    w[1],
                )
            })
            .min_by(|x, y| x.0.total_cmp(&y.0));
        let Some((_, a, b)) = seed.or_else(|| self.any_tested_pair()) else {
            return Ok(None);
        };
        let mut best = (a.min(b), a.max(b), self.distance(a, b)?);
        // Then every pair whose boxes come within the bound, nearest boxes first.
        let reach = best.2.distance + best.2.error_bound;
        let mut candidates: Vec<(f64, u32, u32)> = self
            .candidates(reach)
            .into_iter()
            .map(|(a, b)| (box_gap(self.broad.bounds(a), self.broad.bounds(b)), a, b))
            .collect();
        candidates.sort_by(|x, y| x.0.total_cmp(&y.0));
        for (gap, a, b) in candidates {
            if gap > best.2.distance + best.2.error_bound {
                break;
            }
            if (a, b) == (best.0, best.1) {
                continue;
            }
            let d = self.distance(a, b)?;
            if (d.distance, a, b) < (best.2.distance, best.0, best.1) {
                best = (a, b, d);
            }
        }
        Ok(Some((self.id_of(best.0), self.id_of(best.1), best.2)))
    }

    /// The object nearest to `id` (surfaces) and the certified distance, as
    /// [`nearest_pair`](Self::nearest_pair) restricted to pairs with `id`. `None` when no other
    /// object may be paired with it.
    pub fn nearest_to(&self, id: ObjectId) -> Result<Option<(ObjectId, CertifiedDistance)>, Error> {
        self.object(id)?;
        let me = id.index;
        let world = *self.broad.bounds(me);
        let mut others: Vec<(f64, u32)> = self
            .ids()
            .into_iter()
            .map(|o| o.index)
            .filter(|&o| o != me && self.tested(me, o))
            .map(|o| (box_gap(&world, self.broad.bounds(o)), o))
            .collect();
        others.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        let mut best: Option<(u32, CertifiedDistance)> = None;
        for (gap, o) in others {
            if best.is_some_and(|(_, d)| gap > d.distance + d.error_bound) {
                break;
            }
            let d = self.distance(me, o)?;
            if best.is_none_or(|(b, bd)| (d.distance, o) < (bd.distance, b)) {
                best = Some((o, d));
            }
        }
        Ok(best.map(|(o, d)| (self.id_of(o), d)))
    }

    /// Every object whose surface the closed segment meets, sorted.
    pub fn segment_hits(&self, segment: &Segment) -> Result<Vec<ObjectId>, Error> {
        let (p, q) = (*segment.a(), *segment.b());
        let near: Vec<u32> = self
            .ids()
            .into_iter()
            .map(|o| o.index)
            .filter(|&o| self.broad.bounds(o).may_meet_segment(&p, &q))
            .collect();
        let hits = near
            .par_iter()
            .map(|&o| {
                let object = self.slot(o);
                object
                    .collider
                    .segment_hits_at(&object.pose, segment)
                    .map(|t| !t.is_empty())
            })
            .collect::<Result<Vec<bool>, Error>>()?;
        Ok(self.objects_hit(near, hits))
    }

    /// The tested pairs of slots whose boxes come within `reach`, `a < b`.
    fn candidates(&self, reach: f64) -> Vec<(u32, u32)> {
        let mut pairs = self.broad.pairs(reach);
        pairs.retain(|&(a, b)| self.tested(a, b));
        pairs
    }

    /// Whether two placed objects touch, in the scene's sense.
    fn touch(&self, a: u32, b: u32) -> Result<bool, Error> {
        let (x, y) = (self.slot(a), self.slot(b));
        if self.solid {
            x.collider.collides_solid_at(&x.pose, &y.collider, &y.pose)
        } else {
            x.collider.collides_at(&x.pose, &y.collider, &y.pose)
        }
    }

    fn distance(&self, a: u32, b: u32) -> Result<CertifiedDistance, Error> {
        let (x, y) = (self.slot(a), self.slot(b));
        x.collider.distance_at(&x.pose, &y.collider, &y.pose)
    }

    fn any_tested_pair(&self) -> Option<(f64, u32, u32)> {
        let ids: Vec<u32> = self.ids().into_iter().map(|o| o.index).collect();
        ids.iter().enumerate().find_map(|(k, &a)| {
            ids[k + 1..]
                .iter()
                .find(|&&b| self.tested(a, b))
                .map(|&b| (0.0, a, b))
        })
    }

    /// The pairs whose answer is `true`, as handles, sorted.
    fn ids_of(
        &self,
        answers: impl Iterator<Item = ((u32, u32), bool)>,
    ) -> Vec<(ObjectId, ObjectId)> {
        let mut out: Vec<(ObjectId, ObjectId)> = answers
            .filter(|&(_, hit)| hit)
            .map(|((a, b), _)| (self.id_of(a), self.id_of(b)))
            .collect();
        out.sort_unstable();
        out
    }

    /// The objects whose answer is `true`, as handles, sorted.
    fn objects_hit(&self, slots: Vec<u32>, hits: Vec<bool>) -> Vec<ObjectId> {
        let mut out: Vec<ObjectId> = slots
            .into_iter()
            .zip(hits)
            .filter(|&(_, hit)| hit)
            .map(|(o, _)| self.id_of(o))
            .collect();
        out.sort_unstable();
        out
    }
}
