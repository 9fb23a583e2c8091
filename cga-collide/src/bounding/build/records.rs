//! What the builds read: boxes rounded to `f32` (half the memory to move), one record per leaf
//! box, and the result of splitting a range of records.

use crate::bounding::aabb::Aabb;

#[inline(always)]
fn mn32(a: f32, b: f32) -> f32 {
    if b < a {
        b
    } else {
        a
    }
}

#[inline(always)]
fn mx32(a: f32, b: f32) -> f32 {
    if b > a {
        b
    } else {
        a
    }
}

/// A box in `f32` (what the build's heuristics read).
#[derive(Clone, Copy)]
pub(super) struct Box32 {
    pub(super) lo: [f32; 3],
    pub(super) hi: [f32; 3],
}

impl Box32 {
    pub(super) const EMPTY: Box32 = Box32 {
        lo: [f32::INFINITY; 3],
        hi: [f32::NEG_INFINITY; 3],
    };

    #[inline(always)]
    pub(super) fn union(&self, o: &Box32) -> Box32 {
        Box32 {
            lo: std::array::from_fn(|k| mn32(self.lo[k], o.lo[k])),
            hi: std::array::from_fn(|k| mx32(self.hi[k], o.hi[k])),
        }
    }

    #[inline(always)]
    pub(super) fn grow(&mut self, p: &[f32; 3]) {
        *self = self.union(&Box32 { lo: *p, hi: *p });
    }

    /// Half the surface area, in `f64` (no overflow); 0 for the empty box.
    pub(super) fn half_area(&self) -> f64 {
        let d: [f64; 3] = std::array::from_fn(|k| f64::from(self.hi[k]) - f64::from(self.lo[k]));
        if d.iter().any(|x| x.is_nan() || *x < 0.0) {
            return 0.0;
        }
        d[0] * d[1] + d[1] * d[2] + d[2] * d[0]
    }
}

/// A leaf of the build: its box rounded to `f32`, and its index.
#[derive(Clone, Copy)]
#[repr(C, align(32))]
pub(crate) struct Record {
    pub(super) b: Box32,
    pub(super) t: u32,
}

impl Record {
    pub(crate) fn new(b: &Aabb, t: u32) -> Record {
        Record {
            b: Box32 {
                lo: b.min.map(|x| x as f32),
                hi: b.max.map(|x| x as f32),
            },
            t,
        }
    }

    #[inline(always)]
    pub(super) fn centroid(&self) -> [f32; 3] {
        std::array::from_fn(|k| self.b.lo[k] * 0.5 + self.b.hi[k] * 0.5)
    }
}

/// A split of a range of records at `mid` (relative to the range), with the bounds of the
/// centroids of each side.
pub(super) struct Split {
    pub(super) mid: usize,
    pub(super) left: Box32,
    pub(super) right: Box32,
}

/// The box of the records' centroids.
pub(super) fn centroid_bounds(recs: &[Record]) -> Box32 {
    let mut cb = Box32::EMPTY;
    for r in recs {
        cb.grow(&r.centroid());
    }
    cb
}
