//! The HTTP API (axum): JSON in, model bytes out.

use super::library::{self, GrammarInfo};
use super::request::{from_json, parse_format, CheckBody, RenderBody};
use super::{AppState, Served, ServiceError};
use crate::cache::CacheOutcome;
use crate::eval::{Limits, ParamValue};
use crate::lang::{Diagnostic, Severity};
use axum::body::{Body, Bytes};
use axum::extract::rejection::BytesRejection;
use axum::extract::{DefaultBodyLimit, MatchedPath, Path, RawQuery, Request, State};
use axum::http::{header, HeaderMap, HeaderValue, StatusCode};
use axum::middleware::{self, Next};
use axum::response::{IntoResponse, Response};
use axum::routing::{get, post};
use axum::{Json, Router};
use serde::Serialize;
use std::sync::atomic::{AtomicU64, Ordering};
use std::sync::Arc;
use std::time::Instant;
use tracing::Instrument;

/// `Cache-Control` of a model whose every input is pinned by its URL.
pub const CACHE_IMMUTABLE: &str = "public, max-age=31536000, immutable";
/// `Cache-Control` of a model whose seed is not pinned by its URL.
pub const CACHE_SHORT: &str = "public, max-age=300";

/// The HTTP router with every route, the body limit and request metrics.
pub fn router(state: Arc<AppState>) -> Router {
    Router::new()
        .route("/v1/render", post(render_post))
        .route("/v1/models/{file}", get(model_get))
        .route("/v1/grammars", get(grammars_list))
        .route("/v1/grammars/{name}", get(grammar_source))
        .route("/v1/check", post(check_post))
        .route("/healthz", get(|| async { "ok\n" }))
        .route("/readyz", get(readyz))
        .route("/metrics", get(metrics))
        .fallback(|| async { ServiceError::NotFound("no such route".into()) })
        .layer(DefaultBodyLimit::max(state.config.body_limit))
        .layer(middleware::from_fn_with_state(state.clone(), observe))
        .with_state(state)
}

static REQUEST_ID: AtomicU64 = AtomicU64::new(1);

/// Counts every request by route and status and logs it in a span with a request id.
async fn observe(State(state): State<Arc<AppState>>, req: Request, next: Next) -> Response {
    let route = req.extensions().get::<MatchedPath>().map_or_else(|| "unmatched".to_string(), |m| m.as_str().to_string());
    let id = REQUEST_ID.fetch_add(1, Ordering::Relaxed);
    let span = tracing::info_span!("http", id, method = %req.method(), route = %route);
    let started = Instant::now();
    let mut resp = next.run(req).instrument(span.clone()).await;
    let status = resp.status().as_u16();
    state.metrics.request("http", &route, status);
    let header = |name: &str| resp.headers().get(name).and_then(|v| v.to_str().ok()).unwrap_or("-").to_string();
    span.in_scope(|| {
        tracing::info!(
            status,
            cache = %header("x-rulemesh-cache"),
            etag = %header("etag"),
            ms = started.elapsed().as_secs_f64() * 1000.0,
            "request"
        )
    });
    if let Ok(v) = HeaderValue::from_str(&id.to_string()) {
        resp.headers_mut().insert("x-request-id", v);
    }
    resp
}

/// Whether the request asks to bypass the cache.
fn wants_fresh(headers: &HeaderMap) -> bool {
    headers
        .get_all(header::CACHE_CONTROL)
        .iter()
        .chain(headers.get_all(header::PRAGMA).iter())
        .filter_map(|v| v.to_str().ok())
        .any(|v| v.split(',').any(|d| d.trim().eq_ignore_ascii_case("no-cache")))
}

fn body_bytes(body: Result<Bytes, BytesRejection>, limit: usize) -> Result<Bytes, ServiceError> {
    body.map_err(|e| {
        if e.status() == StatusCode::PAYLOAD_TOO_LARGE {
            ServiceError::PayloadTooLarge { limit }
        } else {
            ServiceError::BadRequest(e.body_text())
        }
    })
}

fn header_value(s: &str) -> HeaderValue {
    HeaderValue::from_str(s).unwrap_or_else(|_| HeaderValue::from_static("invalid"))
}

/// A model response with its ETag, cache and count headers.
fn model_response(served: &Served, cache_control: Option<&'static str>) -> Response {
    let m = &served.model;
    let mut resp = Response::new(Body::from(m.bytes.clone()));
    let h = resp.headers_mut();
    h.insert(header::CONTENT_TYPE, HeaderValue::from_static(m.content_type));
    model_headers(h, served, cache_control);
    resp
}

fn model_headers(h: &mut HeaderMap, served: &Served, cache_control: Option<&'static str>) {
    let m = &served.model;
    h.insert(header::ETAG, header_value(&format!("\"{}\"", m.etag)));
    h.insert("x-rulemesh-cache", HeaderValue::from_static(if served.cache == CacheOutcome::Hit { "hit" } else { "miss" }));
    h.insert("x-rulemesh-primitives", HeaderValue::from(m.primitives));
    h.insert("x-rulemesh-triangles", HeaderValue::from(m.triangles));
    h.insert("x-rulemesh-truncated", HeaderValue::from_static(if m.truncated.is_some() { "true" } else { "false" }));
    if let Some(t) = &m.truncated {
        h.insert("x-rulemesh-truncated-limit", HeaderValue::from_static(t.limit.name()));
        h.insert("x-rulemesh-truncated-configured", HeaderValue::from(t.configured));
        h.insert("x-rulemesh-truncated-reached", HeaderValue::from(t.reached));
    }
    match cache_control {
        Some(cc) if m.truncated.is_none() => h.insert(header::CACHE_CONTROL, HeaderValue::from_static(cc)),
        _ => h.insert(header::CACHE_CONTROL, HeaderValue::from_static("no-store")),
    };
}

/// `POST /v1/render`.
async fn render_post(State(st): State<Arc<AppState>>, headers: HeaderMap, body: Result<Bytes, BytesRejection>) -> Response {
    let result = async {
        let body = body_bytes(body, st.config.body_limit)?;
        let plan = from_json::<RenderBody>(&body)?.plan(&st.ceiling, wants_fresh(&headers))?;
        st.engine.serve(plan).await
    }
    .await;
    match result {
        Ok(served) => model_response(&served, None),
        Err(e) => e.into_response(),
    }
}

/// Whether `If-None-Match` lists `etag` (or `*`).
fn etag_matches(headers: &HeaderMap, etag: &str) -> bool {
    headers.get_all(header::IF_NONE_MATCH).iter().filter_map(|v| v.to_str().ok()).any(|v| {
        v.split(',').map(str::trim).any(|t| t == "*" || t.trim_start_matches("W/").trim_matches('"') == etag)
    })
}

/// `GET /v1/models/{name}.{glb|gltf|stl}?seed=N&p.<param>=V&detail=D`.
async fn model_get(State(st): State<Arc<AppState>>, Path(file): Path<String>, RawQuery(query): RawQuery, headers: HeaderMap) -> Response {
    let result = async {
        let Some((name, ext)) = file.rsplit_once('.') else {
            return Err(ServiceError::NotFound(format!("`{file}`: expected NAME.glb, NAME.gltf or NAME.stl")));
        };
        if !matches!(ext, "glb" | "gltf" | "stl") {
            return Err(ServiceError::NotFound(format!("`{file}`: unknown extension (glb, gltf, stl)")));
        }
        let builtin = library::find(name).ok_or_else(|| ServiceError::NotFound(format!("no built-in grammar `{name}`")))?;
        let mut body = RenderBody {
            source: builtin.source.to_string(),
            language: Some(builtin.language.name().to_string()),
            format: Some(ext.to_string()),
            ..RenderBody::default()
        };
        parse_format(Some(ext))?;
        let pairs: Vec<(String, String)> = serde_urlencoded_pairs(query.as_deref().unwrap_or(""))?;
        for (k, v) in pairs {
            let bad = |what: &str| ServiceError::BadRequest(format!("query `{k}={v}`: {what}"));
            match k.as_str() {
                "seed" => body.seed = Some(v.parse().map_err(|_| bad("seed must be a whole number ≥ 0"))?),
                "detail" => body.detail = Some(v.parse().map_err(|_| bad("detail must be a whole number"))?),
                "quantize" => body.quantize = Some(v.parse().map_err(|_| bad("quantize must be true or false"))?),
                "weld" => body.weld = Some(v.parse().map_err(|_| bad("weld must be true or false"))?),
                "compress" => body.compress = Some(v.clone()),
                "fit" => body.fit = Some(v.clone()),
                _ => match k.strip_prefix("p.") {
                    Some(p) if !p.is_empty() => {
                        body.params.insert(p.to_string(), ParamValue::Text(v.clone()));
                    }
                    _ => return Err(bad("unknown query parameter (seed, detail, quantize, weld, compress, fit, p.<name>)")),
                },
            }
        }
        let pinned = body.seed.is_some();
        let plan = body.plan(&Limits::default().clamped_to(&st.ceiling), wants_fresh(&headers))?;
        let served = st.engine.serve(plan).await?;
        Ok((served, pinned))
    }
    .await;
    match result {
        Ok((served, pinned)) => {
            let cc = if pinned { CACHE_IMMUTABLE } else { CACHE_SHORT };
            if etag_matches(&headers, &served.model.etag) {
                let mut resp = StatusCode::NOT_MODIFIED.into_response();
                model_headers(resp.headers_mut(), &served, Some(cc));
                return resp;
            }
            model_response(&served, Some(cc))
        }
        Err(e) => e.into_response(),
    }
}

/// Decodes `a=b&c=d` (percent-encoding and `+`) into pairs.
fn serde_urlencoded_pairs(query: &str) -> Result<Vec<(String, String)>, ServiceError> {
    axum::extract::Query::<Vec<(String, String)>>::try_from_uri(
        &format!("/?{query}").parse().map_err(|_| ServiceError::BadRequest("malformed query string".into()))?,
    )
    .map(|q| q.0)
    .map_err(|e| ServiceError::BadRequest(format!("malformed query string: {}", e.body_text())))
}

/// `GET /v1/grammars`.
async fn grammars_list() -> Json<GrammarList> {
    Json(GrammarList { grammars: library::all().map(|b| b.info()).collect() })
}

/// The body of `GET /v1/grammars`.
#[derive(Debug, Serialize)]
pub struct GrammarList {
    /// Every built-in grammar.
    pub grammars: Vec<GrammarInfo>,
}

/// `GET /v1/grammars/{name}`: the source as text.
async fn grammar_source(Path(name): Path<String>) -> Response {
    let name = name.strip_suffix(".mdg").unwrap_or(&name);
    match library::find(name) {
        Some(b) => ([(header::CONTENT_TYPE, "text/plain; charset=utf-8")], b.source).into_response(),
        None => ServiceError::NotFound(format!("no built-in grammar `{name}`")).into_response(),
    }
}

/// The body of `POST /v1/check`.
#[derive(Debug, Serialize)]
pub struct CheckReport {
    /// True when the source parses.
    pub ok: bool,
    /// The language it was read as, when known.
    pub language: Option<&'static str>,
    /// Errors and warnings with line and column.
    pub diagnostics: Vec<Diagnostic>,
}

/// Parses without evaluating; shared with gRPC.
pub fn check(body: CheckBody, ceiling: &Limits) -> Result<CheckReport, ServiceError> {
    let language = super::request::parse_language(body.language.as_deref())?;
    let source = crate::cache::normalize_source(body.source.as_bytes());
    let limits = Limits::default().clamped_to(ceiling);
    match crate::pipeline::parse_source(&source, language, &limits) {
        Ok((lang, program)) => Ok(CheckReport { ok: true, language: Some(lang.name()), diagnostics: program.warnings }),
        Err(crate::RenderError::Parse(p)) => {
            let lang = language.or_else(|| crate::lang::Language::detect(&source)).map(|l| l.name());
            let ok = !p.diagnostics.iter().any(|d| d.severity == Severity::Error);
            Ok(CheckReport { ok, language: lang, diagnostics: p.diagnostics })
        }
        Err(e) => Err(e.into()),
    }
}

/// `POST /v1/check`.
async fn check_post(State(st): State<Arc<AppState>>, body: Result<Bytes, BytesRejection>) -> Response {
    let result = body_bytes(body, st.config.body_limit).and_then(|b| from_json::<CheckBody>(&b)).and_then(|b| check(b, &st.ceiling));
    match result {
        Ok(report) => Json(report).into_response(),
        Err(e) => e.into_response(),
    }
}

/// `GET /readyz`: 200 while accepting work, 503 once shutting down.
async fn readyz(State(st): State<Arc<AppState>>) -> Response {
    if st.is_ready() {
        "ready\n".into_response()
    } else {
        ServiceError::ShuttingDown.into_response()
    }
}

/// `GET /metrics`.
async fn metrics(State(st): State<Arc<AppState>>) -> Response {
    st.engine.cache().sync().await;
    ([(header::CONTENT_TYPE, "text/plain; version=0.0.4; charset=utf-8")], st.metrics.render_text(st.engine.cache())).into_response()
}
