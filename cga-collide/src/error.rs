//! Typed errors of the bounded-shape constructors.

use thiserror::Error;

/// Why a bounded shape could not be built.
///
/// Every variant names the constructor argument that was rejected and carries the offending
/// value, so the message says what was wrong and where.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum GeometryError {
    /// A coordinate of a point argument is NaN or infinite.
    #[error("{shape}::new: argument `{argument}` has a non-finite {axis} coordinate ({value}); coordinates must be finite numbers")]
    NonFiniteCoordinate {
        /// The shape being built (`"Segment"`, `"Triangle"`, `"Sphere"`, `"Ball"`).
        shape: &'static str,
        /// The argument name, e.g. `"a"` or `"centre"`.
        argument: &'static str,
        /// `"x"`, `"y"` or `"z"`.
        axis: &'static str,
        /// The rejected value.
        value: f64,
    },
    /// A radius is NaN or infinite.
    #[error("{shape}::new: radius is not finite ({value}); give a finite radius >= 0")]
    NonFiniteRadius {
        /// The shape being built.
        shape: &'static str,
        /// The rejected value.
        value: f64,
    },
    /// A radius is negative.
    #[error("{shape}::new: radius is negative ({value}); give a finite radius >= 0")]
    NegativeRadius {
        /// The shape being built.
        shape: &'static str,
        /// The rejected value.
        value: f64,
    },
    /// An input of a conformal constructor (a coordinate, a scalar or a blade coefficient) is
    /// NaN or infinite.
    #[error("{constructor}: argument `{argument}` has a non-finite value ({value}); give finite numbers")]
    NonFiniteInput {
        /// The constructor, e.g. `"conformal::Line::from_points"`.
        constructor: &'static str,
        /// The argument name, with the component when it has several (`"a.x"`, `"normal.z"`).
        argument: &'static str,
        /// The rejected value.
        value: f64,
    },
    /// The input of a conformal constructor does not define the requested object (coincident
    /// points for a line, collinear points for a plane, coplanar points for a sphere, a zero
    /// normal, a non-positive scale factor, ...). Decided exactly for the `f64` inputs.
    #[error("{constructor}: degenerate input: {reason}")]
    Degenerate {
        /// The constructor, e.g. `"conformal::Plane::from_points"`.
        constructor: &'static str,
        /// What is degenerate, e.g. `"points a, b, c are collinear"`.
        reason: &'static str,
    },
}
