//! What the cache reports about each lookup, to whoever measures it.
//!
//! The cache sits below the service, so it cannot name the service's
//! metrics; it calls a [`CacheObserver`] it was given instead (the service's
//! Prometheus registry implements it). Each request also gets its own
//! account of the lookup ([`Lookup`]), for its `Server-Timing` header and
//! its log line.

use std::time::Duration;

/// A cache tier, the `tier` label of the cache metrics.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Tier {
    /// The in-process, byte-budgeted store.
    Memory,
    /// Content-addressed files on local disk.
    Disk,
    /// The Redis shared between workers.
    Redis,
}

impl Tier {
    /// The tier's name as it appears in metrics and headers.
    pub fn name(self) -> &'static str {
        match self {
            Tier::Memory => "memory",
            Tier::Disk => "disk",
            Tier::Redis => "redis",
        }
    }
}

/// Receives every tier lookup the cache makes, with its result and latency,
/// so that hit ratios and lookup latency can be shown per tier.
pub(crate) trait CacheObserver: Send + Sync + std::fmt::Debug {
    /// One lookup of `tier`: whether it found a (valid) model, and how long it took.
    fn lookup(&self, tier: Tier, hit: bool, took: Duration);
}

/// How one call found (or did not find) its model.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Lookup {
    /// Hit or miss, as the `X-Rulemesh-Cache` header says it.
    pub outcome: super::CacheOutcome,
    /// The tier that answered a hit (`None` on a miss).
    pub tier: Option<Tier>,
    /// Time spent reading tiers in this call (not rendering, not waiting on
    /// another caller's fill).
    pub took: Duration,
}
