//! Pruning the edge–edge candidates of two solid hulls by their Gauss-map arcs.
//!
//! A facet of `M = P − Q` whose normal is the cross product of an edge of `P` and an edge of
//! `Q` exists only where the two edges' arcs on the unit sphere cross: the arc of an edge of
//! `P` joins the outward normals `A`, `B` of its two faces, that of an edge of `−Q` joins
//! `C = −C_Q`, `D = −D_Q`. They cross at an inner point of both exactly when
//! `C·(B×A)` and `D·(B×A)` have opposite signs, `A·(D×C)` and `B·(D×C)` too, and `C·(B×A)`
//! and `B·(D×C)` the same sign. Arcs meeting only at an end meet at a face normal of `P` or
//! `Q`, which is a candidate of its own. So a pair is dropped only when one of the three
//! conditions is *proved* false: each triple product is evaluated on the rounded normals with a
//! proved bound of its error (from the normals' rounding and the evaluation's), and a sign
//! counts only beyond that bound. Every facet normal of `M` stays a candidate.

use crate::query::shapes::rounded_f64::{cross, dot, P3, U};

/// A rounded vector with a proved bound `e` of its Euclidean error and a bound `m` of its
/// true length (its 1-norm plus `e`, rounded up).
#[derive(Debug, Clone, Copy)]
struct Bounded {
    v: P3,
    e: f64,
    m: f64,
}

impl Bounded {
    fn new(v: P3, e: f64) -> Bounded {
        let m = (v[0].abs() + v[1].abs() + v[2].abs() + e) * (1.0 + 4.0 * U);
        Bounded { v, e, m }
    }

    /// `n2 × n1`, with its rounding and the inputs' errors.
    fn cross(n2: &Bounded, n1: &Bounded) -> Bounded {
        let e = (n2.e * n1.m + n2.m * n1.e + 6.0 * U * n2.m * n1.m) * (1.0 + 8.0 * U);
        Bounded::new(cross(&n2.v, &n1.v), e)
    }

    /// The sign of the exact `self · other` when proved (`1` or `-1`), else `0`.
    fn dot_sign(&self, other: &Bounded) -> i8 {
        let value = dot(&self.v, &other.v);
        let bound =
            (self.e * other.m + self.m * other.e + 4.0 * U * self.m * other.m) * (1.0 + 8.0 * U);
        if value > bound {
            1
        } else if value < -bound {
            -1
        } else {
            0
        }
    }
}

/// An edge's arc: the outward normals `n1`, `n2` of its two faces (rounded, with error
/// bounds) and `n2 × n1`, the normal of the arc's great circle.
#[derive(Debug, Clone, Copy)]
pub(super) struct Arc {
    n1: Bounded,
    n2: Bounded,
    axis: Bounded,
}

/// The outward normal `(q − p) × (r − p)` of a counter-clockwise triangle, rounded, with a
/// proved bound of its error (the differences rounded once each, then the cross).
fn normal(p: &P3, q: &P3, r: &P3) -> Bounded {
    let d = [q[0] - p[0], q[1] - p[1], q[2] - p[2]];
    let e = [r[0] - p[0], r[1] - p[1], r[2] - p[2]];
    let size = (d[1] * e[2]).abs()
        + (d[2] * e[1]).abs()
        + (d[2] * e[0]).abs()
        + (d[0] * e[2]).abs()
        + (d[0] * e[1]).abs()
        + (d[1] * e[0]).abs();
    Bounded::new(cross(&d, &e), size * (2.02 * U + 3.0 * U) * (1.0 + 8.0 * U))
}

/// The arcs of the edges `(u, v)` of a closed triangulated boundary (counter-clockwise seen
/// from outside); `None` when an edge does not have exactly two faces.
pub(super) fn of_hull(
    corners: &[P3],
    triangles: &[[u32; 3]],
    faces_of_edge: &[Vec<usize>],
) -> Option<Vec<Arc>> {
    let normals: Vec<Bounded> = triangles
        .iter()
        .map(|t| {
            let [p, q, r] = t.map(|i| &corners[i as usize]);
            normal(p, q, r)
        })
        .collect();
    faces_of_edge
        .iter()
        .map(|faces| match faces.as_slice() {
            [f, g] => {
                let (n1, n2) = (normals[*f], normals[*g]);
                Some(Arc {
                    n1,
                    n2,
                    axis: Bounded::cross(&n2, &n1),
                })
            }
            _ => None,
        })
        .collect()
}

/// Whether the edge of `P` with arc `p` and the edge of `Q` with arc `q` may give a facet of
/// `P − Q` (false only when proved not to). With `A, B` the normals of `p` and `C, D` the
/// negated normals of `q` (so `D × C` is `q`'s axis unchanged): `C·(B×A) = −n1_q·axis_p`,
/// `D·(B×A) = −n2_q·axis_p`, `A·(D×C) = n1_p·axis_q`, `B·(D×C) = n2_p·axis_q`.
pub(super) fn may_face(p: &Arc, q: &Arc) -> bool {
    let x1 = q.n1.dot_sign(&p.axis);
    let x2 = q.n2.dot_sign(&p.axis);
    if x1 * x2 == 1 {
        return false; // C and D on the same side of A B's circle
    }
    let y1 = p.n1.dot_sign(&q.axis);
    let y2 = p.n2.dot_sign(&q.axis);
    // A and B on the same side of C D's circle; or the circles cross on the wrong side
    // (C·(B×A) and B·(D×C) of opposite signs: −x1 · y2 = −1).
    !(y1 * y2 == 1 || x1 * y2 == 1)
}

#[cfg(test)]
mod tests {
    use nalgebra::{Isometry3, Point3, Vector3};
    use proptest::prelude::*;

    use super::super::super::exact_cores;
    use super::super::{signed_distance as fast, Prepared};
    use super::may_face;
    use crate::shape::{ConvexHull, Shape};

    /// Points on a sphere (a fixed spiral turned by `seed`), as the manifold benchmark's hulls.
    fn spiral_hull(n: u32, seed: f64, pose: &Isometry3<f64>) -> Shape {
        let points = (0..n)
            .map(|k| {
                let t = f64::from(k) + 0.5;
                let z = 1.0 - 2.0 * t / f64::from(n);
                let phi = t * 2.399_963 + seed;
                let r = (1.0 - z * z).sqrt();
                pose * Point3::new(r * phi.cos(), r * phi.sin(), z)
            })
            .collect();
        ConvexHull::new(points).unwrap().into()
    }

    #[test]
    fn most_edge_pairs_of_two_hulls_are_pruned() {
        let a = spiral_hull(12, 0.0, &Isometry3::identity());
        let pose = Isometry3::new(Vector3::new(1.6, 0.1, 0.2), Vector3::new(0.1, 0.2, 0.3));
        let b = spiral_hull(12, 1.0, &pose);
        let (pa, pb) = (Prepared::of(&a).unwrap(), Prepared::of(&b).unwrap());
        let (arcs_a, arcs_b) = (pa.arcs.as_ref().unwrap(), pb.arcs.as_ref().unwrap());
        let all = arcs_a.len() * arcs_b.len();
        let kept = arcs_a
            .iter()
            .flat_map(|p| arcs_b.iter().map(move |q| may_face(p, q)))
            .filter(|k| *k)
            .count();
        assert!(kept > 0 && kept * 4 < all, "kept {kept} of {all}");
    }

    fn cloud(points: &[[f64; 3]], pose: &Isometry3<f64>) -> Shape {
        ConvexHull::new(points.iter().map(|p| pose * Point3::from(*p)).collect())
            .unwrap()
            .into()
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(128))]
        /// Random overlapping hulls: the fast path with pruned edge pairs keeps every answer
        /// within its bound of the exact path's depth (a wrongly pruned facet normal would
        /// give a larger depth), with the exact kind.
        #[test]
        fn pruned_depth_agrees_with_the_exact_path(
            pa in proptest::collection::vec(proptest::array::uniform3(-1.0f64..1.0), 4..14),
            pb in proptest::collection::vec(proptest::array::uniform3(-1.0f64..1.0), 4..14),
            shift in proptest::array::uniform3(-1.2f64..1.2),
            turn in proptest::array::uniform3(-3.0f64..3.0),
        ) {
            let a = cloud(&pa, &Isometry3::identity());
            let b = cloud(&pb, &Isometry3::new(Vector3::from(shift), Vector3::from(turn)));
            let Some(got) = fast(&a, &b) else { return Ok(()) };
            let exact = exact_cores(&a, &b).unwrap();
            prop_assert_eq!(got.kind, exact.kind);
            prop_assert!(
                (got.value - exact.value).abs() <= got.error_bound + exact.error_bound,
                "fast {:?} exact {:?}", got, exact
            );
        }
    }
}
