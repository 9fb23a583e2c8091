//! A hook for checking device code against the CPU (feature `gpu`).

use crate::error::Error;
use crate::gpu::Device;

/// Runs `entry` of a compute shader `source` on `device`: the shader reads `input` at binding 0
/// (an `array<f64>` or `array<f32>` in the device's [`precision`](Device::precision)) and
/// writes `output_len` numbers to binding 1, with `threads` invocations in workgroups of 64;
/// returns the numbers as `f64`. For checking device code (the generated functions of
/// `ga_core::cga::wgsl`) against the CPU.
///
/// ```no_run
/// use cga_collide::gpu::{Device, Precision};
/// use cga_collide::testing::gpu::evaluate;
/// let device = Device::new()?;
/// let scalar = match device.precision() {
///     Precision::F32 => "f32",
///     Precision::F64 => "f64",
/// };
/// let source = format!(
///     "@group(0) @binding(0) var<storage, read> inp: array<{scalar}>;\n\
///      @group(0) @binding(1) var<storage, read_write> outp: array<{scalar}>;\n\
///      @compute @workgroup_size(64)\n\
///      fn main(@builtin(global_invocation_id) id: vec3<u32>) {{\n\
///          if id.x < 4u {{ outp[id.x] = 2.0 * inp[id.x]; }}\n\
///      }}\n"
/// );
/// let out = evaluate(&device, &source, "main", &[1.0, 2.0, 3.0, 4.0], 4, 4)?;
/// assert_eq!(out, [2.0, 4.0, 6.0, 8.0]);
/// # Ok::<(), cga_collide::Error>(())
/// ```
pub fn evaluate(
    device: &Device,
    source: &str,
    entry: &str,
    input: &[f64],
    output_len: usize,
    threads: u32,
) -> Result<Vec<f64>, Error> {
    device.evaluate(source, entry, input, output_len, threads)
}
