//! The optional shared tier: complete models in Redis, keyed by the same
//! content hash as the in-process store, so any worker can serve a model any
//! other worker rendered.
//!
//! Redis is a cache here, never a dependency: every command runs under a
//! short timeout, and any failure (Redis down, slow, out of memory, a value
//! that does not decode) makes the call behave as a miss or a skipped write.
//! After a failure the tier is skipped for [`RETRY_AFTER`] (requests are not
//! slowed by a dead Redis), counted in `rulemesh_redis_errors_total`, and
//! logged once when it goes down and once when it comes back.
//!
//! Values use the disk tier's self-checking encoding (magic, JSON header,
//! bytes, and a BLAKE3 content hash over the key and all of it, verified on
//! read: a value that does not verify is a miss, counted in
//! `rulemesh_cache_corrupt_total`), under `rulemesh:m:<hex key>` with a
//! TTL (`SET … PX`). Values over the size cap are not written.
//!
//! With the lock enabled, a worker that misses everywhere takes
//! `rulemesh:l:<hex key>` (`SET NX PX`, a random token) before rendering;
//! other workers missing the same key wait, polling for the value, until it
//! appears, the lock goes away, or the lock's lifetime has passed, and only
//! then render themselves. See `docs/deploy.md` for the trade-offs.

use super::{CacheKey, Rendered};
use ::redis::aio::{ConnectionManager, ConnectionManagerConfig};
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::Arc;
use std::time::{Duration, Instant};
use tokio::sync::Mutex;

/// How long the tier is skipped after a failure before Redis is tried again.
pub(crate) const RETRY_AFTER: Duration = Duration::from_secs(1);
/// Interval at which a worker waiting on another worker's lock polls for the value.
const POLL: Duration = Duration::from_millis(20);
/// Prefix of model keys.
const VALUE_PREFIX: &str = "rulemesh:m:";
/// Prefix of lock keys.
const LOCK_PREFIX: &str = "rulemesh:l:";
/// Deletes a lock only if it still holds our token.
const UNLOCK: &str = "if redis.call('get', KEYS[1]) == ARGV[1] then return redis.call('del', KEYS[1]) else return 0 end";

/// Why the Redis tier could not be configured.
#[derive(Debug, thiserror::Error)]
pub enum RedisError {
    /// The URL is not a Redis URL the client understands.
    #[error("--cache-redis: {0}")]
    Url(String),
}

/// Settings of the Redis tier.
#[derive(Debug, Clone, PartialEq)]
pub struct RedisSettings {
    /// `redis://[user:password@]host[:port][/db]` (or `rediss://`, `unix://`).
    pub url: String,
    /// Lifetime of a stored model.
    pub ttl: Duration,
    /// Largest model written, in encoded bytes.
    pub max_value_bytes: u64,
    /// Longest any one Redis command (or connection attempt) may take.
    pub timeout: Duration,
    /// Lifetime of the distributed single-flight lock; `None` disables the lock.
    pub lock: Option<Duration>,
}

/// What looking for a lock found.
enum Claim {
    /// We hold the lock with this token.
    Held(String),
    /// Another worker stored the model while we waited.
    Found(Rendered),
    /// Render without a lock (Redis failed, or the wait ran out).
    Alone,
}

/// The Redis tier: a lazily (re)connected, multiplexed connection and counters.
pub struct RedisTier {
    settings: RedisSettings,
    client: ::redis::Client,
    conn: Mutex<Option<ConnectionManager>>,
    /// Milliseconds since `epoch` before which Redis is not tried.
    skip_until_ms: AtomicU64,
    /// Milliseconds since `epoch` of the last connection attempt.
    epoch: Instant,
    degraded: AtomicBool,
    tokens: AtomicU64,
    hits: AtomicU64,
    misses: AtomicU64,
    writes: AtomicU64,
    skipped: AtomicU64,
    errors: AtomicU64,
    timeouts: AtomicU64,
    lock_waits: AtomicU64,
    corrupt: AtomicU64,
}

impl std::fmt::Debug for RedisTier {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.debug_struct("RedisTier").field("settings", &self.settings.redacted()).finish_non_exhaustive()
    }
}

impl RedisSettings {
    /// These settings with any password in the URL replaced by `***`, for logs.
    pub(crate) fn redacted(&self) -> String {
        redact_url(&self.url)
    }
}

/// `url` with the password (between `:` and `@` after the scheme) hidden.
pub(crate) fn redact_url(url: &str) -> String {
    let Some((scheme, rest)) = url.split_once("://") else { return url.to_string() };
    let (auth, host) = match rest.rsplit_once('@') {
        Some((a, h)) => (a, h),
        None => return url.to_string(),
    };
    match auth.split_once(':') {
        Some((user, _)) => format!("{scheme}://{user}:***@{host}"),
        None => format!("{scheme}://***@{host}"),
    }
}

impl RedisTier {
    /// A tier for `settings`. Only the URL is checked here; no connection is
    /// made until the first request, so a worker starts whether or not Redis is up.
    pub fn new(settings: RedisSettings) -> Result<RedisTier, RedisError> {
        let client = ::redis::Client::open(settings.url.as_str()).map_err(|e| RedisError::Url(format!("{}: {e}", redact_url(&settings.url))))?;
        Ok(RedisTier {
            settings,
            client,
            conn: Mutex::new(None),
            skip_until_ms: AtomicU64::new(0),
            epoch: Instant::now(),
            degraded: AtomicBool::new(false),
            tokens: AtomicU64::new(0),
            hits: AtomicU64::new(0),
            misses: AtomicU64::new(0),
            writes: AtomicU64::new(0),
            skipped: AtomicU64::new(0),
            errors: AtomicU64::new(0),
            timeouts: AtomicU64::new(0),
            lock_waits: AtomicU64::new(0),
            corrupt: AtomicU64::new(0),
        })
    }

    /// The settings.
    pub fn settings(&self) -> &RedisSettings {
        &self.settings
    }

    /// Models read from Redis.
    pub fn hits(&self) -> u64 {
        self.hits.load(Ordering::Relaxed)
    }

    /// Lookups Redis answered without a (valid) model.
    pub fn misses(&self) -> u64 {
        self.misses.load(Ordering::Relaxed)
    }

    /// Models written to Redis.
    pub fn writes(&self) -> u64 {
        self.writes.load(Ordering::Relaxed)
    }

    /// Models not written: larger than the cap, or Redis skipped or failing.
    pub fn skipped(&self) -> u64 {
        self.skipped.load(Ordering::Relaxed)
    }

    /// Redis commands that failed or timed out (each one degraded a request to local caching).
    pub fn errors(&self) -> u64 {
        self.errors.load(Ordering::Relaxed)
    }

    /// Of the [`errors`](RedisTier::errors), those that were timeouts (Redis slow, not refusing).
    pub(crate) fn timeouts(&self) -> u64 {
        self.timeouts.load(Ordering::Relaxed)
    }

    /// Values that were present but did not verify (counted as misses too; never served).
    pub fn corrupt(&self) -> u64 {
        self.corrupt.load(Ordering::Relaxed)
    }

    /// Renders that waited on another worker's lock.
    pub(crate) fn lock_waits(&self) -> u64 {
        self.lock_waits.load(Ordering::Relaxed)
    }

    /// True while Redis is being skipped after a failure.
    pub(crate) fn is_degraded(&self) -> bool {
        self.degraded.load(Ordering::Relaxed)
    }

    fn now_ms(&self) -> u64 {
        u64::try_from(self.epoch.elapsed().as_millis()).unwrap_or(u64::MAX)
    }

    /// Records a failure: count it (and, if it is one, the timeout), skip
    /// Redis for a while, log once on the way down.
    fn failed(&self, what: &str, error: &str, timed_out: bool) {
        self.errors.fetch_add(1, Ordering::Relaxed);
        if timed_out {
            self.timeouts.fetch_add(1, Ordering::Relaxed);
        }
        let retry = u64::try_from(RETRY_AFTER.as_millis()).unwrap_or(1000);
        self.skip_until_ms.store(self.now_ms().saturating_add(retry), Ordering::Relaxed);
        if !self.degraded.swap(true, Ordering::Relaxed) {
            tracing::warn!(redis = %self.settings.redacted(), op = what, error, "Redis cache unavailable; caching locally only");
        }
    }

    /// Records a success: log once on the way back up.
    fn succeeded(&self) {
        if self.degraded.swap(false, Ordering::Relaxed) {
            tracing::info!(redis = %self.settings.redacted(), "Redis cache available again; sharing models");
        }
    }

    /// A connection, unless Redis is being skipped or cannot be reached in time.
    async fn connection(&self) -> Option<ConnectionManager> {
        if self.now_ms() < self.skip_until_ms.load(Ordering::Relaxed) {
            return None;
        }
        let mut slot = self.conn.lock().await;
        if let Some(c) = slot.as_ref() {
            return Some(c.clone());
        }
        // Another caller's attempt may have failed while we queued for the slot.
        if self.now_ms() < self.skip_until_ms.load(Ordering::Relaxed) {
            return None;
        }
        let t = self.settings.timeout;
        let config = ConnectionManagerConfig::new()
            .set_connection_timeout(Some(t))
            .set_response_timeout(Some(t))
            .set_number_of_retries(1)
            .set_min_delay(Duration::from_millis(10))
            .set_max_delay(Duration::from_millis(100));
        match tokio::time::timeout(t.saturating_mul(2), self.client.get_connection_manager_with_config(config)).await {
            Ok(Ok(c)) => {
                *slot = Some(c.clone());
                Some(c)
            }
            Ok(Err(e)) => {
                self.failed("connect", &e.to_string(), e.is_timeout());
                None
            }
            Err(_) => {
                self.failed("connect", "timed out", true);
                None
            }
        }
    }

    /// Runs one command under the timeout; `None` (and a recorded failure) if it fails.
    async fn run<T: ::redis::FromRedisValue>(&self, what: &str, cmd: &::redis::Cmd) -> Option<T> {
        let mut conn = self.connection().await?;
        match tokio::time::timeout(self.settings.timeout, cmd.query_async::<T>(&mut conn)).await {
            Ok(Ok(v)) => {
                self.succeeded();
                Some(v)
            }
            Ok(Err(e)) => {
                self.failed(what, &e.to_string(), e.is_timeout());
                None
            }
            Err(_) => {
                self.failed(what, "timed out", true);
                None
            }
        }
    }

    fn value_key(key: &CacheKey) -> String {
        format!("{VALUE_PREFIX}{}", key.hex())
    }

    fn lock_key(key: &CacheKey) -> String {
        format!("{LOCK_PREFIX}{}", key.hex())
    }

    /// Reads `key`'s model; `None` on a miss, an invalid value, or any failure.
    pub async fn read(&self, key: CacheKey) -> Option<Rendered> {
        let data: Option<Vec<u8>> = self.run("GET", ::redis::cmd("GET").arg(Self::value_key(&key))).await?;
        let Some(data) = data else {
            self.misses.fetch_add(1, Ordering::Relaxed);
            return None;
        };
        match super::disk::decode(&key, &data) {
            Some(r) => {
                self.hits.fetch_add(1, Ordering::Relaxed);
                Some(r)
            }
            None => {
                // Present but not verifying: a miss, never served; counted and logged.
                self.misses.fetch_add(1, Ordering::Relaxed);
                self.corrupt.fetch_add(1, Ordering::Relaxed);
                tracing::warn!(key = %key.hex(), "a Redis cache value did not verify; ignored");
                None
            }
        }
    }

    /// Stores a complete model under `key` with the TTL, unless it is over
    /// the size cap; failures are counted and logged, never returned.
    pub async fn write(&self, key: CacheKey, model: &Rendered) {
        if !model.cacheable() {
            return;
        }
        let Some(data) = super::disk::encode(&key, model).filter(|d| d.len() as u64 <= self.settings.max_value_bytes) else {
            self.skipped.fetch_add(1, Ordering::Relaxed);
            return;
        };
        let ttl = u64::try_from(self.settings.ttl.as_millis()).unwrap_or(u64::MAX).max(1);
        let mut cmd = ::redis::cmd("SET");
        cmd.arg(Self::value_key(&key)).arg(data).arg("PX").arg(ttl);
        if self.run::<()>("SET", &cmd).await.is_some() {
            self.writes.fetch_add(1, Ordering::Relaxed);
        } else {
            self.skipped.fetch_add(1, Ordering::Relaxed);
        }
    }

    /// Tries once to take `key`'s lock: `Some(true)` taken, `Some(false)` held elsewhere, `None` failed.
    async fn try_lock(&self, key: &CacheKey, token: &str, lifetime: Duration) -> Option<bool> {
        let ms = u64::try_from(lifetime.as_millis()).unwrap_or(u64::MAX).max(1);
        let mut cmd = ::redis::cmd("SET");
        cmd.arg(Self::lock_key(key)).arg(token).arg("NX").arg("PX").arg(ms);
        let r: Option<Option<String>> = self.run("SET NX", &cmd).await;
        r.map(|v| v.is_some())
    }

    /// Before rendering `key` on a miss everywhere: take the lock, or wait
    /// for the worker holding it to store the model.
    async fn claim(&self, key: &CacheKey) -> Claim {
        let Some(lifetime) = self.settings.lock else { return Claim::Alone };
        let n = self.tokens.fetch_add(1, Ordering::Relaxed);
        let token = format!("{}-{}-{n}", std::process::id(), self.now_ms());
        let deadline = Instant::now() + lifetime;
        let mut waited = false;
        loop {
            match self.try_lock(key, &token, lifetime).await {
                None => return Claim::Alone,
                Some(true) => {
                    // The previous holder may have stored the model and let go
                    // between our read and our lock.
                    if let Some(r) = self.read(*key).await {
                        self.unlock(key, &token).await;
                        return Claim::Found(r);
                    }
                    return Claim::Held(token);
                }
                Some(false) => {
                    if !waited {
                        waited = true;
                        self.lock_waits.fetch_add(1, Ordering::Relaxed);
                    }
                }
            }
            if Instant::now() >= deadline || self.is_degraded() {
                return Claim::Alone;
            }
            tokio::time::sleep(POLL).await;
            if let Some(r) = self.read(*key).await {
                return Claim::Found(r);
            }
            if self.is_degraded() {
                return Claim::Alone;
            }
        }
    }

    /// Releases `key`'s lock if it still holds `token`.
    async fn unlock(&self, key: &CacheKey, token: &str) {
        let mut cmd = ::redis::cmd("EVAL");
        cmd.arg(UNLOCK).arg(1).arg(Self::lock_key(key)).arg(token);
        let _: Option<i64> = self.run("unlock", &cmd).await;
    }

    /// The model for `key` from Redis, or from `render` (under the lock when
    /// enabled); a complete render is written back. The flag is true when
    /// the model came from Redis.
    #[cfg(test)]
    pub(crate) async fn read_or_render<E, Fut>(self: &Arc<Self>, key: CacheKey, render: impl FnOnce() -> Fut) -> Result<(Rendered, bool), E>
    where
        Fut: std::future::Future<Output = Result<Rendered, E>>,
    {
        if let Some(r) = self.read(key).await {
            return Ok((r, true));
        }
        self.render_locked(key, render).await
    }

    /// After a lookup of `key` missed: the model from `render`, under the
    /// lock when enabled (or from Redis, if the worker holding the lock
    /// stores it meanwhile: the flag is then true); a complete render is
    /// written back.
    pub(crate) async fn render_locked<E, Fut>(self: &Arc<Self>, key: CacheKey, render: impl FnOnce() -> Fut) -> Result<(Rendered, bool), E>
    where
        Fut: std::future::Future<Output = Result<Rendered, E>>,
    {
        let token = match self.claim(&key).await {
            Claim::Found(r) => return Ok((r, true)),
            Claim::Held(t) => Some(t),
            Claim::Alone => None,
        };
        // Release the lock even if this future is dropped mid-render.
        let guard = LockGuard { tier: self.clone(), key, token };
        let result = render().await;
        if let Ok(r) = &result {
            self.write(key, r).await;
        }
        guard.release().await;
        result.map(|r| (r, false))
    }
}

/// Holds a lock until released (or, if dropped first, releases it in the background).
struct LockGuard {
    tier: Arc<RedisTier>,
    key: CacheKey,
    token: Option<String>,
}

impl LockGuard {
    async fn release(mut self) {
        if let Some(t) = self.token.take() {
            self.tier.unlock(&self.key, &t).await;
        }
    }
}

impl Drop for LockGuard {
    fn drop(&mut self) {
        if let Some(t) = self.token.take() {
            let tier = self.tier.clone();
            let key = self.key;
            if let Ok(handle) = tokio::runtime::Handle::try_current() {
                handle.spawn(async move { tier.unlock(&key, &t).await });
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn urls_are_checked_and_redacted() {
        assert_eq!(redact_url("redis://user:secret@host:6379/0"), "redis://user:***@host:6379/0");
        assert_eq!(redact_url("redis://:secret@host"), "redis://:***@host");
        assert_eq!(redact_url("redis://host:6379"), "redis://host:6379");
        let settings = |url: &str| RedisSettings {
            url: url.to_string(),
            ttl: Duration::from_secs(60),
            max_value_bytes: 1 << 20,
            timeout: Duration::from_millis(100),
            lock: None,
        };
        assert!(RedisTier::new(settings("redis://127.0.0.1:1")).is_ok());
        assert!(matches!(RedisTier::new(settings("http://nope")), Err(RedisError::Url(_))));
    }

    #[tokio::test]
    async fn a_redis_that_is_not_there_is_a_miss_not_an_error() {
        // Port 1 on loopback: connection refused at once.
        let tier = Arc::new(
            RedisTier::new(RedisSettings {
                url: "redis://127.0.0.1:1".into(),
                ttl: Duration::from_secs(60),
                max_value_bytes: 1 << 20,
                timeout: Duration::from_millis(200),
                lock: Some(Duration::from_secs(5)),
            })
            .expect("valid URL"),
        );
        let key = CacheKey([7; 32]);
        assert!(tier.read(key).await.is_none());
        assert!(tier.is_degraded());
        assert_eq!(tier.errors(), 1);
        let started = Instant::now();
        let out: Result<(Rendered, bool), ()> = tier
            .read_or_render(key, || async {
                let bytes = b"solid x\nendsolid x\n".to_vec();
                Ok(Rendered {
                    etag: blake3::hash(&bytes).to_hex()[..32].to_string(),
                    bytes: bytes.into(),
                    content_type: "model/stl",
                    language: crate::lang::Language::Mdg,
                    seed: 0,
                    primitives: 1,
                    triangles: 0,
                    truncated: None,
                    print: None,
                })
            })
            .await;
        assert!(matches!(out, Ok((_, false))));
        assert!(started.elapsed() < Duration::from_millis(100), "a degraded tier is skipped, not retried per call");
        assert_eq!(tier.errors(), 1);
    }
}
