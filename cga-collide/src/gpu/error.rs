//! The errors of the device side, apart from the batches' logic: every one names its cause and
//! what to do about it, since they reach users who may never have set up a GPU.

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
