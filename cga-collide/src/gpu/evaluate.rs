//! The test hook behind `cga_collide::testing::gpu::evaluate` (feature `testing`): runs an
//! arbitrary compute shader on the device, so the generated algebra can be checked against the
//! CPU. Apart from the batches because it is not part of the library proper.

use std::borrow::Cow;

use super::device::WORKGROUP;
use super::{Device, Precision};
use crate::error::Error;

impl Device {
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
    ) -> Result<Vec<f64>, Error> {
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
