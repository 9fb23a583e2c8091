//! How many signs each exact stage decided: the counters behind the benchmarks' "who decided"
//! columns, so the next bottleneck is visible.
//!
//! Only the stages after the first `f64` filter count (they cost tens of nanoseconds or more,
//! so a relaxed atomic increment is noise there); the first filter is the hot path and is left
//! uncounted. The counters are process-wide and never reset by the crate itself; they are
//! read through `testing::stage_counts` (feature `testing`).

use core::sync::atomic::{AtomicU64, Ordering::Relaxed};

static RESCALED: AtomicU64 = AtomicU64::new(0);
static EXPANSION: AtomicU64 = AtomicU64::new(0);
static BIG_INTEGER: AtomicU64 = AtomicU64::new(0);

/// The number of signs decided by each stage after the first `f64` filter, since the process
/// started or the last [`reset_stage_counts`].
#[cfg(feature = "testing")]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub struct StageCounts {
    /// Decided by the `f64` filter again, after scaling the inputs to unit size.
    pub rescaled_filter: u64,
    /// Decided exactly by floating-point expansions ([`Expansion`](super::Expansion)).
    pub expansion: u64,
    /// Decided exactly by big integers (the expansions could not hold the value).
    pub big_integer: u64,
}

/// The counters now.
#[cfg(feature = "testing")]
pub fn stage_counts() -> StageCounts {
    StageCounts {
        rescaled_filter: RESCALED.load(Relaxed),
        expansion: EXPANSION.load(Relaxed),
        big_integer: BIG_INTEGER.load(Relaxed),
    }
}

/// Sets every counter to zero (e.g. between the meshes of a benchmark).
#[cfg(feature = "testing")]
pub fn reset_stage_counts() {
    RESCALED.store(0, Relaxed);
    EXPANSION.store(0, Relaxed);
    BIG_INTEGER.store(0, Relaxed);
}

#[inline]
pub(crate) fn count_rescaled() {
    RESCALED.fetch_add(1, Relaxed);
}

#[inline]
pub(crate) fn count_expansion() {
    EXPANSION.fetch_add(1, Relaxed);
}

#[inline]
pub(crate) fn count_big_integer() {
    BIG_INTEGER.fetch_add(1, Relaxed);
}
