//! The questions at a configuration: forward kinematics once, every part placed once, then
//! each tested pair of links (or link and environment object) set aside by its world boxes or
//! decided by the exact test of its parts.

use std::collections::BinaryHeap;

use crate::collider::Bounded;
use crate::error::Error;
use crate::parallel::over_batch;
use crate::query::{self, CertifiedDistance};

use super::geometry::{box_gap_lower, boxes_within, place, Geometry, PairTest, Placed};
use super::spheres::Sphere;
use super::staged::Staged;
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

/// Every part placed at one configuration (the view of checks that need them all; the
/// questions here place parts on demand, [`Staged`]).
#[cfg_attr(not(test), allow(dead_code))]
pub(super) struct Posed {
    pub(super) parts: Vec<Placed>,
}

impl Robot {
    #[cfg_attr(not(test), allow(dead_code))]
    pub(super) fn pose_parts(&self, q: &[f64]) -> Result<Posed, Error> {
        let links = self.link_poses(q)?;
        let parts = self
            .parts
            .iter()
            .map(|p| place(&p.geometry, links[p.link] * p.local))
            .collect::<Result<Vec<_>, Error>>()?;
        Ok(Posed { parts })
    }

    /// The tested pairs, self pairs first, then link × environment object (no allocation).
    fn units(&self, against: Against) -> impl Iterator<Item = (usize, Other)> + '_ {
        let own = (against != Against::Environment)
            .then(|| self.pairs.iter().map(|&(a, b)| (a, Other::Link(b))))
            .into_iter()
            .flatten();
        let env = (against != Against::Itself)
            .then(|| {
                self.link_parts
                    .iter()
                    .enumerate()
                    .filter(|(_, r)| !r.is_empty())
                    .flat_map(move |(l, _)| {
                        (0..self.environment.len()).map(move |e| (l, Other::Env(e)))
                    })
            })
            .into_iter()
            .flatten();
        own.chain(env)
    }

    /// How many pairs (of links, or of a link and an environment object) a question tests.
    pub fn pairs_checked(&self, against: Against) -> usize {
        self.units(against).count()
    }

    fn name(&self, o: Other) -> String {
        match o {
            Other::Link(l) => self.link_names[l].clone(),
            Other::Env(e) => format!("env:{}", self.environment[e].id.index()),
        }
    }

    /// How many parts the other member has.
    fn member_count(&self, o: Other) -> usize {
        match o {
            Other::Link(l) => self.link_parts[l].len(),
            Other::Env(_) => 1,
        }
    }

    /// The other member's `i`-th part, `(geometry, placed)` (its link placed already).
    fn member<'a>(&'a self, st: &'a Staged, o: Other, i: usize) -> (&'a Geometry, &'a Placed) {
        match o {
            Other::Link(l) => {
                let k = self.link_parts[l].start + i;
                (&self.parts[k].geometry, st.part(k))
            }
            Other::Env(e) => {
                let obj = &self.environment[e];
                (&obj.geometry, &obj.placed)
            }
        }
    }

    /// The other member's `i`-th part's world sphere.
    fn member_sphere(&self, st: &Staged, o: Other, i: usize) -> Sphere {
        match o {
            Other::Link(l) => st.part_sphere(self.link_parts[l].start + i),
            Other::Env(e) => self.environment[e].sphere,
        }
    }

    /// Places both members' parts unless their spheres are proved farther apart than
    /// `reach`; `false` when they are.
    fn stage_pair(&self, st: &mut Staged, a: usize, o: Other, reach: f64) -> Result<bool, Error> {
        let theirs = match o {
            Other::Link(b) => st.link_spheres[b],
            Other::Env(e) => Some(self.environment[e].sphere),
        };
        match (st.link_spheres[a], theirs) {
            (Some(sa), Some(sb)) if !sa.apart(&sb, reach) => {}
            _ => return Ok(false),
        }
        st.place_link(a)?;
        if let Other::Link(b) = o {
            st.place_link(b)?;
        }
        let other_box = match o {
            Other::Link(b) => st.link_box(b),
            Other::Env(e) => &self.environment[e].placed.bbox,
        };
        Ok(boxes_within(st.link_box(a), other_box, reach))
    }

    /// The tested pairs for which some part pair is not proved farther apart than `reach` by
    /// its spheres and boxes and passes `decide` (exact); stops after the first when `first`.
    fn scan(
        &self,
        q: &[f64],
        against: Against,
        first: bool,
        reach: f64,
        decide: impl Fn(&PairTest) -> Result<bool, Error>,
    ) -> Result<Vec<(String, String)>, Error> {
        let mut st = Staged::new(self, q)?;
        let mut out = Vec::new();
        for (a, o) in self.units(against) {
            if !self.stage_pair(&mut st, a, o, reach)? {
                continue;
            }
            let mut hit = false;
            'parts: for k in self.link_parts[a].clone() {
                let mine = (&self.parts[k].geometry, st.part(k));
                let sphere = st.part_sphere(k);
                for i in 0..self.member_count(o) {
                    if sphere.apart(&self.member_sphere(&st, o, i), reach) {
                        continue;
                    }
                    let theirs = self.member(&st, o, i);
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
        let mut st = Staged::new(self, q)?;
        // Best first over two levels: every tested pair (two links, or a link and an object)
        // enters with its link spheres' gap; when it comes up, its links are placed and its
        // part pairs enter with the larger of their spheres' and placed boxes' gap (the boxes
        // order long links' parts much better than their spheres). Every key is a proved
        // lower bound on the distance of what it stands for, so the search stops at the first
        // key at or past the best distance, having placed and measured only what could still
        // win, and the winning pair is usually measured first.
        let mut queue = BinaryHeap::new();
        let mut order = 0usize;
        let mut push = |queue: &mut BinaryHeap<Candidate>, gap: f64, a, o, part| {
            queue.push(Candidate {
                gap,
                order,
                a,
                o,
                part,
            });
            order += 1;
        };
        for (a, o) in self.units(against) {
            let theirs = match o {
                Other::Link(b) => st.link_spheres[b],
                Other::Env(e) => Some(self.environment[e].sphere),
            };
            // A link without geometry has no sphere and nothing to test.
            if let (Some(sa), Some(sb)) = (st.link_spheres[a], theirs) {
                push(&mut queue, sa.gap_lower(&sb), a, o, None);
            }
        }
        let mut best: Option<(usize, Other, CertifiedDistance)> = None;
        // The least lower end `distance - error_bound` over every examined part pair.
        let mut lowest = f64::INFINITY;
        while let Some(Candidate {
            gap, a, o, part, ..
        }) = queue.pop()
        {
            let bound = best.as_ref().map_or(f64::INFINITY, |b| b.2.distance);
            if gap >= bound {
                break;
            }
            let Some((k, i, refined)) = part else {
                st.place_link(a)?;
                if let Other::Link(b) = o {
                    st.place_link(b)?;
                }
                for k in self.link_parts[a].clone() {
                    let sphere = st.part_sphere(k);
                    for i in 0..self.member_count(o) {
                        let spheres = sphere.gap_lower(&self.member_sphere(&st, o, i));
                        let boxes = box_gap_lower(&st.part(k).bbox, &self.member(&st, o, i).1.bbox);
                        let key = gap.max(spheres).max(boxes);
                        push(&mut queue, key, a, o, Some((k, i, false)));
                    }
                }
                continue;
            };
            let mine = (&self.parts[k].geometry, st.part(k));
            let theirs = self.member(&st, o, i);
            // A pair whose certified distance is a long search (two cylinders) first gets a
            // short search's lower bound and goes back in line with it: cheaper pairs usually
            // bring the best distance under it, and it is never measured.
            if let (false, Some(sa), Some(sb)) = (refined, &mine.1.shape, &theirs.1.shape) {
                if let Some(lower) = query::shapes::distance_lower_bound(sa, sb) {
                    if lower > gap {
                        push(&mut queue, lower, a, o, Some((k, i, true)));
                        continue;
                    }
                }
            }
            let test = PairTest {
                a: mine,
                b: theirs,
                solid: self.solid,
            };
            // The best distance so far goes into the pair's own search: nothing proved
            // farther than it is examined there.
            match test.distance_below(bound)? {
                Bounded::Below(d) => {
                    lowest = lowest.min(d.distance - d.error_bound);
                    if d.distance < bound {
                        best = Some((a, o, d));
                    }
                }
                Bounded::AtLeast(at_least) => lowest = lowest.min(at_least),
            }
        }
        Ok(best.map(|(a, o, mut d)| {
            // Pairs skipped by a bound are at least the best distance away; searched ones at
            // least `lowest` (their certified lower end, or the lower bound their search
            // proved): the bound covers both.
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

/// An entry of [`Robot::nearest`]'s queue: a tested pair (`part: None`) or one of its part
/// pairs (part `k` of link `a` and the other member's `i`-th), with a proved lower
/// bound on its distance. The queue pops the least bound first, ties in the order pushed.
struct Candidate {
    gap: f64,
    order: usize,
    a: usize,
    o: Other,
    /// `(k, i, refined)`; `refined`: its gap is already a short search's bound.
    part: Option<(usize, usize, bool)>,
}

impl Ord for Candidate {
    fn cmp(&self, other: &Self) -> std::cmp::Ordering {
        // Reversed: `BinaryHeap` pops its greatest.
        other
            .gap
            .total_cmp(&self.gap)
            .then(other.order.cmp(&self.order))
    }
}

impl PartialOrd for Candidate {
    fn partial_cmp(&self, other: &Self) -> Option<std::cmp::Ordering> {
        Some(self.cmp(other))
    }
}

impl PartialEq for Candidate {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other).is_eq()
    }
}

impl Eq for Candidate {}

fn sorted(a: String, b: String) -> (String, String) {
    if a <= b {
        (a, b)
    } else {
        (b, a)
    }
}
