//! Contact classes of closed meshes against the closed-form truth for axis-aligned boxes
//! (touching faces, edges and vertices included), and the exact intersection geometry.

use cga_collide::collider::{Collider, ContactClass};
use cga_collide::nalgebra::Point3;
use cga_collide::query::{self, ContactGeometry};
use cga_collide::{TriMesh, Triangle};
use proptest::prelude::*;

fn cuboid(lo: [i32; 3], size: [i32; 3]) -> Collider {
    let p = |v: [i32; 3]| Point3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2]));
    let hi = [lo[0] + size[0], lo[1] + size[1], lo[2] + size[2]];
    Collider::new(TriMesh::cuboid(p(lo), p(hi)).unwrap())
}

/// The truth for boxes: interiors overlap iff the open intervals overlap on every axis.
fn truth(a: ([i32; 3], [i32; 3]), b: ([i32; 3], [i32; 3])) -> ContactClass {
    let (alo, ahi) = (a.0, [a.0[0] + a.1[0], a.0[1] + a.1[1], a.0[2] + a.1[2]]);
    let (blo, bhi) = (b.0, [b.0[0] + b.1[0], b.0[1] + b.1[1], b.0[2] + b.1[2]]);
    let closed = (0..3).all(|k| alo[k] <= bhi[k] && blo[k] <= ahi[k]);
    let open = (0..3).all(|k| alo[k] < bhi[k] && blo[k] < ahi[k]);
    let strictly_in = |lo: [i32; 3], hi: [i32; 3], olo: [i32; 3], ohi: [i32; 3]| {
        (0..3).all(|k| olo[k] < lo[k] && hi[k] < ohi[k])
    };
    if !closed {
        ContactClass::Disjoint
    } else if strictly_in(alo, ahi, blo, bhi) {
        ContactClass::AInsideB
    } else if strictly_in(blo, bhi, alo, ahi) {
        ContactClass::BInsideA
    } else if open {
        ContactClass::Penetrating
    } else {
        ContactClass::Touching
    }
}

fn placed_box() -> impl Strategy<Value = ([i32; 3], [i32; 3])> {
    (
        proptest::array::uniform3(-3i32..=3),
        proptest::array::uniform3(1i32..=4),
    )
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(96))]

    #[test]
    fn boxes_match_the_closed_form(a in placed_box(), b in placed_box()) {
        let got = cuboid(a.0, a.1).contact_class(&cuboid(b.0, b.1));
        prop_assert_eq!(got, truth(a, b));
    }
}

#[test]
fn intersection_geometry() {
    let p = |x, y, z| Point3::new(x, y, z);
    let a = Triangle::new(p(0., 0., 0.), p(2., 0., 0.), p(0., 2., 0.)).unwrap();
    // Touching at a vertex.
    let b = Triangle::new(p(2., 0., 0.), p(3., 0., 1.), p(3., 1., 0.)).unwrap();
    assert!(matches!(
        query::triangle_intersection(&a, &b),
        Some(ContactGeometry::Point(_))
    ));
    // Crossing: a segment.
    let c = Triangle::new(p(0.5, 0.5, -1.), p(0.5, 0.5, 1.), p(3., 3., 0.)).unwrap();
    let Some(ContactGeometry::Segment(x, y)) = query::triangle_intersection(&a, &c) else {
        panic!("a segment");
    };
    assert_ne!(x, y);
    // Coplanar overlap: a square [0,1]² ∩ the triangle is a polygon with 4 corners here.
    let d = Triangle::new(p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.)).unwrap();
    let e = Triangle::new(p(0.5, -1., 0.), p(0.5, 3., 0.), p(-1., 0.5, 0.)).unwrap();
    let Some(ContactGeometry::Polygon(poly)) = query::triangle_intersection(&d, &e) else {
        panic!("a polygon");
    };
    assert!(poly.len() >= 3);
    // Apart.
    let f = Triangle::new(p(0., 0., 1.), p(1., 0., 1.), p(0., 1., 1.)).unwrap();
    assert!(query::triangle_intersection(&a, &f).is_none());
}

/// Convex solids with vertices on the quarter grid, so that every placement below is exact in
/// `f64` and the oracle can work in integers (coordinates × 4).
fn convex_solid(kind: usize) -> (Vec<[i64; 3]>, Vec<[u32; 3]>) {
    // Coordinates in quarters: 4 = 1.0, 2 = 0.5.
    let (v, t): (Vec<[i64; 3]>, Vec<[u32; 3]>) = match kind {
        // Cube [0, 1]³.
        0 => (
            vec![
                [0, 0, 0],
                [4, 0, 0],
                [4, 4, 0],
                [0, 4, 0],
                [0, 0, 4],
                [4, 0, 4],
                [4, 4, 4],
                [0, 4, 4],
            ],
            vec![
                [0, 1, 2],
                [0, 2, 3],
                [4, 5, 6],
                [4, 6, 7],
                [0, 1, 5],
                [0, 5, 4],
                [1, 2, 6],
                [1, 6, 5],
                [2, 3, 7],
                [2, 7, 6],
                [3, 0, 4],
                [3, 4, 7],
            ],
        ),
        // Corner tetrahedron.
        1 => (
            vec![[0, 0, 0], [4, 0, 0], [0, 4, 0], [0, 0, 4]],
            vec![[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]],
        ),
        // The regular tetrahedron on alternate corners of the cube (its edges are the cube's
        // face diagonals).
        2 => (
            vec![[0, 0, 0], [4, 4, 0], [4, 0, 4], [0, 4, 4]],
            vec![[0, 1, 2], [0, 1, 3], [0, 2, 3], [1, 2, 3]],
        ),
        // Octahedron on the cube's face centres.
        3 => (
            vec![
                [2, 2, 0],
                [2, 2, 4],
                [0, 2, 2],
                [4, 2, 2],
                [2, 0, 2],
                [2, 4, 2],
            ],
            (0..8u32)
                .map(|k| [k & 1, 2 + ((k >> 1) & 1), 4 + ((k >> 2) & 1)])
                .collect(),
        ),
        // Square pyramid.
        4 => (
            vec![[0, 0, 0], [4, 0, 0], [4, 4, 0], [0, 4, 0], [2, 2, 4]],
            vec![
                [0, 1, 2],
                [0, 2, 3],
                [0, 1, 4],
                [1, 2, 4],
                [2, 3, 4],
                [3, 0, 4],
            ],
        ),
        // Triangular prism.
        _ => (
            vec![
                [0, 0, 0],
                [4, 0, 0],
                [0, 4, 0],
                [0, 0, 4],
                [4, 0, 4],
                [0, 4, 4],
            ],
            vec![
                [0, 1, 2],
                [3, 4, 5],
                [0, 1, 4],
                [0, 4, 3],
                [1, 2, 5],
                [1, 5, 4],
                [2, 0, 3],
                [2, 3, 5],
            ],
        ),
    };
    (v, t)
}

fn sub_i(a: [i64; 3], b: [i64; 3]) -> [i64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn dot_i(a: [i64; 3], b: [i64; 3]) -> i64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross_i(a: [i64; 3], b: [i64; 3]) -> [i64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// Rotation `rot` (of 24) of the cube's symmetry group: `x ↦ (s[k] x[perm[k]])ₖ`. A permutation
/// and two free signs; the third sign makes the determinant +1.
fn rotation(rot: usize) -> ([usize; 3], [i64; 3]) {
    let perm = [
        [0, 1, 2],
        [1, 2, 0],
        [2, 0, 1],
        [1, 0, 2],
        [0, 2, 1],
        [2, 1, 0],
    ][rot % 6];
    let odd_permutation = rot % 6 >= 3;
    let flip = |bit: usize| if (rot / 6) & bit != 0 { -1 } else { 1 };
    let (s0, s1) = (flip(1), flip(2));
    (
        perm,
        [s0, s1, s0 * s1 * if odd_permutation { -1 } else { 1 }],
    )
}

/// A placed convex solid: rotation `rot` of the 24 of the cube (about its centre), scale
/// `2^scale / 2` (½, 1 or 2), translation in halves; every triangle turned outward, or all
/// inward when `inward`.
#[derive(Debug, Clone)]
struct Placed {
    vertices: Vec<[i64; 3]>,
    triangles: Vec<[u32; 3]>,
}

fn place(kind: usize, rot: usize, scale: u32, shift: [i64; 3], inward: bool) -> Placed {
    let (v, mut t) = convex_solid(kind);
    let (perm, s) = rotation(rot);
    let vertices: Vec<[i64; 3]> = v
        .iter()
        .map(|p| {
            let c = [p[0] - 2, p[1] - 2, p[2] - 2]; // about the centre (½, ½, ½)
            let r = [0, 1, 2].map(|k| s[k] * c[perm[k]] + 2);
            [0, 1, 2].map(|k| (r[k] << scale) / 2 + 2 * shift[k])
        })
        .collect();
    let centroid = vertices.iter().fold([0i64; 3], |acc, p| {
        [acc[0] + p[0], acc[1] + p[1], acc[2] + p[2]]
    });
    let n = vertices.len() as i64;
    for tri in &mut t {
        let [a, b, c] = tri.map(|i| vertices[i as usize]);
        let normal = cross_i(sub_i(b, a), sub_i(c, a));
        let towards_centre = dot_i(normal, sub_i(centroid, [a[0] * n, a[1] * n, a[2] * n]));
        if (towards_centre > 0) != inward {
            tri.swap(1, 2);
        }
    }
    Placed {
        vertices,
        triangles: t,
    }
}

impl Placed {
    fn collider(&self) -> Collider {
        let p = |v: &[i64; 3]| Point3::new(v[0] as f64 / 4.0, v[1] as f64 / 4.0, v[2] as f64 / 4.0);
        Collider::new(
            TriMesh::new(
                self.vertices.iter().map(p).collect(),
                self.triangles.clone(),
            )
            .unwrap(),
        )
    }
    fn normals(&self) -> Vec<[i64; 3]> {
        self.triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.map(|i| self.vertices[i as usize]);
                cross_i(sub_i(b, a), sub_i(c, a))
            })
            .collect()
    }
    fn edges(&self) -> Vec<[i64; 3]> {
        self.triangles
            .iter()
            .flat_map(|t| (0..3).map(move |k| (t[k], t[(k + 1) % 3])))
            .map(|(i, j)| sub_i(self.vertices[j as usize], self.vertices[i as usize]))
            .collect()
    }
    fn span(&self, axis: [i64; 3]) -> (i64, i64) {
        let d = self.vertices.iter().map(|&v| dot_i(axis, v));
        (d.clone().min().unwrap(), d.max().unwrap())
    }
    /// Every vertex of `other` strictly inside this convex solid (strictly between the two
    /// supporting planes of every face normal).
    fn strictly_holds(&self, other: &Placed) -> bool {
        self.normals().into_iter().all(|n| {
            let (lo, hi) = self.span(n);
            other
                .vertices
                .iter()
                .all(|&v| lo < dot_i(n, v) && dot_i(n, v) < hi)
        })
    }
}

/// The truth for two convex solids by the separating-axis theorem, in integers: the candidate
/// axes are the face normals of both and the cross products of their edges. Some axis with a
/// gap: disjoint; some axis with only a shared end: touching; otherwise the interiors overlap.
fn convex_truth(a: &Placed, b: &Placed) -> ContactClass {
    let mut axes = a.normals();
    axes.extend(b.normals());
    for ea in a.edges() {
        for eb in b.edges() {
            axes.push(cross_i(ea, eb));
        }
    }
    axes.retain(|n| *n != [0, 0, 0]);
    let spans = |n: [i64; 3]| (a.span(n), b.span(n));
    if axes.iter().any(|&n| {
        let ((alo, ahi), (blo, bhi)) = spans(n);
        ahi < blo || bhi < alo
    }) {
        return ContactClass::Disjoint;
    }
    if axes.iter().any(|&n| {
        let ((alo, ahi), (blo, bhi)) = spans(n);
        ahi == blo || bhi == alo
    }) {
        return ContactClass::Touching;
    }
    if b.strictly_holds(a) {
        ContactClass::AInsideB
    } else if a.strictly_holds(b) {
        ContactClass::BInsideA
    } else {
        ContactClass::Penetrating
    }
}

fn placed_solid() -> impl Strategy<Value = Placed> {
    (
        0usize..6,
        0usize..24,
        0u32..3,
        proptest::array::uniform3(-1i64..=1),
        any::<bool>(),
    )
        .prop_map(|(kind, rot, scale, shift, inward)| place(kind, rot, scale, shift, inward))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(3000))]

    /// Tetrahedra, cubes, octahedra, pyramids and prisms on a coarse grid: touching faces,
    /// edges lying on faces and edges crossing edges are common, and so are inscribed solids.
    #[test]
    fn convex_solids_match_the_separating_axis_truth(a in placed_solid(), b in placed_solid()) {
        let got = (a.collider()).contact_class(&b.collider());
        prop_assert_eq!(got, convex_truth(&a, &b));
    }
}

#[test]
fn an_inscribed_tetrahedron_penetrates_its_cube() {
    // The tetrahedron's edges lie on the cube's faces and its vertices are corners of the
    // cube: no face crosses a face, no vertex is strictly inside, yet the interiors overlap.
    let cube = place(0, 0, 1, [0, 0, 0], false);
    let tetra = place(2, 0, 1, [0, 0, 0], false);
    assert_eq!(convex_truth(&tetra, &cube), ContactClass::Penetrating);
    assert_eq!(
        (tetra.collider()).contact_class(&cube.collider()),
        ContactClass::Penetrating
    );
}

#[test]
fn an_octahedron_on_the_face_centres_penetrates_its_cube() {
    // Every vertex lies on a face of the cube and every edge crosses its interior between two
    // faces: only the pieces of the edges show the overlap.
    let cube = place(0, 0, 1, [0, 0, 0], false);
    let octahedron = place(3, 0, 1, [0, 0, 0], true);
    assert_eq!(convex_truth(&octahedron, &cube), ContactClass::Penetrating);
    assert_eq!(
        (octahedron.collider()).contact_class(&cube.collider()),
        ContactClass::Penetrating
    );
}

/// Polycubes: unions of unit cells with no two cells meeting only along an edge or at a corner,
/// so that their boundary squares form closed 2-manifolds with reflex edges.
fn polycube(kind: usize) -> Vec<[i64; 3]> {
    match kind {
        0 => vec![[0, 0, 0], [1, 0, 0], [0, 1, 0]], // L
        1 => vec![[0, 0, 0], [1, 0, 0], [2, 0, 0], [1, 1, 0]], // T
        2 => vec![[0, 0, 0], [1, 0, 0], [2, 0, 0], [0, 1, 0], [2, 1, 0]], // U, with a notch
        3 => vec![[0, 0, 0], [1, 0, 0], [1, 1, 0], [1, 1, 1]], // a twisted staircase
        _ => vec![[0, 0, 0]],
    }
}

#[derive(Debug, Clone)]
struct Cells(std::collections::BTreeSet<[i64; 3]>);

fn placed_cells(kind: usize, rot: usize, double: bool, shift: [i64; 3]) -> Cells {
    let (perm, s) = rotation(rot);
    let k = if double { 2 } else { 1 };
    let mut out = std::collections::BTreeSet::new();
    for c in polycube(kind) {
        // Rotate the cell [c, c + 1] about the origin: its lowest corner is min(r c, r (c + 1)).
        let r = [0, 1, 2].map(|i| {
            let (x, y) = (s[i] * c[perm[i]], s[i] * (c[perm[i]] + 1));
            x.min(y)
        });
        for d in 0..k * k * k {
            let o = [d % k, (d / k) % k, d / (k * k)];
            out.insert([0, 1, 2].map(|i| r[i] * k + o[i] + shift[i]));
        }
    }
    Cells(out)
}

impl Cells {
    /// The boundary: two triangles for each cell face not shared with another cell, outward.
    fn collider(&self) -> Collider {
        let mut vertices = Vec::new();
        let mut triangles = Vec::new();
        for c in &self.0 {
            for axis in 0..3 {
                for side in [0i64, 1] {
                    let mut n = *c;
                    n[axis] += 2 * side - 1;
                    if self.0.contains(&n) {
                        continue;
                    }
                    let (u, v) = ((axis + 1) % 3, (axis + 2) % 3);
                    let corner = |du: i64, dv: i64| {
                        let mut p = *c;
                        p[axis] += side;
                        p[u] += du;
                        p[v] += dv;
                        Point3::new(p[0] as f64, p[1] as f64, p[2] as f64)
                    };
                    let base = vertices.len() as u32;
                    vertices.extend([corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)]);
                    // (u, v, axis) is right-handed: counter-clockwise in (u, v) faces +axis.
                    if side == 1 {
                        triangles.extend([[base, base + 1, base + 2], [base, base + 2, base + 3]]);
                    } else {
                        triangles.extend([[base, base + 2, base + 1], [base, base + 3, base + 2]]);
                    }
                }
            }
        }
        Collider::new(TriMesh::new(vertices, triangles).unwrap())
    }

    /// Every point of every cell is interior to `other`: all cells around it are in `other`.
    fn strictly_in(&self, other: &Cells) -> bool {
        self.0.iter().all(|c| {
            (0..27).all(|d| {
                let n = [c[0] + d % 3 - 1, c[1] + (d / 3) % 3 - 1, c[2] + d / 9 - 1];
                other.0.contains(&n)
            })
        })
    }
}

/// The truth for polycubes, cell by cell.
fn cells_truth(a: &Cells, b: &Cells) -> ContactClass {
    let meet =
        a.0.iter()
            .any(|x| b.0.iter().any(|y| (0..3).all(|k| (x[k] - y[k]).abs() <= 1)));
    if !meet {
        ContactClass::Disjoint
    } else if a.0.is_disjoint(&b.0) {
        ContactClass::Touching
    } else if a.strictly_in(b) {
        ContactClass::AInsideB
    } else if b.strictly_in(a) {
        ContactClass::BInsideA
    } else {
        ContactClass::Penetrating
    }
}

fn placed_polycube() -> impl Strategy<Value = Cells> {
    (
        0usize..5,
        0usize..24,
        any::<bool>(),
        proptest::array::uniform3(-1i64..=1),
    )
        .prop_map(|(kind, rot, double, shift)| placed_cells(kind, rot, double, shift))
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    /// Non-convex solids: reflex edges against faces, edges and reflex edges.
    #[test]
    fn polycubes_match_the_cell_truth(a in placed_polycube(), b in placed_polycube()) {
        let got = (a.collider()).contact_class(&b.collider());
        prop_assert_eq!(got, cells_truth(&a, &b));
    }
}
