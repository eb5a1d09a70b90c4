//! The HTTP API through the real router (body limit, JSON body parsing,
//! query-string parsing, validation, the engine) on arbitrary requests. The
//! first byte picks the route; for `GET /v1/models/…` the rest is the path
//! and query, else it is the body. No request may get a 500.
#![no_main]
use axum::body::Body;
use axum::http::{Method, Request};
use libfuzzer_sys::fuzz_target;
use rulemesh::service::{AppState, ServeConfig};
use std::sync::{Arc, OnceLock};
use tower::ServiceExt as _;

fn runtime_and_router() -> &'static (tokio::runtime::Runtime, axum::Router) {
    static ONCE: OnceLock<(tokio::runtime::Runtime, axum::Router)> = OnceLock::new();
    ONCE.get_or_init(|| {
        let rt = tokio::runtime::Builder::new_current_thread().enable_all().build().expect("runtime");
        let limits = rulemesh_fuzz::tight_limits();
        let config = ServeConfig {
            body_limit: 64 * 1024,
            cache_bytes: 4 * 1024 * 1024,
            max_concurrency: 1,
            ceiling_primitives: limits.max_primitives,
            ceiling_triangles: limits.max_triangles,
            ceiling_memory: limits.max_memory,
            ceiling_timeout_ms: limits.timeout_ms,
            ..ServeConfig::default()
        };
        let state = Arc::new(AppState::new(config).expect("state"));
        let router = rulemesh::service::http::router(state);
        (rt, router)
    })
}

fuzz_target!(|data: &[u8]| {
    let Some((&route, rest)) = data.split_first() else { return };
    let (rt, router) = runtime_and_router();
    let request = match route % 3 {
        0 => Request::builder().method(Method::POST).uri("/v1/render").body(Body::from(rest.to_vec())),
        1 => Request::builder().method(Method::POST).uri("/v1/check").body(Body::from(rest.to_vec())),
        _ => {
            let Ok(tail) = std::str::from_utf8(rest) else { return };
            Request::builder().method(Method::GET).uri(format!("/v1/models/{tail}")).body(Body::empty())
        }
    };
    // A URI the http crate refuses never reaches the server.
    let Ok(request) = request else { return };
    let response = rt.block_on(router.clone().oneshot(request)).expect("infallible");
    assert_ne!(response.status().as_u16(), 500, "an internal error for {request_kind}", request_kind = route % 3);
});
