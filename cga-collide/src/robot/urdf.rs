//! Reading a URDF (and an SRDF's `disable_collisions`) into plain descriptions: links with
//! their collision elements, joints with their origins, axes and limits. Nothing is loaded or
//! checked against the kinematic tree here (see [`super::Robot::from_urdf_str`]); every error
//! names the file, the line and the element.

use nalgebra::{Isometry3, Translation3, UnitQuaternion, Vector3};
use roxmltree::{Document, Node};

use crate::error::Error;

/// A collision element's geometry as written.
#[derive(Debug, Clone, PartialEq)]
pub(super) enum GeometrySpec {
    /// `<box size="x y z"/>`: full side lengths, centred.
    Box([f64; 3]),
    /// `<cylinder radius length/>`: along z, centred.
    Cylinder { radius: f64, length: f64 },
    /// `<capsule radius length/>`: the cylinder's axis (along z, centred) grown by the radius.
    Capsule { radius: f64, length: f64 },
    /// `<sphere radius/>`.
    Sphere(f64),
    /// `<mesh filename scale/>`.
    Mesh { filename: String, scale: [f64; 3] },
}

/// One `<collision>` element.
#[derive(Debug, Clone)]
pub(super) struct CollisionSpec {
    pub origin: Isometry3<f64>,
    pub geometry: GeometrySpec,
    /// `FILE:LINE: <collision>` of the element, for errors found later (a mesh not found).
    pub at: String,
}

/// One `<link>`.
#[derive(Debug, Clone)]
pub(super) struct LinkSpec {
    pub name: String,
    pub collisions: Vec<CollisionSpec>,
}

/// A joint's type; `Fixed` joins two links into one rigid body.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum JointKind {
    /// A rotation about the axis, within limits.
    Revolute,
    /// A rotation about the axis, without limits.
    Continuous,
    /// A translation along the axis, within limits.
    Prismatic,
    /// No motion: parent and child are one rigid body.
    Fixed,
}

/// One `<joint>`.
#[derive(Debug, Clone)]
pub(super) struct JointSpec {
    pub name: String,
    pub kind: JointKind,
    pub parent: String,
    pub child: String,
    pub origin: Isometry3<f64>,
    pub axis: Vector3<f64>,
    pub limits: Option<(f64, f64)>,
    pub at: String,
}

/// A parsed URDF.
#[derive(Debug, Clone)]
pub(super) struct UrdfSpec {
    pub links: Vec<LinkSpec>,
    pub joints: Vec<JointSpec>,
}

/// `FILE:LINE: <tag name="...">` of a node.
pub(super) fn place(file: &str, doc: &Document, node: Node) -> String {
    let line = doc.text_pos_at(node.range().start).row;
    let tag = node.tag_name().name();
    match node.attribute("name") {
        Some(name) => format!("{file}:{line}: <{tag} name=\"{name}\">"),
        None => format!("{file}:{line}: <{tag}>"),
    }
}

pub(super) fn model_error(at: String, reason: impl Into<String>) -> Error {
    Error::RobotModel {
        at,
        reason: reason.into(),
    }
}

/// Parses an XML document, naming the file on a syntax error.
pub(super) fn document<'a>(file: &str, text: &'a str) -> Result<Document<'a>, Error> {
    Document::parse(text).map_err(|e| model_error(file.to_string(), format!("not valid XML: {e}")))
}

/// A required attribute.
fn attr<'a>(file: &str, doc: &Document, node: Node<'a, '_>, name: &str) -> Result<&'a str, Error> {
    node.attribute(name).ok_or_else(|| {
        model_error(
            place(file, doc, node),
            format!("missing attribute `{name}`"),
        )
    })
}

/// `count` finite numbers separated by white space.
fn numbers<const N: usize>(
    file: &str,
    doc: &Document,
    node: Node,
    name: &str,
    text: &str,
) -> Result<[f64; N], Error> {
    let bad = || {
        model_error(
            place(file, doc, node),
            format!("attribute `{name}` = {text:?} is not {N} finite number(s)"),
        )
    };
    let values: Vec<f64> = text
        .split_whitespace()
        .map(|w| w.parse::<f64>().ok().filter(|x| x.is_finite()))
        .collect::<Option<_>>()
        .ok_or_else(bad)?;
    values.try_into().map_err(|_| bad())
}

fn number(file: &str, doc: &Document, node: Node, name: &str) -> Result<f64, Error> {
    let text = attr(file, doc, node, name)?;
    Ok(numbers::<1>(file, doc, node, name, text)?[0])
}

fn positive(file: &str, doc: &Document, node: Node, name: &str) -> Result<f64, Error> {
    let x = number(file, doc, node, name)?;
    if x < 0.0 {
        return Err(model_error(
            place(file, doc, node),
            format!("attribute `{name}` is negative ({x}); give a length >= 0"),
        ));
    }
    Ok(x)
}

fn child<'a, 'i>(node: Node<'a, 'i>, tag: &str) -> Option<Node<'a, 'i>> {
    node.children().find(|c| c.has_tag_name(tag))
}

/// An `<origin xyz rpy>` (identity when absent; `rpy` is roll about x, then pitch about y, then
/// yaw about z, all about fixed axes).
fn origin(file: &str, doc: &Document, parent: Node) -> Result<Isometry3<f64>, Error> {
    let Some(node) = child(parent, "origin") else {
        return Ok(Isometry3::identity());
    };
    let xyz = match node.attribute("xyz") {
        Some(t) => numbers::<3>(file, doc, node, "xyz", t)?,
        None => [0.0; 3],
    };
    let rpy = match node.attribute("rpy") {
        Some(t) => numbers::<3>(file, doc, node, "rpy", t)?,
        None => [0.0; 3],
    };
    Ok(Isometry3::from_parts(
        Translation3::new(xyz[0], xyz[1], xyz[2]),
        UnitQuaternion::from_euler_angles(rpy[0], rpy[1], rpy[2]),
    ))
}

fn geometry(file: &str, doc: &Document, collision: Node) -> Result<GeometrySpec, Error> {
    let Some(g) = child(collision, "geometry") else {
        return Err(model_error(
            place(file, doc, collision),
            "missing <geometry>",
        ));
    };
    let Some(shape) = g.children().find(|c| c.is_element()) else {
        return Err(model_error(place(file, doc, g), "empty <geometry>"));
    };
    Ok(match shape.tag_name().name() {
        "box" => {
            let text = attr(file, doc, shape, "size")?;
            let size = numbers::<3>(file, doc, shape, "size", text)?;
            if size.iter().any(|s| *s < 0.0) {
                return Err(model_error(
                    place(file, doc, shape),
                    "a box side is negative; give sizes >= 0",
                ));
            }
            GeometrySpec::Box(size)
        }
        "cylinder" => GeometrySpec::Cylinder {
            radius: positive(file, doc, shape, "radius")?,
            length: positive(file, doc, shape, "length")?,
        },
        "capsule" => GeometrySpec::Capsule {
            radius: positive(file, doc, shape, "radius")?,
            length: positive(file, doc, shape, "length")?,
        },
        "sphere" => GeometrySpec::Sphere(positive(file, doc, shape, "radius")?),
        "mesh" => GeometrySpec::Mesh {
            filename: attr(file, doc, shape, "filename")?.to_string(),
            scale: match shape.attribute("scale") {
                Some(t) => numbers::<3>(file, doc, shape, "scale", t)?,
                None => [1.0; 3],
            },
        },
        other => {
            return Err(model_error(
                place(file, doc, shape),
                format!(
                    "unknown geometry <{other}> (expected box, cylinder, capsule, sphere or mesh)"
                ),
            ))
        }
    })
}

fn link(file: &str, doc: &Document, node: Node) -> Result<LinkSpec, Error> {
    let name = attr(file, doc, node, "name")?.to_string();
    let collisions = node
        .children()
        .filter(|c| c.has_tag_name("collision"))
        .map(|c| {
            Ok(CollisionSpec {
                origin: origin(file, doc, c)?,
                geometry: geometry(file, doc, c)?,
                at: place(file, doc, c),
            })
        })
        .collect::<Result<_, Error>>()?;
    Ok(LinkSpec { name, collisions })
}

fn joint(file: &str, doc: &Document, node: Node) -> Result<JointSpec, Error> {
    let at = place(file, doc, node);
    let name = attr(file, doc, node, "name")?.to_string();
    let kind = match attr(file, doc, node, "type")? {
        "revolute" => JointKind::Revolute,
        "continuous" => JointKind::Continuous,
        "prismatic" => JointKind::Prismatic,
        "fixed" => JointKind::Fixed,
        other => {
            return Err(model_error(
                at,
                format!(
                "joint type {other:?} is not supported (revolute, continuous, prismatic, fixed)"
            ),
            ))
        }
    };
    let link_of = |tag: &str| -> Result<String, Error> {
        let n = child(node, tag)
            .ok_or_else(|| model_error(at.clone(), format!("missing <{tag} link=...>")))?;
        Ok(attr(file, doc, n, "link")?.to_string())
    };
    let axis = match child(node, "axis").and_then(|a| a.attribute("xyz").map(|t| (a, t))) {
        Some((a, t)) => {
            let [x, y, z] = numbers::<3>(file, doc, a, "xyz", t)?;
            let v = Vector3::new(x, y, z);
            if kind != JointKind::Fixed && v.norm() == 0.0 {
                return Err(model_error(place(file, doc, a), "the joint axis is zero"));
            }
            v
        }
        None => Vector3::x(),
    };
    let limits = match (kind, child(node, "limit")) {
        (JointKind::Revolute | JointKind::Prismatic, Some(l)) => {
            let lower = match l.attribute("lower") {
                Some(_) => number(file, doc, l, "lower")?,
                None => 0.0,
            };
            let upper = match l.attribute("upper") {
                Some(_) => number(file, doc, l, "upper")?,
                None => 0.0,
            };
            if lower > upper {
                return Err(model_error(
                    place(file, doc, l),
                    format!("lower limit {lower} is above the upper limit {upper}"),
                ));
            }
            Some((lower, upper))
        }
        (JointKind::Revolute | JointKind::Prismatic, None) => {
            return Err(model_error(
                at,
                "a revolute or prismatic joint needs a <limit>",
            ))
        }
        _ => None,
    };
    Ok(JointSpec {
        parent: link_of("parent")?,
        child: link_of("child")?,
        origin: origin(file, doc, node)?,
        name,
        kind,
        axis,
        limits,
        at,
    })
}

/// Reads a URDF document (`file` names it in errors).
pub(super) fn parse_urdf(file: &str, text: &str) -> Result<UrdfSpec, Error> {
    let doc = document(file, text)?;
    let root = doc.root_element();
    if !root.has_tag_name("robot") {
        return Err(model_error(
            place(file, &doc, root),
            "the root element is not <robot>",
        ));
    }
    let mut links = Vec::new();
    let mut joints = Vec::new();
    for node in root.children().filter(|c| c.is_element()) {
        match node.tag_name().name() {
            "link" => links.push(link(file, &doc, node)?),
            "joint" => joints.push(joint(file, &doc, node)?),
            _ => {}
        }
    }
    Ok(UrdfSpec { links, joints })
}

/// The link pairs of an SRDF's `<disable_collisions link1 link2>`, each with its place.
pub(super) fn parse_srdf(file: &str, text: &str) -> Result<Vec<(String, String, String)>, Error> {
    let doc = document(file, text)?;
    doc.root_element()
        .children()
        .filter(|c| c.has_tag_name("disable_collisions"))
        .map(|n| {
            Ok((
                attr(file, &doc, n, "link1")?.to_string(),
                attr(file, &doc, n, "link2")?.to_string(),
                place(file, &doc, n),
            ))
        })
        .collect()
}
