//! The median split: the records halved at the median centroid along the axis.

use crate::bounding::build::records::{centroid_bounds, Record, Split};

/// Split at the median centroid along `axis` (also the fallback of the SAH splits).
pub(super) fn median_split(recs: &mut [Record], axis: usize) -> Split {
    let m = recs.len() / 2;
    recs.select_nth_unstable_by(m, |a, b| a.centroid()[axis].total_cmp(&b.centroid()[axis]));
    Split {
        mid: m,
        left: centroid_bounds(&recs[..m]),
        right: centroid_bounds(&recs[m..]),
    }
}
