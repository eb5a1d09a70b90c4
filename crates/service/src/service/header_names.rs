//! The names of rulemesh's own response headers, made once.
//!
//! Why: `HeaderMap::insert("x-rulemesh-seed", …)` parses the name on every
//! call and, for a name the `http` crate does not know, copies it into a
//! fresh allocation. A model response sets seven such headers, so issue 33's
//! allocation profile of a fresh `gem.glb` counted five allocations a
//! request for names alone. `HeaderName::from_static` is a `const fn` that
//! keeps the `'static` text, so these constants cost nothing per request.

use axum::http::HeaderName;

/// `Server-Timing`: where the request's time went (queue, stages, cache lookup).
pub(crate) const SERVER_TIMING: HeaderName = HeaderName::from_static("server-timing");
/// `X-Request-Id`: the request's id in this process (as in its log line).
pub(crate) const X_REQUEST_ID: HeaderName = HeaderName::from_static("x-request-id");
/// `X-Rulemesh-Cache`: `hit` or `miss`.
pub(crate) const X_CACHE: HeaderName = HeaderName::from_static("x-rulemesh-cache");
/// `X-Rulemesh-Seed`: the seed the model was made with.
pub(crate) const X_SEED: HeaderName = HeaderName::from_static("x-rulemesh-seed");
/// `X-Rulemesh-Variation`: a Context Free design's variation code.
pub(crate) const X_VARIATION: HeaderName = HeaderName::from_static("x-rulemesh-variation");
/// `X-Rulemesh-Primitives`: primitive instances in the model.
pub(crate) const X_PRIMITIVES: HeaderName = HeaderName::from_static("x-rulemesh-primitives");
/// `X-Rulemesh-Triangles`: triangles in the model.
pub(crate) const X_TRIANGLES: HeaderName = HeaderName::from_static("x-rulemesh-triangles");
/// `X-Rulemesh-Truncated`: whether a limit cut the model short.
pub(crate) const X_TRUNCATED: HeaderName = HeaderName::from_static("x-rulemesh-truncated");
/// `X-Rulemesh-Truncated-Limit`: the limit that did.
pub(crate) const X_TRUNCATED_LIMIT: HeaderName = HeaderName::from_static("x-rulemesh-truncated-limit");
/// `X-Rulemesh-Truncated-Configured`: that limit's configured value.
pub(crate) const X_TRUNCATED_CONFIGURED: HeaderName = HeaderName::from_static("x-rulemesh-truncated-configured");
/// `X-Rulemesh-Truncated-Reached`: the value it reached.
pub(crate) const X_TRUNCATED_REACHED: HeaderName = HeaderName::from_static("x-rulemesh-truncated-reached");
