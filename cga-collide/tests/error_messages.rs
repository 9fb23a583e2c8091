//! Every public error type's message says what was wrong, where (file, line, argument, index)
//! and what to do about it.

use cga_collide::collider::Collider;
use cga_collide::hierarchy::double_sphere::{DoubleSphereTree, InnerSphereKind, MAX_LEVEL};
use cga_collide::hierarchy::sphere_tree::format::read;
use cga_collide::hierarchy::sphere_tree::octree::{build, BuildOptions, MAX_DEPTH};
use cga_collide::mesh::{MeshFormat, TriMesh};
use cga_collide::nalgebra::{Isometry3, Point3, Quaternion, Translation3, UnitQuaternion};
use cga_collide::shape::polyhedron::ConvexPolyhedron;
use cga_collide::{Ball, Segment, Sphere};

/// Panics unless `message` contains every one of `parts`.
fn says(message: impl std::fmt::Display, parts: &[&str]) {
    let message = message.to_string();
    for part in parts {
        assert!(message.contains(part), "{part:?} missing from: {message}");
    }
}

fn off(text: &str) -> String {
    TriMesh::from_bytes(text.as_bytes(), MeshFormat::Off, "part.off")
        .expect_err("malformed")
        .to_string()
}

#[test]
fn mesh_files_name_the_file_the_line_and_the_fix() {
    // A malformed number: file, line, the token, what was expected.
    says(
        off("OFF\n3 1 0\n0 0 0\n1 nope 0\n0 1 0\n3 0 1 2\n"),
        &["part.off:4:", "nope", "expected"],
    );
    // A non-finite coordinate: where, which vertex, and that coordinates must be finite.
    says(
        off("OFF\n3 1 0\n0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n"),
        &["part.off:4", "vertex 1", "inf", "must be a finite number"],
    );
    // A face index past the vertices.
    says(
        off("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
        &["part.off:6", "face 0", "index 7", "3 vertices", "check"],
    );
    // No triangles at all.
    says(
        off("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"),
        &[
            "part.off",
            "empty",
            "no triangles",
            "check that the file has faces",
        ],
    );
    // Truncated.
    says(
        off("OFF\n3 1 0\n0 0 0\n1 0 0\n"),
        &["part.off", "truncated", "expected"],
    );
    // A missing file: its name once, the OS's reason, what to check.
    let e = TriMesh::load("no/such/mesh.obj").unwrap_err().to_string();
    assert_eq!(e.matches("no/such/mesh.obj").count(), 1, "{e}");
    says(&e, &["cannot read the file", "check the path"]);
    let e = TriMesh::load("mesh.xyz").unwrap_err();
    says(
        e,
        &[
            "mesh.xyz",
            "unknown mesh format",
            ".obj, .off, .ply or .stl",
        ],
    );
    says(
        TriMesh::cuboid(Point3::new(0.0, 0.0, 0.0), Point3::new(1.0, -1.0, 1.0)).unwrap_err(),
        &["axis 1", "min 0", "max -1", "min <= max"],
    );
}

#[test]
fn shapes_name_the_constructor_the_argument_and_the_rule() {
    let p = Point3::new(0.0, 0.0, 0.0);
    says(
        Segment::new(p, Point3::new(1.0, f64::NAN, 0.0)).unwrap_err(),
        &[
            "Segment::new",
            "`b`",
            "y coordinate",
            "NaN",
            "must be finite",
        ],
    );
    says(
        Sphere::new(p, -1.0).unwrap_err(),
        &[
            "Sphere::new",
            "radius is negative",
            "-1",
            "finite radius >= 0",
        ],
    );
    says(
        Ball::new(p, f64::INFINITY).unwrap_err(),
        &[
            "Ball::new",
            "radius is not finite",
            "inf",
            "finite radius >= 0",
        ],
    );
}

#[test]
fn poses_say_which_component_is_wrong_and_how_to_fix_it() {
    let c = Collider::new(TriMesh::bunny());
    let id = Isometry3::identity();
    let nan = Isometry3::from_parts(
        Translation3::new(f64::NAN, 0.0, 0.0),
        UnitQuaternion::identity(),
    );
    says(
        c.collides_at(&id, &c, &nan).unwrap_err(),
        &["non-finite", "translation", "must be a finite number"],
    );
    // A quaternion of squared length 9, not normalised.
    let long = Isometry3::from_parts(
        Translation3::identity(),
        UnitQuaternion::new_unchecked(Quaternion::new(3.0, 0.0, 0.0, 0.0)),
    );
    says(
        c.collides_at(&id, &c, &long).unwrap_err(),
        &["not a unit quaternion", "9", "normalise"],
    );
}

#[test]
fn hierarchies_say_the_limit_and_what_to_choose() {
    let cube = ConvexPolyhedron::cube();
    says(
        DoubleSphereTree::build(&cube, MAX_LEVEL + 1, InnerSphereKind::Centroid).unwrap_err(),
        &[
            &format!("level {}", MAX_LEVEL + 1),
            &format!("0 to {MAX_LEVEL}"),
        ],
    );
    let bunny = Collider::new(TriMesh::bunny());
    says(
        build(&bunny, &BuildOptions::depth(MAX_DEPTH + 1)).unwrap_err(),
        &[
            &format!("depth {}", MAX_DEPTH + 1),
            &format!("0 to {MAX_DEPTH}"),
        ],
    );
    let one = TriMesh::new(
        vec![p(0.0, 0.0, 0.0), p(1.0, 0.0, 0.0), p(0.0, 1.0, 0.0)],
        vec![[0, 1, 2]],
    )
    .unwrap();
    says(
        build(&Collider::new(one), &BuildOptions::depth(2)).unwrap_err(),
        &["not closed", "close its holes"],
    );
    says(
        ConvexPolyhedron::by_name("dodecahedron").unwrap_err(),
        &["dodecahedron", "known: cube"],
    );
}

fn p(x: f64, y: f64, z: f64) -> Point3<f64> {
    Point3::new(x, y, z)
}

#[test]
fn sphere_tree_files_name_the_line() {
    // Two trees declared, the second's root radius is not a number.
    says(
        read("2\n0 0 0 1 0\n0 8\n0 0 0 x 0\n").unwrap_err(),
        &["line 4", "expected", "`0 0 0 x 0`"],
    );
    // The input stops inside a tree.
    says(
        read("2\n0 0 0 1 0\n0 8\n").unwrap_err(),
        &[
            "input ends after line 3",
            "expected",
            "1 of 2 trees complete",
        ],
    );
    // A negative radius: the line, the field and the rule.
    says(
        read("1\n0 0 0 -1 0\n0 8\n").unwrap_err(),
        &["line 2", "non-negative radius", "not -1"],
    );
}

#[cfg(feature = "gpu")]
#[test]
fn gpu_errors_say_what_to_install_or_change() {
    use cga_collide::Error;
    says(
        Error::NoGpuAdapter,
        &["no GPU adapter", "WGPU_BACKEND", "mesa-vulkan-drivers"],
    );
    says(
        Error::GpuNoF64 {
            device: "llvmpipe".into(),
        },
        &["llvmpipe", "SHADER_F64", "Precision::F32"],
    );
    says(
        Error::GpuBufferTooLarge {
            what: "mesh B",
            bytes: 10,
            limit: 5,
        },
        &["mesh B", "10 bytes", "limit of 5 bytes", "split"],
    );
}

#[test]
fn binary_garbage_named_obj_says_it_is_not_obj_text() {
    let e = TriMesh::from_bytes(
        b"garbage\n\xff\xfe\x00 binary\n",
        MeshFormat::Obj,
        "garbage.obj",
    )
    .expect_err("not an OBJ file");
    says(e, &["garbage.obj:", "not OBJ text", "UTF-8"]);
}
