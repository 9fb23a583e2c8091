//! The shapes a batch tests against triangles, as the device sees them (a kind and 12 packed
//! numbers) and as the CPU re-decides them (the exact test), so the two views cannot drift.

use crate::{Ball, Intersects, Segment, Sphere, Triangle};

/// A query shape for [`Device::hits`](super::Device::hits).
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
    pub(super) fn kind(&self) -> u32 {
        match self {
            Query::Segment(_) => 0,
            Query::Triangle(_) => 1,
            Query::Sphere(_) => 2,
            Query::Ball(_) => 3,
        }
    }

    /// The 12 numbers the device reads.
    pub(super) fn packed(&self) -> [f64; 12] {
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
    pub(super) fn intersects(&self, t: &Triangle) -> bool {
        match self {
            Query::Segment(s) => s.intersects(t),
            Query::Triangle(u) => u.intersects(t),
            Query::Sphere(s) => s.intersects(t),
            Query::Ball(b) => b.intersects(t),
        }
    }
}
