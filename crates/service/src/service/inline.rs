//! Quick renders on the async worker: which renders skip the blocking pool.
//!
//! A fresh icon (the library's `gem` as glb) costs about 50 µs of CPU. Handing
//! it to tokio's blocking pool and back costs a futex wake of a pool thread,
//! two context switches and a wake of the waiting task: in a profile of fresh
//! `GET /v1/models/gem.glb` requests (issue 33, `docs/benchmarks.md`), the
//! scheduler's share was larger than the render's. So a render that is known
//! to be quick runs on the worker thread that received the request.
//!
//! "Known to be quick" is measured, not guessed: [`QuickRenders`] remembers
//! how long the last pool render of each (source, format) took, and a render
//! is tried on the worker only if that was under [`QUICK`]. The try itself
//! runs under a deadline of [`TRY_DEADLINE_MS`] (the render's own deadline,
//! cut short): another seed or other parameters of the same source may be
//! slow, and an async worker must not be held for long. A try that ends at
//! that deadline (an error, or under `truncate` a model cut at it) is thrown
//! away, and the render runs again on the pool under the request's own
//! limits. Nothing else about the render changes: the deadline is not part
//! of the model key or of any output (`pipeline::key::model_key` leaves the
//! limits out), so a finished try gives the same bytes as the pool would.
//!
//! Only requests whose own deadline is at least [`MIN_REQUEST_DEADLINE_MS`]
//! are tried, so that a thrown-away try (at most [`TRY_DEADLINE_MS`]) moves
//! the request's end by at most 1 % of its deadline; only sources of at
//! most [`MAX_SOURCE`] bytes, so that the memo's hash stays small beside a
//! render. Prints never are: they wait for a print slot and run for seconds.

use crate::core::{Limit, LimitExceeded};
use crate::export::Format;
use std::collections::HashMap;
use std::hash::BuildHasher as _;
use std::sync::Mutex;
use std::time::Duration;

/// A pool render at most this long makes the next render of its source and
/// format a candidate for the worker thread.
pub(crate) const QUICK: Duration = Duration::from_micros(300);

/// The deadline of a try on the worker thread, in milliseconds (the
/// budget's deadline has millisecond steps; 1 ms is about three times
/// [`QUICK`]).
pub(crate) const TRY_DEADLINE_MS: u64 = 1;

/// The shortest request deadline for which a try is made.
pub(crate) const MIN_REQUEST_DEADLINE_MS: u64 = 100;

/// The largest source for which a try is made (and whose render time is
/// remembered): the memo hashes the source on the async worker, and an
/// icon's grammar is a few kilobytes.
pub(crate) const MAX_SOURCE: usize = 64 << 10;

/// How many (source, format) pairs are remembered; the memo is emptied when
/// it is full (a sweep of distinct sources costs one pool render each).
const CAPACITY: usize = 4096;

/// The last pool render time of each (source, format) pair seen lately.
#[derive(Debug, Default)]
pub(crate) struct QuickRenders {
    last: Mutex<HashMap<u64, Duration>>,
    /// The memo key's hasher, seeded per process.
    hasher: foldhash::fast::RandomState,
}

impl QuickRenders {
    /// The memo's key: a hash of the source bytes and the format's name.
    /// Collisions only make a render try the worker first (and fall back).
    /// foldhash, not std's SipHash: this hashes the whole source on every
    /// model request, and SipHash was about 1.5 % of a fresh icon's
    /// instructions (issue 33). Its seed is the process's own, so a
    /// collision cannot be chosen in advance.
    pub(crate) fn key(&self, source: &[u8], format: Format) -> u64 {
        self.hasher.hash_one((source, format.name()))
    }

    /// Whether the last pool render of `key` was quick.
    pub(crate) fn is_quick(&self, key: u64) -> bool {
        self.last.lock().ok().and_then(|m| m.get(&key).copied()).is_some_and(|d| d <= QUICK)
    }

    /// Records how long a pool render of `key` took.
    pub(crate) fn record(&self, key: u64, took: Duration) {
        if let Ok(mut m) = self.last.lock() {
            if m.len() >= CAPACITY && !m.contains_key(&key) {
                m.clear();
            }
            m.insert(key, took);
        }
    }

    /// Forgets `key` (its try on the worker ran into the try's deadline).
    pub(crate) fn forget(&self, key: u64) {
        if let Ok(mut m) = self.last.lock() {
            m.remove(&key);
        }
    }
}

/// Whether a request with deadline `timeout_ms` (0: none), print flag and
/// source of `source_len` bytes may be tried on the worker at all. Only
/// such requests are looked up in, or recorded into, the memo.
pub(crate) fn may_try(timeout_ms: u64, print: bool, source_len: usize) -> bool {
    !print && timeout_ms >= MIN_REQUEST_DEADLINE_MS && source_len <= MAX_SOURCE
}

/// Whether a try's outcome ended at the try's deadline (and must be run
/// again on the pool): an error naming the deadline, or a model that
/// `truncate` cut there.
pub(crate) fn hit_try_deadline(error: Option<&LimitExceeded>, truncated: Option<&LimitExceeded>) -> bool {
    error.or(truncated).is_some_and(|l| l.limit == Limit::Deadline)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_a_quick_last_render_makes_a_candidate() {
        let q = QuickRenders::default();
        let gem = q.key(b"gem", Format::Glb);
        let png = q.key(b"gem", Format::Png);
        assert_ne!(gem, png, "the format is part of the key");
        assert_eq!(gem, q.key(b"gem", Format::Glb), "one process, one key");
        assert_ne!(gem, q.key(b"gen", Format::Glb), "the source is part of the key");
        assert!(!q.is_quick(gem), "an unseen source goes to the pool");
        q.record(gem, Duration::from_micros(80));
        q.record(png, Duration::from_micros(1500));
        assert!(q.is_quick(gem));
        assert!(!q.is_quick(png));
        q.forget(gem);
        assert!(!q.is_quick(gem));
    }

    #[test]
    fn the_memo_is_bounded() {
        let q = QuickRenders::default();
        for i in 0..(CAPACITY as u64 + 10) {
            q.record(i, Duration::from_micros(1));
        }
        let len = q.last.lock().map(|m| m.len()).unwrap_or(usize::MAX);
        assert_eq!(len, 10, "emptied once at capacity, then refilled by the last 10");
    }

    #[test]
    fn only_the_deadline_sends_a_try_back_to_the_pool() {
        let deadline = LimitExceeded::deadline_passed(1, 2);
        let depth = LimitExceeded::recorded(Limit::Depth);
        assert!(hit_try_deadline(Some(&deadline), None));
        assert!(hit_try_deadline(None, Some(&deadline)));
        assert!(!hit_try_deadline(Some(&depth), None));
        assert!(!hit_try_deadline(None, Some(&depth)));
        assert!(!hit_try_deadline(None, None));
        assert!(may_try(10_000, false, 1000));
        assert!(!may_try(10_000, true, 1000), "prints never");
        assert!(!may_try(50, false, 1000), "a short deadline is not shortened further");
        assert!(!may_try(0, false, 1000), "no deadline: nothing to cut a try short with");
        assert!(may_try(10_000, false, MAX_SOURCE));
        assert!(!may_try(10_000, false, MAX_SOURCE + 1), "a big source is not hashed on the worker");
    }
}
