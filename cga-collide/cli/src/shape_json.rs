//! The JSON spelling of a solid primitive (a `SHAPE`), read by `cga shapes` and by scene
//! files: an object with one key, the kind, whose value holds the shape's fields.
//!
//! | kind | fields | the shape |
//! |---|---|---|
//! | `ball` | `center` P, `radius` r | the solid ball |
//! | `capsule` | `a` P, `b` P, `radius` r | the points within r of the segment ab |
//! | `cylinder` | `a` P, `b` P, `radius` r | axis segment ab, flat caps at a and b perpendicular to it |
//! | `cone` | `apex` P, `base` P, `radius` r | the base disc centred at `base`, perpendicular to the axis, and the apex |
//! | `cuboid` | `center` P, `half_axes` [U, V, W] | the solid c + s1·U + s2·V + s3·W, abs(si) ≤ 1 |
//! | `halfspace` | `point` P, `normal` N | {x : (x − p)·n ≤ 0} |
//! | `convex` | `points` [P, …] | the convex hull of the points |
//! | `triangle` | `points` [P, P, P] | the closed triangle |
//! | `segment` | `points` [P, P] | the closed segment |
//!
//! P, N, U, V, W are `[x, y, z]`. Every number is read as the nearest `f64` to the decimal
//! written, and the shape is the one those `f64` values denote exactly. Every field is
//! required, and an unknown field is an error (a misspelt `centre` is not skipped).

use anyhow::{bail, Context, Result};
use cga_collide::nalgebra::Point3;
use cga_collide::shape::{Capsule, Cone, ConvexHull, Cuboid, Cylinder, HalfSpace, Shape};
use cga_collide::{Ball, Segment, Triangle};
use serde_json::{Map, Value};

/// The kinds and their fields, in the order of the table above.
const KINDS: &[(&str, &[&str])] = &[
    ("ball", &["center", "radius"]),
    ("capsule", &["a", "b", "radius"]),
    ("cylinder", &["a", "b", "radius"]),
    ("cone", &["apex", "base", "radius"]),
    ("cuboid", &["center", "half_axes"]),
    ("halfspace", &["point", "normal"]),
    ("convex", &["points"]),
    ("triangle", &["points"]),
    ("segment", &["points"]),
];

/// Reads one SHAPE. Errors say which field is wrong and why.
pub fn parse_shape(value: &Value) -> Result<Shape> {
    let object = value
        .as_object()
        .filter(|o| o.len() == 1)
        .with_context(|| {
            format!(
                "a shape is an object with one key, its kind ({}), found {}",
                kinds(),
                brief(value)
            )
        })?;
    let (kind, body) = object.iter().next().context("one key")?;
    let Some((_, fields)) = KINDS.iter().find(|(k, _)| k == kind) else {
        bail!("unknown shape kind `{kind}` (expected one of {})", kinds());
    };
    let body = body
        .as_object()
        .with_context(|| format!("{kind}: expected an object with {}", fields.join(", ")))?;
    if let Some(extra) = body.keys().find(|k| !fields.contains(&k.as_str())) {
        bail!(
            "{kind}: unknown field `{extra}` (expected {})",
            fields.join(", ")
        );
    }
    let shape = build(kind, body).with_context(|| format!("{kind}"))?;
    Ok(shape)
}

fn build(kind: &str, body: &Map<String, Value>) -> Result<Shape> {
    let point = |name: &str| field(body, name).and_then(|v| point(v).context(name.to_owned()));
    let number = |name: &str| field(body, name).and_then(|v| number(v).context(name.to_owned()));
    let points = |name: &str| -> Result<Vec<Point3<f64>>> {
        let list = field(body, name)?
            .as_array()
            .with_context(|| format!("{name}: expected an array of points [x, y, z]"))?;
        list.iter()
            .enumerate()
            .map(|(k, p)| point(p).with_context(|| format!("{name}[{k}]")))
            .collect()
    };
    Ok(match kind {
        "ball" => Ball::new(point("center")?, number("radius")?)?.into(),
        "capsule" => Capsule::new(point("a")?, point("b")?, number("radius")?)?.into(),
        "cylinder" => Cylinder::new(point("a")?, point("b")?, number("radius")?)?.into(),
        "cone" => Cone::new(point("apex")?, point("base")?, number("radius")?)?.into(),
        "cuboid" => {
            let axes = points("half_axes")?;
            let [u, v, w] = axes[..] else {
                bail!(
                    "half_axes: expected 3 vectors [U, V, W], found {}",
                    axes.len()
                );
            };
            Cuboid::new(point("center")?, [u.coords, v.coords, w.coords])?.into()
        }
        "halfspace" => HalfSpace::new(point("point")?, point("normal")?.coords)?.into(),
        "convex" => ConvexHull::new(points("points")?)?.into(),
        "triangle" => {
            let p = points("points")?;
            let [a, b, c] = p[..] else {
                bail!("points: expected 3 points, found {}", p.len());
            };
            Triangle::new(a, b, c)?.into()
        }
        "segment" => {
            let p = points("points")?;
            let [a, b] = p[..] else {
                bail!("points: expected 2 points, found {}", p.len());
            };
            Segment::new(a, b)?.into()
        }
        _ => bail!("unknown shape kind `{kind}`"),
    })
}

fn field<'a>(body: &'a Map<String, Value>, name: &str) -> Result<&'a Value> {
    body.get(name)
        .with_context(|| format!("missing field `{name}`"))
}

fn number(v: &Value) -> Result<f64> {
    v.as_f64()
        .filter(|x| x.is_finite())
        .with_context(|| format!("expected a finite number, found {}", brief(v)))
}

fn point(v: &Value) -> Result<Point3<f64>> {
    let list = v
        .as_array()
        .filter(|a| a.len() == 3)
        .with_context(|| format!("expected [x, y, z], found {}", brief(v)))?;
    let [x, y, z] = [0, 1, 2].map(|k| number(&list[k]));
    Ok(Point3::new(x?, y?, z?))
}

fn kinds() -> String {
    KINDS.iter().map(|(k, _)| *k).collect::<Vec<_>>().join(", ")
}

/// A value as written, cut short.
fn brief(v: &Value) -> String {
    let s = v.to_string();
    if s.chars().count() > 60 {
        format!("{}…", s.chars().take(60).collect::<String>())
    } else {
        s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn every_kind_is_read() {
        let p = json!([0.0, 0.0, 0.0]);
        let q = json!([1.0, 0.0, 0.0]);
        let r = json!([0.0, 1.0, 0.0]);
        let cases = [
            (json!({"ball": {"center": p, "radius": 1.0}}), "ball"),
            (
                json!({"capsule": {"a": p, "b": q, "radius": 0.5}}),
                "capsule",
            ),
            (
                json!({"cylinder": {"a": p, "b": q, "radius": 0.5}}),
                "cylinder",
            ),
            (
                json!({"cone": {"apex": p, "base": q, "radius": 0.5}}),
                "cone",
            ),
            (
                json!({"cuboid": {"center": p, "half_axes": [q, r, [0, 0, 1]]}}),
                "cuboid",
            ),
            (
                json!({"halfspace": {"point": p, "normal": [0, 0, 1]}}),
                "halfspace",
            ),
            (json!({"convex": {"points": [p, q, r]}}), "convex"),
            (json!({"triangle": {"points": [p, q, r]}}), "triangle"),
            (json!({"segment": {"points": [p, q]}}), "segment"),
        ];
        for (value, kind) in cases {
            assert_eq!(parse_shape(&value).unwrap().kind(), kind, "{value}");
        }
    }

    #[test]
    fn mistakes_are_named() {
        let message = |v: Value| format!("{:#}", parse_shape(&v).unwrap_err());
        let m = message(json!({"ball": {"centre": [0, 0, 0], "radius": 1}}));
        assert!(m.contains("unknown field `centre`"), "{m}");
        let m = message(json!({"ball": {"center": [0, 0], "radius": 1}}));
        assert!(m.contains("center") && m.contains("[x, y, z]"), "{m}");
        let m = message(json!({"sphere": {}}));
        assert!(m.contains("unknown shape kind `sphere`"), "{m}");
        let m = message(json!({"ball": {"center": [0, 0, 0], "radius": -1}}));
        assert!(m.contains("negative"), "{m}");
        let m = message(json!({"triangle": {"points": [[0, 0, 0], [1, 0, 0]]}}));
        assert!(m.contains("expected 3 points"), "{m}");
        let m = message(json!({"cylinder": {"a": [0, 0, 0], "b": [0, 0, 0], "radius": 1}}));
        assert!(m.contains("coincide"), "{m}");
        let m = message(json!({"convex": {"points": [[0, 0, 0], [1, "x", 0]]}}));
        assert!(m.contains("points[1]"), "{m}");
        let m = message(json!([1, 2]));
        assert!(m.contains("one key"), "{m}");
    }

    #[test]
    fn numbers_are_the_nearest_f64() {
        let v: Value =
            serde_json::from_str(r#"{"ball": {"center": [0.1, 1e-320, 3], "radius": 0.3}}"#)
                .unwrap();
        let Shape::Ball(b) = parse_shape(&v).unwrap() else {
            panic!("a ball")
        };
        assert_eq!(*b.centre(), Point3::new(0.1, 1e-320, 3.0));
        assert_eq!(b.radius(), 0.3);
    }
}
