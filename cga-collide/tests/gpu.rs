//! The GPU batches (feature `gpu`) against the CPU's exact answers, and the shaders they run.
//!
//! The shader checks need no device. The batch checks need an adapter: on a machine without a
//! GPU, Mesa's software Vulkan driver (lavapipe, package `mesa-vulkan-drivers`) is one. When no
//! adapter is found they fail if the `CI` environment variable is set, and are skipped with a
//! message otherwise.
#![cfg(feature = "gpu")]

use cga_collide::collider::{Collider, Mode};
use cga_collide::gpu::{shader_source, Device, Precision, Query};
use cga_collide::mesh::TriMesh;
use cga_collide::nalgebra::{Isometry3, Point3, Translation3, UnitQuaternion, Vector3};
use cga_collide::testing::adversarial::{adversarial_set, Case};
use cga_collide::Error;
use cga_collide::{Ball, Intersects, Segment, Sphere, Triangle};
use ga_core::cga::{self, wgsl};
use naga::valid::{Capabilities, ValidationFlags, Validator};

fn validate(src: &str, caps: Capabilities) {
    let module = naga::front::wgsl::parse_str(src)
        .unwrap_or_else(|e| panic!("WGSL does not parse:\n{}", e.emit_to_string(src)));
    Validator::new(ValidationFlags::all(), caps)
        .validate(&module)
        .unwrap_or_else(|e| panic!("WGSL does not validate:\n{}", e.emit_to_string(src)));
}

#[test]
fn batch_shader_validates_in_both_precisions() {
    validate(&shader_source(Precision::F32), Capabilities::empty());
    validate(&shader_source(Precision::F64), Capabilities::FLOAT64);
}

/// The device in `precision`, or `None` (skip) when there is no adapter outside CI.
fn device(precision: Precision) -> Option<Device> {
    match Device::with_precision(Some(precision)) {
        Ok(d) => {
            eprintln!("device: {} ({precision:?})", d.name());
            Some(d)
        }
        Err(e @ (Error::NoGpuAdapter | Error::GpuNoF64 { .. })) => {
            if std::env::var_os("CI").is_some() {
                panic!("CI needs a GPU adapter with f32 and f64 (lavapipe offers both): {e}");
            }
            eprintln!("skipped: {e}");
            None
        }
        Err(e) => panic!("{e}"),
    }
}

fn devices() -> Vec<Device> {
    [Precision::F64, Precision::F32]
        .into_iter()
        .filter_map(device)
        .collect()
}

/// A mesh of the given triangles (three fresh vertices each).
fn mesh_of(triangles: &[Triangle]) -> TriMesh {
    let vertices = triangles.iter().flat_map(|t| *t.vertices()).collect();
    let faces = (0..triangles.len() as u32)
        .map(|k| [3 * k, 3 * k + 1, 3 * k + 2])
        .collect();
    TriMesh::new(vertices, faces).expect("finite triangles")
}

#[test]
fn adversarial_set_gives_the_exact_answers() {
    let cases = adversarial_set(7, 40);
    for device in devices() {
        // Queries against triangles, every case its own pair, in one batch per kind.
        let queries: Vec<(Query, Triangle)> = cases
            .iter()
            .filter_map(|case| match *case {
                Case::SegTri(s, t) => Some((s.into(), t)),
                Case::TriTri(a, b) => Some((a.into(), b)),
                Case::TriSphere(t, s) => Some((s.into(), t)),
                Case::TriBall(t, b) => Some((b.into(), t)),
                _ => None,
            })
            .collect();
        let expected: Vec<usize> = cases
            .iter()
            .filter(|c| {
                matches!(
                    c,
                    Case::SegTri(..) | Case::TriTri(..) | Case::TriSphere(..) | Case::TriBall(..)
                )
            })
            .enumerate()
            .filter(|(_, c)| c.truth())
            .map(|(k, _)| k)
            .collect();
        let batch = device.pair_hits(&queries).expect("batch");
        assert_eq!(batch.hits, expected, "{}", device.name());
        let (tested, flagged) = (batch.tested, batch.flagged);
        // Triangle pairs as candidate pairs of two meshes, in one batch.
        let pairs: Vec<(Triangle, Triangle)> = cases
            .iter()
            .filter_map(|c| match *c {
                Case::TriTri(a, b) => Some((a, b)),
                _ => None,
            })
            .collect();
        let a = mesh_of(&pairs.iter().map(|p| p.0).collect::<Vec<_>>());
        let b = mesh_of(&pairs.iter().map(|p| p.1).collect::<Vec<_>>());
        let diagonal: Vec<(u32, u32)> = (0..pairs.len() as u32).map(|k| (k, k)).collect();
        let batch = device
            .intersecting_candidates(&a, &b, &diagonal)
            .expect("batch");
        let expected: Vec<(u32, u32)> = diagonal
            .iter()
            .copied()
            .filter(|&(k, _)| pairs[k as usize].0.intersects(&pairs[k as usize].1))
            .collect();
        assert_eq!(batch.hits, expected);
        eprintln!(
            "{}: {tested} adversarial pairs, {flagged} flagged and re-decided on the CPU",
            device.name()
        );
        assert!(tested > 100);
    }
}

/// A few hundred triangles of the bunny, scaled to the unit box.
fn small_bunny(n: usize) -> TriMesh {
    let bunny = TriMesh::bunny().unit();
    let tris: Vec<[u32; 3]> = bunny.triangles()[..n].to_vec();
    TriMesh::new(bunny.vertices().to_vec(), tris).expect("subset of a valid mesh")
}

fn placed(mesh: &TriMesh, angle: f64, shift: f64) -> TriMesh {
    let iso = Isometry3::from_parts(
        Translation3::new(shift, 0.5 * shift, 0.0),
        UnitQuaternion::from_axis_angle(&Vector3::y_axis(), angle),
    );
    mesh.transformed(&iso).expect("finite")
}

#[test]
fn mesh_pairs_match_the_cpu_brute_force_and_hierarchy() {
    let a = small_bunny(300);
    for device in devices() {
        for (angle, shift) in [(0.3, 0.02), (1.1, 0.1), (0.0, 0.0)] {
            let b = placed(&small_bunny(250), angle, shift);
            let (ca, cb) = (Collider::new(a.clone()), Collider::new(b.clone()));
            let expected = ca.clone().with_mode(Mode::Brute).intersecting_pairs(&cb);
            let all = device.intersecting_pairs(&a, &b).expect("batch");
            assert_eq!(all.hits, expected, "all pairs, angle {angle}");
            assert_eq!(all.tested, 300 * 250);
            let swapped = device.intersecting_pairs(&b, &a).expect("batch");
            let mut back: Vec<(u32, u32)> = swapped.hits.iter().map(|&(i, j)| (j, i)).collect();
            back.sort_unstable();
            assert_eq!(back, expected, "swapped meshes");
            let candidates = ca.box_pairs_bvh(&cb);
            let tree = device
                .intersecting_candidates(&a, &b, &candidates)
                .expect("batch");
            assert_eq!(tree.hits, expected, "candidate pairs, angle {angle}");
            eprintln!(
                "{}: angle {angle}: {} hits, {} of {} pairs flagged ({:.4} %)",
                device.name(),
                all.hits.len(),
                all.flagged,
                all.tested,
                100.0 * all.flagged_fraction()
            );
        }
    }
}

#[test]
fn queries_against_a_mesh_match_the_cpu() {
    let mesh = small_bunny(600);
    let collider = Collider::new(mesh.clone());
    let p = Point3::new;
    let segments = [
        Segment::new(p(-1.0, 0.1, 0.0), p(1.0, 0.1, 0.05)).unwrap(),
        Segment::new(p(0.0, -1.0, 0.0), p(0.0, 1.0, 0.0)).unwrap(),
        // Along an edge of the mesh: touching configurations.
        {
            let [a, b, _] = mesh.corners(5);
            Segment::new(a, b).unwrap()
        },
    ];
    let triangles = [
        Triangle::new(p(-1.0, 0.0, -1.0), p(1.0, 0.0, -1.0), p(0.0, 0.0, 1.0)).unwrap(),
        // One of the mesh's own triangles: shares vertices and edges with its neighbours.
        {
            let [a, b, c] = mesh.corners(10);
            Triangle::new(a, b, c).unwrap()
        },
    ];
    let centres = [p(0.0, 0.0, 0.0), p(0.1, 0.2, -0.1), mesh.corners(3)[0]];
    for device in devices() {
        for s in &segments {
            let batch = device.hits(&(*s).into(), &mesh).expect("batch");
            assert_eq!(
                batch.hits,
                collider.clone().with_mode(Mode::Brute).segment_hits(s),
                "{s:?}"
            );
        }
        for t in &triangles {
            let batch = device.hits(&(*t).into(), &mesh).expect("batch");
            assert_eq!(
                batch.hits,
                collider.clone().with_mode(Mode::Brute).triangle_hits(t),
                "{t:?}"
            );
        }
        for c in centres {
            for r in [0.05, 0.2, 0.5] {
                let s = Sphere::new(c, r).unwrap();
                let batch = device.hits(&s.into(), &mesh).expect("batch");
                assert_eq!(
                    batch.hits,
                    collider.clone().with_mode(Mode::Brute).sphere_hits(&s),
                    "{s:?}"
                );
                let b = Ball::new(c, r).unwrap();
                let batch = device.hits(&b.into(), &mesh).expect("batch");
                assert_eq!(
                    batch.hits,
                    collider.clone().with_mode(Mode::Brute).ball_hits(&b),
                    "{b:?}"
                );
            }
        }
    }
}

/// Every generated WGSL function, run on the device, agrees with the Rust product of the
/// dense generated multivector on random inputs.
#[test]
fn generated_functions_agree_with_the_rust_products() {
    use ga_core::ops::{
        Geometric, LeftContraction, Regressive, RightContraction, ScalarProduct, Wedge,
    };
    let samples = 64u32;
    let mut rng = cga_collide::testing::adversarial::SplitMix64(12);
    for device in devices() {
        let (source, tolerance) = match device.precision() {
            Precision::F64 => (wgsl::F64, 1e-12),
            Precision::F32 => (wgsl::F32, 1e-4),
        };
        for chunk in wgsl::FUNCTIONS.chunks(24) {
            let width_in: usize = chunk
                .iter()
                .map(|f| f.inputs.iter().map(|v| v.blades.len()).sum::<usize>())
                .sum();
            let width_out: usize = chunk.iter().map(|f| f.output.blades.len()).sum();
            let mut body = String::new();
            let (mut at_in, mut at_out) = (0, 0);
            for f in chunk {
                let mut args = Vec::new();
                for v in f.inputs {
                    let xs: Vec<String> = (0..v.blades.len())
                        .map(|k| format!("inp[ib + {}u]", at_in + k))
                        .collect();
                    at_in += v.blades.len();
                    args.push(if v.ty == "Scalar" {
                        xs[0].clone()
                    } else {
                        format!("{}({})", v.ty, xs.join(", "))
                    });
                }
                body += &format!("    {{\n        let r = {}({});\n", f.name, args.join(", "));
                if f.output.ty == "Scalar" {
                    body += &format!("        outp[ob + {at_out}u] = r;\n");
                } else {
                    for (k, field) in f.output.fields.iter().enumerate() {
                        body += &format!("        outp[ob + {}u] = r.{field};\n", at_out + k);
                    }
                }
                at_out += f.output.blades.len();
                body += "    }\n";
            }
            let shader = format!(
                "{source}\n@group(0) @binding(0) var<storage, read> inp: array<Scalar>;\n\
                 @group(0) @binding(1) var<storage, read_write> outp: array<Scalar>;\n\
                 @compute @workgroup_size(64)\n\
                 fn main(@builtin(global_invocation_id) id: vec3<u32>) {{\n\
                 if id.x >= {samples}u {{ return; }}\n\
                 let ib = id.x * {width_in}u;\n let ob = id.x * {width_out}u;\n{body}}}\n"
            );
            let input: Vec<f64> = (0..samples as usize * width_in)
                .map(|_| rng.float(-2.0, 2.0))
                .collect();
            let out = cga_collide::testing::gpu::evaluate(
                &device,
                &shader,
                "main",
                &input,
                samples as usize * width_out,
                samples,
            )
            .expect("evaluation");
            for s in 0..samples as usize {
                let (mut at_in, mut at_out) = (s * width_in, s * width_out);
                for f in chunk {
                    let mut operands = Vec::new();
                    for v in f.inputs {
                        let mut c = [0.0f64; 32];
                        for (k, &b) in v.blades.iter().enumerate() {
                            c[b] = input[at_in + k];
                        }
                        at_in += v.blades.len();
                        operands.push(cga::Multivector::from_coefficients(c));
                    }
                    let (a, b) = (operands[0], operands.get(1).copied());
                    let b = || b.expect("binary");
                    let scalar = |m: cga::Multivector<f64>| m.coefficients()[0];
                    let result: [f64; 32] = match f.operation {
                        "geometric" => a.geometric(&b()).coefficients(),
                        "wedge" => a.wedge(&b()).coefficients(),
                        "left_contraction" => a.left_contraction(&b()).coefficients(),
                        "right_contraction" => a.right_contraction(&b()).coefficients(),
                        "regressive" => a.regressive(&b()).coefficients(),
                        "scalar_product" => {
                            let mut r = [0.0; 32];
                            r[0] = a.scalar_product(&b());
                            r
                        }
                        "add" => (a + b()).coefficients(),
                        "sub" => (a - b()).coefficients(),
                        "scale" => a.scale(&scalar(b())).coefficients(),
                        "reverse" => a.reverse().coefficients(),
                        other => panic!("unknown operation {other}"),
                    };
                    let magnitude: f64 = 1.0 + result.iter().map(|x| x.abs()).sum::<f64>();
                    for (k, &blade) in f.output.blades.iter().enumerate() {
                        let got = out[at_out + k];
                        assert!(
                            (got - result[blade]).abs() <= tolerance * magnitude * 16.0,
                            "{} blade {}: device {got}, Rust {} ({})",
                            f.name,
                            cga::BLADE_NAMES[blade],
                            result[blade],
                            device.name()
                        );
                    }
                    at_out += f.output.blades.len();
                }
            }
        }
        eprintln!(
            "{}: {} generated functions agree with the Rust products",
            device.name(),
            wgsl::FUNCTIONS.len()
        );
    }
}
