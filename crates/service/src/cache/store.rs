//! The in-process model store: a table weighted by model bytes
//! (`quick_cache`), with single-flight fills (`super::flight`), optionally
//! backed by a [`DiskTier`] and a shared [`RedisTier`]. Failed and
//! truncated renders are handed to every waiting caller but never stored.
//!
//! Why `quick_cache` and not moka (issue 33): under a stream of fresh
//! renders every insert evicts, and moka's concurrent table left a
//! tombstone per eviction that it swept by rehashing the whole table now
//! and then, behind a write-op channel and a housekeeper: 6–7 % of a fresh
//! `gem.glb` request's CPU went to moka. quick_cache's table is a hash map
//! under a lock with a CLOCK-Pro-like policy (Arthur Silva's quick_cache;
//! its policy is close to S3-FIFO: Yang, Zhang, Qiu, Yue and Vinayak, "FIFO
//! queues are all you need for cache eviction", SOSP 2023), scan-resistant
//! like moka's TinyLFU, so a burst of one-off renders does not flush the
//! models in demand.

use super::disk::DiskTier;
use super::observe::{CacheObserver, Lookup, Tier};
use super::redis::RedisTier;
use super::CacheKey;
use crate::core::LimitExceeded;
use crate::lang::Language;
use super::flight::{self, Flights, Landed, Turn};
use quick_cache::sync::Cache;
use quick_cache::{Lifecycle, OptionsBuilder, Weighter};
use std::any::Any;
use std::future::Future;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};

/// A finished model as the service hands it out.
#[derive(Debug, Clone, PartialEq)]
pub struct Rendered {
    /// The model bytes.
    pub bytes: bytes::Bytes,
    /// The content hash of `bytes` (hex BLAKE3, 32 characters), used as the ETag.
    pub etag: String,
    /// The MIME type of the format.
    pub content_type: &'static str,
    /// The language the source was read as.
    pub language: Language,
    /// The seed the model was made with (see [`crate::RenderOutput::seed`]),
    /// kept with the bytes so a cache hit reports it without re-rendering.
    pub seed: u64,
    /// Primitive instances in the model.
    pub primitives: u64,
    /// Triangles in the model.
    pub triangles: u64,
    /// Set when a limit cut the model short.
    pub truncated: Option<LimitExceeded>,
    /// A printed model's headline figures (the print stage's, kept with the
    /// bytes so every door and every tier serves them without measuring).
    pub print: Option<crate::print::PrintSummary>,
}

impl Rendered {
    /// Wraps a pipeline output.
    pub(crate) fn from_output(out: crate::RenderOutput, content_type: &'static str) -> Rendered {
        let etag = blake3::hash(&out.bytes).to_hex()[..32].to_string();
        Rendered {
            bytes: bytes::Bytes::from(out.bytes),
            etag,
            content_type,
            language: out.language,
            seed: out.seed,
            primitives: out.primitives,
            triangles: out.triangles,
            truncated: out.truncated,
            print: out.print,
        }
    }

    /// Only complete models may be stored.
    pub fn cacheable(&self) -> bool {
        self.truncated.is_none()
    }
}

/// Whether a model came from the store or was rendered for this call.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CacheOutcome {
    /// Served from the store (or from a fill another caller started).
    Hit,
    /// Rendered for this call.
    Miss,
}

/// Weighs a stored model by its bytes plus [`ENTRY_OVERHEAD`].
#[derive(Debug, Clone, Copy)]
struct ByBytes;

impl Weighter<CacheKey, Arc<Rendered>> for ByBytes {
    fn weight(&self, _: &CacheKey, v: &Arc<Rendered>) -> u64 {
        v.bytes.len().saturating_add(ENTRY_OVERHEAD) as u64
    }
}

/// Counts the models the table evicts (or refuses, when one alone is
/// heavier than the table may hold).
#[derive(Debug, Clone, Default)]
struct CountEvictions(Arc<AtomicU64>);

impl Lifecycle<CacheKey, Arc<Rendered>> for CountEvictions {
    type RequestState = ();

    fn begin_request(&self) {}

    fn on_evict(&self, _: &mut (), _: CacheKey, _: Arc<Rendered>) {
        self.0.fetch_add(1, Ordering::Relaxed);
    }
}

/// The store's table.
type Table = Cache<CacheKey, Arc<Rendered>, ByBytes, KeyHasher, CountEvictions>;

/// The byte-budgeted, single-flight model store.
#[derive(Clone)]
pub struct ModelCache {
    table: Arc<Table>,
    flights: Arc<Flights<Arc<Rendered>>>,
    evictions: Arc<AtomicU64>,
    disk: Option<Arc<DiskTier>>,
    redis: Option<Arc<RedisTier>>,
    observer: Option<Arc<dyn CacheObserver>>,
}

/// The hasher of the model cache's table. Its keys are BLAKE3 digests, so
/// SipHash bought nothing but time (about 5 µs of each fresh `gem.glb`
/// request under moka, issue 33's profile). foldhash is hashbrown's own
/// hasher, seeded per process, so a client that chooses sources still cannot
/// aim keys at one bucket.
type KeyHasher = foldhash::fast::RandomState;

/// Bytes charged per entry besides the model itself (key, metadata, the table's bookkeeping).
const ENTRY_OVERHEAD: usize = 256;

/// The model size the table is sized for (its slots, not its budget).
const TYPICAL_MODEL_BYTES: u64 = 16 * 1024;

impl ModelCache {
    /// A store holding at most about `max_bytes` of models.
    ///
    /// One shard: quick_cache splits its budget evenly between shards and
    /// refuses a model heavier than one shard's share, while moka, before
    /// it, kept any model up to the whole budget. Two workers' lookups
    /// are a few hundred nanoseconds under the lock, against renders of
    /// tens of microseconds and more.
    pub fn new(max_bytes: u64) -> ModelCache {
        let evictions = CountEvictions::default();
        let counter = evictions.0.clone();
        let items = (max_bytes / TYPICAL_MODEL_BYTES).clamp(64, 1 << 20) as usize;
        // `build` fails only when the weight or item capacity is unset, and
        // both are set here, whatever their values.
        let options = OptionsBuilder::new().shards(1).estimated_items_capacity(items).weight_capacity(max_bytes.max(1)).build().expect("both capacities are set");
        let table = Cache::with_options(options, ByBytes, KeyHasher::default(), evictions);
        ModelCache { table: Arc::new(table), flights: Arc::default(), evictions: counter, disk: None, redis: None, observer: None }
    }

    /// The same store, reading from and writing complete models to `disk`
    /// behind the in-process tier.
    pub(crate) fn with_disk(mut self, disk: DiskTier) -> ModelCache {
        self.disk = Some(Arc::new(disk));
        self
    }

    /// The same store, reading from and writing complete models to a Redis
    /// shared with other workers, after the disk tier (if any).
    pub(crate) fn with_redis(mut self, redis: RedisTier) -> ModelCache {
        self.redis = Some(Arc::new(redis));
        self
    }

    /// The Redis tier, if configured.
    pub fn redis(&self) -> Option<&RedisTier> {
        self.redis.as_deref()
    }

    /// The disk tier, if configured.
    pub fn disk(&self) -> Option<&DiskTier> {
        self.disk.as_deref()
    }

    /// Reports every tier lookup to `observer` (the service's metrics).
    pub(crate) fn with_observer(mut self, observer: Arc<dyn CacheObserver>) -> ModelCache {
        self.observer = Some(observer);
        self
    }

    /// Tells the observer about one lookup and adds its time to `spent` (nanoseconds).
    fn observed(&self, tier: Tier, hit: bool, started: Instant, spent: &AtomicU64) {
        let took = started.elapsed();
        spent.fetch_add(u64::try_from(took.as_nanos()).unwrap_or(u64::MAX), Ordering::Relaxed);
        if let Some(o) = &self.observer {
            o.lookup(tier, hit, took);
        }
    }

    /// Returns the model for `key`, calling `render` on a miss. Concurrent
    /// misses on one key share a single call, and its outcome, failures
    /// included. With `fresh`, the store is not read (but a complete result
    /// still refreshes it). On an in-process miss the disk tier (if any) is
    /// read before rendering, and a complete render is written to it; then
    /// Redis (if any) is read the same way, under its distributed lock when
    /// enabled. A model read from disk or Redis counts as a hit; a model read
    /// from Redis is also written to disk. The [`Lookup`] says which tier
    /// answered and how long the reads took.
    pub(crate) async fn get_or_render<E, F, Fut>(&self, key: CacheKey, fresh: bool, render: F) -> Result<(Arc<Rendered>, Lookup), E>
    where
        E: Clone + Send + Sync + 'static,
        F: FnOnce() -> Fut,
        Fut: Future<Output = Result<Rendered, E>>,
    {
        let spent = AtomicU64::new(0);
        if fresh {
            let r = Arc::new(render().await?);
            if r.cacheable() {
                self.table.insert(key, r.clone());
                if let Some(d) = &self.disk {
                    d.write(key, r.clone()).await;
                }
                if let Some(t) = &self.redis {
                    t.write(key, &r).await;
                }
            }
            return Ok((r, lookup(CacheOutcome::Miss, None, &spent)));
        }
        let started = Instant::now();
        let found = self.table.get(&key);
        self.observed(Tier::Memory, found.is_some(), started, &spent);
        if let Some(r) = found {
            return Ok((r, lookup(CacheOutcome::Hit, Some(Tier::Memory), &spent)));
        }
        let leader = loop {
            match self.flights.turn(key, || self.table.get(&key)) {
                // A fill that landed between the lookup above and now.
                Turn::Ready(r) => return Ok((r, lookup(CacheOutcome::Hit, Some(Tier::Memory), &spent))),
                Turn::Follow(rx) => match flight::outcome(rx).await {
                    Some(Landed::Stored(r)) => return Ok((r, lookup(CacheOutcome::Hit, Some(Tier::Memory), &spent))),
                    // Every waiter on an uncacheable fill gets the same model; the
                    // caller that rendered it cannot be told apart here, so all say miss.
                    Some(Landed::Unstored(r)) => return Ok((r, lookup(CacheOutcome::Miss, None, &spent))),
                    Some(Landed::Failed(e)) => match e.downcast_ref::<E>() {
                        Some(e) => return Err(e.clone()),
                        // A leader of another error type: fill afresh.
                        None => continue,
                    },
                    // The leader went away without landing: start over.
                    None => continue,
                },
                Turn::Lead(leader) => break leader,
            }
        };
        // Boxed: the fill (disk, Redis and its lock, the render) is most of
        // the size of this future, which every request carries (issue 33).
        let (filled, tier) = Box::pin(self.fill(key, render, &spent)).await;
        match filled {
            Ok(r) if r.cacheable() => {
                self.table.insert(key, r.clone());
                leader.land(Landed::Stored(r.clone()));
                let outcome = if tier.is_some() { CacheOutcome::Hit } else { CacheOutcome::Miss };
                Ok((r, lookup(outcome, tier, &spent)))
            }
            Ok(r) => {
                leader.land(Landed::Unstored(r.clone()));
                Ok((r, lookup(CacheOutcome::Miss, None, &spent)))
            }
            Err(e) => {
                leader.land(Landed::Failed(Arc::new(e.clone()) as Arc<dyn Any + Send + Sync>));
                Err(e)
            }
        }
    }

    /// A leader's fill: the disk tier, then Redis (or its lock's holder),
    /// else `render`; a complete model is written to disk. Returns the model
    /// and the tier it was found in (none: rendered here).
    async fn fill<E, F, Fut>(&self, key: CacheKey, render: F, spent: &AtomicU64) -> (Result<Arc<Rendered>, E>, Option<Tier>)
    where
        F: FnOnce() -> Fut,
        Fut: Future<Output = Result<Rendered, E>>,
    {
        if let Some(d) = &self.disk {
            let started = Instant::now();
            let found = d.read(key).await;
            self.observed(Tier::Disk, found.is_some(), started, spent);
            if let Some(r) = found {
                return (Ok(Arc::new(r)), Some(Tier::Disk));
            }
        }
        let (rendered, tier) = match &self.redis {
            Some(t) => {
                let started = Instant::now();
                let found = t.read(key).await;
                self.observed(Tier::Redis, found.is_some(), started, spent);
                match found {
                    Some(r) => (Ok(r), Some(Tier::Redis)),
                    None => match t.render_locked(key, render).await {
                        Ok((r, true)) => (Ok(r), Some(Tier::Redis)),
                        Ok((r, false)) => (Ok(r), None),
                        Err(e) => (Err(e), None),
                    },
                }
            }
            None => (render().await, None),
        };
        let rendered = rendered.map(Arc::new);
        if let (Ok(r), Some(d)) = (&rendered, &self.disk) {
            if r.cacheable() {
                d.write(key, r.clone()).await;
            }
        }
        (rendered, tier)
    }

    /// The model the in-process tier holds for `key` now, and how long
    /// asking took: the service's fast path (`service::fast`) answers only
    /// while this is the model it kept. Not reported to the observer, so
    /// that a peek that finds nothing is not counted beside the lookup the
    /// router then makes; a peek that answers is ([`Self::observe_memory_hit`]).
    /// A lookup like any other for the table's policy: it keeps the model hot.
    pub(crate) fn memory_peek(&self, key: &CacheKey) -> (Option<Arc<Rendered>>, Duration) {
        let started = Instant::now();
        let found = self.table.get(key);
        (found, started.elapsed())
    }

    /// Reports a memory-tier hit that took `took` (a peek that answered).
    pub(crate) fn observe_memory_hit(&self, took: Duration) {
        if let Some(o) = &self.observer {
            o.lookup(Tier::Memory, true, took);
        }
    }

    /// Disk and Redis entries that did not verify (misses, never served).
    pub fn corrupt(&self) -> u64 {
        self.disk.as_ref().map_or(0, |d| d.corrupt()) + self.redis.as_ref().map_or(0, |r| r.corrupt())
    }

    /// Stored models.
    pub fn entry_count(&self) -> u64 {
        self.table.len() as u64
    }

    /// Bytes charged to stored models.
    pub(crate) fn weighted_bytes(&self) -> u64 {
        self.table.weight()
    }

    /// Models evicted to stay within the byte budget.
    pub(crate) fn evictions(&self) -> u64 {
        self.evictions.load(Ordering::Relaxed)
    }

    /// Drops every stored model.
    pub fn clear(&self) {
        self.table.clear();
    }
}

/// A [`Lookup`] of `outcome` answered by `tier`, after the reads `spent` counted (nanoseconds).
fn lookup(outcome: CacheOutcome, tier: Option<Tier>, spent: &AtomicU64) -> Lookup {
    Lookup { outcome, tier, took: Duration::from_nanos(spent.load(Ordering::Relaxed)) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::AtomicUsize;

    fn model(bytes: usize, truncated: bool) -> Rendered {
        Rendered {
            bytes: bytes::Bytes::from(vec![1; bytes]),
            etag: String::new(),
            content_type: "model/gltf-binary",
            language: crate::lang::Language::Mdg,
            seed: 0,
            primitives: 0,
            triangles: 0,
            truncated: truncated.then(|| LimitExceeded { limit: crate::core::Limit::Primitives, configured: 1, reached: 2 }),
            print: None,
        }
    }

    /// Fifty concurrent misses of one key: `render` runs once, and every
    /// caller gets its outcome (a model, a truncated model, an error).
    #[tokio::test(flavor = "multi_thread", worker_threads = 2)]
    async fn concurrent_misses_share_one_fill_and_its_outcome() {
        for (case, outcome) in [(0u8, Ok(false)), (1, Ok(true)), (2, Err("boom".to_string()))] {
            let cache = ModelCache::new(1 << 20);
            let calls = Arc::new(AtomicUsize::new(0));
            let key = CacheKey([case; 32]);
            let callers = (0..50).map(|_| {
                let (cache, calls, outcome) = (cache.clone(), calls.clone(), outcome.clone());
                tokio::spawn(async move {
                    cache
                        .get_or_render(key, false, || async move {
                            calls.fetch_add(1, Ordering::SeqCst);
                            tokio::time::sleep(Duration::from_millis(50)).await;
                            outcome.map(|truncated| model(100, truncated))
                        })
                        .await
                        .map(|(m, l)| (m.truncated.is_some(), l.outcome))
                })
            });
            let results: Vec<_> = futures_util::future::join_all(callers).await.into_iter().map(|r| r.expect("joined")).collect();
            assert_eq!(calls.load(Ordering::SeqCst), 1, "case {case}: one fill");
            let misses = results.iter().filter(|r| matches!(r, Ok((_, CacheOutcome::Miss)))).count();
            match case {
                0 => assert_eq!(misses, 1, "the leader misses, the others hit: {results:?}"),
                1 => assert!(results.iter().all(|r| matches!(r, Ok((true, CacheOutcome::Miss)))), "{results:?}"),
                _ => assert!(results.iter().all(|r| r.as_ref().err().map(String::as_str) == Some("boom")), "{results:?}"),
            }
            assert_eq!(cache.entry_count(), u64::from(case == 0), "only a complete model is stored");
        }
    }

    /// The table keeps at most its budget, counting what it lets go, and
    /// keeps a model as heavy as most of the budget (one shard).
    #[tokio::test]
    async fn the_budget_bounds_the_table_and_evictions_are_counted() {
        let cache = ModelCache::new(64 * 1024);
        for i in 0..40u8 {
            let fill = cache.get_or_render(CacheKey([i; 32]), true, || async { Ok::<_, String>(model(4000, false)) }).await;
            assert!(fill.is_ok());
        }
        assert!(cache.weighted_bytes() <= 64 * 1024, "{}", cache.weighted_bytes());
        assert_eq!(cache.entry_count() + cache.evictions(), 40);
        let big = cache.get_or_render(CacheKey([99; 32]), true, || async { Ok::<_, String>(model(60_000, false)) }).await;
        assert!(big.is_ok());
        assert!(cache.memory_peek(&CacheKey([99; 32])).0.is_some(), "a model of 60 KB in a 64 KB table is kept");
    }

    /// Scan resistance: a model asked for again survives a stream of
    /// one-off renders ten times the table's size.
    #[tokio::test]
    async fn models_in_demand_survive_a_burst_of_one_off_renders() {
        let cache = ModelCache::new(100 * 4352);
        let popular = CacheKey([0xee; 32]);
        let fill = || async { Ok::<_, String>(model(4096, false)) };
        cache.get_or_render(popular, true, fill).await.map(|_| ()).expect("filled");
        for i in 0..1000u32 {
            let mut key = [0u8; 32];
            key[..4].copy_from_slice(&i.to_le_bytes());
            cache.get_or_render(CacheKey(key), true, fill).await.map(|_| ()).expect("filled");
            if i % 50 == 0 {
                assert!(cache.memory_peek(&popular).0.is_some(), "after {i} one-off renders");
            }
        }
        assert!(cache.memory_peek(&popular).0.is_some());
        assert!(cache.evictions() >= 900);
    }
}
