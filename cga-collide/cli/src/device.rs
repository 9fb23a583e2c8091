//! `--device cpu|gpu` of `cga collide` and `cga query`: where the exact tests run.
//!
//! The GPU path is cga-collide's `gpu` module (wgpu, feature `gpu` of this package, on by
//! default): the device tests every pair with a certified error bound and flags what it cannot
//! certify; the CPU re-decides the flagged pairs with the exact test, so the answers equal the
//! CPU's. A binary built without the feature still parses `--device gpu` and says how to get
//! it.

use anyhow::Result;
use cga_collide::collider::Collider;
use cga_collide::{Ball, Segment, Sphere, Triangle};
use clap::ValueEnum;

/// Where the exact tests run.
#[derive(Copy, Clone, Debug, Default, ValueEnum, PartialEq, Eq)]
pub enum DeviceArg {
    /// This machine's cores (every answer exact).
    #[default]
    Cpu,
    /// A GPU through wgpu (Vulkan, Metal, DX12): the device tests the pairs, the CPU re-decides
    /// the ones it flags, so the answers equal the CPU's.
    Gpu,
}

/// A shape of `cga query`.
#[derive(Copy, Clone, Debug)]
pub enum Primitive {
    /// `--segment`.
    Segment(Segment),
    /// `--triangle`.
    Triangle(Triangle),
    /// `--sphere`.
    Sphere(Sphere),
    /// `--ball`.
    Ball(Ball),
}

impl Primitive {
    /// The name used in the output (`"segment"`, ...).
    pub fn name(&self) -> &'static str {
        match self {
            Primitive::Segment(_) => "segment",
            Primitive::Triangle(_) => "triangle",
            Primitive::Sphere(_) => "sphere",
            Primitive::Ball(_) => "ball",
        }
    }

    /// The triangles of the collider's mesh it meets, sorted, on the CPU.
    pub fn cpu_hits(&self, collider: &Collider) -> Vec<u32> {
        match self {
            Primitive::Segment(s) => collider.segment_hits(s),
            Primitive::Triangle(t) => collider.triangle_hits(t),
            Primitive::Sphere(s) => collider.sphere_hits(s),
            Primitive::Ball(b) => collider.ball_hits(b),
        }
    }
}

/// The answers of one device batch.
#[derive(Clone, Debug)]
pub struct Answers<T> {
    /// The hits, sorted (as the CPU's).
    pub hits: Vec<T>,
    /// Pairs tested on the device.
    pub tested: u64,
    /// Pairs the device could not certify, re-decided exactly on the CPU.
    pub flagged: u64,
}

/// The options in `given` (given with `--device gpu`) are ones the GPU path does not support:
/// an error that names them and says what to do (`Ok` when `given` is empty).
pub fn reject_unsupported(given: &[&str]) -> Result<()> {
    if given.is_empty() {
        return Ok(());
    }
    anyhow::bail!(
        "{} cannot be combined with --device gpu: the GPU batches find intersecting triangles \
         only; run it with --device cpu (the default), or drop {}",
        given.join(", "),
        if given.len() == 1 { "it" } else { "them" }
    )
}

#[cfg(feature = "gpu")]
mod imp {
    use super::{Answers, Primitive};
    use anyhow::{Context, Result};
    use cga_collide::gpu::{Batch, Device, Precision, Query};
    use cga_collide::shape::mesh::TriMesh;
    use cga_collide::Error;

    /// An open GPU with the batch pipeline.
    pub struct Gpu(Device);

    fn answers<T>(b: Batch<T>) -> Answers<T> {
        Answers {
            hits: b.hits,
            tested: b.tested,
            flagged: b.flagged,
        }
    }

    impl Gpu {
        /// The first adapter wgpu finds (`WGPU_BACKEND`, `WGPU_ADAPTER_NAME` choose one).
        pub fn open() -> Result<Gpu> {
            match Device::new() {
                Ok(d) => Ok(Gpu(d)),
                Err(e @ Error::NoGpuAdapter) => Err(anyhow::anyhow!(
                    "--device gpu: {e}{}; or run with --device cpu (same answers)",
                    std::env::var("WGPU_BACKEND")
                        .map(|b| format!(
                            "; WGPU_BACKEND is `{b}`: unset it, or set it to `vulkan`"
                        ))
                        .unwrap_or_default()
                )),
                Err(e) => {
                    Err(e).context("--device gpu: cannot open the GPU (try --device cpu instead)")
                }
            }
        }

        /// The adapter's name and the precision its shader runs in.
        pub fn name(&self) -> String {
            let precision = match self.0.precision() {
                Precision::F32 => "f32",
                Precision::F64 => "f64",
            };
            format!("{}, {precision}", self.0.name())
        }

        /// The triangles of `mesh` that `shape` meets, every triangle tested on the device.
        pub fn hits(&self, shape: &Primitive, mesh: &TriMesh) -> Result<Answers<u32>> {
            let query: Query = match *shape {
                Primitive::Segment(s) => s.into(),
                Primitive::Triangle(t) => t.into(),
                Primitive::Sphere(s) => s.into(),
                Primitive::Ball(b) => b.into(),
            };
            Ok(answers(self.0.hits(&query, mesh).context("--device gpu")?))
        }

        /// Every intersecting pair of triangles of `a` and `b`, among all pairs
        /// (`candidates` = `None`) or among the candidates.
        pub fn pairs(
            &self,
            a: &TriMesh,
            b: &TriMesh,
            candidates: Option<&[(u32, u32)]>,
        ) -> Result<Answers<(u32, u32)>> {
            let batch = match candidates {
                None => self.0.intersecting_pairs(a, b),
                Some(c) => self.0.intersecting_candidates(a, b, c),
            };
            Ok(answers(batch.context("--device gpu")?))
        }
    }
}

#[cfg(not(feature = "gpu"))]
mod imp {
    use super::{Answers, Primitive};
    use anyhow::Result;
    use cga_collide::shape::mesh::TriMesh;

    /// No GPU support in this binary: there is no value of this type.
    pub enum Gpu {}

    impl Gpu {
        /// Always an error saying how to get a binary with GPU support.
        pub fn open() -> Result<Gpu> {
            anyhow::bail!(
                "--device gpu: this `cga` was built without GPU support (the `gpu` feature of the \
                 cga-cli package, on by default, was turned off). Rebuild with it, e.g. \
                 `cargo build --release -p cga-cli --features gpu`, or run with --device cpu \
                 (same answers)"
            )
        }

        pub fn name(&self) -> String {
            match *self {}
        }

        pub fn hits(&self, _: &Primitive, _: &TriMesh) -> Result<Answers<u32>> {
            match *self {}
        }

        pub fn pairs(
            &self,
            _: &TriMesh,
            _: &TriMesh,
            _: Option<&[(u32, u32)]>,
        ) -> Result<Answers<(u32, u32)>> {
            match *self {}
        }
    }
}

pub use imp::Gpu;

/// Opens the GPU when `device` asks for it.
pub fn open(device: DeviceArg) -> Result<Option<Gpu>> {
    match device {
        DeviceArg::Cpu => Ok(None),
        DeviceArg::Gpu => Gpu::open().map(Some),
    }
}

/// The device's name for the output: `"cpu"`, or the GPU adapter's name and precision.
pub fn name(gpu: Option<&Gpu>) -> String {
    gpu.map_or_else(|| "cpu".to_owned(), Gpu::name)
}
