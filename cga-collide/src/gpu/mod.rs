//! The thesis's brute-force GPU batches (feature `gpu`, with wgpu): a segment, triangle,
//! sphere or ball against every triangle of a mesh, and a mesh against a mesh over every pair
//! of triangles or over the candidate pairs of the hierarchies, with the same exact answers as
//! the CPU.
//!
//! The compute shader ([`shader_source`]) is the generated WGSL of the conformal algebra
//! (`ga_core::cga::wgsl::RING`: points `2·up(x)`, dual spheres, the inner product, planes as
//! `up(a) ∧ up(b) ∧ up(c) ∧ n_inf` and their wedge with a point) evaluated on a scalar that
//! carries a running error bound, plus the decision logic of the exact tests in [`crate::query`]. Every sign
//! is certified on the device or reported as uncertain; a pair whose answer depends on an
//! uncertain sign is *flagged* and re-decided on the CPU by the exact test
//! ([`crate::Intersects`]). So every answer equals the CPU's exact answer; the
//! fraction flagged is reported ([`Batch::flagged`]).
//!
//! **Why the bound holds with or without fused multiply-adds.** Each operation charges
//! `2u·|result|` (twice the unit roundoff) plus an absolute `η` (flushed subnormals), and each
//! product also the propagated input errors. Whether `a·b + c` is rounded twice or once
//! (fused), its actual error is at most `u·|a·b|`-type terms of the same or smaller size than
//! the ones charged (an unrounded product has no error at all), and the factor two, together
//! with the margin on the final comparison, covers the rounding of the bound's own
//! computation. Inputs outside a safe range (which could overflow, or be subnormal and
//! flushed) are not sent to the device but decided on the CPU. The analysis assumes what
//! Vulkan, Metal and D3D require of shader arithmetic: `+ - ×` correctly rounded or fused, no
//! reassociation.
//!
//! On devices without 64-bit floats in shaders ([`Precision::F32`]) the same shader runs on
//! `f32` with `f32` bounds (inputs carry their conversion error): more pairs are flagged, the
//! answers stay exact.
//!
//! ```no_run
//! use cga_collide::gpu::Device;
//! use cga_collide::mesh::TriMesh;
//! use cga_collide::{nalgebra::Point3, Segment};
//! let device = Device::new()?;
//! let bunny = TriMesh::bunny();
//! let s = Segment::new(Point3::new(-1.0, 0.1, 0.0), Point3::new(1.0, 0.1, 0.05))?;
//! let batch = device.hits(&s.into(), &bunny)?;
//! println!("{} hits on {}, {} flagged", batch.hits.len(), batch.device, batch.flagged);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use std::borrow::Cow;
use std::sync::mpsc;

use wgpu::util::DeviceExt as _;

use crate::mesh::TriMesh;
use crate::{Ball, Intersects, Segment, Sphere, Triangle};

/// The device code besides the generated algebra.
const KERNELS: &str = include_str!("kernels.wgsl");

/// Floating-point width of the device code.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Precision {
    /// `f32` (every device).
    F32,
    /// `f64` (devices with `SHADER_F64`; fewer pairs flagged).
    F64,
}

impl Precision {
    fn bytes(self) -> usize {
        match self {
            Precision::F32 => 4,
            Precision::F64 => 8,
        }
    }

    /// Inputs the device may see: zero, or a magnitude in `[2^lo, 2^hi]`. The upper limit keeps
    /// every predicate (degree at most 6, the plane's wedge with a point) and its bound finite;
    /// the lower one keeps inputs and their differences normal numbers.
    fn safe(self, x: f64) -> bool {
        let (lo, hi) = match self {
            Precision::F32 => (f64::powi(2.0, -60), f64::powi(2.0, 16)),
            Precision::F64 => (f64::powi(2.0, -300), f64::powi(2.0, 150)),
        };
        let a = x.abs();
        a == 0.0 || (lo..=hi).contains(&a)
    }

    /// The constants the kernels need, as WGSL.
    fn prelude(self) -> &'static str {
        match self {
            // U = 2^-23, ETA = 2^-100, INPUT_ERR = 2^-23 (f64 -> f32 rounding, relative).
            Precision::F32 => {
                "alias F = f32;\n\
                 const U: F = 1.1920928955078125e-7;\n\
                 const ETA: F = 7.888609052210118e-31;\n\
                 const MARGIN: F = 1.0009765625;\n\
                 const INPUT_ERR: F = 1.1920928955078125e-7;\n"
            }
            // U = 2^-52, ETA = 2^-900, inputs exact.
            Precision::F64 => {
                "alias F = f64;\n\
                 const U: F = 2.220446049250313e-16;\n\
                 const ETA: F = 1.1834109918413096e-271;\n\
                 const MARGIN: F = 1.000000001;\n\
                 const INPUT_ERR: F = 0.0;\n"
            }
        }
    }
}

/// The complete compute shader for `precision`: constants, the certified scalar and the
/// decision logic (the crate's `kernels.wgsl`), and the generated conformal algebra over that scalar.
pub fn shader_source(precision: Precision) -> String {
    // naga has no `enable f64;`: the capability comes from the device feature.
    let prelude = precision.prelude();
    format!("{prelude}\n{KERNELS}\n{}", ga_core::cga::wgsl::RING)
}

/// What can go wrong on the device side.
#[derive(Debug, thiserror::Error)]
pub enum GpuError {
    /// No adapter (GPU or software driver) was found.
    #[error("no GPU adapter found: wgpu found no Vulkan, Metal, DX12 or GL device (only the backends in WGPU_BACKEND if it is set); install the GPU's driver, or on Linux without a GPU Mesa's software Vulkan driver lavapipe (Debian/Ubuntu package mesa-vulkan-drivers)")]
    NoAdapter,
    /// The adapter refused to create a device.
    #[error("the adapter refused to open a device: {0} (check its driver; WGPU_ADAPTER_NAME or WGPU_BACKEND choose another adapter)")]
    Device(String),
    /// `f64` was asked for but the device has no `SHADER_F64`.
    #[error("the device {0} has no 64-bit floats in shaders (SHADER_F64); ask for Precision::F32 or the best available (Device::new), which give the same exact answers with more pairs re-decided on the CPU")]
    NoF64(String),
    /// Reading results back failed.
    #[error("reading results back from the device failed: {0} (the device was lost or ran out of memory; retry, or split the meshes into smaller parts)")]
    Readback(String),
    /// A mesh does not fit in one storage buffer of the device.
    #[error("{what} needs {bytes} bytes, more than the device's storage buffer limit of {limit} bytes; split it into parts that fit, or use the CPU queries (cga_collide::query)")]
    TooLarge {
        /// Which input.
        what: &'static str,
        /// Its size.
        bytes: u64,
        /// The device's limit.
        limit: u64,
    },
}

/// A query shape for [`Device::hits`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Query {
    /// A closed segment.
    Segment(Segment),
    /// A closed triangle.
    Triangle(Triangle),
    /// A sphere (surface).
    Sphere(Sphere),
    /// A ball (solid).
    Ball(Ball),
}

impl From<Segment> for Query {
    fn from(s: Segment) -> Self {
        Query::Segment(s)
    }
}
impl From<Triangle> for Query {
    fn from(t: Triangle) -> Self {
        Query::Triangle(t)
    }
}
impl From<Sphere> for Query {
    fn from(s: Sphere) -> Self {
        Query::Sphere(s)
    }
}
impl From<Ball> for Query {
    fn from(b: Ball) -> Self {
        Query::Ball(b)
    }
}

impl Query {
    fn kind(&self) -> u32 {
        match self {
            Query::Segment(_) => 0,
            Query::Triangle(_) => 1,
            Query::Sphere(_) => 2,
            Query::Ball(_) => 3,
        }
    }

    /// The 12 numbers the device reads.
    fn packed(&self) -> [f64; 12] {
        let mut out = [0.0; 12];
        let mut put = |k: usize, p: &nalgebra::Point3<f64>| {
            out[3 * k..3 * k + 3].copy_from_slice(&[p.x, p.y, p.z]);
        };
        match self {
            Query::Segment(s) => {
                put(0, s.a());
                put(1, s.b());
            }
            Query::Triangle(t) => {
                for (k, v) in t.vertices().iter().enumerate() {
                    put(k, v);
                }
            }
            Query::Sphere(s) => {
                put(0, s.centre());
                out[3] = s.radius();
            }
            Query::Ball(b) => {
                put(0, b.centre());
                out[3] = b.radius();
            }
        }
        out
    }

    /// The exact CPU test against a triangle.
    fn intersects(&self, t: &Triangle) -> bool {
        match self {
            Query::Segment(s) => s.intersects(t),
            Query::Triangle(u) => u.intersects(t),
            Query::Sphere(s) => s.intersects(t),
            Query::Ball(b) => b.intersects(t),
        }
    }
}

/// The answers of one batch.
#[derive(Debug, Clone, PartialEq)]
pub struct Batch<T> {
    /// The hits, sorted: triangle indices for [`Device::hits`], `(i, j)` pairs (triangle `i`
    /// of the first mesh, `j` of the second) for the mesh batches.
    pub hits: Vec<T>,
    /// Pairs tested.
    pub tested: u64,
    /// Pairs the device could not certify (or was not given: inputs outside its safe range),
    /// re-decided on the CPU by the exact test.
    pub flagged: u64,
    /// The device's name ([`Device::name`]).
    pub device: String,
}

impl<T> Batch<T> {
    /// `flagged / tested` (0 for an empty batch).
    pub fn flagged_fraction(&self) -> f64 {
        if self.tested == 0 {
            0.0
        } else {
            self.flagged as f64 / self.tested as f64
        }
    }
}

/// Tests per dispatch, at most: keeps each dispatch short (GPU watchdogs).
const TESTS_PER_DISPATCH: u64 = 1 << 26;
/// Threads per workgroup (the shader's `@workgroup_size`).
const WORKGROUP: u32 = 64;

/// A wgpu device with the batch pipeline.
pub struct Device {
    device: wgpu::Device,
    queue: wgpu::Queue,
    name: String,
    precision: Precision,
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
    max_binding: u64,
}

impl std::fmt::Debug for Device {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("Device")
            .field("name", &self.name)
            .field("precision", &self.precision)
            .finish()
    }
}

/// Raw results of one dispatch.
struct Dispatched {
    hits: Vec<(u32, u32)>,
    flagged: Vec<(u32, u32)>,
}

impl Device {
    /// The first adapter wgpu finds (high-performance preference; `WGPU_BACKEND` and
    /// `WGPU_ADAPTER_NAME` select one), in `f64` when it has `SHADER_F64`, else `f32`.
    pub fn new() -> Result<Device, GpuError> {
        Self::with_precision(None)
    }

    /// As [`new`](Self::new) with a chosen precision (`None`: the best available).
    pub fn with_precision(precision: Option<Precision>) -> Result<Device, GpuError> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            ..Default::default()
        }))
        .map_err(|_| GpuError::NoAdapter)?;
        let info = adapter.get_info();
        let name = format!("{} ({:?}, {:?})", info.name, info.backend, info.device_type);
        let has_f64 = adapter.features().contains(wgpu::Features::SHADER_F64);
        let precision = match precision {
            Some(Precision::F64) if !has_f64 => return Err(GpuError::NoF64(name)),
            Some(p) => p,
            None if has_f64 => Precision::F64,
            None => Precision::F32,
        };
        let required_features = if precision == Precision::F64 {
            wgpu::Features::SHADER_F64
        } else {
            wgpu::Features::empty()
        };
        let (device, queue) = pollster::block_on(adapter.request_device(&wgpu::DeviceDescriptor {
            label: Some("cga-collide"),
            required_features,
            required_limits: adapter.limits(),
            ..Default::default()
        }))
        .map_err(|e| GpuError::Device(e.to_string()))?;
        let limits = device.limits();
        let max_binding = limits
            .max_storage_buffer_binding_size
            .min(limits.max_buffer_size);
        let module = device.create_shader_module(wgpu::ShaderModuleDescriptor {
            label: Some("cga-collide batches"),
            source: wgpu::ShaderSource::Wgsl(Cow::Owned(shader_source(precision))),
        });
        let storage = |binding: u32, read_only: bool| wgpu::BindGroupLayoutEntry {
            binding,
            visibility: wgpu::ShaderStages::COMPUTE,
            ty: wgpu::BindingType::Buffer {
                ty: wgpu::BufferBindingType::Storage { read_only },
                has_dynamic_offset: false,
                min_binding_size: None,
            },
            count: None,
        };
        let layout = device.create_bind_group_layout(&wgpu::BindGroupLayoutDescriptor {
            label: Some("batch"),
            entries: &[
                wgpu::BindGroupLayoutEntry {
                    binding: 0,
                    visibility: wgpu::ShaderStages::COMPUTE,
                    ty: wgpu::BindingType::Buffer {
                        ty: wgpu::BufferBindingType::Uniform,
                        has_dynamic_offset: false,
                        min_binding_size: None,
                    },
                    count: None,
                },
                storage(1, true),
                storage(2, true),
                storage(3, true),
                storage(4, false),
                storage(5, false),
                storage(6, false),
            ],
        });
        let pipeline_layout = device.create_pipeline_layout(&wgpu::PipelineLayoutDescriptor {
            label: Some("batch"),
            bind_group_layouts: &[Some(&layout)],
            immediate_size: 0,
        });
        let pipeline = device.create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
            label: Some("batch"),
            layout: Some(&pipeline_layout),
            module: &module,
            entry_point: Some("main"),
            compilation_options: Default::default(),
            cache: None,
        });
        Ok(Device {
            device,
            queue,
            name,
            precision,
            pipeline,
            layout,
            max_binding,
        })
    }

    /// The adapter's name, backend and type, e.g. `llvmpipe (LLVM 15.0.6, 256 bits) (Vulkan,
    /// Cpu)`.
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The precision the device code runs in.
    pub fn precision(&self) -> Precision {
        self.precision
    }

    /// The triangles of `mesh` that meet `query`, sorted: brute force, every triangle tested
    /// on the device, the flagged ones re-decided exactly on the CPU.
    pub fn hits(&self, query: &Query, mesh: &TriMesh) -> Result<Batch<u32>, GpuError> {
        let queries = [query.packed()];
        let batch = self.run(query.kind(), &queries, mesh, None, |_, j| {
            query.intersects(&triangle(mesh, j))
        })?;
        Ok(Batch {
            hits: batch.hits.into_iter().map(|(_, j)| j).collect(),
            tested: batch.tested,
            flagged: batch.flagged,
            device: batch.device,
        })
    }

    /// The indices `k` of the pairs `pairs[k]` that intersect, sorted: arbitrary
    /// shape–triangle pairs in one batch per kind of shape.
    pub fn pair_hits(&self, pairs: &[(Query, Triangle)]) -> Result<Batch<usize>, GpuError> {
        let mut out = Batch {
            hits: Vec::new(),
            tested: 0,
            flagged: 0,
            device: self.name.clone(),
        };
        for kind in 0..4 {
            let index: Vec<usize> = (0..pairs.len())
                .filter(|&k| pairs[k].0.kind() == kind)
                .collect();
            if index.is_empty() {
                continue;
            }
            let queries: Vec<[f64; 12]> = index.iter().map(|&k| pairs[k].0.packed()).collect();
            let vertices = index.iter().flat_map(|&k| *pairs[k].1.vertices()).collect();
            let faces = (0..index.len() as u32)
                .map(|k| [3 * k, 3 * k + 1, 3 * k + 2])
                .collect();
            // Triangle vertices are finite, so the mesh is valid.
            let mesh = TriMesh::new(vertices, faces)
                .unwrap_or_else(|_| unreachable!("triangles have finite vertices"));
            let diagonal: Vec<(u32, u32)> = (0..index.len() as u32).map(|k| (k, k)).collect();
            let batch = self.run(kind, &queries, &mesh, Some(&diagonal), |i, _| {
                let (q, t) = &pairs[index[i as usize]];
                q.intersects(t)
            })?;
            out.hits
                .extend(batch.hits.iter().map(|&(i, _)| index[i as usize]));
            out.tested += batch.tested;
            out.flagged += batch.flagged;
        }
        out.hits.sort_unstable();
        Ok(out)
    }

    /// Every pair `(i, j)` of a triangle `i` of `a` and `j` of `b` that intersect, sorted: brute
    /// force over all `|a|·|b|` pairs, as the thesis's GPU batch.
    pub fn intersecting_pairs(
        &self,
        a: &TriMesh,
        b: &TriMesh,
    ) -> Result<Batch<(u32, u32)>, GpuError> {
        // The smaller mesh is the loop inside each thread; the larger one is spread over threads.
        let (small, large, swapped) = if a.num_triangles() <= b.num_triangles() {
            (a, b, false)
        } else {
            (b, a, true)
        };
        let queries: Vec<[f64; 12]> = (0..small.num_triangles())
            .map(|i| Query::Triangle(triangle(small, i as u32)).packed())
            .collect();
        let mut batch = self.run(1, &queries, large, None, |i, j| {
            triangle(small, i).intersects(&triangle(large, j))
        })?;
        if swapped {
            for p in &mut batch.hits {
                *p = (p.1, p.0);
            }
            batch.hits.sort_unstable();
        }
        Ok(batch)
    }

    /// The pairs among `candidates` (triangle `i` of `a`, `j` of `b`; e.g. the box-overlap
    /// pairs of the hierarchies, [`Collider::box_pairs_bvh`](crate::collider::Collider::box_pairs_bvh))
    /// that intersect, sorted.
    pub fn intersecting_candidates(
        &self,
        a: &TriMesh,
        b: &TriMesh,
        candidates: &[(u32, u32)],
    ) -> Result<Batch<(u32, u32)>, GpuError> {
        let queries: Vec<[f64; 12]> = (0..a.num_triangles())
            .map(|i| Query::Triangle(triangle(a, i as u32)).packed())
            .collect();
        self.run(1, &queries, b, Some(candidates), |i, j| {
            triangle(a, i).intersects(&triangle(b, j))
        })
    }

    /// Runs a batch: queries (12 numbers each) against the triangles of `mesh`, all pairs or
    /// the listed ones; `exact(i, j)` re-decides a pair on the CPU.
    fn run(
        &self,
        kind: u32,
        queries: &[[f64; 12]],
        mesh: &TriMesh,
        pairs: Option<&[(u32, u32)]>,
        exact: impl Fn(u32, u32) -> bool + Sync,
    ) -> Result<Batch<(u32, u32)>, GpuError> {
        let p = self.precision;
        let n_tri = mesh.num_triangles();
        let query_safe: Vec<bool> = queries
            .iter()
            .map(|q| q.iter().all(|&x| p.safe(x)))
            .collect();
        let tri_data: Vec<[f64; 9]> = (0..n_tri)
            .map(|j| {
                let [a, b, c] = mesh.corners(j as u32);
                [a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z]
            })
            .collect();
        let tri_safe: Vec<bool> = tri_data
            .iter()
            .map(|t| t.iter().all(|&x| p.safe(x)))
            .collect();
        let query_bytes = (queries.len() * 12 * p.bytes()) as u64;
        if query_bytes > self.max_binding {
            return Err(GpuError::TooLarge {
                what: "the query data",
                bytes: query_bytes,
                limit: self.max_binding,
            });
        }
        let query_buf = self.upload("queries", &self.encode(queries.iter().flatten()));
        let mut device_hits = Vec::new();
        let mut device_flagged = Vec::new();
        let tested;
        match pairs {
            None => {
                tested = queries.len() as u64 * n_tri as u64;
                let per_chunk = (self.max_binding / (9 * p.bytes() as u64)).max(1) as usize;
                for start in (0..n_tri).step_by(per_chunk) {
                    let end = (start + per_chunk).min(n_tri);
                    let tri_buf = self.upload(
                        "triangles",
                        &self.encode(tri_data[start..end].iter().flatten()),
                    );
                    let pair_buf = self.upload("pairs", &[0u8; 8]);
                    let n = (end - start) as u64;
                    let step = (TESTS_PER_DISPATCH / n).clamp(1, queries.len() as u64) as usize;
                    for q0 in (0..queries.len()).step_by(step) {
                        let q1 = (q0 + step).min(queries.len());
                        let out = self.dispatch(
                            kind,
                            0,
                            (queries.len() as u32, n as u32, q0 as u32, q1 as u32),
                            [&query_buf, &tri_buf, &pair_buf],
                        )?;
                        let shift = |v: Vec<(u32, u32)>| {
                            v.into_iter().map(move |(i, j)| (i, j + start as u32))
                        };
                        device_hits.extend(shift(out.hits));
                        device_flagged.extend(shift(out.flagged));
                    }
                }
            }
            Some(pairs) => {
                tested = pairs.len() as u64;
                let tri_bytes = (n_tri * 9 * p.bytes()) as u64;
                if tri_bytes > self.max_binding {
                    return Err(GpuError::TooLarge {
                        what: "the mesh",
                        bytes: tri_bytes,
                        limit: self.max_binding,
                    });
                }
                let tri_buf = self.upload("triangles", &self.encode(tri_data.iter().flatten()));
                let per_chunk = (self.max_binding / 8).min(TESTS_PER_DISPATCH) as usize;
                for chunk in pairs.chunks(per_chunk.max(1)) {
                    let raw: Vec<u8> = chunk
                        .iter()
                        .flat_map(|&(i, j)| [i, j])
                        .flat_map(u32::to_le_bytes)
                        .collect();
                    let pair_buf = self.upload("pairs", &raw);
                    let out = self.dispatch(
                        kind,
                        1,
                        (queries.len() as u32, chunk.len() as u32, 0, 0),
                        [&query_buf, &tri_buf, &pair_buf],
                    )?;
                    device_hits.extend(out.hits);
                    device_flagged.extend(out.flagged);
                }
            }
        }
        // Pairs with an input outside the device's safe range: the device's answer is ignored.
        let unsafe_pair = |&(i, j): &(u32, u32)| !query_safe[i as usize] || !tri_safe[j as usize];
        device_hits.retain(|pair| !unsafe_pair(pair));
        device_flagged.retain(|pair| !unsafe_pair(pair));
        let mut undecided = device_flagged;
        match pairs {
            None => {
                for (i, _) in query_safe.iter().enumerate().filter(|(_, s)| !**s) {
                    undecided.extend((0..n_tri as u32).map(|j| (i as u32, j)));
                }
                for (j, _) in tri_safe.iter().enumerate().filter(|(_, s)| !**s) {
                    undecided.extend(
                        (0..queries.len() as u32)
                            .filter(|&i| query_safe[i as usize])
                            .map(|i| (i, j as u32)),
                    );
                }
            }
            Some(pairs) => undecided.extend(pairs.iter().filter(|p| unsafe_pair(p))),
        }
        let flagged = undecided.len() as u64;
        let decided: Vec<(u32, u32)> = undecided
            .into_iter()
            .filter(|&(i, j)| exact(i, j))
            .collect();
        let mut hits = device_hits;
        hits.extend(decided);
        hits.sort_unstable();
        Ok(Batch {
            hits,
            tested,
            flagged,
            device: self.name.clone(),
        })
    }

    /// Numbers in the device's precision, little-endian.
    fn encode<'a>(&self, values: impl Iterator<Item = &'a f64>) -> Vec<u8> {
        match self.precision {
            Precision::F32 => values.flat_map(|&x| (x as f32).to_le_bytes()).collect(),
            Precision::F64 => values.flat_map(|&x| x.to_le_bytes()).collect(),
        }
    }

    fn upload(&self, label: &str, bytes: &[u8]) -> wgpu::Buffer {
        // Bindings may not be empty.
        let padded;
        let contents = if bytes.is_empty() {
            padded = [0u8; 8];
            &padded[..]
        } else {
            bytes
        };
        self.device
            .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                label: Some(label),
                contents,
                usage: wgpu::BufferUsages::STORAGE,
            })
    }

    /// One dispatch over `n_items` threads, growing the output buffers and repeating it if
    /// more answers came back than they hold.
    fn dispatch(
        &self,
        kind: u32,
        mode: u32,
        (n_queries, n_items, first, last): (u32, u32, u32, u32),
        inputs: [&wgpu::Buffer; 3],
    ) -> Result<Dispatched, GpuError> {
        // Room for every answer of a small dispatch; grown on demand for large ones.
        let tests = if mode == 1 {
            n_items as u64
        } else {
            n_items as u64 * (last - first) as u64
        };
        let mut capacity = tests.clamp(16, 1 << 16) as u32;
        loop {
            let groups = n_items.div_ceil(WORKGROUP).max(1);
            let max_dim = self.device.limits().max_compute_workgroups_per_dimension;
            let (gx, gy) = if groups <= max_dim {
                (groups, 1)
            } else {
                (max_dim, groups.div_ceil(max_dim))
            };
            let params: Vec<u8> = [
                kind,
                mode,
                n_queries,
                n_items,
                capacity,
                gx * WORKGROUP,
                first,
                last,
            ]
            .iter()
            .flat_map(|v| v.to_le_bytes())
            .collect();
            let uniform = self
                .device
                .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some("params"),
                    contents: &params,
                    usage: wgpu::BufferUsages::UNIFORM,
                });
            let out_bytes = 8 * capacity as u64;
            let storage_out = |label| {
                self.device.create_buffer(&wgpu::BufferDescriptor {
                    label: Some(label),
                    size: out_bytes,
                    usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
                    mapped_at_creation: false,
                })
            };
            let counts = self
                .device
                .create_buffer_init(&wgpu::util::BufferInitDescriptor {
                    label: Some("counts"),
                    contents: &[0u8; 8],
                    usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
                });
            let hits = storage_out("hits");
            let flagged = storage_out("flagged");
            let readback = self.device.create_buffer(&wgpu::BufferDescriptor {
                label: Some("readback"),
                size: 8 + 2 * out_bytes,
                usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
                mapped_at_creation: false,
            });
            let bind = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
                label: Some("batch"),
                layout: &self.layout,
                entries: &[
                    (0, &uniform),
                    (1, inputs[0]),
                    (2, inputs[1]),
                    (3, inputs[2]),
                    (4, &counts),
                    (5, &hits),
                    (6, &flagged),
                ]
                .map(|(binding, buffer)| wgpu::BindGroupEntry {
                    binding,
                    resource: buffer.as_entire_binding(),
                }),
            });
            let mut encoder = self
                .device
                .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
            {
                let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                    label: Some("batch"),
                    timestamp_writes: None,
                });
                pass.set_pipeline(&self.pipeline);
                pass.set_bind_group(0, &bind, &[]);
                pass.dispatch_workgroups(gx, gy, 1);
            }
            encoder.copy_buffer_to_buffer(&counts, 0, &readback, 0, 8);
            encoder.copy_buffer_to_buffer(&hits, 0, &readback, 8, out_bytes);
            encoder.copy_buffer_to_buffer(&flagged, 0, &readback, 8 + out_bytes, out_bytes);
            self.queue.submit([encoder.finish()]);
            let words = self.read(&readback)?;
            let (n_hits, n_flagged) = (words[0], words[1]);
            if n_hits > capacity || n_flagged > capacity {
                capacity = n_hits.max(n_flagged);
                continue;
            }
            let cap = capacity as usize;
            let pairs = |offset: usize, n: u32| {
                (0..n as usize)
                    .map(|k| (words[offset + 2 * k], words[offset + 2 * k + 1]))
                    .collect()
            };
            return Ok(Dispatched {
                hits: pairs(2, n_hits),
                flagged: pairs(2 + 2 * cap, n_flagged),
            });
        }
    }

    /// Maps `buffer` and returns its words.
    fn read(&self, buffer: &wgpu::Buffer) -> Result<Vec<u32>, GpuError> {
        let (tx, rx) = mpsc::channel();
        buffer.map_async(wgpu::MapMode::Read, .., move |r| {
            let _ = tx.send(r);
        });
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| GpuError::Readback(e.to_string()))?;
        rx.recv()
            .map_err(|e| GpuError::Readback(e.to_string()))?
            .map_err(|e| GpuError::Readback(e.to_string()))?;
        let words = {
            let view = buffer
                .get_mapped_range(..)
                .map_err(|e| GpuError::Readback(e.to_string()))?;
            view.chunks_exact(4)
                .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
                .collect()
        };
        buffer.unmap();
        Ok(words)
    }

    /// Runs `entry` of a compute shader `source` that reads `input` at binding 0 and writes
    /// `output_len` numbers to binding 1 (the test hook
    /// `cga_collide::testing::gpu::evaluate`).
    #[cfg(feature = "testing")]
    pub(crate) fn evaluate(
        &self,
        source: &str,
        entry: &str,
        input: &[f64],
        output_len: usize,
        threads: u32,
    ) -> Result<Vec<f64>, GpuError> {
        let module = self
            .device
            .create_shader_module(wgpu::ShaderModuleDescriptor {
                label: Some("evaluate"),
                source: wgpu::ShaderSource::Wgsl(Cow::Borrowed(source)),
            });
        let pipeline = self
            .device
            .create_compute_pipeline(&wgpu::ComputePipelineDescriptor {
                label: Some("evaluate"),
                layout: None,
                module: &module,
                entry_point: Some(entry),
                compilation_options: Default::default(),
                cache: None,
            });
        let bytes = self.precision.bytes();
        let input_buf = self.upload("input", &self.encode(input.iter()));
        let size = (output_len.max(1) * bytes) as u64;
        let output = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("output"),
            size,
            usage: wgpu::BufferUsages::STORAGE | wgpu::BufferUsages::COPY_SRC,
            mapped_at_creation: false,
        });
        let readback = self.device.create_buffer(&wgpu::BufferDescriptor {
            label: Some("readback"),
            size,
            usage: wgpu::BufferUsages::MAP_READ | wgpu::BufferUsages::COPY_DST,
            mapped_at_creation: false,
        });
        let bind = self.device.create_bind_group(&wgpu::BindGroupDescriptor {
            label: Some("evaluate"),
            layout: &pipeline.get_bind_group_layout(0),
            entries: &[
                wgpu::BindGroupEntry {
                    binding: 0,
                    resource: input_buf.as_entire_binding(),
                },
                wgpu::BindGroupEntry {
                    binding: 1,
                    resource: output.as_entire_binding(),
                },
            ],
        });
        let mut encoder = self
            .device
            .create_command_encoder(&wgpu::CommandEncoderDescriptor { label: None });
        {
            let mut pass = encoder.begin_compute_pass(&wgpu::ComputePassDescriptor {
                label: Some("evaluate"),
                timestamp_writes: None,
            });
            pass.set_pipeline(&pipeline);
            pass.set_bind_group(0, &bind, &[]);
            pass.dispatch_workgroups(threads.div_ceil(WORKGROUP).max(1), 1, 1);
        }
        encoder.copy_buffer_to_buffer(&output, 0, &readback, 0, size);
        self.queue.submit([encoder.finish()]);
        let words = self.read(&readback)?;
        let mut values: Vec<f64> = match self.precision {
            Precision::F32 => words.iter().map(|&w| f32::from_bits(w) as f64).collect(),
            Precision::F64 => words
                .chunks_exact(2)
                .map(|w| f64::from_bits(w[0] as u64 | (w[1] as u64) << 32))
                .collect(),
        };
        values.truncate(output_len);
        Ok(values)
    }
}

/// Triangle `j` of a mesh as an exact-test shape.
fn triangle(mesh: &TriMesh, j: u32) -> Triangle {
    let [a, b, c] = mesh.corners(j);
    // TriMesh vertices are finite, so this cannot fail.
    Triangle::new(a, b, c).unwrap_or_else(|_| unreachable!("TriMesh vertices are finite"))
}
