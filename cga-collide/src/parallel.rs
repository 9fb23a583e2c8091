//! Data parallelism over the cores with rayon (feature `parallel`, on by default), or the same
//! iterator calls run sequentially on one core without it. Call sites are written once, in
//! rayon's vocabulary (`par_iter`, `into_par_iter`, `par_chunks`, `flat_map_iter`).

#[cfg(feature = "parallel")]
pub(crate) use rayon::prelude::*;

#[cfg(not(feature = "parallel"))]
pub(crate) use sequential::*;

#[cfg(not(feature = "parallel"))]
mod sequential {
    /// `into_par_iter()` as a plain `into_iter()`.
    pub(crate) trait IntoParallelIterator: IntoIterator + Sized {
        fn into_par_iter(self) -> Self::IntoIter {
            self.into_iter()
        }
    }
    impl<I: IntoIterator> IntoParallelIterator for I {}

    /// `par_iter()` and `par_chunks()` on slices as their sequential forms.
    pub(crate) trait ParallelSlice<T> {
        fn par_iter(&self) -> core::slice::Iter<'_, T>;
        fn par_chunks(&self, size: usize) -> core::slice::Chunks<'_, T>;
    }
    impl<T> ParallelSlice<T> for [T] {
        fn par_iter(&self) -> core::slice::Iter<'_, T> {
            self.iter()
        }
        fn par_chunks(&self, size: usize) -> core::slice::Chunks<'_, T> {
            self.chunks(size)
        }
    }

    /// rayon's `flat_map_iter` is `flat_map` on one core.
    pub(crate) trait FlatMapIter: Iterator + Sized {
        fn flat_map_iter<U: IntoIterator, F: FnMut(Self::Item) -> U>(
            self,
            f: F,
        ) -> core::iter::FlatMap<Self, U, F> {
            self.flat_map(f)
        }
    }
    impl<I: Iterator> FlatMapIter for I {}
}

/// How many threads the parallel calls would use here (1 without the `parallel` feature):
/// with one, a call site may skip the buffering that spreading work over threads needs.
pub(crate) fn threads() -> usize {
    #[cfg(feature = "parallel")]
    {
        rayon::current_num_threads()
    }
    #[cfg(not(feature = "parallel"))]
    {
        1
    }
}

/// Answers `query` for every item of a batch, spread over the cores; the first refused item
/// (in slice order) is reported as [`Error::InBatch`] with its index, whatever order the
/// threads finish in.
pub(crate) fn over_batch<I: Sync, T: Send>(
    items: &[I],
    query: impl Fn(&I) -> Result<T, crate::error::Error> + Sync,
) -> Result<Vec<T>, crate::error::Error> {
    // Collecting the parallel results straight into a `Result` would report whichever error a
    // thread met first; gathering them in slice order first keeps the first refused item.
    let answers: Vec<Result<T, crate::error::Error>> = items.par_iter().map(&query).collect();
    answers
        .into_iter()
        .enumerate()
        .map(|(index, answer)| {
            answer.map_err(|source| crate::error::Error::InBatch {
                index,
                source: Box::new(source),
            })
        })
        .collect()
}
