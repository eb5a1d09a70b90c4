//! The in-process model store: a moka cache weighted by model bytes, with
//! single-flight fills, optionally backed by a [`DiskTier`] and a shared
//! [`RedisTier`]. Failed and truncated renders are handed to every waiting
//! caller but never stored.

use super::disk::DiskTier;
use super::observe::{CacheObserver, Lookup, Tier};
use super::redis::RedisTier;
use super::CacheKey;
use crate::core::LimitExceeded;
use crate::lang::Language;
use moka::future::Cache;
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

/// What a fill that is not stored hands to its waiters.
#[derive(Debug)]
enum Fill<E> {
    /// A truncated model: returned, not stored.
    Uncacheable(Arc<Rendered>),
    /// The render failed.
    Failed(E),
}

/// The byte-budgeted, single-flight model store.
#[derive(Clone)]
pub struct ModelCache {
    inner: Cache<CacheKey, Arc<Rendered>, KeyHasher>,
    evictions: Arc<AtomicU64>,
    disk: Option<Arc<DiskTier>>,
    redis: Option<Arc<RedisTier>>,
    observer: Option<Arc<dyn CacheObserver>>,
}

/// The hasher of the model cache's table. Its keys are BLAKE3 digests, so
/// SipHash (moka's default, `RandomState`) bought nothing but time: under a
/// stream of fresh renders every insert evicts, and moka's concurrent table
/// rehashes its whole key set now and then to drop the evicted entries'
/// tombstones, which cost about 5 µs of each fresh `gem.glb` request's
/// CPU in SipHash alone (issue 33's profile). foldhash is hashbrown's own
/// hasher, seeded per process, so a client that chooses sources still cannot
/// aim keys at one bucket.
type KeyHasher = foldhash::fast::RandomState;

/// Bytes charged per entry besides the model itself (key, metadata, moka's bookkeeping).
const ENTRY_OVERHEAD: usize = 256;

impl ModelCache {
    /// A store holding at most about `max_bytes` of models.
    pub fn new(max_bytes: u64) -> ModelCache {
        let evictions = Arc::new(AtomicU64::new(0));
        let counter = evictions.clone();
        let inner = Cache::builder()
            .max_capacity(max_bytes)
            .weigher(|_k: &CacheKey, v: &Arc<Rendered>| {
                u32::try_from(v.bytes.len().saturating_add(ENTRY_OVERHEAD)).unwrap_or(u32::MAX)
            })
            .eviction_listener(move |_k, _v, cause| {
                if cause.was_evicted() {
                    counter.fetch_add(1, Ordering::Relaxed);
                }
            })
            .build_with_hasher(KeyHasher::default());
        ModelCache { inner, evictions, disk: None, redis: None, observer: None }
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
    /// misses on one key share a single call. With `fresh`, the store is not
    /// read (but a complete result still refreshes it). On an in-process
    /// miss the disk tier (if any) is read before rendering, and a complete
    /// render is written to it; then Redis (if any) is read the same way,
    /// under its distributed lock when enabled. A model read from disk or
    /// Redis counts as a hit; a model read from Redis is also written to disk.
    /// The [`Lookup`] says which tier answered and how long the reads took.
    pub(crate) async fn get_or_render<E, F, Fut>(&self, key: CacheKey, fresh: bool, render: F) -> Result<(Arc<Rendered>, Lookup), E>
    where
        E: Clone + Send + Sync + 'static,
        F: FnOnce() -> Fut,
        Fut: Future<Output = Result<Rendered, E>>,
    {
        let spent = AtomicU64::new(0);
        let lookup = |outcome, tier, spent: &AtomicU64| Lookup { outcome, tier, took: Duration::from_nanos(spent.load(Ordering::Relaxed)) };
        if fresh {
            let r = Arc::new(render().await?);
            if r.cacheable() {
                self.inner.insert(key, r.clone()).await;
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
        let found = self.inner.get(&key).await;
        self.observed(Tier::Memory, found.is_some(), started, &spent);
        if let Some(r) = found {
            return Ok((r, lookup(CacheOutcome::Hit, Some(Tier::Memory), &spent)));
        }
        // The tier a fill by this call found its model in (none: rendered).
        let from_tier: std::sync::Mutex<Option<Tier>> = std::sync::Mutex::new(None);
        let note = |tier| {
            if let Ok(mut t) = from_tier.lock() {
                *t = Some(tier);
            }
        };
        let init = async {
            if let Some(d) = &self.disk {
                let started = Instant::now();
                let found = d.read(key).await;
                self.observed(Tier::Disk, found.is_some(), started, &spent);
                if let Some(r) = found {
                    note(Tier::Disk);
                    return Ok(Arc::new(r));
                }
            }
            let rendered = match &self.redis {
                Some(t) => {
                    let started = Instant::now();
                    let found = t.read(key).await;
                    self.observed(Tier::Redis, found.is_some(), started, &spent);
                    match found {
                        Some(r) => {
                            note(Tier::Redis);
                            Ok(r)
                        }
                        None => t.render_locked(key, render).await.map(|(r, shared)| {
                            if shared {
                                note(Tier::Redis);
                            }
                            r
                        }),
                    }
                }
                None => render().await,
            };
            match rendered {
                Ok(r) if r.cacheable() => {
                    let r = Arc::new(r);
                    if let Some(d) = &self.disk {
                        d.write(key, r.clone()).await;
                    }
                    Ok(r)
                }
                Ok(r) => Err(Fill::Uncacheable(Arc::new(r))),
                Err(e) => Err(Fill::Failed(e)),
            }
        };
        // Boxed: the fill (disk, Redis and its lock, the render) is most of
        // the size of this future, which every request carries (issue 33).
        match self.inner.entry(key).or_try_insert_with(Box::pin(init)).await {
            Ok(entry) => {
                let tier = from_tier.lock().ok().and_then(|t| *t);
                // Not fresh: another call's fill answered this one, from memory.
                let tier = if entry.is_fresh() { tier } else { Some(Tier::Memory) };
                let outcome = if tier.is_some() { CacheOutcome::Hit } else { CacheOutcome::Miss };
                Ok((entry.into_value(), lookup(outcome, tier, &spent)))
            }
            Err(fill) => match &*fill {
                // Every waiter on an uncacheable fill gets the same model; the
                // caller that rendered it cannot be told apart here, so all say miss.
                Fill::Uncacheable(r) => Ok((r.clone(), lookup(CacheOutcome::Miss, None, &spent))),
                Fill::Failed(e) => Err(e.clone()),
            },
        }
    }

    /// The model the in-process tier holds for `key` now, and how long
    /// asking took: the service's fast path (`service::fast`) answers only
    /// while this is the model it kept. Not reported to the observer, so
    /// that a peek that finds nothing is not counted beside the lookup the
    /// router then makes; a peek that answers is ([`Self::observe_memory_hit`]).
    pub(crate) async fn memory_peek(&self, key: &CacheKey) -> (Option<Arc<Rendered>>, Duration) {
        let started = Instant::now();
        let found = self.inner.get(key).await;
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
        self.inner.entry_count()
    }

    /// Bytes charged to stored models.
    pub(crate) fn weighted_bytes(&self) -> u64 {
        self.inner.weighted_size()
    }

    /// Models evicted to stay within the byte budget.
    pub(crate) fn evictions(&self) -> u64 {
        self.evictions.load(Ordering::Relaxed)
    }

    /// Runs moka's pending maintenance (so counts are current), for metrics and tests.
    pub async fn sync(&self) {
        self.inner.run_pending_tasks().await;
    }

    /// Drops every stored model.
    pub fn clear(&self) {
        self.inner.invalidate_all();
    }
}
