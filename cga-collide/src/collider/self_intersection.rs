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

use core::cmp::Ordering::{self, Equal};
use std::ops::ControlFlow;

use arrayvec::ArrayVec;

use crate::bounding::Aabb;
use crate::collider::{Collider, Mode, EAGER_TREE_MIN};
use crate::exact::{ExactPlane, PlaneSide};
use crate::parallel::*;
use crate::query::coplanar::{
    coplanar_orientation, coplanar_ray_in_corner, coplanar_same_ray,
    coplanar_segment_meets_triangle, coplanar_segments_meet, coplanar_triangles_meet, extremes,
    same_side_in_plane,
};
use crate::query::prepared::{
    segment_meets_triangle_plane, segment_meets_triangle_with_sides, segments_meet, triangles_meet,
};

type P3 = [f64; 3];

/// A triangle of the mesh as the pair tests see it: its plane, whether it is degenerate, and
/// the axis-parallel plane it lies in (if any), decided once per triangle instead of once per
/// pair. A degenerate triangle's plane gives exact zeros for every point, so the tests skip its
/// sides and treat it as the segment it is; its corners are stored with that segment's end
/// points first.
#[derive(Clone, Copy)]
pub(crate) struct Face {
    plane: ExactPlane,
    degenerate: bool,
    /// `k` when every corner has the same coordinate `k` (the largest such `k`), else `NOT_FLAT`.
    flat: u8,
    /// For a flat non-degenerate face, the orientation of its corners in the projection
    /// dropping `flat` (nonzero); `Equal` otherwise.
    flat_orientation: Ordering,
}

/// [`Face::flat`] of a triangle in no axis-parallel plane.
const NOT_FLAT: u8 = 3;

impl Face {
    /// The face of the triangle `t`.
    #[inline]
    pub(crate) fn new(t: &[P3; 3]) -> Self {
        let mut plane = ExactPlane::new(t);
        let degenerate = plane.is_degenerate();
        if degenerate {
            // The same three positions, the extreme ones first (a cold path: rare faces).
            let (a, b) = extremes(t);
            let ia = t.iter().position(|x| *x == a).unwrap_or(0);
            let ib = t.iter().position(|x| *x == b && *x != a).unwrap_or(ia);
            let other = if ia == ib { ia } else { 3 - ia - ib };
            plane = ExactPlane::new(&[a, b, t[other]]);
        }
        let flat = (0..3)
            .rev()
            .find(|&k| t[1][k] == t[0][k] && t[2][k] == t[0][k])
            .map_or(NOT_FLAT, |k| k as u8);
        let flat_orientation = if flat == NOT_FLAT || degenerate {
            Equal
        } else {
            coplanar_orientation(&t[0], &t[1], &t[2], flat as usize)
        };
        Face {
            plane,
            degenerate,
            flat,
            flat_orientation,
        }
    }

    #[inline(always)]
    fn corners(&self) -> &[P3; 3] {
        self.plane.corners()
    }

    /// The segment between the two extreme corners of a degenerate face.
    #[inline(always)]
    fn segment(&self) -> (P3, P3) {
        let c = self.corners();
        (c[0], c[1])
    }

    /// Whether the closed segment `ab` meets this face.
    #[inline]
    fn met_by_segment(&self, a: &P3, b: &P3) -> bool {
        if self.degenerate {
            let (c, d) = self.segment();
            segments_meet(a, b, &c, &d)
        } else {
            segment_meets_triangle_plane(a, b, self.corners(), &self.plane)
        }
    }
}

/// The axis `k` when both faces lie in one plane `x_k = c`: every side of a corner of one
/// against the other's plane is then an exact zero, known without arithmetic (the flat parts
/// of engineering meshes).
#[inline]
fn common_flat_axis(fp: &Face, fq: &Face) -> Option<usize> {
    let k = fp.flat as usize;
    (fp.flat != NOT_FLAT && fq.flat == fp.flat && fp.corners()[0][k] == fq.corners()[0][k])
        .then_some(k)
}

/// A part of a triangle around a shared vertex `v`, with its far set (where every ray from `v`
/// into the part leaves it): the triangle itself and its edge opposite `v`, or, for a
/// degenerate triangle, a segment from `v` to an extreme point and that point. Segments and
/// points stay segments: the exact tests are fast on them, while a degenerate triangle's plane
/// would send every side test to exact arithmetic.
#[derive(Clone, Copy)]
enum Piece<'a> {
    Tri(&'a Face, [P3; 2]),
    Seg([P3; 2], P3),
}

impl Piece<'_> {
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
            Piece::Tri(f, _) => segment_meets_triangle_plane(&a, &b, f.corners(), &f.plane),
            Piece::Seg([c, d], _) => segments_meet(&a, &b, c, d),
        }
    }
}

/// The parts of triangle `t` (degenerate or not, as given) around its vertex `v`: one for a
/// triangle, one or two segments for a degenerate one.
fn pieces<'a>(f: &'a Face, v: &P3) -> [Option<Piece<'a>>; 2] {
    if !f.degenerate {
        let [x, y] = opposite(f.corners(), v);
        return [Some(Piece::Tri(f, [*x, *y])), None];
    }
    let (p, q) = f.segment();
    [p, q].map(|e| (e != *v).then_some(Piece::Seg([*v, e], e)))
}

/// The corners of `t` other than `v` (`v` again where `t` repeats it).
fn opposite<'a>(t: &'a [P3; 3], v: &'a P3) -> [&'a P3; 2] {
    let mut far = t.iter().filter(|x| *x != v);
    [far.next().unwrap_or(v), far.next().unwrap_or(v)]
}

/// Whether triangles sharing exactly the vertex `v` meet anywhere else.
fn meet_beyond_vertex(fp: &Face, fq: &Face, v: &P3) -> bool {
    // The far corners' sides against the other plane once: most neighbours around a vertex of
    // a surface are told apart by these two or four signs, and the rest reuse them. Sides
    // against a degenerate face's plane are all zero: not computed.
    if let Some(k) = common_flat_axis(fp, fq) {
        return meet_beyond_vertex_flat(fp, fq, v, k);
    }
    let (p, q) = (fp.corners(), fq.corners());
    let (far_p, far_q) = (opposite(p, v), opposite(q, v));
    let mut sides_p = [Equal; 2];
    if !fq.degenerate {
        sides_p = [fq.plane.side(far_p[0]), fq.plane.side(far_p[1])];
        if strictly_one_side(sides_p) {
            return false;
        }
    }
    let mut sides_q = [Equal; 2];
    if !fp.degenerate {
        sides_q = [fp.plane.side(far_q[0]), fp.plane.side(far_q[1])];
        if strictly_one_side(sides_q) {
            return false;
        }
    }
    if fp.degenerate || fq.degenerate {
        return meet_beyond_vertex_degenerate(&pieces(fp, v), &pieces(fq, v));
    }
    // Non-degenerate: the far edge of one meets the other (see the module docs).
    segment_meets_triangle_with_sides(far_p[0], far_p[1], sides_p, q, &fq.plane)
        || segment_meets_triangle_with_sides(far_q[0], far_q[1], sides_q, p, &fp.plane)
}

/// How a face leaves its vertex `v`, near `v`: a triangle spans the corner between the rays to
/// its far corners (with that corner's orientation), a degenerate face the rays to its far
/// ends (one, or two when `v` is inside its segment).
enum Spread {
    Corner([P3; 2], Ordering),
    Rays([Option<P3>; 2]),
}

impl Spread {
    /// How `f`, flat (see [`Face::flat`]), leaves its vertex `v`.
    fn of(f: &Face, v: &P3) -> Self {
        if f.degenerate {
            let (a, b) = f.segment();
            return Spread::Rays([a, b].map(|e| (e != *v).then_some(e)));
        }
        // With `v`'s neighbours in cyclic order, the corner turns like the face.
        let c = f.corners();
        let far = if *v == c[1] {
            [c[2], c[0]]
        } else if *v == c[2] {
            [c[0], c[1]]
        } else {
            [c[1], c[2]]
        };
        Spread::Corner(far, f.flat_orientation)
    }
}

/// [`meet_beyond_vertex`] for faces in one axis plane `x_k = c`. Near `v` each face is its
/// corner (or rays), and a triangle lies within its corner, so they meet beyond `v` exactly
/// when their corners share a ray; two closed corners narrower than a half-plane that share a
/// ray share one of their boundary rays. A few 2D signs instead of segment tests.
fn meet_beyond_vertex_flat(fp: &Face, fq: &Face, v: &P3, k: usize) -> bool {
    let in_corner = |x: &[P3; 2], s, e: &P3| coplanar_ray_in_corner(v, &x[0], &x[1], s, e, k);
    match (Spread::of(fp, v), Spread::of(fq, v)) {
        (Spread::Corner(x, s), Spread::Corner(y, t)) => {
            x.iter().any(|e| in_corner(&y, t, e)) || y.iter().any(|e| in_corner(&x, s, e))
        }
        (Spread::Corner(x, s), Spread::Rays(r)) | (Spread::Rays(r), Spread::Corner(x, s)) => {
            r.iter().flatten().any(|e| in_corner(&x, s, e))
        }
        (Spread::Rays(r1), Spread::Rays(r2)) => r1.iter().flatten().any(|e1| {
            r2.iter()
                .flatten()
                .any(|e2| coplanar_same_ray(v, e1, e2, k))
        }),
    }
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
fn meet_beyond_edge(fp: &Face, fq: &Face, u: &P3, v: &P3) -> bool {
    let (p, q) = (fp.corners(), fq.corners());
    let third = |t: &[P3; 3]| *t.iter().find(|x| *x != u && *x != v).unwrap_or(u);
    let (a, b) = (third(p), third(q));
    if !fp.degenerate {
        // `b` off the plane of `p`: `q` is not degenerate (`b` is off the line `uv`) and meets
        // that plane only in `[u, v]`. One sign decides most edges of a surface.
        if common_flat_axis(fp, fq).is_none() && fp.plane.side(&b) != Equal {
            return false;
        }
        // Coplanar: they overlap when the third vertices lie on the same side of `uv`; a
        // degenerate `q` (on the line `uv`) meets `p` only in `[u, v]`.
        return !fq.degenerate && same_side_in_plane(&fp.plane, u, v, &a, &b);
    }
    if !fq.degenerate {
        // A degenerate `p` (on the line `uv`) meets `q` only in `[u, v]`.
        return false;
    }
    // All on the line `uv`: both extend past the same end.
    let k = (0..3).find(|&k| u[k] != v[k]).unwrap_or(0);
    let (lo, hi) = (u[k].min(v[k]), u[k].max(v[k]));
    (a[k] > hi && b[k] > hi) || (a[k] < lo && b[k] < lo)
}

/// Whether triangles sharing nothing meet: the exact triangle test, or segment tests where a
/// face is degenerate (no sides against its plane).
fn meet_apart(fp: &Face, fq: &Face) -> bool {
    if let Some(k) = common_flat_axis(fp, fq) {
        // One axis plane: in its projection, degenerate faces as the segments they are.
        let ((a, b), (c, d)) = (fp.segment(), fq.segment());
        return match (fp.degenerate, fq.degenerate) {
            (false, false) => coplanar_triangles_meet(fp.corners(), fq.corners(), k),
            (true, false) => coplanar_segment_meets_triangle(&a, &b, fq.corners(), k),
            (false, true) => coplanar_segment_meets_triangle(&c, &d, fp.corners(), k),
            (true, true) => coplanar_segments_meet(&a, &b, &c, &d, k),
        };
    }
    match (fp.degenerate, fq.degenerate) {
        (false, false) => triangles_meet(&fp.plane, &fq.plane),
        (true, _) => {
            let (a, b) = fp.segment();
            fq.met_by_segment(&a, &b)
        }
        (false, true) => {
            let (a, b) = fq.segment();
            fp.met_by_segment(&a, &b)
        }
    }
}

/// Whether two triangles of one mesh meet anywhere other than in what they share (see the
/// module docs), exactly.
pub(crate) fn meet_elsewhere(fp: &Face, fq: &Face) -> bool {
    let (p, q) = (fp.corners(), fq.corners());
    // The distinct positions of `p` that `q` has too (no allocation: this runs for every
    // candidate pair).
    // Only a degenerate face can repeat a position.
    let mut shared = [&p[0]; 3];
    let mut n = 0;
    for (k, x) in p.iter().enumerate() {
        if q.contains(x) && !(fp.degenerate && p[..k].contains(x)) {
            shared[n] = x;
            n += 1;
        }
    }
    match n {
        0 => meet_apart(fp, fq),
        1 => meet_beyond_vertex(fp, fq, shared[0]),
        2 => meet_beyond_edge(fp, fq, shared[0], shared[1]),
        _ => !fp.degenerate,
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

/// Meshes up to this many triangles keep every triangle's plane for the whole search (136
/// bytes each: at most 136 MiB); larger ones make the two planes of each candidate pair anew.
const PLANE_CACHE_MAX: usize = 1 << 20;

/// The planes of the triangles of a collider by tree slot (position in the tree's order, so
/// that the pairs of one subtree read nearby memory), kept or made on demand.
enum Planes<'a> {
    Kept(Vec<Face>),
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
        let plane = |&i: &u32| Face::new(&collider.corners(i));
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
                let plane =
                    |slot: u32| Face::new(&collider.corners(collider.bvh().order()[slot as usize]));
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
        if self.is_tiny_without_tree() {
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
        if self.is_tiny_without_tree() {
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

    /// A mesh under [`EAGER_TREE_MIN`] triangles whose tree was never built: the pairs are
    /// found without one.
    fn is_tiny_without_tree(&self) -> bool {
        !self.has_bvh() && self.mesh().num_triangles() < EAGER_TREE_MIN
    }

    /// A tiny mesh whose tree was never built (fewer than 32 triangles): every pair, after an
    /// exact comparison of their boxes (the pairs the tree would have enumerated), in order.
    fn self_intersections_small(&self) -> Vec<(u32, u32)> {
        let n = self.mesh().num_triangles() as u32;
        if n < 2 {
            return Vec::new();
        }
        // On the stack: a tiny mesh's whole cost is a few microseconds, an allocation counts.
        let mut faces = ArrayVec::<(Face, Aabb), EAGER_TREE_MIN>::new();
        for i in 0..n {
            let face = Face::new(&self.corners(i));
            faces.push((face, corner_box(face.corners())));
        }
        // Room for two pairs a triangle: no reallocation on the usual tiny mesh.
        let mut out = Vec::with_capacity(2 * n as usize);
        for (i, (fi, bi)) in faces.iter().enumerate() {
            for (j, (fj, bj)) in faces.iter().enumerate().skip(i + 1) {
                if bi.overlaps(bj) && meet_elsewhere(fi, fj) {
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
                let pi = Face::new(&self.corners(i));
                (i + 1..n).filter_map(move |j| {
                    meet_elsewhere(&pi, &Face::new(&self.corners(j))).then_some((i, j))
                })
            })
            .collect();
        out.sort_unstable();
        out
    }
}
