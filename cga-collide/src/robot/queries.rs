//! The questions at a configuration: forward kinematics once, every part placed once, then
//! each tested pair of links (or link and environment object) set aside by its world boxes or
//! decided by the exact test of its parts.

use crate::bounding::Aabb;
use crate::error::Error;
use crate::parallel::over_batch;
use crate::query::CertifiedDistance;

use super::geometry::{box_gap_lower, boxes_within, place, Geometry, PairTest, Placed};
use super::Robot;

/// What the robot is asked against.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Against {
    /// Its own links (the allowed pairs).
    Itself,
    /// The environment set by [`Robot::set_environment`] (every link with geometry against
    /// every object).
    Environment,
    /// Both.
    Both,
}

/// The nearest pair at a configuration: the names (sorted) and their certified distance, the
/// witnesses in world coordinates (`witness_a` on `pair.0`).
#[derive(Debug, Clone, PartialEq)]
pub struct NearestPair {
    /// The two names, sorted: links by name, environment objects as `env:<i>`.
    pub pair: (String, String),
    /// The distance, its bound and the witnesses. Over every tested pair, the true minimum
    /// lies within `distance ± error_bound`.
    pub distance: CertifiedDistance,
}

/// The second member of a tested pair.
#[derive(Clone, Copy)]
enum Other {
    Link(usize),
    Env(usize),
}

/// Every part placed at one configuration, with each link's box.
pub(super) struct Posed {
    pub(super) parts: Vec<Placed>,
    link_boxes: Vec<Aabb>,
}

impl Robot {
    pub(super) fn pose_parts(&self, q: &[f64]) -> Result<Posed, Error> {
        let links = self.link_poses(q)?;
        let parts = self
            .parts
            .iter()
            .map(|p| place(&p.geometry, links[p.link] * p.local))
            .collect::<Result<Vec<_>, Error>>()?;
        let link_boxes = self
            .link_parts
            .iter()
            .map(|r| {
                parts[r.clone()]
                    .iter()
                    .fold(Aabb::EMPTY, |b, p| b.union(&p.bbox))
            })
            .collect();
        Ok(Posed { parts, link_boxes })
    }

    /// The tested pairs, self pairs first, then link × environment object.
    fn units(&self, against: Against) -> Vec<(usize, Other)> {
        let mut out = Vec::new();
        if against != Against::Environment {
            out.extend(self.pairs.iter().map(|&(a, b)| (a, Other::Link(b))));
        }
        if against != Against::Itself {
            for (l, r) in self.link_parts.iter().enumerate() {
                if !r.is_empty() {
                    out.extend((0..self.environment.len()).map(|e| (l, Other::Env(e))));
                }
            }
        }
        out
    }

    /// How many pairs (of links, or of a link and an environment object) a question tests.
    pub fn pairs_checked(&self, against: Against) -> usize {
        self.units(against).len()
    }

    fn name(&self, o: Other) -> String {
        match o {
            Other::Link(l) => self.link_names[l].clone(),
            Other::Env(e) => format!("env:{}", self.environment[e].id.index()),
        }
    }

    /// The other member's parts: `(geometry, placed)` pairs.
    fn members<'a>(&'a self, posed: &'a Posed, o: Other) -> Vec<(&'a Geometry, &'a Placed)> {
        match o {
            Other::Link(l) => self.link_parts[l]
                .clone()
                .map(|k| (&self.parts[k].geometry, &posed.parts[k]))
                .collect(),
            Other::Env(e) => {
                let obj = &self.environment[e];
                vec![(&obj.geometry, &obj.placed)]
            }
        }
    }

    fn other_box(&self, posed: &Posed, o: Other) -> Aabb {
        match o {
            Other::Link(l) => posed.link_boxes[l],
            Other::Env(e) => self.environment[e].placed.bbox,
        }
    }

    /// The tested pairs for which some part pair is not proved farther apart than `reach` by
    /// its boxes and passes `decide` (exact);
    /// stops after the first when `first`.
    fn scan(
        &self,
        q: &[f64],
        against: Against,
        first: bool,
        reach: f64,
        decide: impl Fn(&PairTest) -> Result<bool, Error>,
    ) -> Result<Vec<(String, String)>, Error> {
        let posed = self.pose_parts(q)?;
        let mut out = Vec::new();
        for (a, o) in self.units(against) {
            if !boxes_within(&posed.link_boxes[a], &self.other_box(&posed, o), reach) {
                continue;
            }
            let others = self.members(&posed, o);
            let mut hit = false;
            'parts: for k in self.link_parts[a].clone() {
                let mine = (&self.parts[k].geometry, &posed.parts[k]);
                for &theirs in &others {
                    if mine.1.apart(theirs.1, reach) {
                        continue;
                    }
                    let test = PairTest {
                        a: mine,
                        b: theirs,
                        solid: self.solid,
                    };
                    if decide(&test)? {
                        hit = true;
                        break 'parts;
                    }
                }
            }
            if hit {
                out.push(sorted(self.link_names[a].clone(), self.name(o)));
                if first {
                    break;
                }
            }
        }
        out.sort();
        Ok(out)
    }

    /// Whether any tested pair touches at configuration `q` (stops at the first).
    pub fn collides(&self, q: &[f64], against: Against) -> Result<bool, Error> {
        let hits = self.scan(q, against, true, 0.0, |t| t.touches())?;
        Ok(!hits.is_empty())
    }

    /// Every touching pair at `q`, each pair's names sorted and the list sorted.
    pub fn colliding_pairs(
        &self,
        q: &[f64],
        against: Against,
    ) -> Result<Vec<(String, String)>, Error> {
        self.scan(q, against, false, 0.0, |t| t.touches())
    }

    /// Every pair within distance `c` at `q` (exact, closed: exactly `c` counts), sorted as
    /// [`colliding_pairs`](Self::colliding_pairs). `c` must be a finite number `>= 0`.
    pub fn pairs_within_distance(
        &self,
        q: &[f64],
        c: f64,
        against: Against,
    ) -> Result<Vec<(String, String)>, Error> {
        if !(c.is_finite() && c >= 0.0) {
            return Err(Error::InvalidClearance { value: c });
        }
        self.scan(q, against, false, c, |t| t.within(c))
    }

    /// The nearest tested pair at `q` and its certified distance (`None` when nothing is
    /// tested). Pairs whose boxes are proved farther than the best so far are skipped. A
    /// part pair the primitives cannot yet measure (a cylinder against most shapes) is
    /// [`Error::UnsupportedPair`] when it has to be examined.
    pub fn nearest(&self, q: &[f64], against: Against) -> Result<Option<NearestPair>, Error> {
        let posed = self.pose_parts(q)?;
        let mut best: Option<(usize, Other, CertifiedDistance)> = None;
        // The least lower end `distance - error_bound` over every examined part pair.
        let mut lowest = f64::INFINITY;
        for (a, o) in self.units(against) {
            let others = self.members(&posed, o);
            for k in self.link_parts[a].clone() {
                let mine = (&self.parts[k].geometry, &posed.parts[k]);
                for &theirs in &others {
                    let bound = best.as_ref().map_or(f64::INFINITY, |b| b.2.distance);
                    if box_gap_lower(&mine.1.bbox, &theirs.1.bbox) >= bound {
                        continue;
                    }
                    let d = PairTest {
                        a: mine,
                        b: theirs,
                        solid: self.solid,
                    }
                    .distance()?;
                    lowest = lowest.min(d.distance - d.error_bound);
                    if d.distance < bound {
                        best = Some((a, o, d));
                    }
                }
            }
        }
        Ok(best.map(|(a, o, mut d)| {
            // Skipped pairs are at least the best distance away; examined ones at least
            // `lowest`: the bound covers both.
            d.error_bound = d.error_bound.max(d.distance - lowest);
            let (na, nb) = (self.link_names[a].clone(), self.name(o));
            if na <= nb {
                NearestPair {
                    pair: (na, nb),
                    distance: d,
                }
            } else {
                std::mem::swap(&mut d.witness_a, &mut d.witness_b);
                d.triangles = d.triangles.map(|(i, j)| (j, i));
                NearestPair {
                    pair: (nb, na),
                    distance: d,
                }
            }
        }))
    }

    /// [`collides`](Self::collides) for many configurations, spread over the cores; the first
    /// refused configuration is [`Error::InBatch`] with its index.
    pub fn collides_batch<Q: AsRef<[f64]> + Sync>(
        &self,
        qs: &[Q],
        against: Against,
    ) -> Result<Vec<bool>, Error> {
        over_batch(qs, |q| self.collides(q.as_ref(), against))
    }

    /// [`colliding_pairs`](Self::colliding_pairs) for many configurations, over the cores.
    pub fn colliding_pairs_batch<Q: AsRef<[f64]> + Sync>(
        &self,
        qs: &[Q],
        against: Against,
    ) -> Result<Vec<Vec<(String, String)>>, Error> {
        over_batch(qs, |q| self.colliding_pairs(q.as_ref(), against))
    }

    /// [`pairs_within_distance`](Self::pairs_within_distance) for many configurations.
    pub fn pairs_within_distance_batch<Q: AsRef<[f64]> + Sync>(
        &self,
        qs: &[Q],
        c: f64,
        against: Against,
    ) -> Result<Vec<Vec<(String, String)>>, Error> {
        over_batch(qs, |q| self.pairs_within_distance(q.as_ref(), c, against))
    }

    /// [`nearest`](Self::nearest) for many configurations.
    pub fn nearest_batch<Q: AsRef<[f64]> + Sync>(
        &self,
        qs: &[Q],
        against: Against,
    ) -> Result<Vec<Option<NearestPair>>, Error> {
        over_batch(qs, |q| self.nearest(q.as_ref(), against))
    }
}

fn sorted(a: String, b: String) -> (String, String) {
    if a <= b {
        (a, b)
    } else {
        (b, a)
    }
}
