//! Filling one vector's slots from several threads, each writing its own
//! stretch in place, with no `unsafe` at the call site.
//!
//! Why: a big drawing's marks (a CFDG design's 262,143 squares) and the
//! preview's plan of them (one job per mark) are each a long array whose
//! every element depends only on its input. Building them on every core
//! and concatenating the pieces would copy tens of megabytes; writing each
//! element where it belongs does not. The one `unsafe` step, setting the
//! length once every slot is written, lives here, guarded by counting what
//! each stretch really wrote, so a caller cannot get it wrong. Rayon's
//! `collect_into_vec` does the same, but rulemesh has no thread pool to
//! share and starts its few scoped threads per call (`std::thread::scope`).

use std::mem::MaybeUninit;
use std::ops::Range;

/// Why [`fill_in_place`] left the vector empty.
#[derive(Debug, Clone, Copy, PartialEq, Eq, thiserror::Error)]
pub enum Unfilled {
    /// A stretch's thread panicked (a bug in the filling closure).
    #[error("a filling thread panicked")]
    Panicked,
    /// A stretch's closure pushed fewer or more elements than its range.
    #[error("a stretch was pushed {pushed} elements for {len} slots")]
    Miscounted {
        /// Elements pushed.
        pushed: usize,
        /// Slots in the stretch.
        len: usize,
    },
    /// The vector given was not empty.
    #[error("the vector to fill was not empty")]
    NotEmpty,
}

/// One stretch of slots, written front to back by [`Slots::push`].
/// Dropped before it is complete (the closure panicked or returned
/// early), it drops the elements it holds.
pub struct Slots<'a, T> {
    slots: &'a mut [MaybeUninit<T>],
    /// Slots written: `slots[..filled]` are initialised.
    filled: usize,
    /// Calls to `push`, including those past the end (a miscount).
    pushed: usize,
    /// Set once the stretch is complete: its elements now belong to the vector.
    kept: bool,
}

impl<T> Slots<'_, T> {
    /// Writes the next slot. A push past the stretch's end drops `value`
    /// and makes the fill fail with [`Unfilled::Miscounted`].
    pub fn push(&mut self, value: T) {
        self.pushed += 1;
        if let Some(slot) = self.slots.get_mut(self.filled) {
            slot.write(value);
            self.filled += 1;
        }
    }
}

impl<T> Drop for Slots<'_, T> {
    fn drop(&mut self) {
        if self.kept {
            return;
        }
        for slot in &mut self.slots[..self.filled] {
            // SAFETY: `push` wrote `slots[..filled]`, and an incomplete
            // stretch never becomes part of the vector, so each is dropped
            // here once and never read again.
            unsafe { slot.assume_init_drop() };
        }
    }
}

/// Runs `fill` on one stretch and keeps its elements only when it pushed
/// exactly one per slot.
fn fill_stretch<T, R>(first: usize, slots: &mut [MaybeUninit<T>], fill: &(impl Fn(Range<usize>, &mut Slots<'_, T>) -> R + Sync)) -> Result<R, Unfilled> {
    let len = slots.len();
    let mut stretch = Slots { slots, filled: 0, pushed: 0, kept: false };
    let r = fill(first..first + len, &mut stretch);
    if stretch.pushed != len {
        return Err(Unfilled::Miscounted { pushed: stretch.pushed, len });
    }
    stretch.kept = true;
    Ok(r)
}

/// Fills the empty vector `v` with `n` elements on up to `threads` threads:
/// the indices are cut into as many equal stretches, and `fill(range,
/// slots)` pushes the elements of `range`, in order, into that stretch's
/// slots. Returns each stretch's result in order. With one thread (or one
/// stretch) nothing is spawned and a panic in `fill` unwinds to the caller
/// as usual.
///
/// On an error `v` is left empty: the elements of incomplete stretches are
/// dropped, those of complete ones leaked (never dropped, which is safe).
pub fn fill_in_place<T: Send, R: Send>(v: &mut Vec<T>, n: usize, threads: usize, fill: impl Fn(Range<usize>, &mut Slots<'_, T>) -> R + Sync) -> Result<Vec<R>, Unfilled> {
    if !v.is_empty() {
        return Err(Unfilled::NotEmpty);
    }
    v.reserve(n);
    let per = n.div_ceil(threads.max(1)).max(1);
    let spare = &mut v.spare_capacity_mut()[..n];
    let results: Vec<Result<R, Unfilled>> = if per >= n {
        vec![fill_stretch(0, spare, &fill)]
    } else {
        let fill = &fill;
        std::thread::scope(|scope| {
            let handles: Vec<_> = spare.chunks_mut(per).enumerate().map(|(k, slots)| scope.spawn(move || fill_stretch(k * per, slots, fill))).collect();
            handles.into_iter().map(|h| h.join().unwrap_or(Err(Unfilled::Panicked))).collect()
        })
    };
    let results: Vec<R> = results.into_iter().collect::<Result<_, _>>()?;
    // SAFETY: `v` was empty with capacity for `n` (reserved above), and
    // `spare` is its first `n` slots, cut into stretches that cover them.
    // Every stretch returned `Ok`, which `fill_stretch` gives only when its
    // closure pushed exactly one element per slot, so every slot was written
    // (front to back, `Slots::push`), and `kept` stopped its drop. The
    // threads have all finished: `thread::scope` returns after joining them.
    unsafe { v.set_len(n) };
    Ok(results)
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicUsize, Ordering};

    #[test]
    fn fills_every_index_in_order_on_any_thread_count() {
        for threads in [1, 2, 3, 4, 7] {
            for n in [0, 1, 2, 5, 100, 1001] {
                let mut v: Vec<String> = Vec::new();
                let firsts = fill_in_place(&mut v, n, threads, |range, slots| {
                    for i in range.clone() {
                        slots.push(format!("{i}"));
                    }
                    range.start
                })
                .unwrap();
                assert_eq!(v, (0..n).map(|i| format!("{i}")).collect::<Vec<_>>(), "{threads} threads, {n}");
                assert!(firsts.windows(2).all(|w| w[0] < w[1]), "results in stretch order");
                assert_eq!(firsts.first().copied().unwrap_or(0), 0);
            }
        }
    }

    /// Counts drops, to check that nothing is dropped twice or read after a failure.
    struct Counted<'a>(&'a AtomicUsize);
    impl Drop for Counted<'_> {
        fn drop(&mut self) {
            self.0.fetch_add(1, Ordering::SeqCst);
        }
    }

    #[test]
    fn a_short_or_long_stretch_leaves_the_vector_empty() {
        for (threads, skip) in [(1, 10), (4, 10), (4, 99)] {
            let drops = AtomicUsize::new(0);
            let mut v = Vec::new();
            let r = fill_in_place(&mut v, 100, threads, |range, slots| {
                for i in range {
                    if i != skip {
                        slots.push(Counted(&drops));
                    }
                }
            });
            assert!(matches!(r, Err(Unfilled::Miscounted { .. })), "{r:?}");
            assert!(v.is_empty());
            // Only the incomplete stretch's 24 (or 99) elements were dropped; the rest leaked.
            let per = 100usize.div_ceil(threads);
            assert_eq!(drops.load(Ordering::SeqCst), if threads == 1 { 99 } else { per - 1 });
        }
        let mut v = Vec::new();
        let r = fill_in_place(&mut v, 10, 2, |range, slots| {
            for i in range.start..range.end + 1 {
                slots.push(i);
            }
        });
        assert_eq!(r, Err(Unfilled::Miscounted { pushed: 6, len: 5 }));
        assert!(v.is_empty());
    }

    #[test]
    fn a_panicking_thread_is_an_error_not_a_vector() {
        let mut v: Vec<u64> = Vec::new();
        let r = fill_in_place(&mut v, 64, 4, |range, slots| {
            for i in range {
                assert!(i != 40, "a bug in the closure");
                slots.push(i as u64);
            }
        });
        assert_eq!(r, Err(Unfilled::Panicked));
        assert!(v.is_empty());
        let mut full = vec![1u8];
        assert_eq!(fill_in_place(&mut full, 1, 1, |_, s| s.push(2)), Err(Unfilled::NotEmpty));
    }
}
