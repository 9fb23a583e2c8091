//! Loader tests: every format, its errors, agreement between formats, and malformed input.

use cga_collide::shape::mesh::{MeshFormat, TriMesh};
use cga_collide::Error;
use nalgebra::Point3;
use proptest::prelude::*;

fn off_text(m: &TriMesh) -> String {
    let mut s = format!("OFF\n{} {} 0\n", m.vertices().len(), m.num_triangles());
    for v in m.vertices() {
        s += &format!("{:?} {:?} {:?}\n", v.x, v.y, v.z);
    }
    for t in m.triangles() {
        s += &format!("3 {} {} {}\n", t[0], t[1], t[2]);
    }
    s
}

fn obj_text(m: &TriMesh) -> String {
    let mut s = String::from("# test\no thing\n");
    for v in m.vertices() {
        s += &format!("v {:?} {:?} {:?}\n", v.x, v.y, v.z);
    }
    for t in m.triangles() {
        s += &format!("f {} {} {}\n", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    s
}

fn ply_header(m: &TriMesh, format: &str) -> String {
    format!(
        "ply\nformat {format} 1.0\ncomment made by a test\nelement vertex {}\nproperty double x\n\
         property double y\nproperty double z\nproperty uchar red\nelement face {}\n\
         property list uchar int vertex_indices\nend_header\n",
        m.vertices().len(),
        m.num_triangles()
    )
}

fn ply_ascii(m: &TriMesh) -> Vec<u8> {
    let mut s = ply_header(m, "ascii");
    for v in m.vertices() {
        s += &format!("{:?} {:?} {:?} 7\n", v.x, v.y, v.z);
    }
    for t in m.triangles() {
        s += &format!("3 {} {} {}\n", t[0], t[1], t[2]);
    }
    s.into_bytes()
}

fn ply_binary(m: &TriMesh, big: bool) -> Vec<u8> {
    let mut out = ply_header(
        m,
        if big {
            "binary_big_endian"
        } else {
            "binary_little_endian"
        },
    )
    .into_bytes();
    let f = |x: f64| {
        if big {
            x.to_be_bytes()
        } else {
            x.to_le_bytes()
        }
    };
    let i = |x: u32| {
        if big {
            x.to_be_bytes()
        } else {
            x.to_le_bytes()
        }
    };
    for v in m.vertices() {
        for c in [v.x, v.y, v.z] {
            out.extend(f(c));
        }
        out.push(7);
    }
    for t in m.triangles() {
        out.push(3);
        for &k in t {
            out.extend(i(k));
        }
    }
    out
}

fn stl_binary(m: &TriMesh) -> Vec<u8> {
    let mut out = vec![0u8; 80];
    out.extend((m.num_triangles() as u32).to_le_bytes());
    for k in 0..m.num_triangles() {
        out.extend([0u8; 12]);
        for p in m.corners(k as u32) {
            for c in [p.x, p.y, p.z] {
                out.extend((c as f32).to_le_bytes());
            }
        }
        out.extend([0u8; 2]);
    }
    out
}

fn stl_ascii(m: &TriMesh) -> Vec<u8> {
    let mut s = String::from("solid test\n");
    for k in 0..m.num_triangles() {
        s += "  facet normal 0 0 1\n    outer loop\n";
        for p in m.corners(k as u32) {
            s += &format!(
                "      vertex {:?} {:?} {:?}\n",
                p.x as f32, p.y as f32, p.z as f32
            );
        }
        s += "    endloop\n  endfacet\n";
    }
    s += "endsolid test\n";
    s.into_bytes()
}

/// Same triangles, corner by corner (OBJ and STL renumber vertices).
fn same_geometry(a: &TriMesh, b: &TriMesh) -> bool {
    a.num_triangles() == b.num_triangles()
        && (0..a.num_triangles()).all(|k| a.corners(k as u32) == b.corners(k as u32))
}

fn tetra() -> TriMesh {
    TriMesh::new(
        vec![
            Point3::new(0.0, 0.0, 0.0),
            Point3::new(1.0, 0.0, 0.0),
            Point3::new(0.0, 1.5, 0.0),
            Point3::new(0.0, 0.0, -2.25),
        ],
        vec![[0, 2, 1], [0, 1, 3], [1, 2, 3], [0, 3, 2]],
    )
    .unwrap()
}

#[test]
fn builtin_meshes_load() {
    let bunny = TriMesh::bunny();
    assert_eq!(bunny.num_triangles(), 3674);
    let b00 = TriMesh::bunny00();
    assert_eq!((b00.vertices().len(), b00.num_triangles()), (37706, 75408));
    let arm = TriMesh::armadillo();
    assert_eq!((arm.vertices().len(), arm.num_triangles()), (26002, 52000));
}

#[test]
fn subdivision_quadruples_and_keeps_closed() {
    let t = tetra();
    let s = t.subdivided();
    assert_eq!(s.num_triangles(), 16);
    assert_eq!(s.vertices().len(), 4 + 6);
    // closed: every undirected edge used exactly twice, with opposite orientations
    let mut edges = std::collections::HashMap::new();
    for tri in s.triangles() {
        for k in 0..3 {
            *edges.entry((tri[k], tri[(k + 1) % 3])).or_insert(0) += 1;
        }
    }
    for (&(a, b), &n) in &edges {
        assert_eq!(n, 1);
        assert_eq!(edges.get(&(b, a)), Some(&1));
    }
    assert_eq!(t.subdivided_to(17).num_triangles(), 64);
    assert_eq!(
        TriMesh::bunny_with_at_least(10_000).num_triangles(),
        3674 * 4
    );
}

#[test]
fn all_formats_agree_on_a_mesh() {
    let m = tetra();
    let cases: Vec<(Vec<u8>, MeshFormat)> = vec![
        (off_text(&m).into_bytes(), MeshFormat::Off),
        (ply_ascii(&m), MeshFormat::Ply),
        (ply_binary(&m, false), MeshFormat::Ply),
        (ply_binary(&m, true), MeshFormat::Ply),
    ];
    for (bytes, format) in cases {
        let got = TriMesh::from_bytes(&bytes, format, "t").unwrap();
        assert_eq!(got, m, "{format:?}");
    }
    let got = TriMesh::from_bytes(obj_text(&m).as_bytes(), MeshFormat::Obj, "t.obj").unwrap();
    assert!(same_geometry(&got, &m));
    // STL re-indexes (welds) corners, so compare triangle coordinates.
    for bytes in [stl_binary(&m), stl_ascii(&m)] {
        let got = TriMesh::from_bytes(&bytes, MeshFormat::Stl, "t.stl").unwrap();
        assert_eq!(got.vertices().len(), 4);
        for k in 0..4 {
            assert_eq!(got.corners(k), m.corners(k));
        }
    }
}

#[test]
fn off_variants() {
    let text = "# comment\nCOFF 5 2 0 # counts on the header line\n\
                0 0 0 255 0 0 255\n1 0 0 1 2 3 4\n1 1 0 1 1 1 1\n0 1 0 0 0 0 0\n0 0 1\n\
                \n4 0 1 2 3 200 10 10\n3 0 1 4 # a triangle\n";
    let m = TriMesh::from_bytes(text.as_bytes(), MeshFormat::Off, "c.off").unwrap();
    assert_eq!(m.triangles(), &[[0, 1, 2], [0, 2, 3], [0, 1, 4]]);
    // degenerate triangles are kept
    let deg = "OFF\n2 1 0\n0 0 0\n1 1 1\n3 0 1 1\n";
    let m = TriMesh::from_bytes(deg.as_bytes(), MeshFormat::Off, "d.off").unwrap();
    assert_eq!(m.triangles(), &[[0, 1, 1]]);
}

fn off_err(text: &str) -> Error {
    TriMesh::from_bytes(text.as_bytes(), MeshFormat::Off, "bad.off").unwrap_err()
}

#[test]
fn off_errors_name_file_line_and_index() {
    let e = off_err("OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n");
    assert!(matches!(&e, Error::BadNumber { at, token, .. } if at.line == Some(4) && token == "x"));
    assert!(e.to_string().starts_with("bad.off:4:"), "{e}");

    let e = off_err("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n");
    assert!(
        matches!(&e, Error::IndexOutOfRange { at, face: 0, index: 3, vertex_count: 3 } if at.line == Some(6)),
        "{e}"
    );

    let e = off_err("OFF\n3 1 0\n0 0 0\n1 inf 0\n0 1 0\n3 0 1 2\n");
    assert!(
        matches!(&e, Error::NonFinite { at, vertex: 1, .. } if at.line == Some(4)),
        "{e}"
    );

    let e = off_err("OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n");
    assert!(
        matches!(&e, Error::Empty { file } if file == "bad.off"),
        "{e}"
    );

    let e = off_err("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n");
    assert!(matches!(&e, Error::Truncated { .. }), "{e}");
    assert!(e.to_string().contains("face 1 of 2"), "{e}");

    let e = off_err("OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n");
    assert!(
        matches!(&e, Error::Syntax { at, .. } if at.line == Some(6)),
        "{e}"
    );

    let e = off_err("OFF\n99999999999999999999999 1 0\n");
    assert!(matches!(&e, Error::BadNumber { .. }), "{e}");
    // a lying header must not make us allocate or loop absurdly
    let e = off_err("OFF\n18446744073709551615 18446744073709551615 0\n0 0 0\n");
    assert!(matches!(&e, Error::Truncated { .. }), "{e}");
}

#[test]
fn obj_errors_name_the_line() {
    let bad = "v 0 0 0\nv 1 0 0\nv 0 1 0\n# ok so far\nf 1 2 4\n";
    let e = TriMesh::from_bytes(bad.as_bytes(), MeshFormat::Obj, "bad.obj").unwrap_err();
    assert!(e.to_string().starts_with("bad.obj:5:"), "{e}");
    let bad = "v 0 0 0\nv 1 zz 0\nv 0 1 0\nf 1 2 3\n";
    let e = TriMesh::from_bytes(bad.as_bytes(), MeshFormat::Obj, "bad.obj").unwrap_err();
    assert!(e.to_string().starts_with("bad.obj:2:"), "{e}");
    // A NaN or infinite coordinate: the line and the vertex's place among the `v` statements,
    // as the OFF reader gives them (tobj reports neither).
    for (value, shown) in [("nan", "NaN"), ("-inf", "-inf")] {
        let bad = format!("v 0 0 0\n# a comment\nv 1 {value} 0\nv 0 1 0\nf 1 2 3\n");
        let e = TriMesh::from_bytes(bad.as_bytes(), MeshFormat::Obj, "bad.obj").unwrap_err();
        assert!(
            matches!(&e, Error::NonFinite { at, vertex: 1, .. } if at.line == Some(3)),
            "{e}"
        );
        assert!(e.to_string().starts_with("bad.obj:3: vertex 1"), "{e}");
        assert!(e.to_string().contains(shown), "{e}");
    }
    // quads are fan-triangulated, negative (relative) indices resolved
    let quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf -4 -3 -2 -1\n";
    let m = TriMesh::from_bytes(quad.as_bytes(), MeshFormat::Obj, "q.obj").unwrap();
    assert_eq!(m.num_triangles(), 2);
    let e = TriMesh::from_bytes(b"v 0 0 0\n", MeshFormat::Obj, "e.obj").unwrap_err();
    assert!(matches!(e, Error::Empty { .. }), "{e}");
}

#[test]
fn ply_and_stl_errors() {
    let m = tetra();
    let bin = ply_binary(&m, false);
    let e = TriMesh::from_bytes(&bin[..bin.len() - 3], MeshFormat::Ply, "t.ply").unwrap_err();
    assert!(
        matches!(&e, Error::Truncated { at, .. } if at.byte.is_some()),
        "{e}"
    );
    assert!(e.to_string().contains("face 3 of 4"), "{e}");
    let ascii = String::from_utf8(ply_ascii(&m))
        .unwrap()
        .replace("3 1 2 3", "3 1 2 9");
    let e = TriMesh::from_bytes(ascii.as_bytes(), MeshFormat::Ply, "t.ply").unwrap_err();
    assert!(
        matches!(&e, Error::IndexOutOfRange { face: 2, index: 9, at, .. } if at.line == Some(17)),
        "{e}"
    );
    let e = TriMesh::from_bytes(
        b"ply\nformat ascii 1.0\nelement vertex 99999999999999999999999\n",
        MeshFormat::Ply,
        "t.ply",
    )
    .unwrap_err();
    assert!(
        matches!(&e, Error::BadNumber { at, .. } if at.line == Some(3)),
        "{e}"
    );

    let stl = stl_binary(&m);
    let e = TriMesh::from_bytes(&stl[..stl.len() - 10], MeshFormat::Stl, "t.stl").unwrap_err();
    assert!(matches!(&e, Error::Truncated { .. }), "{e}");
    let ascii = String::from_utf8(stl_ascii(&m))
        .unwrap()
        .replacen("vertex 1.0", "vertex 1.q", 1);
    let e = TriMesh::from_bytes(ascii.as_bytes(), MeshFormat::Stl, "t.stl").unwrap_err();
    assert!(
        matches!(&e, Error::BadNumber { at, .. } if at.line.is_some()),
        "{e}"
    );
}

#[test]
fn format_from_extension() {
    use std::path::Path;
    assert_eq!(
        MeshFormat::from_path(Path::new("a/b.OFF")),
        Some(MeshFormat::Off)
    );
    assert_eq!(
        MeshFormat::from_path(Path::new("b.ply.gz")),
        Some(MeshFormat::Ply)
    );
    assert_eq!(MeshFormat::from_path(Path::new("b.txt")), None);
    let e = TriMesh::load("nowhere/b.txt").unwrap_err();
    assert!(matches!(e, Error::UnknownFormat { .. }), "{e}");
    let e = TriMesh::load("nowhere/b.stl").unwrap_err();
    assert!(matches!(e, Error::Io { .. }), "{e}");
}

/// Valid seed files of every format, from a small random mesh.
fn seeds(m: &TriMesh) -> Vec<(Vec<u8>, MeshFormat)> {
    use std::io::Write;
    let mut gz = flate2::write::GzEncoder::new(Vec::new(), flate2::Compression::fast());
    gz.write_all(off_text(m).as_bytes()).unwrap();
    vec![
        (gz.finish().unwrap(), MeshFormat::Off),
        (off_text(m).into_bytes(), MeshFormat::Off),
        (obj_text(m).into_bytes(), MeshFormat::Obj),
        (ply_ascii(m), MeshFormat::Ply),
        (ply_binary(m, false), MeshFormat::Ply),
        (ply_binary(m, true), MeshFormat::Ply),
        (stl_binary(m), MeshFormat::Stl),
        (stl_ascii(m), MeshFormat::Stl),
    ]
}

#[derive(Debug, Clone)]
enum Mutation {
    Truncate(usize),
    Flip(usize, u8),
    Insert(usize, u8),
    Delete(usize),
    Splice(usize, &'static str),
}

fn mutation() -> impl Strategy<Value = Mutation> {
    let tokens = prop::sample::select(vec![
        "-1",
        "nan",
        "inf",
        "1e999",
        "99999999999999999999",
        "4294967295",
        "\n",
        " ",
        "#",
        "3",
        "0",
        "x",
        "end_header\n",
        "endloop",
        "outer loop",
        "-",
        ".",
        "\u{0}",
        "OFF",
        "f",
        "v",
    ]);
    prop_oneof![
        any::<usize>().prop_map(Mutation::Truncate),
        (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Mutation::Flip(i, b)),
        (any::<usize>(), any::<u8>()).prop_map(|(i, b)| Mutation::Insert(i, b)),
        any::<usize>().prop_map(Mutation::Delete),
        (any::<usize>(), tokens).prop_map(|(i, t)| Mutation::Splice(i, t)),
    ]
}

fn apply(bytes: &mut Vec<u8>, m: &Mutation) {
    let n = bytes.len().max(1);
    match *m {
        Mutation::Truncate(i) => bytes.truncate(i % n),
        Mutation::Flip(i, b) => {
            if !bytes.is_empty() {
                bytes[i % n] ^= b;
            }
        }
        Mutation::Insert(i, b) => bytes.insert(i % (bytes.len() + 1), b),
        Mutation::Delete(i) => {
            if !bytes.is_empty() {
                bytes.remove(i % n);
            }
        }
        Mutation::Splice(i, t) => {
            let at = i % (bytes.len() + 1);
            bytes.splice(at..at, t.bytes());
        }
    }
}

fn small_mesh() -> impl Strategy<Value = TriMesh> {
    (3usize..7).prop_flat_map(|nv| {
        (
            prop::collection::vec((-4i32..5, -4i32..5, -4i32..5), nv),
            prop::collection::vec((0..nv as u32, 0..nv as u32, 0..nv as u32), 1..6),
        )
            .prop_map(|(vs, ts)| {
                let vs = vs
                    .into_iter()
                    .map(|(x, y, z)| Point3::new(x as f64 * 0.5, y as f64 * 0.25, z as f64))
                    .collect();
                TriMesh::new(vs, ts.into_iter().map(|(a, b, c)| [a, b, c]).collect()).unwrap()
            })
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(300))]

    /// Random meshes round-trip through every format.
    #[test]
    fn formats_round_trip(m in small_mesh()) {
        for (bytes, format) in seeds(&m).into_iter().take(6) {
            let got = TriMesh::from_bytes(&bytes, format, "rt").unwrap();
            if format == MeshFormat::Obj {
                prop_assert!(same_geometry(&got, &m));
            } else {
                prop_assert_eq!(&got, &m, "{:?}", format);
            }
        }
        for bytes in [stl_binary(&m), stl_ascii(&m)] {
            let got = TriMesh::from_bytes(&bytes, MeshFormat::Stl, "rt.stl").unwrap();
            prop_assert!(same_geometry(&got, &m));
        }
    }

    /// Mutated and truncated files: every loader returns Ok or Err, never panics.
    #[test]
    fn malformed_input_never_panics(m in small_mesh(), muts in prop::collection::vec(mutation(), 1..5)) {
        for (mut bytes, format) in seeds(&m) {
            for mu in &muts {
                apply(&mut bytes, mu);
            }
            for f in [format, MeshFormat::Off, MeshFormat::Obj, MeshFormat::Ply, MeshFormat::Stl] {
                let _ = TriMesh::from_bytes(&bytes, f, "fuzz");
            }
        }
    }
}
