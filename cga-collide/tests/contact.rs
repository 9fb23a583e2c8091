//! Contact classes of closed meshes against the closed-form truth for axis-aligned boxes
//! (touching faces, edges and vertices included), and the exact intersection geometry.

use cga_collide::nalgebra::Point3;
use cga_collide::query::{self, Collider, Contact, ContactGeometry};
use cga_collide::{TriMesh, Triangle};
use proptest::prelude::*;

fn cuboid(lo: [i32; 3], size: [i32; 3]) -> Collider {
    let p = |v: [i32; 3]| Point3::new(f64::from(v[0]), f64::from(v[1]), f64::from(v[2]));
    let hi = [lo[0] + size[0], lo[1] + size[1], lo[2] + size[2]];
    Collider::new(TriMesh::cuboid(p(lo), p(hi)).unwrap())
}

/// The truth for boxes: interiors overlap iff the open intervals overlap on every axis.
fn truth(a: ([i32; 3], [i32; 3]), b: ([i32; 3], [i32; 3])) -> Contact {
    let (alo, ahi) = (a.0, [a.0[0] + a.1[0], a.0[1] + a.1[1], a.0[2] + a.1[2]]);
    let (blo, bhi) = (b.0, [b.0[0] + b.1[0], b.0[1] + b.1[1], b.0[2] + b.1[2]]);
    let closed = (0..3).all(|k| alo[k] <= bhi[k] && blo[k] <= ahi[k]);
    let open = (0..3).all(|k| alo[k] < bhi[k] && blo[k] < ahi[k]);
    let strictly_in = |lo: [i32; 3], hi: [i32; 3], olo: [i32; 3], ohi: [i32; 3]| {
        (0..3).all(|k| olo[k] < lo[k] && hi[k] < ohi[k])
    };
    if !closed {
        Contact::Disjoint
    } else if strictly_in(alo, ahi, blo, bhi) {
        Contact::AInsideB
    } else if strictly_in(blo, bhi, alo, ahi) {
        Contact::BInsideA
    } else if open {
        Contact::Penetrating
    } else {
        Contact::Touching
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
        let got = query::contact_class(&cuboid(a.0, a.1), &cuboid(b.0, b.1));
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
