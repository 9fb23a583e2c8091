//! Motion between two configurations, straight in joint space: certified free over the whole
//! motion, or a configuration along it that collides (with its time), or, when the budget
//! runs out first, a typed "undecided" that says how far the motion is certified.
//!
//! The motion `q(t) = (1 - t) q0 + t q1`, `t` in `[0, 1]`, is split in halves, earliest
//! stretch first. On a stretch `[a, b]`, every part is placed at the middle configuration and
//! each link gets a bound `δ` on how far any of its points moves from there over the stretch
//! ([`motion_bound`](super::motion_bound)); a pair (of links, or of a link and an environment
//! object, which does not move) whose parts are not within `δ_a + δ_b` of each other (the
//! exact, closed `within_distance` test) cannot touch anywhere on the stretch, and is dropped
//! from its halves. A stretch with no pair left is certified free. Every sample is an exact
//! test of the placed parts, so a reported collision is a real one, and a contact between
//! samples is never missed: a stretch is only called free by the bound.

use std::borrow::Cow;

use super::geometry::{Geometry, PairTest, Placed};
use super::motion_bound::{along, LinkSweep};
use super::queries::Posed;
use super::{Against, Robot};
use crate::error::Error;
use crate::parallel::over_batch;
use crate::shape::{Capsule, Shape};

/// How a motion is checked: against what, how finely at most, and how much work at most.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotionOptions {
    /// What the robot is checked against along the motion.
    pub against: Against,
    /// The shortest stretch of the motion (a fraction of it, in `(0, 1]`) that is still
    /// split in halves: a stretch this short that is neither certified free nor found
    /// colliding at its middle leaves the answer [`MotionAnswer::Undecided`] unless a
    /// collision is found later on.
    pub resolution: f64,
    /// The most configurations placed and tested (at least 1); past it the answer is
    /// [`MotionAnswer::Undecided`] unless a collision was found.
    pub max_configurations: usize,
}

impl Default for MotionOptions {
    /// Against the robot itself, stretches down to `1e-6` of the motion, at most 100,000
    /// configurations.
    fn default() -> Self {
        MotionOptions {
            against: Against::Itself,
            resolution: 1e-6,
            max_configurations: 100_000,
        }
    }
}

/// Which budget left a motion undecided.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum MotionLimit {
    /// A stretch as short as [`MotionOptions::resolution`] could be neither certified free
    /// nor found colliding (the links graze something, or pass within rounding of it).
    Resolution,
    /// [`MotionOptions::max_configurations`] were tested.
    Configurations,
}

/// The answer about a straight motion from `q0` (time 0) to `q1` (time 1).
#[derive(Debug, Clone, PartialEq)]
pub enum MotionAnswer {
    /// No tested pair touches at any configuration of the motion (certified).
    Free,
    /// The configuration at `time` collides (the exact test at that configuration); every
    /// configuration before `free_until` is certified free, so the first contact lies in
    /// `[free_until, time]`. A collision at `q0` is `time = free_until = 0`.
    Collides {
        /// The time along the motion, in `[0, 1]`.
        time: f64,
        /// The configuration at that time, `(1 - time) q0 + time q1`.
        configuration: Vec<f64>,
        /// Every touching pair at that configuration, names sorted within each pair and the
        /// list sorted (as [`Robot::colliding_pairs`]).
        pairs: Vec<(String, String)>,
        /// The motion is certified free before this time (`free_until <= time`).
        free_until: f64,
    },
    /// The budget ran out before the motion was decided: it is certified free on
    /// `[0, free_until]`, and no colliding configuration was found.
    Undecided {
        /// The motion is certified free up to this time.
        free_until: f64,
        /// Which budget ran out.
        limit: MotionLimit,
    },
}

impl MotionAnswer {
    /// Whether the motion is certified free.
    pub fn is_free(&self) -> bool {
        matches!(self, MotionAnswer::Free)
    }
}

/// The second member of a tested pair.
#[derive(Debug, Clone, Copy)]
enum Member {
    Link(usize),
    Env(usize),
}

type Unit = (usize, Member);

/// What a stretch's search ended with.
enum Step {
    /// Certified free.
    Free,
    /// Not decided somewhere (a stretch at the resolution), no collision found.
    Open,
    /// A collision at this time, with its pairs.
    Hit(f64, Vec<(String, String)>),
    /// The configuration budget ran out.
    Stop,
}

struct Search<'a> {
    robot: &'a Robot,
    q0: &'a [f64],
    q1: &'a [f64],
    sweeps: &'a [LinkSweep],
    options: &'a MotionOptions,
    configurations: usize,
    free_until: f64,
    open: Option<MotionLimit>,
}

impl Search<'_> {
    /// Searches `[a, b]` for the earliest collision among `units`; `a`'s side is searched
    /// first, so every stretch before the current one is decided when it is reached.
    fn stretch(&mut self, a: f64, b: f64, units: &[Unit]) -> Result<Step, Error> {
        if self.configurations >= self.options.max_configurations {
            self.open = Some(MotionLimit::Configurations);
            return Ok(Step::Stop);
        }
        self.configurations += 1;
        let m = a + (b - a) / 2.0;
        let (qa, qb, qm) = (
            along(self.q0, self.q1, a),
            along(self.q0, self.q1, b),
            along(self.q0, self.q1, m),
        );
        let posed = self.robot.pose_parts(&qm)?;
        let reach = |l: usize| self.sweeps[l].bound(&qa, &qb);
        let mut alive = Vec::new();
        for &(l, o) in units {
            let c = reach(l)
                + match o {
                    Member::Link(k) => reach(k),
                    Member::Env(_) => 0.0,
                };
            if self.robot.may_meet(&posed, l, o, c)? {
                alive.push((l, o));
            }
        }
        if alive.is_empty() {
            if self.open.is_none() {
                self.free_until = b;
            }
            return Ok(Step::Free);
        }
        if b - a <= self.options.resolution {
            let hits = self.robot.touching(&posed, &alive)?;
            if !hits.is_empty() {
                return Ok(Step::Hit(m, hits));
            }
            self.open.get_or_insert(MotionLimit::Resolution);
            return Ok(Step::Open);
        }
        let left = self.stretch(a, m, &alive)?;
        if matches!(left, Step::Hit(..) | Step::Stop) {
            return Ok(left);
        }
        // A free left half covers its closed end `m`; otherwise `m` is tested here.
        if matches!(left, Step::Open) {
            let hits = self.robot.touching(&posed, &alive)?;
            if !hits.is_empty() {
                return Ok(Step::Hit(m, hits));
            }
        }
        drop(posed);
        match self.stretch(m, b, &alive)? {
            Step::Free if matches!(left, Step::Open) => Ok(Step::Open),
            right => Ok(right),
        }
    }
}

/// A round part grown to a capsule around its axis (a superset), for the clearance test that
/// certifies a stretch: the exact clearance of cylinders and cones is not available for every
/// pair, a capsule's is.
fn rounded(p: &Placed) -> Result<Cow<'_, Placed>, Error> {
    let capsule = match &p.shape {
        Some(Shape::Cylinder(c)) => Capsule::new(*c.a(), *c.b(), c.radius())?,
        Some(Shape::Cone(c)) => Capsule::new(*c.apex(), *c.base(), c.radius())?,
        _ => return Ok(Cow::Borrowed(p)),
    };
    Ok(Cow::Owned(Placed {
        shape: Some(capsule.into()),
        ..p.clone()
    }))
}

impl Robot {
    /// The pairs a motion is checked for, self pairs first (as the configuration questions).
    fn motion_units(&self, against: Against) -> Vec<Unit> {
        let mut out = Vec::new();
        if against != Against::Environment {
            out.extend(self.pairs.iter().map(|&(a, b)| (a, Member::Link(b))));
        }
        if against != Against::Itself {
            for (l, r) in self.link_parts.iter().enumerate() {
                if !r.is_empty() {
                    out.extend((0..self.environment.len()).map(|e| (l, Member::Env(e))));
                }
            }
        }
        out
    }

    fn member_parts<'a>(&'a self, posed: &'a Posed, o: Member) -> Vec<(&'a Geometry, &'a Placed)> {
        match o {
            Member::Link(l) => self.link_parts[l]
                .clone()
                .map(|k| (&self.parts[k].geometry, &posed.parts[k]))
                .collect(),
            Member::Env(e) => {
                let obj = &self.environment[e];
                vec![(&obj.geometry, &obj.placed)]
            }
        }
    }

    /// Whether some part pair of link `l` and `o` may come within `c` of each other
    /// (exact, closed; conservative for cylinders and cones, grown to capsules), or touches
    /// (a part held inside a solid mesh is farther than `c` from its surface but touches it).
    fn may_meet(&self, posed: &Posed, l: usize, o: Member, c: f64) -> Result<bool, Error> {
        let others = self.member_parts(posed, o);
        for k in self.link_parts[l].clone() {
            let mine = (&self.parts[k].geometry, &posed.parts[k]);
            for &theirs in &others {
                if mine.1.apart(theirs.1, c) {
                    continue;
                }
                let exact = PairTest {
                    a: mine,
                    b: theirs,
                    solid: self.solid,
                };
                if c == 0.0 {
                    // Neither moves: the stretch is as its middle.
                    if exact.touches()? {
                        return Ok(true);
                    }
                    continue;
                }
                let (pa, pb) = (rounded(mine.1)?, rounded(theirs.1)?);
                let grown = PairTest {
                    a: (mine.0, &*pa),
                    b: (theirs.0, &*pb),
                    solid: self.solid,
                };
                if grown.within(c)? || (self.solid && exact.touches()?) {
                    return Ok(true);
                }
            }
        }
        Ok(false)
    }

    /// Every pair of `units` that touches at the posed configuration, sorted.
    fn touching(&self, posed: &Posed, units: &[Unit]) -> Result<Vec<(String, String)>, Error> {
        let mut out = Vec::new();
        for &(l, o) in units {
            let others = self.member_parts(posed, o);
            let mut hit = false;
            'parts: for k in self.link_parts[l].clone() {
                let mine = (&self.parts[k].geometry, &posed.parts[k]);
                for &theirs in &others {
                    if mine.1.apart(theirs.1, 0.0) {
                        continue;
                    }
                    let test = PairTest {
                        a: mine,
                        b: theirs,
                        solid: self.solid,
                    };
                    if test.touches()? {
                        hit = true;
                        break 'parts;
                    }
                }
            }
            if hit {
                let a = self.link_names[l].clone();
                let b = match o {
                    Member::Link(k) => self.link_names[k].clone(),
                    Member::Env(e) => format!("env:{}", self.environment[e].id.index()),
                };
                out.push(if a <= b { (a, b) } else { (b, a) });
            }
        }
        out.sort();
        Ok(out)
    }

    /// The straight motion from `q0` to `q1` in joint space: certified free, the earliest
    /// colliding configuration found (with its time and every touching pair there), or
    /// undecided within the options' budget (see [Motion](crate::robot#motion)). `q0` and
    /// `q1` are configurations as for [`collides`](Self::collides); the options must have a
    /// resolution in `(0, 1]` and at least one configuration.
    pub fn motion_collision(
        &self,
        q0: &[f64],
        q1: &[f64],
        options: &MotionOptions,
    ) -> Result<MotionAnswer, Error> {
        check_options(options)?;
        let sweeps = self.link_sweeps()?;
        self.motion_with(q0, q1, options, &sweeps)
    }

    /// [`motion_collision`](Self::motion_collision) for many motions `(q0, q1)`, spread over
    /// the cores; the first refused motion is [`Error::InBatch`] with its index.
    pub fn motion_collision_batch<Q: AsRef<[f64]> + Sync>(
        &self,
        motions: &[(Q, Q)],
        options: &MotionOptions,
    ) -> Result<Vec<MotionAnswer>, Error> {
        check_options(options)?;
        let sweeps = self.link_sweeps()?;
        over_batch(motions, |(q0, q1)| {
            self.motion_with(q0.as_ref(), q1.as_ref(), options, &sweeps)
        })
    }

    fn motion_with(
        &self,
        q0: &[f64],
        q1: &[f64],
        options: &MotionOptions,
        sweeps: &[LinkSweep],
    ) -> Result<MotionAnswer, Error> {
        let units = self.motion_units(options.against);
        let collides_at = |time: f64, q: &[f64]| -> Result<Option<MotionAnswer>, Error> {
            let pairs = self.touching(&self.pose_parts(q)?, &units)?;
            Ok((!pairs.is_empty()).then(|| MotionAnswer::Collides {
                time,
                configuration: q.to_vec(),
                pairs,
                free_until: 0.0,
            }))
        };
        if let Some(hit) = collides_at(0.0, q0)? {
            return Ok(hit);
        }
        // The end is checked here so that a bad `q1` is refused before any search.
        self.link_poses(q1)?;
        let mut search = Search {
            robot: self,
            q0,
            q1,
            sweeps,
            options,
            configurations: 1,
            free_until: 0.0,
            open: None,
        };
        let step = search.stretch(0.0, 1.0, &units)?;
        let free_until = search.free_until;
        Ok(match step {
            Step::Free => MotionAnswer::Free,
            Step::Hit(time, pairs) => MotionAnswer::Collides {
                time,
                configuration: along(q0, q1, time),
                pairs,
                free_until,
            },
            Step::Open | Step::Stop => match collides_at(1.0, q1)? {
                Some(MotionAnswer::Collides {
                    time,
                    configuration,
                    pairs,
                    ..
                }) => MotionAnswer::Collides {
                    time,
                    configuration,
                    pairs,
                    free_until,
                },
                _ => MotionAnswer::Undecided {
                    free_until,
                    limit: search.open.unwrap_or(MotionLimit::Configurations),
                },
            },
        })
    }
}

fn check_options(options: &MotionOptions) -> Result<(), Error> {
    let r = options.resolution;
    if !(r.is_finite() && r > 0.0 && r <= 1.0) {
        return Err(Error::Configuration {
            reason: format!("motion resolution must be a number in (0, 1], got {r}"),
        });
    }
    if options.max_configurations == 0 {
        return Err(Error::Configuration {
            reason: "motion max_configurations must be at least 1".to_string(),
        });
    }
    Ok(())
}
