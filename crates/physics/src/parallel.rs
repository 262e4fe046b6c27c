//! Work split across threads without changing a bit of the result.
//!
//! Only work whose pieces are independent is split: each piece (a range of particles or
//! of candidate pairs) writes its own output, and the outputs are joined in the order of
//! the pieces, so the joined list is the one a single thread makes, element for element,
//! whatever the number of threads. Order-dependent work (impacts applied in time order,
//! the resting solver's Gauss–Seidel sweeps) stays on one thread.
//!
//! Threads come from a rayon pool owned by the simulation, native builds with the
//! `parallel` feature only; on wasm32, or with one thread, the pieces run in a loop.

use std::ops::Range;

use crate::profile::Clock;
use crate::tuning::MIN_ITEMS;
#[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
use crate::tuning::{MIN_ITEMS_IN_POOL, PIECES_PER_THREAD};

/// The machine's cores: how many threads to use when not told (1 where it cannot say,
/// as in a browser).
pub fn every_core() -> usize {
    std::thread::available_parallelism().map_or(1, std::num::NonZeroUsize::get)
}

/// The fewest items worth splitting where the caller runs, for work that splits from
/// `least` items: on a thread of the pool the other threads are awake, so smaller work
/// pays ([`crate::tuning::MIN_ITEMS_IN_POOL`]).
fn least_here(least: usize) -> usize {
    #[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
    if rayon::current_thread_index().is_some() {
        return least.min(MIN_ITEMS_IN_POOL);
    }
    least
}

/// The threads a simulation may use.
#[derive(Clone, Debug, Default)]
pub(crate) struct Workers {
    #[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
    pool: Option<std::sync::Arc<rayon::ThreadPool>>,
    /// With a clock: the wall time spent in work that may be split (whether it was split
    /// or not), shared by the copies that the forces and the contacts hold.
    timing: Option<std::sync::Arc<Timing>>,
}

/// The time spent in work that may be split, nanoseconds, read with a clock lent by the
/// caller.
#[derive(Debug)]
struct Timing {
    clock: Clock,
    nanoseconds: std::sync::atomic::AtomicU64,
}

std::thread_local! {
    /// How deep the calling thread is in timed regions: a region inside another is
    /// counted once.
    static DEPTH: std::cell::Cell<u32> = const { std::cell::Cell::new(0) };
}

impl Workers {
    /// Starts timing the work that may be split with `clock` (`None` stops), from zero.
    pub fn time_regions(&mut self, clock: Option<Clock>) {
        self.timing = clock.map(|clock| {
            std::sync::Arc::new(Timing {
                clock,
                nanoseconds: std::sync::atomic::AtomicU64::new(0),
            })
        });
    }

    /// The timing of `other`, shared, so that new workers go on counting.
    pub fn keep_timing(&mut self, other: &Self) {
        self.timing.clone_from(&other.timing);
    }

    /// Seconds spent in work that may be split since [`Self::time_regions`].
    pub fn region_seconds(&self) -> f64 {
        self.timing.as_ref().map_or(0.0, |t| {
            t.nanoseconds.load(std::sync::atomic::Ordering::Relaxed) as f64 * 1e-9
        })
    }

    /// `work()`, its wall time booked to the regions when it may be split and is timed.
    fn region<R>(&self, splittable: bool, work: impl FnOnce() -> R) -> R {
        let Some(timing) = self.timing.as_ref().filter(|_| splittable) else {
            return work();
        };
        let outermost = DEPTH.with(|d| {
            d.set(d.get() + 1);
            d.get() == 1
        });
        let start = (timing.clock)();
        let result = work();
        if outermost {
            #[expect(
                clippy::cast_possible_truncation,
                clippy::cast_sign_loss,
                reason = "a duration in nanoseconds, far below u64::MAX"
            )]
            let nanoseconds = (((timing.clock)() - start).max(0.0) * 1e9) as u64;
            timing
                .nanoseconds
                .fetch_add(nanoseconds, std::sync::atomic::Ordering::Relaxed);
        }
        DEPTH.with(|d| d.set(d.get() - 1));
        result
    }
}

impl Workers {
    /// `threads` threads (0 or 1: the calling thread only). Where threads are not
    /// available, always the calling thread only.
    pub fn new(threads: usize) -> Self {
        #[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
        {
            let pool = (threads > 1)
                .then(|| {
                    rayon::ThreadPoolBuilder::new()
                        .num_threads(threads)
                        .build()
                        .ok()
                })
                .flatten()
                .map(std::sync::Arc::new);
            Self { pool, timing: None }
        }
        #[cfg(not(all(feature = "parallel", not(target_arch = "wasm32"))))]
        {
            let _ = threads;
            Self { timing: None }
        }
    }

    /// How many threads work.
    #[cfg_attr(
        not(all(feature = "parallel", not(target_arch = "wasm32"))),
        expect(clippy::unused_self, reason = "the pool exists only where threads do")
    )]
    pub fn threads(&self) -> usize {
        #[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
        if let Some(pool) = &self.pool {
            return pool.current_num_threads();
        }
        1
    }

    /// Runs `work` over `0..n` in pieces and appends what the pieces push to `out`, in the
    /// order of the pieces: the same `out` for any number of threads.
    pub fn collect_into<T: Send>(
        &self,
        n: usize,
        out: &mut Vec<T>,
        work: impl Fn(Range<usize>, &mut Vec<T>) + Sync,
    ) {
        self.collect_into_from(MIN_ITEMS, n, out, work);
    }

    /// [`Self::collect_into`] for items that cost enough to be split from `least` of them
    /// (a Barnes–Hut tree's leaves, each a walk and the sums of its bodies).
    pub fn collect_into_from<T: Send>(
        &self,
        least: usize,
        n: usize,
        out: &mut Vec<T>,
        work: impl Fn(Range<usize>, &mut Vec<T>) + Sync,
    ) {
        let least = least_here(least);
        self.region(n >= least, || self.split_into(least, n, out, work));
    }

    /// `out` made `f(0)`, …, `f(n − 1)`: one element per item, each written in its place
    /// by whichever thread computes it (no pieces to allocate and join, which cost more
    /// than a cheap item's work), so the same list for any number of threads.
    pub fn map_into<T: Send>(
        &self,
        n: usize,
        out: &mut Vec<T>,
        f: impl Fn(usize) -> T + Sync + Send,
    ) {
        out.clear();
        let least = least_here(MIN_ITEMS);
        self.region(n >= least, || {
            #[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
            if let Some(pool) = self.pool.as_ref().filter(|_| n >= least) {
                use rayon::prelude::*;
                let pieces = pool.current_num_threads() * PIECES_PER_THREAD;
                pool.install(|| {
                    out.par_extend(
                        (0..n)
                            .into_par_iter()
                            .with_min_len(n.div_ceil(pieces))
                            .map(&f),
                    );
                });
                return;
            }
            out.extend((0..n).map(f));
        });
    }

    /// [`Self::collect_into_from`], untimed.
    #[cfg_attr(
        not(all(feature = "parallel", not(target_arch = "wasm32"))),
        expect(clippy::unused_self, reason = "the pool exists only where threads do")
    )]
    fn split_into<T: Send>(
        &self,
        least: usize,
        n: usize,
        out: &mut Vec<T>,
        work: impl Fn(Range<usize>, &mut Vec<T>) + Sync,
    ) {
        #[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
        if let Some(pool) = self.pool.as_ref().filter(|_| n >= least) {
            use rayon::prelude::*;
            let pieces = (pool.current_num_threads() * PIECES_PER_THREAD).min(n.max(1));
            let piece = |k: usize| k * n / pieces..(k + 1) * n / pieces;
            let outputs: Vec<Vec<T>> = pool.install(|| {
                (0..pieces)
                    .into_par_iter()
                    .map(|k| {
                        let mut output = Vec::new();
                        work(piece(k), &mut output);
                        output
                    })
                    .collect()
            });
            for output in outputs {
                out.extend(output);
            }
            return;
        }
        #[cfg(not(all(feature = "parallel", not(target_arch = "wasm32"))))]
        let _ = least;
        work(0..n, out);
    }
}

impl Workers {
    /// Runs `f` on one of the pool's threads (on the calling thread without a pool), so
    /// that the pieces of the work inside it start at once: a call into the pool from
    /// outside it waits for a sleeping thread to wake and for the caller to be woken
    /// again, twice for each piece of work, where a pool thread that splits work goes on
    /// with its own share and takes back a share no other thread has picked up yet. On
    /// the two shared cores of the development machine that wait was about 30 µs a call:
    /// `bench --scene cloud --particles 1000 --threads 2` summed 2.8e9 pairs a second with
    /// each force evaluation called from outside, 3.3e9 with each step run inside (one
    /// thread: 2.0e9).
    #[cfg_attr(
        not(all(feature = "parallel", not(target_arch = "wasm32"))),
        expect(clippy::unused_self, reason = "the pool exists only where threads do")
    )]
    pub fn inside<R: Send>(&self, f: impl FnOnce() -> R + Send) -> R {
        #[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
        if let Some(pool) = &self.pool {
            return pool.install(f);
        }
        f()
    }

    /// `work` on each of `items`, on the pool's threads where there are several: each
    /// item is its own, so the items come out the same for any number of threads.
    pub fn each_mut<T: Send>(&self, items: &mut [T], work: impl Fn(&mut T) + Sync) {
        self.region(items.len() > 1, || {
            #[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
            if let Some(pool) = self.pool.as_ref().filter(|_| items.len() > 1) {
                use rayon::prelude::*;
                pool.install(|| items.par_iter_mut().for_each(&work));
                return;
            }
            items.iter_mut().for_each(work);
        });
    }

    /// `work(0)`, …, `work(pieces − 1)`, on the pool's threads where there are several,
    /// returned in the order of the pieces: the same list for any number of threads.
    pub fn map<T: Send>(&self, pieces: usize, work: impl Fn(usize) -> T + Sync) -> Vec<T> {
        self.region(pieces > 1, || {
            #[cfg(all(feature = "parallel", not(target_arch = "wasm32")))]
            if let Some(pool) = self.pool.as_ref().filter(|_| pieces > 1) {
                use rayon::prelude::*;
                return pool.install(|| (0..pieces).into_par_iter().map(&work).collect());
            }
            (0..pieces).map(work).collect()
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Pieces of uneven cost, mapped on 1, 2 and 3 threads: the results in the order of
    /// the pieces, whichever thread ran each (50 times
    /// over, for the threads to take them in different orders).
    #[test]
    fn mapped_pieces_come_back_in_order_for_any_thread_count() {
        let work = |k: usize| {
            (0..(k % 3 + 1) * 20_000)
                .fold(k as u64, |a, i| a.wrapping_mul(31).wrapping_add(i as u64))
        };
        let expected: Vec<u64> = (0..8).map(work).collect();
        for threads in [1, 2, 3] {
            let workers = Workers::new(threads);
            for _ in 0..50 {
                assert_eq!(workers.map(8, work), expected, "{threads} threads");
            }
        }
    }

    /// Squares of 0..20,000 (enough to be split), gathered in pieces on 1, 2 and 3 threads: always the same list.
    #[test]
    fn pieces_join_in_order_for_any_thread_count() {
        let n = 20_000;
        assert!(n >= MIN_ITEMS, "too few to be split");
        let expected: Vec<u64> = (0..n as u64).map(|i| i * i).collect();
        for threads in [1, 2, 3] {
            let mut out = Vec::new();
            Workers::new(threads).collect_into(n, &mut out, |range, out| {
                out.extend(range.map(|i| (i as u64) * (i as u64)));
            });
            assert_eq!(out, expected, "{threads} threads");
        }
    }

    /// One element per item, mapped on 1, 2, 3 and 7 threads, from the pool's threads and
    /// from outside them, over a list that held something before: always each item's own
    /// element in its place, and nothing of the old list.
    #[test]
    fn mapped_items_land_in_their_places_for_any_thread_count() {
        let n = 20_000;
        assert!(n >= MIN_ITEMS, "too few to be split");
        let expected: Vec<u64> = (0..n as u64).map(|i| i * 3 + 1).collect();
        for threads in [1, 2, 3, 7] {
            let workers = Workers::new(threads);
            let mut out = vec![7; 5];
            workers.map_into(n, &mut out, |i| i as u64 * 3 + 1);
            assert_eq!(out, expected, "{threads} threads");
            let inside = workers.inside(|| {
                let mut out = Vec::new();
                workers.map_into(n, &mut out, |i| i as u64 * 3 + 1);
                out
            });
            assert_eq!(inside, expected, "{threads} threads, inside the pool");
        }
    }
}
