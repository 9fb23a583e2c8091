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

mod batches;
mod device;
#[cfg(feature = "testing")]
mod evaluate;
mod precision;
mod query;

pub use batches::Batch;
pub use device::Device;
pub use precision::{shader_source, Precision};
pub use query::Query;
