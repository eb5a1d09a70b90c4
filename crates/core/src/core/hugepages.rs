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
    // SAFETY: sysconf has no preconditions; it returns -1 on error.
    let page = usize::try_from(unsafe { libc::sysconf(libc::_SC_PAGESIZE) }).unwrap_or(0);
    if page == 0 || !page.is_power_of_two() {
        return;
    }
    // Only the whole pages inside the allocation: a page shared with a
    // neighbouring allocation is not advised.
    let from = (start as usize).next_multiple_of(page);
    let to = (start as usize).saturating_add(bytes) & !(page - 1);
    if to <= from {
        return;
    }
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
}
