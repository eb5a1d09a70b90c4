//! The process-level memory guard: a second line behind each render's
//! memory budget (issue 38).
//!
//! A render's budget (`max_memory`) is meant to bound what it allocates,
//! and `docs/deploy.md` sizes a worker from it. Where a charge falls short
//! of what a stage really holds (Manifold's C++ data, allocator slack, a
//! sizing mistake in a manifest), the kernel's OOM killer would end the
//! whole worker: every render in flight and the in-process cache. So before
//! a render starts, the engine reads the process's resident memory
//! (`/proc/self/statm`) and admits the render only if that plus the
//! render's whole memory budget stays under a ceiling; otherwise it waits a
//! little for renders in flight to finish and give memory back, then
//! refuses with a typed `memory_pressure` (HTTP 503, gRPC
//! RESOURCE_EXHAUSTED) that the balancer can retry on another worker.
//!
//! The ceiling is `--memory-ceiling` (`RULEMESH_MEMORY_CEILING`), 0 for
//! off; unset, it is [`CGROUP_SHARE`] of the cgroup's memory limit
//! (`/sys/fs/cgroup/memory.max`, or cgroup v1's
//! `memory/memory.limit_in_bytes`) when the process has one, and off
//! without one (a developer's machine, where the kernel's own overcommit
//! rules apply).

use std::path::Path;
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::{Duration, Instant};

/// The share of the cgroup's memory limit the guard keeps renders under
/// when no ceiling is configured: 15/16, so that the kernel's own use in
/// the cgroup (page tables, socket buffers, the page cache it may not
/// reclaim at once) has room before the OOM killer is reached.
pub(crate) const CGROUP_SHARE: (u64, u64) = (15, 16);

/// How often a render waiting for memory looks at the resident size again.
const POLL: Duration = Duration::from_millis(50);

/// Reads the process's resident bytes. A trait so that tests can drive the
/// guard through exact values.
pub trait ResidentReader: Send + Sync {
    /// Resident bytes now; `None` where the system does not say (no `/proc`).
    fn resident(&self) -> Option<u64>;
}

/// The real reader: `/proc/self/statm`'s resident pages times the page size.
#[derive(Debug, Default, Clone, Copy)]
pub(crate) struct Statm;

impl ResidentReader for Statm {
    fn resident(&self) -> Option<u64> {
        resident_bytes()
    }
}

/// The process's resident bytes from `/proc/self/statm`; `None` without it.
///
/// The guard reads this before every render, so the file is opened once and
/// read again from offset 0 each time (the kernel writes a `/proc` file's
/// text anew on each read from its start): opening it per render cost 3 % of
/// the CPU of fresh icon renders (issue 33's profile).
pub(crate) fn resident_bytes() -> Option<u64> {
    use std::os::unix::fs::FileExt;
    static STATM: std::sync::OnceLock<Option<std::fs::File>> = std::sync::OnceLock::new();
    let file = STATM.get_or_init(|| std::fs::File::open("/proc/self/statm").ok()).as_ref()?;
    // statm is seven numbers of at most 20 digits: 160 bytes always suffice.
    let mut buf = [0u8; 160];
    let n = file.read_at(&mut buf, 0).ok()?;
    let text = std::str::from_utf8(buf.get(..n)?).ok()?;
    Some(parse_statm(text)?.saturating_mul(page_size()))
}

/// The resident pages (the second field) of a `statm` line.
pub(crate) fn parse_statm(text: &str) -> Option<u64> {
    text.split_whitespace().nth(1)?.parse().ok()
}

fn page_size() -> u64 {
    // SAFETY: sysconf has no preconditions; it returns -1 on error.
    let size = unsafe { libc::sysconf(libc::_SC_PAGESIZE) };
    u64::try_from(size).ok().filter(|&s| s > 0).unwrap_or(4096)
}

/// A cgroup memory limit file's value: bytes, or `None` for `max` (no
/// limit) or a value so large it means none (cgroup v1 writes
/// 9223372036854771712 for "unlimited").
pub(crate) fn parse_cgroup_limit(text: &str) -> Option<u64> {
    let v: u64 = text.trim().parse().ok()?;
    (v > 0 && v < 1 << 60).then_some(v)
}

/// The cgroup's memory limit in bytes, if the process runs under one.
pub(crate) fn cgroup_limit() -> Option<u64> {
    ["/sys/fs/cgroup/memory.max", "/sys/fs/cgroup/memory/memory.limit_in_bytes"]
        .iter()
        .find_map(|p| std::fs::read_to_string(Path::new(p)).ok().and_then(|t| parse_cgroup_limit(&t)))
}

/// The ceiling the guard enforces: `configured` when given (0: off), else
/// [`CGROUP_SHARE`] of `cgroup` when there is one, else off.
pub(crate) fn effective_ceiling(configured: Option<u64>, cgroup: Option<u64>) -> Option<u64> {
    match configured {
        Some(0) => None,
        Some(c) => Some(c),
        None => cgroup.map(|c| c / CGROUP_SHARE.1 * CGROUP_SHARE.0),
    }
}

/// Why a render was not let start: the process was too close to its
/// memory ceiling for one more render's budget.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Pressure {
    /// Resident bytes when the render gave up waiting.
    pub resident: u64,
    /// The ceiling.
    pub ceiling: u64,
    /// The render's memory budget, which had to fit under the ceiling.
    pub budget: u64,
}

/// How long a reading far below the ceiling stands in for a new one.
const READING_STANDS: Duration = Duration::from_millis(2);

/// Admits renders while the process has room for their memory budget.
pub struct MemoryGuard {
    ceiling: Option<u64>,
    wait: Duration,
    reader: Box<dyn ResidentReader>,
    /// The last reading (bytes) and when it was taken (nanoseconds after `born`).
    last: (AtomicU64, AtomicU64),
    /// The budgets admitted on that reading without reading again.
    since: AtomicU64,
    /// How long a reading stands ([`READING_STANDS`]; tests set their own).
    stands: Duration,
    born: Instant,
}

impl std::fmt::Debug for MemoryGuard {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("MemoryGuard").field("ceiling", &self.ceiling).field("wait", &self.wait).finish_non_exhaustive()
    }
}

impl MemoryGuard {
    /// A guard with `ceiling` (`None`: off) that lets a render wait up to
    /// `wait` for room, reading the resident size with `reader`.
    pub fn new(ceiling: Option<u64>, wait: Duration, reader: Box<dyn ResidentReader>) -> MemoryGuard {
        MemoryGuard { ceiling, wait, reader, last: (AtomicU64::new(u64::MAX), AtomicU64::new(0)), since: AtomicU64::new(0), stands: READING_STANDS, born: Instant::now() }
    }

    /// The resident size: while the last reading is at most
    /// [`READING_STANDS`] old and it, the budgets admitted on it since and
    /// `budget` together stay within half the ceiling, that reading plus
    /// those budgets (each counted as if already allocated in full); else a
    /// new reading (kept for the next calls).
    ///
    /// Why: reading `/proc/self/statm` is a system call in which the kernel
    /// formats seven numbers, about 3 µs, 2 % of a fresh icon's CPU at
    /// thousands of renders a second (issue 33's profile). Far from the
    /// ceiling nothing is lost: to overshoot after admitting on the old
    /// reading, the process would have had to grow, beyond the budgets it
    /// admitted, by half its ceiling in two milliseconds; near it, every
    /// render reads afresh, as before. (Two renders admitted at the same
    /// instant may both count the same earlier sum: the half-ceiling
    /// margin covers that too.)
    fn resident_for(&self, budget: u64, ceiling: u64) -> Option<u64> {
        let now = u64::try_from(self.born.elapsed().as_nanos()).unwrap_or(u64::MAX);
        let (bytes, at) = (self.last.0.load(Ordering::Relaxed), self.last.1.load(Ordering::Relaxed));
        let young = now.saturating_sub(at) <= u64::try_from(self.stands.as_nanos()).unwrap_or(u64::MAX);
        let estimate = bytes.saturating_add(self.since.load(Ordering::Relaxed));
        if young && bytes != u64::MAX && estimate.saturating_add(budget) <= ceiling / 2 {
            self.since.fetch_add(budget, Ordering::Relaxed);
            return Some(estimate);
        }
        let read = self.reader.resident()?;
        self.last.0.store(read, Ordering::Relaxed);
        self.last.1.store(now, Ordering::Relaxed);
        self.since.store(0, Ordering::Relaxed);
        Some(read)
    }

    /// The same guard with readings standing for `stands` (tests: long
    /// enough that a loaded machine does not age a reading between calls).
    #[cfg(test)]
    fn with_stands(mut self, stands: Duration) -> MemoryGuard {
        self.stands = stands;
        self
    }

    /// The ceiling in bytes, if the guard is on.
    pub fn ceiling(&self) -> Option<u64> {
        self.ceiling
    }

    /// Resident bytes now (0 where the system does not say).
    pub fn resident(&self) -> u64 {
        self.reader.resident().unwrap_or(0)
    }

    /// Whether a render of memory budget `budget` fits now; `Err` with the
    /// figures when it does not. Always fits when the guard is off or the
    /// resident size cannot be read.
    pub fn fits(&self, budget: u64) -> Result<(), Pressure> {
        let Some(ceiling) = self.ceiling else { return Ok(()) };
        let Some(resident) = self.resident_for(budget, ceiling) else { return Ok(()) };
        if resident.saturating_add(budget) <= ceiling {
            Ok(())
        } else {
            Err(Pressure { resident, ceiling, budget })
        }
    }

    /// Waits until a render of memory budget `budget` fits, at most the
    /// guard's wait; the first time it does not fit, asks the allocator to
    /// give freed memory back to the system (`malloc_trim`: glibc keeps
    /// freed pages of a finished render's arenas resident otherwise).
    /// `Ok(true)` if it had to wait.
    pub async fn admit(&self, budget: u64) -> Result<bool, Pressure> {
        if self.fits(budget).is_ok() {
            return Ok(false);
        }
        trim();
        let until = tokio::time::Instant::now() + self.wait;
        loop {
            match self.fits(budget) {
                Ok(()) => return Ok(true),
                Err(p) if tokio::time::Instant::now() >= until => return Err(p),
                Err(_) => tokio::time::sleep(POLL).await,
            }
        }
    }
}

/// The size from which glibc's malloc maps each block on its own (and
/// unmaps it when freed): 1 MiB, fixed.
pub(crate) const MMAP_THRESHOLD: i32 = 1 << 20;

/// Fixes glibc's mmap threshold at [`MMAP_THRESHOLD`]. By default glibc
/// raises the threshold to the size of the largest mapped block freed (up
/// to 32 MiB), after which a print's big vectors (Manifold's half-edges,
/// the fused route's grids) come from the heap and stay resident after
/// they are freed, so the next stage's vectors are added on top instead
/// of reusing the pages: the Sierpinski bush's print peaked at 664 MB
/// resident with the default and at 573 MB with the threshold fixed, and
/// plant-e's at 634 and 576 MB, for the same bytes out and the same CPU
/// time (docs/print.md, "Memory"). Called first thing in `main`, before
/// any thread starts.
pub fn tune_allocator() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: mallopt only sets a malloc parameter; called before other threads exist.
    unsafe {
        libc::mallopt(libc::M_MMAP_THRESHOLD, MMAP_THRESHOLD);
    }
}


/// Returns freed heap memory to the system where the allocator keeps it.
pub fn trim() {
    #[cfg(all(target_os = "linux", target_env = "gnu"))]
    // SAFETY: malloc_trim has no preconditions and may be called from any thread.
    unsafe {
        libc::malloc_trim(0);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicU64, Ordering};
    use std::sync::Arc;

    struct Fixed(Arc<AtomicU64>);

    impl ResidentReader for Fixed {
        fn resident(&self) -> Option<u64> {
            Some(self.0.load(Ordering::SeqCst))
        }
    }

    #[test]
    fn statm_and_cgroup_files_are_read_as_the_kernel_writes_them() {
        assert_eq!(parse_statm("125013 3261 1850 274 0 9830 0\n"), Some(3261));
        assert_eq!(parse_statm("12"), None);
        assert_eq!(parse_cgroup_limit("1610612736\n"), Some(1_610_612_736));
        assert_eq!(parse_cgroup_limit("max\n"), None);
        assert_eq!(parse_cgroup_limit("9223372036854771712\n"), None);
        assert!(resident_bytes().is_some_and(|r| r > 1 << 20), "this test process holds more than a MiB");
    }

    #[test]
    fn the_ceiling_is_the_flag_or_fifteen_sixteenths_of_the_cgroup_limit() {
        let mib = 1024 * 1024;
        assert_eq!(effective_ceiling(Some(1536 * mib), Some(4096 * mib)), Some(1536 * mib));
        assert_eq!(effective_ceiling(Some(0), Some(1536 * mib)), None);
        assert_eq!(effective_ceiling(None, Some(1536 * mib)), Some(1440 * mib));
        assert_eq!(effective_ceiling(None, None), None);
    }

    #[tokio::test]
    async fn a_render_fits_waits_for_room_or_is_refused_with_the_figures() {
        let resident = Arc::new(AtomicU64::new(600));
        let guard = MemoryGuard::new(Some(1000), Duration::from_millis(300), Box::new(Fixed(resident.clone())));
        assert_eq!(guard.admit(400).await, Ok(false), "600 + 400 fits under 1000 exactly");
        assert_eq!(guard.admit(401).await, Err(Pressure { resident: 600, ceiling: 1000, budget: 401 }));
        // Memory given back while a render waits lets it start.
        let later = resident.clone();
        tokio::spawn(async move {
            tokio::time::sleep(Duration::from_millis(100)).await;
            later.store(500, Ordering::SeqCst);
        });
        assert_eq!(guard.admit(450).await, Ok(true));
        let off = MemoryGuard::new(None, Duration::ZERO, Box::new(Fixed(resident)));
        assert_eq!(off.admit(u64::MAX).await, Ok(false));
    }

    /// Counts its readings.
    struct Counting(Arc<AtomicU64>, Arc<AtomicU64>);

    impl ResidentReader for Counting {
        fn resident(&self) -> Option<u64> {
            self.1.fetch_add(1, Ordering::SeqCst);
            Some(self.0.load(Ordering::SeqCst))
        }
    }

    #[test]
    fn a_young_reading_far_below_the_ceiling_stands_and_near_it_never_does() {
        let (resident, reads) = (Arc::new(AtomicU64::new(100)), Arc::new(AtomicU64::new(0)));
        let guard = MemoryGuard::new(Some(1000), Duration::ZERO, Box::new(Counting(resident.clone(), reads.clone()))).with_stands(Duration::from_secs(600));
        assert_eq!(guard.fits(100), Ok(()));
        assert_eq!(guard.fits(100), Ok(()));
        assert_eq!(reads.load(Ordering::SeqCst), 1, "100 + 100 is under half of 1000: the first reading stands");
        // The budgets admitted on it count: 100 + 100 + 250 is under half, + 100 more is not.
        assert_eq!(guard.fits(250), Ok(()));
        assert_eq!(reads.load(Ordering::SeqCst), 1);
        assert_eq!(guard.fits(100), Ok(()));
        assert_eq!(reads.load(Ordering::SeqCst), 2, "100 + 350 + 100 is over half: read again");
        // Past half the ceiling every call reads, and sees the process grown.
        resident.store(700, Ordering::SeqCst);
        assert_eq!(guard.fits(450), Err(Pressure { resident: 700, ceiling: 1000, budget: 450 }));
        assert_eq!(reads.load(Ordering::SeqCst), 3);
        // An old reading does not stand, however far below.
        let guard = MemoryGuard::new(Some(1000), Duration::ZERO, Box::new(Counting(resident.clone(), reads.clone()))).with_stands(Duration::from_millis(1));
        resident.store(100, Ordering::SeqCst);
        assert_eq!(guard.fits(100), Ok(()));
        std::thread::sleep(Duration::from_millis(20));
        resident.store(990, Ordering::SeqCst);
        assert_eq!(guard.fits(100), Err(Pressure { resident: 990, ceiling: 1000, budget: 100 }));
        assert_eq!(reads.load(Ordering::SeqCst), 5);
    }
}
