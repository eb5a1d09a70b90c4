//! The in-process model store: a moka cache weighted by model bytes, with
//! single-flight fills, optionally backed by a [`DiskTier`] and a shared
//! [`RedisTier`]. Failed and truncated renders are handed to every waiting
//! caller but never stored.

use super::disk::DiskTier;
use super::redis::RedisTier;
use super::CacheKey;
use crate::core::LimitExceeded;
use crate::lang::Language;
use moka::future::Cache;
use std::future::Future;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;

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
    /// Primitive instances in the model.
    pub primitives: u64,
    /// Triangles in the model.
    pub triangles: u64,
    /// Set when a limit cut the model short.
    pub truncated: Option<LimitExceeded>,
}

impl Rendered {
    /// Wraps a pipeline output.
    pub fn from_output(out: crate::RenderOutput, content_type: &'static str) -> Rendered {
        let etag = blake3::hash(&out.bytes).to_hex()[..32].to_string();
        Rendered {
            bytes: bytes::Bytes::from(out.bytes),
            etag,
            content_type,
            language: out.language,
            primitives: out.primitives,
            triangles: out.triangles,
            truncated: out.truncated,
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
    inner: Cache<CacheKey, Arc<Rendered>>,
    evictions: Arc<AtomicU64>,
    disk: Option<Arc<DiskTier>>,
    redis: Option<Arc<RedisTier>>,
}

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
            .build();
        ModelCache { inner, evictions, disk: None, redis: None }
    }

    /// The same store, reading from and writing complete models to `disk`
    /// behind the in-process tier.
    pub fn with_disk(mut self, disk: DiskTier) -> ModelCache {
        self.disk = Some(Arc::new(disk));
        self
    }

    /// The same store, reading from and writing complete models to a Redis
    /// shared with other workers, after the disk tier (if any).
    pub fn with_redis(mut self, redis: RedisTier) -> ModelCache {
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

    /// Returns the model for `key`, calling `render` on a miss. Concurrent
    /// misses on one key share a single call. With `fresh`, the store is not
    /// read (but a complete result still refreshes it). On an in-process
    /// miss the disk tier (if any) is read before rendering, and a complete
    /// render is written to it; then Redis (if any) is read the same way,
    /// under its distributed lock when enabled. A model read from disk or
    /// Redis counts as a hit; a model read from Redis is also written to disk.
    pub async fn get_or_render<E, F, Fut>(&self, key: CacheKey, fresh: bool, render: F) -> Result<(Arc<Rendered>, CacheOutcome), E>
    where
        E: Clone + Send + Sync + 'static,
        F: FnOnce() -> Fut,
        Fut: Future<Output = Result<Rendered, E>>,
    {
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
            return Ok((r, CacheOutcome::Miss));
        }
        let from_tier = std::sync::atomic::AtomicBool::new(false);
        let init = async {
            if let Some(d) = &self.disk {
                if let Some(r) = d.read(key).await {
                    from_tier.store(true, Ordering::Relaxed);
                    return Ok(Arc::new(r));
                }
            }
            let rendered = match &self.redis {
                Some(t) => t.read_or_render(key, render).await.map(|(r, shared)| {
                    if shared {
                        from_tier.store(true, Ordering::Relaxed);
                    }
                    r
                }),
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
        match self.inner.entry(key).or_try_insert_with(init).await {
            Ok(entry) => {
                let rendered = entry.is_fresh() && !from_tier.load(Ordering::Relaxed);
                let outcome = if rendered { CacheOutcome::Miss } else { CacheOutcome::Hit };
                Ok((entry.into_value(), outcome))
            }
            Err(fill) => match &*fill {
                // Every waiter on an uncacheable fill gets the same model; the
                // caller that rendered it cannot be told apart here, so all say miss.
                Fill::Uncacheable(r) => Ok((r.clone(), CacheOutcome::Miss)),
                Fill::Failed(e) => Err(e.clone()),
            },
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
    pub fn weighted_bytes(&self) -> u64 {
        self.inner.weighted_size()
    }

    /// Models evicted to stay within the byte budget.
    pub fn evictions(&self) -> u64 {
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
