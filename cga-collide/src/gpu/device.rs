//! Opening a wgpu device with the batch pipeline, and the plumbing every batch shares: encoding
//! inputs in the device's precision, uploading them, and one dispatch with its read-back. The
//! batches themselves (`batches.rs`) only decide what to send and re-decide what comes
//! back flagged.

use std::borrow::Cow;
use std::sync::mpsc;

use wgpu::util::DeviceExt as _;

use super::{shader_source, Precision};
use crate::error::Error;

/// Tests per dispatch, at most: keeps each dispatch short (GPU watchdogs).
pub(super) const TESTS_PER_DISPATCH: u64 = 1 << 26;
/// Threads per workgroup (the shader's `@workgroup_size`).
pub(super) const WORKGROUP: u32 = 64;

/// A wgpu device with the batch pipeline.
pub struct Device {
    pub(super) device: wgpu::Device,
    pub(super) queue: wgpu::Queue,
    pub(super) name: String,
    pub(super) precision: Precision,
    pipeline: wgpu::ComputePipeline,
    layout: wgpu::BindGroupLayout,
    pub(super) max_binding: u64,
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
pub(super) struct Dispatched {
    pub(super) hits: Vec<(u32, u32)>,
    pub(super) flagged: Vec<(u32, u32)>,
}

impl Device {
    /// The first adapter wgpu finds (high-performance preference; `WGPU_BACKEND` and
    /// `WGPU_ADAPTER_NAME` select one), in `f64` when it has `SHADER_F64`, else `f32`.
    pub fn new() -> Result<Device, Error> {
        Self::with_precision(None)
    }

    /// As [`new`](Self::new) with a chosen precision (`None`: the best available).
    pub fn with_precision(precision: Option<Precision>) -> Result<Device, Error> {
        let instance =
            wgpu::Instance::new(wgpu::InstanceDescriptor::new_without_display_handle_from_env());
        let adapter = pollster::block_on(instance.request_adapter(&wgpu::RequestAdapterOptions {
            power_preference: wgpu::PowerPreference::HighPerformance,
            ..Default::default()
        }))
        .map_err(|_| Error::NoGpuAdapter)?;
        let info = adapter.get_info();
        let name = format!("{} ({:?}, {:?})", info.name, info.backend, info.device_type);
        let has_f64 = adapter.features().contains(wgpu::Features::SHADER_F64);
        let precision = match precision {
            Some(Precision::F64) if !has_f64 => return Err(Error::GpuNoF64 { device: name }),
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
        .map_err(|e| Error::GpuDevice {
            message: e.to_string(),
        })?;
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
    /// Numbers in the device's precision, little-endian.
    pub(super) fn encode<'a>(&self, values: impl Iterator<Item = &'a f64>) -> Vec<u8> {
        match self.precision {
            Precision::F32 => values.flat_map(|&x| (x as f32).to_le_bytes()).collect(),
            Precision::F64 => values.flat_map(|&x| x.to_le_bytes()).collect(),
        }
    }

    pub(super) fn upload(&self, label: &str, bytes: &[u8]) -> wgpu::Buffer {
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
    pub(super) fn dispatch(
        &self,
        kind: u32,
        mode: u32,
        (n_queries, n_items, first, last): (u32, u32, u32, u32),
        inputs: [&wgpu::Buffer; 3],
    ) -> Result<Dispatched, Error> {
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
    pub(super) fn read(&self, buffer: &wgpu::Buffer) -> Result<Vec<u32>, Error> {
        let (tx, rx) = mpsc::channel();
        buffer.map_async(wgpu::MapMode::Read, .., move |r| {
            let _ = tx.send(r);
        });
        self.device
            .poll(wgpu::PollType::wait_indefinitely())
            .map_err(|e| Error::GpuReadback {
                message: e.to_string(),
            })?;
        rx.recv()
            .map_err(|e| Error::GpuReadback {
                message: e.to_string(),
            })?
            .map_err(|e| Error::GpuReadback {
                message: e.to_string(),
            })?;
        let words = {
            let view = buffer
                .get_mapped_range(..)
                .map_err(|e| Error::GpuReadback {
                    message: e.to_string(),
                })?;
            view.chunks_exact(4)
                .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]))
                .collect()
        };
        buffer.unmap();
        Ok(words)
    }
}
