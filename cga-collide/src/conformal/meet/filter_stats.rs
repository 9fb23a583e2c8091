//! How often the certified filter of the meets decides alone, and how often plain `f64` signs
//! (no error bound, no fall-back) would classify wrongly, on a fixed adversarial set (test
//! support: the unit tests check it, `cga_collide::testing::conformal::filter_tallies` exposes
//! it and the CLI example `conformal_filter_table` prints it as a table).

use nalgebra::{Point3, Vector3};

use super::*;
use crate::conformal::{Line, Plane, Sphere};

/// One pair's counts (see [`filter_tallies`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct FilterTally {
    /// The pair, e.g. `"line–plane"`.
    pub pair: &'static str,
    /// Cases classified.
    pub cases: usize,
    /// Cases the certified `f64` filter decided alone.
    pub filtered: usize,
    /// Cases where plain `f64` signs classify differently from the exact answer.
    pub float_wrong: usize,
}

/// A small deterministic generator (64-bit LCG).
pub(crate) struct Lcg(pub(crate) u64);
impl Lcg {
    pub(crate) fn next(&mut self) -> u64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        self.0 >> 33
    }
    fn int(&mut self, lo: i64, hi: i64) -> f64 {
        (lo + (self.next() % ((hi - lo + 1) as u64)) as i64) as f64
    }
    fn point(&mut self) -> Point3<f64> {
        Point3::new(self.int(-3, 3), self.int(-3, 3), self.int(-3, 3))
    }
}

#[derive(Default, Debug)]
struct Tally {
    cases: usize,
    filtered: usize,
    float_wrong: usize,
}

impl Tally {
    fn named(self, pair: &'static str) -> FilterTally {
        FilterTally {
            pair,
            cases: self.cases,
            filtered: self.filtered,
            float_wrong: self.float_wrong,
        }
    }
}

fn tally<K: PartialEq>(t: &mut Tally, certified: Option<K>, float: Option<K>, exact: Option<K>) {
    t.cases += 1;
    t.filtered += usize::from(certified.is_some());
    if let Some(c) = &certified {
        assert!(
            Some(c) == exact.as_ref(),
            "certified filter disagrees with exact"
        );
    }
    t.float_wrong += usize::from(float != exact);
}

/// Tallies one case: the certified filter, plain `f64` and exact `Rational` run the same
/// classification function on the same arguments.
macro_rules! tally_kinds {
    ($t:expr, $kind:ident($($arg:expr),*)) => {
        tally(
            $t,
            $kind::<ErrF64>($($arg),*),
            $kind::<f64>($($arg),*),
            $kind::<Rational>($($arg),*),
        )
    };
}

fn scale(r: &mut Lcg) -> (f64, bool) {
    let k = [0, 0, 0, -30, 40, -500, 500][(r.next() % 7) as usize];
    (2f64.powi(k), r.next().is_multiple_of(4))
}

fn nudge(p: Point3<f64>, on: bool) -> Point3<f64> {
    let mut p = p;
    if on {
        p.z = if p.z == 0.0 {
            1e-300
        } else {
            p.z * (1.0 + f64::EPSILON)
        };
    }
    p
}

/// The counts for the six pairs, about `cases_per_pair` adversarial cases each (cases whose
/// primitives cannot be built are skipped). Panics if the certified filter ever disagrees with
/// the exact classification.
///
/// ```
/// let rows = cga_collide::testing::conformal::filter_tallies(100);
/// assert_eq!(rows[0].pair, "line–line");
/// assert!(rows.iter().map(|t| t.float_wrong).sum::<usize>() > 0);
/// ```
pub fn filter_tallies(cases_per_pair: usize) -> Vec<FilterTally> {
    let n = cases_per_pair;
    let mut r = Lcg(0x5eed);
    let mut rows = Vec::new();

    let mut t = Tally::default();
    for _ in 0..n {
        let (s, nu) = scale(&mut r);
        let a = r.point() * s;
        let d = r.point().coords;
        let b = match r.next() % 3 {
            0 => Line::from_point_direction(nudge(a + d * r.int(-2, 2) * s, nu), r.point().coords),
            1 => Line::from_point_direction(nudge(r.point() * s, nu), d * r.int(1, 3)),
            _ => Line::from_point_direction(nudge(r.point() * s, nu), r.point().coords),
        };
        let (Ok(la), Ok(lb)) = (Line::from_point_direction(a, d), b) else {
            continue;
        };
        tally_kinds!(
            &mut t,
            ll_kind(&la.blade_in(), &lb.blade_in(), lb.spanning_vectors())
        );
    }
    rows.push(t.named("line–line"));

    let mut t = Tally::default();
    for _ in 0..n {
        let (s, nu) = scale(&mut r);
        let (a, b, c) = (r.point() * s, r.point() * s, r.point() * s);
        let Ok(p) = Plane::from_points(a, b, c) else {
            continue;
        };
        let l = match r.next() % 3 {
            0 => Line::from_points(nudge(a + (b - a) * r.int(-2, 2), nu), c),
            1 => Line::from_point_direction(nudge(r.point() * s, nu), (b - a) * r.int(1, 2)),
            _ => Line::from_point_direction(nudge(r.point() * s, nu), r.point().coords),
        };
        let Ok(l) = l else { continue };
        tally_kinds!(&mut t, lp_kind(&l.blade_in(), &p.ipns_in()));
    }
    rows.push(t.named("line–plane"));

    let mut t = Tally::default();
    for _ in 0..n {
        let (s, nu) = scale(&mut r);
        let c = r.point();
        let rad = r.int(0, 3);
        let axis = (r.next() % 3) as usize;
        let mut u = Vector3::zeros();
        u[axis] = rad;
        let mut d = r.point().coords;
        d[axis] = 0.0;
        let Ok(l) = Line::from_point_direction(nudge((c + u) * s, nu), d) else {
            continue;
        };
        let sp = Sphere::from_centre_radius(c * s, rad * s).unwrap();
        tally_kinds!(&mut t, ls_kind(&l.blade_in(), &sp.ipns_in()));
    }
    rows.push(t.named("line–sphere"));

    let mut t = Tally::default();
    for _ in 0..n {
        let (s, nu) = scale(&mut r);
        let (a, b, c) = (r.point() * s, r.point() * s, r.point() * s);
        let Ok(p) = Plane::from_points(a, b, c) else {
            continue;
        };
        let q = match r.next() % 2 {
            0 => Plane::from_points(
                nudge(a + (b - a) * r.int(-2, 2), nu),
                b + (c - a),
                c + (b - a),
            ),
            _ => Plane::from_points(nudge(r.point() * s, nu), r.point() * s, r.point() * s),
        };
        let Ok(q) = q else { continue };
        tally_kinds!(&mut t, pp_kind(&p.ipns_in(), &q.ipns_in()));
    }
    rows.push(t.named("plane–plane"));

    let mut t = Tally::default();
    for _ in 0..n {
        let (s, nu) = scale(&mut r);
        let c = r.point();
        let rad = r.int(0, 3);
        let axis = (r.next() % 3) as usize;
        let mut nn = Vector3::zeros();
        nn[axis] = r.int(1, 3);
        let off = nn[axis] * (c[axis] + rad * r.int(-1, 1)) * s;
        let Ok(p) = Plane::from_normal_offset(nn, off) else {
            continue;
        };
        let sp = Sphere::from_centre_radius(nudge(c * s, nu), rad * s).unwrap();
        tally_kinds!(&mut t, sp_kind(&sp.ipns_in(), &p.ipns_in()));
    }
    rows.push(t.named("sphere–plane"));

    let mut t = Tally::default();
    for _ in 0..n {
        let (s, nu) = scale(&mut r);
        let c1 = r.point();
        let (r1, r2) = (r.int(0, 4), r.int(0, 4));
        let axis = (r.next() % 3) as usize;
        let mut e = Vector3::zeros();
        e[axis] = match r.next() % 3 {
            0 => r1 + r2,
            1 => (r1 - r2).abs(),
            _ => r.int(0, 6),
        };
        let a = Sphere::from_centre_radius(c1 * s, r1 * s).unwrap();
        let b = Sphere::from_centre_radius(nudge((c1 + e) * s, nu), r2 * s).unwrap();
        tally_kinds!(&mut t, ss_kind(&a.ipns_in(), &b.ipns_in()));
    }
    rows.push(t.named("sphere–sphere"));

    rows
}
