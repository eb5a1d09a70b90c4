//! The unfinished shapes, ordered as cfdg orders them: a max-heap on area
//! kept by libstdc++'s `push_heap`/`pop_heap` ([`super::frame`]), so shapes
//! of equal area leave in the very order cfdg's `mUnfinishedShapes` gives
//! them (`renderimpl.cpp`, Context Free 3.4).
//!
//! The heap holds only (area, slot) pairs and the shapes stay put in their
//! slots. The order depends only on the keys the heap compares, never on
//! what travels with them, so this is cfdg's order; and a sift moves 16
//! bytes instead of a whole shape state, which made the heap the
//! renderer's largest cost (a fifth of the bush benchmark's time in
//! `memmove`).

use super::frame::{pop_heap, push_heap};
use super::Unfinished;

/// Unfinished shapes, largest area first: the general loop's
/// [`Unfinished`], or what a memoised run keeps of a shape (`run/memo.rs`).
pub(super) struct Pending<T = Unfinished> {
    heap: Vec<(f64, u32)>,
    slots: Vec<Option<T>>,
    free: Vec<u32>,
}

impl<T> Default for Pending<T> {
    fn default() -> Self {
        Pending { heap: Vec::new(), slots: Vec::new(), free: Vec::new() }
    }
}

fn less(a: &(f64, u32), b: &(f64, u32)) -> bool {
    a.0 < b.0
}

impl<T> Pending<T> {
    /// How many shapes wait.
    pub(super) fn len(&self) -> usize {
        self.heap.len()
    }

    /// Whether none waits.
    pub(super) fn is_empty(&self) -> bool {
        self.heap.is_empty()
    }

    /// Room for `n` waiting shapes without growing, on huge pages
    /// (`core::hugepages`); only what is used becomes resident.
    pub(super) fn reserve(&mut self, n: usize) {
        self.heap.reserve(n);
        self.slots.reserve(n);
        crate::core::hugepages::advise(&mut self.heap);
        crate::core::hugepages::advise(&mut self.slots);
    }

    /// A prefaulter for the slots (`core::hugepages::Prefault`): they fill
    /// front to back, a freed slot taken again first.
    pub(super) fn slots_prefault(&self) -> crate::core::hugepages::Prefault {
        crate::core::hugepages::Prefault::of(&self.slots)
    }

    /// Tells `ahead` (from [`Pending::slots_prefault`]) how far the slots are used.
    pub(super) fn report_slots(&self, ahead: &crate::core::hugepages::Prefault) {
        ahead.written(self.slots.len(), std::mem::size_of::<Option<T>>());
    }

    /// Adds `s`, which waits by its `area`.
    pub(super) fn push(&mut self, area: f64, s: T) {
        let slot = match self.free.pop() {
            Some(i) => {
                self.slots[i as usize] = Some(s);
                i
            }
            None => {
                let room = self.slots.capacity();
                self.slots.push(Some(s));
                if self.slots.capacity() != room {
                    // Grown: the new buffer is fresh memory (module documentation of `hugepages`).
                    crate::core::hugepages::advise(&mut self.slots);
                }
                (self.slots.len() - 1) as u32
            }
        };
        let room = self.heap.capacity();
        self.heap.push((area, slot));
        if self.heap.capacity() != room {
            crate::core::hugepages::advise(&mut self.heap);
        }
        push_heap(&mut self.heap, &less);
    }

    /// Takes the shape cfdg would expand next: the largest.
    pub(super) fn pop(&mut self) -> Option<T> {
        pop_heap(&mut self.heap, &less);
        let (_, slot) = self.heap.pop()?;
        self.free.push(slot);
        let s = self.slots.get_mut(slot as usize).and_then(Option::take);
        self.prefetch_top();
        s
    }

    /// Asks the cache for the slot of the shape now on top, usually the
    /// next one out: slots are met in area order, scattered over a large
    /// array, and fetching one cold was a tenth of the bush benchmark.
    fn prefetch_top(&self) {
        #[cfg(target_arch = "x86_64")]
        if let Some(next) = self.heap.first().and_then(|&(_, i)| self.slots.get(i as usize)) {
            use std::arch::x86_64::{_mm_prefetch, _MM_HINT_T0};
            // SAFETY: `_mm_prefetch` needs SSE, which every x86_64 target
            // has (it is in the baseline), and is a hint that never reads
            // or faults; the pointer comes from a live reference anyway.
            unsafe { _mm_prefetch::<_MM_HINT_T0>((next as *const Option<T>).cast::<i8>()) };
        }
    }
}
