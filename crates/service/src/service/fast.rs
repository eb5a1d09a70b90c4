//! The cached-GET fast path (issue 33): a repeated `GET /v1/models/…` whose
//! model the in-process cache holds is answered in front of the axum router,
//! with the very response the router gave it last time.
//!
//! Why: a cached GET spent most of its CPU around the model, not on it. The
//! profile of issue 33's session 21 had 43 % in the kernel's send, about
//! 17 % in the router's four `from_fn` middlewares (each boxes its future
//! and clones the request's parts), 16 % in the handler (the query parsed
//! into options, the options planned and validated, a BLAKE3 cache key over
//! the grammar's source) and 6 % in hyper's head writing: rulemesh spent
//! 37.7 µs of CPU per cached 12 KB `gem.glb`, nginx 24.4 µs for the same
//! bytes as a static file. All of that work repeats the last request's.
//!
//! How it stays exact:
//! - **Keyed by every input the response reads.** The request target (path
//!   and query, byte for byte), whether the caller is a phone
//!   ([`super::phone::is_phone`], which changes glTF's instancing), and the
//!   `Accept-Encoding` and `Origin` headers (compression and CORS read them).
//!   `If-None-Match` selects the entry's 200 or its 304 (the handler's own
//!   [`super::http::etag_matches`] against the model's ETag). A request
//!   asking for a fresh render (`Cache-Control`/`Pragma: no-cache`), with a
//!   body, repeated `Accept-Encoding` or `Origin` headers, or not HTTP/1.1
//!   always takes the router. So does every request while spans are
//!   exported (each request is a span of its trace). With API keys, the
//!   key's digest is part of the entry's key (its ceiling plans its
//!   requests), and every fast answer is admitted first as the router's
//!   `access` admits (key, rate, concurrency share); a refusal goes to the
//!   router, which answers and counts it.
//! - **Filled only by the router's own answer.** An entry is the response
//!   the router gave to the same key (status, every header in its order),
//!   kept only when the handler marked it [`Fillable`] and it was a hit of
//!   the in-process cache tier: so the entry is what the router would say
//!   again. Its per-request headers are made afresh on every answer: a new
//!   `x-request-id` and the `Server-Timing` of this request's own lookup
//!   (hyper adds `date`). Errors, renders, truncated models, other tiers'
//!   hits and compressed bodies are never kept.
//! - **Never staler than the cache.** Every answer first asks the model
//!   cache for the entry's cache key (which holds the engine version, the
//!   source and every option), and answers only if the cache still holds
//!   the very model the entry was made from (the same `Arc`); otherwise the
//!   entry is dropped and the router answers. Clearing or evicting a model
//!   ends its fast answers, and the lookup keeps the model hot in the
//!   table's eviction policy, as the router's lookup would.
//! - **Counted and logged like the router's answers.** `/metrics` counts
//!   the request (route, status, latency), the response bytes, the cache
//!   hit and the memory-tier lookup, plus `rulemesh_fast_path_hits_total`;
//!   the access log writes the same short line under `--access-log`. While
//!   DEBUG lines are on (which carry the request's span), the router answers.
//! - **Bounded.** At most [`MAX_ENTRIES`] entries of keys up to
//!   [`MAX_TARGET`] bytes; an entry holds its response headers (a 200's and
//!   a 304's, each about a kilobyte) and a weak reference to the model, so
//!   it never keeps model bytes the cache has let go.

use super::access_log::{log_request, Finished};
use super::timing::RequestTiming;
use super::AppState;
use crate::cache::{CacheKey, CacheOutcome, Lookup, Rendered, Tier};
use crate::export::Format;
use axum::body::{Body, HttpBody};
use axum::http::{header, HeaderMap, HeaderValue, Method, Request, Response, StatusCode, Version};
use std::collections::HashMap;
use std::hash::{BuildHasher, RandomState};
use std::sync::{Arc, Mutex, Weak};
use std::time::Instant;

/// Most entries held (a full map drops an arbitrary entry for a new one).
pub(crate) const MAX_ENTRIES: usize = 1024;
/// Most bytes of a kept key: the request target (path and query) with its
/// `Accept-Encoding` and `Origin` values.
pub(crate) const MAX_TARGET: usize = 2048;

/// Marks a model response the fast path may keep: the plan's cache key, the
/// model, its format and the route, as the handler knew them.
#[derive(Debug, Clone)]
pub(crate) struct Fillable {
    /// The cache key the handler planned.
    pub key: CacheKey,
    /// The model served.
    pub model: Arc<Rendered>,
    /// Its format (for the bytes metric).
    pub format: Format,
    /// The matched route (for the request metric and the log line).
    pub route: &'static str,
}

/// The inputs of a response, borrowed from a request (no `Debug`: it holds
/// the API key presented).
#[derive(Clone, Copy)]
pub(crate) struct Probe<'a> {
    hash: u64,
    target: &'a str,
    phone: bool,
    accept_encoding: Option<&'a [u8]>,
    origin: Option<&'a [u8]>,
    /// The API key presented, when keys are configured (for admission).
    presented: Option<&'a str>,
    /// Its digest (the entry's owner).
    caller: Option<[u8; 32]>,
}

/// The inputs of a response, owned (kept from a request the router answers).
#[derive(Debug, PartialEq, Eq)]
pub(crate) struct Target {
    hash: u64,
    target: Box<str>,
    phone: bool,
    accept_encoding: Option<Box<[u8]>>,
    origin: Option<Box<[u8]>>,
    caller: Option<[u8; 32]>,
}

impl Probe<'_> {
    /// The owned copy, for [`Answers::offer`].
    pub(crate) fn to_target(self) -> Target {
        Target {
            hash: self.hash,
            target: self.target.into(),
            phone: self.phone,
            accept_encoding: self.accept_encoding.map(Into::into),
            origin: self.origin.map(Into::into),
            caller: self.caller,
        }
    }

    fn is(&self, t: &Target) -> bool {
        *self.target == *t.target
            && self.phone == t.phone
            && self.accept_encoding == t.accept_encoding.as_deref()
            && self.origin == t.origin.as_deref()
            && self.caller == t.caller
    }
}

/// One kept response: its headers in the router's order (status implied by the slot).
#[derive(Debug, Clone)]
struct Kept {
    headers: HeaderMap,
}

/// One target's kept answers.
#[derive(Debug)]
struct Entry {
    target: Target,
    key: CacheKey,
    model: Weak<Rendered>,
    etag: String,
    format: Format,
    route: &'static str,
    ok: Option<Kept>,
    not_modified: Option<Kept>,
}

/// What an answer needs from its entry, copied out under the lock.
struct Chosen {
    key: CacheKey,
    model: Weak<Rendered>,
    format: Format,
    route: &'static str,
    kept: Kept,
    modified: bool,
}

/// The fast path's map of ready answers (one per [`AppState`]).
#[derive(Debug, Default)]
pub struct Answers {
    hasher: RandomState,
    entries: Mutex<HashMap<u64, Entry>>,
}

impl Answers {
    /// The request's inputs when it may be answered here (see the module
    /// documentation for what is refused); `None` sends it to the router.
    pub(crate) fn probe<'a, B: HttpBody>(&self, state: &AppState, req: &'a Request<B>) -> Option<Probe<'a>> {
        if req.method() != Method::GET || req.version() != Version::HTTP_11 || !req.uri().path().starts_with("/v1/models/") {
            return None;
        }
        let target = req.uri().path_and_query()?.as_str();
        let h = req.headers();
        if target.len() > MAX_TARGET || !req.body().is_end_stream() || h.contains_key(header::TRANSFER_ENCODING) || super::http::wants_fresh(h) {
            return None;
        }
        if super::telemetry::tracing_on() || super::access_log::detail_enabled() {
            return None;
        }
        // With API keys, each key has its own entries (its ceiling plans its
        // requests), named by the key's digest, never by the secret itself.
        let presented = match state.access.enabled() {
            true => Some(super::access::presented_key(|n| h.get(n).and_then(|v| v.to_str().ok()))?),
            false => None,
        };
        let caller = presented.map(|k| *blake3::hash(k.as_bytes()).as_bytes());
        let accept_encoding = single(h, header::ACCEPT_ENCODING)?;
        let origin = single(h, header::ORIGIN)?;
        // The whole key is bounded, not only the target: hyper admits header values of hundreds of KB.
        if target.len() + accept_encoding.map_or(0, <[u8]>::len) + origin.map_or(0, <[u8]>::len) > MAX_TARGET {
            return None;
        }
        let phone = super::phone::is_phone(h);
        let hash = self.hasher.hash_one((target, phone, accept_encoding, origin, caller));
        Some(Probe { hash, target, phone, accept_encoding, origin, presented, caller })
    }

    /// Answers `req` from its entry when the cache still holds the entry's
    /// model, counting and logging it; `None` when the router must answer.
    pub(crate) async fn answer(&self, state: &AppState, probe: &Probe<'_>, headers: &HeaderMap) -> Option<Response<Body>> {
        let started = Instant::now();
        let chosen = self.choose(probe, headers)?;
        let model = chosen.model.upgrade();
        let (held, took) = state.engine.cache().memory_peek(&chosen.key);
        let model = match (model, held) {
            (Some(m), Some(h)) if Arc::ptr_eq(&m, &h) => m,
            _ => {
                self.forget(probe);
                return None;
            }
        };
        // Admitted as the router's `access` would (key, rate, share), held
        // until the response is made; a refusal is the router's to answer and count.
        let admission = match state.access.enabled() {
            true => Some(state.access.admit(probe.presented, &state.ceiling).ok()?),
            false => None,
        };
        state.engine.cache().observe_memory_hit(took);
        let timing = RequestTiming { lookup: Lookup { outcome: CacheOutcome::Hit, tier: Some(Tier::Memory), took }, ran: None };
        let id = super::http::next_request_id();
        let mut h = chosen.kept.headers;
        // `insert` keeps a header's place, so the order is the router's.
        h.insert(super::header_names::SERVER_TIMING, HeaderValue::from_str(&timing.header_value()).unwrap_or_else(|_| HeaderValue::from_static("invalid")));
        h.insert(super::header_names::X_REQUEST_ID, HeaderValue::from(id));
        let (status, body, bytes) = match chosen.modified {
            true => (StatusCode::OK, Body::from(model.bytes.clone()), model.bytes.len()),
            false => (StatusCode::NOT_MODIFIED, Body::empty(), 0),
        };
        let mut resp = Response::new(body);
        *resp.status_mut() = status;
        *resp.headers_mut() = h;
        resp.extensions_mut().insert(timing);
        let wall = started.elapsed();
        let m = &state.metrics;
        m.request("http", chosen.route, status.as_u16(), wall);
        if chosen.modified {
            m.bytes_out("http", chosen.format, bytes);
        }
        m.cache(true);
        m.fast_path_hit();
        let etag = resp.headers().get(header::ETAG).and_then(|v| v.to_str().ok());
        let finished =
            Finished { id, method: "GET", route: chosen.route, status: Some(status.as_u16()), code: None, wall, bytes: Some(bytes as u64), etag, timing: Some(&timing) };
        log_request(&finished, &tracing::Span::none());
        drop(admission);
        Some(resp)
    }

    /// The kept answer for `probe` (its 200, or its 304 when `If-None-Match`
    /// names the model), copied out of the map.
    fn choose(&self, probe: &Probe<'_>, headers: &HeaderMap) -> Option<Chosen> {
        let entries = self.entries.lock().ok()?;
        let e = entries.get(&probe.hash).filter(|e| probe.is(&e.target))?;
        let modified = !super::http::etag_matches(headers, &e.etag);
        let kept = if modified { e.ok.clone()? } else { e.not_modified.clone()? };
        Some(Chosen { key: e.key, model: e.model.clone(), format: e.format, route: e.route, kept, modified })
    }

    fn forget(&self, probe: &Probe<'_>) {
        if let Ok(mut entries) = self.entries.lock() {
            if entries.get(&probe.hash).is_some_and(|e| probe.is(&e.target)) {
                entries.remove(&probe.hash);
            }
        }
    }

    /// Keeps the router's response `resp` to `target` when it may be
    /// answered again as it is (see the module documentation).
    pub(crate) fn offer(&self, target: Target, resp: &Response<Body>) {
        let Some(fill) = resp.extensions().get::<Fillable>() else { return };
        let memory_hit = resp
            .extensions()
            .get::<RequestTiming>()
            .is_some_and(|t| t.lookup.outcome == CacheOutcome::Hit && t.lookup.tier == Some(Tier::Memory) && t.ran.is_none());
        let status = resp.status();
        let whole = match status {
            StatusCode::OK => resp.body().size_hint().exact() == Some(fill.model.bytes.len() as u64),
            StatusCode::NOT_MODIFIED => true,
            _ => false,
        };
        if !memory_hit || !whole || resp.headers().contains_key(header::CONTENT_ENCODING) || !fill.model.cacheable() {
            return;
        }
        let Ok(mut entries) = self.entries.lock() else { return };
        let hash = target.hash;
        let same = entries.get(&hash).is_some_and(|e| e.target == target && e.key == fill.key && Weak::as_ptr(&e.model) == Arc::as_ptr(&fill.model));
        if !same {
            if entries.len() >= MAX_ENTRIES && !entries.contains_key(&hash) {
                let victim = entries.keys().next().copied();
                if let Some(v) = victim {
                    entries.remove(&v);
                }
            }
            let entry = Entry {
                target,
                key: fill.key,
                model: Arc::downgrade(&fill.model),
                etag: fill.model.etag.clone(),
                format: fill.format,
                route: fill.route,
                ok: None,
                not_modified: None,
            };
            entries.insert(hash, entry);
        }
        let Some(e) = entries.get_mut(&hash) else { return };
        let kept = Some(Kept { headers: resp.headers().clone() });
        if status == StatusCode::OK {
            e.ok = kept;
        } else {
            e.not_modified = kept;
        }
    }

    /// Entries held now (for tests and the metrics).
    pub fn len(&self) -> usize {
        self.entries.lock().map_or(0, |e| e.len())
    }

    /// Whether no entry is held.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
}

/// The value of header `name` when it appears at most once (`Some(None)`
/// when absent); `None` when repeated (the router answers those).
fn single(h: &HeaderMap, name: header::HeaderName) -> Option<Option<&[u8]>> {
    let mut all = h.get_all(name).iter();
    let first = all.next();
    match all.next() {
        Some(_) => None,
        None => Some(first.map(HeaderValue::as_bytes)),
    }
}
