//! The figures that live in the cache itself (bytes and entries held,
//! evictions, disk and Redis counters), read at each scrape rather than
//! copied: the tiers keep their own counters, which the cache's tests read
//! too, and a copy could only drift.

use crate::cache::ModelCache;
use prometheus_client::collector::Collector;
use prometheus_client::encoding::{DescriptorEncoder, EncodeMetric};
use prometheus_client::metrics::counter::ConstCounter;
use prometheus_client::metrics::gauge::ConstGauge;
use std::sync::{Arc, OnceLock};

/// Encodes the cache's figures, once the engine has attached its cache.
pub(super) struct CacheFigures {
    cache: Arc<OnceLock<ModelCache>>,
}

impl CacheFigures {
    pub(super) fn new(cache: Arc<OnceLock<ModelCache>>) -> CacheFigures {
        CacheFigures { cache }
    }
}

impl std::fmt::Debug for CacheFigures {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("CacheFigures").field("attached", &self.cache.get().is_some()).finish()
    }
}

fn counter(e: &mut DescriptorEncoder, name: &str, help: &str, v: u64) -> Result<(), std::fmt::Error> {
    let c = ConstCounter::new(v);
    c.encode(e.encode_descriptor(name, help, None, c.metric_type())?)
}

fn gauge(e: &mut DescriptorEncoder, name: &str, help: &str, v: u64) -> Result<(), std::fmt::Error> {
    let g = ConstGauge::new(i64::try_from(v).unwrap_or(i64::MAX));
    g.encode(e.encode_descriptor(name, help, None, g.metric_type())?)
}

impl Collector for CacheFigures {
    fn encode(&self, mut e: DescriptorEncoder) -> Result<(), std::fmt::Error> {
        let Some(cache) = self.cache.get() else { return Ok(()) };
        let e = &mut e;
        counter(e, "cache_evictions", "Models evicted from memory to keep the byte budget", cache.evictions())?;
        gauge(e, "cache_bytes", "Bytes held by the in-process cache", cache.weighted_bytes())?;
        gauge(e, "cache_entries", "Models held by the in-process cache", cache.entry_count())?;
        counter(e, "cache_corrupt", "Disk or Redis cache entries whose content hash did not match (treated as misses, never served)", cache.corrupt())?;
        if let Some(d) = cache.disk() {
            gauge(e, "cache_disk_bytes", "Bytes held by the disk cache tier", d.used_bytes())?;
            counter(e, "cache_disk_writes", "Models written to the disk tier", d.writes())?;
            counter(e, "cache_disk_skipped", "Models not written to the disk tier (budget reached, or writing failed)", d.skipped())?;
        }
        if let Some(r) = cache.redis() {
            counter(e, "redis_hits", "Models read from the shared Redis tier", r.hits())?;
            counter(e, "redis_misses", "Redis lookups without a model", r.misses())?;
            counter(e, "redis_writes", "Models written to Redis", r.writes())?;
            counter(e, "redis_skipped", "Models not written to Redis (too large, or Redis failing)", r.skipped())?;
            counter(e, "redis_errors", "Redis commands that failed or timed out (served from local caching instead)", r.errors())?;
            counter(e, "redis_timeouts", "Redis commands (or connection attempts) that timed out, of the errors", r.timeouts())?;
            counter(e, "redis_lock_waits", "Renders that waited for another worker's lock", r.lock_waits())?;
            gauge(e, "redis_up", "1 while Redis answers, 0 while it is skipped after a failure", u64::from(!r.is_degraded()))?;
        }
        Ok(())
    }
}

/// Encodes the process's resident bytes (read at each scrape, from
/// `/proc/self/statm`) and the memory guard's ceiling (0 when it is off),
/// so that an alert can see a worker near its ceiling before renders are
/// refused.
pub(super) struct MemoryFigures {
    guard: Arc<OnceLock<Arc<crate::service::memory::MemoryGuard>>>,
}

impl MemoryFigures {
    pub(super) fn new(guard: Arc<OnceLock<Arc<crate::service::memory::MemoryGuard>>>) -> MemoryFigures {
        MemoryFigures { guard }
    }
}

impl std::fmt::Debug for MemoryFigures {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("MemoryFigures").field("attached", &self.guard.get().is_some()).finish()
    }
}

impl Collector for MemoryFigures {
    fn encode(&self, mut e: DescriptorEncoder) -> Result<(), std::fmt::Error> {
        let e = &mut e;
        let resident = self.guard.get().map_or_else(|| crate::service::memory::resident_bytes().unwrap_or(0), |g| g.resident());
        gauge(e, "process_resident_bytes", "Resident memory of the process now (/proc/self/statm)", resident)?;
        let ceiling = self.guard.get().and_then(|g| g.ceiling()).unwrap_or(0);
        gauge(e, "memory_ceiling_bytes", "The memory guard's ceiling (0: off); renders start only while resident memory plus their budget fits under it", ceiling)?;
        Ok(())
    }
}

/// Encodes the log writer's dropped lines (read at each scrape from the
/// non-blocking writer's own counter, `telemetry::dropped_lines`), so that a
/// log reader too slow for the service shows as a number, not as latency.
#[derive(Debug)]
pub(super) struct LogFigures;

impl Collector for LogFigures {
    fn encode(&self, mut e: DescriptorEncoder) -> Result<(), std::fmt::Error> {
        counter(
            &mut e,
            "log_lines_dropped",
            "Log lines dropped because the log writer's queue was full (the service never waits for its log)",
            crate::service::telemetry::dropped_lines(),
        )
    }
}
