//! The floating-point width of the device code and the shader it runs: the constants that
//! make the error bounds sound for that width, the range of inputs the device may see, and the
//! complete WGSL source. Kept apart from the device so the shader can be built and validated
//! without one.

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
    pub(super) fn bytes(self) -> usize {
        match self {
            Precision::F32 => 4,
            Precision::F64 => 8,
        }
    }

    /// Inputs the device may see: zero, or a magnitude in `[2^lo, 2^hi]`. The upper limit keeps
    /// every predicate (degree at most 6, the plane's wedge with a point) and its bound finite;
    /// the lower one keeps inputs and their differences normal numbers.
    pub(super) fn safe(self, x: f64) -> bool {
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
