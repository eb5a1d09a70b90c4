//! Access control: optional API keys, each with its own request rate,
//! concurrency share and limit ceilings, checked the same way for HTTP
//! (`Authorization: Bearer KEY` or `X-Api-Key: KEY`) and gRPC (the same
//! names as metadata).
//!
//! With no key configured the service is open, as before. With keys, every
//! `/v1/…` route and every `rulemesh.v1.Rulemesh` method needs one; probes,
//! `/metrics` and `/openapi.json` stay open so that load balancers and
//! Prometheus need no secret.
//!
//! Rates are a token bucket per key, written out here instead of taken from
//! `governor`: a bucket is a dozen lines under one mutex, and owning it lets
//! the 429 carry the exact `Retry-After` the bucket implies, without another
//! dependency tree in the service.

use super::ServiceError;
use crate::core::Limits;
use serde::{Deserialize, Serialize};
use std::collections::HashMap;
use std::sync::{Arc, Mutex};
use std::time::Instant;
use tokio::sync::{OwnedSemaphorePermit, Semaphore};

/// One API key as configured (a `[[api_keys]]` table in the config file, or
/// one object of the JSON array in `RULEMESH_API_KEYS`).
#[derive(Debug, Clone, PartialEq, Deserialize, Serialize)]
#[serde(deny_unknown_fields)]
pub struct ApiKeySpec {
    /// A label for logs and metrics (never the secret itself).
    pub name: String,
    /// The secret the client presents. Never serialised (the printed
    /// configuration shows `***`).
    #[serde(serialize_with = "redacted")]
    pub key: String,
    /// Sustained requests per second; absent: no rate limit.
    pub rate_per_sec: Option<f64>,
    /// Requests that may arrive at once after a quiet spell (the bucket
    /// size); default: the rate rounded up, at least 1.
    pub burst: Option<u32>,
    /// Requests of this key in flight at once; more get 429. Absent: no share.
    pub max_concurrency: Option<usize>,
    /// Ceiling on this key's `max_primitives` (never above the server's).
    pub ceiling_primitives: Option<u64>,
    /// Ceiling on this key's `max_triangles`.
    pub ceiling_triangles: Option<u64>,
    /// Ceiling on this key's `max_memory`, in bytes.
    pub ceiling_memory: Option<u64>,
    /// Ceiling on this key's `timeout_ms`.
    pub ceiling_timeout_ms: Option<u64>,
    /// Ceiling on this key's `max_steps`.
    pub ceiling_steps: Option<u64>,
}

impl ApiKeySpec {
    /// The key `key` named `name`, with no rate, share or ceilings of its
    /// own (the server's apply); set those with struct update syntax.
    pub fn new(name: impl Into<String>, key: impl Into<String>) -> ApiKeySpec {
        ApiKeySpec {
            name: name.into(),
            key: key.into(),
            rate_per_sec: None,
            burst: None,
            max_concurrency: None,
            ceiling_primitives: None,
            ceiling_triangles: None,
            ceiling_memory: None,
            ceiling_timeout_ms: None,
            ceiling_steps: None,
        }
    }
}

fn redacted<S: serde::Serializer>(_: &str, s: S) -> Result<S::Ok, S::Error> {
    s.serialize_str("***")
}

/// Every configured key; empty means the service is open.
#[derive(Debug, Clone, Default, PartialEq, Deserialize, Serialize)]
#[serde(transparent)]
pub struct ApiKeys(pub Vec<ApiKeySpec>);

impl ApiKeys {
    /// Reads `RULEMESH_API_KEYS` / `--api-keys`: a JSON array of key objects
    /// (the same fields as the file's tables); empty text means no keys.
    pub fn parse(text: &str) -> Result<ApiKeys, String> {
        if text.trim().is_empty() {
            return Ok(ApiKeys::default());
        }
        let keys: ApiKeys = serde_json::from_str(text).map_err(|e| format!("API keys: expected a JSON array of key objects: {e}"))?;
        keys.validate()?;
        Ok(keys)
    }

    /// Rejects empty or duplicate secrets and rates that are not positive.
    pub fn validate(&self) -> Result<(), String> {
        let mut seen = std::collections::HashSet::new();
        for k in &self.0 {
            if k.key.is_empty() {
                return Err(format!("API key `{}`: empty key", k.name));
            }
            if !seen.insert(&k.key) {
                return Err(format!("API key `{}`: the same key is configured twice", k.name));
            }
            if let Some(r) = k.rate_per_sec {
                if !(r.is_finite() && r > 0.0) {
                    return Err(format!("API key `{}`: rate_per_sec must be a positive number", k.name));
                }
            }
            if k.max_concurrency == Some(0) || k.burst == Some(0) {
                return Err(format!("API key `{}`: max_concurrency and burst must be at least 1", k.name));
            }
        }
        Ok(())
    }
}

/// A token bucket: `rate` tokens a second up to `capacity`.
#[derive(Debug)]
struct Bucket {
    rate: f64,
    capacity: f64,
    tokens: f64,
    last: Instant,
}

impl Bucket {
    fn new(rate: f64, capacity: f64) -> Bucket {
        Bucket { rate, capacity, tokens: capacity, last: Instant::now() }
    }

    /// Takes a token, or says in how many whole seconds one will be there.
    fn take(&mut self, now: Instant) -> Result<(), u64> {
        let dt = now.saturating_duration_since(self.last).as_secs_f64();
        self.last = now;
        self.tokens = (self.tokens + dt * self.rate).min(self.capacity);
        if self.tokens >= 1.0 {
            self.tokens -= 1.0;
            Ok(())
        } else {
            let wait = (1.0 - self.tokens) / self.rate;
            // At least one second: Retry-After is in whole seconds.
            Err((wait.ceil() as u64).max(1))
        }
    }
}

/// A key's live state.
#[derive(Debug)]
struct KeyState {
    name: String,
    ceiling: Limits,
    bucket: Option<Mutex<Bucket>>,
    slots: Option<Arc<Semaphore>>,
    max_concurrency: usize,
}

/// A request let in: the ceiling its limits are clamped to, and its share
/// of the key's concurrency (released when this is dropped).
#[derive(Debug)]
pub struct Admission {
    /// The ceiling for this caller: the server's, lowered by the key's.
    pub ceiling: Limits,
    /// The key's name, when keys are configured.
    pub key_name: Option<String>,
    _slot: Option<OwnedSemaphorePermit>,
}

/// The key table, built once at startup.
#[derive(Debug, Default)]
pub struct Access {
    keys: HashMap<[u8; 32], KeyState>,
}

/// The 32-byte digest a key is looked up by, so the table holds no secret
/// and the lookup compares digests, not the secret's bytes one by one.
fn digest(key: &str) -> [u8; 32] {
    *blake3::hash(key.as_bytes()).as_bytes()
}

impl Access {
    /// The table for `keys`, each ceiling clamped to `server_ceiling`.
    pub fn new(keys: &ApiKeys, server_ceiling: &Limits) -> Access {
        let keys = keys
            .0
            .iter()
            .map(|k| {
                let c = server_ceiling;
                let ceiling = Limits {
                    max_primitives: k.ceiling_primitives.unwrap_or(c.max_primitives),
                    max_triangles: k.ceiling_triangles.unwrap_or(c.max_triangles),
                    max_memory: k.ceiling_memory.unwrap_or(c.max_memory),
                    timeout_ms: k.ceiling_timeout_ms.unwrap_or(c.timeout_ms),
                    max_steps: k.ceiling_steps.unwrap_or(c.max_steps),
                    ..*c
                }
                .clamped_to(c);
                let bucket = k.rate_per_sec.map(|rate| {
                    let burst = k.burst.map_or_else(|| rate.ceil().max(1.0), f64::from);
                    Mutex::new(Bucket::new(rate, burst))
                });
                let state = KeyState {
                    name: k.name.clone(),
                    ceiling,
                    bucket,
                    slots: k.max_concurrency.map(|n| Arc::new(Semaphore::new(n))),
                    max_concurrency: k.max_concurrency.unwrap_or(0),
                };
                (digest(&k.key), state)
            })
            .collect();
        Access { keys }
    }

    /// Whether requests need a key.
    pub fn enabled(&self) -> bool {
        !self.keys.is_empty()
    }

    /// Lets a request in or says why not: 401 without a known key (when keys
    /// are configured), 429 over the key's concurrency share or rate.
    pub fn admit(&self, presented: Option<&str>, server_ceiling: &Limits) -> Result<Admission, ServiceError> {
        if !self.enabled() {
            return Ok(Admission { ceiling: *server_ceiling, key_name: None, _slot: None });
        }
        let state = presented.and_then(|k| self.keys.get(&digest(k))).ok_or(ServiceError::Unauthorized)?;
        let slot = match &state.slots {
            Some(s) => Some(s.clone().try_acquire_owned().map_err(|_| ServiceError::RateLimited {
                reason: format!("API key `{}` has {} requests in flight, its share", state.name, state.max_concurrency),
                retry_after_secs: 1,
            })?),
            None => None,
        };
        if let Some(b) = &state.bucket {
            let mut b = b.lock().map_err(|_| ServiceError::Internal("rate limiter lock poisoned".into()))?;
            b.take(Instant::now()).map_err(|secs| ServiceError::RateLimited {
                reason: format!("API key `{}` is over its rate of {} requests a second", state.name, b.rate),
                retry_after_secs: secs,
            })?;
        }
        Ok(Admission { ceiling: state.ceiling, key_name: Some(state.name.clone()), _slot: slot })
    }
}

/// The key a request presents: `Authorization: Bearer KEY`, else `X-Api-Key: KEY`.
/// `get` reads a header (HTTP) or metadata entry (gRPC) by lowercase name.
pub(crate) fn presented_key<'a>(get: impl Fn(&str) -> Option<&'a str>) -> Option<&'a str> {
    let bearer = get("authorization").and_then(|v| {
        let (scheme, token) = v.trim().split_once(' ')?;
        scheme.eq_ignore_ascii_case("bearer").then(|| token.trim())
    });
    bearer.or_else(|| get("x-api-key").map(str::trim))
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::time::Duration;

    fn spec(key: &str) -> ApiKeySpec {
        ApiKeySpec::new(format!("n-{key}"), key)
    }

    #[test]
    fn bucket_refills_at_its_rate() {
        let t0 = Instant::now();
        let mut b = Bucket::new(2.0, 2.0);
        assert_eq!((b.take(t0), b.take(t0), b.take(t0)), (Ok(()), Ok(()), Err(1)));
        assert_eq!(b.take(t0 + Duration::from_millis(500)), Ok(()));
        let mut slow = Bucket::new(0.1, 1.0);
        assert_eq!((slow.take(t0), slow.take(t0)), (Ok(()), Err(10)));
    }

    #[test]
    fn keys_concurrency_and_ceilings() {
        let server = Limits::ceiling();
        let a = Access::new(&ApiKeys(vec![]), &server);
        assert!(a.admit(None, &server).is_ok());
        let keys = ApiKeys(vec![ApiKeySpec { max_concurrency: Some(1), ceiling_primitives: Some(10), ..spec("k1") }]);
        let a = Access::new(&keys, &server);
        assert!(matches!(a.admit(None, &server), Err(ServiceError::Unauthorized)));
        assert!(matches!(a.admit(Some("k2"), &server), Err(ServiceError::Unauthorized)));
        let first = a.admit(Some("k1"), &server).expect("admitted");
        assert_eq!(first.ceiling.max_primitives, 10);
        assert!(matches!(a.admit(Some("k1"), &server), Err(ServiceError::RateLimited { retry_after_secs: 1, .. })));
        drop(first);
        assert!(a.admit(Some("k1"), &server).is_ok());
    }

    #[test]
    fn parse_validates_and_the_header_forms_are_read() {
        assert_eq!(ApiKeys::parse(" "), Ok(ApiKeys::default()));
        let k = ApiKeys::parse(r#"[{"name":"a","key":"s","rate_per_sec":5}]"#).expect("parses");
        assert_eq!(k.0[0].rate_per_sec, Some(5.0));
        assert!(ApiKeys::parse(r#"[{"name":"a","key":""}]"#).is_err());
        assert!(ApiKeys::parse(r#"[{"name":"a","key":"s"},{"name":"b","key":"s"}]"#).is_err());
        assert!(ApiKeys::parse(r#"[{"name":"a","key":"s","rate_per_sec":0}]"#).is_err());
        assert!(ApiKeys::parse(r#"[{"name":"a","key":"s","secret":1}]"#).is_err());
        assert_eq!(serde_json::to_value(&k).expect("json")[0]["key"], "***");
        let h = |pairs: &'static [(&'static str, &'static str)]| move |n: &str| pairs.iter().find(|p| p.0 == n).map(|p| p.1);
        assert_eq!(presented_key(h(&[("authorization", "Bearer  abc ")])), Some("abc"));
        assert_eq!(presented_key(h(&[("x-api-key", "xyz")])), Some("xyz"));
        assert_eq!(presented_key(h(&[("authorization", "Basic abc")])), None);
    }
}
