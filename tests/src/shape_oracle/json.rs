//! The command line's shape-pair lines: `{"a": SHAPE, "b": SHAPE, "expected": bool, ...}`,
//! every number printed so that it reads back as the same `f64` (Rust's `{:?}`).

use cga_collide::nalgebra::{Point3, Vector3};
use cga_collide::shape::{Capsule, Cone, ConvexHull, Cuboid, Cylinder, HalfSpace, Shape};
use cga_collide::{Ball, Segment, Triangle};
use serde_json::Value;

fn num(x: f64) -> String {
    assert!(x.is_finite());
    format!("{x:?}")
}

fn point(p: &Point3<f64>) -> String {
    format!("[{}, {}, {}]", num(p.x), num(p.y), num(p.z))
}

fn vector(v: &Vector3<f64>) -> String {
    format!("[{}, {}, {}]", num(v.x), num(v.y), num(v.z))
}

fn points<'a>(ps: impl IntoIterator<Item = &'a Point3<f64>>) -> String {
    let items: Vec<String> = ps.into_iter().map(point).collect();
    format!("[{}]", items.join(", "))
}

/// One shape as the command line spells it.
pub fn shape_json(s: &Shape) -> String {
    match s {
        Shape::Ball(b) => format!(
            r#"{{"ball": {{"center": {}, "radius": {}}}}}"#,
            point(b.centre()),
            num(b.radius())
        ),
        Shape::Capsule(c) => format!(
            r#"{{"capsule": {{"a": {}, "b": {}, "radius": {}}}}}"#,
            point(c.a()),
            point(c.b()),
            num(c.radius())
        ),
        Shape::Cylinder(c) => format!(
            r#"{{"cylinder": {{"a": {}, "b": {}, "radius": {}}}}}"#,
            point(c.a()),
            point(c.b()),
            num(c.radius())
        ),
        Shape::Cone(c) => format!(
            r#"{{"cone": {{"apex": {}, "base": {}, "radius": {}}}}}"#,
            point(c.apex()),
            point(c.base()),
            num(c.radius())
        ),
        Shape::Cuboid(c) => {
            let [u, v, w] = c.half_axes();
            format!(
                r#"{{"cuboid": {{"center": {}, "half_axes": [{}, {}, {}]}}}}"#,
                point(c.centre()),
                vector(u),
                vector(v),
                vector(w)
            )
        }
        Shape::HalfSpace(h) => format!(
            r#"{{"halfspace": {{"point": {}, "normal": {}}}}}"#,
            point(h.point()),
            vector(h.normal())
        ),
        Shape::ConvexHull(h) => format!(r#"{{"convex": {{"points": {}}}}}"#, points(h.points())),
        Shape::Triangle(t) => format!(r#"{{"triangle": {{"points": {}}}}}"#, points(t.vertices())),
        Shape::Segment(s) => format!(r#"{{"segment": {{"points": {}}}}}"#, points([s.a(), s.b()])),
    }
}

/// One fixture line: the pair, the exact answer of `intersects`, and where it comes from.
pub fn pair_line(a: &Shape, b: &Shape, expected: bool, family: &str, note: &str) -> String {
    format!(
        r#"{{"a": {}, "b": {}, "expected": {}, "family": "{}", "pair": "{}-{}", "note": "{}"}}"#,
        shape_json(a),
        shape_json(b),
        expected,
        family,
        a.kind(),
        b.kind(),
        note
    )
}

fn f(v: &Value) -> Result<f64, String> {
    v.as_f64().ok_or_else(|| format!("not a number: {v}"))
}

fn pt(v: &Value) -> Result<Point3<f64>, String> {
    let a = v.as_array().ok_or("a point is not an array")?;
    if a.len() != 3 {
        return Err("a point has not 3 coordinates".into());
    }
    Ok(Point3::new(f(&a[0])?, f(&a[1])?, f(&a[2])?))
}

fn pts(v: &Value) -> Result<Vec<Point3<f64>>, String> {
    v.as_array()
        .ok_or("points is not an array")?
        .iter()
        .map(pt)
        .collect()
}

/// Reads one shape of the command line's JSON.
pub fn parse_shape(v: &Value) -> Result<Shape, String> {
    let obj = v.as_object().ok_or("a shape is not an object")?;
    let (kind, d) = obj.iter().next().ok_or("an empty shape")?;
    let e = |e: cga_collide::Error| e.to_string();
    Ok(match kind.as_str() {
        "ball" => Ball::new(pt(&d["center"])?, f(&d["radius"])?)
            .map_err(e)?
            .into(),
        "capsule" => Capsule::new(pt(&d["a"])?, pt(&d["b"])?, f(&d["radius"])?)
            .map_err(e)?
            .into(),
        "cylinder" => Cylinder::new(pt(&d["a"])?, pt(&d["b"])?, f(&d["radius"])?)
            .map_err(e)?
            .into(),
        "cone" => Cone::new(pt(&d["apex"])?, pt(&d["base"])?, f(&d["radius"])?)
            .map_err(e)?
            .into(),
        "cuboid" => {
            let h = pts(&d["half_axes"])?;
            if h.len() != 3 {
                return Err("a cuboid needs 3 half axes".into());
            }
            Cuboid::new(pt(&d["center"])?, [h[0].coords, h[1].coords, h[2].coords])
                .map_err(e)?
                .into()
        }
        "halfspace" => HalfSpace::new(pt(&d["point"])?, pt(&d["normal"])?.coords)
            .map_err(e)?
            .into(),
        "convex" => ConvexHull::new(pts(&d["points"])?).map_err(e)?.into(),
        "triangle" => {
            let p = pts(&d["points"])?;
            if p.len() != 3 {
                return Err("a triangle needs 3 points".into());
            }
            Triangle::new(p[0], p[1], p[2]).map_err(e)?.into()
        }
        "segment" => {
            let p = pts(&d["points"])?;
            if p.len() != 2 {
                return Err("a segment needs 2 points".into());
            }
            Segment::new(p[0], p[1]).map_err(e)?.into()
        }
        other => return Err(format!("unknown shape kind {other}")),
    })
}

/// One parsed fixture line.
#[derive(Debug, Clone)]
pub struct Case {
    pub a: Shape,
    pub b: Shape,
    pub expected: bool,
    pub family: String,
    pub note: String,
}

/// Reads one fixture line.
pub fn parse_line(line: &str) -> Result<Case, String> {
    let v: Value = serde_json::from_str(line).map_err(|e| e.to_string())?;
    let text = |k: &str| v[k].as_str().unwrap_or("").to_string();
    Ok(Case {
        a: parse_shape(&v["a"])?,
        b: parse_shape(&v["b"])?,
        expected: v["expected"].as_bool().ok_or("no boolean `expected`")?,
        family: text("family"),
        note: text("note"),
    })
}
