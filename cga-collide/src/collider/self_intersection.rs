//! Self-intersection of one mesh: every pair of triangles that meet anywhere other than in
//! the vertices or the edge they share. Exact, with the hierarchy, in parallel.
//!
//! # Semantics
//! Two triangles *share* the vertex positions they have in common (exact `f64` equality of the
//! coordinates, so unwelded meshes, e.g. from STL, behave like welded ones). A pair is reported
//! when the intersection `K` of the two closed triangles is more than the shared set `S`:
//! * nothing shared: `K` is not empty (the exact triangle–triangle test);
//! * one shared vertex `v`: `K ≠ {v}`. Every ray from `v` into a triangle leaves it through the
//!   opposite edge, so `K ≠ {v}` exactly when the opposite edge of one triangle meets the
//!   other (for a degenerate triangle, a segment through `v`, the far end points play the
//!   role of the opposite edge);
//! * one shared edge `uv`: `K ≠ [u, v]`. For non-degenerate triangles this happens exactly when
//!   they are coplanar (`orient3d = 0`) and their third vertices lie on the same side of
//!   `uv` (they overlap or fold onto each other); a degenerate triangle next to a
//!   non-degenerate one meets it only in `[u, v]`; two degenerate ones overlap beyond `u` or
//!   `v` when both extend past the same end;
//! * all three positions shared (a duplicated triangle): reported unless degenerate.

use core::cmp::Ordering::{Equal, Greater};
use std::ops::ControlFlow;

use crate::bounding::Aabb;
use crate::collider::{Collider, Mode};
use crate::exact::predicates::EdgeSide;
use crate::exact::{ExactKernel, ExactPlane, Kernel, PlaneSide};
use crate::parallel::*;
use crate::query::intersects::{
    extremes, segment_meets_triangle, segment_meets_triangle_with_sides, segments_meet,
    triangles_meet,
};

type P3 = [f64; 3];

/// A part of a triangle around a shared vertex `v`, with its far set (where every ray from `v`
/// into the part leaves it): the triangle itself and its edge opposite `v`, or, for a
/// degenerate triangle, a segment from `v` to an extreme point and that point. Segments and
/// points stay segments: the exact tests are fast on them, while a degenerate triangle's plane
/// would send every side test to exact arithmetic.
#[derive(Clone, Copy)]
enum Piece {
    Tri([P3; 3], [P3; 2]),
    Seg([P3; 2], P3),
}

impl Piece {
    /// The far set, as a segment (a point is a segment of length zero).
    fn far(&self) -> (P3, P3) {
        match self {
            Piece::Tri(_, [x, y]) => (*x, *y),
            Piece::Seg(_, e) => (*e, *e),
        }
    }

    /// Whether the closed segment `ab` meets this part.
    fn met_by(&self, (a, b): (P3, P3)) -> bool {
        match self {
            Piece::Tri(t, _) => segment_meets_triangle(&a, &b, t),
            Piece::Seg([c, d], _) => segments_meet(&a, &b, c, d),
        }
    }
}

/// The parts of triangle `t` (degenerate or not, as given) around its vertex `v`: one for a
/// triangle, one or two segments for a degenerate one.
fn pieces(t: &[P3; 3], v: &P3, degenerate: bool) -> [Option<Piece>; 2] {
    if !degenerate {
        let [x, y] = opposite(t, v);
        return [Some(Piece::Tri(*t, [*x, *y])), None];
    }
    let (p, q) = extremes(t);
    [p, q].map(|e| (e != *v).then_some(Piece::Seg([*v, e], e)))
}

/// The corners of `t` other than `v` (`v` again where `t` repeats it).
fn opposite<'a>(t: &'a [P3; 3], v: &'a P3) -> [&'a P3; 2] {
    let mut far = t.iter().filter(|x| *x != v);
    [far.next().unwrap_or(v), far.next().unwrap_or(v)]
}

/// Whether triangles sharing exactly the vertex `v` meet anywhere else.
fn meet_beyond_vertex(plane_p: &ExactPlane, plane_q: &ExactPlane, v: &P3) -> bool {
    // The far corners' sides against the other plane once: most neighbours around a vertex of
    // a surface are told apart by these two or four signs, and the rest reuse them.
    let (p, q) = (plane_p.corners(), plane_q.corners());
    let (far_p, far_q) = (opposite(p, v), opposite(q, v));
    let sides_p = [plane_q.side(far_p[0]), plane_q.side(far_p[1])];
    if strictly_one_side(sides_p) {
        return false;
    }
    let sides_q = [plane_p.side(far_q[0]), plane_p.side(far_q[1])];
    if strictly_one_side(sides_q) {
        return false;
    }
    let (degenerate_p, degenerate_q) = (plane_p.is_degenerate(), plane_q.is_degenerate());
    if degenerate_p || degenerate_q {
        return meet_beyond_vertex_degenerate(
            &pieces(p, v, degenerate_p),
            &pieces(q, v, degenerate_q),
        );
    }
    // Non-degenerate: the far edge of one meets the other (see the module docs).
    segment_meets_triangle_with_sides(far_p[0], far_p[1], sides_p, q, plane_q)
        || segment_meets_triangle_with_sides(far_q[0], far_q[1], sides_q, p, plane_p)
}

/// Two signs, nonzero and equal.
#[inline]
fn strictly_one_side(s: [core::cmp::Ordering; 2]) -> bool {
    s[0] != Equal && s[0] == s[1]
}

/// [`meet_beyond_vertex`] when a triangle is degenerate: its parts around `v` (segments).
fn meet_beyond_vertex_degenerate(pp: &[Option<Piece>; 2], pq: &[Option<Piece>; 2]) -> bool {
    pp.iter().flatten().any(|part_p| {
        pq.iter()
            .flatten()
            .any(|part_q| part_q.met_by(part_p.far()) || part_p.met_by(part_q.far()))
    })
}

/// Whether triangles sharing exactly the edge `uv` meet anywhere else.
fn meet_beyond_edge(plane_p: &ExactPlane, plane_q: &ExactPlane, u: &P3, v: &P3) -> bool {
    let (p, q) = (plane_p.corners(), plane_q.corners());
    let third = |t: &[P3; 3]| *t.iter().find(|x| *x != u && *x != v).unwrap_or(u);
    let (a, b) = (third(p), third(q));
    if !plane_p.is_degenerate() {
        // `b` off the plane of `p`: `q` is not degenerate (`b` is off the line `uv`) and meets
        // that plane only in `[u, v]`. One sign decides most edges of a surface.
        if plane_p.side(&b) != Equal {
            return false;
        }
        // Coplanar: they overlap when the third vertices lie on the same side of `uv`; a
        // degenerate `q` (on the line `uv`) meets `p` only in `[u, v]`.
        return !plane_q.is_degenerate()
            && ExactKernel::sign::<EdgeSide, 12>(&[
                u[0], u[1], u[2], v[0], v[1], v[2], a[0], a[1], a[2], b[0], b[1], b[2],
            ]) == Greater;
    }
    if !plane_q.is_degenerate() {
        // A degenerate `p` (on the line `uv`) meets `q` only in `[u, v]`.
        return false;
    }
    // All on the line `uv`: both extend past the same end.
    let k = (0..3).find(|&k| u[k] != v[k]).unwrap_or(0);
    let (lo, hi) = (u[k].min(v[k]), u[k].max(v[k]));
    (a[k] > hi && b[k] > hi) || (a[k] < lo && b[k] < lo)
}

/// Whether two triangles of one mesh, given by their planes, meet anywhere other than in what
/// they share (see the module docs), exactly.
pub(crate) fn meet_elsewhere(plane_p: &ExactPlane, plane_q: &ExactPlane) -> bool {
    let (p, q) = (plane_p.corners(), plane_q.corners());
    // The distinct positions of `p` that `q` has too (no allocation: this runs for every
    // candidate pair).
    let mut shared = [&p[0]; 3];
    let mut n = 0;
    for (k, x) in p.iter().enumerate() {
        if q.contains(x) && !p[..k].contains(x) {
            shared[n] = x;
            n += 1;
        }
    }
    match n {
        0 => triangles_meet(plane_p, plane_q),
        1 => meet_beyond_vertex(plane_p, plane_q, shared[0]),
        2 => meet_beyond_edge(plane_p, plane_q, shared[0], shared[1]),
        _ => !plane_p.is_degenerate(),
    }
}

/// The exact box of three corners.
fn corner_box(t: &[P3; 3]) -> Aabb {
    let mut b = Aabb {
        min: t[0],
        max: t[0],
    };
    for p in &t[1..] {
        for (k, &x) in p.iter().enumerate() {
            b.min[k] = b.min[k].min(x);
            b.max[k] = b.max[k].max(x);
        }
    }
    b
}

/// Meshes up to this many triangles keep every triangle's plane for the whole search (128
/// bytes each: at most 128 MiB); larger ones make the two planes of each candidate pair anew.
const PLANE_CACHE_MAX: usize = 1 << 20;

/// The planes of the triangles of a collider by tree slot (position in the tree's order, so
/// that the pairs of one subtree read nearby memory), kept or made on demand.
enum Planes<'a> {
    Kept(Vec<ExactPlane>),
    OnDemand(&'a Collider),
}

impl<'a> Planes<'a> {
    fn of(collider: &'a Collider) -> Self {
        let order = collider.bvh().order();
        if order.len() > PLANE_CACHE_MAX {
            return Planes::OnDemand(collider);
        }
        // Made once per triangle instead of once per candidate pair (each triangle has about
        // ten neighbours whose boxes overlap its own).
        let plane = |&i: &u32| ExactPlane::new(&collider.corners(i));
        Planes::Kept(if crate::parallel::threads() == 1 || order.len() < 4096 {
            // Cheaper than the parallel machinery where it cannot pay off.
            order.iter().map(plane).collect()
        } else {
            order.par_iter().map(plane).collect()
        })
    }

    /// [`meet_elsewhere`] for the triangles in two slots.
    #[inline(always)]
    fn meet_elsewhere(&self, a: u32, b: u32) -> bool {
        match self {
            Planes::Kept(planes) => meet_elsewhere(&planes[a as usize], &planes[b as usize]),
            Planes::OnDemand(collider) => {
                let plane = |slot: u32| {
                    ExactPlane::new(&collider.corners(collider.bvh().order()[slot as usize]))
                };
                meet_elsewhere(&plane(a), &plane(b))
            }
        }
    }
}

impl Collider {
    /// Every pair `(i, j)`, `i < j`, of triangles of the mesh that meet anywhere other than in
    /// the vertices or the edge they share (see the module docs), sorted. With [`Mode::Bvh`]
    /// the tree enumerates the pairs whose boxes overlap; with [`Mode::Brute`] every pair is
    /// tested; either way they are decided in parallel, and the answers are identical.
    /// A rigid pose does not change the answer, so there is no `_at` twin.
    ///
    /// ```
    /// use cga_collide::{nalgebra::Point3, Collider, TriMesh};
    /// // A closed cube has no self-intersection...
    /// let cube = TriMesh::cuboid(Point3::origin(), Point3::new(1., 1., 1.))?;
    /// assert!(Collider::new(cube).self_intersections().is_empty());
    /// // ...a fold does: two triangles on the edge 0-1, the second folded onto the first.
    /// let p = |x, y| Point3::new(x, y, 0.0);
    /// let fold = TriMesh::new(vec![p(0., 0.), p(2., 0.), p(1., 1.), p(1., 2.)],
    ///                         vec![[0, 1, 2], [1, 0, 3]])?;
    /// let fold = Collider::new(fold);
    /// assert_eq!(fold.self_intersections(), vec![(0, 1)]);
    /// assert!(fold.self_intersects());
    /// # Ok::<(), cga_collide::Error>(())
    /// ```
    pub fn self_intersections(&self) -> Vec<(u32, u32)> {
        if self.mode() == Mode::Brute {
            return self.self_intersections_brute();
        }
        if !self.has_bvh() {
            return self.self_intersections_small();
        }
        let planes = Planes::of(self);
        if crate::parallel::threads() == 1 {
            // One thread: decide each pair as the tree yields it (no candidate buffer).
            let (mut out, order) = (Vec::new(), self.bvh().order());
            let _ = self.bvh().for_each_self_pair_slot::<()>(|a, b| {
                if planes.meet_elsewhere(a, b) {
                    let (i, j) = (order[a as usize], order[b as usize]);
                    out.push((i.min(j), i.max(j)));
                }
                ControlFlow::Continue(())
            });
            out.sort_unstable();
            return out;
        }
        let mut candidates = Vec::new();
        let _ = self.bvh().for_each_self_pair_slot::<()>(|a, b| {
            candidates.push((a, b));
            ControlFlow::Continue(())
        });
        let order = self.bvh().order();
        let mut out: Vec<(u32, u32)> = candidates
            .par_iter()
            .filter(|&&(a, b)| planes.meet_elsewhere(a, b))
            .map(|&(a, b)| {
                let (i, j) = (order[a as usize], order[b as usize]);
                (i.min(j), i.max(j))
            })
            .collect();
        out.sort_unstable();
        out
    }

    /// Whether any two triangles of the mesh meet anywhere other than in what they share (stops
    /// at the first such pair). See [`self_intersections`](Self::self_intersections).
    pub fn self_intersects(&self) -> bool {
        if self.mode() == Mode::Brute {
            return !self.self_intersections_brute().is_empty();
        }
        if !self.has_bvh() {
            return !self.self_intersections_small().is_empty();
        }
        // Stops early: planes made per candidate pair, not for the whole mesh up front.
        let planes = Planes::OnDemand(self);
        self.bvh()
            .for_each_self_pair_slot(|a, b| {
                if planes.meet_elsewhere(a, b) {
                    ControlFlow::Break(())
                } else {
                    ControlFlow::Continue(())
                }
            })
            .is_break()
    }

    /// A tiny mesh whose tree was never built (fewer than 32 triangles): every pair, after an
    /// exact comparison of their boxes (the pairs the tree would have enumerated), in order.
    fn self_intersections_small(&self) -> Vec<(u32, u32)> {
        let n = self.mesh().num_triangles() as u32;
        if n < 2 {
            return Vec::new();
        }
        let planes: Vec<ExactPlane> = (0..n).map(|i| ExactPlane::new(&self.corners(i))).collect();
        let boxes: Vec<Aabb> = planes.iter().map(|p| corner_box(p.corners())).collect();
        let mut out = Vec::new();
        for i in 0..n as usize {
            for j in i + 1..n as usize {
                if boxes[i].overlaps(&boxes[j]) && meet_elsewhere(&planes[i], &planes[j]) {
                    out.push((i as u32, j as u32));
                }
            }
        }
        out
    }

    /// Every pair tested, in parallel, with no tree and no box filter.
    fn self_intersections_brute(&self) -> Vec<(u32, u32)> {
        let n = self.mesh().num_triangles() as u32;
        let mut out: Vec<(u32, u32)> = (0..n)
            .into_par_iter()
            .flat_map_iter(|i| {
                let pi = ExactPlane::new(&self.corners(i));
                (i + 1..n).filter_map(move |j| {
                    meet_elsewhere(&pi, &ExactPlane::new(&self.corners(j))).then_some((i, j))
                })
            })
            .collect();
        out.sort_unstable();
        out
    }
}
