//! The direct model route (issue 33): `GET /v1/models/{file}` answered in
//! front of the axum router by the router's own pieces, called in a row.
//!
//! Why: a fresh `gem.glb` spent about 7 µs of its CPU in the router's
//! machinery around the handler, not in the handler: four `from_fn`
//! middlewares that each box their future and clone the route service,
//! tower's `Oneshot` and `MapFuture` wrappers, the path match and the
//! extractors, about forty allocations a request (issue 33's profiles).
//! The model route is the one the load is on, and its layers do little for
//! it, so it gets a direct way through them.
//!
//! How it stays the router's answer:
//! - **The same code, not a copy.** The handler's work is
//!   [`super::http::model_for`], which the router's `model_get` calls too;
//!   access is [`super::access::Access::admit`] as the `access` middleware
//!   calls it; compression is [`super::http::compression`], the router's
//!   layer itself, applied to the request; the ETag of a compressed body is
//!   [`super::http::tag_encoded_etag`]; counting, the access line and the
//!   request id are [`super::http::observed`], `observe`'s own tail. The
//!   order is the router's: observe, ETag, compression, access, handler.
//! - **Only where the two cannot differ.** A request goes to the router,
//!   untouched, unless it is a `GET` of `/v1/models/FILE` with FILE a
//!   non-empty segment without `%` (so axum's percent-decoding would leave
//!   it as it is) and no body, while no span is made (spans not exported,
//!   DEBUG lines off: `observe` would make one), with no CORS policy (its
//!   layer sits outside the others), and when its caller is admitted (a
//!   refusal is the router's to answer and count).
//! - **Tested against the router** (`tests/it/service/direct.rs`): the same
//!   request spelled with a `%`-escape takes the router, and the two answers
//!   are the same on the wire (status, every header in order, body), for
//!   fresh renders, hits, 304s, errors, compressed errors and phones.

use super::http::{compression, model_for, observed, tag_encoded_etag, Caller, MODELS_ROUTE};
use super::AppState;
use axum::body::{Body, HttpBody};
use axum::http::{header, Method, Request};
use axum::response::Response;
use std::convert::Infallible;
use std::sync::Arc;
use std::time::Instant;
use tower::{Layer, ServiceExt};

/// The path prefix of the model route.
const PREFIX: &str = "/v1/models/";

/// Answers `req` when it is a model `GET` the direct route takes (see the
/// module documentation); otherwise hands it back untouched for the router.
pub(crate) async fn answer<B>(state: &Arc<AppState>, req: Request<B>) -> Result<Response, Request<B>>
where
    B: HttpBody + Send + 'static,
{
    if !takes(state, &req) {
        return Err(req);
    }
    let key = super::access::presented_key(|n| req.headers().get(n).and_then(|v| v.to_str().ok()));
    let Ok(admission) = state.access.admit(key, &state.ceiling) else { return Err(req) };
    let caller = Caller { ceiling: admission.ceiling };
    let id = super::http::next_request_id();
    let started = Instant::now();
    let handler = tower::service_fn(|req: Request<B>| async move {
        let file = req.uri().path().strip_prefix(PREFIX).unwrap_or_default();
        let resp = model_for(state, &caller, file, req.uri().query(), req.headers()).await;
        Ok::<_, Infallible>(resp)
    });
    let mut resp = match compression().layer(handler).oneshot(req).await {
        Ok(resp) => resp.map(Body::new),
        Err(never) => match never {},
    };
    drop(admission);
    state.metrics.direct_model_request();
    tag_encoded_etag(&mut resp);
    observed(state, id, Method::GET.as_str(), MODELS_ROUTE, started.elapsed(), &mut resp, &tracing::Span::none());
    Ok(resp)
}

/// Whether the direct route may answer `req` (everything but admission).
fn takes<B: HttpBody>(state: &AppState, req: &Request<B>) -> bool {
    let Some(file) = req.uri().path().strip_prefix(PREFIX) else { return false };
    req.method() == Method::GET
        && !file.is_empty()
        && !file.contains(['/', '%'])
        && req.body().is_end_stream()
        && !req.headers().contains_key(header::TRANSFER_ENCODING)
        && !super::telemetry::tracing_on()
        && !super::access_log::detail_enabled()
        && state.config.cors_origins.is_empty()
}
