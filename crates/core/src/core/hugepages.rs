//! Transparent huge pages for the few large, short-lived arrays a big
//! render fills front to back (a CFDG design's finished shapes and waiting
//! shapes, a drawing's marks, a preview's plan).
//!
//! Why: such an array is fresh anonymous memory, and the kernel backs it a
//! 4 KiB page at a time, each first touch a page fault that zeroes its
//! page. In a virtual machine a fault costs several microseconds: the
//! 262,143 squares of Context Free's bush (bench/bush-262k.cfdg) took
//! 24,000 faults, a third of their evaluation's time (docs/benchmarks.md).
//! Debian's kernels give huge pages only to memory that asks for them
//! (`/sys/kernel/mm/transparent_hugepage/enabled` is `madvise`), so an
//! array of at least [`HUGE_FROM`] bytes asks, with
//! `madvise(MADV_HUGEPAGE)` (Linux's `Documentation/admin-guide/mm/transhuge.rst`):
//! one fault per 2 MiB. Where the kernel has no huge pages, or another
//! system, nothing changes. The advice never changes what the memory holds,
//! so output is the same bytes either way.

/// Arrays smaller than this are left alone: the huge page a small array
/// would round up to is resident memory it does not use.
pub const HUGE_FROM: usize = 4 << 20;

/// Asks the kernel to back `v`'s whole allocation (its capacity, used or
/// not) with transparent huge pages, when it is at least [`HUGE_FROM`]
/// bytes. Call it right after reserving, before the array is filled: pages
/// already touched keep their small pages until the kernel's background
/// collapse. A hint: errors are ignored.
pub fn advise<T>(v: &mut Vec<T>) {
    let bytes = v.capacity().saturating_mul(std::mem::size_of::<T>());
    if bytes < HUGE_FROM {
        return;
    }
    advise_range(v.as_mut_ptr().cast::<u8>(), bytes);
}

#[cfg(target_os = "linux")]
fn advise_range(start: *mut u8, bytes: usize) {
    // Only the whole pages inside the allocation: a page shared with a
    // neighbouring allocation is not advised.
    let Some((from, to)) = whole_pages(start as usize, bytes) else { return };
    // SAFETY: `from..to` lies inside one live allocation of this process
    // (`start..start + bytes`, the vector's buffer, rounded inwards to whole
    // pages), so the call names only mapped memory that this allocation
    // owns. MADV_HUGEPAGE is advice on how the kernel backs those pages:
    // it never changes their contents, never unmaps them and never makes
    // an access fault, so no Rust reference into the buffer is invalidated.
    // The return value is ignored: failure leaves the small pages.
    unsafe {
        libc::madvise(from as *mut libc::c_void, to - from, libc::MADV_HUGEPAGE);
    }
}

#[cfg(not(target_os = "linux"))]
fn advise_range(_: *mut u8, _: usize) {}

/// Faults in, ahead of its writer, the pages of an array that one thread
/// fills front to back, from another thread that would otherwise wait.
///
/// Why: first touching fresh memory is kernel work (a fault, a page
/// zeroed, and in a virtual machine often the host backing the page),
/// and for a big render it fell on the one thread that cannot be split:
/// the bush's 40 MB of finished shapes. The writer says how far it has
/// written ([`Prefault::written`]); [`Prefault::run`], on a helper thread,
/// keeps the pages [`AHEAD`] bytes beyond that faulted in with
/// `madvise(MADV_POPULATE_WRITE)` (Linux 5.14, `Documentation/admin-guide/mm/`),
/// which maps the zeroed pages a first write would map and writes nothing,
/// so the array's values and the output are the same. Only what the
/// writer is about to use is faulted in: an array reserved for a million
/// shapes that holds ten costs ten's pages.
pub struct Prefault {
    start: usize,
    bytes: usize,
    written: std::sync::atomic::AtomicUsize,
    done: std::sync::atomic::AtomicBool,
}

/// Calls [`Prefault::finish`] when dropped ([`Prefault::finish_on_drop`]).
pub struct FinishOnDrop<'a>(&'a Prefault);

impl Drop for FinishOnDrop<'_> {
    fn drop(&mut self) {
        self.0.finish();
    }
}

/// How far ahead of the writer pages are faulted in.
pub const AHEAD: usize = 8 << 20;

impl Prefault {
    /// For `v`'s whole allocation (its capacity), its writer at `v.len()`.
    pub fn of<T>(v: &Vec<T>) -> Prefault {
        let size = std::mem::size_of::<T>();
        Prefault {
            start: v.as_ptr() as usize,
            bytes: v.capacity().saturating_mul(size),
            written: std::sync::atomic::AtomicUsize::new(v.len().saturating_mul(size)),
            done: std::sync::atomic::AtomicBool::new(false),
        }
    }

    /// The writer has filled `items` elements of `size` bytes.
    pub fn written(&self, items: usize, size: usize) {
        self.written.store(items.saturating_mul(size), std::sync::atomic::Ordering::Release);
    }

    /// The writer is finished: [`Prefault::run`] returns.
    pub fn finish(&self) {
        self.done.store(true, std::sync::atomic::Ordering::Release);
    }

    /// A guard that calls [`Prefault::finish`] when dropped: the writer
    /// holds it, so that the helper stops even when the writer unwinds
    /// from a panic (a scope joins its threads before it re-raises one, and
    /// would wait for a helper never told to stop).
    pub fn finish_on_drop(&self) -> FinishOnDrop<'_> {
        FinishOnDrop(self)
    }

    /// Keeps the pages ahead of the writer faulted in until
    /// [`Prefault::finish`], looking every `every`.
    pub fn run(&self, every: std::time::Duration) {
        Prefault::run_all(&[self], every);
    }

    /// [`Prefault::run`] for several arrays with one thread, until the first
    /// is finished.
    pub fn run_all(arrays: &[&Prefault], every: std::time::Duration) {
        use std::sync::atomic::Ordering;
        let mut faulted = vec![0usize; arrays.len()];
        while !arrays.first().is_none_or(|a| a.done.load(Ordering::Acquire)) {
            for (a, done) in arrays.iter().zip(faulted.iter_mut()) {
                let want = a.written.load(Ordering::Acquire).saturating_add(AHEAD).min(a.bytes);
                if want > *done {
                    populate_range(a.start.saturating_add(*done), want - *done);
                    *done = want;
                }
            }
            std::thread::sleep(every);
        }
    }
}

#[cfg(target_os = "linux")]
fn populate_range(start: usize, bytes: usize) {
    let Some((from, to)) = whole_pages(start, bytes) else { return };
    // SAFETY: MADV_POPULATE_WRITE never changes what memory holds: a page
    // already mapped is left as it is (the kernel serialises this with the
    // writer's own faults on the same page), and a page not yet mapped is
    // mapped zeroed, which is what the writer's first write would have
    // faulted in; it writes no byte, so it races with no access the Rust
    // program makes. The range lies in the array's allocation, rounded
    // inwards to whole pages; should the array have been moved or freed
    // meanwhile, the call either fails (unmapped: ENOMEM, ignored) or maps
    // pages of whatever lives there now, again without changing a byte.
    unsafe {
        libc::madvise(from as *mut libc::c_void, to - from, libc::MADV_POPULATE_WRITE);
    }
}

#[cfg(not(target_os = "linux"))]
fn populate_range(_: usize, _: usize) {}

/// The whole pages inside `start..start + bytes` (rounded inwards), or
/// `None` when there is none or the page size is unknown: the one range
/// both `madvise` calls may name.
#[cfg(target_os = "linux")]
fn whole_pages(start: usize, bytes: usize) -> Option<(usize, usize)> {
    // SAFETY: sysconf has no preconditions; it returns -1 on error.
    let page = usize::try_from(unsafe { libc::sysconf(libc::_SC_PAGESIZE) }).ok().filter(|p| p.is_power_of_two())?;
    let from = start.next_multiple_of(page);
    let to = start.saturating_add(bytes) & !(page - 1);
    (to > from).then_some((from, to))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The advice keeps what the array holds and lets it grow (the call is
    /// a hint; this checks it names only the vector's own memory).
    #[test]
    fn advice_keeps_the_contents() {
        let mut v: Vec<u64> = Vec::with_capacity(HUGE_FROM / 8 + 3);
        v.extend(0..1000);
        advise(&mut v);
        v.extend(1000..(HUGE_FROM / 8 + 3) as u64);
        assert!(v.iter().enumerate().all(|(i, &x)| x == i as u64));
        let mut small: Vec<u8> = vec![7; 100];
        advise(&mut small);
        assert_eq!(small, vec![7; 100]);
    }

    /// A writer that panics still stops its helper: the scope returns (by
    /// re-raising the panic) instead of waiting for the helper for ever.
    #[test]
    fn a_panicking_writer_stops_its_helper() {
        let v: Vec<u64> = Vec::with_capacity(2 * AHEAD / 8);
        let ahead = Prefault::of(&v);
        let outcome = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
            std::thread::scope(|scope| {
                scope.spawn(|| ahead.run(std::time::Duration::from_micros(50)));
                let _done = ahead.finish_on_drop();
                panic!("the writer fails");
            })
        }));
        assert!(outcome.is_err());
    }

    /// A writer filling an array while a helper faults in its pages ahead
    /// of it: every value is the writer's, and an array never filled
    /// beyond its start is faulted in no further than `AHEAD`.
    #[test]
    fn prefaulting_keeps_the_contents() {
        let mut v: Vec<u64> = Vec::with_capacity(4 * AHEAD / 8);
        v.extend(0..100);
        let ahead = Prefault::of(&v);
        std::thread::scope(|scope| {
            scope.spawn(|| ahead.run(std::time::Duration::from_micros(50)));
            for i in 100..(3 * AHEAD / 8) as u64 {
                v.push(i);
                if i % 4096 == 0 {
                    ahead.written(v.len(), 8);
                }
            }
            ahead.finish();
        });
        assert!(v.iter().enumerate().all(|(i, &x)| x == i as u64));
    }
}
